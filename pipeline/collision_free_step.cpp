// The collision-free step (step.hpp): one minimum-separation query of the one pipeline at an
// effective separation delta' between delta and the start's distance. The distance at t = 0 is
// only estimated in doubles; the query itself certifies the choice (it reports whether the pair
// starts within delta'), and a wrong estimate only lowers delta' towards delta.
// PROOF: proofs/api_reductions.md#collision-free-step
#include "exactccd/step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/float_only/tolerance_ccd.hpp"
#include "core/predicates/fp_environment.hpp"
#include "exactccd/ccd.hpp"
#include "pipeline/ccd_options_check.hpp"

namespace exactccd {

namespace {

/// t_max and min_separation as every CCD option; the step's own two options.
void check_step_options(const StepOptions& o) {
  CcdOptions ccd;
  ccd.t_max = o.t_max;
  ccd.min_separation = o.min_separation;
  check_ccd_options(ccd);
  if (!(o.conservative_rescaling > 0.0 && o.conservative_rescaling <= 1.0))
    throw_bad_option("conservative_rescaling must lie in (0, 1]", o.conservative_rescaling);
  if (!(o.max_margin >= 0.0))
    throw_bad_option("max_margin must be >= 0 (+infinity: no cap)", o.max_margin);
}

/// The step from `limit`, the certified answer at separation `effective` (delta'), or, when
/// given, from `robust`, the answer at delta' + slack (which does not start within it).
StepResult step_of(const CcdResult& limit, const CcdResult* robust, double effective,
                   const StepOptions& o) {
  StepResult out;
  out.effective_separation = effective;
  if (!limit.collides) {
    out.step = o.t_max;
    return out;
  }
  out.limited = true;
  if (limit.starts_within) {  // only reached at effective == delta
    out.step = 0.0;
    out.starts_within = true;
    return out;
  }
  if (robust) {  // the distance is >= delta' + slack before robust->toi_lo
    out.step = robust->toi_lo;
    return out;
  }
  out.step = limit.toi_lo;
  // At delta itself toi_lo may be t* (the distance there is delta): one double earlier is
  // strictly before it. Above delta, the distance at t* is delta' > delta already.
  if (effective == o.min_separation && limit.toi_lo == limit.toi_hi)
    out.step = std::nextafter(limit.toi_lo, 0.0);
  return out;
}

/// The step, given the distance at t = 0 estimated in doubles, the rounding slack and
/// `decide`, the certified query at given options.
template <class Decide>
StepResult collision_free(double start_distance, double slack, const StepOptions& o,
                          Decide&& decide) {
  check_step_options(o);
  const double delta = o.min_separation;
  double excess = (1.0 - o.conservative_rescaling) * (start_distance - delta);
  if (!(excess > 0.0)) excess = 0.0;  // also NaN: no estimate, no margin
  excess = std::min({excess, o.max_margin, std::numeric_limits<double>::max()});
  while (!std::isfinite(delta + excess)) excess *= 0.5;
  CcdOptions options;
  options.t_max = o.t_max;
  // Lower delta' towards delta, each time by a squared factor (2, 4, 16, 256, ...), so that
  // even an estimate wrong by a factor 2^2000 costs a dozen queries.
  double factor = 2.0;
  for (;;) {
    const double effective = delta + excess;
    options.min_separation = effective;
    const CcdResult r = decide(options);
    if (r.starts_within && effective != delta) {
      excess /= factor;
      factor = factor > 1e150 ? std::numeric_limits<double>::infinity() : factor * factor;
      continue;
    }
    // Limited: step where the distance is still delta' + slack, so that the caller's rounded
    // positions there stay beyond delta' (one more query, for limited pairs only).
    if (r.collides && !r.starts_within && slack > 0) {
      options.min_separation = effective + slack;
      if (std::isfinite(options.min_separation)) {
        const CcdResult robust = decide(options);
        if (!robust.starts_within) return step_of(r, &robust, effective, o);
      }
    }
    return step_of(r, nullptr, effective, o);
  }
}

/// The rounding slack of a linear query whose largest |coordinate| is `largest`: twice a bound
/// on how far rounding the positions at a time t to doubles, by x0 + t (x1 - x0) or
/// (1 - t) x0 + t x1, can move the distance (proofs/api_reductions.md#collision-free-step).
double rounding_slack(double largest) { return std::ldexp(largest, -46) + std::ldexp(1.0, -1070); }

template <class... Vectors>
double largest_coordinate(const Vectors&... v) {
  return std::max({v.cwiseAbs().maxCoeff()...});
}

Eigen::Vector3d in_plane_z0(const Eigen::Vector2d& v) { return {v.x(), v.y(), 0.0}; }

/// The distance estimates, in plain doubles (nothing relies on them).
double start_distance(const VertexFaceQuery& q) {
  return methods::point_triangle_distance(q.p_t0, q.a_t0, q.b_t0, q.c_t0);
}
double start_distance(const EdgeEdgeQuery& q) {
  return methods::segment_segment_distance(q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0);
}
double start_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& e0,
                      const Eigen::Vector3d& e1) {
  return methods::point_segment_distance(p, e0, e1);
}
double start_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  return (p - q).norm();
}
double start_distance(const RigidVertexFaceQuery& q) {
  return methods::point_triangle_distance(q.p, q.a, q.b, q.c);
}
double start_distance(const RigidEdgeEdgeQuery& q) {
  return methods::segment_segment_distance(q.ea0, q.ea1, q.eb0, q.eb1);
}

