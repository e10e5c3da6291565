// Cylinder ranges: the broad-phase cull of pairs whose two sides turn about one fixed line.
//
// Boxes cannot separate two coaxial walls that turn past each other with a tiny clearance (a
// key's barrel on a lock's drill pin): at every angle of a step the arc boxes of one wall reach
// into the other's. Distances to the axis can. For the line through p along u (u not
// necessarily of unit length) write w(x) = (x - p) x u and h(x) = (x - p) . u: |w|^2 is |u|^2
// times the squared distance to the line, h is |u| times the height along it. A rotation about
// the line keeps both; a translation by d parallel to u keeps |w| and adds d . u to h. So a
// primitive that moves so keeps its range of |w|^2 and its range of h, widened by
// s (d . u), s in [0, 1]; two primitives whose |w|^2 ranges or h ranges are disjoint never share
// a point during the motion.
//
// Every bound is certified: interval arithmetic (Interval_nt<false>, so the caller holds a
// predicates::RoundingGuard) on the input doubles; "same line" and "parallel" are decided by
// intervals that are exactly [0, 0] (else the pair is not culled). With a minimum separation delta
// one side's ranges are widened by |u| delta (widened), so pairs within delta are kept.
// PROOF: proofs/scene.md#cylinder-ranges
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "core/predicates/interval.hpp"

