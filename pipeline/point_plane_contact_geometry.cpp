// The contact geometry of a point against a plane (linear, and a rigid body's point against a
// static plane): the point at t*, the plane's unit normal there oriented by the exact side of
// the start. PROOF: proofs/contact_geometry.md#point-plane
#include <stdexcept>

#include "core/predicates/fp_environment.hpp"
#include "core/predicates/interval.hpp"
#include "core/predicates/motion.hpp"
#include "core/predicates/rigid_motion.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exact/arithmetic/stack_dyadic.hpp"
#include "exactccd/contact.hpp"
#include "pipeline/contact_enclosures.hpp"

namespace exactccd {

namespace {

namespace contact = pipeline::contact;
using contact::Interval;
using contact::IVec;

/// The exact sign of (p - o) . n for doubles: intervals, then StackDyadic, then rationals.
int exact_sign_of_offset(const Eigen::Vector3d& p, const Eigen::Vector3d& o,
                         const Eigen::Vector3d& n) {
  {
    Interval f(0.0);
    for (int k = 0; k < 3; ++k) f += (Interval(p[k]) - Interval(o[k])) * Interval(n[k]);
    if (f.inf() > 0) return 1;
    if (f.sup() < 0) return -1;
  }
  exact::StackDyadic d;
  for (int k = 0; k < 3; ++k)
    d = d + (exact::StackDyadic(p[k]) - exact::StackDyadic(o[k])) * exact::StackDyadic(n[k]);
  if (!d.overflow()) return d.sign();
  exact::Rational r(0);
  for (int k = 0; k < 3; ++k)
    r += (exact::Rational(p[k]) - exact::Rational(o[k])) * exact::Rational(n[k]);
  return exact::sign(r);
}

IVec interval(const Eigen::Vector3d& x) { return {Interval(x.x()), Interval(x.y()), Interval(x.z())}; }

/// The geometry from the point P, the plane's point O and normal N enclosed at t*, and the side
/// of the start (sign of the offset at t = 0). Needs upward rounding.
ContactGeometry point_plane_from(const IVec& P, const IVec& O, const IVec& N, int side,
                                 bool at_start, double delta) {
  ContactGeometry g;
  g.parameter_count = 0;
  if (delta > 0.0) {
    // The closest point of the plane: P - ((P - O) . N / N . N) N.
    const Interval nn = predicates::dot(N, N);
    if (nn.inf() > 0) {
      const Interval f = predicates::dot(P - O, N) / nn;
      g.point = contact::point_of(P - IVec{f * N[0], f * N[1], f * N[2]}, 0);
    } else {
      g.point = contact::point_of(P, 0);  // no plane to project on: the point itself
    }
  } else {
    g.point = contact::point_of(P, 0);
  }
  const bool oriented = !at_start && side != 0;
  if (!contact::unit_normal(N, oriented ? side : 1, &g.normal)) {
    g.kind = ContactKind::unresolved;
    return g;
  }
  g.normal_oriented = oriented;
  g.kind = at_start ? ContactKind::at_start : ContactKind::point;
  return g;
}

void require_finite(const Eigen::Vector3d& x) {
  if (!x.allFinite())
    throw std::invalid_argument("exactccd: contact_geometry: non-finite coordinate");
}

}  // namespace

ContactGeometry contact_geometry(const PointPlaneQuery& q, const CcdResult& r,
                                 double min_separation) {
  contact::check_separation(min_separation);
  for (const Eigen::Vector3d* x :
       {&q.p_t0, &q.origin_t0, &q.normal_t0, &q.p_t1, &q.origin_t1, &q.normal_t1})
    require_finite(*x);
  contact::check_result(r);
  const predicates::RoundingGuard upward;
  const Interval t = contact::parameter_enclosure(r);
  const auto at = [&](const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
    const IVec a = interval(x0), b = interval(x1);
    return IVec{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  };
  const int side = r.starts_within ? 0 : exact_sign_of_offset(q.p_t0, q.origin_t0, q.normal_t0);
  return point_plane_from(at(q.p_t0, q.p_t1), at(q.origin_t0, q.origin_t1),
                          at(q.normal_t0, q.normal_t1), side, r.starts_within, min_separation);
}

ContactGeometry contact_geometry(const RigidPointPlaneQuery& q, const RigidCcdResult& rr,
                                 double min_separation) {
  contact::check_separation(min_separation);
  for (const Eigen::Vector3d* x : {&q.p, &q.motion.pivot, &q.motion.translation,
                                   &q.motion.cayley, &q.origin, &q.normal})
    require_finite(*x);
  const CcdResult& r = rr.ccd;
  contact::check_result(r);
  const predicates::RoundingGuard upward;
  const Interval s = contact::parameter_enclosure(r);
  const auto iv = [](const Eigen::Vector3d& x) {
    return predicates::Vec3<Interval>{Interval(x.x()), Interval(x.y()), Interval(x.z())};
  };
  const predicates::RigidMotionOver<Interval> motion{iv(q.motion.pivot), iv(q.motion.translation),
                                                     iv(q.motion.cayley)};
  const auto X = predicates::rigid_path_numerator(motion, iv(q.p));
  const Interval w = predicates::evaluate(predicates::rigid_path_denominator(motion), s);
  const IVec P{predicates::evaluate(X.x, s) / w, predicates::evaluate(X.y, s) / w,
               predicates::evaluate(X.z, s) / w};
  const int side = r.starts_within ? 0 : exact_sign_of_offset(q.p, q.origin, q.normal);
  return point_plane_from(P, interval(q.origin), interval(q.normal), side, r.starts_within,
                          min_separation);
}

}  // namespace exactccd
