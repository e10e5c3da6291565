// Minimum-separation predicates: "the closed primitives are within Euclidean distance delta at
// one instant", written once: the region polynomials over any number type, and the region
// logic once over their signs.
//
// A Point is a Vec3 of FixedPoly<NT, D> (a moving point: D = 1 linear, D = 5 rigid on a common
// denominator); `delta2` is delta squared: an NT, or for rigid motion the polynomial delta^2 W^2
// (every region polynomial is homogeneous in coordinate differences, and delta^2 stands in each
// for a factor of degree 2, so multiplying through by a power of W > 0 keeps every sign).
// PROOF: proofs/min_separation.md#rigid-separation Each separation numbers its polynomials: the non-strict ones first (0 ..
// kNonStrictCount - 1, every condition "<= 0" or ">= 0"), then the strict ones (each "> 0", a
// sum of squares); for_each_polynomial visits them in that order. within(sign) decides the
// instant predicate from sign(k), the sign (-1, 0, +1) of polynomial k at the instant under
// test: the exact path reads exact signs at algebraic times; the filters read certified signs
// over time intervals, or optimistic ones (0 for an uncertain non-strict polynomial, which
// satisfies its condition, +1 for an uncertain strict one). within is monotone: it can only
// become true when a condition becomes true, whatever the others.
// PROOF: proofs/min_separation.md#region-decomposition
#pragma once

#include "core/predicates/coplanarity_cubic.hpp"

namespace exactccd::predicates {

/// k p, coefficient-wise.
template <class NT, int D>
EXACTCCD_CERTIFIED FixedPoly<NT, D> scaled(const NT& k, const FixedPoly<NT, D>& p) {
  FixedPoly<NT, D> r{};
  for (int i = 0; i <= D; ++i) r.c[i] = k * p.c[i];
  return r;
}

/// delta^2 given as a polynomial (rigid motion on a common denominator W: delta^2 W^2) times p.
template <class NT, int K, int D>
EXACTCCD_CERTIFIED FixedPoly<NT, K + D> scaled(const FixedPoly<NT, K>& k,
                                               const FixedPoly<NT, D>& p) {
  return k * p;
}

/// delta^2 as a polynomial: a constant, or the polynomial it already is.
template <class NT>
EXACTCCD_CERTIFIED FixedPoly<NT, 0> as_polynomial(const NT& k) {
  return {{k}};
}
template <class NT, int K>
EXACTCCD_CERTIFIED const FixedPoly<NT, K>& as_polynomial(const FixedPoly<NT, K>& k) {
  return k;
}

/// The polynomials of "p within delta of the closed segment [x, y]", e = y - x: the end
/// spheres |p - x|^2 - delta^2 <= 0 and |p - y|^2 - delta^2 <= 0; the capsule's side
/// (p - x).e >= 0, (p - y).(x - y) >= 0, |p - x|^2 |e|^2 - ((p - x).e)^2 - delta^2 |e|^2 <= 0
/// with |e|^2 > 0. PROOF: proofs/min_separation.md#point-segment
template <class Point, class NT>
struct PointSegmentPolynomials {
  const Point& p;
  const Point& x;
  const Point& y;
  const NT& delta2;

  auto sphere(const Point& v) const {
    const auto w = p - v;
    return dot(w, w) - as_polynomial(delta2);
  }
  auto projection_from_x() const { return dot(p - x, y - x); }
  auto projection_from_y() const { return dot(p - y, x - y); }
  auto capsule() const {
    const auto w = p - x, e = y - x;
    const auto ee = dot(e, e), we = dot(w, e);
    return dot(w, w) * ee - we * we - scaled(delta2, ee);
  }
  auto length2() const { return dot(y - x, y - x); }
};

/// The point-segment condition from the signs of its polynomials (numbers in the caller's
/// order): an end sphere, or the capsule's side of a segment of non-zero length.
template <class Sign>
EXACTCCD_CERTIFIED bool point_segment_within(Sign&& sign, int sphere_x, int sphere_y,
                                             int projection_x, int projection_y, int capsule,
                                             int length2) {
  if (sign(sphere_x) <= 0 || sign(sphere_y) <= 0) return true;
  return sign(length2) > 0 && sign(projection_x) >= 0 && sign(projection_y) >= 0 &&
         sign(capsule) <= 0;
}

/// Vertex p against the closed triangle (a, b, c). Polynomials: 0 the face,
/// (n.(p - a))^2 - delta^2 |n|^2 <= 0 with n = (b - a) x (c - a); 1-3 the projection inside,
/// ((y - x) x (p - x)).n >= 0 for the edges ab, bc, ca; for edge i (ab, bc, ca) with first
/// vertex v: 4 + 4i the sphere of v, 5 + 4i and 6 + 4i the side's projections, 7 + 4i the
/// capsule; strict: 16 |n|^2 > 0, 17 + i edge i's |e|^2 > 0.
/// PROOF: proofs/min_separation.md#vertex-face-regions
template <class Point, class NT>
struct VertexFaceSeparation {
  static constexpr int kNonStrictCount = 16;
  static constexpr int kCount = 20;
  Point p, a, b, c;
  NT delta2;

