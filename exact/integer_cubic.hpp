// The coplanarity cubic of a double-precision query with exact integer coefficients, for fast
// exact signs at doubles (no rational normalisation: every input double is an integer times a
// common power of two, which scales the cubic by a positive constant).
// PROOF: proofs/filters.md#exact-toi-tightening
#pragma once

#include <gmpxx.h>

#include <utility>

#include "exactccd/types.hpp"

namespace exactccd::exact {

class IntegerCubic {
 public:
  explicit IntegerCubic(const VertexFaceQuery& q);
  explicit IntegerCubic(const EdgeEdgeQuery& q);

  /// The exact sign of the coplanarity cubic at the finite double t >= 0.
  int sign_at(double t) const;

  /// Doubles around the only root of the cubic in [lo, hi] (0 <= lo < hi; the cubic non-zero
  /// with opposite signs at lo and hi, and a single simple root between them), meeting `width`
  /// (0: the tightest pair; toi_lo == toi_hi when the root is a double).
  std::pair<double, double> bisect_root(double lo, double hi, double width) const;

 private:
  mpz_class c_[4];  // c_[i] of t^i, times 2^(-3E) for the common exponent E of the input
};

}  // namespace exactccd::exact
