// Exact power-of-two normalisation of a query before the filters. Scaling space by 2^s > 0
// changes no contact and no contact time; when every coordinate times 2^s is again a double
// (no overflow, no bit lost to underflow) the scaled query is exactly that scaled query, so it
// has the same verdict and the same exact first contact time. The filters, whose double
// arithmetic overflows or underflows far from unit scale (the semi-static stage refuses column
// maxima outside [2^-200, 2^200]), then see data near unit scale whatever the input's.
// PROOF: proofs/filters.md#power-of-two-normalisation
#pragma once

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/query_points.hpp"
#include "exactccd/types.hpp"

namespace exactccd::detail {

/// A largest |coordinate| in [2^-kComfortableExponent, 2^(kComfortableExponent + 1)) is left as
/// it is: the filters' products of up to three coordinates stay far inside the double range.
constexpr int kComfortableExponent = 64;

constexpr std::uint64_t kMagnitudeBits = ~(std::uint64_t{1} << 63);

/// Whether the largest magnitude (as its bit pattern) is 0 or lies outside
/// [2^-kComfortableExponent, 2^(kComfortableExponent + 1)).
inline bool outside_comfortable_range(std::uint64_t largest) {
  const auto biased = static_cast<int>(largest >> 52);  // 1023 + exponent, 0 if subnormal
  return largest == 0 || std::abs(biased - 1023) > kComfortableExponent;
}

/// |x| as a bit pattern: non-negative doubles are ordered as their patterns.
inline std::uint64_t magnitude_bits(double x) { return predicates::bits_of(x) & kMagnitudeBits; }

inline std::uint64_t largest_magnitude(const Eigen::Vector3d& x, std::uint64_t largest) {
  for (int k = 0; k < 3; ++k) largest = std::max(largest, magnitude_bits(x.coeff(k)));
  return largest;
}

/// The exponent s of the normalising scale 2^s for finite coordinates: 0 when the largest
/// |coordinate| M is 0 or lies in the comfortable range; otherwise the s with M 2^s in
/// [1/2, 1), provided every coordinate times 2^s is a double; else 0. A cheap test first: the
/// first point's coordinates, the others only when those lie outside the comfortable range
/// (data near unit scale pays that alone). Leaving a query unnormalised is always correct, only
/// slower, so a query whose first point is near unit scale while others are far from it is
/// simply left as it is.
template <class Query>
int normalising_exponent(const Query& q) {
  const predicates::QueryPoints p = predicates::points_of(q);
  const Eigen::Vector3d& first = *p[0];
  std::uint64_t largest = std::max(std::max(magnitude_bits(first.x()), magnitude_bits(first.y())),
                                   magnitude_bits(first.z()));
  if (!outside_comfortable_range(largest)) return 0;
  for (int i = 1; i < 8; ++i) largest = largest_magnitude(*p[i], largest);
  if (!outside_comfortable_range(largest)) return 0;
  int e;
  std::frexp(predicates::double_of(largest), &e);  // M = m 2^e, 1/2 <= m < 1
  const int s = -e;
  if (s > 0) return s;  // |x| 2^s <= M 2^s < 1: no overflow, and no bit is lost going up
  // Going down, x = m 2^f (m odd) stays a double iff f + s >= -1074 (the subnormal ulp).
  int lowest = INT_MAX;
  for (const Eigen::Vector3d* x : p)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t bits = magnitude_bits(x->coeff(k));
      if (bits == 0) continue;
      const int exponent_field = static_cast<int>(bits >> 52);
      const int ulp_exponent = exponent_field == 0 ? -1074 : exponent_field - 1075;
      lowest = std::min(lowest, ulp_exponent + __builtin_ctzll(bits | (std::uint64_t{1} << 52)));
    }
  return lowest + s >= -1074 ? s : 0;
}

/// x times 2^s, coordinate-wise (exact by the choice of s).
inline Eigen::Vector3d scaled_by_power_of_two(const Eigen::Vector3d& x, int s) {
  return {std::ldexp(x.x(), s), std::ldexp(x.y(), s), std::ldexp(x.z(), s)};
}

/// The query with every coordinate times 2^s.
inline VertexFaceQuery scaled_by_power_of_two(const VertexFaceQuery& q, int s) {
  const auto f = [s](const Eigen::Vector3d& x) { return scaled_by_power_of_two(x, s); };
  return {f(q.p_t0), f(q.a_t0), f(q.b_t0), f(q.c_t0), f(q.p_t1), f(q.a_t1), f(q.b_t1), f(q.c_t1)};
}

inline EdgeEdgeQuery scaled_by_power_of_two(const EdgeEdgeQuery& q, int s) {
  const auto f = [s](const Eigen::Vector3d& x) { return scaled_by_power_of_two(x, s); };
  return {f(q.ea0_t0), f(q.ea1_t0), f(q.eb0_t0), f(q.eb1_t0),
          f(q.ea0_t1), f(q.ea1_t1), f(q.eb0_t1), f(q.eb1_t1)};
}

}  // namespace exactccd::detail