  const Point& vertex(int i) const { return i == 0 ? a : (i == 1 ? b : c); }
  PointSegmentPolynomials<Point, NT> edge(int i) const {
    return {p, vertex(i), vertex((i + 1) % 3), delta2};
  }
  /// Calls f on every polynomial in numbering order, or on polynomial `only` alone.
  template <class F>
  void for_each_polynomial(F&& f, int only = -1) const {
    auto wanted = [only](int k) { return only < 0 || only == k; };
    decltype(cross(b - a, c - a)) n{};  // the face's normal: only where it is used
    if (only < 0 || only <= 3 || only == 16) n = cross(b - a, c - a);
    if (wanted(0)) {
      const auto d = dot(n, p - a);
      f(d * d - scaled(delta2, dot(n, n)));
    }
    for (int i = 0; i < 3; ++i) {
      const Point& x = vertex(i);
      if (wanted(1 + i)) f(dot(cross(vertex((i + 1) % 3) - x, p - x), n));
    }
    for (int i = 0; i < 3; ++i) {
      const auto e = edge(i);
      if (wanted(4 + 4 * i)) f(e.sphere(e.x));
      if (wanted(5 + 4 * i)) f(e.projection_from_x());
      if (wanted(6 + 4 * i)) f(e.projection_from_y());
      if (wanted(7 + 4 * i)) f(e.capsule());
    }
    if (wanted(16)) f(dot(n, n));
    for (int i = 0; i < 3; ++i)
      if (wanted(17 + i)) f(edge(i).length2());
  }
  /// The condition on non-strict polynomial k: -1 for "<= 0", +1 for ">= 0".
  static constexpr int condition(int k) {
    if (k == 0) return -1;
    if (k <= 3) return 1;
    const int r = (k - 4) % 4;  // sphere, projection from x, projection from y, capsule
    return r == 0 || r == 3 ? -1 : 1;
  }
  /// Within delta from the signs: an edge's capsule or sphere, or the face region.
  template <class Sign>
  static bool within(Sign&& sign) {
    for (int i = 0; i < 3; ++i)
      if (point_segment_within(sign, 4 + 4 * i, 4 + 4 * ((i + 1) % 3), 5 + 4 * i, 6 + 4 * i,
                               7 + 4 * i, 17 + i))
        return true;
    return sign(16) > 0 && sign(0) <= 0 && sign(1) >= 0 && sign(2) >= 0 && sign(3) >= 0;
  }
};

template <class NT, class Point>
EXACTCCD_CERTIFIED VertexFaceSeparation<Point, NT> vertex_face_separation(
    const Point& p, const Point& a, const Point& b, const Point& c, const NT& delta2) {
  return {p, a, b, c, delta2};
}

/// Closed segments [a0, a1] and [b0, b1], u = a1 - a0, v = b1 - b0, w = a0 - b0, m = u x v,
/// A = u.u, B = u.v, C = v.v, D = u.w, E = v.w. Polynomials: 0 the interior region,
/// (w.m)^2 - delta^2 |m|^2 <= 0; 1 s = BE - CD >= 0, 2 |m|^2 - s >= 0, 3 t = AE - BD >= 0,
/// 4 |m|^2 - t >= 0 (the lines' closest parameters in [0, 1]); 5-8 the endpoint spheres
/// a0b0, a0b1, a1b0, a1b1; for endpoint i (a0, a1 against [b0, b1], b0, b1 against [a0, a1]):
/// 9 + 3i and 10 + 3i the side's projections, 11 + 3i the capsule; strict: 21 |m|^2 > 0,
/// 22 |b1 - b0|^2 > 0, 23 |a1 - a0|^2 > 0.
/// PROOF: proofs/min_separation.md#edge-edge-regions
template <class Point, class NT>
struct EdgeEdgeSeparation {
  static constexpr int kNonStrictCount = 21;
  static constexpr int kCount = 24;
  Point a0, a1, b0, b1;
  NT delta2;