/// The certified query of each kind (the public entry points: each validates and owns the
/// FP state).
CcdResult ccd_of(const VertexFaceQuery& q, const CcdOptions& c) { return vertex_face_ccd(q, c); }
CcdResult ccd_of(const EdgeEdgeQuery& q, const CcdOptions& c) { return edge_edge_ccd(q, c); }
CcdResult ccd_of(const PointEdgeQuery& q, const CcdOptions& c) { return point_edge_ccd(q, c); }
CcdResult ccd_of(const PointPointQuery& q, const CcdOptions& c) { return point_point_ccd(q, c); }
CcdResult ccd_of(const PointEdgeQuery2d& q, const CcdOptions& c) {
  return point_edge_ccd_2d(q, c);
}
CcdResult ccd_of(const PointPointQuery2d& q, const CcdOptions& c) {
  return point_point_ccd_2d(q, c);
}
CcdResult ccd_of(const RigidVertexFaceQuery& q, const CcdOptions& c) {
  return vertex_face_ccd(q, c).ccd;
}
CcdResult ccd_of(const RigidEdgeEdgeQuery& q, const CcdOptions& c) {
  return edge_edge_ccd(q, c).ccd;
}

/// The step of a query: `start()` estimates the distance at t = 0, `largest` is its largest
/// |coordinate| (negative: no rounding slack, rigid queries). Rounding to nearest for the
/// estimate and the margins, the caller's FP state restored on return (each query sets its
/// own).
template <class Query, class Start>
StepResult step_of_query(const Query& q, Start&& start, double largest, const StepOptions& o) {
  const predicates::RoundToNearestGuard nearest;
  return collision_free(start(), largest < 0 ? 0.0 : rounding_slack(largest), o,
                        [&](const CcdOptions& c) { return ccd_of(q, c); });
}

}  // namespace

StepResult collision_free_step(const VertexFaceQuery& q, const StepOptions& o) {
  return step_of_query(
      q, [&] { return start_distance(q); },
      largest_coordinate(q.p_t0, q.a_t0, q.b_t0, q.c_t0, q.p_t1, q.a_t1, q.b_t1, q.c_t1), o);
}

StepResult collision_free_step(const EdgeEdgeQuery& q, const StepOptions& o) {
  return step_of_query(q, [&] { return start_distance(q); },
                       largest_coordinate(q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1,
                                          q.ea1_t1, q.eb0_t1, q.eb1_t1),
                       o);
}

StepResult collision_free_step(const PointEdgeQuery& q, const StepOptions& o) {
  return step_of_query(
      q, [&] { return start_distance(q.p_t0, q.e0_t0, q.e1_t0); },
      largest_coordinate(q.p_t0, q.e0_t0, q.e1_t0, q.p_t1, q.e0_t1, q.e1_t1), o);
}

StepResult collision_free_step(const PointPointQuery& q, const StepOptions& o) {
  return step_of_query(q, [&] { return start_distance(q.p_t0, q.q_t0); },
                       largest_coordinate(q.p_t0, q.q_t0, q.p_t1, q.q_t1), o);
}

StepResult collision_free_step(const PointEdgeQuery2d& q, const StepOptions& o) {
  return step_of_query(
      q,
      [&] {
        return start_distance(in_plane_z0(q.p_t0), in_plane_z0(q.e0_t0), in_plane_z0(q.e1_t0));
      },
      largest_coordinate(q.p_t0, q.e0_t0, q.e1_t0, q.p_t1, q.e0_t1, q.e1_t1), o);
}

StepResult collision_free_step(const PointPointQuery2d& q, const StepOptions& o) {
  return step_of_query(q, [&] { return start_distance(in_plane_z0(q.p_t0), in_plane_z0(q.q_t0)); },
                       largest_coordinate(q.p_t0, q.q_t0, q.p_t1, q.q_t1), o);
}

// Rigid positions are formed by the rigid motion's rational formula, whose rounding the slack
// does not bound: no slack.
StepResult collision_free_step(const RigidVertexFaceQuery& q, const StepOptions& o) {
  return step_of_query(q, [&] { return start_distance(q); }, -1.0, o);
}

StepResult collision_free_step(const RigidEdgeEdgeQuery& q, const StepOptions& o) {
  return step_of_query(q, [&] { return start_distance(q); }, -1.0, o);
}

}  // namespace exactccd
