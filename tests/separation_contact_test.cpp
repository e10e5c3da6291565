// The contact geometry with a minimum separation where the closest points are not interior: a
// vertex passing beside a triangle (its closest point on a side or at a corner), edges passing
// near each other's ends (an end against an edge, or two ends), and points against segments
// and points. Against exact rational closest points (Ericson's region tests, in rationals: they
// share no code with the library) at rational times of the TOI enclosure: the parameters, the
// closest point on the face or edge b, and the unit normal from it towards the vertex or edge a.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "tests/rational_geometry.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;

RationalVector vec(const RationalPoint& p) { return {p.x, p.y, p.z}; }
RationalVector add(const RationalVector& a, const RationalVector& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
RationalVector sub(const RationalVector& a, const RationalVector& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
RationalVector scale(const mpq_class& k, const RationalVector& a) {
  return {k * a.x, k * a.y, k * a.z};
}

/// The closest point of the triangle (a, b, c) to p and its barycentric coordinates, exactly
/// (Ericson, Real-Time Collision Detection, 5.1.5).
RationalVector closest_on_triangle(const RationalVector& p, const RationalVector& a,
                                   const RationalVector& b, const RationalVector& c,
                                   std::array<mpq_class, 3>* bary) {
  const RationalVector ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const mpq_class d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return *bary = {1, 0, 0}, a;
  const RationalVector bp = sub(p, b);
  const mpq_class d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return *bary = {0, 1, 0}, b;
  const mpq_class vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const mpq_class v = d1 / (d1 - d3);
    *bary = {1 - v, v, 0};
    return add(a, scale(v, ab));
  }
  const RationalVector cp = sub(p, c);
  const mpq_class d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return *bary = {0, 0, 1}, c;
  const mpq_class vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const mpq_class w = d2 / (d2 - d6);
    *bary = {1 - w, 0, w};
    return add(a, scale(w, ac));
  }
  const mpq_class va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const mpq_class w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    *bary = {0, 1 - w, w};
    return add(b, scale(w, sub(c, b)));
  }
  const mpq_class denom = va + vb + vc, v = vb / denom, w = vc / denom;
  *bary = {1 - v - w, v, w};
  return add(a, add(scale(v, ab), scale(w, ac)));
}

/// The closest points of the segments [p1, q1] and [p2, q2] (neither a point), their
/// parameters s (on the first) and u, exactly (Ericson 5.1.9).
void closest_on_segments(const RationalVector& p1, const RationalVector& q1,
                         const RationalVector& p2, const RationalVector& q2, mpq_class* s,
                         mpq_class* u) {
  const RationalVector d1 = sub(q1, p1), d2 = sub(q2, p2), r = sub(p1, p2);
  const mpq_class a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r),
                  b = dot(d1, d2), denom = a * e - b * b;
  *s = denom != 0 ? clamp01((b * f - c * e) / denom) : mpq_class(0);
  *u = (b * *s + f) / e;
  if (*u < 0) {
    *u = 0;
    *s = clamp01(-c / a);
  } else if (*u > 1) {
    *u = 1;
    *s = clamp01((b - c) / a);
  }
}

/// Every enclosure of g holds the exact value at t: parameters, the closest point on b, the
/// unit vector from it to the closest point on a.
void expect_holds(const ContactGeometry& g, const std::array<mpq_class, 3>& param,
                  const RationalVector& on_a, const RationalVector& on_b) {
  for (int i = 0; i < g.parameter_count; ++i)
    EXPECT_TRUE(contains(g.parameters[i], param[i])) << "parameter " << i;
  EXPECT_TRUE(contains(g.point[0], on_b.x) && contains(g.point[1], on_b.y) &&
              contains(g.point[2], on_b.z));
  const RationalVector d = sub(on_a, on_b);
  const mpq_class nn = dot(d, d);
  ASSERT_GT(nn, 0);
  EXPECT_TRUE(unit_component_in(d.x, nn, g.normal[0]) && unit_component_in(d.y, nn, g.normal[1]) &&
              unit_component_in(d.z, nn, g.normal[2]));
}

std::array<mpq_class, 3> times_of(const CcdResult& r) {
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  return {lo, hi, mpq_class((lo + hi) / 2)};
}