namespace exactccd::scene {

/// A line through `point` along `direction` (non-zero, any length).
struct AxisLine {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  bool operator==(const AxisLine& o) const {
    return point == o.point && direction == o.direction;
  }
};

/// What a side's motion keeps: nothing that helps (`none`: a linearly moving mesh, a rigid motion
/// whose translation is not along its rotation axis), every line (`any`: a static mesh or a
/// rigid body at rest), every line parallel to `line.direction` (`parallels`: a pure translation)
/// or one line (`one_line`: a rotation about it, perhaps sliding along it).
struct KeptAxes {
  enum Kind { none, any, parallels, one_line } kind = none;
  AxisLine line;
};

namespace cylinder_detail {

using predicates::Interval;
using IVec = std::array<Interval, 3>;

inline IVec ivec(const Eigen::Vector3d& x) { return {Interval(x[0]), Interval(x[1]), Interval(x[2])}; }
inline IVec sub(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline IVec cross(const IVec& a, const IVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Interval dot(const IVec& a, const IVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Interval norm2(const IVec& a) {
  return CGAL::square(a[0]) + CGAL::square(a[1]) + CGAL::square(a[2]);
}
/// True when the interval vector is exactly the zero vector (then so is the real value).
inline bool certainly_zero(const IVec& a) {
  for (const Interval& x : a)
    if (x.inf() != 0 || x.sup() != 0) return false;
  return true;
}
/// a x b == 0 certainly (a and b parallel, or one of them zero).
inline bool certainly_parallel(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return certainly_zero(cross(ivec(a), ivec(b)));
}

}  // namespace cylinder_detail

/// What a rigid motion keeps (KeptAxes). Needs upward rounding.
inline KeptAxes kept_axes(const RigidMotion& m) {
  KeptAxes k;
  const bool turns = !m.cayley.isZero(0), slides = !m.translation.isZero(0);
  if (!turns && !slides) {
    k.kind = KeptAxes::any;
  } else if (!turns) {
    k.kind = KeptAxes::parallels;
    k.line = {m.pivot, m.translation};
  } else if (!slides || cylinder_detail::certainly_parallel(m.translation, m.cayley)) {
    k.kind = KeptAxes::one_line;
    k.line = {m.pivot, m.cayley};
  }
  return k;
}

/// The line of `l` written canonically when it is parallel to a coordinate axis e_k: direction
/// e_k, point with coordinate k = 0 (the same line exactly), so that steps about one axis with
/// different angles share a static mesh's cached ranges.
inline AxisLine canonical(AxisLine l) {
  int nonzero = 0, k = 0;
  for (int i = 0; i < 3; ++i)
    if (l.direction[i] != 0) ++nonzero, k = i;
  if (nonzero != 1) return l;
  l.direction = Eigen::Vector3d::Unit(k);
  l.point[k] = 0;
  return l;
}

/// A line both sides' motions keep, or nullopt (also when nothing moves). Needs upward rounding.
inline std::optional<AxisLine> common_axis(const KeptAxes& a, const KeptAxes& b) {
  using cylinder_detail::certainly_parallel;
  using cylinder_detail::certainly_zero;
  if (a.kind == KeptAxes::none || b.kind == KeptAxes::none) return std::nullopt;
  if (a.kind == KeptAxes::any && b.kind == KeptAxes::any) return std::nullopt;
  // The reference: a side that keeps one line, else a translating side's pivot line.
  const bool a_first = a.kind == KeptAxes::one_line ||
                       (b.kind != KeptAxes::one_line && a.kind == KeptAxes::parallels);
  const KeptAxes& ref = a_first ? a : b;
  const KeptAxes& other = a_first ? b : a;
  const AxisLine& l = ref.line;
  switch (other.kind) {
    case KeptAxes::any: break;
    case KeptAxes::parallels:
      if (!certainly_parallel(other.line.direction, l.direction)) return std::nullopt;
      break;
    case KeptAxes::one_line: {
      if (!certainly_parallel(other.line.direction, l.direction)) return std::nullopt;
      const auto offset = cylinder_detail::sub(cylinder_detail::ivec(other.line.point),
                                               cylinder_detail::ivec(l.point));
      if (!certainly_zero(cylinder_detail::cross(offset, cylinder_detail::ivec(l.direction))))
        return std::nullopt;
      break;
    }
    case KeptAxes::none: return std::nullopt;
  }
  return canonical(l);
}

/// Ranges of |w|^2 and h (the file comment) over a closed primitive.
struct CylinderRange {
  double rho2_lo, rho2_hi, h_lo, h_hi;
};

/// The smallest ranges holding both (of a node of a hierarchy: every primitive below it).
inline CylinderRange merge_ranges(const CylinderRange& x, const CylinderRange& y) {
  return {std::min(x.rho2_lo, y.rho2_lo), std::max(x.rho2_hi, y.rho2_hi),
          std::min(x.h_lo, y.h_lo), std::max(x.h_hi, y.h_hi)};
}

/// True when the ranges show that the primitives share no point.
inline bool apart(const CylinderRange& x, const CylinderRange& y) {
  return x.rho2_hi < y.rho2_lo || y.rho2_hi < x.rho2_lo || x.h_hi < y.h_lo || y.h_hi < x.h_lo;
}

namespace cylinder_detail {

/// w(x) = (x - p) x u and h(x) = (x - p) . u as intervals.
struct Projected {
  IVec w;
  Interval h;
};

inline Projected project(const AxisLine& l, const Eigen::Vector3d& x) {
  const IVec r = sub(ivec(x), ivec(l.point));
  const IVec u = ivec(l.direction);
  return {cross(r, u), dot(r, u)};
}

/// A lower bound of min |A + t (B - A)|^2 over t in [0, 1]; `ba` encloses B - A (computed from
/// b - a, so exactly zero for a segment along the axis). The closest point is A when
/// A . (B - A) >= 0, B when B . (B - A) <= 0, and the squared distance to the line AB bounds it
/// in every case; when |B - A| is not certainly positive, |A| - |B - A| does.
inline double segment_rho2_lo(const IVec& A, const IVec& B, const IVec& ba) {
  if (certainly_zero(ba)) return norm2(A).inf();
  const Interval len2 = norm2(ba);
  if (len2.inf() <= 0) {
    const double gap = (CGAL::sqrt(norm2(A)) - CGAL::sqrt(len2)).inf();
    return gap > 0 ? (Interval(gap) * gap).inf() : 0.0;
  }
  if (dot(A, ba).inf() >= 0) return norm2(A).inf();
  if (dot(B, ba).sup() <= 0) return norm2(B).inf();
  return std::max(0.0, (norm2(cross(A, ba)) / len2).inf());
}

inline IVec w_difference(const AxisLine& l, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return cross(sub(ivec(b), ivec(a)), ivec(l.direction));
}

}  // namespace cylinder_detail

/// The ranges of a point, a segment [a, b] and a triangle (a, b, c). Need upward rounding.
inline CylinderRange point_range(const AxisLine& l, const Eigen::Vector3d& x) {
  const auto p = cylinder_detail::project(l, x);
  const auto r2 = cylinder_detail::norm2(p.w);
  return {r2.inf(), r2.sup(), p.h.inf(), p.h.sup()};
}

inline CylinderRange segment_range(const AxisLine& l, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b) {
  using namespace cylinder_detail;
  const Projected pa = project(l, a), pb = project(l, b);
  return {segment_rho2_lo(pa.w, pb.w, w_difference(l, a, b)),
          std::max(norm2(pa.w).sup(), norm2(pb.w).sup()), std::min(pa.h.inf(), pb.h.inf()),
          std::max(pa.h.sup(), pb.h.sup())};
}

inline CylinderRange triangle_range(const AxisLine& l, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  using namespace cylinder_detail;
  const Projected pa = project(l, a), pb = project(l, b), pc = project(l, c);
  const IVec u = ivec(l.direction);
  // The line misses the projected triangle when two of the orientations (A x B) . u,
  // (B x C) . u, (C x A) . u have certainly opposite signs; then the closest point lies on an
  // edge.
  const int s[3] = {predicates::certain_strict_sign(dot(cross(pa.w, pb.w), u)),
                    predicates::certain_strict_sign(dot(cross(pb.w, pc.w), u)),
                    predicates::certain_strict_sign(dot(cross(pc.w, pa.w), u))};
  const bool outside = (s[0] * s[1] < 0) || (s[1] * s[2] < 0) || (s[2] * s[0] < 0);
  const double lo =
      outside ? std::min({segment_rho2_lo(pa.w, pb.w, w_difference(l, a, b)),
                          segment_rho2_lo(pb.w, pc.w, w_difference(l, b, c)),
                          segment_rho2_lo(pc.w, pa.w, w_difference(l, c, a))})
              : 0.0;
  return {lo, std::max({norm2(pa.w).sup(), norm2(pb.w).sup(), norm2(pc.w).sup()}),
          std::min({pa.h.inf(), pb.h.inf(), pc.h.inf()}),
          std::max({pa.h.sup(), pb.h.sup(), pc.h.sup()})};
}

/// The ranges of every vertex, edge and face of a mesh at `positions`, about `line`.
struct MeshCylinderRanges {
  AxisLine line;
  std::vector<CylinderRange> vertices, edges, faces;
};

/// Needs upward rounding.
inline MeshCylinderRanges mesh_ranges(const AxisLine& l, const Positions& x, const Edges& e,
                                      const Triangles& f) {
  MeshCylinderRanges r;
  r.line = l;
  const auto at = [&](std::int32_t i) { return Eigen::Vector3d(x.row(i).transpose()); };
  r.vertices.resize(static_cast<std::size_t>(x.rows()));
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    r.vertices[static_cast<std::size_t>(i)] = point_range(l, at(static_cast<std::int32_t>(i)));
  r.edges.resize(static_cast<std::size_t>(e.rows()));
  for (Eigen::Index i = 0; i < e.rows(); ++i)
    r.edges[static_cast<std::size_t>(i)] = segment_range(l, at(e(i, 0)), at(e(i, 1)));
  r.faces.resize(static_cast<std::size_t>(f.rows()));
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    r.faces[static_cast<std::size_t>(i)] = triangle_range(l, at(f(i, 0)), at(f(i, 1)), at(f(i, 2)));
  return r;
}

/// The shift of h over s in [0, 1] for a side translating by d along the line: [min(0, d . u),
/// max(0, d . u)]. Needs upward rounding.
inline std::array<double, 2> h_shift(const AxisLine& l, const Eigen::Vector3d& d) {
  const auto du = cylinder_detail::dot(cylinder_detail::ivec(d), cylinder_detail::ivec(l.direction));
  return {std::min(0.0, du.inf()), std::max(0.0, du.sup())};
}

/// `r` with every h range widened by `shift` (rounded outward). Needs upward rounding.
inline MeshCylinderRanges shifted(MeshCylinderRanges r, const std::array<double, 2>& shift) {
  using predicates::Interval;
  for (auto* list : {&r.vertices, &r.edges, &r.faces})
    for (CylinderRange& c : *list) {
      c.h_lo = (Interval(c.h_lo) + shift[0]).inf();
      c.h_hi = (Interval(c.h_hi) + shift[1]).sup();
    }
  return r;
}

/// `r` with every range widened by the minimum separation delta >= 0 (rounded outward), so that
/// a point within distance delta of a primitive lies in its widened ranges: the distance to the
/// line and the height along it are 1-Lipschitz, so |w| (|u| times the distance) and h change by
/// at most |u| delta. Two primitives that come within delta then have overlapping ranges once
/// either side is widened. Needs upward rounding.
EXACTCCD_CERTIFIED MeshCylinderRanges widened(MeshCylinderRanges r, double delta) {
  using predicates::Interval;
  const Interval reach =
      CGAL::sqrt(cylinder_detail::norm2(cylinder_detail::ivec(r.line.direction))) * delta;
  for (auto* list : {&r.vertices, &r.edges, &r.faces})
    for (CylinderRange& c : *list) {
      // A lower end <= 0 (or NaN, never expected) gives 0: no lower bound, never a cull.
      const double w_lo = (CGAL::sqrt(Interval(c.rho2_lo)) - reach).inf();
      c.rho2_lo = w_lo > 0 ? CGAL::square(Interval(w_lo)).inf() : 0.0;
      c.rho2_hi = CGAL::square(CGAL::sqrt(Interval(c.rho2_hi)) + reach).sup();
      c.h_lo = (Interval(c.h_lo) - reach).inf();
      c.h_hi = (Interval(c.h_hi) + reach).sup();
    }
  return r;
}

}  // namespace exactccd::scene
