// A point of a rigid body against a static plane, as an instance of the one pipeline
// (dispatch.hpp): F(s) = (X(s) - o w(s)) . n of degree <= 3 (contact) or
// G = F^2 - delta^2 |n|^2 w^2 of degree <= 6 (minimum separation), X / w the point's rational
// path (core/predicates/rigid_motion.hpp). The filter encloses the polynomial by interval
// arithmetic over eight pieces of [0, t_max] and certifies "no contact" when it keeps a certain
// sign on each; everything else goes to the exact path (exact/reference/rigid_point_plane.cpp).
// PROOF: proofs/point_plane.md#rigid
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/float_only/float_only_ccd.hpp"
#include "core/predicates/fp_environment.hpp"
#include "core/predicates/interval.hpp"
#include "core/predicates/plane_offset.hpp"
#include "exact/reference/rigid_point_plane.hpp"
#include "exactccd/rigid.hpp"
#include "pipeline/ccd_options_check.hpp"
#include "pipeline/dispatch.hpp"
#include "pipeline/rotation_time.hpp"

namespace exactccd {

namespace pipeline {

namespace {

using predicates::FixedPoly;

struct RigidPointPlane : WithoutExactStage<RigidPointPlane, RigidPointPlaneQuery> {
  using Query = RigidPointPlaneQuery;
  static constexpr int kPieces = 8;

  static CcdResult exact(const Query& q, const CcdOptions& o) {
    return exact::rigid_point_plane_ccd_exact(q, o);
  }
  /// The cubic's roots in doubles; with delta, the double distance at each compared with delta
  /// (the common practice). Uncertified.
  static CcdResult float_only(const Query& q, const CcdOptions& o) {
    FixedPoly<double, 2> w;
    const FixedPoly<double, 3> F = predicates::rigid_plane_offset<double>(q, &w);
    const double n = q.normal.norm();
    const auto distance_at = [&](double s) {
      const double f = F.c[0] + s * (F.c[1] + s * (F.c[2] + s * F.c[3]));
      return std::abs(f) / ((w.c[0] + s * s * w.c[2]) * n);
    };
    CcdResult r;
    r.decided_by = Stage::float_only;
    if (o.min_separation > 0.0 && distance_at(0.0) <= o.min_separation) {
      r.collides = true;
      r.toi_lo = r.toi_hi = 0.0;
      return r;
    }
    double roots[3];
    const int count = float_only::cubic_roots(F, o.t_max, roots);
    for (int i = 0; i < count; ++i)
      if (o.min_separation == 0.0 || distance_at(roots[i]) <= o.min_separation) {
        r.collides = true;
        r.toi_lo = r.toi_hi = roots[i];
        break;
      }
    return r;
  }
  /// No contact when the polynomial keeps a certain sign on every piece of [0, t_max]
  /// (contact: F != 0; within delta: G > 0), by interval arithmetic with upward rounding.
  static FilterOutcome filter(const Query& q, const CcdOptions& o, NoStage&) {
    const predicates::RoundingGuard upward;
    using predicates::Interval;
    FixedPoly<Interval, 2> w;
    const FixedPoly<Interval, 3> F = predicates::rigid_plane_offset<Interval>(q, &w);
    FixedPoly<Interval, 6> G;
    if (o.min_separation > 0.0) {
      Interval nn(0.0);
      for (int k = 0; k < 3; ++k) nn += Interval(q.normal[k]) * Interval(q.normal[k]);
      const Interval delta(o.min_separation);
      const FixedPoly<Interval, 0> scale{{delta * delta * nn}};
      G = F * F - scale * (w * w);
    }
    FilterOutcome out;
    for (int k = 0; k < kPieces; ++k) {
      // Piece ends: k t_max / kPieces, rounded either way, so the pieces cover [0, t_max].
      const double a = k == 0 ? 0.0 : -(-o.t_max * k / kPieces);  // rounded down
      const double b = k + 1 == kPieces ? o.t_max : o.t_max * (k + 1) / kPieces;  // rounded up
      const bool apart = o.min_separation == 0.0
                             ? predicates::certain_strict_sign(predicates::enclosure_over(F, a, b)) != 0
                             : predicates::enclosure_over(G, a, b).inf() > 0;
      if (!apart) return out;  // uncertain: the exact path
    }
    out.verdict = FilterOutcome::Verdict::no_contact;
    return out;
  }
};

void require_finite(const Eigen::Vector3d& x, const char* name) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + name);
}

}  // namespace

}  // namespace pipeline

RigidCcdResult point_plane_ccd(const RigidPointPlaneQuery& q, const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  pipeline::require_finite(q.p, "p");
  pipeline::require_finite(q.motion.pivot, "motion.pivot");
  pipeline::require_finite(q.motion.translation, "motion.translation");
  pipeline::require_finite(q.motion.cayley, "motion.cayley");
  pipeline::require_finite(q.origin, "origin");
  pipeline::require_finite(q.normal, "normal");
  if (q.normal.isZero(0.0))
    throw std::invalid_argument("exactccd: point_plane_ccd: the normal is zero: no plane");
  RigidCcdResult r;
  r.ccd = pipeline::certified_ccd<pipeline::RigidPointPlane>(q, options);
  // The time (rigid.hpp): s itself without rotation, t(s) for a pure rotation about a fixed
  // axis (the plane does not move), undefined otherwise.
  if (q.motion.cayley.isZero(0.0)) {
    r.has_time = true;
    r.time_lo = r.ccd.toi_lo;
    r.time_hi = r.ccd.toi_hi;
  } else if (q.motion.translation.isZero(0.0)) {
    r.has_time = true;
    if (r.ccd.collides)
      std::tie(r.time_lo, r.time_hi) = pipeline::rotation_time(
          {q.motion.cayley.x(), q.motion.cayley.y(), q.motion.cayley.z()}, r.ccd.toi_lo,
          r.ccd.toi_hi);
  }
  return r;
}

}  // namespace exactccd
