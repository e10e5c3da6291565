// Minimum-separation predicates: "the closed primitives are within Euclidean distance delta at
// one instant", written once over the number type as sign conditions on polynomials in t.
//
// A Point is a Vec3 of FixedPoly<NT, D> (a moving point, D = 1, or a position, D = 0);
// `delta2` is delta squared, an NT; `sign_at(q)` returns the sign of the polynomial q at the
// instant under test (the exact path: at an algebraic time; the filters: over a time interval,
// where it may answer `uncertain` through its own channel), and `positive_at(q)` decides the
// strict conditions q > 0 (by default sign_at(q) > 0). within_at is monotone: it only grows
// when any condition changes from false to true, which the filters' optimistic exclusion uses. Each condition is the union of the
// closed feature regions of the distance function, every one a conjunction of non-strict sign
// conditions plus one strict "non-degenerate" condition.
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

/// The polynomials of "p within delta of the closed segment [x, y]": the sphere conditions
/// |p - x|^2 - delta^2 <= 0 and |p - y|^2 - delta^2 <= 0, and the capsule's conditions
/// (p - x).(y - x) >= 0, (p - y).(x - y) >= 0, |p - x|^2 |e|^2 - ((p - x).e)^2 - delta^2 |e|^2
/// <= 0 with e = y - x and |e|^2 > 0. PROOF: proofs/min_separation.md#point-segment
template <class Point, class NT>
struct PointSegmentSeparation {
  Point p, x, y;
  NT delta2;

  auto e() const { return y - x; }
  auto length2() const { return dot(e(), e()); }
  auto sphere(const Point& v) const {
    const auto w = p - v;
    return dot(w, w) - FixedPoly<NT, 0>{{delta2}};
  }
  auto projection_from_x() const { return dot(p - x, y - x); }
  auto projection_from_y() const { return dot(p - y, x - y); }
  auto capsule() const {
    const auto w = p - x;
    const auto ee = length2();
    const auto we = dot(w, e());
    return dot(w, w) * ee - we * we - scaled(delta2, ee);
  }
  /// Calls f on every polynomial of a non-strict condition: the earliest time within delta is
  /// t = 0 or a root of one of them (the strict |e|^2 > 0 is not needed).
  /// PROOF: proofs/min_separation.md#candidate-times
  template <class F>
  void for_each_polynomial(F&& f, bool with_spheres = true) const {
    if (with_spheres) {
      f(sphere(x));
      f(sphere(y));
    }
    f(projection_from_x());
    f(projection_from_y());
    f(capsule());
  }
  /// Calls f on the polynomial of the strict condition (|e|^2 > 0).
  template <class F>
  void for_each_strict_polynomial(F&& f) const {
    f(length2());
  }
  /// `positive_at(q)`: q > 0 (the strict conditions); by default sign_at(q) > 0.
  template <class SignAt, class PositiveAt>
  bool within_at(SignAt&& sign_at, PositiveAt&& positive_at) const {
    if (sign_at(sphere(x)) <= 0 || sign_at(sphere(y)) <= 0) return true;
    return positive_at(length2()) && sign_at(projection_from_x()) >= 0 &&
           sign_at(projection_from_y()) >= 0 && sign_at(capsule()) <= 0;
  }
  template <class SignAt>
  bool within_at(SignAt&& sign_at) const {
    return within_at(sign_at, [&sign_at](const auto& q) { return sign_at(q) > 0; });
  }
};

template <class NT, class Point>
EXACTCCD_CERTIFIED PointSegmentSeparation<Point, NT> point_segment_separation(
    const Point& p, const Point& x, const Point& y, const NT& delta2) {
  return {p, x, y, delta2};
}

/// Vertex p against the closed triangle (a, b, c): the face region (n = (b - a) x (c - a),
/// |n|^2 > 0, (n.(p - a))^2 - delta^2 |n|^2 <= 0, and the projection of p inside the closed
/// triangle: ((b - a) x (p - a)).n >= 0 and its two cyclic copies), or p within delta of one
/// of the three closed edges. PROOF: proofs/min_separation.md#vertex-face-regions
template <class Point, class NT>
struct VertexFaceSeparation {
  Point p, a, b, c;
  NT delta2;

  auto normal() const { return cross(b - a, c - a); }
  auto normal2() const {
    const auto n = normal();
    return dot(n, n);
  }
  auto face() const {
    const auto n = normal();
    const auto d = dot(n, p - a);
    return d * d - scaled(delta2, dot(n, n));
  }
  auto inside(const Point& x, const Point& y) const { return dot(cross(y - x, p - x), normal()); }
  PointSegmentSeparation<Point, NT> edge(int i) const {
    return i == 0 ? PointSegmentSeparation<Point, NT>{p, a, b, delta2}
                  : (i == 1 ? PointSegmentSeparation<Point, NT>{p, b, c, delta2}
                            : PointSegmentSeparation<Point, NT>{p, c, a, delta2});
  }
  /// Calls f on every polynomial of a non-strict condition (each vertex sphere once).
  /// PROOF: proofs/min_separation.md#candidate-times
  template <class F>
  void for_each_polynomial(F&& f) const {
    f(face());
    f(inside(a, b));
    f(inside(b, c));
    f(inside(c, a));
    for (int i = 0; i < 3; ++i) {
      const auto e = edge(i);
      f(e.sphere(e.x));
      e.for_each_polynomial(f, false);
    }
  }
  /// Calls f on every polynomial of a strict condition (|n|^2 > 0, each |e|^2 > 0).
  template <class F>
  void for_each_strict_polynomial(F&& f) const {
    f(normal2());
    for (int i = 0; i < 3; ++i) edge(i).for_each_strict_polynomial(f);
  }
  template <class SignAt, class PositiveAt>
  bool within_at(SignAt&& sign_at, PositiveAt&& positive_at) const {
    for (int i = 0; i < 3; ++i)
      if (edge(i).within_at(sign_at, positive_at)) return true;
    return positive_at(normal2()) && sign_at(face()) <= 0 && sign_at(inside(a, b)) >= 0 &&
           sign_at(inside(b, c)) >= 0 && sign_at(inside(c, a)) >= 0;
  }
  template <class SignAt>
  bool within_at(SignAt&& sign_at) const {
    return within_at(sign_at, [&sign_at](const auto& q) { return sign_at(q) > 0; });
  }
};

