// t_max = 0 asks for the state at t = 0 alone (a barrier method's shrinking step reaches it).
// The one pipeline (dispatch.hpp, certified_ccd) and the rational exact_ccd answer it as the
// same query with every point held at its t = 0 position, decided over [0, 1]: nothing moves, so
// the primitives meet (or come within delta) at some t in [0, 1] iff they do at t = 0, and then
// the earliest such t is 0 exactly. The held query copies
// coordinates, never computes them, so it is exactly that query.
// PROOF: proofs/api_reductions.md#t-max-zero
#pragma once

#include "core/predicates/rigid_query.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::pipeline {

inline VertexFaceQuery held_at_start(VertexFaceQuery q) {
  q.p_t1 = q.p_t0;
  q.a_t1 = q.a_t0;
  q.b_t1 = q.b_t0;
  q.c_t1 = q.c_t0;
  return q;
}

inline EdgeEdgeQuery held_at_start(EdgeEdgeQuery q) {
  q.ea0_t1 = q.ea0_t0;
  q.ea1_t1 = q.ea1_t0;
  q.eb0_t1 = q.eb0_t0;
  q.eb1_t1 = q.eb1_t0;
  return q;
}

inline PointPlaneQuery held_at_start(PointPlaneQuery q) {
  q.p_t1 = q.p_t0;
  q.origin_t1 = q.origin_t0;
  q.normal_t1 = q.normal_t0;
  return q;
}

/// The body at rest: the zero motion keeps x(s) = p for every s.
inline RigidPointPlaneQuery held_at_start(RigidPointPlaneQuery q) {
  q.motion = {};
  return q;
}

inline RationalQuery held_at_start(RationalQuery q) {
  for (int i = 0; i < 4; ++i) q.points[4 + i] = q.points[i];
  return q;
}

/// Both sides at rest: the rigid motion with zero pivot, translation and Cayley vector moves
/// x(s) = x0 for every s.
inline predicates::DoubleRigidQuery held_at_start(predicates::DoubleRigidQuery q) {
  for (predicates::DoubleSide& side : q.side) {
    side.rigid = true;
    side.motion = {};
  }
  return q;
}

/// `decide(query, options)` answers the held query over [0, 1], read as the answer over [0, 0]:
/// a contact lies at t = 0 exactly.
/// Out of line and cold: the callers' fast path (every query with t_max > 0) stays as small as
/// it was.
template <class Query, class Decide>
[[gnu::noinline, gnu::cold]] CcdResult decided_at_start(const Query& query,
                                                        const CcdOptions& options,
                                                        Decide&& decide) {
  CcdOptions whole = options;
  whole.t_max = 1.0;
  CcdResult r = decide(held_at_start(query), whole);
  if (r.collides) r.toi_lo = r.toi_hi = 0.0;
  r.starts_within = r.collides;
  return r;
}

/// r, the answer over [0, t_max], with CcdResult::starts_within: t* = 0. Free in all but one
/// case: no contact or toi_lo > 0 gives t* > 0 (or none), toi_hi = 0 gives t* = 0; only
/// toi_lo = 0 < toi_hi (a wide toi_width, or t* below the least subnormal) asks the held
/// query. PROOF: proofs/api_reductions.md#t-max-zero
template <class Query, class Decide>
CcdResult with_start_flag(CcdResult r, const Query& query, const CcdOptions& options,
                          Decide&& decide) {
  // Resting contact (t* = 0, [0, 0]) is common in simulations: decided inline.
  if (r.collides && r.toi_lo == 0.0)
    r.starts_within = r.toi_hi == 0.0 || decided_at_start(query, options, decide).collides;
  return r;
}

}  // namespace exactccd::pipeline
