#include "bench/scenes/assembly/rigid_broad_phase.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "bench/scenes/assembly/lock_and_key.hpp"
#include "filters/interval.hpp"

namespace exactccd::assembly {

namespace {

using filters::Interval;
using Clock = std::chrono::steady_clock;

double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

using Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The two coordinates across the axis, relative to it, as exact intervals of their rounding.
struct Across {
  Interval u, v;
};

Across across(const Axis& axis, const Vector3d& p) {
  const int iu = axis.index == 0 ? 1 : 0, iv = axis.index == 2 ? 1 : 2;
  return {Interval(p[iu]) - axis.u, Interval(p[iv]) - axis.v};
}

Interval norm2(const Across& a) { return CGAL::square(a.u) + CGAL::square(a.v); }

/// a x b in the plane across the axis.
Interval cross2(const Across& a, const Across& b) { return a.u * b.v - a.v * b.u; }

/// True when p and q have the same coordinates across the axis.
bool same_across(const Axis& axis, const Vector3d& p, const Vector3d& q) {
  const int iu = axis.index == 0 ? 1 : 0, iv = axis.index == 2 ? 1 : 2;
  return p[iu] == q[iu] && p[iv] == q[iv];
}

/// A lower bound of the squared distance from the axis to the segment [a, b] (projected; `same`:
/// a and b project to the same point): the closest point is an end when the foot of the
/// perpendicular lies beyond it, and the line's distance bounds the segment's from below in
/// every case.
double segment_rho2_lo(const Across& a, const Across& b, bool same) {
  if (same) return norm2(a).inf();
  const Across ab{b.u - a.u, b.v - a.v};
  const Interval len2 = norm2(ab);
  if (len2.inf() <= 0) return 0;                                       // too short to tell
  if ((a.u * ab.u + a.v * ab.v).inf() >= 0) return norm2(a).inf();    // closest: a
  if ((b.u * ab.u + b.v * ab.v).sup() <= 0) return norm2(b).inf();    // closest: b
  const Interval line = CGAL::square(cross2(a, b)) / len2;            // distance to the line
  return std::max(0.0, line.inf());
}

Box5 universal_cylinder(Box5 b) {
  b.lo[3] = 0;
  b.hi[3] = kInf;
  b.lo[4] = -kInf;
  b.hi[4] = kInf;
  return b;
}

Box5 point_box(const Vector3d& p) {
  Box5 b;
  for (int k = 0; k < 3; ++k) b.lo[k] = b.hi[k] = p[k];
  return universal_cylinder(b);
}

void grow(Box5& b, const Box5& o) {
  for (int k = 0; k < 5; ++k) {
    b.lo[k] = std::min(b.lo[k], o.lo[k]);
    b.hi[k] = std::max(b.hi[k], o.hi[k]);
  }
}

void set_cylinder(Box5& b, const CylinderRange& r) {
  b.lo[3] = r.rho2_lo;
  b.hi[3] = r.rho2_hi;
  b.lo[4] = r.axial_lo;
  b.hi[4] = r.axial_hi;
}

/// Cylinder ranges of every vertex, edge and face of a mesh at rest.
struct MeshRanges {
  std::vector<CylinderRange> vertices, edges, faces;
};

MeshRanges mesh_ranges(const Axis& axis, const Positions& x, const Edges& e, const Triangles& f) {
  MeshRanges r;
  const auto row = [&](std::int32_t i) { return Vector3d(x.row(i).transpose()); };
  r.vertices.reserve(static_cast<std::size_t>(x.rows()));
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    r.vertices.push_back(point_range(axis, row(static_cast<std::int32_t>(i))));
  r.edges.reserve(static_cast<std::size_t>(e.rows()));
  for (Eigen::Index i = 0; i < e.rows(); ++i)
    r.edges.push_back(segment_range(axis, row(e(i, 0)), row(e(i, 1))));
  r.faces.reserve(static_cast<std::size_t>(f.rows()));
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    r.faces.push_back(triangle_range(axis, row(f(i, 0)), row(f(i, 1)), row(f(i, 2))));
  return r;
}

/// Shifts a range's axial coordinate by s d for s in [0, 1] (rounded outward).
CylinderRange swept_axially(CylinderRange r, double d) {
  r.axial_lo = (Interval(r.axial_lo) + std::min(0.0, d)).inf();
  r.axial_hi = (Interval(r.axial_hi) + std::max(0.0, d)).sup();
  return r;
}

/// Boxes of edges and faces: the hull of their vertices' boxes.
void primitive_boxes(const std::vector<Box5>& v, const Edges& e, const Triangles& f,
                     std::vector<Box5>& edge_boxes, std::vector<Box5>& face_boxes) {
  edge_boxes.resize(static_cast<std::size_t>(e.rows()));
  for (Eigen::Index i = 0; i < e.rows(); ++i) {
    Box5 b = v[static_cast<std::size_t>(e(i, 0))];
    grow(b, v[static_cast<std::size_t>(e(i, 1))]);
    edge_boxes[static_cast<std::size_t>(i)] = b;
  }
  face_boxes.resize(static_cast<std::size_t>(f.rows()));
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    Box5 b = v[static_cast<std::size_t>(f(i, 0))];
    grow(b, v[static_cast<std::size_t>(f(i, 1))]);
    grow(b, v[static_cast<std::size_t>(f(i, 2))]);
    face_boxes[static_cast<std::size_t>(i)] = b;
  }
}

}  // namespace

