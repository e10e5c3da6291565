// The contact geometry of rigid queries (exactccd/contact.hpp): the positions over the
// enclosure S of s* by interval arithmetic on the rational rigid motion (or the straight lines
// of a linear side), each with its derivative in s (forward mode: pairs of value and
// derivative), then the enclosures of contact_enclosures.hpp. The side just before s* is the
// sign of minus the coplanarity determinant's derivative, as for linear motion.
// PROOF: proofs/contact_geometry.md#rigid
#include <cmath>
#include <stdexcept>

#include "core/predicates/interval.hpp"
#include "exactccd/contact.hpp"
#include "pipeline/contact_enclosures.hpp"

namespace exactccd {

namespace {

using predicates::Interval;
using IVec = predicates::Vec3<Interval>;

/// A value and its derivative in s, both intervals.
struct Dual {
  Interval v, d;
};
Dual operator+(const Dual& a, const Dual& b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(const Dual& a, const Dual& b) { return {a.v - b.v, a.d - b.d}; }
Dual operator*(const Dual& a, const Dual& b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
Dual operator/(const Dual& a, const Dual& b) {
  return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
}
Dual constant(double x) { return {Interval(x), Interval(0.0)}; }
using DVec = predicates::Vec3<Dual>;

DVec constant(const Eigen::Vector3d& x) { return {constant(x.x()), constant(x.y()), constant(x.z())}; }

IVec values(const DVec& x) { return {x.x.v, x.y.v, x.z.v}; }

/// The position at s in S of the side's vertex that is at x0 at s = 0 (`end`: its position at
/// s = 1 when the side moves on straight lines), with its derivative.
DVec position(const SideMotion& side, const Eigen::Vector3d& x0, const Eigen::Vector3d& end,
              const Interval& S) {
  const Dual s{S, Interval(1.0)};
  if (side.kind == PathKind::linear) {
    const DVec a = constant(x0), b = constant(end);
    return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)};
  }
  // x(s) = c + s d + ((1 - v.v) r + 2 v (v.r) + 2 v x r) / (1 + v.v), v = s q, r = x0 - c.
  const RigidMotion& m = side.rigid;
  const DVec c = constant(m.pivot), d = constant(m.translation), q = constant(m.cayley);
  const DVec r = constant(x0) - c;
  const DVec v{s * q.x, s * q.y, s * q.z};
  const Dual vv = predicates::dot(v, v), vr = predicates::dot(v, r);
  const DVec vxr = predicates::cross(v, r);
  const Dual one = constant(1.0), two = constant(2.0), den = one + vv;
  const auto coordinate = [&](const Dual& ci, const Dual& di, const Dual& ri, const Dual& vi,
                              const Dual& wi) {
    return ci + s * di + ((one - vv) * ri + two * vi * vr + two * wi) / den;
  };
  return {coordinate(c.x, d.x, r.x, v.x, vxr.x), coordinate(c.y, d.y, r.y, v.y, vxr.y),
          coordinate(c.z, d.z, r.z, v.z, vxr.z)};
}

bool finite(const SideMotion& side) {
  if (side.kind == PathKind::linear) {
    for (const auto& x : side.linear_end)
      if (!x.allFinite()) return false;
    return true;
  }
  return side.rigid.pivot.allFinite() && side.rigid.translation.allFinite() &&
         side.rigid.cayley.allFinite();
}

/// The enclosure S of s*: [0, 0] when the primitives touch at the start.
Interval parameter_of(const CcdResult& r, bool finite_input) {
  if (!finite_input)
    throw std::invalid_argument("exactccd: contact_geometry: non-finite position or motion");
  if (!r.collides)
    throw std::invalid_argument("exactccd: contact_geometry needs a colliding result");
  if (!(r.toi_lo >= 0.0 && r.toi_lo <= r.toi_hi && r.toi_hi <= 1.0))
    throw std::invalid_argument("exactccd: contact_geometry: the result's TOI enclosure is not "
                                "in [0, 1]");
  return r.starts_within ? Interval(0.0) : Interval(r.toi_lo, r.toi_hi);
}

}  // namespace

void check_separation(double min_separation) {
  if (!(min_separation >= 0.0) || !std::isfinite(min_separation))
    throw std::invalid_argument("exactccd: contact_geometry: min_separation must be finite and "
                                ">= 0");
}

ContactGeometry contact_geometry(const RigidVertexFaceQuery& q, const RigidCcdResult& result,
                                 double min_separation) {
  check_separation(min_separation);
  const predicates::RoundingGuard upward;
  const bool ok = q.p.allFinite() && q.a.allFinite() && q.b.allFinite() && q.c.allFinite() &&
                  finite(q.vertex) && finite(q.face);
  const Interval S = parameter_of(result.ccd, ok);
  const DVec p = position(q.vertex, q.p, q.vertex.linear_end[0], S),
             a = position(q.face, q.a, q.face.linear_end[0], S),
             b = position(q.face, q.b, q.face.linear_end[1], S),
             c = position(q.face, q.c, q.face.linear_end[2], S);
  if (min_separation > 0.0)
    return pipeline::contact::vertex_face_separation_from(values(p), values(a), values(b),
                                                          values(c), result.ccd.starts_within, 0);
  return pipeline::contact::vertex_face_from(
      values(p), values(a), values(b), values(c), result.ccd.starts_within, 0, [&] {
        const Dual g = predicates::dot(predicates::cross(b - a, c - a), p - a);
        return pipeline::contact::side_just_before(g.d);
      });
}

ContactGeometry contact_geometry(const RigidEdgeEdgeQuery& q, const RigidCcdResult& result,
                                 double min_separation) {
  check_separation(min_separation);
  const predicates::RoundingGuard upward;
  const bool ok = q.ea0.allFinite() && q.ea1.allFinite() && q.eb0.allFinite() &&
                  q.eb1.allFinite() && finite(q.edge_a) && finite(q.edge_b);
  const Interval S = parameter_of(result.ccd, ok);
  const DVec a0 = position(q.edge_a, q.ea0, q.edge_a.linear_end[0], S),
             a1 = position(q.edge_a, q.ea1, q.edge_a.linear_end[1], S),
             b0 = position(q.edge_b, q.eb0, q.edge_b.linear_end[0], S),
             b1 = position(q.edge_b, q.eb1, q.edge_b.linear_end[1], S);
  if (min_separation > 0.0)
    return pipeline::contact::edge_edge_separation_from(values(a0), values(a1), values(b0),
                                                        values(b1), result.ccd.starts_within, 0);
  return pipeline::contact::edge_edge_from(
      values(a0), values(a1), values(b0), values(b1), result.ccd.starts_within, 0, [&] {
        // det[a1 - a0, b0 - a0, b1 - a0], as the linear edge-edge determinant.
        const Dual g = predicates::dot(predicates::cross(a1 - a0, b0 - a0), b1 - a0);
        return pipeline::contact::side_just_before(g.d);
      });
}

}  // namespace exactccd
