// Certified floating-point decisions for minimum-separation CCD (delta > 0): culling by swept
// boxes more than delta apart, separating directions over adaptively subdivided time
// intervals (never within delta), and "within delta at t = 0". `uncertain` sends the query to
// the exact path. PROOF: proofs/min_separation.md#filters
#pragma once

#include <cstdint>

#include "exactccd/types.hpp"

namespace exactccd::filters {

/// Certainly never within delta: the swept boxes are more than delta apart on one axis.
bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta);
bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta);

enum class SeparationVerdict : std::uint8_t {
  never_within,    ///< certainly never within delta on [0, t_max]
  within_at_zero,  ///< certainly within delta at t = 0 (the TOI is 0)
  uncertain,
};

/// The interval stages on finite input, options validated, delta = options.min_separation > 0.
/// No heap allocation.
SeparationVerdict vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options);
SeparationVerdict edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options);

}  // namespace exactccd::filters
