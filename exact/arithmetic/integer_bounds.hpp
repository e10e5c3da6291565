// Bit-length bounds of the exact integer computations at double times, and the fixed width
// they select. L is the query's coordinate bits (every coordinate, scaled to an integer X by the
// common power of two, has |X| < 2^L) and k the exponent of the time (t = T 2^-k, T odd,
// 0 <= T <= 2^k, i.e. 0 <= t <= 1). Every intermediate value of a computation has magnitude
// below 2 to the bound:
// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
#pragma once

namespace exactccd::exact {

/// The cubic's computation, stage by stage: the coordinates and their differences; the cross
/// products and their partial sums; the dot products, i.e. the coefficients and every
/// intermediate of their computation.
constexpr long difference_bits(long coordinate_bits) { return coordinate_bits + 2; }
constexpr long cross_product_bits(long coordinate_bits) { return 2 * coordinate_bits + 5; }
constexpr long cubic_coefficient_bits(long coordinate_bits) { return 3 * coordinate_bits + 10; }

/// 2^(3k) f(t) and every intermediate of its Horner evaluation.
constexpr long cubic_value_bits(long coordinate_bits, long time_exponent) {
  return 3 * coordinate_bits + 11 + 3 * time_exponent;
}

/// The contact test at t: positions 2^k x(t) and every value of the inclusion predicates.
constexpr long contact_bits(long coordinate_bits, long time_exponent) {
  return 2 * (coordinate_bits + time_exponent) + 4;
}

/// The widest fixed-size integer (FixedInt<16>: 1024 bits); GMP beyond.
constexpr int kMaxFixedLimbs = 16;

/// The largest coordinate bits whose coefficients fit the widest fixed-size integer.
constexpr long kMaxFixedCoordinateBits = (64 * kMaxFixedLimbs - 1 - 10) / 3;

/// The limbs of the smallest FixedInt holding every integer of magnitude below 2^bits (two's
/// complement: 64 N - 1 >= bits), or 0 when that exceeds kMaxFixedLimbs (use GMP).
constexpr int fixed_limbs_for(long bits) {
  const long limbs = (bits + 64) / 64;
  return limbs <= kMaxFixedLimbs ? static_cast<int>(limbs) : 0;
}

/// The widths of the cubic's three stages for coordinates of L bits (L <=
/// kMaxFixedCoordinateBits).
struct CubicWidths {
  int difference = 0, cross_product = 0, coefficient = 0;
  constexpr bool operator==(const CubicWidths& o) const {
    return difference == o.difference && cross_product == o.cross_product &&
           coefficient == o.coefficient;
  }
};

constexpr CubicWidths cubic_widths(long coordinate_bits) {
  return {fixed_limbs_for(difference_bits(coordinate_bits)),
          fixed_limbs_for(cross_product_bits(coordinate_bits)),
          fixed_limbs_for(cubic_coefficient_bits(coordinate_bits))};
}

}  // namespace exactccd::exact
