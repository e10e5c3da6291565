// A bounding volume hierarchy over closed axis-aligned boxes, one box per primitive.
//
// Exactness: boxes are built and merged with min/max of input doubles and tested with
// comparisons only, so "boxes overlap" is decided exactly and no overlapping pair of primitive
// boxes is ever skipped. The tree's shape (split planes from rounded centroids) affects speed
// only. PROOF: proofs/scene.md#broad-phase
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "core/predicates/fp_environment.hpp"

namespace exactccd::scene {

/// A closed box: lo[k] <= hi[k].
struct Box {
  std::array<double, 3> lo, hi;
};

/// True when the closed boxes share a point (touching counts).
inline bool overlap(const Box& a, const Box& b) {
  return !(a.hi[0] < b.lo[0] || b.hi[0] < a.lo[0] || a.hi[1] < b.lo[1] || b.hi[1] < a.lo[1] ||
           a.hi[2] < b.lo[2] || b.hi[2] < a.lo[2]);
}

/// Raises the upper corner by delta >= 0, each sum rounded upwards (the caller holds upward
/// rounding): two boxes so raised overlap whenever the originals are at most delta apart on
/// every axis, since fl(hi + delta) >= hi + delta >= the other's lo. The lower corner stays, so
/// a raised pair overlaps exactly when no axis has hi1 + delta < lo2 or hi2 + delta < lo1 with
/// upward rounding: the per-pair culling with delta. PROOF: proofs/scene.md#min-separation
EXACTCCD_CERTIFIED void raise_upper_corner(Box& box, double delta) {
  for (int k = 0; k < 3; ++k) box.hi[k] = box.hi[k] + delta;
}

/// The smallest box holding both.
inline Box merge(const Box& a, const Box& b) {
  Box r;
  for (int k = 0; k < 3; ++k) {
    r.lo[k] = std::min(a.lo[k], b.lo[k]);
    r.hi[k] = std::max(a.hi[k], b.hi[k]);
  }
  return r;
}

/// The box of a point.
template <class Point>
Box point_box(const Point& p) {
  return {{p[0], p[1], p[2]}, {p[0], p[1], p[2]}};
}

/// Grows `box` to hold the point.
template <class Point>
void grow(Box& box, const Point& p) {
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::min(box.lo[k], static_cast<double>(p[k]));
    box.hi[k] = std::max(box.hi[k], static_cast<double>(p[k]));
  }
}

class Bvh {
 public:
  static constexpr int max_leaf_size = 4;

  struct Node {
    Box box;
    /// Inner node: the left child is the next node, the right child is node `first`.
    /// Leaf: the primitives order_[first .. first + count).
    std::uint32_t first = 0;
    std::uint32_t count = 0;  ///< 0 for an inner node
    bool leaf() const { return count != 0; }
  };

  /// Builds the tree over one box per primitive (top-down, median split on the widest axis of
  /// the centroids). An empty list gives an empty tree.
  void build(const std::vector<Box>& boxes);

  /// New boxes for the same primitives (same count): node boxes recomputed bottom-up, the shape
  /// kept. Throws std::invalid_argument on a count mismatch.
  void refit(const std::vector<Box>& boxes);

  /// True when refits have loosened the tree so far that a rebuild pays: the summed surface of
  /// the inner nodes, relative to the summed surface of the primitive boxes, has more than
  /// doubled since the last build. (A speed heuristic only: any tree gives exact answers.)
  bool degraded() const;

  /// refit, then build afresh when that left the tree degraded. Returns true when it rebuilt.
  bool refit_or_rebuild(const std::vector<Box>& boxes) {
    refit(boxes);
    if (!degraded()) return false;
    build(boxes);
    return true;
  }

  bool empty() const { return nodes_.empty(); }
  /// The box of primitive i as last built or refitted.
  const Box& box(std::uint32_t i) const { return boxes_[i]; }
  /// The box of every primitive (the root's); the tree must not be empty.
  const Box& bounds() const { return nodes_.front().box; }

