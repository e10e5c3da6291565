// Exact sums of signed products of two or three query coordinates (each a 53-bit mantissa times
// a power of two), accumulated limb by limb where each product lies: a product of mantissas is
// at most three limbs, added at its bit position with its carry, so a sum costs a few limb
// operations per term however far apart the exponents are, and one pass over the width at the
// end. The plain route forms the coordinate differences first, dense over the whole exponent
// spread (2,100 bits at +-1000), and multiplies those limb by limb. The polynomials of the
// exact stage at double brackets whose coordinates exceed the fixed widths are formed here:
// the coplanarity cubic and the inclusion orientations, in the Bernstein basis of [0, 1] (each
// coefficient a sum of products of end-point coordinates), then in the power basis.
// PROOF: proofs/exact_ccd.md#product-accumulator
#pragma once

#include <gmpxx.h>

#include <cstdint>

#include "exact/stages/integer_cubic.hpp"

namespace exactccd::exact {

/// An exact integer sum of signed terms m 2^s (m below 2^192 in magnitude, s >= 0), held as two
/// non-negative sums (positive and negative terms) over `limbs` limbs each; every partial sum
/// must stay below 2^(64 limbs) (the caller's bound).
class ProductAccumulator {
 public:
  /// Room for sums below 2^6,720: three coordinates of at most 2,200 bits each, times 2^8.
  static constexpr int kMaxLimbs = 105;

  /// Zero, with room for sums below 2^(64 limbs); limbs <= kMaxLimbs (else std::length_error).
  explicit ProductAccumulator(int limbs);

  /// += m1 m2 2^s (negated when `negative`; m_i as in Dyadic, |m_i| < 2^63).
  void add_product(std::int64_t m1, std::int64_t m2, unsigned long s, bool negative);
  void add_product(std::int64_t m1, std::int64_t m2, std::int64_t m3, unsigned long s,
                   bool negative);

  mpz_class to_mpz() const;

 private:
  void add_at(std::uint64_t (&sum)[kMaxLimbs], const std::uint64_t (&v)[3], unsigned long s);

  int limbs_;
  std::uint64_t positive_[kMaxLimbs];
  std::uint64_t negative_[kMaxLimbs];
};

/// The coplanarity cubic's coefficients (power basis, scaled by 2^(-3E) as in
/// coplanarity_coefficients): the same integers, from 192 triple products of end-point
/// coordinates. PROOF: proofs/exact_ccd.md#product-accumulator
void accumulated_coplanarity_coefficients(const IntegerCoordinates& q, mpz_class (&c)[4]);

/// One term of an orientation in the plane along axis k (axes u = k+1, v = k+2 mod 3): the
/// 2D cross product x_u y_v - x_v y_u of moving points x, y (row indices at t = 0; the t = 1
/// row is index + 4), with a sign.
struct Cross2Term {
  int x, y;
  bool negative;
};

/// The power-basis coefficients (scaled by 2^(-2E)) of sum of the terms' 2D cross products
/// along axis k, a quadratic in t: e.g. orient2d_along_axis(k, a, b, c) = cross2(a, b) +
/// cross2(b, c) + cross2(c, a). PROOF: proofs/exact_ccd.md#product-accumulator
void accumulated_cross2_coefficients(const IntegerCoordinates& q, int k, const Cross2Term* terms,
                                     int count, mpz_class (&c)[3]);

}  // namespace exactccd::exact
