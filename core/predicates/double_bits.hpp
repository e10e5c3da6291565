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

}  // namespace exactccd::predicates
