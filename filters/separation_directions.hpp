// Separating directions over a time interval for minimum-separation CCD: the certified test
// "the two convex hulls are more than delta apart along a direction" for the axes and for
// directions guessed at the interval's middle (closest points, the normal), read at the
// interval's two ends (the gap along a fixed direction is concave in t); over the whole step
// from the input doubles alone, rounding to nearest with a proven error bound; over a piece
// from interval positions, which needs a RoundingGuard.
// PROOF: proofs/min_separation.md#separating-directions
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "filters/certified_numbers.hpp"

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
      // 1 / e in parallel with the first division rather than a second division after it.
      const double b = d1.dot(d2), denom = a * e - b * b, inverse_e = 1.0 / e;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) * inverse_e;
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

/// `s` or -s, whichever has `towards` on its positive side (a guess only).
EXACTCCD_CERTIFIED Eigen::Vector3d oriented(const Eigen::Vector3d& s,
                                           const Eigen::Vector3d& towards) {
  return s.dot(towards) < 0 ? Eigen::Vector3d(-s) : s;
}

/// Direction guesses in plain arithmetic (never a decision), each oriented with the first
/// primitive (the vertex, the edge a) on its positive side, tried in turn by `apart_along`
/// until one separates: the vector between the closest points, then (only then computed, and
/// only with `normal_too`: over the whole step, where it decides some pairs; over a piece of
/// the search it rarely does and costs a second test) the triangle's normal or the edges'
/// cross product.
template <class ApartAlong>
EXACTCCD_CERTIFIED bool vertex_face_guesses_separate(const Eigen::Vector3d& p,
                                                     const Eigen::Vector3d& a,
                                                     const Eigen::Vector3d& b,
                                                     const Eigen::Vector3d& c,
                                                     ApartAlong&& apart_along,
                                                     bool normal_too = true) {
  return apart_along(p - closest_on_triangle(p, a, b, c)) ||
         (normal_too && apart_along(oriented((b - a).cross(c - a), p - a)));
}

template <class ApartAlong>
EXACTCCD_CERTIFIED bool edge_edge_guesses_separate(const Eigen::Vector3d& a0,
                                                   const Eigen::Vector3d& a1,
                                                   const Eigen::Vector3d& b0,
                                                   const Eigen::Vector3d& b1,
                                                   ApartAlong&& apart_along,
                                                   bool normal_too = true) {
  const auto [ca, cb] = closest_on_segments(a0, a1, b0, b1);
  const Eigen::Vector3d between = ca - cb;
  return apart_along(between) ||
         (normal_too && apart_along(oriented((a1 - a0).cross(b1 - b0),
                                             between.isZero(0.0) ? a0 - b0 : between)));
}

/// True when gap (a lower bound of the gap along s, at every time of the piece) certainly
/// exceeds delta |s|: gap > 0 and gap^2 (rounded downwards) > delta^2 |s|^2 (upwards).
EXACTCCD_CERTIFIED bool gap_exceeds(double gap, const Eigen::Vector3d& s, double delta2_upper) {
  if (!(gap > 0)) return false;
  const double bound = delta2_upper * ((s[0] * s[0] + s[1] * s[1]) + s[2] * s[2]);
  return -((-gap) * gap) > bound;
}

/// Usable as a direction: finite and non-zero.
EXACTCCD_CERTIFIED bool usable(const Eigen::Vector3d& s) {
  return s.allFinite() && !s.isZero(0.0);
}

// ---- A piece [lo, hi] of the step: interval positions at its ends.

/// The vertices' positions at the two ends of a piece.
template <std::size_t N1, std::size_t N2>
struct EndPositions {
  Positions<N1> first_lo, first_hi;
  Positions<N2> second_lo, second_hi;
};

/// The positions at lo and hi of v's vertices, the first N1 of them the first primitive.
template <std::size_t N1>
EXACTCCD_CERTIFIED EndPositions<N1, 4 - N1> end_positions(const std::array<MovingVertex, 4>& v,
                                                          const Interval& lo,
                                                          const Interval& hi) {
  EndPositions<N1, 4 - N1> ends;
  for (std::size_t i = 0; i < N1; ++i) {
    ends.first_lo[i] = v[i].at(lo);
    ends.first_hi[i] = v[i].at(hi);
  }
  for (std::size_t j = 0; j < 4 - N1; ++j) {
    ends.second_lo[j] = v[N1 + j].at(lo);
    ends.second_hi[j] = v[N1 + j].at(hi);
  }
  return ends;
}

