// The contact geometry at t* (exactccd/contact.hpp): interval arithmetic with upward rounding
// (CGAL::Interval_nt) over the certified enclosure T = [toi_lo, toi_hi] of t*. Every quantity is
// a rational function of the positions at t, so its interval over T contains its value at t*.
// PROOF: proofs/contact_geometry.md#enclosures
#include "exactccd/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/interval.hpp"
#include "exact/arithmetic/rational.hpp"
#include "core/predicates/query_points.hpp"
#include "pipeline/contact_enclosures.hpp"
#include "pipeline/power_of_two_scaling.hpp"

namespace exactccd {

namespace {

using predicates::FixedPoly;
using predicates::Interval;
using predicates::MovingPoint;
using IVec = predicates::Vec3<Interval>;
namespace contact = pipeline::contact;
using contact::point_of;
using contact::side_just_before;
using contact::unit_normal;
using contact::within;

/// The 8 points of a query in the benchmark's row order, as the pipeline reads them.
using Points = std::array<Eigen::Vector3d, 8>;

/// A query ready for the enclosures: finite (else invalid_argument), normalised by the
/// pipeline's exact power-of-two scaling 2^s (power_of_two_scaling.hpp; the point scales back by
/// 2^-s), its rows, and T, the enclosure of t* ([0, 0] when it touches at the start).
struct Prepared {
  Points x;
  int e = 0;  ///< the point's scale-back exponent
  Interval t;
};

template <class Query>
Prepared prepared(const Query& query, const CcdResult& r) {
  if (!predicates::all_finite(query))
    throw std::invalid_argument("exactccd: contact_geometry: non-finite coordinate");
  contact::check_result(r);
  const int s = detail::normalising_exponent(query);
  const Query q = s != 0 ? detail::scaled_by_power_of_two(query, s) : query;
  Prepared out;
  const predicates::QueryPoints rows = predicates::points_of(q);
  for (int i = 0; i < 8; ++i) out.x[i] = *rows[i];
  out.e = -s;
  out.t = contact::parameter_enclosure(r);
  return out;
}

Interval at(const FixedPoly<Interval, 1>& x, const Interval& t) { return x.c[0] + t * x.c[1]; }

IVec at(const MovingPoint<Interval>& x, const Interval& t) {
  return {at(x.x, t), at(x.y, t), at(x.z, t)};
}

/// Every coefficient zero: the polynomial vanishes identically.
template <int D>
bool identically_zero(const FixedPoly<exact::Rational, D>& f) {
  for (const auto& c : f.c)
    if (sgn(c) != 0) return false;
  return true;
}

template <class V>
bool identically_zero(const V& v) {
  return identically_zero(v.x) && identically_zero(v.y) && identically_zero(v.z);
}

/// An unresolved geometry's exact degenerate kind, when its configuration is degenerate at
/// every t (exact rational polynomials of the doubles; only on this rare path).
/// PROOF: proofs/contact_geometry.md#degenerate-kinds
ContactKind degenerate_kind(const Points& x, bool vertex_face) {
  using exact::Rational;
  const auto m = [&](int i) { return predicates::moving_point<Rational>(x[i], x[i + 4]); };
  if (vertex_face) {
    const auto p = m(0), a = m(1), b = m(2), c = m(3);
    if (identically_zero(predicates::cross(b - a, c - a))) return ContactKind::degenerate_triangle;
    if (identically_zero(predicates::vertex_face_coplanarity_cubic(p, a, b, c)))
      return ContactKind::coplanar;
    return ContactKind::unresolved;
  }
  const auto a0 = m(0), a1 = m(1), b0 = m(2), b1 = m(3);
  if (identically_zero(predicates::cross(a1 - a0, b1 - b0))) return ContactKind::parallel_edges;
  if (identically_zero(predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1)))
    return ContactKind::coplanar;
  return ContactKind::unresolved;
}

ContactGeometry with_degenerate_kind(ContactGeometry g, const Points& x, bool vertex_face) {
  if (g.kind == ContactKind::unresolved) g.kind = degenerate_kind(x, vertex_face);
  return g;
}

ContactGeometry vertex_face(const VertexFaceQuery& query, const CcdResult& r) {
  const predicates::RoundingGuard upward;
  const Prepared q = prepared(query, r);
  const Points& x = q.x;
  const Interval& t = q.t;
  const auto p = predicates::moving_point<Interval>(x[0], x[4]),
             a = predicates::moving_point<Interval>(x[1], x[5]),
             b = predicates::moving_point<Interval>(x[2], x[6]),
             c = predicates::moving_point<Interval>(x[3], x[7]);
  return with_degenerate_kind(
      contact::vertex_face_from(
          at(p, t), at(a, t), at(b, t), at(c, t), r.starts_within, q.e,
          [&] {
            return side_just_before(contact::derivative_over(
                predicates::vertex_face_coplanarity_cubic(p, a, b, c), t));
          }),
      x, true);
}

/// A point (edge `point_edge`, zero-length throughout) against the segment [s0, s1].
ContactGeometry point_segment(const MovingPoint<Interval>& q, const MovingPoint<Interval>& s0,
                              const MovingPoint<Interval>& s1, bool point_is_a, bool in_plane,
                              const CcdResult& r, const Interval& t, int e) {
  const IVec Q = at(q, t), S0 = at(s0, t), S1 = at(s1, t);
  ContactGeometry g;
  g.parameter_count = 2;
  g.point = point_of(Q, e);
  const IVec d = S1 - S0;
  const Interval dd = predicates::dot(d, d);
  const Enclosure on_segment =
      dd.inf() > 0 ? within(predicates::dot(Q - S0, d) / dd, 0.0, 1.0) : Enclosure{0, 1};
  g.parameters[point_is_a ? 0 : 1] = {0.0, 0.0};
  g.parameters[point_is_a ? 1 : 0] = on_segment;
  const bool resolved = dd.inf() > 0;
  if (r.starts_within) {
    g.kind = resolved ? ContactKind::at_start : ContactKind::unresolved;
    return g;
  }
  if (!in_plane || !resolved) return g;  // 3D: the normal is not defined by the rules
  // In z = 0: h(t) = (q - s0) . perp(d), perp(d) = (-d_y, d_x), vanishes at t* (q on the
  // segment); its side just before t* orients the perpendicular from the segment to the point.
  const IVec perp{-d.y, d.x, Interval(0.0)};
  // h'(t) by the product rule: (q' - s0') . perp(d) + (q - s0) . perp(d').
  const IVec dq{q.x.c[1] - s0.x.c[1], q.y.c[1] - s0.y.c[1], Interval(0.0)};
  const IVec dd_dt{s1.x.c[1] - s0.x.c[1], s1.y.c[1] - s0.y.c[1], Interval(0.0)};
  const IVec perp_dt{-dd_dt.y, dd_dt.x, Interval(0.0)};
  const Interval h_dt = predicates::dot(dq, perp) + predicates::dot(Q - S0, perp_dt);
  const int side = side_just_before(h_dt) * (point_is_a ? 1 : -1);
  g.normal_oriented = side != 0 && unit_normal(perp, side, &g.normal);
  g.kind = g.normal_oriented ? ContactKind::point : ContactKind::unresolved;
  return g;
}

ContactGeometry edge_edge(const EdgeEdgeQuery& query, const CcdResult& r) {
  const predicates::RoundingGuard upward;
  const Prepared q = prepared(query, r);
  const Points& x = q.x;
  const Interval& t = q.t;
  const int e = q.e;
  // Exact scaling keeps zeros and equalities: these read the scaled rows as the input's.
  const bool in_plane =
      std::all_of(x.begin(), x.end(), [](const Eigen::Vector3d& v) { return v.z() == 0.0; });
  const bool a_is_point = x[0] == x[1] && x[4] == x[5];
  const bool b_is_point = x[2] == x[3] && x[6] == x[7];
  const auto a0 = predicates::moving_point<Interval>(x[0], x[4]),
             a1 = predicates::moving_point<Interval>(x[1], x[5]),
             b0 = predicates::moving_point<Interval>(x[2], x[6]),
             b1 = predicates::moving_point<Interval>(x[3], x[7]);
  if (a_is_point && b_is_point) {
    // p(t) - q(t) = (t - t*) v, v the relative velocity: from q towards p before t* is -v.
    ContactGeometry g;
    g.parameter_count = 2;
    g.parameters = {Enclosure{0, 0}, Enclosure{0, 0}, Enclosure{0, 0}};
    g.point = point_of(at(a0, t), e);
    if (r.starts_within) {
      g.kind = ContactKind::at_start;
      return g;
    }
    const IVec v{a0.x.c[1] - b0.x.c[1], a0.y.c[1] - b0.y.c[1], a0.z.c[1] - b0.z.c[1]};
    g.normal_oriented = unit_normal(v, -1, &g.normal);
    g.kind = g.normal_oriented ? ContactKind::point : ContactKind::unresolved;
    return g;
  }
  if (a_is_point) return point_segment(a0, b0, b1, true, in_plane, r, t, e);
  if (b_is_point) return point_segment(b0, a0, a1, false, in_plane, r, t, e);
  return with_degenerate_kind(
      contact::edge_edge_from(
          at(a0, t), at(a1, t), at(b0, t), at(b1, t), r.starts_within, e,
          [&] {
            return side_just_before(contact::derivative_over(
                predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1), t));
          }),
      x, false);
}

