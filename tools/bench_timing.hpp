// The timing helpers of the bench subcommands: a steady clock, medians, the cost of an empty
// timed region.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace exactccd::cli {

using Clock = std::chrono::steady_clock;

/// Median of `values` (the mean of the two middle ones for an even count); reorders them.
inline double median(std::vector<double>& values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + mid);
  return 0.5 * (lower + upper);
}

inline double nanoseconds(Clock::duration d) {
  return static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(d).count());
}

/// The median cost of an empty timed region: two consecutive clock readings.
inline double timer_overhead_ns() {
  std::vector<double> samples(100001);
  for (double& s : samples) {
    const auto start = Clock::now();
    const auto stop = Clock::now();
    s = nanoseconds(stop - start);
  }
  return median(samples);
}

}  // namespace exactccd::cli