/// A lower bound, at one instant, of min s.x - max s.y over x in first, y in second.
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED double interval_gap(const Eigen::Vector3d& s, const Positions<N1>& first,
                                       const Positions<N2>& second) {
  double min1 = std::numeric_limits<double>::infinity();
  for (const auto& x : first) {
    const Interval proj = Interval(s[0]) * x[0] + Interval(s[1]) * x[1] + Interval(s[2]) * x[2];
    min1 = std::min(min1, proj.inf());
  }
  double max2 = -std::numeric_limits<double>::infinity();
  for (const auto& y : second) {
    const Interval proj = Interval(s[0]) * y[0] + Interval(s[1]) * y[1] + Interval(s[2]) * y[2];
    max2 = std::max(max2, proj.sup());
  }
  return (exact_interval(min1) - exact_interval(max2)).inf();
}

/// Certainly more than delta apart along s, `first` on its positive side, over the piece.
/// PROOF: proofs/min_separation.md#separating-directions
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED bool apart_along(const Eigen::Vector3d& s, const EndPositions<N1, N2>& ends,
                                    double delta2_upper) {
  if (!usable(s)) return false;
  return gap_exceeds(std::min(interval_gap(s, ends.first_lo, ends.second_lo),
                              interval_gap(s, ends.first_hi, ends.second_hi)),
                     s, delta2_upper);
}

/// A lower bound of min over `second` minus max over `first` on axis k.
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED double axis_gap(int k, const Positions<N1>& first, const Positions<N2>& second) {
  double hi1 = first[0][k].sup(), lo2 = second[0][k].inf();
  for (const auto& x : first) hi1 = std::max(hi1, x[k].sup());
  for (const auto& y : second) lo2 = std::min(lo2, y[k].inf());
  return (exact_interval(lo2) - exact_interval(hi1)).inf();
}

/// Axis-aligned gaps wider than delta at both ends of the piece, either side.
template <std::size_t N1, std::size_t N2>
EXACTCCD_CERTIFIED bool apart_on_an_axis(const EndPositions<N1, N2>& ends, double delta) {
  for (int k = 0; k < 3; ++k) {
    if (std::min(axis_gap(k, ends.first_lo, ends.second_lo),
                 axis_gap(k, ends.first_hi, ends.second_hi)) > delta ||
        std::min(axis_gap(k, ends.second_lo, ends.first_lo),
                 axis_gap(k, ends.second_hi, ends.first_hi)) > delta)
      return true;
  }
  return false;
}

/// Conservative advancement from a cleared time lo along the direction s guessed there (the
/// first N1 of v the first primitive, on s's positive side): the piece [lo, end] certified more
/// than delta apart along s (§4b, the gap read at its two ends), end as far as the gap's linear
/// extrapolation allows, or lo when none is certified. *estimate: the time at which that
/// extrapolation reaches delta (a guess, never a decision; +infinity when the gap along s
/// does not shrink). PROOF: proofs/min_separation.md#conservative-advancement
template <std::size_t N1>
EXACTCCD_CERTIFIED double advance_along(const std::array<MovingVertex, 4>& v,
                                        const std::array<Eigen::Vector3d, 4>& at_lo,
                                        const Eigen::Vector3d& s, double lo, double t_max,
                                        double delta2_upper, double delta, double* estimate) {
  *estimate = lo;
  if (!usable(s)) return lo;
  // The gap along s between vertex i of the first and j of the second is linear in t: its
  // first zero (less delta |s|) over all pairs is where the concave gap reaches delta.
  const double reach = delta * s.norm();
  double first = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < N1; ++i)
    for (std::size_t j = N1; j < 4; ++j) {
      const double value = s.dot(at_lo[i] - at_lo[j]) - reach;
      if (!(value > 0)) return lo;
      double rate = 0;
      for (int k = 0; k < 3; ++k) rate += s[k] * (v[i].dx[k].inf() - v[j].dx[k].inf());
      if (rate < 0) first = std::min(first, lo + value / -rate);
    }
  *estimate = first;
  // Seven eighths of the way: the gap at the end stays well above the rounding errors.
  double end = first >= t_max ? t_max : lo + 0.875 * (first - lo);
  for (int attempt = 0; attempt < 2 && end > lo; ++attempt) {
    const auto ends = end_positions<N1>(v, Interval(lo), Interval(std::min(end, t_max)));
    if (apart_along(s, ends, delta2_upper)) return std::min(end, t_max);
    end = lo + 0.5 * (end - lo);
  }
  return lo;
}

