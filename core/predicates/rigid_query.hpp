// A rigid (or per-vertex linear) query in doubles, as the public RigidVertexFaceQuery /
// RigidEdgeEdgeQuery give it, exactly: the one form the filters, the float_only test and the
// exact path's conversion read (the pipeline checks the input and builds it once per query).
#pragma once

#include <array>

#include "core/predicates/rigid_motion.hpp"
#include "exactccd/types.hpp"

namespace exactccd::predicates {

/// One side of a rigid query in doubles (as the public SideMotion, exactly).
struct DoubleSide {
  bool rigid = true;
  /// Zero unless set ({}: Vec3 has no initialisers of its own; the filters read the motion of a
  /// linear side too, and must never see indeterminate doubles).
  RigidMotionOver<double> motion{};
  std::array<Vec3<double>, 3> end{};
};

/// Positions at s = 0 in the public queries' order, and the two sides (rigid_ccd.hpp's layout).
struct DoubleRigidQuery {
  QueryType type = QueryType::vertex_face;
  std::array<Vec3<double>, 4> start;
  std::array<DoubleSide, 2> side;
};

}  // namespace exactccd::predicates
