// Separating directions over a time interval for minimum-separation CCD: the vertices'
// positions enclosed over the interval, and the certified test "the two convex hulls are
// more than delta apart along a direction" for the axes and for directions guessed at the
// interval's middle (closest points, the normal). Needs a RoundingGuard.
// PROOF: proofs/min_separation.md#separating-directions
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "filters/interval.hpp"

namespace exactccd::filters::separation {

/// [d, d] for any double d, infinities included (an overflowed bound): Interval_nt's
/// one-argument constructor asserts a finite value.
EXACTCCD_CERTIFIED Interval exact_interval(double d) { return Interval(d, d); }

/// A vertex's linear motion: x(T) = x0 + T (x1 - x0) enclosed over a time interval T.
struct MovingVertex {
  std::array<Interval, 3> x0, dx;
  MovingVertex(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    for (int k = 0; k < 3; ++k) {
      x0[k] = Interval(a[k]);
      dx[k] = Interval(b[k]) - Interval(a[k]);
    }
  }
  std::array<Interval, 3> at(const Interval& t) const {
    return {x0[0] + t * dx[0], x0[1] + t * dx[1], x0[2] + t * dx[2]};
  }
  /// Midpoint position at the double t, in plain arithmetic (a direction guess only).
  Eigen::Vector3d guess_at(double t) const {
    Eigen::Vector3d r;
    for (int k = 0; k < 3; ++k) r[k] = x0[k].inf() + t * dx[k].inf();
    return r;
  }
};

template <std::size_t N>
using Positions = std::array<std::array<Interval, 3>, N>;

/// Lower bound of min over the second set minus max over the first, along s.
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED double support_gap(const Eigen::Vector3d& s, const Positions<N1>& first,
                   const Positions<N2>& second) {
  double max1 = -std::numeric_limits<double>::infinity();
  for (const auto& x : first) {
    const Interval proj = Interval(s[0]) * x[0] + Interval(s[1]) * x[1] + Interval(s[2]) * x[2];
    max1 = std::max(max1, proj.sup());
  }
  double min2 = std::numeric_limits<double>::infinity();
  for (const auto& x : second) {
    const Interval proj = Interval(s[0]) * x[0] + Interval(s[1]) * x[1] + Interval(s[2]) * x[2];
    min2 = std::min(min2, proj.inf());
  }
  return (exact_interval(min2) - exact_interval(max1)).inf();
}

/// Certainly more than delta apart along the direction s (either orientation): the convex
/// hulls of the two vertex sets are separated by the slab of width gap / |s| > delta.
/// PROOF: proofs/min_separation.md#separating-directions
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED bool apart_along(const Eigen::Vector3d& s, const Positions<N1>& first,
                 const Positions<N2>& second, const Interval& delta2) {
  if (!s.allFinite() || s.isZero(0.0)) return false;
  const Interval norm2 = Interval(s[0]) * s[0] + Interval(s[1]) * s[1] + Interval(s[2]) * s[2];
  for (const double orientation : {1.0, -1.0}) {
    const double gap = support_gap<N1, N2>(orientation * s, first, second);
    if (gap > 0 && (exact_interval(gap) * exact_interval(gap)).inf() > (delta2 * norm2).sup())
      return true;
  }
  return false;
}

/// Axis-aligned gaps wider than delta over T.
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED bool apart_on_an_axis(const Positions<N1>& first, const Positions<N2>& second,
                                         double delta) {
  for (int k = 0; k < 3; ++k) {
    double lo1 = first[0][k].inf(), hi1 = first[0][k].sup();
    for (const auto& x : first) {
      lo1 = std::min(lo1, x[k].inf());
      hi1 = std::max(hi1, x[k].sup());
    }
    double lo2 = second[0][k].inf(), hi2 = second[0][k].sup();
    for (const auto& x : second) {
      lo2 = std::min(lo2, x[k].inf());
      hi2 = std::max(hi2, x[k].sup());
    }
    if ((exact_interval(lo2) - exact_interval(hi1)).inf() > delta ||
        (exact_interval(lo1) - exact_interval(hi2)).inf() > delta)
      return true;
  }
  return false;
}

/// The closest point to p on the closed triangle (a, b, c) in plain arithmetic (Ericson,
/// Real-Time Collision Detection, 5.1.5): a direction guess only, never a decision.
EXACTCCD_CERTIFIED Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p,
                                                       const Eigen::Vector3d& a,
                                                       const Eigen::Vector3d& b,
                                                       const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// The closest points of the closed segments [p1, q1] and [p2, q2] in plain arithmetic
/// (Ericson 5.1.9): a direction guess only.
EXACTCCD_CERTIFIED std::pair<Eigen::Vector3d, Eigen::Vector3d> closest_on_segments(
    const Eigen::Vector3d& p1, const Eigen::Vector3d& q1, const Eigen::Vector3d& p2,
    const Eigen::Vector3d& q2) {
  const Eigen::Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) return {p1, p2};
  if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p1 + d1 * s, p2 + d2 * t};
}

/// Vertex-face: the positions over T and the direction guesses at T's middle.
struct VertexFaceMotion {
  std::array<MovingVertex, 4> v;  // p, a, b, c
  /// `axes`: try the axes too (false where culling has just tried the same boxes).
  bool apart_over(const Interval& T, const Interval& delta2, double delta, bool axes) const {
    const Positions<1> first{v[0].at(T)};
    const Positions<3> second{v[1].at(T), v[2].at(T), v[3].at(T)};
    if (axes && apart_on_an_axis<1, 3>(first, second, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    const Eigen::Vector3d p = v[0].guess_at(mid), a = v[1].guess_at(mid), b = v[2].guess_at(mid),
                          c = v[3].guess_at(mid);
    if (apart_along<1, 3>(p - closest_on_triangle(p, a, b, c), first, second, delta2))
      return true;
    return apart_along<1, 3>((b - a).cross(c - a), first, second, delta2);
  }
};

/// Edge-edge: the positions over T and the direction guesses at T's middle.
struct EdgeEdgeMotion {
  std::array<MovingVertex, 4> v;  // a0, a1, b0, b1
  /// `axes`: try the axes too (false where culling has just tried the same boxes).
  bool apart_over(const Interval& T, const Interval& delta2, double delta, bool axes) const {
    const Positions<2> first{v[0].at(T), v[1].at(T)};
    const Positions<2> second{v[2].at(T), v[3].at(T)};
    if (axes && apart_on_an_axis<2, 2>(first, second, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    const Eigen::Vector3d a0 = v[0].guess_at(mid), a1 = v[1].guess_at(mid),
                          b0 = v[2].guess_at(mid), b1 = v[3].guess_at(mid);
    const auto [ca, cb] = closest_on_segments(a0, a1, b0, b1);
    if (apart_along<2, 2>(ca - cb, second, first, delta2)) return true;
    return apart_along<2, 2>((a1 - a0).cross(b1 - b0), second, first, delta2);
  }
};

}  // namespace exactccd::filters::separation
