// Double-double arithmetic (a value as an unevaluated sum hi + lo of two doubles, about 106
// bits), rounding to nearest: for guesses only, never for a decision (no error bound is
// claimed). The minimum-separation search uses it to place a Newton step near a root where the
// polynomial's value is a small difference of large terms, so that one exact sign at the guess
// and one at its neighbour close the bracket. Callers set round-to-nearest.
#pragma once

#include <cmath>

namespace exactccd::predicates::dd {

struct DoubleDouble {
  double hi = 0.0, lo = 0.0;
};

inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

inline DoubleDouble normalised(double hi, double lo) {
  const double s = hi + lo;
  return {s, lo - (s - hi)};
}

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  const DoubleDouble s = two_sum(a.hi, b.hi);
  return normalised(s.hi, s.lo + (a.lo + b.lo));
}

inline DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }
inline DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) { return a + (-b); }

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  const double p = a.hi * b.hi;
  const double e = std::fma(a.hi, b.hi, -p);  // the product's rounding error, exactly
  return normalised(p, e + (a.hi * b.lo + a.lo * b.hi));
}

/// x - y for doubles, exactly.
inline DoubleDouble difference(double x, double y) { return two_sum(x, -y); }

inline DoubleDouble dot(const DoubleDouble (&a)[3], const DoubleDouble (&b)[3]) {
  return (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2];
}

}  // namespace exactccd::predicates::dd
