// The coplanarity polynomial g of a rigid (or per-vertex linear) query in closed form, written
// once over the number type: the determinant of the four common-denominator points with the
// positive factors w0, w1 divided out symbolically, so that
//
//   det(Y(s)) = w0(s)^(2 [side 0 rigid]) * w1(s)^(2 [side 1 rigid]) * g(s),   deg g <= 5,
//
// with det the coplanarity_determinant the exact path forms on the Y's (vertex-face:
// det[b - a, c - a, p - a]; edge-edge: det[a1 - a0, b0 - a0, b1 - a0]). g has the real roots
// and, at every s, the sign of the determinant: over the rationals the exact path isolates its
// roots; over intervals it is a degree-5 polynomial, far tighter than the degree-15 determinant.
// PROOF: proofs/rigid_ccd.md#reduced-polynomial
#pragma once

#include "core/predicates/rigid_motion.hpp"

namespace exactccd::predicates {

namespace rigid_detail {

// Spelled out over NT (not through the auto-returning Vec3 helpers): with gmpxx those return
// expression templates that refer to temporaries of the call.
template <class NT, class V>
EXACTCCD_CERTIFIED Vec3<NT> as(const V& v) {
  return {NT(v.x), NT(v.y), NT(v.z)};
}

template <class NT>
EXACTCCD_CERTIFIED Vec3<NT> minus(const Vec3<NT>& a, const Vec3<NT>& b) {
  return {NT(a.x - b.x), NT(a.y - b.y), NT(a.z - b.z)};
}

template <class NT>
EXACTCCD_CERTIFIED Vec3<NT> cross_of(const Vec3<NT>& a, const Vec3<NT>& b) {
  return {NT(a.y * b.z) - NT(a.z * b.y), NT(a.z * b.x) - NT(a.x * b.z),
          NT(a.x * b.y) - NT(a.y * b.x)};
}

template <class NT>
EXACTCCD_CERTIFIED NT dot_of(const Vec3<NT>& a, const Vec3<NT>& b) {
  return NT(a.x * b.x) + NT(a.y * b.y) + NT(a.z * b.z);
}

/// A constant vector as polynomials of degree 0.
template <class NT>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 0>> constant(const Vec3<NT>& a) {
  return {FixedPoly<NT, 0>{{a.x}}, FixedPoly<NT, 0>{{a.y}}, FixedPoly<NT, 0>{{a.z}}};
}

/// a + s b, coordinate-wise.
template <class NT>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 1>> line(const Vec3<NT>& a, const Vec3<NT>& b) {
  return {FixedPoly<NT, 1>{{a.x, b.x}}, FixedPoly<NT, 1>{{a.y, b.y}},
          FixedPoly<NT, 1>{{a.z, b.z}}};
}

/// w(s) = 1 + |q|^2 s^2 of a rigid side (1 for a linear one: never used there).
template <class NT>
EXACTCCD_CERTIFIED FixedPoly<NT, 2> denominator(const NT& qq) {
  return FixedPoly<NT, 2>{{NT(1), NT(0), qq}};
}

/// R~(s) u = u + 2 s (q x u) + s^2 (2 (q.u) q - |q|^2 u) for a fixed vector u: the Cayley
/// rotation's numerator (w(s) times the rotation by C(s q)), applied to u.
template <class NT>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 2>> turned(const Vec3<NT>& q, const NT& qq,
                                                 const Vec3<NT>& u) {
  const NT qu = dot_of(q, u);
  const Vec3<NT> qxu = cross_of(q, u);
  Vec3<FixedPoly<NT, 2>> r;
  FixedPoly<NT, 2>* out[3] = {&r.x, &r.y, &r.z};
  for (int k = 0; k < 3; ++k)
    *out[k] = FixedPoly<NT, 2>{{u[k], NT(2) * qxu[k], NT(NT(2) * qu) * q[k] - NT(qq * u[k])}};
  return r;
}

template <class NT, int D>
EXACTCCD_CERTIFIED FixedPoly<NT, 5> padded(const FixedPoly<NT, D>& p) {
  static_assert(D <= 5, "the reduced polynomial has degree <= 5");
  FixedPoly<NT, 5> r;
  for (int i = 0; i <= 5; ++i) r.c[i] = i <= D ? p.c[i] : NT(0);
  return r;
}

template <class A, class B, class C>
EXACTCCD_CERTIFIED auto determinant(const Vec3<A>& a, const Vec3<B>& b, const Vec3<C>& c) {
  return dot(cross(a, b), c);
}

/// The side's values over NT: its motion, |q|^2, and its linear end positions.
template <class NT>
struct SideOver {
  bool rigid;
  Vec3<NT> pivot, translation, cayley;
  NT qq;
  std::array<Vec3<NT>, 3> end;
};

template <class NT, class Side>
EXACTCCD_CERTIFIED SideOver<NT> side_over(const Side& side, int vertices) {
  SideOver<NT> s;
  s.rigid = side.rigid;
  if (s.rigid) {
    s.pivot = as<NT>(side.motion.pivot);
    s.translation = as<NT>(side.motion.translation);
    s.cayley = as<NT>(side.motion.cayley);
    s.qq = dot_of(s.cayley, s.cayley);
  } else {
    for (int i = 0; i < vertices; ++i) s.end[i] = as<NT>(side.end[i]);
  }
  return s;
}

}  // namespace rigid_detail

/// g for the vertex p against the triangle (a, b, c), positions at s = 0 (any type with x, y,
/// z convertible to NT); `vertex` and `face` are the two sides (fields rigid, motion with
/// pivot / translation / cayley, and end: the linear end positions). With n0 = u x v the face's
/// normal at s = 0 and, for a rigid side i, w_i, R~_i, pivot c_i, translation d_i:
///   both rigid:            w0 (R~1 n0).(c0 - c1 + s (d0 - d1)) + (R~1 n0).(R~0 (p - c0))
///                          - w0 w1 n0.(a - c1)
///   linear vertex X_p(s):  (R~1 n0).(X_p - c1 - s d1) - w1 n0.(a - c1)
///   linear face:           det[U(s), V(s), X_p(s) - w0 X_a(s)]  (w0 = 1 for a linear vertex)
/// PROOF: proofs/rigid_ccd.md#reduced-polynomial
template <class NT, class Point, class Side>
EXACTCCD_CERTIFIED FixedPoly<NT, 5> vertex_face_rigid_coplanarity(const Point& p_, const Point& a_,
                                                                  const Point& b_, const Point& c_,
                                                                  const Side& vertex,
                                                                  const Side& face) {
  using namespace rigid_detail;
  const Vec3<NT> p = as<NT>(p_), a = as<NT>(a_), b = as<NT>(b_), c = as<NT>(c_);
  const SideOver<NT> v = side_over<NT>(vertex, 1), f = side_over<NT>(face, 3);
  if (f.rigid) {
    const Vec3<NT> n0 = cross_of(minus(b, a), minus(c, a));
    const Vec3<FixedPoly<NT, 2>> Rn = turned(f.cayley, f.qq, n0);
    const FixedPoly<NT, 0> na{{dot_of(n0, minus(a, f.pivot))}};
    const FixedPoly<NT, 2> w1 = denominator(f.qq);
    if (v.rigid) {
      const FixedPoly<NT, 2> w0 = denominator(v.qq);
      const auto dc = line(minus(v.pivot, f.pivot), minus(v.translation, f.translation));
      const auto Rp = turned(v.cayley, v.qq, minus(p, v.pivot));
      return padded(w0 * dot(Rn, dc) + dot(Rn, Rp) - (w0 * w1) * na);
    }
    const auto e = line(minus(p, f.pivot), minus(minus(v.end[0], p), f.translation));
    return padded(dot(Rn, e) - w1 * na);
  }
  const auto U = line(minus(b, a), minus(minus(f.end[1], b), minus(f.end[0], a)));
  const auto V = line(minus(c, a), minus(minus(f.end[2], c), minus(f.end[0], a)));
  const auto Xa = line(a, minus(f.end[0], a));
  if (v.rigid) {
    const Vec3<FixedPoly<NT, 3>> Xp = rigid_path_numerator(
        RigidMotionOver<NT>{v.pivot, v.translation, v.cayley}, p);
    const FixedPoly<NT, 2> w0 = denominator(v.qq);
    const Vec3<FixedPoly<NT, 3>> E{Xp.x - w0 * Xa.x, Xp.y - w0 * Xa.y, Xp.z - w0 * Xa.z};
    return padded(determinant(U, V, E));
  }
  const auto Xp = line(p, minus(v.end[0], p));
  return padded(determinant(U, V, Xp - Xa));
}

/// g for the segment [a0, a1] (side edge_a) against [b0, b1] (side edge_b), positions at s = 0.
/// With u = a1 - a0, v = b1 - b0, r_a = a0 - c0, r_b = b0 - c1:
///   both rigid:   det[R~0 u, R~1 v, c0 - c1 + s (d0 - d1)] + (R~0 (r_a x u)).(R~1 v)
///                 - (R~1 (v x r_b)).(R~0 u)
///   a rigid, b linear (v(s), X_b0(s)):  v.(R~0 (r_a x u)) + det[R~0 u, v, c0 + s d0 - X_b0]
///   a linear, b rigid (u(s), X_a0(s)):  det[u, R~1 v, X_a0 - c1 - s d1] - u.(R~1 (v x r_b))
///   both linear:  det[A1 - A0, B0 - A0, B1 - A0] (the cubic of linear CCD)
/// PROOF: proofs/rigid_ccd.md#reduced-polynomial
template <class NT, class Point, class Side>
EXACTCCD_CERTIFIED FixedPoly<NT, 5> edge_edge_rigid_coplanarity(const Point& a0_, const Point& a1_,
                                                                const Point& b0_, const Point& b1_,
                                                                const Side& edge_a,
                                                                const Side& edge_b) {
  using namespace rigid_detail;
  const Vec3<NT> a0 = as<NT>(a0_), a1 = as<NT>(a1_), b0 = as<NT>(b0_), b1 = as<NT>(b1_);
  const SideOver<NT> A = side_over<NT>(edge_a, 2), B = side_over<NT>(edge_b, 2);
  const Vec3<NT> u = minus(a1, a0), v = minus(b1, b0);
  if (A.rigid && B.rigid) {
    const auto Ru = turned(A.cayley, A.qq, u), Rv = turned(B.cayley, B.qq, v);
    const auto dc = line(minus(A.pivot, B.pivot), minus(A.translation, B.translation));
    const auto Rau = turned(A.cayley, A.qq, cross_of(minus(a0, A.pivot), u));
    const auto Rvb = turned(B.cayley, B.qq, cross_of(v, minus(b0, B.pivot)));
    return padded(determinant(Ru, Rv, dc) + dot(Rau, Rv) - dot(Rvb, Ru));
  }
  if (A.rigid) {
    const auto Ru = turned(A.cayley, A.qq, u);
    const auto Rau = turned(A.cayley, A.qq, cross_of(minus(a0, A.pivot), u));
    const auto vs = line(v, minus(minus(B.end[1], b1), minus(B.end[0], b0)));
    // c0 + s d0 - X_b0(s)
    const auto e = line(minus(A.pivot, b0), minus(A.translation, minus(B.end[0], b0)));
    return padded(dot(vs, Rau) + determinant(Ru, vs, e));
  }
  if (B.rigid) {
    const auto Rv = turned(B.cayley, B.qq, v);
    const auto Rvb = turned(B.cayley, B.qq, cross_of(v, minus(b0, B.pivot)));
    const auto us = line(u, minus(minus(A.end[1], a1), minus(A.end[0], a0)));
    // X_a0(s) - c1 - s d1
    const auto e = line(minus(a0, B.pivot), minus(minus(A.end[0], a0), B.translation));
    return padded(determinant(us, Rv, e) - dot(us, Rvb));
  }
  const auto A0 = line(a0, minus(A.end[0], a0)), A1 = line(a1, minus(A.end[1], a1));
  const auto B0 = line(b0, minus(B.end[0], b0)), B1 = line(b1, minus(B.end[1], b1));
  return padded(determinant(A1 - A0, B0 - A0, B1 - A0));
}

}  // namespace exactccd::predicates
