// Building and refitting the hierarchy (pipeline/scene/bvh.hpp).
#include "pipeline/scene/bvh.hpp"

#include <numeric>
#include <stdexcept>

namespace exactccd::scene {

namespace {

double half_surface(const Box& b) {
  const double dx = b.hi[0] - b.lo[0], dy = b.hi[1] - b.lo[1], dz = b.hi[2] - b.lo[2];
  return dx * dy + dy * dz + dz * dx;
}

}  // namespace

void Bvh::build(const std::vector<Box>& boxes) {
  boxes_ = boxes;
  nodes_.clear();
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (boxes_.empty()) return;
  // Centroids only steer the split; rounding here affects speed, never answers.
  std::vector<std::array<double, 3>> centroids(boxes_.size());
  for (std::size_t i = 0; i < boxes_.size(); ++i)
    for (int k = 0; k < 3; ++k) centroids[i][k] = 0.5 * boxes_[i].lo[k] + 0.5 * boxes_[i].hi[k];
  nodes_.reserve(2 * boxes_.size() / max_leaf_size + 2);
  build_node(0, static_cast<std::uint32_t>(boxes_.size()), centroids);
  built_ratio_ = inner_surface_ratio();
}

std::uint32_t Bvh::build_node(std::uint32_t begin, std::uint32_t end,
                              std::vector<std::array<double, 3>>& centroids) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Box box = boxes_[order_[begin]];
  for (std::uint32_t s = begin + 1; s < end; ++s) box = merge(box, boxes_[order_[s]]);
  nodes_[index].box = box;
  if (end - begin <= static_cast<std::uint32_t>(max_leaf_size)) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  std::array<double, 3> lo = centroids[order_[begin]], hi = lo;
  for (std::uint32_t s = begin + 1; s < end; ++s)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], centroids[order_[s]][k]);
      hi[k] = std::max(hi[k], centroids[order_[s]][k]);
    }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  const std::uint32_t mid = begin + (end - begin) / 2;
  // Ties broken by primitive index: the tree, hence the traversal order, is deterministic.
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = centroids[a][axis], cb = centroids[b][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  build_node(begin, mid, centroids);  // the left child: index + 1
  const std::uint32_t right_child = build_node(mid, end, centroids);
  nodes_[index].first = right_child;
  nodes_[index].count = 0;
  return index;
}

void Bvh::refit(const std::vector<Box>& boxes) {
  if (boxes.size() != boxes_.size())
    throw std::invalid_argument("exactccd: Bvh::refit with a different primitive count");
  boxes_ = boxes;
  // Pre-order numbering: children follow their parent, so a reverse sweep is bottom-up.
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    Node& node = nodes_[n];
    if (node.leaf()) {
      Box box = boxes_[order_[node.first]];
      for (std::uint32_t s = node.first + 1; s < node.first + node.count; ++s)
        box = merge(box, boxes_[order_[s]]);
      node.box = box;
    } else {
      node.box = merge(nodes_[n + 1].box, nodes_[node.first].box);
    }
  }
}

double Bvh::inner_surface_ratio() const {
  double inner = 0.0, leaves = 0.0;
  for (const Node& n : nodes_)
    if (!n.leaf()) inner += half_surface(n.box);
  for (const Box& b : boxes_) leaves += half_surface(b);
  // Point-like primitives (vertices at rest) have zero surface: the root's surface in the
  // denominator keeps the ratio finite and scale-free.
  const double denominator = leaves + half_surface(nodes_.front().box);
  return denominator > 0.0 ? inner / denominator : 0.0;
}

bool Bvh::degraded() const {
  if (nodes_.size() < 3) return false;
  return inner_surface_ratio() > 2.0 * built_ratio_;
}

}  // namespace exactccd::scene
