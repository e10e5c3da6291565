// exactccd: exact continuous collision detection for linearly moving vertices.
//
// Both functions are exact for every finite input (degenerate ones included): `collides` is
// the true answer for the closed primitives over the closed interval [0, t_max], and
// [toi_lo, toi_hi] contains the exact earliest contact time. They are thread-safe (no shared
// state). Non-finite coordinates or options outside their domain throw std::invalid_argument.
#pragma once

#include "exactccd/types.hpp"

namespace exactccd {

/// Vertex p against the closed triangle (a, b, c), over [0, options.t_max].
CcdResult vertex_face_ccd(const VertexFaceQuery& query, const CcdOptions& options = {});

/// Closed segment [ea0, ea1] against the closed segment [eb0, eb1], over [0, options.t_max].
CcdResult edge_edge_ccd(const EdgeEdgeQuery& query, const CcdOptions& options = {});

}  // namespace exactccd
