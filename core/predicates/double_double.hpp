// Double-double values (an unevaluated sum hi + lo of two doubles) and TwoSum, the exact sum of
// two doubles as one: the base of the certified double-double bounds
// (double_double_bounds.hpp). Callers set round-to-nearest.
#pragma once

namespace exactccd::predicates::dd {

struct DoubleDouble {
  double hi = 0.0, lo = 0.0;
};

inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

}  // namespace exactccd::predicates::dd