  /// Calls f(i, j) for every primitive i of `*this` and j of `other` whose boxes overlap, each
  /// pair once. Node pairs are spread over TBB tasks: f is called concurrently.
  template <class F>
  void parallel_for_each_overlap(const Bvh& other, F&& f) const {
    parallel_for_each_overlap(other, f, [](std::uint32_t, std::uint32_t) { return true; });
  }
  /// The same, skipping every node pair (a, b) (node indices of *this and other) for which
  /// keep(a, b) is false, and the pairs of primitives below it: keep must be false only when
  /// no primitive pair below the two nodes is wanted. Called concurrently.
  template <class F, class Keep>
  void parallel_for_each_overlap(const Bvh& other, F&& f, const Keep& keep) const {
    if (empty() || other.empty()) return;
    // The caller may be a worker running with the host's FP state: the splitting compares boxes
    // and calls keep, whose time spans subtract (proofs/filters.md#fp-environment).
    const predicates::RoundToNearestGuard fp;
    std::vector<Task> tasks{{0, 0, false}};
    split_tasks(other, tasks, keep);
    run_tasks(other, tasks, f, keep);
  }
  /// Per node, the merge of `per_primitive[i]` over the primitives i below it (`merge(x, y)`
  /// an associative union of two values; one value per primitive, by primitive index).
  template <class T, class Merge>
  std::vector<T> node_values(const std::vector<T>& per_primitive, const Merge& merge) const {
    std::vector<T> out(nodes_.size());
    // Pre-order: children follow their parent, so a reverse sweep meets them first.
    for (std::size_t n = nodes_.size(); n-- > 0;) {
      const Node& node = nodes_[n];
      if (node.leaf()) {
        T v = per_primitive[order_[node.first]];
        for (std::uint32_t s = node.first + 1; s < node.first + node.count; ++s)
          v = merge(v, per_primitive[order_[s]]);
        out[n] = v;
      } else {
        out[n] = merge(out[n + 1], out[node.first]);
      }
    }
    return out;
  }

  /// Calls f(i, j), i != j, once for every unordered pair of primitives whose boxes overlap
  /// (in some order of i and j). Node pairs are spread over TBB tasks: f is called concurrently.
  template <class F>
  void parallel_for_each_self_overlap(F&& f) const {
    parallel_for_each_self_overlap(f, [](std::uint32_t, std::uint32_t) { return true; });
  }
  /// The same, skipping every pair of distinct nodes (a, b) for which keep(a, b) is false, and
  /// the pairs of primitives below it (keep as for parallel_for_each_overlap).
  template <class F, class Keep>
  void parallel_for_each_self_overlap(F&& f, const Keep& keep) const {
    if (empty()) return;
    const predicates::RoundToNearestGuard fp;  // as in parallel_for_each_overlap
    std::vector<Task> tasks{{0, 0, true}};
    split_tasks(*this, tasks, keep);
    run_tasks(*this, tasks, f, keep);
  }

