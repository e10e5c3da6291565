// Certified floating-point decisions for minimum-separation CCD (delta > 0): culling by swept
// boxes more than delta apart, then a search over adaptively subdivided time intervals
// (separating directions, signs of the region polynomials) for the first time within delta.
// `uncertain` sends the query to the exact path. PROOF: proofs/min_separation.md#filters
#pragma once

#include <array>
#include <cstdint>

#include "core/predicates/separation_exact_stage.hpp"
#include "filters/filter_outcome.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filters {

/// Certainly never within delta: the swept boxes are more than delta apart on one axis.
bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta);
bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta);

/// The interval stages on finite input, options validated, delta = options.min_separation > 0;
/// `exact` answers for the same query (exact/stages/separation_exact_signs.hpp) where the
/// intervals cannot tell. Called rounding to nearest, without flush-to-zero (the library's
/// entries set it; the whole-step test relies on it and the rest sets its own mode). No heap
/// allocation but the exact stage's.
FilterOutcome vertex_face_separation_filter(const VertexFaceQuery& q, const CcdOptions& options,
                                            const predicates::SeparationExactStage& exact);
FilterOutcome edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options,
                                          const predicates::SeparationExactStage& exact);

}  // namespace exactccd::filters
