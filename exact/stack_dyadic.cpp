#include "exact/stack_dyadic.hpp"

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

StackDyadic StackDyadic::sum(const StackDyadic& a, const StackDyadic& b_in, bool negate_b) {
  if (a.overflow_ || b_in.overflow_) return overflowed();
  StackDyadic b = b_in;
  if (negate_b && b.size_ != 0) b.negative_ = !b.negative_;
  if (b.size_ == 0) return a;
  if (a.size_ == 0) return b;
  // Align: the operand with the larger exponent is shifted left onto the smaller one's.
  const StackDyadic& low = a.exponent_ <= b.exponent_ ? a : b;
  const StackDyadic& high = a.exponent_ <= b.exponent_ ? b : a;
  const long shift = high.exponent_ - low.exponent_;
  if (shift >= 64L * kLimbs) return overflowed();
  const int whole = static_cast<int>(shift / 64), bits = static_cast<int>(shift % 64);
  const int shifted_size = high.size_ + whole + 1;
  if (shifted_size > kLimbs) return overflowed();
  mp_limb_t shifted[kLimbs];
  for (int i = 0; i < whole; ++i) shifted[i] = 0;
  if (bits == 0) {
    for (int i = 0; i < high.size_; ++i) shifted[whole + i] = high.limb_[i];
    shifted[whole + high.size_] = 0;
  } else {
    shifted[whole + high.size_] = mpn_lshift(shifted + whole, high.limb_, high.size_, bits);
  }
  int hs = shifted_size;
  while (hs > 0 && shifted[hs - 1] == 0) --hs;
  // Signed addition of the magnitudes low.limb_ (low.size_) and shifted (hs).
  StackDyadic r;
  r.exponent_ = low.exponent_;
  const mp_limb_t* x = low.limb_;
  const mp_limb_t* y = shifted;
  int xs = low.size_, ys = hs;
  bool x_negative = low.negative_, y_negative = high.negative_;
  if (xs < ys || (xs == ys && mpn_cmp(x, y, xs) < 0)) {  // x the larger magnitude
    std::swap(x, y);
    std::swap(xs, ys);
    std::swap(x_negative, y_negative);
  }
  if (x_negative == y_negative) {
    if (xs + 1 > kLimbs) return overflowed();
    mp_limb_t carry = 0;
    if (ys > 0)
      carry = mpn_add(r.limb_, x, xs, y, ys);
    else
      mpn_copyi(r.limb_, x, xs);
    r.limb_[xs] = carry;
    r.size_ = xs + 1;
  } else {
    if (ys > 0)
      mpn_sub(r.limb_, x, xs, y, ys);  // no borrow: |x| >= |y|
    else
      mpn_copyi(r.limb_, x, xs);
    r.size_ = xs;
  }
  r.negative_ = x_negative;
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