 private:
  /// A pair of nodes still to traverse; `self`: both are the same node of a self traversal.
  struct Task {
    std::uint32_t a, b;
    bool self;
  };
  static constexpr std::size_t target_tasks = 256;
  static constexpr std::size_t nodes_per_task = 64;

  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end,
                           std::vector<std::array<double, 3>>& centroids);
  double inner_surface_ratio() const;

  std::uint32_t left(std::uint32_t n) const { return n + 1; }
  std::uint32_t right(std::uint32_t n) const { return nodes_[n].first; }

  template <class F>
  void leaf_pairs(const Bvh& other, const Node& na, const Node& nb, F& f) const {
    for (std::uint32_t s = na.first; s < na.first + na.count; ++s) {
      const std::uint32_t i = order_[s];
      const Box& bi = boxes_[i];
      if (!overlap(bi, nb.box)) continue;
      for (std::uint32_t u = nb.first; u < nb.first + nb.count; ++u) {
        const std::uint32_t j = other.order_[u];
        if (overlap(bi, other.boxes_[j])) f(i, j);
      }
    }
  }

  template <class F, class Keep>
  void overlap_nodes(const Bvh& other, std::uint32_t a, std::uint32_t b, F& f,
                     const Keep& keep) const {
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];
    if (!overlap(na.box, nb.box) || !keep(a, b)) return;
    if (na.leaf() && nb.leaf()) return leaf_pairs(other, na, nb, f);
    // Descend the node that is not a leaf; of two inner nodes, the larger one.
    if (nb.leaf() || (!na.leaf() && size_of(na.box) >= size_of(nb.box))) {
      overlap_nodes(other, left(a), b, f, keep);
      overlap_nodes(other, right(a), b, f, keep);
    } else {
      overlap_nodes(other, a, other.left(b), f, keep);
      overlap_nodes(other, a, other.right(b), f, keep);
    }
  }

  template <class F, class Keep>
  void self_nodes(std::uint32_t a, F& f, const Keep& keep) const {
    const Node& na = nodes_[a];
    if (na.leaf()) {
      for (std::uint32_t s = na.first; s < na.first + na.count; ++s)
        for (std::uint32_t u = s + 1; u < na.first + na.count; ++u)
          if (overlap(boxes_[order_[s]], boxes_[order_[u]])) f(order_[s], order_[u]);
      return;
    }
    self_nodes(left(a), f, keep);
    self_nodes(right(a), f, keep);
    overlap_nodes(*this, left(a), right(a), f, keep);
  }

  static double size_of(const Box& b) {
    return (b.hi[0] - b.lo[0]) + (b.hi[1] - b.lo[1]) + (b.hi[2] - b.lo[2]);
  }

  /// Expands tasks breadth-first until there are enough to keep the threads busy (fewer for
  /// small trees, where a task would cost more than its work); every overlapping pair is
  /// reached from exactly one task. Node pairs that do not overlap or that keep rejects are
  /// dropped on the way (keep as for parallel_for_each_overlap).
  template <class Keep>
  void split_tasks(const Bvh& other, std::vector<Task>& tasks, const Keep& keep) const {
    const std::size_t target =
        std::min(target_tasks, (nodes_.size() + other.nodes_.size()) / nodes_per_task + 1);
    for (int round = 0; round < 32 && tasks.size() < target; ++round) {
      std::vector<Task> next;
      bool split_any = false;
      for (const Task& t : tasks) {
        const Node& na = nodes_[t.a];
        const Node& nb = other.nodes_[t.b];
        if (t.self) {
          if (na.leaf()) {
            next.push_back(t);
            continue;
          }
          next.push_back({left(t.a), left(t.a), true});
          next.push_back({right(t.a), right(t.a), true});
          next.push_back({left(t.a), right(t.a), false});
          split_any = true;
          continue;
        }
        if (!overlap(na.box, nb.box) || !keep(t.a, t.b)) continue;
        if (na.leaf() && nb.leaf()) {
          next.push_back(t);
        } else if (nb.leaf() || (!na.leaf() && size_of(na.box) >= size_of(nb.box))) {
          next.push_back({left(t.a), t.b, false});
          next.push_back({right(t.a), t.b, false});
          split_any = true;
        } else {
          next.push_back({t.a, other.left(t.b), false});
          next.push_back({t.a, other.right(t.b), false});
          split_any = true;
        }
      }
      tasks.swap(next);
      if (!split_any) break;
    }
  }

  template <class F, class Keep>
  void run_tasks(const Bvh& other, const std::vector<Task>& tasks, F& f, const Keep& keep) const {
    if (tasks.size() == 1) {  // a small tree: no task to spawn (the caller holds the FP state)
      const Task& t = tasks.front();
      return t.self ? self_nodes(t.a, f, keep) : overlap_nodes(other, t.a, t.b, f, keep);
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tasks.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        // A worker may run with the host's FP state: box comparisons must not
                        // read subnormals as zero (proofs/filters.md#fp-environment).
                        const predicates::RoundToNearestGuard fp;
                        for (std::size_t k = range.begin(); k != range.end(); ++k) {
                          const Task& t = tasks[k];
                          if (t.self)
                            self_nodes(t.a, f, keep);
                          else
                            overlap_nodes(other, t.a, t.b, f, keep);
                        }
                      });
  }

  std::vector<Node> nodes_;           ///< pre-order: a node's left child follows it
  std::vector<std::uint32_t> order_;  ///< primitives in leaf order
  std::vector<Box> boxes_;            ///< one per primitive, by primitive index
  double built_ratio_ = 0.0;          ///< inner_surface_ratio() right after the last build
};

}  // namespace exactccd::scene
