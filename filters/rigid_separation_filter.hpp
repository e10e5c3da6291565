// Certified floating-point decisions for rigid (and per-vertex linear) motion with a minimum
// separation delta > 0: the region polynomials of core/predicates/separation.hpp evaluated on
// interval boxes of the positions over adaptively subdivided parameter intervals, earliest
// first; on the first piece where one region polynomial alone decides and is monotone, its
// root tightened by certified signs at doubles (exact where the intervals cannot tell).
// PROOF: proofs/min_separation.md#rigid-separation-filter
#pragma once

#include "filters/rigid_filter.hpp"
#include "filters/separation_filter.hpp"

namespace exactccd::filters {

/// The interval stages of a rigid query (finite, options validated, delta =
/// options.min_separation > 0), the same outcome as the linear separation filter's: a verdict,
/// or `uncertain` with what it cleared for the exact path. `exact` gives exact signs of the
/// region polynomials at doubles. Sets and restores its own rounding mode; no heap allocation
/// but the exact stage's.
FilterOutcome rigid_separation_filter(const DoubleRigidQuery& query, const CcdOptions& options,
                                          RigidExactStage& exact);

}  // namespace exactccd::filters
