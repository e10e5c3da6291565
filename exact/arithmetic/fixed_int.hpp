// Fixed-size signed integers on the stack: N 64-bit limbs in two's complement, i.e. arithmetic
// modulo 2^(64N). Addition, subtraction, multiplication and shifts left are ring operations,
// and reduction modulo 2^(64N) commutes with them, so any chain of them yields the exact
// integer whenever that integer lies in [-2^(64N-1), 2^(64N-1)). The callers choose N from the
// bit-length bounds of proofs/filters.md#fixed-size-exact-at-doubles BEFORE computing, so no
// overflow check is ever needed; N is a compile-time constant and every loop is unrolled.
// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
#pragma once

#include <cstdint>

/// Small fixed-size operations are inlined into the kernels: a call costs as much as the work.
#define EXACTCCD_FIXED_INLINE inline __attribute__((always_inline))

namespace exactccd::exact {

#if !defined(__SIZEOF_INT128__)
#error "exact/arithmetic/fixed_int.hpp needs unsigned __int128 (GCC or Clang on a 64-bit target)"
#endif

template <int N>
class FixedInt {
  static_assert(N >= 1, "at least one limb");
  using Limb = std::uint64_t;
  using Wide = unsigned __int128;

 public:
  static constexpr int kLimbs = N;

  constexpr FixedInt() : limb_{} {}
  /// Limbs left unset, for storage that is always written before it is read.
  struct Uninitialized {};
  explicit FixedInt(Uninitialized) {}  // NOLINT(cppcoreguidelines-pro-type-member-init)
  // NOLINTNEXTLINE(google-explicit-constructor): integers convert implicitly, as for mpz_class
  constexpr FixedInt(std::int64_t v) : limb_{} {
    limb_[0] = static_cast<Limb>(v);
    for (int i = 1; i < N; ++i) limb_[i] = v < 0 ? ~Limb{0} : 0;
  }

  /// The integer with these two's complement limbs (least significant first).
  static FixedInt from_limbs(const std::uint64_t (&limbs)[N]) {
    FixedInt r;
    for (int i = 0; i < N; ++i) r.limb_[i] = limbs[i];
    return r;
  }

  /// m 2^s (modulo 2^(64N)), built in place without branches on the data (the signs and
  /// shifts of coordinates are unpredictable) and without indexing by a variable.
  static FixedInt scaled(std::int64_t m, unsigned s) {
    const Limb negative = m < 0 ? ~Limb{0} : 0;
    const Limb magnitude = (static_cast<Limb>(m) ^ negative) - negative;
    const unsigned whole = s / 64, bits = s % 64;
    const Limb low = magnitude << bits;
    const Limb spill = (magnitude >> 1) >> (63 - bits);  // magnitude >> (64 - bits), 0 if bits = 0
    FixedInt r{Uninitialized{}};  // every limb is written below
    Limb carry = negative & 1;  // -x = ~x + 1, applied when m < 0
    for (int i = 0; i < N; ++i) {
      const auto u = static_cast<unsigned>(i);
      const Limb limb = (u == whole ? low : 0) | (u == whole + 1 ? spill : 0);
      const Wide sum = static_cast<Wide>(limb ^ negative) + carry;
      r.limb_[i] = static_cast<Limb>(sum);
      carry = static_cast<Limb>(sum >> 64);
    }
    return r;
  }

  /// The same integer in M limbs: sign-extended (M > N) or truncated (M < N). Truncation is
  /// reduction modulo 2^(64M), exact when the value fits in M limbs.
  template <int M>
  FixedInt<M> resized() const {
    FixedInt<M> r{typename FixedInt<M>::Uninitialized{}};  // every limb is written below
    const Limb extension = is_negative() ? ~Limb{0} : 0;
    for (int i = 0; i < M; ++i) r.limb_[i] = i < N ? limb_[i] : extension;
    return r;
  }

  Limb limb(int i) const { return limb_[i]; }
  bool is_negative() const { return static_cast<std::int64_t>(limb_[N - 1]) < 0; }

  /// -1, 0 or +1.
  int sign() const {
    if (is_negative()) return -1;
    Limb any = 0;
    for (int i = 0; i < N; ++i) any |= limb_[i];
    return any != 0;
  }

