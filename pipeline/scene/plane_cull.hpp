// The broad phase of a plane (Scene::add_plane): one certified test per vertex, no hierarchy
// (for a rigid body's vertex, its certified box over the step against the plane, at the end).
//
// For a static plane {x : (x - o) . n = 0}, f(t) = (p(t) - o) . n is linear in t along a
// vertex's straight path, so it lies between f(0) and f(1). The vertex comes within delta of
// the plane (|f| <= delta |n|) only if that range meets [-delta |n|, delta |n|]. f(0), f(1) and
// delta |n| are enclosed by interval arithmetic with directed rounding (the caller holds upward
// rounding, predicates::RoundingGuard), so a vertex cut here never comes within delta. An
// overflow or a NaN end never cuts (every comparison with it is false).
// PROOF: proofs/scene.md#planes
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "core/predicates/interval.hpp"
#include "exactccd/types.hpp"

namespace exactccd::scene {

/// True when the point moving linearly from p0 (t = 0) to p1 (t = 1) stays more than delta >= 0
/// from the plane through `origin` with normal `normal` (0: never touches it) at every t in
/// [0, window], window in [0, 1]. Over [0, window], f runs from f(0) to f(window) = f(0) +
/// window (f(1) - f(0)), enclosed from the enclosures of f(0) and f(1). Needs upward rounding.
EXACTCCD_CERTIFIED bool apart_from_plane(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                         const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& normal, double delta,
                                         double window = 1.0) {
  using predicates::Interval;
  const auto signed_offset = [&](const Eigen::Vector3d& p) {
    Interval f(0.0);
    for (int k = 0; k < 3; ++k)
      f += (Interval(p[k]) - Interval(origin[k])) * Interval(normal[k]);
    return f;
  };
  const Interval f0 = signed_offset(p0), f1 = signed_offset(p1);
  const Interval f_end = window == 1.0 ? f1 : f0 + Interval(window) * (f1 - f0);
  double reach = 0.0;  // an upper bound of delta |n|
  if (delta > 0.0) {
    Interval nn(0.0);
    for (int k = 0; k < 3; ++k) nn += Interval(normal[k]) * Interval(normal[k]);
    reach = (Interval(delta) * CGAL::sqrt(nn)).sup();
  }
  return (f0.inf() > reach && f_end.inf() > reach) ||
         (f0.sup() < -reach && f_end.sup() < -reach);
}

/// True when every point of the box lo <= x <= hi (a certified box of a rigid body's vertex
/// over some s-range, rigid_boxes.hpp) is more than delta >= 0 from the plane: the offset
/// (x - origin) . normal enclosed over the box is certainly beyond delta |n|. A box with a
/// non-finite end cuts nothing. Needs upward rounding.
EXACTCCD_CERTIFIED bool box_apart_from_plane(const std::array<double, 3>& lo,
                                             const std::array<double, 3>& hi,
                                             const Eigen::Vector3d& origin,
                                             const Eigen::Vector3d& normal, double delta) {
  using predicates::Interval;
  Interval f(0.0), nn(0.0);
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(lo[k]) || !std::isfinite(hi[k]) || !(lo[k] <= hi[k])) return false;
    f += (Interval(lo[k], hi[k]) - Interval(origin[k])) * Interval(normal[k]);
    nn += Interval(normal[k]) * Interval(normal[k]);
  }
  const double reach = delta > 0.0 ? (Interval(delta) * CGAL::sqrt(nn)).sup() : 0.0;
  return f.inf() > reach || f.sup() < -reach;
}

/// The window cull of a point-plane query of the scene (a static plane: origin and normal as
/// at t = 0). Needs upward rounding.
EXACTCCD_CERTIFIED bool disjoint_over_window(const PointPlaneQuery& q, double window,
                                             double delta) {
  return apart_from_plane(q.p_t0, q.p_t1, q.origin_t0, q.normal_t0, delta, window);
}

}  // namespace exactccd::scene
