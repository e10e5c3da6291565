#include "corpus/assembly/rigid_broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "corpus/assembly/lock_and_key.hpp"
#include "core/predicates/interval.hpp"

namespace exactccd::assembly {

namespace {

using predicates::Interval;
using Eigen::Vector3d;

Box3 point_box(const Vector3d& p) {
  Box3 b;
  for (int k = 0; k < 3; ++k) b.lo[k] = b.hi[k] = p[k];
  return b;
}

void grow(Box3& b, const Box3& o) {
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = std::min(b.lo[k], o.lo[k]);
    b.hi[k] = std::max(b.hi[k], o.hi[k]);
  }
}

/// Boxes of edges and faces: the hull of their vertices' boxes.
void primitive_boxes(const std::vector<Box3>& v, const Edges& e, const Triangles& f,
                     std::vector<Box3>& edge_boxes, std::vector<Box3>& face_boxes) {
  edge_boxes.resize(static_cast<std::size_t>(e.rows()));
  for (Eigen::Index i = 0; i < e.rows(); ++i) {
    Box3 b = v[static_cast<std::size_t>(e(i, 0))];
    grow(b, v[static_cast<std::size_t>(e(i, 1))]);
    edge_boxes[static_cast<std::size_t>(i)] = b;
  }
  face_boxes.resize(static_cast<std::size_t>(f.rows()));
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    Box3 b = v[static_cast<std::size_t>(f(i, 0))];
    grow(b, v[static_cast<std::size_t>(f(i, 1))]);
    grow(b, v[static_cast<std::size_t>(f(i, 2))]);
    face_boxes[static_cast<std::size_t>(i)] = b;
  }
}

}  // namespace

bool overlap(const Box3& a, const Box3& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

Box3 arc_box(const RigidMotion& m, const Vector3d& x0) {
  if (!m.pivot.allFinite() || !m.translation.allFinite() || !m.cayley.allFinite() ||
      !x0.allFinite())
    throw std::invalid_argument("arc_box: non-finite input");
  const predicates::RoundingGuard upward;
  Box3 box;
  const Vector3d& c = m.pivot;
  const Vector3d& d = m.translation;
  const Vector3d& q = m.cayley;
  if (q.isZero(0)) {  // a translation: the segment's box
    for (int k = 0; k < 3; ++k) {
      const Interval end = Interval(x0[k]) + d[k];
      box.lo[k] = std::min(x0[k], end.inf());
      box.hi[k] = std::max(x0[k], end.sup());
    }
    return box;
  }
  Interval r[3], qi[3];
  for (int k = 0; k < 3; ++k) {
    r[k] = Interval(x0[k]) - c[k];
    qi[k] = Interval(q[k]);
  }
  const Interval qq = CGAL::square(qi[0]) + CGAL::square(qi[1]) + CGAL::square(qi[2]);
  const Interval qr = qi[0] * r[0] + qi[1] * r[1] + qi[2] * r[2];
  const Interval qxr[3] = {qi[1] * r[2] - qi[2] * r[1], qi[2] * r[0] - qi[0] * r[2],
                           qi[0] * r[1] - qi[1] * r[0]};
  // a = c + lambda q on the axis, lambda any double (the projection's, rounded: tight).
  double lambda = (x0 - c).dot(q) / q.squaredNorm();
  if (!std::isfinite(lambda)) lambda = 0;
  Interval a[3], ra2 = 0;
  for (int k = 0; k < 3; ++k) {
    a[k] = Interval(c[k]) + Interval(lambda) * q[k];
    ra2 += CGAL::square(Interval(x0[k]) - a[k]);
  }
  const double radius = CGAL::sqrt(ra2).sup();                 // >= |x0 - a| >= the arc's radius
  const double sagitta = (Interval(radius) * qq / 2).sup();     // >= radius (1 - cos(theta / 2))
  for (int k = 0; k < 3; ++k) {
    // y1 = c + C(q) r: the rotated end without the translation.
    const Interval y1 = Interval(c[k]) + ((1 - qq) * r[k] + 2 * qr * qi[k] + 2 * qxr[k]) / (1 + qq);
    const double dlo = std::min(0.0, d[k]), dhi = std::max(0.0, d[k]);
    const double chord_lo =
        (Interval(std::min(x0[k], y1.inf())) + dlo - sagitta).inf();
    const double chord_hi = (Interval(std::max(x0[k], y1.sup())) + dhi + sagitta).sup();
    const double ball_lo = (a[k] + dlo - radius).inf();
    const double ball_hi = (a[k] + dhi + radius).sup();
    box.lo[k] = std::max(chord_lo, ball_lo);
    box.hi[k] = std::min(chord_hi, ball_hi);
  }
  return box;
}

// ---- Bvh3 ------------------------------------------------------------------------------------

void Bvh3::build(const std::vector<Box3>& boxes) {
  boxes_ = boxes;
  nodes_.clear();
  order_.resize(boxes.size());
  if (boxes.empty()) return;
  std::vector<std::array<double, 3>> centroids(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    order_[i] = static_cast<std::uint32_t>(i);
    for (int k = 0; k < 3; ++k) centroids[i][k] = 0.5 * boxes[i].lo[k] + 0.5 * boxes[i].hi[k];
  }
  nodes_.reserve(2 * boxes.size());
  build_node(0, static_cast<std::uint32_t>(boxes.size()), centroids);
}

std::uint32_t Bvh3::build_node(std::uint32_t begin, std::uint32_t end,
                               std::vector<std::array<double, 3>>& centroids) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Box3 box = boxes_[order_[begin]];
  std::array<double, 3> clo = centroids[order_[begin]], chi = clo;
  for (std::uint32_t s = begin; s < end; ++s) {
    grow(box, boxes_[order_[s]]);
    for (int k = 0; k < 3; ++k) {
      clo[k] = std::min(clo[k], centroids[order_[s]][k]);
      chi[k] = std::max(chi[k], centroids[order_[s]][k]);
    }
  }
  nodes_[index].box = box;
  if (end - begin <= 4) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t x, std::uint32_t y) {
                     return centroids[x][axis] < centroids[y][axis];
                   });
  build_node(begin, mid, centroids);
  const std::uint32_t right = build_node(mid, end, centroids);
  nodes_[index].first = right;
  return index;
}

