// An exact number type for ring expressions of doubles (+, -, *) without heap allocation:
// (-1)^negative M 2^exponent with the magnitude M in at most kLimbs limbs on the stack,
// computed with GMP's mpn layer (no gcd, unlike mpq; no allocation, unlike mpz). A result that
// could need more limbs is marked `overflow` instead, and every result computed from an
// overflowed value is marked too: the caller then computes over the rationals. The rigid
// filter's exact signs at doubles use it (exact/reference/rigid_ccd.hpp). PROOF: proofs/rigid_ccd.md#toi-tightening
#pragma once

#include <gmp.h>
#include <gmpxx.h>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

namespace exactccd::exact {

class StackDyadic {
 public:
  /// 1024 bits: the rigid coefficients of doubles near unit scale need about 400, their values
  /// at a double about 700; wider spreads of exponents overflow to the rationals.
  static constexpr int kLimbs = 16;

  StackDyadic() = default;  ///< zero
  /// The double d exactly (finite).
  explicit StackDyadic(double d);
  explicit StackDyadic(int i) : StackDyadic(static_cast<double>(i)) {}

  bool overflow() const { return overflow_; }
  /// -1, 0 or +1 (meaningless when overflow()).
  int sign() const { return size_ == 0 ? 0 : (negative_ ? -1 : 1); }
  /// The exact value (for tests; not for an overflowed value).
  mpq_class to_rational() const;

  friend StackDyadic operator*(const StackDyadic& a, const StackDyadic& b);
  friend StackDyadic operator+(const StackDyadic& a, const StackDyadic& b) {
    return sum(a, b, false);
  }
  friend StackDyadic operator-(const StackDyadic& a, const StackDyadic& b) {
    return sum(a, b, true);
  }
  friend StackDyadic operator-(const StackDyadic& a) {
    StackDyadic r = a;
    if (r.size_ != 0) r.negative_ = !r.negative_;
    return r;
  }

 private:
  /// a + b, or a - b when negate_b.
  static StackDyadic sum(const StackDyadic& a, const StackDyadic& b, bool negate_b);
  static StackDyadic overflowed() {
    StackDyadic r;
    r.overflow_ = true;
    return r;
  }
  /// Drops high zero limbs, and low zero limbs into the exponent (keeps magnitudes short).
  void normalise();

  mp_limb_t limb_[kLimbs];
  int size_ = 0;  // limbs of M in use; 0 for zero
  bool negative_ = false;
  bool overflow_ = false;
  long exponent_ = 0;
};

}  // namespace exactccd::exact