template <class NT, class Point>
EXACTCCD_CERTIFIED VertexFaceSeparation<Point, NT> vertex_face_separation(
    const Point& p, const Point& a, const Point& b, const Point& c, const NT& delta2) {
  return {p, a, b, c, delta2};
}

/// Closed segments [a0, a1] and [b0, b1]: the interior region (u = a1 - a0, v = b1 - b0,
/// w = a0 - b0, m = u x v, |m|^2 > 0, (w.m)^2 - delta^2 |m|^2 <= 0, and the lines' closest
/// parameters s = (BE - CD)/|m|^2 and t = (AE - BD)/|m|^2 in [0, 1], with A = u.u, B = u.v,
/// C = v.v, D = u.w, E = v.w), or an endpoint within delta of the other closed segment.
/// PROOF: proofs/min_separation.md#edge-edge-regions
template <class Point, class NT>
struct EdgeEdgeSeparation {
  Point a0, a1, b0, b1;
  NT delta2;

  auto direction_cross() const { return cross(a1 - a0, b1 - b0); }
  auto cross2() const {
    const auto m = direction_cross();
    return dot(m, m);
  }
  auto interior() const {
    const auto m = direction_cross();
    const auto g = dot(a0 - b0, m);
    return g * g - scaled(delta2, dot(m, m));
  }
  /// |m|^2 s and |m|^2 t (the closest parameters' numerators).
  auto s_numerator() const {
    const auto u = a1 - a0, v = b1 - b0, w = a0 - b0;
    return dot(u, v) * dot(v, w) - dot(v, v) * dot(u, w);
  }
  auto t_numerator() const {
    const auto u = a1 - a0, v = b1 - b0, w = a0 - b0;
    return dot(u, u) * dot(v, w) - dot(u, v) * dot(u, w);
  }
  PointSegmentSeparation<Point, NT> endpoint(int i) const {
    switch (i) {
      case 0: return {a0, b0, b1, delta2};
      case 1: return {a1, b0, b1, delta2};
      case 2: return {b0, a0, a1, delta2};
      default: return {b1, a0, a1, delta2};
    }
  }
  /// Calls f on every polynomial of a non-strict condition (each endpoint pair's sphere once).
  /// PROOF: proofs/min_separation.md#candidate-times
  template <class F>
  void for_each_polynomial(F&& f) const {
    f(interior());
    f(s_numerator());
    f(cross2() - s_numerator());
    f(t_numerator());
    f(cross2() - t_numerator());
    for (int i = 0; i < 4; ++i) {
      const auto e = endpoint(i);
      if (i < 2) {  // a0, a1 against b0 and b1: the four endpoint pairs
        f(e.sphere(e.x));
        f(e.sphere(e.y));
      }
      e.for_each_polynomial(f, false);
    }
  }
  /// Calls f on every polynomial of a strict condition (|m|^2 > 0, |b1 - b0|^2 > 0,
  /// |a1 - a0|^2 > 0).
  template <class F>
  void for_each_strict_polynomial(F&& f) const {
    f(cross2());
    endpoint(0).for_each_strict_polynomial(f);
    endpoint(2).for_each_strict_polynomial(f);
  }
  template <class SignAt, class PositiveAt>
  bool within_at(SignAt&& sign_at, PositiveAt&& positive_at) const {
    for (int i = 0; i < 4; ++i)
      if (endpoint(i).within_at(sign_at, positive_at)) return true;
    if (!positive_at(cross2()) || sign_at(interior()) > 0) return false;
    const auto m2 = cross2();
    const auto s = s_numerator(), t = t_numerator();
    return sign_at(s) >= 0 && sign_at(m2 - s) >= 0 && sign_at(t) >= 0 && sign_at(m2 - t) >= 0;
  }
  template <class SignAt>
  bool within_at(SignAt&& sign_at) const {
    return within_at(sign_at, [&sign_at](const auto& q) { return sign_at(q) > 0; });
  }
};

template <class NT, class Point>
EXACTCCD_CERTIFIED EdgeEdgeSeparation<Point, NT> edge_edge_separation(
    const Point& a0, const Point& a1, const Point& b0, const Point& b1, const NT& delta2) {
  return {a0, a1, b0, b1, delta2};
}

}  // namespace exactccd::predicates
