// Exact intersection test of two closed triangles with double coordinates.
//
// Every decision is a filtered exact predicate of CGAL's Exact_predicates_inexact_constructions
// kernel evaluated on the input doubles themselves (no constructed point is ever compared), so
// the answer is exact for every finite input. Degenerate triangles are the point sets they are:
// three collinear vertices span a segment, three equal vertices a point.
// PROOF: proofs/discrete.md#triangle-test
#pragma once

#include <Eigen/Core>

namespace exactccd::exact {

/// True iff the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point. Throws
/// std::invalid_argument for a NaN or infinite coordinate.
bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                         const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                         const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

}  // namespace exactccd::exact