TEST(SeparationContact, AVertexBesideATriangleSideOrCorner) {
  std::mt19937_64 rng(test_seed("separation_contact_vf"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int sides = 0, corners = 0;
  for (int n = 0; n < 300; ++n) {
    const auto v = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
    const Vector3d a = 0.02 * v(), b = Vector3d(1, 0, 0) + 0.02 * v(),
                   c = Vector3d(0, 1, 0) + 0.02 * v();
    // A point of the plane just outside the triangle (within 0.08 of it): beyond a side
    // (n % 3 < 2) or near a corner.
    const double out = 0.01 + 0.07 * (0.5 + 0.5 * u(rng)), along = 0.5 + 0.45 * u(rng);
    const Vector3d tip[3] = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
    const Vector3d outward[3] = {Vector3d(0, -1, 0), Vector3d(1, 1, 0).normalized(),
                                 Vector3d(-1, 0, 0)};  // beyond y = 0, x + y = 1, x = 0
    const int k = n % 3;
    const Vector3d beside =
        n % 3 < 2 ? Vector3d(tip[k] + along * (tip[(k + 1) % 3] - tip[k]) + out * outward[k])
                  : Vector3d(tip[n % 9 / 3] + out * Vector3d(u(rng), u(rng), 0).normalized());
    const Vector3d p0 = beside + Vector3d(0.02 * u(rng), 0.02 * u(rng), 0.5),
                   p1 = beside + Vector3d(0.02 * u(rng), 0.02 * u(rng), -0.5);
    const VertexFaceQuery q{p0, a, b, c, p1, a, b, c};
    CcdOptions o;
    o.min_separation = 0.1;
    const CcdResult r = vertex_face_ccd(q, o);
    if (!r.collides || r.starts_within) continue;
    const ContactGeometry g = contact_geometry(q, r, 0.1);
    if (g.kind != ContactKind::point) continue;
    ASSERT_TRUE(g.normal_oriented);
    for (const mpq_class& t : times_of(r)) {
      const RationalQuery rq = rational_query_of(q);
      std::array<mpq_class, 3> bary;
      const RationalVector P = vec(position_at(rq, 0, t));
      const RationalVector Q = closest_on_triangle(P, vec(position_at(rq, 1, t)),
                                                   vec(position_at(rq, 2, t)),
                                                   vec(position_at(rq, 3, t)), &bary);
      expect_holds(g, bary, P, Q);
    }
    const int zeros = (g.parameters[0].hi == 0) + (g.parameters[1].hi == 0) +
                      (g.parameters[2].hi == 0);
    sides += zeros == 1;
    corners += zeros == 2;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(sides, 30);
  EXPECT_GT(corners, 10);
}

TEST(SeparationContact, EdgesNearEachOthersEnds) {
  std::mt19937_64 rng(test_seed("separation_contact_ee"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int end_edge = 0, end_end = 0;
  for (int n = 0; n < 300; ++n) {
    // Edge a along x at height 0.5 falling to -0.5; edge b in z = 0 beyond a's end x = 1.
    const Vector3d a0(-1 + 0.02 * u(rng), 0.02 * u(rng), 0.5), a1(1 + 0.02 * u(rng), 0.02 * u(rng), 0.5);
    const Vector3d b0(1.04 + 0.05 * u(rng), 0.6 * u(rng), 0.02 * u(rng));
    const Vector3d b1 = b0 + Vector3d(0.5 * u(rng), 1 + 0.5 * u(rng), 0.02 * u(rng));
    const Vector3d drop(0.02 * u(rng), 0.02 * u(rng), -1);
    const EdgeEdgeQuery q{a0, a1, b0, b1, a0 + drop, a1 + drop, b0, b1};
    CcdOptions o;
    o.min_separation = 0.1;
    const CcdResult r = edge_edge_ccd(q, o);
    if (!r.collides || r.starts_within) continue;
    const ContactGeometry g = contact_geometry(q, r, 0.1);
    if (g.kind != ContactKind::point) continue;
    for (const mpq_class& t : times_of(r)) {
      const RationalQuery rq = rational_query_of(q);
      const RationalVector A0 = vec(position_at(rq, 0, t)), A1 = vec(position_at(rq, 1, t)),
                           B0 = vec(position_at(rq, 2, t)), B1 = vec(position_at(rq, 3, t));
      mpq_class s, w;
      closest_on_segments(A0, A1, B0, B1, &s, &w);
      expect_holds(g, {s, w, 0}, add(A0, scale(s, sub(A1, A0))), add(B0, scale(w, sub(B1, B0))));
    }
    const bool a_end = g.parameters[0].lo == g.parameters[0].hi;
    const bool b_end = g.parameters[1].lo == g.parameters[1].hi;
    end_edge += a_end != b_end;
    end_end += a_end && b_end;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(end_edge, 30);
  EXPECT_GT(end_end, 10);
}

TEST(SeparationContact, PointsAgainstSegmentsAndPoints) {
  std::mt19937_64 rng(test_seed("separation_contact_points"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int resolved = 0;
  for (int n = 0; n < 200; ++n) {
    const Vector3d e0(-1, 0.02 * u(rng), 0), e1(1, 0.02 * u(rng), 0);
    const Vector3d p0(1.5 * u(rng), 0.08 * u(rng), 0.5), p1 = p0 + Vector3d(0.1 * u(rng), 0, -1);
    const bool point_point = n % 2 == 1;
    const Vector3d b1 = point_point ? e0 : e1;  // edge b: [e0, e1], or the point e0
    const EdgeEdgeQuery q{p0, p0, e0, b1, p1, p1, e0, b1};
    CcdOptions o;
    o.min_separation = point_point ? 1.2 : 0.1;
    const CcdResult r = edge_edge_ccd(q, o);
    if (!r.collides || r.starts_within) continue;
    const ContactGeometry g = contact_geometry(q, r, o.min_separation);
    ASSERT_EQ(g.kind, ContactKind::point) << n;
    ++resolved;
    EXPECT_EQ(g.parameters[0].lo, 0.0);
    EXPECT_EQ(g.parameters[0].hi, 0.0);
    for (const mpq_class& t : times_of(r)) {
      const RationalQuery rq = rational_query_of(q);
      const RationalVector P = vec(position_at(rq, 0, t)), B0 = vec(position_at(rq, 2, t)),
                           B1 = vec(position_at(rq, 3, t));
      mpq_class lambda = 0;
      const RationalVector d = sub(B1, B0);
      if (dot(d, d) > 0) lambda = clamp01(dot(sub(P, B0), d) / dot(d, d));
      expect_holds(g, {0, lambda, 0}, P, add(B0, scale(lambda, d)));
    }
  }
  EXPECT_GT(resolved, 60);
}

/// Closest points that are not unique are named by their exact kind: parallel edges (a segment
/// of closest pairs) and a degenerate triangle; their enclosures stay the trivial ones.
TEST(SeparationContact, ParallelEdgesAndDegenerateTrianglesAreNamed) {
  CcdOptions o;
  o.min_separation = 0.1;
  const EdgeEdgeQuery parallel{Vector3d(0, 0, 1), Vector3d(2, 0, 1), Vector3d(1, 0, 0),
                               Vector3d(3, 0, 0), Vector3d(0, 0, -1), Vector3d(2, 0, -1),
                               Vector3d(1, 0, 0), Vector3d(3, 0, 0)};
  const CcdResult r = edge_edge_ccd(parallel, o);
  ASSERT_TRUE(r.collides);
  const ContactGeometry g = contact_geometry(parallel, r, 0.1);
  EXPECT_EQ(g.kind, ContactKind::parallel_edges);
  EXPECT_FALSE(g.normal_oriented);
  EXPECT_LE(g.point[0].lo, 1.0);  // the closest points on b: x in [1, 2]
  EXPECT_GE(g.point[0].hi, 2.0);
  const VertexFaceQuery flat{Vector3d(0.5, 0.01, 1), Vector3d(0, 0, 0), Vector3d(1, 0, 0),
                             Vector3d(0.25, 0, 0), Vector3d(0.5, 0.01, -1), Vector3d(0, 0, 0),
                             Vector3d(1, 0, 0), Vector3d(0.25, 0, 0)};
  const CcdResult f = vertex_face_ccd(flat, o);
  ASSERT_TRUE(f.collides);
  EXPECT_EQ(contact_geometry(flat, f, 0.1).kind, ContactKind::degenerate_triangle);
}

}  // namespace
}  // namespace exactccd::test
