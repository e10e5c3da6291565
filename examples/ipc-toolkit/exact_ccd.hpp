/// \file
/// ExactCCD: ipc-toolkit's narrow-phase CCD interface (ipc::NarrowPhaseCCD) implemented with
/// exactccd's certified collision-free step (exactccd/step.hpp).
///
/// Each method answers as ipc-toolkit's TightInclusionCCD does:
///   - returns true iff the pair comes within an effective separation of min_distance during
///     [0, tmax] (or already is within min_distance at t = 0: then toi = 0);
///   - toi is the step the pair may safely take: the whole of [0, toi] keeps the distance above
///     min_distance, and above the effective separation
///     min_distance + min((1 - conservative_rescaling) * (d0 - min_distance), max_margin), d0
///     the distance at t = 0, so the next step, started at toi, is not at contact at once;
///   - when it returns false, toi = tmax (TightInclusionCCD's value; ipc-toolkit ignores it).
/// With the default max_margin = 1e-4 the effective separation is TightInclusionCCD's, so
/// ExactCCD is a drop-in for it; unlike TightInclusionCCD, the answer is certified (no
/// tolerance, no iteration limit, no false negatives, and no fallback for steps below 1e-6).
#pragma once

#include <ipc/ccd/narrow_phase_ccd.hpp>

namespace exactccd_ipc {

/// ipc-toolkit's narrow phase with exactccd underneath. Pass an instance wherever ipc-toolkit
/// takes a `const ipc::NarrowPhaseCCD&` (compute_collision_free_stepsize,
/// is_step_collision_free, Candidates, ...).
class ExactCCD : public ipc::NarrowPhaseCCD {
public:
    /// ipc-toolkit's default conservative rescaling (TightInclusionCCD's).
    static constexpr double DEFAULT_CONSERVATIVE_RESCALING = 0.8;
    /// TightInclusionCCD's cap on the margin (tight_inclusion_ccd.cpp, ccd_strategy).
    static constexpr double DEFAULT_MAX_MARGIN = 1e-4;

    /// \param conservative_rescaling s in (0, 1]: the step keeps the fraction 1 - s of the
    ///        initial gap d0 - min_distance as a margin (stored in the public member
    ///        `conservative_rescaling` of ipc::NarrowPhaseCCD, which may be changed later).
    /// \param max_margin the largest margin kept, an absolute distance >= 0 (the public member
    ///        `max_margin`).
    explicit ExactCCD(
        double conservative_rescaling = DEFAULT_CONSERVATIVE_RESCALING,
        double max_margin = DEFAULT_MAX_MARGIN);

    /// The cap on the margin: the effective separation is
    /// min_distance + min((1 - s)(d0 - min_distance), max_margin). 1e-4 (the default) is
    /// TightInclusionCCD's cap; +infinity gives the rule of ipc-toolkit's interface
    /// (narrow_phase_ccd.hpp) without the cap, i.e. shorter steps when the initial gap is
    /// large. Negative or NaN values make every method throw std::invalid_argument.
    double max_margin = DEFAULT_MAX_MARGIN;

    /// Points p0 and p1, in 2D or 3D (all four vectors the same size).
    bool point_point_ccd(
        Eigen::ConstRef<ipc::VectorMax3d> p0_t0,
        Eigen::ConstRef<ipc::VectorMax3d> p1_t0,
        Eigen::ConstRef<ipc::VectorMax3d> p0_t1,
        Eigen::ConstRef<ipc::VectorMax3d> p1_t1,
        double& toi,
        const double min_distance = 0.0,
        const double tmax = 1.0) const override;

    /// Point p against the closed edge [e0, e1], in 2D or 3D (all six vectors the same size).
    bool point_edge_ccd(
        Eigen::ConstRef<ipc::VectorMax3d> p_t0,
        Eigen::ConstRef<ipc::VectorMax3d> e0_t0,
        Eigen::ConstRef<ipc::VectorMax3d> e1_t0,
        Eigen::ConstRef<ipc::VectorMax3d> p_t1,
        Eigen::ConstRef<ipc::VectorMax3d> e0_t1,
        Eigen::ConstRef<ipc::VectorMax3d> e1_t1,
        double& toi,
        const double min_distance = 0.0,
        const double tmax = 1.0) const override;

    /// Point p against the closed triangle (t0, t1, t2).
    bool point_triangle_ccd(
        Eigen::ConstRef<Eigen::Vector3d> p_t0,
        Eigen::ConstRef<Eigen::Vector3d> t0_t0,
        Eigen::ConstRef<Eigen::Vector3d> t1_t0,
        Eigen::ConstRef<Eigen::Vector3d> t2_t0,
        Eigen::ConstRef<Eigen::Vector3d> p_t1,
        Eigen::ConstRef<Eigen::Vector3d> t0_t1,
        Eigen::ConstRef<Eigen::Vector3d> t1_t1,
        Eigen::ConstRef<Eigen::Vector3d> t2_t1,
        double& toi,
        const double min_distance = 0.0,
        const double tmax = 1.0) const override;

    /// The closed edges [ea0, ea1] and [eb0, eb1].
    bool edge_edge_ccd(
        Eigen::ConstRef<Eigen::Vector3d> ea0_t0,
        Eigen::ConstRef<Eigen::Vector3d> ea1_t0,
        Eigen::ConstRef<Eigen::Vector3d> eb0_t0,
        Eigen::ConstRef<Eigen::Vector3d> eb1_t0,
        Eigen::ConstRef<Eigen::Vector3d> ea0_t1,
        Eigen::ConstRef<Eigen::Vector3d> ea1_t1,
        Eigen::ConstRef<Eigen::Vector3d> eb0_t1,
        Eigen::ConstRef<Eigen::Vector3d> eb1_t1,
        double& toi,
        const double min_distance = 0.0,
        const double tmax = 1.0) const override;
};

} // namespace exactccd_ipc
