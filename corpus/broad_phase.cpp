#include "corpus/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace exactccd::sim {

namespace {

// A grid of `dims` cells of side `cell` from `origin`; cell coordinates are clamped so that
// boxes reaching outside the grid still map to its border cells. The map from a coordinate to
// its cell is monotone (a subtraction and a product by a positive constant, both rounded
// monotonically), which is all the duplicate-free reporting needs.
struct Grid {
  std::array<double, 3> origin{};
  double inverse_cell = 1.0;
  std::array<int, 3> dims{1, 1, 1};

  int cell_of(double x, int k) const {
    const double c = (x - origin[k]) * inverse_cell;
    if (!(c > 0.0)) return 0;
    if (c >= dims[k] - 1) return dims[k] - 1;
    return static_cast<int>(c);
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dims[1] + y) * dims[0] + x;
  }
  std::size_t size() const {
    return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  }
};

Grid make_grid(const std::vector<Box>& boxes) {
  Grid grid;
  std::array<double, 3> lo = boxes[0].lo, hi = boxes[0].hi;
  double extent_sum = 0.0;
  for (const Box& b : boxes) {
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
      largest = std::max(largest, b.hi[k] - b.lo[k]);
    }
    extent_sum += largest;
  }
  grid.origin = lo;
  const double domain = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  // Cells about as large as the average box: a box then spans few cells and a cell holds
  // few boxes.
  double cell = extent_sum / static_cast<double>(boxes.size());
  if (!(cell > 0.0)) cell = domain > 0.0 ? domain / 16.0 : 1.0;
  const double max_cells = 4.0 * static_cast<double>(boxes.size()) + 64.0;
  for (;;) {
    double cells = 1.0;
    for (int k = 0; k < 3; ++k) cells *= std::floor((hi[k] - lo[k]) / cell) + 1.0;
    if (cells <= max_cells) break;
    cell *= 1.25;
  }
  grid.inverse_cell = 1.0 / cell;
  for (int k = 0; k < 3; ++k)
    grid.dims[k] = static_cast<int>(std::floor((hi[k] - lo[k]) / cell)) + 1;
  return grid;
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs(
    const std::vector<Box>& first, const std::vector<Box>& second) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  if (first.empty() || second.empty()) return pairs;
  const Grid grid = make_grid(second);

  // Cells as a compressed array: start[c] .. start[c + 1] index `members`, in increasing j.
  std::vector<std::uint32_t> start(grid.size() + 1, 0);
  auto for_each_cell = [&grid](const Box& b, auto&& f) {
    const int x0 = grid.cell_of(b.lo[0], 0), x1 = grid.cell_of(b.hi[0], 0);
    const int y0 = grid.cell_of(b.lo[1], 1), y1 = grid.cell_of(b.hi[1], 1);
    const int z0 = grid.cell_of(b.lo[2], 2), z1 = grid.cell_of(b.hi[2], 2);
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) f(x, y, z);
  };
  for (const Box& b : second)
    for_each_cell(b, [&](int x, int y, int z) { ++start[grid.index(x, y, z) + 1]; });
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::uint32_t> members(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t j = 0; j < second.size(); ++j)
    for_each_cell(second[j],
                  [&](int x, int y, int z) { members[fill[grid.index(x, y, z)]++] = j; });

  std::vector<std::uint32_t> found;
  for (std::uint32_t i = 0; i < first.size(); ++i) {
    const Box& a = first[i];
    found.clear();
    for_each_cell(a, [&](int x, int y, int z) {
      const std::size_t c = grid.index(x, y, z);
      for (std::uint32_t m = start[c]; m < start[c + 1]; ++m) {
        const std::uint32_t j = members[m];
        const Box& b = second[j];
        if (!overlap(a, b)) continue;
        // Report from the cell of the intersection's low corner only: that cell lies in both
        // boxes' cell ranges (monotone cell map), so each pair is reported exactly once.
        if (grid.cell_of(std::max(a.lo[0], b.lo[0]), 0) == x &&
            grid.cell_of(std::max(a.lo[1], b.lo[1]), 1) == y &&
            grid.cell_of(std::max(a.lo[2], b.lo[2]), 2) == z)
          found.push_back(j);
      }
    });
    std::sort(found.begin(), found.end());
    for (const std::uint32_t j : found) pairs.emplace_back(i, j);
  }
  return pairs;
}

}  // namespace exactccd::sim
