// Interval arithmetic in x87 extended precision (64-bit significands), rounding upward: a second,
// tighter interval stage where double intervals leave a sign uncertain (the rigid filter's
// signs of the coplanarity polynomial at doubles near a root). Only where long double is the
// x87 format; elsewhere the stage is off and the exact signs decide.
// PROOF: proofs/rigid_ccd.md#toi-tightening
#pragma once

#include <cfloat>

#include "core/predicates/fp_environment.hpp"

#if (defined(__x86_64__) || defined(__i386__)) && LDBL_MANT_DIG == 64
#define EXACTCCD_EXTENDED_INTERVAL 1
#else
#define EXACTCCD_EXTENDED_INTERVAL 0
#endif

namespace exactccd::filters {

#if EXACTCCD_EXTENDED_INTERVAL

/// [lo, hi]. Every operation assumes the x87 rounds upward with 64-bit precision
/// (predicates::X87EnvironmentGuard(Rounding::upward) held); a lower bound is the negation of
/// an upper bound of the negated value. Operands are finite: the rigid filter's expressions are
/// products of at most 15 doubles and of times in [0, 1], far inside the extended exponent range
/// (|x| < 2^16384), so no bound overflows and none is NaN.
struct ExtendedInterval {
  long double lo = 0, hi = 0;
  ExtendedInterval() = default;
  explicit ExtendedInterval(double d) : lo(d), hi(d) {}
  explicit ExtendedInterval(int i) : lo(i), hi(i) {}
  ExtendedInterval(long double l, long double h) : lo(l), hi(h) {}
};

/// x y rounded down (the x87 rounds upward).
inline long double product_down(long double x, long double y) { return -((-x) * y); }

inline ExtendedInterval operator+(const ExtendedInterval& a, const ExtendedInterval& b) {
  return {-((-a.lo) - b.lo), a.hi + b.hi};
}

inline ExtendedInterval operator-(const ExtendedInterval& a, const ExtendedInterval& b) {
  return {-(b.hi - a.lo), a.hi - b.lo};
}

inline ExtendedInterval operator-(const ExtendedInterval& a) { return {-a.hi, -a.lo}; }

/// The product's bounds by the signs of the operands (the extreme products of the end points
/// are known from them), two multiplications except when both straddle 0.
inline ExtendedInterval operator*(const ExtendedInterval& a, const ExtendedInterval& b) {
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

/// +1 / -1 when certainly positive / negative, 2 when certainly zero (the point [0, 0]), 0 when
/// uncertain.
inline int extended_sign(const ExtendedInterval& x) {
  if (x.lo > 0) return 1;
  if (x.hi < 0) return -1;
  if (x.lo == 0 && x.hi == 0) return 2;
  return 0;
}

#endif

}  // namespace exactccd::filters
