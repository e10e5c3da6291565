// PROOF: proofs/min_separation.md#filters
#include "filters/separation_filter.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <optional>

#include "core/predicates/separation.hpp"
#include "filters/interval.hpp"
#include "filters/separation_directions.hpp"
#include "filters/separation_exact_signs.hpp"
#include "filters/separation_search.hpp"

namespace exactccd::filters {

namespace {

using predicates::Vec3;

/// hi1 + delta < lo2 or hi2 + delta < lo1 on some axis, the sums rounded upwards: a certain
/// gap wider than delta. PROOF: proofs/min_separation.md#culling-with-delta
template <std::size_t N1, std::size_t N2>
bool boxes_apart(const std::array<const Eigen::Vector3d*, N1>& first,
                 const std::array<const Eigen::Vector3d*, N2>& second, double delta) {
  const RoundingGuard upward;
  for (int k = 0; k < 3; ++k) {
    double lo1 = first[0]->coeff(k), hi1 = lo1, lo2 = second[0]->coeff(k), hi2 = lo2;
    for (const auto* v : first) {
      lo1 = std::min(lo1, v->coeff(k));
      hi1 = std::max(hi1, v->coeff(k));
    }
    for (const auto* v : second) {
      lo2 = std::min(lo2, v->coeff(k));
      hi2 = std::max(hi2, v->coeff(k));
    }
    if (hi1 + delta < lo2 || hi2 + delta < lo1) return true;
  }
  return false;
}

predicates::MovingPoint<Interval> moving(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  return predicates::linear_motion(Vec3<Interval>{x0.x(), x0.y(), x0.z()},
                                   Vec3<Interval>{x1.x(), x1.y(), x1.z()});
}

template <class Motion, class Separation>
SeparationOutcome first_within(const Motion& m, const Separation& s,
                               const separation::ExactAtDoubles& exact,
                               const CcdOptions& options) {
  return separation::FirstWithinSearch<Motion, Separation>(m, s, exact, options).run();
}

}  // namespace

bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta) {
  return boxes_apart<2, 6>({&q.p_t0, &q.p_t1},
                           {&q.a_t0, &q.b_t0, &q.c_t0, &q.a_t1, &q.b_t1, &q.c_t1}, delta);
}

bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta) {
  return boxes_apart<4, 4>({&q.ea0_t0, &q.ea1_t0, &q.ea0_t1, &q.ea1_t1},
                           {&q.eb0_t0, &q.eb1_t0, &q.eb0_t1, &q.eb1_t1}, delta);
}

SeparationOutcome vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options) {
  using separation::MovingVertex;
  const RoundingGuard upward;
  const separation::VertexFaceMotion m{
      {MovingVertex(q.p_t0, q.p_t1), MovingVertex(q.a_t0, q.a_t1), MovingVertex(q.b_t0, q.b_t1),
       MovingVertex(q.c_t0, q.c_t1)}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto s = predicates::vertex_face_separation(moving(q.p_t0, q.p_t1),
                                                    moving(q.a_t0, q.a_t1),
                                                    moving(q.b_t0, q.b_t1),
                                                    moving(q.c_t0, q.c_t1), delta2);
  std::optional<separation::ExactSignsAtDoubles> integer;  // built on first use
  auto exact_signs = [&]() -> const separation::ExactSignsAtDoubles& {
    if (!integer)
      integer.emplace(std::array<const Eigen::Vector3d*, 4>{&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0},
                      std::array<const Eigen::Vector3d*, 4>{&q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1},
                      options.min_separation);
    return *integer;
  };
  const separation::ExactAtDoubles exact{
      [&](int k, double t) { return exact_signs().vertex_face_sign(k, t); },
      [&](int k, double lo, double hi) { return exact_signs().vertex_face_secant(k, lo, hi); }};
  return first_within(m, s, exact, options);
}

SeparationOutcome edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options) {
  using separation::MovingVertex;
  const RoundingGuard upward;
  const separation::EdgeEdgeMotion m{
      {MovingVertex(q.ea0_t0, q.ea0_t1), MovingVertex(q.ea1_t0, q.ea1_t1),
       MovingVertex(q.eb0_t0, q.eb0_t1), MovingVertex(q.eb1_t0, q.eb1_t1)}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto s = predicates::edge_edge_separation(moving(q.ea0_t0, q.ea0_t1),
                                                  moving(q.ea1_t0, q.ea1_t1),
                                                  moving(q.eb0_t0, q.eb0_t1),
                                                  moving(q.eb1_t0, q.eb1_t1), delta2);
  std::optional<separation::ExactSignsAtDoubles> integer;  // built on first use
  auto exact_signs = [&]() -> const separation::ExactSignsAtDoubles& {
    if (!integer)
      integer.emplace(
          std::array<const Eigen::Vector3d*, 4>{&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0},
          std::array<const Eigen::Vector3d*, 4>{&q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1},
          options.min_separation);
    return *integer;
  };
  const separation::ExactAtDoubles exact{
      [&](int k, double t) { return exact_signs().edge_edge_sign(k, t); },
      [&](int k, double lo, double hi) { return exact_signs().edge_edge_secant(k, lo, hi); }};
  return first_within(m, s, exact, options);
}

}  // namespace exactccd::filters
