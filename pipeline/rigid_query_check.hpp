// A public rigid query as the pipeline reads it (predicates::DoubleRigidQuery), every input
// checked to be finite (the message names the field): for the rigid entry points
// (rigid_ccd.cpp) and the rigid contact geometry (rigid_contact_geometry.cpp).
#pragma once

#include "core/predicates/rigid_query.hpp"
#include "exactccd/rigid.hpp"

namespace exactccd::pipeline {

/// The query in doubles; throws std::invalid_argument for a non-finite input.
predicates::DoubleRigidQuery checked_query(const RigidVertexFaceQuery& query);
/// The query in doubles; throws std::invalid_argument for a non-finite input.
predicates::DoubleRigidQuery checked_query(const RigidEdgeEdgeQuery& query);

}  // namespace exactccd::pipeline
