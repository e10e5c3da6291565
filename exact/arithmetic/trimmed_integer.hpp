// An exact integer M 2^e held as the odd M (GMP) and e >= 0: the trailing zero bits of an integer
// coordinate are not stored. A query's doubles become integers over their common power of two,
// so a coordinate of exponent 2,000 above the smallest is a 53-bit mantissa followed by 2,000
// zero bits; an mpz multiplies all of them, M 2^e multiplies the 53. Sums align on the smaller
// exponent (dense only over the spread of their operands). The general route of the exact stage
// at double brackets (degenerate triangles, parallel edges, motion coplanar throughout) forms
// its inclusion polynomials with it where the coordinates span more than 1,024 bits, then
// converts them to mpz; the cubic and the contact orientations at roots come from the product
// accumulator (exact/arithmetic/product_accumulator.hpp).
// PROOF: proofs/exact_ccd.md#trimmed-integers
#pragma once

#include <gmpxx.h>

#include <cstdint>

#include "exact/arithmetic/integer_arithmetic.hpp"
#include "exact/stages/integer_cubic.hpp"

namespace exactccd::exact {

class TrimmedInteger {
 public:
  TrimmedInteger() = default;  ///< 0
  explicit TrimmedInteger(int i) : m_(i) { trim(); }
  /// m 2^s.
  static TrimmedInteger scaled(std::int64_t m, unsigned long s) {
    TrimmedInteger r;
    r.m_ = mpz_from_i64(m);
    r.e_ = s;
    r.trim();
    return r;
  }

  int sign() const { return sgn(m_); }
  /// The integer, in GMP.
  mpz_class to_mpz() const {
    mpz_class z;
    mpz_mul_2exp(z.get_mpz_t(), m_.get_mpz_t(), e_);
    return z;
  }
  const mpz_class& odd_part() const { return m_; }  ///< 0 for 0
  unsigned long exponent() const { return e_; }     ///< 0 for 0

  TrimmedInteger& operator+=(const TrimmedInteger& o) { return add(o.m_, o.e_, false); }
  TrimmedInteger& operator-=(const TrimmedInteger& o) { return add(o.m_, o.e_, true); }
  friend TrimmedInteger operator+(TrimmedInteger a, const TrimmedInteger& b) { return a += b; }
  friend TrimmedInteger operator-(TrimmedInteger a, const TrimmedInteger& b) { return a -= b; }
  friend TrimmedInteger operator-(TrimmedInteger a) {
    a.m_ = -a.m_;
    return a;
  }
  /// The product of odd parts is odd: no trimming.
  friend TrimmedInteger operator*(const TrimmedInteger& a, const TrimmedInteger& b) {
    TrimmedInteger r;
    if (a.m_ == 0 || b.m_ == 0) return r;
    mpz_mul(r.m_.get_mpz_t(), a.m_.get_mpz_t(), b.m_.get_mpz_t());
    r.e_ = a.e_ + b.e_;
    return r;
  }
  /// this += a b (or -= when negate), without a temporary TrimmedInteger.
  void add_product(const TrimmedInteger& a, const TrimmedInteger& b, bool negate) {
    if (a.m_ == 0 || b.m_ == 0) return;
    thread_local mpz_class product;  // scratch: its limbs are reused
    mpz_mul(product.get_mpz_t(), a.m_.get_mpz_t(), b.m_.get_mpz_t());
    add(product, a.e_ + b.e_, negate);
  }

 private:
  static mpz_class mpz_from_i64(std::int64_t m) {
    mpz_class z = mpz_from_u64(magnitude_of(m));
    return m < 0 ? mpz_class(-z) : z;
  }
  /// this += (or -=) x 2^f.
  TrimmedInteger& add(const mpz_class& x, unsigned long f, bool negate) {
    if (x == 0) return *this;
    if (m_ == 0) {
      m_ = negate ? mpz_class(-x) : x;
      e_ = f;
      return *this;
    }
    if (e_ <= f) {
      thread_local mpz_class shifted;  // scratch: its limbs are reused
      mpz_mul_2exp(shifted.get_mpz_t(), x.get_mpz_t(), f - e_);
      if (negate) m_ -= shifted;
      else m_ += shifted;
    } else {
      mpz_mul_2exp(m_.get_mpz_t(), m_.get_mpz_t(), e_ - f);
      e_ = f;
      if (negate) m_ -= x;
      else m_ += x;
    }
    trim();
    return *this;
  }
  void trim() {
    if (m_ == 0) {
      e_ = 0;
      return;
    }
    const mp_bitcnt_t zeros = mpz_scan1(m_.get_mpz_t(), 0);
    if (zeros == 0) return;
    mpz_tdiv_q_2exp(m_.get_mpz_t(), m_.get_mpz_t(), zeros);  // exact: those bits are 0
    e_ += zeros;
  }

  mpz_class m_;          // odd, or 0
  unsigned long e_ = 0;  // 0 when m_ == 0
};

// The operations exact/stages/integer_cubic.hpp calls unqualified.
inline int sign_of(const TrimmedInteger& x) { return x.sign(); }
inline void add_product(TrimmedInteger& out, const TrimmedInteger& a, const TrimmedInteger& b) {
  out.add_product(a, b, false);
}
inline void sub_product(TrimmedInteger& out, const TrimmedInteger& a, const TrimmedInteger& b) {
  out.add_product(a, b, true);
}
template <>
struct ScaledInteger<TrimmedInteger> {
  static TrimmedInteger make(std::int64_t m, unsigned s) { return TrimmedInteger::scaled(m, s); }
};

/// Coordinates of more bits than this are formed in TrimmedInteger, fewer in plain mpz_class:
/// under it the zero limbs a coordinate carries are too few to pay for the alignments and
/// trims (callgrind on the stage when it formed everything this way: exponents within +-300,
/// about 650 bits, 0.89x in plain mpz; within +-1000, about 2,100 bits, 0.92x in
/// TrimmedInteger). A speed setting only: both compute the same integers.
constexpr int kTrimmedCoordinateBits = 1024;

inline bool prefers_trimmed_integers(const IntegerCoordinates& q) {
  return q.bits > kTrimmedCoordinateBits;
}

}  // namespace exactccd::exact