/// With a minimum separation delta > 0: the closest points at t* (contact_enclosures.hpp).
/// PROOF: proofs/contact_geometry.md#separation
template <class Query>
ContactGeometry separation(const Query& query, const CcdResult& r) {
  const predicates::RoundingGuard upward;
  const Prepared q = prepared(query, r);
  const auto at_row = [&](int i) {
    return at(predicates::moving_point<Interval>(q.x[i], q.x[i + 4]), q.t);
  };
  constexpr bool vf = std::is_same_v<Query, VertexFaceQuery>;
  const bool points = !vf && ((q.x[0] == q.x[1] && q.x[4] == q.x[5]) ||
                              (q.x[2] == q.x[3] && q.x[6] == q.x[7]));
  ContactGeometry g =
      vf ? contact::vertex_face_separation_from(at_row(0), at_row(1), at_row(2), at_row(3),
                                                r.starts_within, q.e)
         : contact::edge_edge_separation_from(
               at_row(0), at_row(1), at_row(2), at_row(3), r.starts_within, q.e,
               q.x[0] == q.x[1] && q.x[4] == q.x[5], q.x[2] == q.x[3] && q.x[6] == q.x[7]);
  // Closest points that are not unique: a triangle degenerate, or edges parallel, at every t
  // (exactly); the enclosures stay the trivially valid ones. Not for points, which are
  // "parallel" to everything and resolved above.
  if (g.kind == ContactKind::unresolved && !points) {
    const ContactKind k = degenerate_kind(q.x, vf);
    if (k == ContactKind::degenerate_triangle || k == ContactKind::parallel_edges) g.kind = k;
  }
  return g;
}

}  // namespace

const char* to_string(ContactKind kind) noexcept {
  switch (kind) {
    case ContactKind::point: return "point";
    case ContactKind::at_start: return "at_start";
    case ContactKind::unresolved: return "unresolved";
    case ContactKind::degenerate_triangle: return "degenerate_triangle";
    case ContactKind::parallel_edges: return "parallel_edges";
    case ContactKind::coplanar: return "coplanar";
  }
  return "unknown";
}

ContactGeometry contact_geometry(const VertexFaceQuery& q, const CcdResult& r,
                                 double min_separation) {
  contact::check_separation(min_separation);
  return min_separation > 0.0 ? separation(q, r) : vertex_face(q, r);
}

ContactGeometry contact_geometry(const EdgeEdgeQuery& q, const CcdResult& r,
                                 double min_separation) {
  contact::check_separation(min_separation);
  return min_separation > 0.0 ? separation(q, r) : edge_edge(q, r);
}

}  // namespace exactccd
