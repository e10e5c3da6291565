// The contact time of a pure rotation from its motion parameter (rigid.hpp: a body turning
// about a fixed axis with Cayley vector q is at angle 2 atan(s |q|) at s, so the constant-speed
// time is t(s) = atan(s |q|) / atan(|q|)).
// PROOF: proofs/rigid_ccd.md#time-of-rotation
#pragma once

#include <utility>

#include "core/predicates/motion.hpp"

namespace exactccd::pipeline {

/// A certified enclosure of t(s) = atan(s r) / atan(r) over s in [s_lo, s_hi], r = |q| > 0:
/// every operation rounded outwards by MPFR.
std::pair<double, double> rotation_time(const predicates::Vec3<double>& q, double s_lo,
                                        double s_hi);

}  // namespace exactccd::pipeline
