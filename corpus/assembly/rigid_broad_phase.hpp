// The demonstration's broad phase of arc boxes for one rigid body moving against a static mesh
// over a step, and of swept chord boxes for the chord approximation. The exact path runs through
// exactccd::Scene (which adds the cylinder ranges, proofs/scene.md#cylinder-ranges); this one
// stays for the chord and for counting the pairs of boxes alone. Certified: it never drops a
// pair that meets during the step.
//
//  * Arc boxes: a box holding every position of a vertex over s in [0, 1] under a RigidMotion,
//    the intersection of two certified enclosures: the ball about the moving axis point
//    (radius |x0 - a|, a on the rotation axis) and the box of the chord of the rotation
//    inflated by the sagitta bound |x0 - a| |q|^2 / 2, each shifted along the translation.
//    PROOF: proofs/rigid_ccd.md#arc-boxes
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::assembly {

/// A closed box.
struct Box3 {
  std::array<double, 3> lo, hi;
};

/// The certified box of x0's path over s in [0, 1]. PROOF: proofs/rigid_ccd.md#arc-boxes
Box3 arc_box(const RigidMotion& motion, const Eigen::Vector3d& x0);

/// A bounding volume hierarchy over Box3 (median splits on the centroids' widest axis).
class Bvh3 {
 public:
  void build(const std::vector<Box3>& boxes);
  /// New boxes for the same primitives, the shape kept.
  void refit(const std::vector<Box3>& boxes);
  bool empty() const { return nodes_.empty(); }
  std::size_t size() const { return boxes_.size(); }
  /// f(i, j) for every primitive i of *this and j of other whose boxes overlap.
  template <class F>
  void for_each_overlap(const Bvh3& other, F&& f) const;

 private:
  struct Node {
    Box3 box;
    std::uint32_t first = 0;  ///< leaf: order_[first, first + count); inner: the right child
    std::uint32_t count = 0;  ///< 0 for an inner node (its left child is the next node)
  };
  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end,
                           std::vector<std::array<double, 3>>& centroids);
  void refit_node(std::uint32_t n);
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
  std::vector<Box3> boxes_;
};

bool overlap(const Box3& a, const Box3& b);

/// Candidate pairs of one step, each (moving primitive, static primitive).
struct Candidates {
  std::vector<std::pair<std::int32_t, std::int32_t>> moving_vertex_static_face;
  std::vector<std::pair<std::int32_t, std::int32_t>> static_vertex_moving_face;
  std::vector<std::pair<std::int32_t, std::int32_t>> edge_edge;  ///< (moving edge, static edge)
  std::size_t size() const {
    return moving_vertex_static_face.size() + static_vertex_moving_face.size() + edge_edge.size();
  }
};

/// One moving mesh against one static mesh, over a sequence of steps. The static side's boxes
/// and hierarchies are built once; the moving side's hierarchies are built at the first step and
/// refitted after.
class RigidBroadPhase {
 public:
  RigidBroadPhase(const Positions& static_positions, const Triangles& static_triangles,
                  const Triangles& moving_triangles);

  /// Pairs whose arc boxes overlap while the moving mesh, at `start` when s = 0, moves with
  /// `motion`.
  Candidates rigid_step(const Positions& start, const RigidMotion& motion);

  /// Pairs that may meet while every moving vertex goes on the straight line from `start` to
  /// `end` (the chord approximation): swept boxes only.
  Candidates linear_step(const Positions& start, const Positions& end);

  const Edges& static_edges() const { return static_edges_; }
  const Edges& moving_edges() const { return moving_edges_; }

 private:
  Candidates traverse(const std::vector<Box3>& vertex_boxes, const std::vector<Box3>& edge_boxes,
                      const std::vector<Box3>& face_boxes);

  Triangles moving_triangles_;
  Edges static_edges_, moving_edges_;
  Bvh3 static_vertices_, static_edges_bvh_, static_faces_;
  Bvh3 moving_vertices_, moving_edges_bvh_, moving_faces_;
};

// ---- Bvh3::for_each_overlap --------------------------------------------------------------------

template <class F>
void Bvh3::for_each_overlap(const Bvh3& other, F&& f) const {
  if (empty() || other.empty()) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];
    if (!overlap(na.box, nb.box)) continue;
    if (na.count && nb.count) {
      for (std::uint32_t s = na.first; s < na.first + na.count; ++s) {
        const std::uint32_t i = order_[s];
        if (!overlap(boxes_[i], nb.box)) continue;
        for (std::uint32_t u = nb.first; u < nb.first + nb.count; ++u) {
          const std::uint32_t j = other.order_[u];
          if (overlap(boxes_[i], other.boxes_[j])) f(i, j);
        }
      }
      continue;
    }
    // Descend the inner node; of two inner nodes, the one with the larger extent.
    const auto extent = [](const Box3& x) {
      return (x.hi[0] - x.lo[0]) + (x.hi[1] - x.lo[1]) + (x.hi[2] - x.lo[2]);
    };
    if (nb.count || (!na.count && extent(na.box) >= extent(nb.box))) {
      stack.push_back({na.first, b});
      stack.push_back({a + 1, b});
    } else {
      stack.push_back({a, nb.first});
      stack.push_back({a, b + 1});
    }
  }
}

}  // namespace exactccd::assembly