void Bvh3::refit(const std::vector<Box3>& boxes) {
  if (boxes.size() != boxes_.size()) throw std::invalid_argument("Bvh3::refit: count mismatch");
  boxes_ = boxes;
  if (!nodes_.empty()) refit_node(0);
}

void Bvh3::refit_node(std::uint32_t n) {
  Node& node = nodes_[n];
  if (node.count) {
    node.box = boxes_[order_[node.first]];
    for (std::uint32_t s = node.first + 1; s < node.first + node.count; ++s)
      grow(node.box, boxes_[order_[s]]);
    return;
  }
  refit_node(n + 1);
  refit_node(node.first);
  node.box = nodes_[n + 1].box;
  grow(node.box, nodes_[node.first].box);
}

// ---- RigidBroadPhase -------------------------------------------------------------------------

RigidBroadPhase::RigidBroadPhase(const Positions& static_positions,
                                 const Triangles& static_triangles,
                                 const Triangles& moving_triangles)
    : moving_triangles_(moving_triangles),
      static_edges_(unique_edges(static_triangles)),
      moving_edges_(unique_edges(moving_triangles)) {
  std::vector<Box3> v(static_cast<std::size_t>(static_positions.rows()));
  for (Eigen::Index i = 0; i < static_positions.rows(); ++i)
    v[static_cast<std::size_t>(i)] = point_box(static_positions.row(i).transpose());
  std::vector<Box3> e, f;
  primitive_boxes(v, static_edges_, static_triangles, e, f);
  static_vertices_.build(v);
  static_edges_bvh_.build(e);
  static_faces_.build(f);
}

Candidates RigidBroadPhase::rigid_step(const Positions& start, const RigidMotion& motion) {
  std::vector<Box3> v(static_cast<std::size_t>(start.rows()));
  for (Eigen::Index i = 0; i < start.rows(); ++i)
    v[static_cast<std::size_t>(i)] = arc_box(motion, start.row(i).transpose());
  std::vector<Box3> e, f;
  primitive_boxes(v, moving_edges_, moving_triangles_, e, f);
  return traverse(v, e, f);
}

Candidates RigidBroadPhase::linear_step(const Positions& start, const Positions& end) {
  if (start.rows() != end.rows()) throw std::invalid_argument("linear_step: row mismatch");
  std::vector<Box3> v(static_cast<std::size_t>(start.rows()));
  for (Eigen::Index i = 0; i < start.rows(); ++i) {
    Box3 b = point_box(start.row(i).transpose());
    grow(b, point_box(end.row(i).transpose()));
    v[static_cast<std::size_t>(i)] = b;
  }
  std::vector<Box3> e, f;
  primitive_boxes(v, moving_edges_, moving_triangles_, e, f);
  return traverse(v, e, f);
}

Candidates RigidBroadPhase::traverse(const std::vector<Box3>& v, const std::vector<Box3>& e,
                                     const std::vector<Box3>& f) {
  if (moving_vertices_.empty() && !v.empty()) {
    moving_vertices_.build(v);
    moving_edges_bvh_.build(e);
    moving_faces_.build(f);
  } else {
    moving_vertices_.refit(v);
    moving_edges_bvh_.refit(e);
    moving_faces_.refit(f);
  }
  Candidates c;
  moving_vertices_.for_each_overlap(static_faces_, [&](std::uint32_t i, std::uint32_t j) {
    c.moving_vertex_static_face.emplace_back(i, j);
  });
  moving_faces_.for_each_overlap(static_vertices_, [&](std::uint32_t i, std::uint32_t j) {
    c.static_vertex_moving_face.emplace_back(i, j);
  });
  moving_edges_bvh_.for_each_overlap(static_edges_bvh_, [&](std::uint32_t i, std::uint32_t j) {
    c.edge_edge.emplace_back(i, j);
  });
  // A fixed order, whatever the traversal's.
  for (auto* list : {&c.moving_vertex_static_face, &c.static_vertex_moving_face, &c.edge_edge})
    std::sort(list->begin(), list->end());
  return c;
}

}  // namespace exactccd::assembly
