// PROOF: proofs/filters.md (culling, interval enclosures, the cubic filter, inclusion over a
// time interval).
#include "filters/ccd_filters.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <utility>

#include "core/predicates/coplanarity_cubic.hpp"
#include "filters/coplanarity_semistatic.hpp"
#include "filters/swept_box_culling.hpp"

namespace exactccd::filters {

namespace {

using predicates::moving_point;
using predicates::FixedPoly;
using predicates::MovingPoint;
using Quadratic = FixedPoly<Interval, 2>;

Interval at(const Quadratic& q, const Interval& T) { return predicates::evaluate(q, T); }

/// The axes by decreasing |n_k|, n a normal of the plane the primitives nearly share at
/// mid-step (plain doubles): the projections the inclusion tests try first, the best
/// conditioned ones. Only an order, whatever its rounding: each projection's test is certified
/// on its own.
struct AxisOrder {
  int axis[3] = {0, 1, 2};
  explicit AxisOrder(const Eigen::Vector3d& n) {
    const double m[3] = {std::fabs(n.x()), std::fabs(n.y()), std::fabs(n.z())};
    if (m[axis[1]] > m[axis[0]]) std::swap(axis[0], axis[1]);  // NaN: no swap
    if (m[axis[2]] > m[axis[1]]) std::swap(axis[1], axis[2]);
    if (m[axis[1]] > m[axis[0]]) std::swap(axis[0], axis[1]);
  }
};

/// The last time interval on which the leading projection was found not to exclude (the
/// whole step is tried before the cubic is formed, then again as the root node): the repeat
/// starts at the next projection.
struct LeadingProjectionMemo {
  double inf = 1, sup = 0;  // none yet
  int skip(const Interval& T) const { return T.inf() == inf && T.sup() == sup ? 1 : 0; }
  void failed_on(const Interval& T) { inf = T.inf(), sup = T.sup(); }
};

/// Inclusion of p in the triangle over a time interval, in the projections along each axis.
/// The orientation quadratics are formed when first needed (most queries are decided by the
/// first axis or two), then kept.
/// PROOF: proofs/filters.md#inclusion-over-an-interval
class VertexFaceInclusion {
 public:
  VertexFaceInclusion(const MovingPoint<Interval>& p, const MovingPoint<Interval>& a,
                      const MovingPoint<Interval>& b, const MovingPoint<Interval>& c,
                      const AxisOrder& order)
      : p_(p), a_(a), b_(b), c_(c), order_(order) {}

  // Some projection where the triangle keeps orientation s and p is strictly outside an edge.
  bool excluded(const Interval& T) const { return excluded_in(T, 3); }
  bool excluded_in_leading_projection(const Interval& T) const { return excluded_in(T, 1); }
  // Some projection where p is strictly inside: then contact at every coplanar instant.
  bool certainly_included(const Interval& T) const {
    for (const int k : order_.axis) {
      const int s = certain_strict_sign(at(normal(k), T));
      if (s == 0) continue;
      if (certainly_has_sign(at(edge_side(k, 0), T), s) &&
          certainly_has_sign(at(edge_side(k, 1), T), s) &&
          certainly_has_sign(at(edge_side(k, 2), T), s))
        return true;
    }
    return false;
  }

 private:
  bool excluded_in(const Interval& T, int projections) const {
    for (int i = leading_.skip(T); i < projections; ++i) {
      const int k = order_.axis[i];
      const int s = certain_strict_sign(at(normal(k), T));
      if (s == 0) continue;
      for (int e = 0; e < 3; ++e)
        if (certainly_has_sign(at(edge_side(k, e), T), -s)) return true;
    }
    leading_.failed_on(T);  // projections >= 1: the leading one did not exclude
    return false;
  }
  // n_k = orient2d_k(a, b, c)
  const Quadratic& normal(int k) const {
    if (!(ready_ & (1u << k))) {
      normal_[k] = predicates::orient2d_along_axis(k, a_, b_, c_);
      ready_ |= 1u << k;
    }
    return normal_[k];
  }
  // orient2d_k(a, b, p), orient2d_k(b, c, p), orient2d_k(c, a, p) for e = 0, 1, 2
  const Quadratic& edge_side(int k, int e) const {
    const unsigned bit = 1u << (3 + 3 * k + e);
    if (!(ready_ & bit)) {
      const MovingPoint<Interval>* const ends[4] = {&a_, &b_, &c_, &a_};
      edge_side_[k][e] = predicates::orient2d_along_axis(k, *ends[e], *ends[e + 1], p_);
      ready_ |= bit;
    }
    return edge_side_[k][e];
  }

