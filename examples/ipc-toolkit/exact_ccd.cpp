#include "exact_ccd.hpp"

#include <exactccd/step.hpp>

#include <algorithm>
#include <stdexcept>

namespace exactccd_ipc {

namespace {

// ipc-toolkit's arguments, as exactccd's options. tmax is clamped into [0, 1] (ipc-toolkit
// asserts it is there; its callers pass the running earliest step, which is). An s outside
// (0, 1] or a negative max_margin is an error of the caller: exactccd throws
// std::invalid_argument for it.
exactccd::StepOptions
step_options(double min_distance, double tmax, double s, double max_margin)
{
    exactccd::StepOptions options;
    options.t_max = std::clamp(tmax, 0.0, 1.0);
    options.min_separation = min_distance;
    options.conservative_rescaling = s;
    options.max_margin = max_margin;
    return options;
}

// ipc-toolkit's convention for the answer: true iff the step is limited (toi = 0 when the
// pair starts within min_distance); toi = tmax otherwise.
bool answer(const exactccd::StepResult& result, double& toi)
{
    toi = result.step;
    return result.limited;
}

Eigen::Vector2d v2(Eigen::ConstRef<ipc::VectorMax3d> v) { return v.head<2>(); }
Eigen::Vector3d v3(Eigen::ConstRef<ipc::VectorMax3d> v) { return v.head<3>(); }

} // namespace

ExactCCD::ExactCCD(const double s, const double max_margin_) : max_margin(max_margin_)
{
    conservative_rescaling = s;
}

bool ExactCCD::point_point_ccd(
    Eigen::ConstRef<ipc::VectorMax3d> p0_t0,
    Eigen::ConstRef<ipc::VectorMax3d> p1_t0,
    Eigen::ConstRef<ipc::VectorMax3d> p0_t1,
    Eigen::ConstRef<ipc::VectorMax3d> p1_t1,
    double& toi,
    const double min_distance,
    const double tmax) const
{
    const auto options = step_options(min_distance, tmax, conservative_rescaling, max_margin);
    const auto dim = p0_t0.size();
    if (p1_t0.size() != dim || p0_t1.size() != dim || p1_t1.size() != dim
        || (dim != 2 && dim != 3)) {
        throw std::invalid_argument("ExactCCD::point_point_ccd: points of 2 or 3 coordinates, "
                                    "all the same");
    }
    if (dim == 2) {
        const exactccd::PointPointQuery2d q { v2(p0_t0), v2(p1_t0), v2(p0_t1), v2(p1_t1) };
        return answer(exactccd::collision_free_step(q, options), toi);
    }
    const exactccd::PointPointQuery q { v3(p0_t0), v3(p1_t0), v3(p0_t1), v3(p1_t1) };
    return answer(exactccd::collision_free_step(q, options), toi);
}

bool ExactCCD::point_edge_ccd(
    Eigen::ConstRef<ipc::VectorMax3d> p_t0,
    Eigen::ConstRef<ipc::VectorMax3d> e0_t0,
    Eigen::ConstRef<ipc::VectorMax3d> e1_t0,
    Eigen::ConstRef<ipc::VectorMax3d> p_t1,
    Eigen::ConstRef<ipc::VectorMax3d> e0_t1,
    Eigen::ConstRef<ipc::VectorMax3d> e1_t1,
    double& toi,
    const double min_distance,
    const double tmax) const
{
    const auto options = step_options(min_distance, tmax, conservative_rescaling, max_margin);
    const auto dim = p_t0.size();
    if (e0_t0.size() != dim || e1_t0.size() != dim || p_t1.size() != dim
        || e0_t1.size() != dim || e1_t1.size() != dim || (dim != 2 && dim != 3)) {
        throw std::invalid_argument("ExactCCD::point_edge_ccd: points of 2 or 3 coordinates, "
                                    "all the same");
    }
    if (dim == 2) {
        const exactccd::PointEdgeQuery2d q { v2(p_t0),  v2(e0_t0), v2(e1_t0),
                                             v2(p_t1),  v2(e0_t1), v2(e1_t1) };
        return answer(exactccd::collision_free_step(q, options), toi);
    }
    const exactccd::PointEdgeQuery q { v3(p_t0), v3(e0_t0), v3(e1_t0),
                                       v3(p_t1), v3(e0_t1), v3(e1_t1) };
    return answer(exactccd::collision_free_step(q, options), toi);
}

bool ExactCCD::point_triangle_ccd(
    Eigen::ConstRef<Eigen::Vector3d> p_t0,
    Eigen::ConstRef<Eigen::Vector3d> t0_t0,
    Eigen::ConstRef<Eigen::Vector3d> t1_t0,
    Eigen::ConstRef<Eigen::Vector3d> t2_t0,
    Eigen::ConstRef<Eigen::Vector3d> p_t1,
    Eigen::ConstRef<Eigen::Vector3d> t0_t1,
    Eigen::ConstRef<Eigen::Vector3d> t1_t1,
    Eigen::ConstRef<Eigen::Vector3d> t2_t1,
    double& toi,
    const double min_distance,
    const double tmax) const
{
    const exactccd::VertexFaceQuery q { p_t0, t0_t0, t1_t0, t2_t0, p_t1, t0_t1, t1_t1, t2_t1 };
    return answer(
        exactccd::collision_free_step(
            q, step_options(min_distance, tmax, conservative_rescaling, max_margin)),
        toi);
}

bool ExactCCD::edge_edge_ccd(
    Eigen::ConstRef<Eigen::Vector3d> ea0_t0,
    Eigen::ConstRef<Eigen::Vector3d> ea1_t0,
    Eigen::ConstRef<Eigen::Vector3d> eb0_t0,
    Eigen::ConstRef<Eigen::Vector3d> eb1_t0,
    Eigen::ConstRef<Eigen::Vector3d> ea0_t1,
    Eigen::ConstRef<Eigen::Vector3d> ea1_t1,
    Eigen::ConstRef<Eigen::Vector3d> eb0_t1,
    Eigen::ConstRef<Eigen::Vector3d> eb1_t1,
    double& toi,
    const double min_distance,
    const double tmax) const
{
    const exactccd::EdgeEdgeQuery q { ea0_t0, ea1_t0, eb0_t0, eb1_t0,
                                      ea0_t1, ea1_t1, eb0_t1, eb1_t1 };
    return answer(
        exactccd::collision_free_step(
            q, step_options(min_distance, tmax, conservative_rescaling, max_margin)),
        toi);
}

} // namespace exactccd_ipc
