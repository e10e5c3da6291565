// Double-double values that carry an upper bound on their absolute error, for certified signs
// at double times (the minimum-separation search's last bracket, where a region polynomial's
// value is about its slope times one ulp of t and plain intervals cannot tell its sign). Every
// operation rounds to nearest (callers set it) and adds its own rounding errors to the bound;
// the bound's arithmetic is itself rounded, which `certified_sign` absorbs. Values must stay
// below 2^900 in magnitude (the callers scale the query below 1).
// PROOF: proofs/min_separation.md#double-double-signs
#pragma once

#include <cmath>

#include "core/predicates/double_double.hpp"

namespace exactccd::predicates::dd {

/// v = hi + lo (|lo| <= 2^-53 |hi| after each operation) and err >= |exact - v|, where
/// exact is the value the same expression has in exact arithmetic.
struct Bounded {
  double hi = 0.0, lo = 0.0, err = 0.0;
};

/// Half an ulp's relative size (unit roundoff), and an absolute term that covers the errors of
/// a product that underflows (at most 2^-1075 per rounding, three roundings).
inline constexpr double kUnit = 0x1p-53;
inline constexpr double kUnderflow = 0x1p-1060;

/// TwoSum (Knuth, dd::two_sum): s + e == a + b exactly, rounding to nearest (no overflow).
inline Bounded exact_sum(double a, double b) {
  const DoubleDouble s = two_sum(a, b);
  return {s.hi, s.lo, 0.0};
}

/// The double x, exactly.
inline Bounded exactly(double x) { return {x, 0.0, 0.0}; }

inline Bounded operator-(const Bounded& a) { return {-a.hi, -a.lo, a.err}; }

/// (a.hi + b.hi) exactly by TwoSum, plus a.lo + b.lo rounded twice (t, then w), renormalised
/// exactly by TwoSum: the new error is at most 2^-53 (|t| + |w|).
inline Bounded operator+(const Bounded& a, const Bounded& b) {
  const Bounded s = exact_sum(a.hi, b.hi);
  const double t = a.lo + b.lo;
  const double w = s.lo + t;
  Bounded r = exact_sum(s.hi, w);
  r.err = (a.err + b.err) + kUnit * (std::fabs(t) + std::fabs(w));
  return r;
}

inline Bounded operator-(const Bounded& a, const Bounded& b) { return a + (-b); }

/// a.hi b.hi exactly as p + e (e by fma), plus the cross terms c = a.hi b.lo and
/// d = a.lo b.hi rounded, summed (f) and added to e (g), renormalised by TwoSum; a.lo b.lo is
/// dropped. New error: 2^-53 (|c| + |d| + |f| + |g|) + |a.lo b.lo| + kUnderflow; the operands'
/// errors propagate as |a| b.err + a.err |b| + a.err b.err.
inline Bounded operator*(const Bounded& a, const Bounded& b) {
  const double p = a.hi * b.hi;
  const double e = std::fma(a.hi, b.hi, -p);
  const double c = a.hi * b.lo, d = a.lo * b.hi;
  const double f = c + d;
  const double g = e + f;
  Bounded r = exact_sum(p, g);
  const double ma = std::fabs(a.hi) + std::fabs(a.lo), mb = std::fabs(b.hi) + std::fabs(b.lo);
  const double own = kUnit * (((std::fabs(c) + std::fabs(d)) + std::fabs(f)) + std::fabs(g)) +
                     std::fabs(a.lo) * std::fabs(b.lo) + kUnderflow;
  r.err = ((ma * b.err + a.err * mb) + a.err * b.err) + own;
  return r;
}

inline Bounded dot(const Bounded (&a)[3], const Bounded (&b)[3]) {
  return (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2];
}

/// Sentinel of `certified_sign`: the bound does not exclude 0.
inline constexpr int kUncertain = 2;

/// +1 or -1 when the exact value certainly has hi's sign: |hi| (1 - 2^-52) > err (1 + 2^-40)
/// + 2^-1000 (the first factor covers lo, the others the bound's own rounding and underflow);
/// kUncertain otherwise, and for a non-finite value or bound. Never 0: an exact zero is left to
/// exact arithmetic.
inline int certified_sign(const Bounded& x) {
  if (!std::isfinite(x.hi) || !std::isfinite(x.err)) return kUncertain;
  const double bound = x.err * (1 + 0x1p-40) + 0x1p-1000;
  if (std::fabs(x.hi) * (1 - 0x1p-52) > bound) return x.hi > 0 ? 1 : -1;
  return kUncertain;
}

}  // namespace exactccd::predicates::dd
