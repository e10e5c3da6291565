// Certified filters of rigid (and per-vertex linear) queries: on pieces of [0, t_max], interval
// boxes of each primitive's swept arc (culling) and an interval enclosure of the coplanarity
// polynomial that excludes pieces without a root. Each decides "no contact" or nothing.
// PROOF: proofs/rigid_ccd.md#filters
#pragma once

#include <array>
#include <optional>

#include "core/predicates/rigid_motion.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filters {

/// One side of a rigid query in doubles (as the public SideMotion, exactly).
struct DoubleSide {
  bool rigid = true;
  predicates::RigidMotionOver<double> motion;
  std::array<predicates::Vec3<double>, 3> end;
};

/// Positions at s = 0 in the public queries' order, and the two sides (rigid_ccd.hpp's layout).
struct DoubleRigidQuery {
  QueryType type = QueryType::vertex_face;
  std::array<predicates::Vec3<double>, 4> start;
  std::array<DoubleSide, 2> side;
};

/// A result with Stage::culling or Stage::filter when the filters prove that the primitives
/// never meet on [0, options.t_max]; nothing otherwise (never a contact: contacts go to the
/// exact path). Sets and restores its own rounding mode; allocates nothing.
std::optional<CcdResult> rigid_no_contact_filter(const DoubleRigidQuery& query,
                                                 const CcdOptions& options);

}  // namespace exactccd::filters