  PointSegmentPolynomials<Point, NT> endpoint(int i) const {
    switch (i) {
      case 0: return {a0, b0, b1, delta2};
      case 1: return {a1, b0, b1, delta2};
      case 2: return {b0, a0, a1, delta2};
      default: return {b1, a0, a1, delta2};
    }
  }
  /// Calls f on every polynomial in numbering order, or on polynomial `only` alone.
  template <class F>
  void for_each_polynomial(F&& f, int only = -1) const {
    auto wanted = [only](int k) { return only < 0 || only == k; };
    if (only <= 4) {  // the interior region's polynomials (all when only < 0)
      const auto u = a1 - a0, v = b1 - b0, w = a0 - b0;
      const auto m = cross(u, v);
      const auto m2 = dot(m, m);
      if (wanted(0)) {
        const auto g = dot(w, m);
        f(g * g - scaled(delta2, m2));
      }
      if (only < 0 || (only >= 1 && only <= 4)) {
        const auto s = dot(u, v) * dot(v, w) - dot(v, v) * dot(u, w);
        const auto t = dot(u, u) * dot(v, w) - dot(u, v) * dot(u, w);
        if (wanted(1)) f(s);
        if (wanted(2)) f(m2 - s);
        if (wanted(3)) f(t);
        if (wanted(4)) f(m2 - t);
      }
    }
    const auto e0 = endpoint(0), e1 = endpoint(1);
    if (wanted(5)) f(e0.sphere(b0));
    if (wanted(6)) f(e0.sphere(b1));
    if (wanted(7)) f(e1.sphere(b0));
    if (wanted(8)) f(e1.sphere(b1));
    for (int i = 0; i < 4; ++i) {
      const auto e = endpoint(i);
      if (wanted(9 + 3 * i)) f(e.projection_from_x());
      if (wanted(10 + 3 * i)) f(e.projection_from_y());
      if (wanted(11 + 3 * i)) f(e.capsule());
    }
    if (wanted(21)) {
      const auto m = cross(a1 - a0, b1 - b0);
      f(dot(m, m));
    }
    if (wanted(22)) f(e0.length2());
    if (wanted(23)) f(endpoint(2).length2());
  }
  /// The condition on non-strict polynomial k: -1 for "<= 0", +1 for ">= 0".
  static constexpr int condition(int k) {
    if (k == 0) return -1;
    if (k <= 4) return 1;
    if (k <= 8) return -1;  // the endpoint spheres
    return (k - 9) % 3 == 2 ? -1 : 1;  // projections >= 0, capsule <= 0
  }
  /// Within delta from the signs: an endpoint's capsule or sphere, or the interior region.
  template <class Sign>
  static bool within(Sign&& sign) {
    // Spheres of endpoint i against the other segment's ends (5 a0b0, 6 a0b1, 7 a1b0, 8 a1b1).
    constexpr int kSphereX[4] = {5, 7, 5, 6};
    constexpr int kSphereY[4] = {6, 8, 7, 8};
    for (int i = 0; i < 4; ++i)
      if (point_segment_within(sign, kSphereX[i], kSphereY[i], 9 + 3 * i, 10 + 3 * i,
                               11 + 3 * i, i < 2 ? 22 : 23))
        return true;
    return sign(21) > 0 && sign(0) <= 0 && sign(1) >= 0 && sign(2) >= 0 && sign(3) >= 0 &&
           sign(4) >= 0;
  }
};

template <class NT, class Point>
EXACTCCD_CERTIFIED EdgeEdgeSeparation<Point, NT> edge_edge_separation(
    const Point& a0, const Point& a1, const Point& b0, const Point& b1, const NT& delta2) {
  return {a0, a1, b0, b1, delta2};
}

}  // namespace exactccd::predicates
