// PROOF: proofs/filters.md (culling, interval enclosures, the cubic filter, inclusion over a
// time interval).
#include "filters/ccd_filters.hpp"

#include "core/predicates/coplanarity_cubic.hpp"
#include "filters/coplanarity_semistatic.hpp"
#include "filters/swept_box_culling.hpp"

namespace exactccd::filters {

namespace {

using predicates::FixedPoly;
using predicates::MovingPoint;
using Quadratic = FixedPoly<Interval, 2>;

MovingPoint<Interval> moving(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  return predicates::linear_motion(predicates::Vec3<Interval>{x0.x(), x0.y(), x0.z()},
                                   predicates::Vec3<Interval>{x1.x(), x1.y(), x1.z()});
}

Interval at(const Quadratic& q, const Interval& T) { return predicates::evaluate(q, T); }

/// Inclusion of p in the triangle over a time interval, in the projections along each axis.
/// PROOF: proofs/filters.md#inclusion-over-an-interval
struct VertexFaceInclusion {
  Quadratic normal[3];       // n_k = orient2d_k(a, b, c)
  Quadratic edge_side[3][3]; // orient2d_k(a, b, p), orient2d_k(b, c, p), orient2d_k(c, a, p)

  VertexFaceInclusion(const MovingPoint<Interval>& p, const MovingPoint<Interval>& a,
                      const MovingPoint<Interval>& b, const MovingPoint<Interval>& c) {
    for (int k = 0; k < 3; ++k) {
      normal[k] = predicates::orient2d_along_axis(k, a, b, c);
      edge_side[k][0] = predicates::orient2d_along_axis(k, a, b, p);
      edge_side[k][1] = predicates::orient2d_along_axis(k, b, c, p);
      edge_side[k][2] = predicates::orient2d_along_axis(k, c, a, p);
    }
  }
  // Some projection where the triangle keeps orientation s and p is strictly outside an edge.
  bool excluded(const Interval& T) const {
    for (int k = 0; k < 3; ++k) {
      const int s = certain_strict_sign(at(normal[k], T));
      if (s == 0) continue;
      for (const auto& e : edge_side[k])
        if (certainly_has_sign(at(e, T), -s)) return true;
    }
    return false;
  }
  // Some projection where p is strictly inside: then contact at every coplanar instant.
  bool certainly_included(const Interval& T) const {
    for (int k = 0; k < 3; ++k) {
      const int s = certain_strict_sign(at(normal[k], T));
      if (s == 0) continue;
      if (certainly_has_sign(at(edge_side[k][0], T), s) &&
          certainly_has_sign(at(edge_side[k][1], T), s) &&
          certainly_has_sign(at(edge_side[k][2], T), s))
        return true;
    }
    return false;
  }
};

/// Crossing of the two segments over a time interval, in the projections along each axis.
/// PROOF: proofs/filters.md#inclusion-over-an-interval
struct EdgeEdgeInclusion {
  Quadratic side[3][4];  // orient2d_k(a0,a1,b0), (a0,a1,b1), (b0,b1,a0), (b0,b1,a1)

