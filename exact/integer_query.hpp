// A double-precision query in exact integer arithmetic, for fast exact decisions at double
// times: every input double is an integer times a common power of two 2^E, and scaling space
// by 2^-E (a positive constant) changes no contact, no contact time and no sign used here.
// No rational normalisation (gcd) is ever needed, and the temporaries live in a per-thread
// workspace, so that a warm thread allocates only the four coefficients.
// PROOF: proofs/filters.md#exact-at-double-times
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <utility>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

#include "exactccd/types.hpp"

namespace exactccd::exact {

class IntegerQuery {
 public:
  explicit IntegerQuery(const VertexFaceQuery& q);
  explicit IntegerQuery(const EdgeEdgeQuery& q);

  /// The exact sign of the coplanarity cubic at the finite double t >= 0.
  int cubic_sign_at(double t) const;

  /// Doubles around the only root of the cubic in [lo, hi] (0 <= lo < hi; the cubic non-zero
  /// with opposite signs at lo and hi, and a single simple root between them), meeting `width`
  /// (0: the tightest pair; toi_lo == toi_hi when the root is a double). The result is the
  /// one of bit-order bisection (an exact sign at the middle double of what is left, until
  /// no double is left inside or hi - lo <= width exactly), which for width > 0 fixes which
  /// pair is returned; it is reached with exact signs at points chosen by Newton's method,
  /// usually two or three evaluations, at most 73 (bisection alone: up to 65).
  std::pair<double, double> bisect_root(double lo, double hi, double width) const;

  /// Exact contact test at the double t in [0, 1], where the cubic vanishes (coplanar).
  bool contact_at(double t) const;

  /// x = mantissa * 2^exponent with an integer mantissa of at most 53 bits.
  struct Dyadic {
    std::int64_t mantissa = 0;
    int exponent = 0;
  };

 private:
  void compute_cubic();

  QueryType type_;
  Dyadic coords_[8][3];  // benchmark row order
  int common_exponent_ = 0;
  mpz_class cubic_[4];   // cubic_[i] of t^i, scaled by 2^(-3E)
};

}  // namespace exactccd::exact
