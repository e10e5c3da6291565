// Interval arithmetic in x87 extended precision (64-bit significands, exponents to 2^16383),
// rounding upward: a tighter interval stage where double intervals leave a sign uncertain (the
// rigid filter's signs near a root), and a filter in front of the exact stage's integer
// evaluations when the polynomials' coefficients have hundreds or thousands of bits. Every
// operation assumes the x87 rounds upward with 64-bit precision
// (predicates::X87EnvironmentGuard(Rounding::upward) held); a lower bound is the negation of an
// upper bound of the negated value. Operands are finite and far inside the extended exponent
// range (each user states why), so no bound overflows and none is NaN. Only where long double
// is the x87 format; elsewhere the stages are off and exact signs decide.
// PROOF: proofs/rigid_ccd.md#toi-tightening, proofs/exact_ccd.md#wide-interval-filter
#pragma once

#include <cfloat>

#include "core/predicates/fp_environment.hpp"

#if (defined(__x86_64__) || defined(__i386__)) && LDBL_MANT_DIG == 64
#define EXACTCCD_X87_INTERVAL 1
#else
#define EXACTCCD_X87_INTERVAL 0
#endif

namespace exactccd::predicates {

#if EXACTCCD_X87_INTERVAL

/// [lo, hi], a number type of the predicates' templates (constructible from double and int).
/// Default construction leaves it uninitialised, as CGAL's Interval_nt does (the predicates
/// never read a default value): the exact stage's polynomials hold arrays of them, and zeroing
/// those on every construction cost it 9% on the degenerate suite.
struct X87Interval {
  long double lo, hi;
  X87Interval() = default;
  explicit X87Interval(double d) : lo(d), hi(d) {}
  explicit X87Interval(int i) : lo(i), hi(i) {}
  X87Interval(long double l, long double h) : lo(l), hi(h) {}
};

/// x y rounded down (the x87 rounds upward).
inline long double product_down(long double x, long double y) { return -((-x) * y); }

inline X87Interval operator+(const X87Interval& a, const X87Interval& b) {
  return {-((-a.lo) - b.lo), a.hi + b.hi};
}

inline X87Interval operator-(const X87Interval& a, const X87Interval& b) {
  return {-(b.hi - a.lo), a.hi - b.lo};
}

inline X87Interval operator-(const X87Interval& a) { return {-a.hi, -a.lo}; }

/// The product's bounds by the signs of the operands (the extreme products of the end points
/// are known from them), two multiplications except when both straddle 0.
inline X87Interval operator*(const X87Interval& a, const X87Interval& b) {
  if (a.lo >= 0) {
    if (b.lo >= 0) return {product_down(a.lo, b.lo), a.hi * b.hi};
    if (b.hi <= 0) return {product_down(a.hi, b.lo), a.lo * b.hi};
    return {product_down(a.hi, b.lo), a.hi * b.hi};
  }
  if (a.hi <= 0) {
    if (b.lo >= 0) return {product_down(a.lo, b.hi), a.hi * b.lo};
    if (b.hi <= 0) return {product_down(a.hi, b.hi), a.lo * b.lo};
    return {product_down(a.lo, b.hi), a.lo * b.lo};
  }
  if (b.lo >= 0) return {product_down(a.lo, b.hi), a.hi * b.hi};
  if (b.hi <= 0) return {product_down(a.hi, b.lo), a.lo * b.lo};
  const long double lo1 = product_down(a.lo, b.hi), lo2 = product_down(a.hi, b.lo);
  const long double hi1 = a.lo * b.lo, hi2 = a.hi * b.hi;
  return {lo1 < lo2 ? lo1 : lo2, hi1 > hi2 ? hi1 : hi2};
}

/// a t for a point t >= 0: the ends scale without changing order (two products).
inline X87Interval times_nonnegative(const X87Interval& a, long double t) {
  return {product_down(a.lo, t), a.hi * t};
}

/// a [t_lo, t_hi] for 0 <= t_lo <= t_hi: the least product is a.lo times t_hi when a.lo < 0,
/// else times t_lo; the greatest a.hi times t_hi when a.hi > 0, else times t_lo.
inline X87Interval times_nonnegative(const X87Interval& a, long double t_lo, long double t_hi) {
  return {product_down(a.lo, a.lo < 0 ? t_hi : t_lo), a.hi * (a.hi > 0 ? t_hi : t_lo)};
}

/// +1 or -1 when the interval excludes 0, else 0 (uncertain: the caller decides exactly).
inline int certain_sign(const X87Interval& x) { return x.lo > 0 ? 1 : (x.hi < 0 ? -1 : 0); }

/// +1 / -1 when certainly positive / negative, 2 when certainly zero (the point [0, 0]), 0 when
/// uncertain.
inline int certain_sign_or_zero(const X87Interval& x) {
  if (x.lo == 0 && x.hi == 0) return 2;
  return certain_sign(x);
}

#endif

}  // namespace exactccd::predicates
