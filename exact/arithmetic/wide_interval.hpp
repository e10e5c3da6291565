// Interval arithmetic in x87 extended precision (64-bit significands, exponents to 2^16383),
// rounding upward: a certified filter in front of the exact stage's integer evaluations when
// the polynomials' coefficients have hundreds or thousands of bits (queries whose coordinates'
// exponents spread widely), where the exact integers cost far more than their few significant
// bits need. Every value of the stage (coefficients below 2^6400, products of them with times
// in [0, 1]) lies far inside the exponent range, so nothing overflows; bounds are rounded
// outward by the upward rounding mode and negation. Only where long double is the x87 format;
// elsewhere the filter is off and the exact evaluation decides alone.
// PROOF: proofs/exact_ccd.md#wide-interval-filter
#pragma once

#include <gmpxx.h>

#include <cfloat>
#include <cmath>
#include <cstdint>

#include "exact/arithmetic/fixed_int.hpp"

#if (defined(__x86_64__) || defined(__i386__)) && LDBL_MANT_DIG == 64
#define EXACTCCD_WIDE_INTERVAL 1
#else
#define EXACTCCD_WIDE_INTERVAL 0
#endif

namespace exactccd::exact {

#if EXACTCCD_WIDE_INTERVAL

/// [lo, hi]. Every operation below assumes the x87 rounds upward
/// (predicates::X87EnvironmentGuard(Rounding::upward)); a lower bound is the negation of an
/// upper bound of the negated value.
struct WideInterval {
  long double lo, hi;
};

inline WideInterval operator+(const WideInterval& a, const WideInterval& b) {
  return {-((-a.lo) - b.lo), a.hi + b.hi};
}

/// The larger of two finite bounds (no NaN arises: std::fmax's NaN rules, a libm call for long
/// double, are not needed).
inline long double larger(long double x, long double y) { return x > y ? x : y; }

inline WideInterval operator*(const WideInterval& a, const WideInterval& b) {
  const long double h1 = a.lo * b.lo, h2 = a.lo * b.hi, h3 = a.hi * b.lo, h4 = a.hi * b.hi;
  const long double l1 = (-a.lo) * b.lo, l2 = (-a.lo) * b.hi, l3 = (-a.hi) * b.lo,
                    l4 = (-a.hi) * b.hi;
  const long double hi = larger(larger(h1, h2), larger(h3, h4));
  const long double minus_lo = larger(larger(l1, l2), larger(l3, l4));
  return {-minus_lo, hi};
}

/// a t for a point t >= 0: the ends scale without changing order (two products, not eight).
inline WideInterval times_nonnegative(const WideInterval& a, long double t) {
  return {-((-a.lo) * t), a.hi * t};
}

/// a [t_lo, t_hi] for 0 <= t_lo <= t_hi: the least product is a.lo times t_hi when a.lo < 0,
/// else times t_lo; the greatest a.hi times t_hi when a.hi > 0, else times t_lo.
inline WideInterval times_nonnegative(const WideInterval& a, long double t_lo, long double t_hi) {
  return {-((-a.lo) * (a.lo < 0 ? t_hi : t_lo)), a.hi * (a.hi > 0 ? t_hi : t_lo)};
}

/// +1 or -1 when the interval excludes 0, else 0 (uncertain: the caller decides exactly).
inline int certain_sign(const WideInterval& x) { return x.lo > 0 ? 1 : (x.hi < 0 ? -1 : 0); }

/// An enclosure of the integer z (GMP): mpz_get_d_2exp truncates toward zero to 53 bits, so |z| lies
/// in [|d|, |d| + 2^-53] 2^e; both ends are exact in 64-bit significands.
inline WideInterval enclosure_of(const mpz_class& z) {
  if (sgn(z) == 0) return {0.0L, 0.0L};
  long e = 0;
  const double d = mpz_get_d_2exp(&e, z.get_mpz_t());
  const long double near = std::ldexp(static_cast<long double>(d), static_cast<int>(e));
  const long double far =
      std::ldexp(static_cast<long double>(d) + (d < 0 ? -0x1p-53L : 0x1p-53L), static_cast<int>(e));
  return d < 0 ? WideInterval{far, near} : WideInterval{near, far};
}

/// An enclosure of the FixedInt x without GMP: its leading 64 bits M at position s give
/// M 2^s <= |x| <= (M + 1) 2^s, both exact long doubles (M + 1 <= 2^64).
template <int N>
WideInterval enclosure_of(const FixedInt<N>& x) {
  const FixedInt<N> m = x.magnitude();
  int top = N - 1;
  while (top >= 0 && m.limb(top) == 0) --top;
  if (top < 0) return {0.0L, 0.0L};
  const int lz = __builtin_clzll(m.limb(top));
  const std::uint64_t below = top > 0 ? m.limb(top - 1) : 0;
  const std::uint64_t lead = lz == 0 ? m.limb(top) : (m.limb(top) << lz) | (below >> (64 - lz));
  const int shift = 64 * top - lz;  // the weight of lead's lowest bit
  const long double near = std::ldexp(static_cast<long double>(lead), shift);
  const long double far = std::ldexp(static_cast<long double>(lead) + 1.0L, shift);
  return x.is_negative() ? WideInterval{-far, -near} : WideInterval{near, far};
}

#endif

}  // namespace exactccd::exact