bool overlap(const Box5& a, const Box5& b) {
  for (int k = 0; k < 5; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

bool turns_about(const RigidMotion& m, const Axis& axis) {
  if (axis.index < 0 || axis.index > 2) return false;
  const int iu = axis.index == 0 ? 1 : 0, iv = axis.index == 2 ? 1 : 2;
  if (m.cayley[iu] != 0 || m.cayley[iv] != 0) return false;
  if (m.translation[iu] != 0 || m.translation[iv] != 0) return false;
  if (m.cayley[axis.index] == 0) return true;  // a translation along the axis
  return m.pivot[iu] == axis.u && m.pivot[iv] == axis.v;
}

Box5 arc_box(const RigidMotion& m, const Vector3d& x0) {
  if (!m.pivot.allFinite() || !m.translation.allFinite() || !m.cayley.allFinite() ||
      !x0.allFinite())
    throw std::invalid_argument("arc_box: non-finite input");
  const filters::RoundingGuard upward;
  Box5 box;
  const Vector3d& c = m.pivot;
  const Vector3d& d = m.translation;
  const Vector3d& q = m.cayley;
  if (q.isZero(0)) {  // a translation: the segment's box
    for (int k = 0; k < 3; ++k) {
      const Interval end = Interval(x0[k]) + d[k];
      box.lo[k] = std::min(x0[k], end.inf());
      box.hi[k] = std::max(x0[k], end.sup());
    }
    return universal_cylinder(box);
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
  return universal_cylinder(box);
}

CylinderRange point_range(const Axis& axis, const Vector3d& p) {
  const filters::RoundingGuard upward;
  const Interval rho2 = norm2(across(axis, p));
  return {rho2.inf(), rho2.sup(), p[axis.index], p[axis.index]};
}

CylinderRange segment_range(const Axis& axis, const Vector3d& a, const Vector3d& b) {
  const filters::RoundingGuard upward;
  const Across pa = across(axis, a), pb = across(axis, b);
  return {segment_rho2_lo(pa, pb, same_across(axis, a, b)),
          std::max(norm2(pa).sup(), norm2(pb).sup()),
          std::min(a[axis.index], b[axis.index]), std::max(a[axis.index], b[axis.index])};
}

CylinderRange triangle_range(const Axis& axis, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  const filters::RoundingGuard upward;
  const Across pa = across(axis, a), pb = across(axis, b), pc = across(axis, c);
  // The axis misses the projected triangle when two of the orientations of (edge, axis point)
  // have certainly opposite signs; then the closest point lies on an edge.
  const int s[3] = {filters::certain_strict_sign(cross2(pa, pb)),
                    filters::certain_strict_sign(cross2(pb, pc)),
                    filters::certain_strict_sign(cross2(pc, pa))};
  const bool outside = (s[0] * s[1] < 0) || (s[1] * s[2] < 0) || (s[2] * s[0] < 0);
  const double lo = outside ? std::min({segment_rho2_lo(pa, pb, same_across(axis, a, b)),
                                        segment_rho2_lo(pb, pc, same_across(axis, b, c)),
                                        segment_rho2_lo(pc, pa, same_across(axis, c, a))})
                            : 0.0;
  const double hi = std::max({norm2(pa).sup(), norm2(pb).sup(), norm2(pc).sup()});
  const int i = axis.index;
  return {lo, hi, std::min({a[i], b[i], c[i]}), std::max({a[i], b[i], c[i]})};
}

// ---- Bvh5 ------------------------------------------------------------------------------------

void Bvh5::build(const std::vector<Box5>& boxes) {
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

std::uint32_t Bvh5::build_node(std::uint32_t begin, std::uint32_t end,
                               std::vector<std::array<double, 3>>& centroids) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Box5 box = boxes_[order_[begin]];
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

void Bvh5::refit(const std::vector<Box5>& boxes) {
  if (boxes.size() != boxes_.size()) throw std::invalid_argument("Bvh5::refit: count mismatch");
  boxes_ = boxes;
  if (!nodes_.empty()) refit_node(0);
}

void Bvh5::refit_node(std::uint32_t n) {
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
                                 const Triangles& moving_triangles, std::optional<Axis> axis)
    : moving_triangles_(moving_triangles),
      static_edges_(unique_edges(static_triangles)),
      moving_edges_(unique_edges(moving_triangles)),
      axis_(axis) {
  std::vector<Box5> v(static_cast<std::size_t>(static_positions.rows()));
  for (Eigen::Index i = 0; i < static_positions.rows(); ++i)
    v[static_cast<std::size_t>(i)] = point_box(static_positions.row(i).transpose());
  std::vector<Box5> e, f;
  primitive_boxes(v, static_edges_, static_triangles, e, f);
  if (axis_) {
    const MeshRanges r = mesh_ranges(*axis_, static_positions, static_edges_, static_triangles);
    for (std::size_t i = 0; i < v.size(); ++i) set_cylinder(v[i], r.vertices[i]);
    for (std::size_t i = 0; i < e.size(); ++i) set_cylinder(e[i], r.edges[i]);
    for (std::size_t i = 0; i < f.size(); ++i) set_cylinder(f[i], r.faces[i]);
  }
  static_vertices_.build(v);
  static_edges_bvh_.build(e);
  static_faces_.build(f);
}

Candidates RigidBroadPhase::rigid_step(const Positions& start, const RigidMotion& motion,
                                       bool use_cylinders) {
  const auto t0 = Clock::now();
  std::vector<Box5> v(static_cast<std::size_t>(start.rows()));
  for (Eigen::Index i = 0; i < start.rows(); ++i)
    v[static_cast<std::size_t>(i)] = arc_box(motion, start.row(i).transpose());
  std::vector<Box5> e, f;
  primitive_boxes(v, moving_edges_, moving_triangles_, e, f);
  const auto t1 = Clock::now();
  if (use_cylinders && axis_ && turns_about(motion, *axis_)) {
    // Distances to the axis stay; the axial coordinate moves by s d.
    const double d = motion.translation[axis_->index];
    const MeshRanges r = mesh_ranges(*axis_, start, moving_edges_, moving_triangles_);
    for (std::size_t i = 0; i < v.size(); ++i) set_cylinder(v[i], swept_axially(r.vertices[i], d));
    for (std::size_t i = 0; i < e.size(); ++i) set_cylinder(e[i], swept_axially(r.edges[i], d));
    for (std::size_t i = 0; i < f.size(); ++i) set_cylinder(f[i], swept_axially(r.faces[i], d));
  }
  const auto t2 = Clock::now();
  Candidates c = traverse(v, e, f);
  timing_ = {ms(t0, t1), ms(t1, t2), ms(t2, Clock::now())};
  return c;
}

Candidates RigidBroadPhase::linear_step(const Positions& start, const Positions& end) {
  if (start.rows() != end.rows()) throw std::invalid_argument("linear_step: row mismatch");
  std::vector<Box5> v(static_cast<std::size_t>(start.rows()));
  for (Eigen::Index i = 0; i < start.rows(); ++i) {
    Box5 b = point_box(start.row(i).transpose());
    grow(b, point_box(end.row(i).transpose()));
    v[static_cast<std::size_t>(i)] = b;
  }
  std::vector<Box5> e, f;
  primitive_boxes(v, moving_edges_, moving_triangles_, e, f);
  return traverse(v, e, f);
}

Candidates RigidBroadPhase::traverse(const std::vector<Box5>& v, const std::vector<Box5>& e,
                                     const std::vector<Box5>& f) {
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
