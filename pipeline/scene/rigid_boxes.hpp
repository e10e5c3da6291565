// Certified boxes of points on rigid (or straight-line) paths over a range of the motion
// parameter s: the scene's broad-phase boxes of rigid bodies and its window culls of pairs that
// involve one.
//
// A point at x0 (s = 0) moved by (pivot c, translation d, Cayley vector q) is at
//
//   x(s) = x0 + s d + f1(s) u + f2(s) v,   u = q x (x0 - c),  v = q x u,
//   f1(s) = 2 s / (1 + |q|^2 s^2),          f2(s) = 2 s^2 / (1 + |q|^2 s^2)
//
// (rigid_motion.hpp's motion, written so that no large term cancels another). [s_lo, s_hi] is
// cut into pieces, the same for every point of a body; on a piece S, f2 is increasing and f1
// increasing up to s = 1/|q| and decreasing after, so their ranges over S are enclosed from
// their values at the piece's ends, and x(S) is enclosed by interval arithmetic. The union of
// these boxes over the pieces holds the point over [s_lo, s_hi]. The pieces only need to cover
// the range: their ends are any non-decreasing doubles from s_lo to s_hi, here spaced for equal
// turns, so that every piece's box is about as tight whatever the angle. Needs upward rounding
// (predicates::RoundingGuard) for Interval_nt<false>; a NaN end (overflow) widens the box to the
// whole axis, never shrinks it.
// PROOF: proofs/scene.md#rigid-boxes
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/predicates/rigid_motion.hpp"
#include "pipeline/scene/bvh.hpp"
#include "exactccd/rigid.hpp"
#include "core/predicates/interval.hpp"

