// PROOF: proofs/point_plane.md#rigid
#include "exact/reference/rigid_point_plane.hpp"

#include "core/predicates/plane_offset.hpp"
#include "exact/reference/earliest_contact.hpp"

namespace exactccd::exact {

CcdResult rigid_point_plane_ccd_exact(const RigidPointPlaneQuery& q, const CcdOptions& options) {
  predicates::FixedPoly<Rational, 2> w;
  const predicates::FixedPoly<Rational, 3> F = predicates::rigid_plane_offset<Rational>(q, &w);
  const Polynomial f(F);
  const Rational t_max(options.t_max);
  if (options.min_separation == 0.0)
    return make_result(earliest_contact(std::vector<Polynomial>{f}, true, t_max,
                                        [&](AlgebraicTime& t) { return t.sign_of(f) == 0; }),
                       options);
  // Within delta: G <= 0. The first such s is 0 or a root of G (G is continuous).
  const Rational delta(options.min_separation);
  const Rational n0(q.normal.x()), n1(q.normal.y()), n2(q.normal.z());
  const Rational nn = n0 * n0 + n1 * n1 + n2 * n2;
  const predicates::FixedPoly<Rational, 0> scale{{Rational(delta * delta * nn)}};
  const Polynomial g(F * F - scale * (w * w));
  return make_result(earliest_contact(std::vector<Polynomial>{g}, true, t_max,
                                      [&](AlgebraicTime& t) { return t.sign_of(g) <= 0; }),
                     options);
}

}  // namespace exactccd::exact
