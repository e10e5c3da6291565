// PROOF: proofs/min_separation.md#filters
#include "filters/separation_filter.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/predicates/separation.hpp"
#include "filters/interval.hpp"

namespace exactccd::filters {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;

/// hi1 + delta < lo2 or hi2 + delta < lo1 on some axis, the sums rounded upwards: a certain
/// gap wider than delta. PROOF: proofs/min_separation.md#culling-with-delta
template <std::size_t N1, std::size_t N2>
bool boxes_apart(const std::array<const Eigen::Vector3d*, N1>& first,
                 const std::array<const Eigen::Vector3d*, N2>& second, double delta) {
  const RoundingGuard upward;
  for (int k = 0; k < 3; ++k) {
    double lo1 = first[0]->coeff(k), hi1 = lo1, lo2 = second[0]->coeff(k), hi2 = lo2;
    for (const auto* v : first) {
      lo1 = std::min(lo1, v->coeff(k));
      hi1 = std::max(hi1, v->coeff(k));
    }
    for (const auto* v : second) {
      lo2 = std::min(lo2, v->coeff(k));
      hi2 = std::max(hi2, v->coeff(k));
    }
    if (hi1 + delta < lo2 || hi2 + delta < lo1) return true;
  }
  return false;
}

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
double support_gap(const Eigen::Vector3d& s, const Positions<N1>& first,
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
  return (Interval(min2) - Interval(max1)).inf();
}

/// Certainly more than delta apart along the direction s (either orientation): the convex
/// hulls of the two vertex sets are separated by the slab of width gap / |s| > delta.
/// PROOF: proofs/min_separation.md#separating-directions
template <std::size_t N1, std::size_t N2>
bool apart_along(const Eigen::Vector3d& s, const Positions<N1>& first,
                 const Positions<N2>& second, const Interval& delta2) {
  if (!s.allFinite() || s.isZero(0.0)) return false;
  const Interval norm2 = Interval(s[0]) * s[0] + Interval(s[1]) * s[1] + Interval(s[2]) * s[2];
  for (const double orientation : {1.0, -1.0}) {
    const double gap = support_gap<N1, N2>(orientation * s, first, second);
    if (gap > 0 && (Interval(gap) * gap).inf() > (delta2 * norm2).sup()) return true;
  }
  return false;
}

/// Axis-aligned gaps wider than delta over T.
template <std::size_t N1, std::size_t N2>
bool apart_on_an_axis(const Positions<N1>& first, const Positions<N2>& second, double delta) {
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
    if ((Interval(lo2) - hi1).inf() > delta || (Interval(lo1) - hi2).inf() > delta) return true;
  }
  return false;
}

