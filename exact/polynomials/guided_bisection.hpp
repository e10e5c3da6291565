// Root bracketing of the coplanarity cubic with exact signs at double times, and probes chosen
// by Newton's method. Independent of how the signs are computed (exact/stages/integer_query.cpp gives
// them in fixed-size or GMP integers).
// PROOF: proofs/filters.md#guided-bisection
#pragma once

#include <utility>

#include "exact/arithmetic/integer_arithmetic.hpp"

namespace exactccd::exact {

/// Exact signs of a cubic f at finite doubles t >= 0, with rounded values for guidance.
class CubicAtDoubles {
 public:
  /// The exact sign of f(t); when `value` is not null, f(t) rounded (guidance only).
  virtual int sign_at(double t, Approximation* value) const = 0;
  /// f's coefficients rounded, c[i] of t^i, on the scale of the values (guidance only).
  virtual void approximate_coefficients(Approximation (&c)[4]) const = 0;

 protected:
  ~CubicAtDoubles() = default;
};

/// Doubles around the only root of f in [lo, hi] (0 <= lo < hi finite; f non-zero with opposite
/// signs at lo and hi, and a single root between them), meeting `width` (0: the tightest pair;
/// lo == hi when the root is a double). The result is the one of bit-order bisection (an exact
/// sign at the middle double of what is left, until no double is left inside or hi - lo <= width
/// exactly), which for width > 0 fixes which pair is returned; it is reached with exact signs at
/// points chosen by Newton's method, usually two or three evaluations, at most 73 (bisection
/// alone: up to 65).
std::pair<double, double> guided_bisection(const CubicAtDoubles& f, double lo, double hi,
                                           double width);

}  // namespace exactccd::exact
