// PROOF: proofs/point_plane.md#rigid
#include "exact/reference/rigid_point_plane.hpp"

#include "core/predicates/rigid_motion.hpp"
#include "exact/reference/earliest_contact.hpp"

namespace exactccd::exact {

CcdResult rigid_point_plane_ccd_exact(const RigidPointPlaneQuery& q, const CcdOptions& options) {
  using predicates::FixedPoly;
  using predicates::Vec3;
  const auto to = [](const Eigen::Vector3d& x) {
    return Vec3<Rational>{Rational(x.x()), Rational(x.y()), Rational(x.z())};
  };
  const predicates::RigidMotionOver<Rational> motion{to(q.motion.pivot), to(q.motion.translation),
                                                     to(q.motion.cayley)};
  const Vec3<FixedPoly<Rational, 3>> X = predicates::rigid_path_numerator(motion, to(q.p));
  const FixedPoly<Rational, 2> w = predicates::rigid_path_denominator(motion);
  const Vec3<Rational> o = to(q.origin), n = to(q.normal);
  // F = sum_k (X_k - o_k w) n_k, spelled out (no expression templates over temporaries).
  FixedPoly<Rational, 3> F{};
  const FixedPoly<Rational, 3>* Xk[3] = {&X.x, &X.y, &X.z};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 4; ++i) {
      Rational c = Xk[k]->c[i];
      if (i < 3) c -= o[k] * w.c[i];
      F.c[i] += c * n[k];
    }
  const Polynomial f(F);
  const Rational t_max(options.t_max);
  if (options.min_separation == 0.0)
    return make_result(earliest_contact(std::vector<Polynomial>{f}, true, t_max,
                                        [&](AlgebraicTime& t) { return t.sign_of(f) == 0; }),
                       options);
  // Within delta: G <= 0. The first such s is 0 or a root of G (G is continuous).
  const Rational delta(options.min_separation);
  const Rational nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const FixedPoly<Rational, 0> scale{{Rational(delta * delta * nn)}};
  const Polynomial g(F * F - scale * (w * w));
  return make_result(earliest_contact(std::vector<Polynomial>{g}, true, t_max,
                                      [&](AlgebraicTime& t) { return t.sign_of(g) <= 0; }),
                     options);
}

}  // namespace exactccd::exact
