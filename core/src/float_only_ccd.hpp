// The classic, uncertified cubic CCD test in plain double arithmetic (Mode::float_only).
#pragma once

#include "exactccd/types.hpp"

namespace exactccd::float_only {

CcdResult vertex_face_ccd(const VertexFaceQuery& q, const CcdOptions& options);
CcdResult edge_edge_ccd(const EdgeEdgeQuery& q, const CcdOptions& options);

}  // namespace exactccd::float_only
