// A double-precision query in exact integer arithmetic, for fast exact decisions at double
// times: every input double is an integer times a common power of two 2^E, and scaling space
// by 2^-E (a positive constant) changes no contact, no contact time and no sign used here.
// No rational normalisation (gcd) is ever needed. PROOF: proofs/filters.md#exact-at-double-times
#pragma once

#include <gmpxx.h>

#include <array>
#include <utility>

#include "core/predicates/motion.hpp"
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
  /// (0: the tightest pair; toi_lo == toi_hi when the root is a double).
  std::pair<double, double> bisect_root(double lo, double hi, double width) const;

  /// Exact contact test at the double t >= 0, where the cubic vanishes (coplanar instant).
  bool contact_at(double t) const;

 private:
  QueryType type_;
  std::array<predicates::Vec3<mpz_class>, 8> points_;  // benchmark row order, scaled to integers
  mpz_class cubic_[4];                                  // c_[i] of t^i, scaled by 2^(-3E)
};

}  // namespace exactccd::exact