  const MovingPoint<Interval>&p_, &a_, &b_, &c_;
  const AxisOrder order_;
  mutable LeadingProjectionMemo leading_;
  mutable Quadratic normal_[3], edge_side_[3][3];
  mutable unsigned ready_ = 0;  // bit k: normal_[k]; bit 3 + 3k + e: edge_side_[k][e]
};

/// Crossing of the two segments over a time interval, in the projections along each axis.
/// The orientation quadratics are formed when first needed, then kept.
/// PROOF: proofs/filters.md#inclusion-over-an-interval
class EdgeEdgeInclusion {
 public:
  EdgeEdgeInclusion(const MovingPoint<Interval>& a0, const MovingPoint<Interval>& a1,
                    const MovingPoint<Interval>& b0, const MovingPoint<Interval>& b1,
                    const AxisOrder& order)
      : a0_(a0), a1_(a1), b0_(b0), b1_(b1), order_(order) {}

  // Some projection where one segment lies strictly on one side of the other's line.
  bool excluded(const Interval& T) const { return excluded_in(T, 3); }
  bool excluded_in_leading_projection(const Interval& T) const { return excluded_in(T, 1); }
  // Some projection where the segments cross properly: then contact at every coplanar instant.
  bool certainly_included(const Interval& T) const {
    for (const int k : order_.axis) {
      const int s0 = certain_strict_sign(at(side(k, 0), T));
      if (s0 == 0 || !certainly_has_sign(at(side(k, 1), T), -s0)) continue;
      const int s2 = certain_strict_sign(at(side(k, 2), T));
      if (s2 != 0 && certainly_has_sign(at(side(k, 3), T), -s2)) return true;
    }
    return false;
  }

 private:
  bool excluded_in(const Interval& T, int projections) const {
    for (int i = leading_.skip(T); i < projections; ++i) {
      const int k = order_.axis[i];
      for (int pair = 0; pair < 4; pair += 2) {
        const int s = certain_strict_sign(at(side(k, pair), T));
        if (s != 0 && certainly_has_sign(at(side(k, pair + 1), T), s)) return true;
      }
    }
    leading_.failed_on(T);  // projections >= 1: the leading one did not exclude
    return false;
  }
  // orient2d_k(a0,a1,b0), (a0,a1,b1), (b0,b1,a0), (b0,b1,a1) for i = 0 ... 3
  const Quadratic& side(int k, int i) const {
    const unsigned bit = 1u << (4 * k + i);
    if (!(ready_ & bit)) {
      const MovingPoint<Interval>* const line[2][2] = {{&a0_, &a1_}, {&b0_, &b1_}};
      const MovingPoint<Interval>* const point[4] = {&b0_, &b1_, &a0_, &a1_};
      side_[k][i] = predicates::orient2d_along_axis(k, *line[i / 2][0], *line[i / 2][1], *point[i]);
      ready_ |= bit;
    }
    return side_[k][i];
  }

