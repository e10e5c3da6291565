// The contact geometry's enclosures from the positions at the enclosure T of t* (intervals),
// shared by the linear and the rigid entry points (contact_geometry.cpp,
// rigid_contact_geometry.cpp): the parameters, the point and the unit normal, and the kind.
// PROOF: proofs/contact_geometry.md#enclosures
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/predicates/motion.hpp"
#include "core/predicates/interval.hpp"
#include "exactccd/contact.hpp"

namespace exactccd::pipeline::contact {

using predicates::Interval;
using IVec = predicates::Vec3<Interval>;

/// Throws std::invalid_argument unless `r` collides with an enclosure in [0, 1].
inline void check_result(const CcdResult& r) {
  if (!r.collides)
    throw std::invalid_argument("exactccd: contact_geometry needs a colliding result");
  if (!(r.toi_lo >= 0.0 && r.toi_lo <= r.toi_hi && r.toi_hi <= 1.0))
    throw std::invalid_argument("exactccd: contact_geometry: the result's TOI enclosure is not "
                                "in [0, 1]");
}

/// Throws std::invalid_argument unless delta is finite and >= 0.
inline void check_separation(double min_separation) {
  if (!(min_separation >= 0.0) || !std::isfinite(min_separation))
    throw std::invalid_argument("exactccd: contact_geometry: min_separation must be finite and "
                                ">= 0");
}

/// The enclosure of t* (of s* for rigid motion): [0, 0] when the primitives touch at the start
/// (starts_within: t* = 0 exactly), else [toi_lo, toi_hi].
inline Interval parameter_enclosure(const CcdResult& r) {
  return r.starts_within ? Interval(0.0) : Interval(r.toi_lo, r.toi_hi);
}

/// g'(t) over t, by Horner's rule on the derivative's coefficients (an enclosure of g' there).
template <int D>
Interval derivative_over(const predicates::FixedPoly<Interval, D>& g, const Interval& t) {
  Interval r = double(D) * g.c[D];
  for (int k = D - 1; k >= 1; --k) r = double(k) * g.c[k] + t * r;
  return r;
}

/// +1 (-1) when g, which vanishes at t* in t, is certainly positive (negative) just before t*:
/// g'(t*) lies in g'(t), so a certain sign of g'(t) is -sign(g) just before. 0: not certain.
inline int side_just_before(const Interval& derivative) {
  if (derivative.sup() < 0) return 1;
  if (derivative.inf() > 0) return -1;
  return 0;
}

/// x, known to lie in [lo, hi] at t*, intersected with it. An empty intersection would
/// contradict the proof: a bug, never an answer.
inline Enclosure within(const Interval& x, double lo, double hi) {
  const Enclosure e{std::max(x.inf(), lo), std::min(x.sup(), hi)};
  if (!(e.lo <= e.hi)) throw std::logic_error("exactccd: contact_geometry: empty enclosure");
  return e;
}

/// The enclosure of a point, scaled back by 2^e. Exact unless a bound becomes subnormal; then
/// ldexp rounds upward (the guard's mode), so the lower bound is scaled negated.
inline std::array<Enclosure, 3> point_of(const IVec& p, int e) {
  std::array<Enclosure, 3> out;
  for (int i = 0; i < 3; ++i)
    out[i] = {-std::ldexp(-p[i].inf(), e), std::ldexp(p[i].sup(), e)};
  return out;
}

/// The unit vector side * v / |v| when |v| is certainly positive (else false).
inline bool unit_normal(const IVec& v, int side, std::array<Enclosure, 3>* out) {
  const Interval vv = predicates::dot(v, v);
  if (!(vv.inf() > 0)) return false;
  const Interval length = CGAL::sqrt(vv);
  for (int i = 0; i < 3; ++i) (*out)[i] = within(v[i] * double(side) / length, -1.0, 1.0);
  return true;
}

/// The box hull of a segment's enclosures: the segment's points, each in it, lie in it.
inline IVec hull(const IVec& a, const IVec& b) {
  IVec h;
  Interval* c[3] = {&h.x, &h.y, &h.z};
  for (int i = 0; i < 3; ++i)
    *c[i] = Interval(std::min(a[i].inf(), b[i].inf()), std::max(a[i].sup(), b[i].sup()));
  return h;
}

inline IVec intersect(const IVec& a, const IVec& b) {
  IVec h;
  Interval* c[3] = {&h.x, &h.y, &h.z};
  for (int i = 0; i < 3; ++i) {
    const Enclosure e = within(a[i], b[i].inf(), b[i].sup());
    *c[i] = Interval(e.lo, e.hi);
  }
  return h;
}

/// Vertex p against the triangle (a, b, c), from their positions over T (p(t*) lies in the
/// triangle); `side_before()` is the side of det[b - a, c - a, p - a] just before t* (+1, -1,
/// or 0 when not certain), asked only when t* > 0. e: the point's scaling exponent.
template <class SideBefore>
ContactGeometry vertex_face_from(const IVec& P, const IVec& A, const IVec& B, const IVec& C,
                                 bool starts_within, int e, SideBefore&& side_before) {
  ContactGeometry g;
  g.parameter_count = 3;
  g.point = point_of(P, e);  // the contact point is the vertex
  g.parameters = {Enclosure{0, 1}, Enclosure{0, 1}, Enclosure{0, 1}};
  const IVec n = predicates::cross(B - A, C - A);
  const Interval nn = predicates::dot(n, n);
  if (!(nn.inf() > 0)) return g;  // degenerate or nearly: unresolved
  // p(t*) lies in the triangle's plane, where these are its barycentric coordinates.
  g.parameters[0] = within(predicates::dot(n, predicates::cross(B - P, C - P)) / nn, 0.0, 1.0);
  g.parameters[1] = within(predicates::dot(n, predicates::cross(C - P, A - P)) / nn, 0.0, 1.0);
  g.parameters[2] = within(predicates::dot(n, predicates::cross(A - P, B - P)) / nn, 0.0, 1.0);
  if (starts_within) {
    unit_normal(n, 1, &g.normal);
    g.kind = ContactKind::at_start;
    return g;
  }
  // det[b - a, c - a, p - a] = (p - a) . n: positive when p is on n's side.
  const int side = side_before();
  g.normal_oriented = side != 0 && unit_normal(n, side, &g.normal);
  if (!g.normal_oriented) unit_normal(n, 1, &g.normal);
  g.kind = g.normal_oriented ? ContactKind::point : ContactKind::unresolved;
  return g;
}

/// Segments [a0, a1] and [b0, b1] (neither a point), from their positions over T;
/// `side_before()` is the side of det[a1 - a0, b0 - a0, b1 - a0] just before t*.
template <class SideBefore>
ContactGeometry edge_edge_from(const IVec& A0, const IVec& A1, const IVec& B0, const IVec& B1,
                               bool starts_within, int e, SideBefore&& side_before) {
  ContactGeometry g;
  g.parameter_count = 2;
  g.parameters = {Enclosure{0, 1}, Enclosure{0, 1}, Enclosure{0, 0}};
  const IVec da = A1 - A0, db = B1 - B0, m = predicates::cross(da, db);
  const Interval mm = predicates::dot(m, m);
  if (!(mm.inf() > 0)) {  // parallel or nearly: the point lies on both segments
    g.point = point_of(intersect(hull(A0, A1), hull(B0, B1)), e);
    return g;
  }
  // a0 + s da = b0 + u db at t*: crossing with db and with da isolates s and u.
  const IVec w = B0 - A0;
  const Interval s = predicates::dot(predicates::cross(w, db), m) / mm;
  const Interval u = predicates::dot(predicates::cross(w, da), m) / mm;
  g.parameters[0] = within(s, 0.0, 1.0);
  g.parameters[1] = within(u, 0.0, 1.0);
  const Interval sc(g.parameters[0].lo, g.parameters[0].hi),
      uc(g.parameters[1].lo, g.parameters[1].hi);
  const IVec on_a{A0.x + sc * da.x, A0.y + sc * da.y, A0.z + sc * da.z};
  const IVec on_b{B0.x + uc * db.x, B0.y + uc * db.y, B0.z + uc * db.z};
  g.point = point_of(intersect(on_a, on_b), e);
  if (starts_within) {
    unit_normal(m, 1, &g.normal);
    g.kind = ContactKind::at_start;
    return g;
  }
  // det[a1 - a0, b0 - a0, b1 - a0] = (a0 - b0) . m: positive when edge a is on m's side.
  const int side = side_before();
  g.normal_oriented = side != 0 && unit_normal(m, side, &g.normal);
  if (!g.normal_oriented) unit_normal(m, 1, &g.normal);
  g.kind = g.normal_oriented ? ContactKind::point : ContactKind::unresolved;
  return g;
}

/// The box hull of three point enclosures.
inline IVec hull3(const IVec& a, const IVec& b, const IVec& c) { return hull(hull(a, b), c); }

/// Where the closest point of the segment [S0, S1] to X lies, certainly: its parameter
/// lambda = (X - S0) . d / d . d (d = S1 - S0) clamped to [0, 1].
struct SegmentFoot {
  enum Where { start, interior, end, uncertain } where = uncertain;
  Interval lambda{0.0, 1.0};  ///< the clamped parameter (exact 0 or 1 at an end)
};

inline SegmentFoot foot_on_segment(const IVec& X, const IVec& S0, const IVec& S1) {
  SegmentFoot f;
  const IVec d = S1 - S0;
  const Interval dd = predicates::dot(d, d);
  if (!(dd.inf() > 0)) return f;
  const Interval along = predicates::dot(X - S0, d);
  if (along.sup() <= 0) {
    f.where = SegmentFoot::start;
    f.lambda = Interval(0.0);
  } else if ((along - dd).inf() >= 0) {
    f.where = SegmentFoot::end;
    f.lambda = Interval(1.0);
  } else if (along.inf() > 0 && (along - dd).sup() < 0) {
    f.where = SegmentFoot::interior;
    const Enclosure l = within(along / dd, 0.0, 1.0);
    f.lambda = Interval(l.lo, l.hi);
  }
  return f;
}

inline IVec point_at(const IVec& S0, const IVec& S1, const Interval& lambda) {
  const IVec d = S1 - S0;
  return {S0.x + lambda * d.x, S0.y + lambda * d.y, S0.z + lambda * d.z};
}

/// The geometry from the closest points Qa (on the vertex or edge a) and Qb (on the face or edge
/// b): `point` is Qb, the normal the unit vector from Qb towards Qa (certain when |Qa - Qb| is
/// certainly positive: at t* > 0 it is delta).
inline void closest_points(ContactGeometry& g, const IVec& Qa, const IVec& Qb,
                           bool starts_within, int e) {
  g.point = point_of(Qb, e);
  g.normal_oriented = unit_normal(Qa - Qb, 1, &g.normal);
  g.kind = !g.normal_oriented ? ContactKind::unresolved
                              : (starts_within ? ContactKind::at_start : ContactKind::point);
}

/// With a minimum separation delta > 0, from the positions over T: the closest points at t*,
/// where the distance is delta. The closest point of the triangle is the vertex's projection
/// when every barycentric coordinate is certainly positive (the normal is then the triangle's,
/// towards the vertex's side); on a side when the projection is certainly beyond that side and
/// its foot certainly inside it; at a corner when the vertex is certainly in the corner's cone
/// of the Voronoi diagram ((p - x) . (y - x) <= 0 for both other corners y). Anything else (a
/// degenerate triangle, a region not certain over T) is `unresolved`.
/// PROOF: proofs/contact_geometry.md#separation
inline ContactGeometry vertex_face_separation_from(const IVec& P, const IVec& A, const IVec& B,
                                                   const IVec& C, bool starts_within, int e) {
  ContactGeometry g;
  g.parameter_count = 3;
  g.parameters = {Enclosure{0, 1}, Enclosure{0, 1}, Enclosure{0, 1}};
  g.point = point_of(hull3(A, B, C), e);  // the closest point is on the triangle
  const IVec n = predicates::cross(B - A, C - A);
  const Interval nn = predicates::dot(n, n);
  if (!(nn.inf() > 0)) return g;
  // The projection's barycentric coordinates (with respect to a, b, c).
  const Interval bary[3] = {predicates::dot(n, predicates::cross(B - P, C - P)) / nn,
                            predicates::dot(n, predicates::cross(C - P, A - P)) / nn,
                            predicates::dot(n, predicates::cross(A - P, B - P)) / nn};
  if (bary[0].inf() > 0 && bary[1].inf() > 0 && bary[2].inf() > 0) {
    g.parameters = {within(bary[0], 0.0, 1.0), within(bary[1], 0.0, 1.0),
                    within(bary[2], 0.0, 1.0)};
    const Interval f = predicates::dot(P - A, n);  // (p - a) . n: the vertex's side
    const Interval k = f / nn;
    g.point = point_of(IVec{P.x - k * n.x, P.y - k * n.y, P.z - k * n.z}, e);
    const int side = predicates::certain_strict_sign(f);
    g.normal_oriented = side != 0 && unit_normal(n, side, &g.normal);
    g.kind = !g.normal_oriented ? ContactKind::unresolved
                                : (starts_within ? ContactKind::at_start : ContactKind::point);
    return g;
  }
  const IVec corner[3] = {A, B, C};
  // A corner's cone: the closest point is that corner.
  for (int i = 0; i < 3; ++i) {
    const IVec& X = corner[i];
    const IVec& Y = corner[(i + 1) % 3];
    const IVec& Z = corner[(i + 2) % 3];
    if (predicates::dot(P - X, Y - X).sup() <= 0 && predicates::dot(P - X, Z - X).sup() <= 0) {
      g.parameters = {Enclosure{0, 0}, Enclosure{0, 0}, Enclosure{0, 0}};
      g.parameters[i] = {1.0, 1.0};
      closest_points(g, P, X, starts_within, e);
      return g;
    }
  }
  // A side: beyond it (the opposite corner's coordinate certainly negative), its foot inside.
  for (int k = 0; k < 3; ++k) {  // the side opposite corner k, from corner k+1 to corner k+2
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (!(bary[k].sup() < 0)) continue;
    const SegmentFoot f = foot_on_segment(P, corner[i], corner[j]);
    if (f.where != SegmentFoot::interior) continue;
    g.parameters = {Enclosure{0, 0}, Enclosure{0, 0}, Enclosure{0, 0}};
    g.parameters[i] = within(Interval(1.0) - f.lambda, 0.0, 1.0);
    g.parameters[j] = within(f.lambda, 0.0, 1.0);
    closest_points(g, P, point_at(corner[i], corner[j], f.lambda), starts_within, e);
    return g;
  }
  return g;
}

/// The same for two segments (a point as a zero-length one: `a_is_point`, `b_is_point`, known
/// exactly from the query): the closest points are interior to both when the lines' closest
/// parameters are certainly in (0, 1) (the normal: the edges' cross product towards edge a);
/// otherwise, when those parameters are certainly outside (0, 1)^2, the closest pair is the
/// nearest of the four endpoint-against-segment pairs, taken when it is certainly nearer than
/// the others with its foot certainly placed. `point` is the closest point on edge b, the
/// normal from it towards edge a. PROOF: proofs/contact_geometry.md#separation
inline ContactGeometry edge_edge_separation_from(const IVec& A0, const IVec& A1, const IVec& B0,
                                                 const IVec& B1, bool starts_within, int e,
                                                 bool a_is_point = false,
                                                 bool b_is_point = false) {
  ContactGeometry g;
  g.parameter_count = 2;
  g.parameters = {Enclosure{0, 1}, Enclosure{0, 1}, Enclosure{0, 0}};
  g.point = point_of(hull(B0, B1), e);  // the closest point on edge b
  if (a_is_point) g.parameters[0] = {0.0, 0.0};
  if (b_is_point) g.parameters[1] = {0.0, 0.0};
  if (a_is_point && b_is_point) {
    closest_points(g, A0, B0, starts_within, e);
    return g;
  }
  if (a_is_point || b_is_point) {  // a point against a segment: its foot
    const IVec& X = a_is_point ? A0 : B0;
    const SegmentFoot f = a_is_point ? foot_on_segment(X, B0, B1) : foot_on_segment(X, A0, A1);
    if (f.where == SegmentFoot::uncertain) return g;
    g.parameters[a_is_point ? 1 : 0] = within(f.lambda, 0.0, 1.0);
    if (a_is_point)
      closest_points(g, A0, point_at(B0, B1, f.lambda), starts_within, e);
    else
      closest_points(g, point_at(A0, A1, f.lambda), B0, starts_within, e);
    return g;
  }
  const IVec da = A1 - A0, db = B1 - B0, m = predicates::cross(da, db);
  const Interval mm = predicates::dot(m, m);
  if (!(mm.inf() > 0)) return g;  // parallel or nearly: the closest pair need not be unique
  const IVec wv = B0 - A0;
  const Interval s = predicates::dot(predicates::cross(wv, db), m) / mm;
  const Interval u = predicates::dot(predicates::cross(wv, da), m) / mm;
  if (s.inf() > 0 && s.sup() < 1 && u.inf() > 0 && u.sup() < 1) {
    g.parameters[0] = within(s, 0.0, 1.0);
    g.parameters[1] = within(u, 0.0, 1.0);
    g.point = point_of(IVec{B0.x + u * db.x, B0.y + u * db.y, B0.z + u * db.z}, e);
    // (a0 - b0) . m: the side of edge a; the closest points differ by a multiple of m.
    const int side = predicates::certain_strict_sign(predicates::dot(A0 - B0, m));
    g.normal_oriented = side != 0 && unit_normal(m, side, &g.normal);
    g.kind = !g.normal_oriented ? ContactKind::unresolved
                                : (starts_within ? ContactKind::at_start : ContactKind::point);
    return g;
  }
  // The lines' minimiser certainly outside the square: the minimum is on its boundary, one of
  // the four endpoint-against-segment pairs.
  const bool outside = s.sup() <= 0 || s.inf() >= 1 || u.sup() <= 0 || u.inf() >= 1;
  if (!outside) return g;
  struct Candidate {
    Interval s, u;
    IVec on_a, on_b;
    Interval d2;
    int ends = -1;  ///< 2 ia + ib when the pair is end ia of a against end ib of b, else -1
  };
  Candidate c[4];
  const IVec ends_a[2] = {A0, A1}, ends_b[2] = {B0, B1};
  for (int k = 0; k < 4; ++k) {
    const bool from_a = k < 2;  // an end of edge a against edge b, or the reverse
    const IVec& X = from_a ? ends_a[k] : ends_b[k - 2];
    const SegmentFoot f = from_a ? foot_on_segment(X, B0, B1) : foot_on_segment(X, A0, A1);
    if (f.where == SegmentFoot::uncertain) return g;
    c[k].s = from_a ? Interval(double(k)) : f.lambda;
    c[k].u = from_a ? f.lambda : Interval(double(k - 2));
    c[k].on_a = from_a ? X : point_at(A0, A1, f.lambda);
    c[k].on_b = from_a ? point_at(B0, B1, f.lambda) : X;
    const IVec d = c[k].on_a - c[k].on_b;
    c[k].d2 = predicates::dot(d, d);
    if (f.where != SegmentFoot::interior) {  // an end against an end: found from both sides
      const int other = f.where == SegmentFoot::start ? 0 : 1;
      c[k].ends = from_a ? 2 * k + other : 2 * other + (k - 2);
    }
  }
  for (int k = 0; k < 4; ++k) {
    bool nearest = true;
    for (int j = 0; j < 4 && nearest; ++j)
      nearest = j == k || (c[k].ends >= 0 && c[j].ends == c[k].ends) ||
                c[k].d2.sup() < c[j].d2.inf();
    if (!nearest) continue;
    g.parameters[0] = within(c[k].s, 0.0, 1.0);
    g.parameters[1] = within(c[k].u, 0.0, 1.0);
    closest_points(g, c[k].on_a, c[k].on_b, starts_within, e);
    return g;
  }
  return g;
}

}  // namespace exactccd::pipeline::contact
