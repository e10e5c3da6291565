// EXACTCCD_TEST_SCALE: one factor on the size of the long tests. 1 (the default) runs
// everything; below 1, the seeded random loops run about that share of their queries and the
// loops over fixed data sets (the sample queries, the simulation-like queries, the degenerate
// suite, random scenes) check every subset_stride()-th item. The sanitizer build
// (.ci/sanitizers.sh) runs the whole suite this way. Checks that count what a loop reached (so
// that it cannot pass vacuously) scale their thresholds with it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace exactccd::test {

/// EXACTCCD_TEST_SCALE when set (a positive factor on loop counts), else 1.
inline double scale_from_environment() {
  if (const char* env = std::getenv("EXACTCCD_TEST_SCALE")) {
    const double s = std::strtod(env, nullptr);
    if (s > 0 && std::isfinite(s)) return s;
  }
  return 1.0;
}

/// n * scale, rounded, at least 1.
inline std::uint64_t scaled_count(std::uint64_t n, double scale) {
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(n * scale)));
}

inline std::uint64_t scaled_count(std::uint64_t n) {
  return scaled_count(n, scale_from_environment());
}

/// n, or `floor` when n is smaller: for a test that counts how often a case occurs, so that a
/// reduced scale (the sanitizer run) still sees it reliably.
inline std::uint64_t at_least(std::uint64_t n, std::uint64_t floor) { return n < floor ? floor : n; }

/// A loop over a fixed data set checks the items whose index is a multiple of this: 1 at
/// scale >= 1, else about 1 / scale.
inline std::size_t subset_stride() {
  const double scale = scale_from_environment();
  return scale >= 1 ? 1 : static_cast<std::size_t>(std::llround(1 / scale));
}

}  // namespace exactccd::test