/// Vertex-face over a piece T: p, a, b, c.
struct VertexFaceMotion {
  std::array<MovingVertex, 4> v;  // p, a, b, c
  /// `axes`: try the axes too (false where culling has just tried the same boxes).
  bool apart_over(const Interval& T, const Interval& delta2, double delta, bool axes) const {
    const Interval lo(T.inf()), hi(T.sup());
    const auto ends = end_positions<1>(v, lo, hi);
    if (axes && apart_on_an_axis(ends, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    return vertex_face_guesses_separate(
        v[0].guess_at(mid), v[1].guess_at(mid), v[2].guess_at(mid), v[3].guess_at(mid),
        [&](const Eigen::Vector3d& s) { return apart_along(s, ends, delta2.sup()); }, false);
  }
  /// advance_along from lo, along the vertex's offset from its closest point on the triangle.
  double advance(double lo, double t_max, const Interval& delta2, double delta,
                 double* estimate) const {
    const std::array<Eigen::Vector3d, 4> x = {v[0].guess_at(lo), v[1].guess_at(lo),
                                              v[2].guess_at(lo), v[3].guess_at(lo)};
    return advance_along<1>(v, x, x[0] - closest_on_triangle(x[0], x[1], x[2], x[3]), lo, t_max,
                            delta2.sup(), delta, estimate);
  }
};

/// Edge-edge over a piece T: a0, a1, b0, b1.
struct EdgeEdgeMotion {
  std::array<MovingVertex, 4> v;  // a0, a1, b0, b1
  /// `axes`: try the axes too (false where culling has just tried the same boxes).
  bool apart_over(const Interval& T, const Interval& delta2, double delta, bool axes) const {
    const Interval lo(T.inf()), hi(T.sup());
    const auto ends = end_positions<2>(v, lo, hi);
    if (axes && apart_on_an_axis(ends, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    return edge_edge_guesses_separate(
        v[0].guess_at(mid), v[1].guess_at(mid), v[2].guess_at(mid), v[3].guess_at(mid),
        [&](const Eigen::Vector3d& s) { return apart_along(s, ends, delta2.sup()); }, false);
  }
  /// advance_along from lo, along the vector between the edges' closest points.
  double advance(double lo, double t_max, const Interval& delta2, double delta,
                 double* estimate) const {
    const std::array<Eigen::Vector3d, 4> x = {v[0].guess_at(lo), v[1].guess_at(lo),
                                              v[2].guess_at(lo), v[3].guess_at(lo)};
    const auto [ca, cb] = closest_on_segments(x[0], x[1], x[2], x[3]);
    return advance_along<2>(v, x, ca - cb, lo, t_max, delta2.sup(), delta, estimate);
  }
};

// ---- The whole step [0, 1], which contains [0, t_max]: the positions at its ends are the
// input doubles themselves, so no interval is needed. Computed rounding to nearest, with the
// error bound of proofs/min_separation.md#whole-step: most queries that culling leaves end
// here, and setting a rounding mode would cost them as much as the test.

template <std::size_t N>
using InputVertices = std::array<const Eigen::Vector3d*, N>;

/// s.x rounded to nearest, r = (s0 x0 + s1 x1) + s2 x2, and a = (|s0 x0| + |s1 x1|) + |s2 x2|
/// from the same products: |r - s.x| <= 2^-51 a + 2^-1070 (Lemma W).
struct NearestDot {
  double r, a;
};

EXACTCCD_CERTIFIED NearestDot nearest_dot(const Eigen::Vector3d& s, const Eigen::Vector3d& x) {
  const double p0 = s[0] * x[0], p1 = s[1] * x[1], p2 = s[2] * x[2];
  return {(p0 + p1) + p2, (std::fabs(p0) + std::fabs(p1)) + std::fabs(p2)};
}

/// Plain midpoint of a vertex's motion (a guess only).
EXACTCCD_CERTIFIED Eigen::Vector3d midpoint_guess(const Eigen::Vector3d& x0,
                                                  const Eigen::Vector3d& x1) {
  return 0.5 * (x0 + x1);
}

/// The test along s over [0, 1]: t0, t1 = the four vertices at t = 0 and t = 1, the first N1
/// of them the first primitive (on s's positive side). Rounding to nearest (the caller's mode
/// is set to it by the library's entry).
template <std::size_t N1>
struct WholeStepGaps {
  static constexpr std::size_t N2 = 4 - N1;
  InputVertices<N1> first0, first1;
  InputVertices<N2> second0, second1;
  double delta;

  WholeStepGaps(const InputVertices<4>& t0, const InputVertices<4>& t1, double delta)
      : delta(delta) {
    for (std::size_t i = 0; i < N1; ++i) first0[i] = t0[i], first1[i] = t1[i];
    for (std::size_t i = 0; i < N2; ++i) second0[i] = t0[N1 + i], second1[i] = t1[N1 + i];
  }

  /// At both ends, min over the first of s.x - max over the second of s.y certainly exceeds
  /// delta |s|: -c > ((d + 2^-50 a) + 2^-1067)(1 + 2^-47), all rounded to nearest, with
  /// c = max (-s).x + max s.y from nearest_dot, a the largest absolute sum and d = delta
  /// sqrt(|s|^2), s first scaled by a power of two when |s|^2 leaves [2^-1000, 2^1000]; false
  /// (nothing claimed) when a value is not finite. PROOF: proofs/min_separation.md#whole-step
  bool apart_along(Eigen::Vector3d s) const {
    double n2 = (s[0] * s[0] + s[1] * s[1]) + s[2] * s[2];
    if (!(n2 >= 0x1p-1000 && n2 <= 0x1p+1000)) {  // a direction's scale is free: 1 <= |s|^2 < 12
      if (!usable(s)) return false;
      int e = 0;
      std::frexp(s.cwiseAbs().maxCoeff(), &e);
      for (int k = 0; k < 3; ++k) s[k] = std::ldexp(s[k], 1 - e);
      n2 = (s[0] * s[0] + s[1] * s[1]) + s[2] * s[2];
    }
    const double d = delta * std::sqrt(n2);
    const Eigen::Vector3d n = -s;
    double a = 0.0;
    auto largest = [&a](const Eigen::Vector3d& direction, const auto& points) {
      double r = -std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d* x : points) {
        const NearestDot dot = nearest_dot(direction, *x);
        r = std::max(r, dot.r);
        a = std::max(a, dot.a);
      }
      return r;
    };
    const double c0 = largest(n, first0) + largest(s, second0);
    const double c1 = largest(n, first1) + largest(s, second1);
    if (!(a <= std::numeric_limits<double>::max())) return false;
    const double bound = ((d + 0x1p-50 * a) + 0x1p-1067) * (1 + 0x1p-47);
    return std::isfinite(c0) && std::isfinite(c1) && -c0 > bound && -c1 > bound;
  }
};

/// Separated over the whole step [0, 1] (the axes are the culling's) along a guess made at
/// t = 1/2: {p, a, b, c} or {a0, a1, b0, b1} at t = 0 and t = 1.
template <std::size_t N1, class GuessesSeparate>
EXACTCCD_CERTIFIED bool apart_over_whole_step(const InputVertices<4>& t0,
                                              const InputVertices<4>& t1, double delta,
                                              GuessesSeparate guesses_separate) {
  const WholeStepGaps<N1> gaps(t0, t1, delta);
  return guesses_separate(midpoint_guess(*t0[0], *t1[0]), midpoint_guess(*t0[1], *t1[1]),
                          midpoint_guess(*t0[2], *t1[2]), midpoint_guess(*t0[3], *t1[3]),
                          [&](const Eigen::Vector3d& s) { return gaps.apart_along(s); });
}

EXACTCCD_CERTIFIED bool vertex_face_apart_over_whole_step(const InputVertices<4>& t0,
                                                          const InputVertices<4>& t1,
                                                          double delta) {
  return apart_over_whole_step<1>(t0, t1, delta, [](const auto& p, const auto& a, const auto& b,
                                                    const auto& c, auto&& apart_along) {
    // First the direction from the triangle's centroid (three times it) to the vertex: no
    // closest point to compute, and it separates a mesh's neighbours that are far apart
    // but whose boxes touch (a grid cell's corner against its other triangle).
    return apart_along(3.0 * p - ((a + b) + c)) ||
           vertex_face_guesses_separate(p, a, b, c, apart_along);
  });
}

EXACTCCD_CERTIFIED bool edge_edge_apart_over_whole_step(const InputVertices<4>& t0,
                                                        const InputVertices<4>& t1,
                                                        double delta) {
  return apart_over_whole_step<2>(t0, t1, delta, [](const auto& a0, const auto& a1,
                                                    const auto& b0, const auto& b1,
                                                    auto&& apart_along) {
    // First the direction between the edges' middles (twice it), as for vertex-face.
    return apart_along((a0 + a1) - (b0 + b1)) ||
           edge_edge_guesses_separate(a0, a1, b0, b1, apart_along);
  });
}

}  // namespace exactccd::filters::separation