/// The closest point to p on the closed triangle (a, b, c) in plain arithmetic (Ericson,
/// Real-Time Collision Detection, 5.1.5): a direction guess only, never a decision.
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
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
std::pair<Eigen::Vector3d, Eigen::Vector3d> closest_on_segments(
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
  bool apart_over(const Interval& T, const Interval& delta2, double delta) const {
    const Positions<1> first{v[0].at(T)};
    const Positions<3> second{v[1].at(T), v[2].at(T), v[3].at(T)};
    if (apart_on_an_axis<1, 3>(first, second, delta)) return true;
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
  bool apart_over(const Interval& T, const Interval& delta2, double delta) const {
    const Positions<2> first{v[0].at(T), v[1].at(T)};
    const Positions<2> second{v[2].at(T), v[3].at(T)};
    if (apart_on_an_axis<2, 2>(first, second, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    const Eigen::Vector3d a0 = v[0].guess_at(mid), a1 = v[1].guess_at(mid),
                          b0 = v[2].guess_at(mid), b1 = v[3].guess_at(mid);
    const auto [ca, cb] = closest_on_segments(a0, a1, b0, b1);
    if (apart_along<2, 2>(ca - cb, second, first, delta2)) return true;
    return apart_along<2, 2>((a1 - a0).cross(b1 - b0), second, first, delta2);
  }
};

/// Depth of the time subdivision: at most 2^kMaxDepth leaves, searched earliest first.
constexpr int kMaxDepth = 6;

/// Certainly never within delta on [lo, hi]: each piece of an adaptive bisection (depth
/// first, earliest first) is shown apart, or the search gives up at the first piece of the
/// deepest level that is not.
template <class Motion>
bool never_within(const Motion& m, double lo, double hi, int depth, const Interval& delta2,
                  double delta) {
  if (m.apart_over(Interval(lo, hi), delta2, delta)) return true;
  if (depth == kMaxDepth) return false;
  const double mid = lo + 0.5 * (hi - lo);  // rounded upwards: still inside (lo, hi]
  if (!(mid > lo && mid < hi)) return false;
  return never_within(m, lo, mid, depth + 1, delta2, delta) &&
         never_within(m, mid, hi, depth + 1, delta2, delta);
}

/// The sign of a polynomial at t = 0 (its constant coefficient), certified or not.
struct SignAtZero {
  bool* uncertain;
  template <int D>
  int operator()(const FixedPoly<Interval, D>& g) const {
    const CertifiedSign s = certified_sign(g.c[0]);
    if (s == CertifiedSign::uncertain) {
      *uncertain = true;
      return 0;
    }
    return static_cast<int>(s);
  }
};

predicates::MovingPoint<Interval> moving(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  return predicates::linear_motion(Vec3<Interval>{x0.x(), x0.y(), x0.z()},
                                   Vec3<Interval>{x1.x(), x1.y(), x1.z()});
}

/// The instant predicate at t = 0 with certified signs; true only when every sign it read
/// was certain. PROOF: proofs/min_separation.md#within-at-zero
template <class Separation>
bool certainly_within_at_zero(const Separation& separation) {
  bool uncertain = false;
  const bool within = separation.within_at(SignAtZero{&uncertain});
  return within && !uncertain;
}

}  // namespace

bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta) {
  return boxes_apart<2, 6>({&q.p_t0, &q.p_t1},
                           {&q.a_t0, &q.b_t0, &q.c_t0, &q.a_t1, &q.b_t1, &q.c_t1}, delta);
}

bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta) {
  return boxes_apart<4, 4>({&q.ea0_t0, &q.ea1_t0, &q.ea0_t1, &q.ea1_t1},
                           {&q.eb0_t0, &q.eb1_t0, &q.eb0_t1, &q.eb1_t1}, delta);
}

SeparationVerdict vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options) {
  const RoundingGuard upward;
  const double delta = options.min_separation;
  const Interval delta2 = Interval(delta) * delta;
  const VertexFaceMotion m{{MovingVertex(q.p_t0, q.p_t1), MovingVertex(q.a_t0, q.a_t1),
                            MovingVertex(q.b_t0, q.b_t1), MovingVertex(q.c_t0, q.c_t1)}};
  if (never_within(m, 0.0, options.t_max, 0, delta2, delta))
    return SeparationVerdict::never_within;
  const auto separation = predicates::vertex_face_separation(
      moving(q.p_t0, q.p_t1), moving(q.a_t0, q.a_t1), moving(q.b_t0, q.b_t1),
      moving(q.c_t0, q.c_t1), delta2);
  return certainly_within_at_zero(separation) ? SeparationVerdict::within_at_zero
                                              : SeparationVerdict::uncertain;
}

SeparationVerdict edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options) {
  const RoundingGuard upward;
  const double delta = options.min_separation;
  const Interval delta2 = Interval(delta) * delta;
  const EdgeEdgeMotion m{{MovingVertex(q.ea0_t0, q.ea0_t1), MovingVertex(q.ea1_t0, q.ea1_t1),
                          MovingVertex(q.eb0_t0, q.eb0_t1), MovingVertex(q.eb1_t0, q.eb1_t1)}};
  if (never_within(m, 0.0, options.t_max, 0, delta2, delta))
    return SeparationVerdict::never_within;
  const auto separation = predicates::edge_edge_separation(
      moving(q.ea0_t0, q.ea0_t1), moving(q.ea1_t0, q.ea1_t1), moving(q.eb0_t0, q.eb0_t1),
      moving(q.eb1_t0, q.eb1_t1), delta2);
  return certainly_within_at_zero(separation) ? SeparationVerdict::within_at_zero
                                              : SeparationVerdict::uncertain;
}

}  // namespace exactccd::filters
