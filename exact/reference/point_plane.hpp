// The exact decision procedure of point-plane CCD: a point p moving linearly against the plane
// through o with normal n, both moving linearly too (a static plane repeats them). Contact at t
// iff f(t) = (p(t) - o(t)) . n(t) = 0, a polynomial of degree <= 2 (<= 1 for a static plane);
// within delta iff f(t)^2 <= delta^2 |n(t)|^2, degree <= 4.
// PROOF: proofs/point_plane.md#reduction
#pragma once

#include <Eigen/Core>
#include <array>
#include <gmpxx.h>

#include "exactccd/types.hpp"

namespace exactccd::exact {

/// Rows p_t0, origin_t0, normal_t0, p_t1, origin_t1, normal_t1, finite doubles.
using PointPlanePoints = std::array<Eigen::Vector3d, 6>;

/// The exact answer over [0, options.t_max] (options.min_separation: delta; the tightest TOI
/// pair, or options.toi_width), every decision in rational arithmetic.
CcdResult point_plane_ccd_exact(const PointPlanePoints& x, const CcdOptions& options);

/// Whether the first contact (first time within min_separation) t* lies strictly before the
/// rational time t (t in [0, 1]), exactly: the grading of a reported time of impact.
bool point_plane_contact_before(const PointPlanePoints& x, const mpq_class& t,
                                double min_separation);

}  // namespace exactccd::exact
