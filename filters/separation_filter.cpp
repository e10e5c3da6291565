// PROOF: proofs/min_separation.md#filters
#include "filters/separation_filter.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <type_traits>

#include "core/predicates/query_points.hpp"
#include "core/predicates/separation.hpp"
#include "filters/certified_numbers.hpp"
#include "filters/separation_directions.hpp"
#include "filters/separation_search.hpp"

namespace exactccd::filters {

namespace {

using predicates::moving_point;
using predicates::Vec3;

/// The extent [lo, hi] of some points on axis k.
struct Extent {
  double lo, hi;
};
template <std::size_t N>
Extent extent(const std::array<const Eigen::Vector3d*, N>& points, int k) {
  Extent e{points[0]->coeff(k), points[0]->coeff(k)};
  for (const auto* v : points) {
    e.lo = std::min(e.lo, v->coeff(k));
    e.hi = std::max(e.hi, v->coeff(k));
  }
  return e;
}

/// On some axis, the two primitives' boxes more than delta apart on the same side at t = 0 and
/// at t = 1 (first0/second0 the vertices at t = 0, first1/second1 at t = 1): the gap along a
/// fixed axis is concave in t, so it exceeds delta over the whole step. Each difference is
/// rounded in any mode: rounding is monotone and delta is a double, so a rounded difference
/// above delta means an exact one above it; no rounding mode to set. This is stronger than the
/// boxes of the whole sweeps apart (a primitive that passes over the other's box during the
/// step without meeting it). PROOF: proofs/min_separation.md#culling-with-delta
template <std::size_t N1, std::size_t N2>
bool boxes_apart(const std::array<const Eigen::Vector3d*, N1>& first0,
                 const std::array<const Eigen::Vector3d*, N2>& second0,
                 const std::array<const Eigen::Vector3d*, N1>& first1,
                 const std::array<const Eigen::Vector3d*, N2>& second1, double delta) {
  for (int k = 0; k < 3; ++k) {
    const Extent a0 = extent(first0, k), b0 = extent(second0, k);
    const Extent a1 = extent(first1, k), b1 = extent(second1, k);
    if ((b0.lo - a0.hi > delta && b1.lo - a1.hi > delta) ||
        (a0.lo - b0.hi > delta && a1.lo - b1.hi > delta))
      return true;
  }
  return false;
}

using Vertices = std::array<const Eigen::Vector3d*, 4>;

/// An enclosure of region polynomial k at the double t from the vertices' interval
/// positions at t: the polynomial's factored form (differences, cross and dot products of
/// positions), whose enclosure is as wide as the positions' (a few ulps) where the expanded
/// coefficients' is as wide as their largest terms'. PROOF: proofs/min_separation.md#factored-form
template <class Motion, class Make>
struct FactoredEnclosures {
  const Motion& m;
  const Make& make;
  const Interval& delta2;

  Interval operator()(int k, double t) const {
    Interval v(0);
    visit(Interval(t), [&v](const auto& g) { v = g.c[0]; }, k);
    return v;
  }

  /// Every polynomial over the time interval ti (the inclusion property of interval
  /// arithmetic: the positions enclosed over it), in one pass.
  void all_over(const Interval& ti, separation::CoefficientValues* out) const {
    int k = 0;
    visit(ti, [&](const auto& g) { (*out)[k++] = g.c[0]; }, -1);
  }

 private:
  template <class F>
  void visit(const Interval& ti, F&& f, int only) const {
    auto at = [&](int i) {
      const std::array<Interval, 3> x = m.v[i].at(ti);
      using Constant = predicates::FixedPoly<Interval, 0>;
      return Vec3<Constant>{Constant{{x[0]}}, Constant{{x[1]}}, Constant{{x[2]}}};
    };
    make(at(0), at(1), at(2), at(3), delta2).for_each_polynomial(f, only);
  }
};

/// The search over [0, t_max] for the four moving vertices (t0, t1) of one query type: `make`
/// builds its separation. Not inlined: its frame (the polynomial table) is large, and most
/// queries never get here.
template <class Motion, class Make>
[[gnu::noinline]] FilterOutcome search_for_first_within(
    const Vertices& t0, const Vertices& t1, const CcdOptions& options, Make make,
    const predicates::SeparationExactStage& exact) {
  using separation::MovingVertex;
  const RoundingGuard upward;
  const Motion m{{MovingVertex(*t0[0], *t1[0]), MovingVertex(*t0[1], *t1[1]),
                  MovingVertex(*t0[2], *t1[2]), MovingVertex(*t0[3], *t1[3])}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto s =
      make(moving_point<Interval>(*t0[0], *t1[0]), moving_point<Interval>(*t0[1], *t1[1]),
           moving_point<Interval>(*t0[2], *t1[2]), moving_point<Interval>(*t0[3], *t1[3]), delta2);
  const FactoredEnclosures<Motion, Make> factored{m, make, delta2};
  FilterOutcome out =
      separation::FirstWithinSearch<Motion, std::decay_t<decltype(s)>, decltype(factored)>(
          m, s, factored, exact, options)
          .run();
  // The stage: exact_at_double when a sign, guess or table needed exact integers.
  if (exact.used_exact_arithmetic()) out.exact_used = true;
  return out;
}

/// The whole-step test, then the search.
template <class Motion, class WholeStep, class Make>
FilterOutcome separation_filter(const Vertices& t0, const Vertices& t1,
                                    const CcdOptions& options, WholeStep apart_over_whole_step,
                                    Make make, const predicates::SeparationExactStage& exact) {
  // Most pairs that pass culling are decided here, from the input doubles alone, rounding to
  // nearest as the library's entry has set.
  if (apart_over_whole_step(t0, t1, options.min_separation)) {
    FilterOutcome out;
    out.verdict = FilterOutcome::Verdict::no_contact;
    out.cleared_until = options.t_max;
    return out;
  }
  return search_for_first_within<Motion>(t0, t1, options, make, exact);
}

}  // namespace

bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta) {
  return boxes_apart<1, 3>({&q.p_t0}, {&q.a_t0, &q.b_t0, &q.c_t0}, {&q.p_t1},
                           {&q.a_t1, &q.b_t1, &q.c_t1}, delta);
}

bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta) {
  return boxes_apart<2, 2>({&q.ea0_t0, &q.ea1_t0}, {&q.eb0_t0, &q.eb1_t0},
                           {&q.ea0_t1, &q.ea1_t1}, {&q.eb0_t1, &q.eb1_t1}, delta);
}

FilterOutcome vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options,
                                                const predicates::SeparationExactStage& exact) {
  return separation_filter<separation::VertexFaceMotion>(
      predicates::points_at(q, false), predicates::points_at(q, true), options,
      separation::vertex_face_apart_over_whole_step,
      [](const auto&... x) { return predicates::vertex_face_separation(x...); },
      exact);
}

FilterOutcome edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options,
                                              const predicates::SeparationExactStage& exact) {
  return separation_filter<separation::EdgeEdgeMotion>(
      predicates::points_at(q, false), predicates::points_at(q, true), options, separation::edge_edge_apart_over_whole_step,
      [](const auto&... x) { return predicates::edge_edge_separation(x...); },
      exact);
}

}  // namespace exactccd::filters
