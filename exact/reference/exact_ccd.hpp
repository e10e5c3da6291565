// The exact decision procedure: coplanarity cubic, exact root isolation, exact inclusion at
// each root, reductions for motion that is coplanar throughout.
// PROOF: proofs/exact_ccd.md
#pragma once

#include "exactccd/rational_query.hpp"

namespace exactccd::exact {

/// Options must already be validated (t_max in (0, 1], toi_width >= 0 finite).
CcdResult vertex_face_ccd_exact(const RationalQuery& query, const CcdOptions& options);
CcdResult edge_edge_ccd_exact(const RationalQuery& query, const CcdOptions& options);

}  // namespace exactccd::exact
