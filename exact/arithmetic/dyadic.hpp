// An exact dyadic number M 2^e (M a GMP integer, e any int) for ring expressions of doubles:
// +, -, * never round and never take a gcd (unlike mpq), and grow only as the operands do (no
// fixed capacity, unlike StackDyadic). The rigid separation's exact signs at doubles use it:
// their values need a few thousand bits. PROOF: proofs/min_separation.md#rigid-separation-filter
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <cstdint>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

namespace exactccd::exact {

class Dyadic {
 public:
  Dyadic() = default;  ///< zero
  /// The finite double d exactly: its 53-bit integer mantissa times a power of two.
  explicit Dyadic(double d) {
    if (d == 0) return;
    int e;
    const double m = std::frexp(d, &e);  // d = m 2^e, |m| in [1/2, 1)
    m_ = static_cast<long>(std::ldexp(m, 53));  // an integer below 2^53 in magnitude: exact
    e_ = e - 53;
  }
  explicit Dyadic(int i) : Dyadic(static_cast<double>(i)) {}

  int sign() const { return sgn(m_); }

  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) {
    Dyadic r;
    r.m_ = a.m_ * b.m_;
    r.e_ = a.e_ + b.e_;
    return r;
  }
  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) { return sum(a, b, false); }
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return sum(a, b, true); }
  friend Dyadic operator-(const Dyadic& a) {
    Dyadic r = a;
    r.m_ = -r.m_;
    return r;
  }

 private:
  /// a + b (a - b when negate_b), aligned on the smaller exponent.
  static Dyadic sum(const Dyadic& a, const Dyadic& b, bool negate_b) {
    Dyadic r;
    if (sgn(b.m_) == 0) return a;
    if (sgn(a.m_) == 0) {
      r = b;
      if (negate_b) r.m_ = -r.m_;
      return r;
    }
    const bool a_low = a.e_ <= b.e_;  // (by value, not address: a and b may be one object)
    const Dyadic& low = a_low ? a : b;
    const Dyadic& high = a_low ? b : a;
    mpz_class shifted;
    mpz_mul_2exp(shifted.get_mpz_t(), high.m_.get_mpz_t(),
                 static_cast<mp_bitcnt_t>(high.e_ - low.e_));
    const bool negate_low = negate_b && !a_low, negate_high = negate_b && a_low;
    if (negate_low == negate_high) {
      r.m_ = shifted + low.m_;
      if (negate_low) r.m_ = -r.m_;
    } else {
      r.m_ = negate_high ? low.m_ - shifted : shifted - low.m_;
    }
    r.e_ = low.e_;
    return r;
  }

  mpz_class m_;
  std::int64_t e_ = 0;
};

}  // namespace exactccd::exact
