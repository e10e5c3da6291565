// The operations the exact integer kernels (exact/stages/integer_cubic.hpp) use, for each integer
// type they are instantiated with: FixedInt<N> (stack, exact within the proven bounds) and
// mpz_class (GMP, the reference and the fallback beyond the largest fixed width). The kernels call
// these unqualified, so a test can add its own integer type (e.g. one that records bit lengths) by
// declaring the same functions next to it.
#pragma once

#include <gmpxx.h>

#include <climits>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "exact/arithmetic/fixed_int.hpp"

namespace exactccd::exact {

// ---- FixedInt<N> -----------------------------------------------------------------------------

template <int N>
int sign_of(const FixedInt<N>& x) {
  return x.sign();
}

/// r *= m.
template <int N>
void multiply_by(FixedInt<N>& r, std::uint64_t m) {
  r.multiply_by(m);
}

/// r += c 2^s.
template <int N>
EXACTCCD_FIXED_INLINE void add_shifted(FixedInt<N>& r, const FixedInt<N>& c, unsigned s) {
  r += c << s;
}

/// out += a b, out -= a b: in one width (the product modulo 2^(64N)), or from narrower operands
/// (their exact product when N >= A + B).
template <int N>
void add_product(FixedInt<N>& out, const FixedInt<N>& a, const FixedInt<N>& b) {
  out += a * b;
}
template <int N>
void sub_product(FixedInt<N>& out, const FixedInt<N>& a, const FixedInt<N>& b) {
  out -= a * b;
}
template <int N, int A, int B>
EXACTCCD_FIXED_INLINE void add_product(FixedInt<N>& out, const FixedInt<A>& a,
                                       const FixedInt<B>& b) {
  out += FixedInt<N>::product(a, b);
}
template <int N, int A, int B>
EXACTCCD_FIXED_INLINE void sub_product(FixedInt<N>& out, const FixedInt<A>& a,
                                       const FixedInt<B>& b) {
  out -= FixedInt<N>::product(a, b);
}

/// m 2^s: by a shift in general, in place for FixedInt.
template <class Int>
struct ScaledInteger {
  static Int make(std::int64_t m, unsigned s) { return Int(m) << s; }
};
template <int N>
struct ScaledInteger<FixedInt<N>> {
  static FixedInt<N> make(std::int64_t m, unsigned s) { return FixedInt<N>::scaled(m, s); }
};
template <class Int>
Int scaled_integer(std::int64_t m, unsigned s) {
  return ScaledInteger<Int>::make(m, s);
}

/// Bits of |x| (0 for x = 0).
template <int N>
long bit_length(const FixedInt<N>& x) {
  const FixedInt<N> m = x.magnitude();
  for (int i = N - 1; i >= 0; --i)
    if (m.limb(i) != 0) return 64L * i + 64 - __builtin_clzll(m.limb(i));
  return 0;
}

// ---- mpz_class -------------------------------------------------------------------------------

inline int sign_of(const mpz_class& x) { return sgn(x); }

inline mpz_class mpz_from_u64(std::uint64_t m) {
  mpz_class z;
  mpz_import(z.get_mpz_t(), 1, -1, sizeof m, 0, 0, &m);
  return z;
}

inline void multiply_by(mpz_class& r, std::uint64_t m) {
  if constexpr (ULONG_MAX >= std::numeric_limits<std::uint64_t>::max())
    mpz_mul_ui(r.get_mpz_t(), r.get_mpz_t(), static_cast<unsigned long>(m));
  else
    r *= mpz_from_u64(m);
}

/// r *= m for an integer factor (a time t >= 2^53 as an integer).
inline void multiply_by(mpz_class& r, const mpz_class& m) { r *= m; }

inline void add_shifted(mpz_class& r, const mpz_class& c, unsigned s) {
  mpz_class term;
  mpz_mul_2exp(term.get_mpz_t(), c.get_mpz_t(), s);
  r += term;
}

inline void add_product(mpz_class& out, const mpz_class& a, const mpz_class& b) {
  mpz_addmul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
}
inline void sub_product(mpz_class& out, const mpz_class& a, const mpz_class& b) {
  mpz_submul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
}

inline long bit_length(const mpz_class& x) {
  return sgn(x) == 0 ? 0 : static_cast<long>(mpz_sizeinbase(x.get_mpz_t(), 2));
}

// ---- conversions -----------------------------------------------------------------------------

/// The integer a FixedInt holds, in mpz (its value, not a residue: the bounds guarantee it).
template <int N>
mpz_class to_mpz(const FixedInt<N>& x) {
  const FixedInt<N> m = x.magnitude();
  int n = N;  // significant limbs: the wide stored coefficients are mostly leading zeros
  while (n > 0 && m.limb(n - 1) == 0) --n;
  mpz_class z;
  if (n == 0) return z;
  if constexpr (GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8) {
    mp_limb_t* d = mpz_limbs_write(z.get_mpz_t(), n);
    for (int i = 0; i < n; ++i) d[i] = m.limb(i);
    mpz_limbs_finish(z.get_mpz_t(), x.is_negative() ? -n : n);
  } else {
    std::uint64_t limbs[N];
    for (int i = 0; i < n; ++i) limbs[i] = m.limb(i);
    mpz_import(z.get_mpz_t(), static_cast<std::size_t>(n), -1, sizeof limbs[0], 0, 0, limbs);
    if (x.is_negative()) z = -z;
  }
  return z;
}

inline const mpz_class& to_mpz(const mpz_class& x) { return x; }

// ---- certified enclosures in doubles ---------------------------------------------------------

/// |x| = m 2^e + r with 0 <= r < 2^e and m < 2^53 its leading bits (m >= 2^52 when e > 0);
/// `inexact`: r != 0. For x = 0, m = e = 0. PROOF: proofs/filters.md#exact-cubic-retry
struct LeadingBits {
  std::uint64_t m = 0;
  long e = 0;
  bool inexact = false;
};

template <int N>
LeadingBits leading_bits(const FixedInt<N>& x) {
  const FixedInt<N> a = x.magnitude();  // exact: every value the bounds admit is > -2^(64N-1)
  int top = N - 1;
  while (top >= 0 && a.limb(top) == 0) --top;
  if (top < 0) return {};
  const long bits = 64L * top + 64 - __builtin_clzll(a.limb(top));
  if (bits <= 53) return {a.limb(0), 0, false};
  LeadingBits b;
  b.e = bits - 53;
  const int limb = static_cast<int>(b.e / 64), offset = static_cast<int>(b.e % 64);
  std::uint64_t m = a.limb(limb) >> offset;
  if (offset != 0 && limb + 1 < N) m |= a.limb(limb + 1) << (64 - offset);
  b.m = m & ((std::uint64_t{1} << 53) - 1);
  bool below = offset != 0 && (a.limb(limb) & ((std::uint64_t{1} << offset) - 1)) != 0;
  for (int i = 0; i < limb; ++i) below = below || a.limb(i) != 0;
  b.inexact = below;
  return b;
}

inline LeadingBits leading_bits(const mpz_class& x) {
  if (sgn(x) == 0) return {};
  const auto bits = static_cast<long>(mpz_sizeinbase(x.get_mpz_t(), 2));
  mpz_class m = abs(x);
  LeadingBits b;
  if (bits > 53) {
    b.e = bits - 53;
    b.inexact = static_cast<long>(mpz_scan1(m.get_mpz_t(), 0)) < b.e;
    mpz_tdiv_q_2exp(m.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(b.e));
  }
  b.m = mpz_getlimbn(m.get_mpz_t(), 0);  // m < 2^53 fits the lowest limb (GMP_NUMB_BITS >= 53)
  static_assert(GMP_NUMB_BITS >= 53, "a 53-bit value in one GMP limb");
  return b;
}

// ---- rounded values, for guidance only ---------------------------------------------------------

/// The floating point of guidance (exact/polynomials/guided_bisection.hpp): double. (Extended
/// precision would pin a root no better once the probes use exact values, and costs x87 arithmetic
/// and an x87 environment switch per bisection.)
using GuideReal = double;

/// x ~ mantissa 2^exponent, 1/2 <= |mantissa| <= 1 (mantissa 0 for x = 0), from the leading 64
/// bits of |x|. Nothing is decided from it.
struct Approximation {
  GuideReal mantissa = 0;
  long exponent = 0;
};

namespace detail {
/// From the top limb `top` != 0 and the one below it, of a magnitude of `limbs` limbs.
inline Approximation from_leading_limbs(std::uint64_t top, std::uint64_t below, long limbs,
                                        bool negative) {
  const int lz = __builtin_clzll(top);
  const std::uint64_t leading = lz == 0 ? top : (top << lz) | (below >> (64 - lz));
  Approximation a;
  a.exponent = 64 * limbs - lz;
  a.mantissa = static_cast<GuideReal>(leading) * static_cast<GuideReal>(0x1p-64);
  if (negative) a.mantissa = -a.mantissa;
  return a;
}
}  // namespace detail

/// For a negative x of two or more significant limbs, the leading bits of ~x = |x| - 1 stand for
/// those of |x| (no carry chain; a relative difference below 2^-64); a magnitude within one limb
/// is taken exactly.
template <int N>
Approximation approximate(const FixedInt<N>& x) {
  const bool negative = x.is_negative();
  const std::uint64_t flip = negative ? ~std::uint64_t{0} : 0;
  for (int i = N - 1; i >= 1; --i) {
    const std::uint64_t top = x.limb(i) ^ flip;
    if (top != 0) return detail::from_leading_limbs(top, x.limb(i - 1) ^ flip, i + 1, negative);
  }
  if (!negative) {
    if (x.limb(0) == 0) return {};
    return detail::from_leading_limbs(x.limb(0), 0, 1, false);
  }
  if (x.limb(0) == 0) return {-0.5, 65};  // x = -2^64
  return detail::from_leading_limbs(0 - x.limb(0), 0, 1, true);
}

inline Approximation approximate(const mpz_class& x) {
  const std::size_t n = mpz_size(x.get_mpz_t());
  if (n == 0) return {};
  if constexpr (GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8) {
    return detail::from_leading_limbs(mpz_getlimbn(x.get_mpz_t(), n - 1),
                                      n >= 2 ? mpz_getlimbn(x.get_mpz_t(), n - 2) : 0,
                                      static_cast<long>(n), sgn(x) < 0);
  } else {
    Approximation a;
    a.mantissa = mpz_get_d_2exp(&a.exponent, x.get_mpz_t());
    return a;
  }
}

}  // namespace exactccd::exact
