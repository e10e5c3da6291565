// The pose a rigid body ends a step in, for `exactccd rigid`'s next step: the exact position
// at s = 1 (rational), rounded to the nearest doubles.
#pragma once

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::cli {

/// Each vertex's exact position at s = 1 under `motion`, c + d + C(q)(x0 - c) over the
/// rationals, each coordinate rounded to the nearest double (ties to even). `rounding`
/// receives an upper bound of the largest |rounded - exact| over all coordinates (0 when every
/// one is a double). Throws InputError (naming `what`) when a coordinate is beyond the doubles.
Positions rounded_end_pose(const Positions& start, const RigidMotion& motion, double* rounding,
                           const std::string& what);

}  // namespace exactccd::cli
