// The offset of a point from a plane as a polynomial in time, written once over the number type
// for the filters (intervals), the exact signs (StackDyadic, rationals) and float_only:
//   linear motion: f(t) = (p(t) - o(t)) . n(t), degree <= 2 (<= 1 for a static plane);
//   a rigid body's point against a static plane: F(s) = (X(s) - o w(s)) . n, degree <= 3, where
//   x(s) = X(s) / w(s) is the point's rational path (rigid_motion.hpp), so F / w is the offset.
// And a polynomial's interval enclosure over [a, b] by Horner's rule.
// PROOF: proofs/point_plane.md#reduction, proofs/point_plane.md#rigid
#pragma once

#include "core/predicates/interval.hpp"
#include "core/predicates/motion.hpp"
#include "core/predicates/rigid_motion.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::predicates {

/// f(t) = (p(t) - origin(t)) . normal(t) over NT, every double converted exactly.
template <class NT>
EXACTCCD_CERTIFIED FixedPoly<NT, 2> linear_plane_offset(const PointPlaneQuery& q) {
  const auto p = moving_point<NT>(q.p_t0, q.p_t1), o = moving_point<NT>(q.origin_t0, q.origin_t1),
             n = moving_point<NT>(q.normal_t0, q.normal_t1);
  return dot(p - o, n);
}

/// F(s) = (X(s) - origin w(s)) . normal over NT, and the path's denominator w in *w_out.
template <class NT>
EXACTCCD_CERTIFIED FixedPoly<NT, 3> rigid_plane_offset(const RigidPointPlaneQuery& q,
                                                        FixedPoly<NT, 2>* w_out) {
  const auto to = [](const Eigen::Vector3d& x) { return Vec3<NT>{NT(x.x()), NT(x.y()), NT(x.z())}; };
  const RigidMotionOver<NT> motion{to(q.motion.pivot), to(q.motion.translation),
                                   to(q.motion.cayley)};
  const Vec3<FixedPoly<NT, 3>> X = rigid_path_numerator(motion, to(q.p));
  const FixedPoly<NT, 2> w = rigid_path_denominator(motion);
  const FixedPoly<NT, 3>* Xk[3] = {&X.x, &X.y, &X.z};
  // Spelled out over NT (with gmpxx, expressions over temporaries would dangle).
  FixedPoly<NT, 3> F;
  for (int i = 0; i < 4; ++i) F.c[i] = NT(0);
  for (int k = 0; k < 3; ++k) {
    const NT o(q.origin[k]), n(q.normal[k]);
    for (int i = 0; i < 4; ++i) {
      NT c = Xk[k]->c[i];
      if (i < 3) c -= o * w.c[i];
      F.c[i] += c * n;
    }
  }
  if (w_out) *w_out = w;
  return F;
}

/// The polynomial's enclosure over [a, b] (a <= b): Horner's rule on the interval [a, b].
/// Needs upward rounding.
template <int D>
EXACTCCD_CERTIFIED Interval enclosure_over(const FixedPoly<Interval, D>& f, double a, double b) {
  const Interval T(a, b);
  Interval r = f.c[D];
  for (int i = D - 1; i >= 0; --i) r = f.c[i] + T * r;
  return r;
}

}  // namespace exactccd::predicates
