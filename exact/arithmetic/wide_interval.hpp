// Enclosures of exact integers (GMP, FixedInt) by x87 extended-precision intervals
// (core/predicates/x87_interval.hpp): the entries of the filter in front of the exact stage's
// integer evaluations when the polynomials' coefficients have hundreds or thousands of bits
// (queries whose coordinates' exponents spread widely), where the exact integers cost far more
// than their few significant bits need. Every value of the stage (coefficients below 2^6400,
// products of them with times in [0, 1]) lies far inside the exponent range, so nothing
// overflows. Only where long double is the x87 format; elsewhere the filter is off and the
// exact evaluation decides alone.
// PROOF: proofs/exact_ccd.md#wide-interval-filter
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <cstdint>

#include "core/predicates/x87_interval.hpp"
#include "exact/arithmetic/fixed_int.hpp"

namespace exactccd::exact {

#if EXACTCCD_X87_INTERVAL

using predicates::X87Interval;
using predicates::certain_sign;

/// An enclosure of the integer z (GMP): mpz_get_d_2exp truncates toward zero to 53 bits, so |z|
/// lies in [|d|, |d| + 2^-53] 2^e; both ends are exact in 64-bit significands.
inline X87Interval enclosure_of(const mpz_class& z) {
  if (sgn(z) == 0) return {0.0L, 0.0L};
  long e = 0;
  const double d = mpz_get_d_2exp(&e, z.get_mpz_t());
  const long double near = std::ldexp(static_cast<long double>(d), static_cast<int>(e));
  const long double far =
      std::ldexp(static_cast<long double>(d) + (d < 0 ? -0x1p-53L : 0x1p-53L), static_cast<int>(e));
  return d < 0 ? X87Interval{far, near} : X87Interval{near, far};
}

/// An enclosure of the FixedInt x without GMP: its leading 64 bits M at position s give
/// M 2^s <= |x| <= (M + 1) 2^s, both exact long doubles (M + 1 <= 2^64).
template <int N>
X87Interval enclosure_of(const FixedInt<N>& x) {
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
  return x.is_negative() ? X87Interval{-far, -near} : X87Interval{near, far};
}

#endif

}  // namespace exactccd::exact
