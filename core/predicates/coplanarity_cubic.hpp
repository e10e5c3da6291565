// The coplanarity cubics of vertex-face and edge-edge CCD (Provot 1997; Redon et al. 2002).
// PROOF: proofs/exact_ccd.md#coplanarity-cubic
#pragma once

#include "core/predicates/motion.hpp"

namespace exactccd::predicates {

template <class NT>
using MovingPoint = Vec3<FixedPoly<NT, 1>>;

/// det[b - a, c - a, p - a](t): zero exactly when p(t), a(t), b(t), c(t) are coplanar, in
/// particular whenever p(t) lies in the closed triangle, degenerate triangles included.
template <class NT>
EXACTCCD_CERTIFIED
FixedPoly<NT, 3> vertex_face_coplanarity_cubic(const MovingPoint<NT>& p, const MovingPoint<NT>& a,
                                               const MovingPoint<NT>& b, const MovingPoint<NT>& c) {
  return dot(cross(b - a, c - a), p - a);
}

/// det[a1 - a0, b0 - a0, b1 - a0](t): zero exactly when the four endpoints are coplanar, in
/// particular whenever the closed segments [a0, a1] and [b0, b1] meet.
template <class NT>
EXACTCCD_CERTIFIED
FixedPoly<NT, 3> edge_edge_coplanarity_cubic(const MovingPoint<NT>& a0, const MovingPoint<NT>& a1,
                                             const MovingPoint<NT>& b0, const MovingPoint<NT>& b1) {
  return dot(cross(a1 - a0, b0 - a0), b1 - a0);
}

}  // namespace exactccd::predicates
