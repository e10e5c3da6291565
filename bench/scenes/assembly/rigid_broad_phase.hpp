// The demonstration's broad phase for one rigid body moving against a static mesh over a step
// (to be replaced by the Scene's when it has rigid bodies). Certified: it never drops a pair
// that meets during the step.
//
//  * Arc boxes: a box holding every position of a vertex over s in [0, 1] under a RigidMotion,
//    the intersection of two certified enclosures: the ball about the moving axis point
//    (radius |x0 - a|, a on the rotation axis) and the box of the chord of the rotation
//    inflated by the sagitta bound |x0 - a| |q|^2 / 2, each shifted along the translation.
//    PROOF: proofs/rigid_ccd.md#arc-boxes
//  * Cylinder ranges: when the step turns about a line parallel to a coordinate axis and
//    translates along it, every point keeps its distance to that line and moves along it by
//    s d; primitives whose ranges of squared distance to the line, or of the axial coordinate,
//    are disjoint never meet. Coaxial walls that slide past each other with a tiny clearance
//    (where no axis-aligned box can separate them) are culled this way.
//    PROOF: proofs/rigid_ccd.md#cylinder-ranges
//
// Boxes have five coordinates (x, y, z, squared distance to the axis, axial coordinate; the
// last two universal when unused) and two boxes overlap only if they overlap in all five.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::assembly {

/// A closed box in five coordinates (see the file comment).
struct Box5 {
  std::array<double, 5> lo, hi;
};

/// The line through (u, v) parallel to coordinate axis `index` (u, v: the other two coordinates
/// in increasing order).
struct Axis {
  int index = 2;
  double u = 0, v = 0;
};

/// True when `motion` turns about `axis` (its Cayley vector parallel to it and, unless zero, its
/// pivot on it) and translates along it: checked exactly on the doubles.
bool turns_about(const RigidMotion& motion, const Axis& axis);

/// The certified box (first three coordinates) of x0's path over s in [0, 1]; the last two
/// universal. PROOF: proofs/rigid_ccd.md#arc-boxes
Box5 arc_box(const RigidMotion& motion, const Eigen::Vector3d& x0);

/// Squared distance to the axis (lo, hi) and axial coordinate (lo, hi) of a closed primitive
/// at rest, certified. PROOF: proofs/rigid_ccd.md#cylinder-ranges
struct CylinderRange {
  double rho2_lo, rho2_hi, axial_lo, axial_hi;
};
CylinderRange point_range(const Axis& axis, const Eigen::Vector3d& p);
CylinderRange segment_range(const Axis& axis, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
CylinderRange triangle_range(const Axis& axis, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c);

/// A bounding volume hierarchy over Box5 (median splits on the centroids' widest spatial axis).
class Bvh5 {
 public:
  void build(const std::vector<Box5>& boxes);
  /// New boxes for the same primitives, the shape kept.
  void refit(const std::vector<Box5>& boxes);
  bool empty() const { return nodes_.empty(); }
  std::size_t size() const { return boxes_.size(); }
  /// f(i, j) for every primitive i of *this and j of other whose boxes overlap.
  template <class F>
  void for_each_overlap(const Bvh5& other, F&& f) const;

 private:
  struct Node {
    Box5 box;
    std::uint32_t first = 0;  ///< leaf: order_[first, first + count); inner: the right child
    std::uint32_t count = 0;  ///< 0 for an inner node (its left child is the next node)
  };
  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end,
                           std::vector<std::array<double, 3>>& centroids);
  void refit_node(std::uint32_t n);
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
  std::vector<Box5> boxes_;
};

bool overlap(const Box5& a, const Box5& b);

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
  /// `axis`: the line the cylinder ranges refer to (nullopt: boxes only).
  RigidBroadPhase(const Positions& static_positions, const Triangles& static_triangles,
                  const Triangles& moving_triangles, std::optional<Axis> axis);

  /// Pairs that may meet while the moving mesh, at `start` when s = 0, moves with `motion`.
  /// The cylinder ranges are used when the motion turns about the axis (turns_about) and
  /// `use_cylinders`.
  Candidates rigid_step(const Positions& start, const RigidMotion& motion,
                        bool use_cylinders = true);

  /// Pairs that may meet while every moving vertex goes on the straight line from `start` to
  /// `end` (the chord approximation): swept boxes only.
  Candidates linear_step(const Positions& start, const Positions& end);

  /// Where the last step's time went (milliseconds): boxes of the moving primitives (arc boxes
  /// and hulls), their cylinder ranges, the hierarchies' refit and traversal.
  struct Timing {
    double boxes_ms = 0, cylinders_ms = 0, traversal_ms = 0;
  };
  const Timing& last_timing() const { return timing_; }

  const Edges& static_edges() const { return static_edges_; }
  const Edges& moving_edges() const { return moving_edges_; }

 private:
  Candidates traverse(const std::vector<Box5>& vertex_boxes, const std::vector<Box5>& edge_boxes,
                      const std::vector<Box5>& face_boxes);

  Triangles moving_triangles_;
  Edges static_edges_, moving_edges_;
  std::optional<Axis> axis_;
  Bvh5 static_vertices_, static_edges_bvh_, static_faces_;
  Bvh5 moving_vertices_, moving_edges_bvh_, moving_faces_;
  Timing timing_;
};

// ---- Bvh5::for_each_overlap --------------------------------------------------------------------

template <class F>
void Bvh5::for_each_overlap(const Bvh5& other, F&& f) const {
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
    // Descend the inner node; of two inner nodes, the one with the larger spatial extent.
    const auto extent = [](const Box5& x) {
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
