// Uniform-grid broad phase over axis-aligned boxes (internal to the query generator).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace exactccd::sim {

/// A closed axis-aligned box.
struct Box {
  std::array<double, 3> lo, hi;
};

/// True when the closed boxes share a point (touching counts).
inline bool overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

/// Every (i, j) with first[i] and second[j] overlapping, sorted by i then j, each once.
/// A uniform grid over the boxes of `second`: each pair is reported only from the cell that
/// holds the low corner of the two boxes' intersection, so no pair is found twice.
std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs(
    const std::vector<Box>& first, const std::vector<Box>& second);

}  // namespace exactccd::sim
