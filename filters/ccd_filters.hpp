// Certified floating-point decisions for vertex-face and edge-edge CCD: culling, then the
// cubic filter. An `uncertain` outcome sends the query to the exact path.
#pragma once

#include "exactccd/types.hpp"
#include "filters/cubic_filter.hpp"

namespace exactccd::filters {

/// Certain no-contact by disjoint swept boxes (exact comparisons).
bool vertex_face_ccd_culling(const VertexFaceQuery& q);
bool edge_edge_ccd_culling(const EdgeEdgeQuery& q);

/// The semi-static and interval cubic filters on finite input; options already validated.
/// `exact` is consulted only where the interval tests cannot decide.
FilterOutcome vertex_face_ccd_filter(const VertexFaceQuery& q, const CcdOptions& options,
                                 ContactExactStage& exact);
FilterOutcome edge_edge_ccd_filter(const EdgeEdgeQuery& q, const CcdOptions& options,
                               ContactExactStage& exact);

}  // namespace exactccd::filters
