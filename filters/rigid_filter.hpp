// The certified floating-point path of rigid (and per-vertex linear) queries: the reduced
// coplanarity polynomial g (degree <= 5, core/predicates/rigid_coplanarity.hpp) in interval
// arithmetic, its roots on [0, t_max] isolated earliest first by Bernstein subdivision, the
// inclusion tests on interval boxes of the positions over each root's bracket, and the bracket
// narrowed to the TOI by certified signs at doubles. Exact signs of g at doubles are consulted
// where the intervals cannot tell; anything else undecided is left to the exact path.
// PROOF: proofs/rigid_ccd.md#filters
#pragma once

#include <array>

#include "core/predicates/rigid_exact_stage.hpp"
#include "core/predicates/rigid_query.hpp"
#include "exactccd/types.hpp"
#include "filters/filter_outcome.hpp"

namespace exactccd::filters {

using predicates::DoubleRigidQuery;
using predicates::DoubleSide;

using predicates::RigidExactStage;

/// The verdict and TOI of the query when the filters decide it (culled, by the intervals, the
/// TOI narrowed with exact signs, or the verdict by exact signs), the TOI equal to the exact
/// path's for toi_width = 0 (the tightest pair of doubles around the first contact); uncertain
/// when they cannot (then the exact path decides). Sets and restores its own rounding mode;
/// allocates nothing itself (`exact` may).
FilterOutcome rigid_ccd_filter(const DoubleRigidQuery& query, const CcdOptions& options,
                               RigidExactStage& exact);

}  // namespace exactccd::filters
