// Rational rigid motion (Cayley parametrisation) as polynomials in the motion parameter s,
// written once over the number type, and the common-denominator positions the rigid CCD
// predicates use.
//
// A point x0 moved by (pivot c, translation d, Cayley vector q) is x(s) = X(s) / w(s) with
//   w(s) = 1 + |q|^2 s^2                                   (> 0 for every real s),
//   X(s) = x0 + (d + 2 q x r) s + (|q|^2 (c - r) + 2 (q.r) q) s^2 + |q|^2 d s^3,  r = x0 - c.
// A linearly moving vertex is X(s) = x0 + s (x1 - x0), w = 1.
// PROOF: proofs/rigid_ccd.md#homogeneous-paths
#pragma once

#include "core/predicates/motion.hpp"

namespace exactccd::predicates {

template <class NT>
struct RigidMotionOver {
  Vec3<NT> pivot, translation, cayley;
};

/// v.v, each product evaluated to NT.
template <class NT>
EXACTCCD_CERTIFIED NT squared_norm(const Vec3<NT>& v) {
  return NT(v.x * v.x) + NT(v.y * v.y) + NT(v.z * v.z);
}

/// The numerator X of a point's rigid path (degree 3 in s).
template <class NT>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 3>> rigid_path_numerator(const RigidMotionOver<NT>& m,
                                                              const Vec3<NT>& x0) {
  const auto& c = m.pivot;
  const auto& d = m.translation;
  const auto& q = m.cayley;
  // Spelled out over NT, not through dot / operator- on Vec3: with gmpxx those return
  // expression templates that refer to temporaries of the call (dangling once it returns).
  const NT qq = squared_norm(q);
  const Vec3<NT> r{x0.x - c.x, x0.y - c.y, x0.z - c.z};
  const NT qr = NT(q.x * r.x) + NT(q.y * r.y) + NT(q.z * r.z);
  const Vec3<NT> qxr{q.y * r.z - q.z * r.y, q.z * r.x - q.x * r.z, q.x * r.y - q.y * r.x};
  Vec3<FixedPoly<NT, 3>> X;
  FixedPoly<NT, 3>* out[3] = {&X.x, &X.y, &X.z};
  for (int k = 0; k < 3; ++k) {
    out[k]->c[0] = x0[k];
    out[k]->c[1] = d[k] + NT(2) * qxr[k];
    out[k]->c[2] = qq * (c[k] - r[k]) + NT(2) * qr * q[k];
    out[k]->c[3] = qq * d[k];
  }
  return X;
}

/// The denominator w(s) = 1 + |q|^2 s^2 of every point's rigid path.
template <class NT>
EXACTCCD_CERTIFIED FixedPoly<NT, 2> rigid_path_denominator(const RigidMotionOver<NT>& m) {
  return FixedPoly<NT, 2>{{NT(1), NT(0), squared_norm(m.cayley)}};
}

/// A linear path as the same degree-3 numerator (w = 1).
template <class NT>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 3>> linear_path_numerator(const Vec3<NT>& x0,
                                                               const Vec3<NT>& x1) {
  Vec3<FixedPoly<NT, 3>> X;
  FixedPoly<NT, 3>* out[3] = {&X.x, &X.y, &X.z};
  for (int k = 0; k < 3; ++k) *out[k] = FixedPoly<NT, 3>{{x0[k], x1[k] - x0[k], NT(0), NT(0)}};
  return X;
}

/// A point of a query on the common denominator W = w_side * w_other of both sides:
/// Y(s) = X(s) w_other(s), so that x(s) = Y(s) / W(s) with W > 0 the same for all four points.
/// Every predicate of the rigid path is a homogeneous polynomial in coordinate differences, so
/// its sign at s is its sign on the Y's. PROOF: proofs/rigid_ccd.md#common-denominator
template <class NT>
using RigidPoint = Vec3<FixedPoly<NT, 5>>;

template <class NT>
EXACTCCD_CERTIFIED RigidPoint<NT> on_common_denominator(const Vec3<FixedPoly<NT, 3>>& X,
                                                      const FixedPoly<NT, 2>& w_other) {
  return {X.x * w_other, X.y * w_other, X.z * w_other};
}

/// det[b - a, c - a, p - a]: zero exactly when the four points are coplanar (any point type).
template <class Point>
EXACTCCD_CERTIFIED auto coplanarity_determinant(const Point& p, const Point& a, const Point& b,
                                                const Point& c) {
  return dot(cross(b - a, c - a), p - a);
}

}  // namespace exactccd::predicates