  EXACTCCD_FIXED_INLINE FixedInt& operator+=(const FixedInt& o) {
    Limb carry = 0;
    for (int i = 0; i < N; ++i) {
      const Wide s = static_cast<Wide>(limb_[i]) + o.limb_[i] + carry;
      limb_[i] = static_cast<Limb>(s);
      carry = static_cast<Limb>(s >> 64);
    }
    return *this;
  }

  EXACTCCD_FIXED_INLINE FixedInt& operator-=(const FixedInt& o) {
    Limb borrow = 0;
    for (int i = 0; i < N; ++i) {
      const Wide d = static_cast<Wide>(limb_[i]) - o.limb_[i] - borrow;
      limb_[i] = static_cast<Limb>(d);
      borrow = static_cast<Limb>(d >> 64) & 1;  // 1 when the difference wrapped
    }
    return *this;
  }

  /// The product modulo 2^(64N): the lower half of the schoolbook product, in two's complement
  /// (which is the product of the two residues, whatever their signs).
  friend FixedInt operator*(const FixedInt& a, const FixedInt& b) {
    FixedInt r;
    for (int i = 0; i < N; ++i) {
      Limb carry = 0;
      for (int j = 0; i + j < N - 1; ++j) {
        const Wide p = static_cast<Wide>(a.limb_[i]) * b.limb_[j] + r.limb_[i + j] + carry;
        r.limb_[i + j] = static_cast<Limb>(p);
        carry = static_cast<Limb>(p >> 64);
      }
      r.limb_[N - 1] += a.limb_[i] * b.limb_[N - 1 - i] + carry;  // modulo 2^64
    }
    return r;
  }

  /// *this *= m for an unsigned m < 2^64 (modulo 2^(64N)).
  void multiply_by(std::uint64_t m) {
    Limb carry = 0;
    for (int i = 0; i < N; ++i) {
      const Wide p = static_cast<Wide>(limb_[i]) * m + carry;
      limb_[i] = static_cast<Limb>(p);
      carry = static_cast<Limb>(p >> 64);
    }
  }

  /// this * 2^s (modulo 2^(64N)).
  friend FixedInt operator<<(const FixedInt& a, unsigned s) {
    FixedInt r;
    const unsigned whole = s / 64, bits = s % 64;
    for (int i = N - 1; i >= 0; --i) {
      const int from = i - static_cast<int>(whole);
      if (from < 0) break;
      const Limb high = a.limb_[from] << bits;
      const Limb low = (bits != 0 && from >= 1) ? a.limb_[from - 1] >> (64 - bits) : 0;
      r.limb_[i] = high | low;
    }
    return r;
  }

  friend FixedInt operator-(const FixedInt& a) {
    FixedInt r;
    return r -= a;
  }
  friend FixedInt operator+(FixedInt a, const FixedInt& b) { return a += b; }
  friend FixedInt operator-(FixedInt a, const FixedInt& b) { return a -= b; }
  FixedInt& operator*=(const FixedInt& o) { return *this = *this * o; }

  /// a b for an A-limb a and a B-limb b, modulo 2^(64N): exact for any a and b when
  /// N >= A + B (the product of two represented values fits in A + B limbs). The schoolbook
  /// product of the limb patterns read as unsigned (a_u = a + 2^(64A) [a < 0]), less the
  /// corrections 2^(64A) [a < 0] b_u and 2^(64B) [b < 0] a_u; the term 2^(64(A+B)) [both < 0]
  /// vanishes modulo 2^(64(A+B)), and the result is sign-extended beyond A + B limbs.
  template <int A, int B>
  EXACTCCD_FIXED_INLINE static FixedInt product(const FixedInt<A>& a, const FixedInt<B>& b) {
    // The narrowest operands (the cubic's coordinate differences and cross products near unit
    // scale) in native 128-bit multiplications: the same exact product.
    if constexpr (A == 1 && B == 1) {
      return from_wide(static_cast<__int128>(static_cast<std::int64_t>(a.limb_[0])) *
                       static_cast<std::int64_t>(b.limb_[0]));
    } else if constexpr (A == 2 && B == 1) {
      return two_by_one(a, b.limb_[0]);
    } else if constexpr (A == 1 && B == 2) {
      return two_by_one(b, a.limb_[0]);
    } else {
      return schoolbook_product(a, b);
    }
  }

