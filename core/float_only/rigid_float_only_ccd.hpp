// The uncertified floating-point test of rigid (and per-vertex linear) queries: Mode::float_only
// of exactccd/rigid.hpp, the counterpart of the linear float_only test (float_only_ccd.hpp).
//
// In plain double arithmetic: the reduced coplanarity polynomial g of the query (degree <= 5 in
// the motion parameter s, core/predicates/rigid_coplanarity.hpp instantiated with double), its
// roots in [0, t_max] (polynomial_roots: the derivatives' roots split [0, t_max] into monotone
// pieces, recursively down to degree 1, and each piece whose ends differ in sign is bisected),
// then, earliest first, the inclusion test of core/predicates/inclusion.hpp on the positions at
// the root computed in doubles (x(s) = X(s) / w(s), core/predicates/rigid_motion.hpp). The first
// root that passes is the TOI: toi_lo == toi_hi == that double, decided_by Stage::float_only;
// +infinity when none passes. A g that vanishes identically in doubles (motion coplanar
// throughout) is sampled instead: the inclusion test at 65 equally spaced parameters, the first
// transition to contact narrowed by bisection of the inclusion verdict.
//
// UNCERTIFIED, for comparison only: rounding moves, creates and loses roots (a double root of g,
// a grazing contact, is usually missed) and flips inclusion signs, so it misses contacts and
// reports false ones. Nothing in the certified path depends on it.
#pragma once

#include "core/predicates/motion.hpp"
#include "core/predicates/rigid_query.hpp"
#include "exactccd/types.hpp"

namespace exactccd::float_only {

/// The float_only test of a rigid query (vertex-face or edge-edge, as query.type says) over s in
/// [0, options.t_max] (options already validated, the query checked finite by the pipeline;
/// toi_width is not read: the TOI is one double). With min_separation > 0 the common practice
/// instead: the instant predicate "within delta" (core/predicates/separation.hpp) in doubles at
/// 65 equally spaced parameters, the first transition bisected (a contact shorter than the
/// spacing is missed). The time of a rotation is left to the caller.
CcdResult rigid_ccd(const predicates::DoubleRigidQuery& query, const CcdOptions& options);

/// The roots in [0, t_max] of the degree-5 polynomial g found in double arithmetic, ascending,
/// at most 5, written to roots; returns their count (0 for the zero polynomial: the caller
/// handles it). Each is the lower end of the last bisection bracket (or an exact double zero).
/// Uncertified.
int polynomial_roots(const predicates::FixedPoly<double, 5>& g, double t_max, double roots[5]);

}  // namespace exactccd::float_only