namespace exactccd::scene {

/// Ends of pieces [ends[k], ends[k + 1]], k < count, covering [ends[0], ends[count]].
struct Pieces {
  static constexpr int max_count = 32;
  std::array<double, max_count + 1> ends{};
  int count = 1;
};

/// Pieces covering [s_lo, s_hi] (0 <= s_lo <= s_hi) for a body turning with `motion`: the
/// half-angle atan(s |q|) advances by at most about pi / 64 per piece (a turn of pi / 32), at
/// most max_count pieces; one piece without rotation. The ends are rounded doubles (any
/// rounding mode): correctness needs only that they do not decrease from s_lo to s_hi, which is
/// enforced.
inline Pieces pieces_for(const RigidMotion& motion, double s_lo, double s_hi) {
  Pieces p;
  p.ends[0] = s_lo;
  p.ends[1] = s_hi;
  const double rate = motion.cayley.norm();
  if (!(rate > 0.0) || !std::isfinite(rate) || !(s_hi > s_lo)) return p;
  const double a_lo = std::atan(s_lo * rate), a_hi = std::atan(s_hi * rate);
  const double wanted = std::ceil((a_hi - a_lo) / (M_PI / 64));
  if (!(wanted > 1.0)) return p;
  p.count = wanted >= Pieces::max_count ? Pieces::max_count : static_cast<int>(wanted);
  for (int k = 1; k < p.count; ++k) {
    const double s = std::tan(a_lo + (a_hi - a_lo) * k / p.count) / rate;
    // NaN (never expected) fails the comparison and takes the previous end.
    p.ends[k] = s >= p.ends[k - 1] ? std::min(s, s_hi) : p.ends[k - 1];
  }
  p.ends[p.count] = s_hi;
  return p;
}

/// Per piece of one body: enclosures of s, f1(s) and f2(s) over the piece.
struct ArcPieces {
  struct Piece {
    predicates::Interval s, f1, f2;
  };
  std::array<Piece, Pieces::max_count> piece;
  int count = 0;
};

/// The pieces' enclosures for a body with Cayley vector `cayley`. Needs upward rounding.
EXACTCCD_CERTIFIED ArcPieces arc_pieces(const Eigen::Vector3d& cayley, const Pieces& pieces) {
  using predicates::Interval;
  const Interval qq = Interval(cayley.x()) * cayley.x() + Interval(cayley.y()) * cayley.y() +
                      Interval(cayley.z()) * cayley.z();
  // f1, f2 at one s, as intervals (s >= 0; 1 + |q|^2 s^2 >= 1).
  const auto f1 = [&](const Interval& s) { return Interval(2) * s / (Interval(1) + qq * (s * s)); };
  const auto f2 = [&](const Interval& s) {
    return Interval(2) * (s * s) / (Interval(1) + qq * (s * s));
  };
  ArcPieces out;
  out.count = pieces.count;
  for (int k = 0; k < pieces.count; ++k) {
    const Interval a(pieces.ends[k]), b(pieces.ends[k + 1]), s(pieces.ends[k], pieces.ends[k + 1]);
    const Interval f1a = f1(a), f1b = f1(b);
    Interval range_f1;
    if ((qq * (b * b)).sup() <= 1.0)  // s |q| <= 1 on the piece: f1 increasing
      range_f1 = Interval(f1a.inf(), f1b.sup());
    else if ((qq * (a * a)).inf() >= 1.0)  // s |q| >= 1: f1 decreasing
      range_f1 = Interval(f1b.inf(), f1a.sup());
    else  // the maximum inside: the least end below, the whole piece's enclosure above
      range_f1 = Interval(std::min(f1a.inf(), f1b.inf()), f1(s).sup());
    out.piece[k] = {s, range_f1, Interval(f2(a).inf(), f2(b).sup())};
  }
  return out;
}

/// One point of a rigid body: x0, d, u = q x (x0 - c) and v = q x u as intervals.
struct ArcPoint {
  predicates::Vec3<predicates::Interval> x0, d, u, v;
};

/// Needs upward rounding.
EXACTCCD_CERTIFIED ArcPoint arc_point(const RigidMotion& m, const Eigen::Vector3d& x0) {
  using predicates::Interval;
  using V = predicates::Vec3<Interval>;
  const V q{m.cayley.x(), m.cayley.y(), m.cayley.z()};
  const V r{Interval(x0.x()) - m.pivot.x(), Interval(x0.y()) - m.pivot.y(),
            Interval(x0.z()) - m.pivot.z()};
  const auto cross = [](const V& a, const V& b) {
    return V{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  };
  const V u = cross(q, r);
  return {V{x0.x(), x0.y(), x0.z()}, V{m.translation.x(), m.translation.y(), m.translation.z()},
          u, cross(q, u)};
}

/// An empty box (lo = +infinity, hi = -infinity), to be grown.
inline Box empty_box() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {{inf, inf, inf}, {-inf, -inf, -inf}};
}

namespace detail {

/// Grows box on `axis` to hold x; std::min / std::max would drop a NaN: an unknown end is the
/// whole axis.
EXACTCCD_CERTIFIED void grow_axis(Box& box, int axis, const predicates::Interval& x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double lo = x.inf(), hi = x.sup();
  box.lo[axis] = std::isnan(lo) ? -inf : std::min(box.lo[axis], lo);
  box.hi[axis] = std::isnan(hi) ? inf : std::max(box.hi[axis], hi);
}

}  // namespace detail

/// Grows `box` to hold the point over every piece. Needs upward rounding.
EXACTCCD_CERTIFIED void grow_by_arc(Box& box, const ArcPoint& p, const ArcPieces& pieces) {
  for (int k = 0; k < pieces.count; ++k) {
    const ArcPieces::Piece& piece = pieces.piece[k];
    for (int axis = 0; axis < 3; ++axis)
      detail::grow_axis(box, axis,
                        p.x0[axis] + piece.s * p.d[axis] + piece.f1 * p.u[axis] +
                            piece.f2 * p.v[axis]);
  }
}

/// Grows `box` to hold the point moving on the straight line from x0 (s = 0) to x1 (s = 1) over
/// s in [s_lo, s_hi]. Needs upward rounding.
EXACTCCD_CERTIFIED void grow_by_segment(Box& box, const Eigen::Vector3d& x0,
                                        const Eigen::Vector3d& x1, double s_lo, double s_hi) {
  using predicates::Interval;
  const Interval s(s_lo, s_hi);
  for (int axis = 0; axis < 3; ++axis) {
    const Interval a(x0[axis]);
    detail::grow_axis(box, axis, a + s * (Interval(x1[axis]) - a));
  }
}

}  // namespace exactccd::scene
