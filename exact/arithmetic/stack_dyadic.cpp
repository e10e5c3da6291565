#include "exact/arithmetic/stack_dyadic.hpp"

#include <cmath>
#include <cstdint>
#include <utility>

namespace exactccd::exact {

static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "64-bit GMP limbs expected");

StackDyadic::StackDyadic(double d) {
  if (d == 0) return;
  int e;
  const double f = std::frexp(std::fabs(d), &e);  // |d| = f 2^e, f in [1/2, 1)
  // f 2^53 is an integer below 2^53 (exact); subnormals have fewer significant bits, still
  // exact.
  limb_[0] = static_cast<mp_limb_t>(std::ldexp(f, 53));
  size_ = 1;
  negative_ = d < 0;
  exponent_ = e - 53;
}

void StackDyadic::normalise() {
  while (size_ > 0 && limb_[size_ - 1] == 0) --size_;
  if (size_ == 0) {
    negative_ = false;
    return;
  }
  int low = 0;
  while (limb_[low] == 0) ++low;
  if (low > 0) {
    for (int i = low; i < size_; ++i) limb_[i - low] = limb_[i];
    size_ -= low;
    exponent_ += 64L * low;
  }
}

StackDyadic operator*(const StackDyadic& a, const StackDyadic& b) {
  if (a.overflow_ || b.overflow_) return StackDyadic::overflowed();
  if (a.size_ == 0 || b.size_ == 0) return StackDyadic();
  if (a.size_ + b.size_ > StackDyadic::kLimbs) return StackDyadic::overflowed();
  StackDyadic r;
  const StackDyadic& big = a.size_ >= b.size_ ? a : b;
  const StackDyadic& small = a.size_ >= b.size_ ? b : a;
  mpn_mul(r.limb_, big.limb_, big.size_, small.limb_, small.size_);
  r.size_ = a.size_ + b.size_;
  r.negative_ = a.negative_ != b.negative_;
  r.exponent_ = a.exponent_ + b.exponent_;
  r.normalise();
  return r;
}

StackDyadic StackDyadic::sum(const StackDyadic& a, const StackDyadic& b, bool negate_b) {
  if (a.overflow_ || b.overflow_) return overflowed();
  if (b.size_ == 0) return a;
  if (a.size_ == 0) return negate_b ? -b : b;
  const bool b_negative = b.negative_ != negate_b;
  // Align: the operand with the larger exponent is shifted left onto the smaller one's.
  const bool a_low = a.exponent_ <= b.exponent_;
  const StackDyadic& low = a_low ? a : b;
  const StackDyadic& high = a_low ? b : a;
  const bool low_negative = a_low ? a.negative_ : b_negative;
  const bool high_negative = a_low ? b_negative : a.negative_;
  const long shift = high.exponent_ - low.exponent_;
  if (shift >= 64L * kLimbs) return overflowed();
  const int whole = static_cast<int>(shift / 64), bits = static_cast<int>(shift % 64);
  mp_limb_t shifted[kLimbs];
  const mp_limb_t* y = high.limb_;
  int ys = high.size_;
  if (shift != 0) {
    if (high.size_ + whole + 1 > kLimbs) return overflowed();
    for (int i = 0; i < whole; ++i) shifted[i] = 0;
    if (bits == 0) {
      for (int i = 0; i < high.size_; ++i) shifted[whole + i] = high.limb_[i];
      ys = whole + high.size_;
    } else {
      const mp_limb_t out = mpn_lshift(shifted + whole, high.limb_, high.size_, bits);
      ys = whole + high.size_;
      if (out != 0) shifted[ys++] = out;
    }
    y = shifted;
  }
  // Signed addition of the magnitudes x = low's and y (the shifted high's).
  const mp_limb_t* x = low.limb_;
  int xs = low.size_;
  bool x_negative = low_negative, y_negative = high_negative;
  if (xs < ys || (xs == ys && mpn_cmp(x, y, xs) < 0)) {  // x the larger magnitude
    std::swap(x, y);
    std::swap(xs, ys);
    std::swap(x_negative, y_negative);
  }
  StackDyadic r;
  r.exponent_ = low.exponent_;
  r.negative_ = x_negative;
  if (x_negative == y_negative) {
    if (xs + 1 > kLimbs) return overflowed();
    r.limb_[xs] = mpn_add(r.limb_, x, xs, y, ys);
    r.size_ = xs + 1;
  } else {
    mpn_sub(r.limb_, x, xs, y, ys);  // no borrow: |x| >= |y|
    r.size_ = xs;
  }
  r.normalise();
  return r;
}

mpq_class StackDyadic::to_rational() const {
  mpz_class m;
  if (size_ > 0)
    mpz_import(m.get_mpz_t(), static_cast<std::size_t>(size_), -1, sizeof(mp_limb_t), 0, 0, limb_);
  mpq_class r(m);
  if (exponent_ >= 0)
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(exponent_));
  else
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-exponent_));
  return negative_ ? mpq_class(-r) : r;
}

}  // namespace exactccd::exact
