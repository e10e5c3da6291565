// Culling over a shortened time window [0, T], T <= 1 (used by Scene::earliest_contact).
//
// Over [0, T] a vertex moving from x0 to x1 stays on the segment from x0 to x(T) = x0 +
// T (x1 - x0), so in the box of those two points. x(T) is not a double in general: it is
// enclosed by interval arithmetic with directed rounding, and the box is widened to the
// enclosure, so a pair reported disjoint is disjoint at every t in [0, T]. With a minimum
// separation delta the boxes must be more than delta apart on one axis (hi + delta < lo, the sum
// rounded upwards), so the pair never comes within delta over [0, T]. The caller holds
// rounding towards +infinity (predicates::RoundingGuard), which Interval_nt<false> needs: one guard
// for a whole batch of pairs, not a mode switch per pair.
// PROOF: proofs/scene.md#time-window, proofs/scene.md#min-separation
#pragma once

#include <Eigen/Core>
#include <algorithm>

#include "exactccd/types.hpp"
#include "core/predicates/interval.hpp"

namespace exactccd::scene {

namespace detail {

/// Box of the vertices over [0, T] on axis k: [lo, hi], certified to contain every position.
template <std::size_t N>
EXACTCCD_CERTIFIED
void window_extent(const Eigen::Vector3d* const (&start)[N], const Eigen::Vector3d* const (&end)[N],
                   const predicates::Interval& t, int k, double& lo, double& hi) {
  lo = start[0]->coeff(k);
  hi = lo;
  for (std::size_t i = 0; i < N; ++i) {
    const double x0 = start[i]->coeff(k);
    const predicates::Interval at_t =
        predicates::Interval(x0) +
        t * (predicates::Interval(end[i]->coeff(k)) - predicates::Interval(x0));
    lo = std::min({lo, x0, at_t.inf()});
    hi = std::max({hi, x0, at_t.sup()});
  }
}

template <std::size_t NA, std::size_t NB>
EXACTCCD_CERTIFIED
bool disjoint(const Eigen::Vector3d* const (&a0)[NA], const Eigen::Vector3d* const (&a1)[NA],
              const Eigen::Vector3d* const (&b0)[NB], const Eigen::Vector3d* const (&b1)[NB],
              double window, double delta) {
  const predicates::Interval t(window);
  for (int k = 0; k < 3; ++k) {
    double lo_a, hi_a, lo_b, hi_b;
    window_extent(a0, a1, t, k, lo_a, hi_a);
    window_extent(b0, b1, t, k, lo_b, hi_b);
    if (hi_a + delta < lo_b || hi_b + delta < lo_a) return true;
  }
  return false;
}

}  // namespace detail

/// True when the vertex and the triangle cannot come within delta >= 0 (0: meet) at any t in
/// [0, window]. Needs upward rounding (see above).
EXACTCCD_CERTIFIED bool disjoint_over_window(const VertexFaceQuery& q, double window,
                                             double delta) {
  const Eigen::Vector3d* const a0[] = {&q.p_t0};
  const Eigen::Vector3d* const a1[] = {&q.p_t1};
  const Eigen::Vector3d* const b0[] = {&q.a_t0, &q.b_t0, &q.c_t0};
  const Eigen::Vector3d* const b1[] = {&q.a_t1, &q.b_t1, &q.c_t1};
  return detail::disjoint(a0, a1, b0, b1, window, delta);
}

/// True when the two edges cannot come within delta >= 0 (0: meet) at any t in [0, window].
/// Needs upward rounding.
EXACTCCD_CERTIFIED bool disjoint_over_window(const EdgeEdgeQuery& q, double window,
                                             double delta) {
  const Eigen::Vector3d* const a0[] = {&q.ea0_t0, &q.ea1_t0};
  const Eigen::Vector3d* const a1[] = {&q.ea0_t1, &q.ea1_t1};
  const Eigen::Vector3d* const b0[] = {&q.eb0_t0, &q.eb1_t0};
  const Eigen::Vector3d* const b1[] = {&q.eb0_t1, &q.eb1_t1};
  return detail::disjoint(a0, a1, b0, b1, window, delta);
}

}  // namespace exactccd::scene
