// The exact decision procedure of a point of a rigid body against a static plane. The point's
// path is x(s) = X(s) / w(s) (core/predicates/rigid_motion.hpp: X of degree <= 3, w = 1 +
// s^2 |q|^2 > 0), so with F(s) = (X(s) - o w(s)) . n, of degree <= 3, the signed offset
// (x(s) - o) . n is F / w: contact at s iff F(s) = 0; within delta iff
// G(s) = F(s)^2 - delta^2 |n|^2 w(s)^2 <= 0, of degree <= 6.
// PROOF: proofs/point_plane.md#rigid
#pragma once

#include <Eigen/Core>

#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

/// The exact answer over [0, options.t_max] of the motion parameter s (options.min_separation:
/// delta; the tightest TOI pair, or options.toi_width), every decision in rational arithmetic.
/// Finite doubles, a non-zero normal.
CcdResult rigid_point_plane_ccd_exact(const RigidPointPlaneQuery& q, const CcdOptions& options);

}  // namespace exactccd::exact