  const MovingPoint<Interval>&a0_, &a1_, &b0_, &b1_;
  const AxisOrder order_;
  mutable LeadingProjectionMemo leading_;
  mutable Quadratic side_[3][4];
  mutable unsigned ready_ = 0;  // bit 4k + i: side_[k][i]
};

}  // namespace

bool vertex_face_ccd_culling(const VertexFaceQuery& q) {
  return swept_boxes_disjoint({&q.p_t0, &q.p_t1},
                              {&q.a_t0, &q.b_t0, &q.c_t0, &q.a_t1, &q.b_t1, &q.c_t1});
}

bool edge_edge_ccd_culling(const EdgeEdgeQuery& q) {
  return swept_boxes_disjoint({&q.ea0_t0, &q.ea1_t0, &q.ea0_t1, &q.ea1_t1},
                              {&q.eb0_t0, &q.eb1_t0, &q.eb0_t1, &q.eb1_t1});
}

namespace {
FilterOutcome no_contact() {
  FilterOutcome none;
  none.verdict = FilterOutcome::Verdict::no_contact;
  return none;
}

/// The coplanarity cubic from its exact coefficients (ContactExactStage, whose exact cubic the
/// exact path reuses), scaled by a power of two and enclosed in intervals of one ulp (a point
/// where exact): a positive multiple of the cubic, with its roots and signs.
/// PROOF: proofs/filters.md#exact-cubic-retry
predicates::FixedPoly<Interval, 3> exact_cubic(ContactExactStage& exact) {
  double lo[4], hi[4];
  exact.cubic_coefficient_bounds(lo, hi);
  predicates::FixedPoly<Interval, 3> cubic;
  for (int i = 0; i < 4; ++i) cubic.c[i] = Interval(lo[i], hi[i]);
  return cubic;
}

/// The cubic filter, and where the interval cubic was too wide to isolate its roots, once more
/// with the cubic from its exact coefficients (rare: massive cancellation in the coefficients,
/// e.g. motions far smaller than the coordinates).
template <class Inclusion>
FilterOutcome cubic_filter_then_exact_cubic(const predicates::FixedPoly<Interval, 3>& cubic,
                                            const CcdOptions& options, const Inclusion& inclusion,
                                            ContactExactStage& exact) {
  const FilterOutcome f =
      cubic_filter(cubic, options.t_max, options.toi_width, inclusion, exact, true);
  if (!f.roots_unresolved) return f;
  FilterOutcome g =
      cubic_filter(exact_cubic(exact), options.t_max, options.toi_width, inclusion, exact);
  g.exact_used = true;
  return g;
}
}  // namespace

FilterOutcome vertex_face_ccd_filter(const VertexFaceQuery& q, const CcdOptions& options,
                                 ContactExactStage& exact) {
  // Semi-static stage (round to nearest, no guard needed): root-free on [0, 1] implies
  // root-free on [0, t_max] for every t_max <= 1.
  if (coplanarity_cubic_root_free_semistatic(q.b_t0 - q.a_t0, q.b_t1 - q.a_t1, q.c_t0 - q.a_t0,
                                             q.c_t1 - q.a_t1, q.p_t0 - q.a_t0, q.p_t1 - q.a_t1))
    return no_contact();
  RoundingGuard guard;
  const auto p = moving_point<Interval>(q.p_t0, q.p_t1), a = moving_point<Interval>(q.a_t0, q.a_t1),
             b = moving_point<Interval>(q.b_t0, q.b_t1), c = moving_point<Interval>(q.c_t0, q.c_t1);
  const AxisOrder order(
      (q.b_t0 + q.b_t1 - q.a_t0 - q.a_t1).cross(q.c_t0 + q.c_t1 - q.a_t0 - q.a_t1));
  const VertexFaceInclusion inclusion(p, a, b, c, order);
  // Excluded over the whole step in the best-conditioned projection: no contact, whatever the
  // cubic (cheaper than the cubic for most queries the semi-static stage leaves).
  if (inclusion.excluded_in_leading_projection(Interval(0.0, options.t_max))) return no_contact();
  // (A cubic certainly root-free on [0, t_max] is the cubic filter's first discarded node.)
  const auto cubic = predicates::vertex_face_coplanarity_cubic(p, a, b, c);
  return cubic_filter_then_exact_cubic(cubic, options, inclusion, exact);
}

FilterOutcome edge_edge_ccd_filter(const EdgeEdgeQuery& q, const CcdOptions& options,
                               ContactExactStage& exact) {
  if (coplanarity_cubic_root_free_semistatic(q.ea1_t0 - q.ea0_t0, q.ea1_t1 - q.ea0_t1,
                                             q.eb0_t0 - q.ea0_t0, q.eb0_t1 - q.ea0_t1,
                                             q.eb1_t0 - q.ea0_t0, q.eb1_t1 - q.ea0_t1))
    return no_contact();
  RoundingGuard guard;
  const auto a0 = moving_point<Interval>(q.ea0_t0, q.ea0_t1),
             a1 = moving_point<Interval>(q.ea1_t0, q.ea1_t1),
             b0 = moving_point<Interval>(q.eb0_t0, q.eb0_t1),
             b1 = moving_point<Interval>(q.eb1_t0, q.eb1_t1);
  const AxisOrder order(
      (q.ea1_t0 + q.ea1_t1 - q.ea0_t0 - q.ea0_t1).cross(q.eb1_t0 + q.eb1_t1 - q.eb0_t0 - q.eb0_t1));
  const EdgeEdgeInclusion inclusion(a0, a1, b0, b1, order);
  if (inclusion.excluded_in_leading_projection(Interval(0.0, options.t_max))) return no_contact();
  const auto cubic = predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1);
  return cubic_filter_then_exact_cubic(cubic, options, inclusion, exact);
}

}  // namespace exactccd::filters