  EdgeEdgeInclusion(const MovingPoint<Interval>& a0, const MovingPoint<Interval>& a1,
                    const MovingPoint<Interval>& b0, const MovingPoint<Interval>& b1) {
    for (int k = 0; k < 3; ++k) {
      side[k][0] = predicates::orient2d_along_axis(k, a0, a1, b0);
      side[k][1] = predicates::orient2d_along_axis(k, a0, a1, b1);
      side[k][2] = predicates::orient2d_along_axis(k, b0, b1, a0);
      side[k][3] = predicates::orient2d_along_axis(k, b0, b1, a1);
    }
  }
  // Some projection where one segment lies strictly on one side of the other's line.
  bool excluded(const Interval& T) const {
    for (int k = 0; k < 3; ++k) {
      for (int pair = 0; pair < 4; pair += 2) {
        const int s = certain_strict_sign(at(side[k][pair], T));
        if (s != 0 && certainly_has_sign(at(side[k][pair + 1], T), s)) return true;
      }
    }
    return false;
  }
  // Some projection where the segments cross properly: then contact at every coplanar instant.
  bool certainly_included(const Interval& T) const {
    for (int k = 0; k < 3; ++k) {
      const int s0 = certain_strict_sign(at(side[k][0], T));
      if (s0 == 0 || !certainly_has_sign(at(side[k][1], T), -s0)) continue;
      const int s2 = certain_strict_sign(at(side[k][2], T));
      if (s2 != 0 && certainly_has_sign(at(side[k][3], T), -s2)) return true;
    }
    return false;
  }
};

}  // namespace

bool vertex_face_culled(const VertexFaceQuery& q) {
  return swept_boxes_disjoint({&q.p_t0, &q.p_t1},
                              {&q.a_t0, &q.b_t0, &q.c_t0, &q.a_t1, &q.b_t1, &q.c_t1});
}

bool edge_edge_culled(const EdgeEdgeQuery& q) {
  return swept_boxes_disjoint({&q.ea0_t0, &q.ea1_t0, &q.ea0_t1, &q.ea1_t1},
                              {&q.eb0_t0, &q.eb1_t0, &q.eb0_t1, &q.eb1_t1});
}

namespace {
FilterOutcome no_contact() {
  FilterOutcome none;
  none.verdict = FilterOutcome::Verdict::no_contact;
  return none;
}
}  // namespace

FilterOutcome vertex_face_filter(const VertexFaceQuery& q, const CcdOptions& options,
                                 ExactAtDoubles& exact) {
  // Semi-static stage (round to nearest, no guard needed): root-free on [0, 1] implies
  // root-free on [0, t_max] for every t_max <= 1.
  if (coplanarity_cubic_root_free_semistatic(q.b_t0 - q.a_t0, q.b_t1 - q.a_t1, q.c_t0 - q.a_t0,
                                             q.c_t1 - q.a_t1, q.p_t0 - q.a_t0, q.p_t1 - q.a_t1))
    return no_contact();
  RoundingGuard guard;
  const auto p = moving(q.p_t0, q.p_t1), a = moving(q.a_t0, q.a_t1), b = moving(q.b_t0, q.b_t1),
             c = moving(q.c_t0, q.c_t1);
  const auto cubic = predicates::vertex_face_coplanarity_cubic(p, a, b, c);
  if (cubic_certainly_root_free(cubic, options.t_max)) return no_contact();
  return cubic_filter(cubic, options.t_max, options.toi_width, VertexFaceInclusion(p, a, b, c),
                      exact);
}

FilterOutcome edge_edge_filter(const EdgeEdgeQuery& q, const CcdOptions& options,
                               ExactAtDoubles& exact) {
  if (coplanarity_cubic_root_free_semistatic(q.ea1_t0 - q.ea0_t0, q.ea1_t1 - q.ea0_t1,
                                             q.eb0_t0 - q.ea0_t0, q.eb0_t1 - q.ea0_t1,
                                             q.eb1_t0 - q.ea0_t0, q.eb1_t1 - q.ea0_t1))
    return no_contact();
  RoundingGuard guard;
  const auto a0 = moving(q.ea0_t0, q.ea0_t1), a1 = moving(q.ea1_t0, q.ea1_t1),
             b0 = moving(q.eb0_t0, q.eb0_t1), b1 = moving(q.eb1_t0, q.eb1_t1);
  const auto cubic = predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1);
  if (cubic_certainly_root_free(cubic, options.t_max)) return no_contact();
  return cubic_filter(cubic, options.t_max, options.toi_width, EdgeEdgeInclusion(a0, a1, b0, b1),
                      exact);
}

}  // namespace exactccd::filters
