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

#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/interval.hpp"
#include "exact/arithmetic/rational.hpp"
#include "pipeline/contact_enclosures.hpp"

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

/// The 8 points of a query in the benchmark's row order.
using Points = std::array<Eigen::Vector3d, 8>;

void check_input(const Points& x, const CcdResult& r) {
  for (const auto& v : x)
    if (!v.allFinite())
      throw std::invalid_argument("exactccd: contact_geometry: non-finite coordinate");
  if (!r.collides)
    throw std::invalid_argument("exactccd: contact_geometry needs a colliding result");
  if (!(r.toi_lo >= 0.0 && r.toi_lo <= r.toi_hi && r.toi_hi <= 1.0))
    throw std::invalid_argument("exactccd: contact_geometry: the result's TOI enclosure is not "
                                "in [0, 1]");
}

/// Every coordinate scaled by the power of two 2^-e that brings the largest to [0.5, 1), when no
/// non-zero coordinate then falls below the normal range (so the scaling is exact). Barycentric
/// coordinates, segment parameters and unit normals do not change; the point scales back by 2^e.
int scale_exactly(Points& x) {
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (const auto& v : x)
    for (int i = 0; i < 3; ++i) {
      const double a = std::abs(v[i]);
      largest = std::max(largest, a);
      if (a > 0) smallest = std::min(smallest, a);
    }
  if (largest == 0.0) return 0;
  const int e = std::ilogb(largest) + 1;
  if (std::ilogb(smallest) - e < std::numeric_limits<double>::min_exponent - 1) return 0;
  for (auto& v : x)
    for (int i = 0; i < 3; ++i) v[i] = std::ldexp(v[i], -e);
  return e;
}

Interval at(const FixedPoly<Interval, 1>& x, const Interval& t) { return x.c[0] + t * x.c[1]; }

IVec at(const MovingPoint<Interval>& x, const Interval& t) {
  return {at(x.x, t), at(x.y, t), at(x.z, t)};
}

/// g'(t) over t, by Horner's rule on the derivative's coefficients.
Interval derivative_at(const FixedPoly<Interval, 3>& g, const Interval& t) {
  return g.c[1] + t * (2 * g.c[2] + t * (3 * g.c[3]));
}

/// T: [0, 0] when the primitives touch at the start (t* = 0, exact), else the TOI enclosure.
Interval time_of(const CcdResult& r) {
  return r.starts_within ? Interval(0.0) : Interval(r.toi_lo, r.toi_hi);
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

ContactGeometry vertex_face(Points x, const CcdResult& r) {
  check_input(x, r);
  const predicates::RoundingGuard upward;
  const int e = scale_exactly(x);
  const Interval t = time_of(r);
  const auto p = predicates::moving_point<Interval>(x[0], x[4]),
             a = predicates::moving_point<Interval>(x[1], x[5]),
             b = predicates::moving_point<Interval>(x[2], x[6]),
             c = predicates::moving_point<Interval>(x[3], x[7]);
  return with_degenerate_kind(
      contact::vertex_face_from(
          at(p, t), at(a, t), at(b, t), at(c, t), r.starts_within, e,
          [&] {
            return side_just_before(
                derivative_at(predicates::vertex_face_coplanarity_cubic(p, a, b, c), t));
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

ContactGeometry edge_edge(Points x, const CcdResult& r) {
  check_input(x, r);
  const predicates::RoundingGuard upward;
  const bool in_plane =
      std::all_of(x.begin(), x.end(), [](const Eigen::Vector3d& v) { return v.z() == 0.0; });
  const bool a_is_point = x[0] == x[1] && x[4] == x[5];
  const bool b_is_point = x[2] == x[3] && x[6] == x[7];
  const int e = scale_exactly(x);
  const Interval t = time_of(r);
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
            return side_just_before(
                derivative_at(predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1), t));
          }),
      x, false);
}

/// With a minimum separation delta > 0: the closest points at t* (contact_enclosures.hpp).
/// PROOF: proofs/contact_geometry.md#separation
ContactGeometry vertex_face_separation(Points x, const CcdResult& r) {
  check_input(x, r);
  const predicates::RoundingGuard upward;
  const int e = scale_exactly(x);
  const Interval t = time_of(r);
  const auto at_row = [&](int i) {
    return at(predicates::moving_point<Interval>(x[i], x[i + 4]), t);
  };
  return contact::vertex_face_separation_from(at_row(0), at_row(1), at_row(2), at_row(3),
                                              r.starts_within, e);
}

ContactGeometry edge_edge_separation(Points x, const CcdResult& r) {
  check_input(x, r);
  const predicates::RoundingGuard upward;
  const int e = scale_exactly(x);
  const Interval t = time_of(r);
  const auto at_row = [&](int i) {
    return at(predicates::moving_point<Interval>(x[i], x[i + 4]), t);
  };
  return contact::edge_edge_separation_from(at_row(0), at_row(1), at_row(2), at_row(3),
                                            r.starts_within, e);
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

namespace {

void check_separation(double min_separation) {
  if (!(min_separation >= 0.0) || !std::isfinite(min_separation))
    throw std::invalid_argument("exactccd: contact_geometry: min_separation must be finite and "
                                ">= 0");
}

}  // namespace

ContactGeometry contact_geometry(const VertexFaceQuery& q, const CcdResult& r,
                                 double min_separation) {
  check_separation(min_separation);
  const Points x{q.p_t0, q.a_t0, q.b_t0, q.c_t0, q.p_t1, q.a_t1, q.b_t1, q.c_t1};
  return min_separation > 0.0 ? vertex_face_separation(x, r) : vertex_face(x, r);
}

ContactGeometry contact_geometry(const EdgeEdgeQuery& q, const CcdResult& r,
                                 double min_separation) {
  check_separation(min_separation);
  const Points x{q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1};
  return min_separation > 0.0 ? edge_edge_separation(x, r) : edge_edge(x, r);
}

}  // namespace exactccd