  /// |value| as N limbs (for a value > -2^(64N-1), i.e. any value the bounds admit).
  FixedInt magnitude() const { return is_negative() ? -*this : *this; }

 private:
  template <int>
  friend class FixedInt;

  /// The signed 128-bit integer p, sign-extended (or, for N = 1, reduced modulo 2^64).
  EXACTCCD_FIXED_INLINE static FixedInt from_wide(__int128 p) {
    FixedInt r{Uninitialized{}};  // every limb is written below
    r.limb_[0] = static_cast<Limb>(p);
    if constexpr (N > 1) {
      const auto high = static_cast<Limb>(static_cast<Wide>(p) >> 64);
      r.limb_[1] = high;
      for (int i = 2; i < N; ++i) r.limb_[i] = static_cast<std::int64_t>(high) < 0 ? ~Limb{0} : 0;
    }
    return r;
  }

  /// w s for a two-limb w = w_hi 2^64 + w_lo (w_hi signed, w_lo unsigned) and a one-limb s,
  /// modulo 2^(64N). With s_u = s + 2^64 [s < 0] the limb read as unsigned,
  /// w_lo s = w_lo s_u - 2^64 [s < 0] w_lo, so
  /// w s = (w_hi s + floor(w_lo s_u / 2^64) - [s < 0] w_lo) 2^64 + (w_lo s_u mod 2^64),
  /// where the first factor is below 2^126 + 2^65 in magnitude: exact in a signed __int128.
  EXACTCCD_FIXED_INLINE static FixedInt two_by_one(const FixedInt<2>& w, Limb s_limb) {
    const auto s = static_cast<std::int64_t>(s_limb);
    const Wide low = static_cast<Wide>(w.limb_[0]) * s_limb;
    const __int128 high = static_cast<__int128>(static_cast<std::int64_t>(w.limb_[1])) * s +
                          static_cast<__int128>(low >> 64) -
                          (s < 0 ? static_cast<__int128>(w.limb_[0]) : 0);
    FixedInt r{Uninitialized{}};  // every limb is written below
    r.limb_[0] = static_cast<Limb>(low);
    if constexpr (N > 1) r.limb_[1] = static_cast<Limb>(high);
    if constexpr (N > 2) {
      const auto top = static_cast<Limb>(static_cast<Wide>(high) >> 64);
      r.limb_[2] = top;
      for (int i = 3; i < N; ++i) r.limb_[i] = static_cast<std::int64_t>(top) < 0 ? ~Limb{0} : 0;
    }
    return r;
  }

  template <int A, int B>
  EXACTCCD_FIXED_INLINE static FixedInt schoolbook_product(const FixedInt<A>& a,
                                                           const FixedInt<B>& b) {
    constexpr int R = N < A + B ? N : A + B;
    FixedInt<R> r;
    for (int i = 0; i < A && i < R; ++i) {
      Limb carry = 0;
      for (int j = 0; j < B && i + j < R; ++j) {
        const Wide p = static_cast<Wide>(a.limb_[i]) * b.limb_[j] + r.limb_[i + j] + carry;
        r.limb_[i + j] = static_cast<Limb>(p);
        carry = static_cast<Limb>(p >> 64);
      }
      if (i + B < R) r.limb_[i + B] = carry;
    }
    const Limb a_negative = a.is_negative() ? ~Limb{0} : 0;
    const Limb b_negative = b.is_negative() ? ~Limb{0} : 0;
    Limb borrow = 0;
    for (int j = 0; A + j < R; ++j) {  // - 2^(64A) b_u when a < 0
      const Wide d = static_cast<Wide>(r.limb_[A + j]) - (j < B ? b.limb_[j] & a_negative : 0) -
                     borrow;
      r.limb_[A + j] = static_cast<Limb>(d);
      borrow = static_cast<Limb>(d >> 64) & 1;
    }
    borrow = 0;
    for (int j = 0; B + j < R; ++j) {  // - 2^(64B) a_u when b < 0
      const Wide d = static_cast<Wide>(r.limb_[B + j]) - (j < A ? a.limb_[j] & b_negative : 0) -
                     borrow;
      r.limb_[B + j] = static_cast<Limb>(d);
      borrow = static_cast<Limb>(d >> 64) & 1;
    }
    return r.template resized<N>();
  }

  Limb limb_[N];
};

}  // namespace exactccd::exact
