// The bit pattern of a double and back. For non-negative doubles the patterns are ordered as
// the values and consecutive doubles have consecutive patterns: bisection "in bit order" picks
// the middle double of a range, reaching the tightest pair in at most 64 steps.
#pragma once

#include <cstdint>
#include <cstring>

namespace exactccd::predicates {

inline std::uint64_t bits_of(double d) {
  std::uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  return u;
}

inline double double_of(std::uint64_t u) {
  double d;
  std::memcpy(&d, &u, sizeof d);
  return d;
}

/// The bit pattern of a double x >= 0, with -0 read as +0: ordered as the values, consecutive
/// doubles having consecutive patterns.
inline std::uint64_t order_bits(double x) { return x == 0 ? 0 : bits_of(x); }

/// The middle double, in bit order, of the doubles strictly between lo and hi (0 <= lo <= hi,
/// finite): those have the patterns order_bits(lo) + 1 ... order_bits(hi) - 1, and splitting at
/// their middle leaves at most half of them on either side, so at most 64 splits reach the
/// tightest pair. False when no double lies strictly between.
inline bool middle_double(double lo, double hi, double* mid) {
  const std::uint64_t l = order_bits(lo), h = order_bits(hi);
  if (h < l + 2) return false;
  *mid = double_of(l + 1 + (h - l - 2) / 2);
  return true;
}

}  // namespace exactccd::predicates
