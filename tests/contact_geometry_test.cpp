// The contact geometry at t* (exactccd/contact.hpp, proofs/contact_geometry.md#enclosures),
// against exact rational evaluation, which shares no code with the library: at rational times
// t of [toi_lo, toi_hi] (both ends and the midpoint) the barycentric coordinates and segment
// parameters, clamped to [0, 1], lie in their enclosures (this holds for every t of the
// enclosure of t*, t* included: proofs/contact_geometry.md#test-criterion); the normal's
// direction at t lies in the normal's box; an oriented normal points to the side that CGAL's
// orientation gives at toi_lo (where toi_lo < t*); the vertex at t lies in the point's box.
// Queries: the sample queries (every colliding one in the subset), constructed contacts with a
// known normal, degenerate ones, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "tests/rational_geometry.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;

/// The normal's unoriented direction at t (vertex-face (b - a) x (c - a), edge-edge
/// (a1 - a0) x (b1 - b0)), exactly.
RationalVector direction_at(const RationalQuery& q, const mpq_class& t) {
  std::array<RationalPoint, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = position_at(q, i, t);
  if (q.type == QueryType::vertex_face) return cross(minus(x[2], x[1]), minus(x[3], x[1]));
  return cross(minus(x[1], x[0]), minus(x[3], x[2]));
}

/// The parameters at t, exactly (the projection's barycentric coordinates; the lines' closest
/// parameters), or false where the direction vanishes.
bool parameters_at(const RationalQuery& q, const mpq_class& t, std::array<mpq_class, 3>* out) {
  std::array<RationalPoint, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = position_at(q, i, t);
  const RationalVector n = direction_at(q, t);
  const mpq_class nn = dot(n, n);
  if (nn == 0) return false;
  if (q.type == QueryType::vertex_face) {
    (*out)[0] = dot(n, cross(minus(x[2], x[0]), minus(x[3], x[0]))) / nn;
    (*out)[1] = dot(n, cross(minus(x[3], x[0]), minus(x[1], x[0]))) / nn;
    (*out)[2] = dot(n, cross(minus(x[1], x[0]), minus(x[2], x[0]))) / nn;
  } else {
    const RationalVector w = minus(x[2], x[0]), da = minus(x[1], x[0]), db = minus(x[3], x[2]);
    (*out)[0] = dot(cross(w, db), n) / nn;
    (*out)[1] = dot(cross(w, da), n) / nn;
  }
  return true;
}

ContactGeometry geometry_of(const RationalQuery& q, const CcdResult& r) {
  std::array<Vector3d, 8> v;
  for (int i = 0; i < 8; ++i) v[i] = to_vector(q.points[i]);
  if (q.type == QueryType::vertex_face)
    return contact_geometry(VertexFaceQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, r);
  return contact_geometry(EdgeEdgeQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, r);
}

/// Every promise of `g` for the colliding query q with answer r, checked exactly.
void expect_enclosures(const RationalQuery& q, const CcdResult& r, const ContactGeometry& g) {
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  const std::vector<mpq_class> times =
      r.starts_within ? std::vector<mpq_class>{mpq_class(0)}
                      : std::vector<mpq_class>{lo, hi, mpq_class((lo + hi) / 2)};
  EXPECT_EQ(g.parameter_count, q.type == QueryType::vertex_face ? 3 : 2);
  for (const mpq_class& t : times) {
    SCOPED_TRACE("t = " + std::to_string(t.get_d()));
    if (q.type == QueryType::vertex_face) {  // the vertex is the contact point
      const RationalPoint p = position_at(q, 0, t);
      EXPECT_TRUE(contains(g.point[0], p.x) && contains(g.point[1], p.y) &&
                  contains(g.point[2], p.z));
    }
    if (g.kind == ContactKind::unresolved || g.kind == ContactKind::degenerate_triangle ||
        g.kind == ContactKind::parallel_edges)
      continue;
    std::array<mpq_class, 3> param;
    if (g.kind == ContactKind::coplanar && !parameters_at(q, t, &param)) continue;
    ASSERT_TRUE(parameters_at(q, t, &param)) << "a resolved kind with a vanishing direction";
    for (int i = 0; i < g.parameter_count; ++i)
      EXPECT_TRUE(contains(g.parameters[i], clamp01(param[i])))
          << "parameter " << i << " " << param[i].get_d() << " not in [" << g.parameters[i].lo
          << ", " << g.parameters[i].hi << "]";
    RationalVector n = direction_at(q, t);
    const mpq_class nn = dot(n, n);
    if (g.normal_oriented) {
      // The side just before t*: CGAL's orientation at toi_lo, when toi_lo < t* (there the
      // determinant is not 0; the enclosure's monotone determinant has this sign on [lo, t*)).
      const int side = cgal_coplanarity_sign_at(q, lo);
      if (side != 0 && !r.starts_within) {
        if (side < 0) n = {-n.x, -n.y, -n.z};
        EXPECT_TRUE(unit_component_in(n.x, nn, g.normal[0]) &&
                    unit_component_in(n.y, nn, g.normal[1]) &&
                    unit_component_in(n.z, nn, g.normal[2]))
            << "oriented normal";
      }
    } else if (g.kind == ContactKind::at_start) {
      EXPECT_TRUE(unit_component_in(n.x, nn, g.normal[0]) &&
                  unit_component_in(n.y, nn, g.normal[1]) &&
                  unit_component_in(n.z, nn, g.normal[2]))
          << "unoriented normal";
    }
  }
}

TEST(ContactGeometry, EnclosesTheExactGeometryOnTheSampleQueries) {
  int colliding = 0, resolved = 0;
  for (const SampleQuery& s : scaled_sample_queries()) {
    if (!s.truth || !all_coordinates_are_doubles(s.query)) continue;
    const CcdResult r = double_api_ccd(s.query);
    ASSERT_TRUE(r.collides) << s.file << ":" << s.line;
    SCOPED_TRACE(s.file + ":" + std::to_string(s.line));
    const ContactGeometry g = geometry_of(s.query, r);
    ++colliding;
    resolved += g.kind == ContactKind::point;
    expect_enclosures(s.query, r, g);
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GE(colliding * subset_stride(), 100u);  // the whole set at EXACTCCD_TEST_SCALE 1
  // The sample queries are mostly degenerate by design; still, many resolve to a point.
  EXPECT_GT(resolved, colliding / 10);
}

/// A vertex (or a segment) crossing a triangle (or a segment) at a random time: every
/// enclosure against exact evaluation, and the normal's side against the motion.
TEST(ContactGeometry, EnclosesTheExactGeometryOnCrossingQueries) {
  std::mt19937_64 rng(test_seed("contact_geometry"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int resolved = 0;
  for (int n = 0; n < 400; ++n) {
    const bool vf = n % 2 == 0;
    std::array<Vector3d, 8> x;
    const auto v = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
    if (vf) {
      x = {Vector3d(0.2, 0.2, 0.5) + 0.1 * v(), Vector3d(0, 0, 0) + 0.1 * v(),
           Vector3d(1, 0, 0) + 0.1 * v(), Vector3d(0, 1, 0) + 0.1 * v(),
           Vector3d(0.3, 0.2, -0.5) + 0.1 * v(), Vector3d(0, 0, 0) + 0.1 * v(),
           Vector3d(1, 0, 0) + 0.1 * v(), Vector3d(0, 1, 0) + 0.1 * v()};
    } else {
      x = {Vector3d(-1, 0, 0.5) + 0.1 * v(), Vector3d(1, 0, 0.5) + 0.1 * v(),
           Vector3d(0, -1, 0) + 0.1 * v(), Vector3d(0, 1, 0) + 0.1 * v(),
           Vector3d(-1, 0, -0.5) + 0.1 * v(), Vector3d(1, 0, -0.5) + 0.1 * v(),
           Vector3d(0, -1, 0) + 0.1 * v(), Vector3d(0, 1, 0) + 0.1 * v()};
    }
    if (n % 4 >= 2)  // the other direction: from below
      for (auto& p : x) p.z() = -p.z();
    RationalQuery q{vf ? QueryType::vertex_face : QueryType::edge_edge, {}};
    for (int i = 0; i < 8; ++i)
      q.points[i] = {mpq_class(x[i].x()), mpq_class(x[i].y()), mpq_class(x[i].z())};
    const CcdResult r = double_api_ccd(q);
    if (!r.collides) continue;
    SCOPED_TRACE(describe(q));
    const ContactGeometry g = geometry_of(q, r);
    expect_enclosures(q, r, g);
    if (g.kind == ContactKind::point) {
      ++resolved;
      // From above the normal points up (towards where the vertex / edge a came from).
      const double up = n % 4 >= 2 ? -1.0 : 1.0;
      EXPECT_GT(g.normal[2].lo * up, 0.5);
      // Tight where well conditioned: a few units in the last place.
      for (int i = 0; i < g.parameter_count; ++i)
        EXPECT_LT(g.parameters[i].hi - g.parameters[i].lo, 1e-13);
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(resolved, 300);
}

TEST(ContactGeometry, KnownContacts) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // The vertex falls on (0.25, 0.5) at t = 1/2: barycentric (0.25, 0.25, 0.5), normal +z.
  const VertexFaceQuery fall{Vector3d(0.25, 0.5, 1), a, b, c, Vector3d(0.25, 0.5, -1), a, b, c};
  const CcdResult r = vertex_face_ccd(fall);
  ASSERT_TRUE(r.collides);
  ContactGeometry g = contact_geometry(fall, r);
  EXPECT_EQ(g.kind, ContactKind::point);
  EXPECT_TRUE(g.normal_oriented);
  EXPECT_EQ(g.parameters[0].lo, 0.25);
  EXPECT_EQ(g.parameters[0].hi, 0.25);
  EXPECT_EQ(g.parameters[2].lo, 0.5);
  EXPECT_EQ(g.normal[2].lo, 1.0);
  EXPECT_EQ(g.point[2].lo, 0.0);
  EXPECT_EQ(g.point[2].hi, 0.0);
  // The same from below: normal -z.
  const VertexFaceQuery rise{Vector3d(0.25, 0.5, -1), a, b, c, Vector3d(0.25, 0.5, 1), a, b, c};
  g = contact_geometry(rise, vertex_face_ccd(rise));
  EXPECT_EQ(g.normal[2].hi, -1.0);
  // Edge a falls across edge b at t = 1/2: parameters (0.5, 0.25), normal +z (a x b = +z, and a
  // comes from above).
  const EdgeEdgeQuery cross_fall{Vector3d(-1, 0, 1), Vector3d(1, 0, 1),  Vector3d(0, -0.5, 0),
                                 Vector3d(0, 1.5, 0), Vector3d(-1, 0, -1), Vector3d(1, 0, -1),
                                 Vector3d(0, -0.5, 0), Vector3d(0, 1.5, 0)};
  g = contact_geometry(cross_fall, edge_edge_ccd(cross_fall));
  EXPECT_EQ(g.kind, ContactKind::point);
  EXPECT_EQ(g.parameters[0].lo, 0.5);
  EXPECT_EQ(g.parameters[1].hi, 0.25);
  EXPECT_EQ(g.normal[2].lo, 1.0);
  EXPECT_EQ(g.point[0].lo, 0.0);
  EXPECT_EQ(g.point[1].hi, 0.0);
}

TEST(ContactGeometry, PointKinds) {
  // Point-point: p from (0,0,0) to (4,0,0), q at (1,0,0): meet at 1/4, normal from q to p
  // before contact = -x.
  const Vector3d p0(0, 0, 0), p1(4, 0, 0), q(1, 0, 0);
  const PointPointQuery pp{p0, q, p1, q};
  ContactGeometry g = contact_geometry(EdgeEdgeQuery{p0, p0, q, q, p1, p1, q, q},
                                       point_point_ccd(pp));
  EXPECT_EQ(g.kind, ContactKind::point);
  EXPECT_EQ(g.normal[0].lo, -1.0);
  EXPECT_EQ(g.normal[0].hi, -1.0);
  EXPECT_EQ(g.point[0].lo, 1.0);
  // Point-edge in the plane: p falls from y = 1 onto [(0,0), (1,0)] at x = 0.25: parameter
  // 0.25 on the segment, normal +y.
  const Vector3d e0(0, 0, 0), e1(1, 0, 0), pa(0.25, 1, 0), pb(0.25, -1, 0);
  g = contact_geometry(EdgeEdgeQuery{pa, pa, e0, e1, pb, pb, e0, e1},
                       point_edge_ccd(PointEdgeQuery{pa, e0, e1, pb, e0, e1}));
  EXPECT_EQ(g.kind, ContactKind::point);
  EXPECT_EQ(g.parameters[0].hi, 0.0);
  EXPECT_EQ(g.parameters[1].lo, 0.25);
  EXPECT_EQ(g.normal[1].lo, 1.0);
  // The point as edge b: the normal points from b (the point) to a (the segment): -y.
  g = contact_geometry(EdgeEdgeQuery{e0, e1, pa, pa, e0, e1, pb, pb},
                       edge_edge_ccd(EdgeEdgeQuery{e0, e1, pa, pa, e0, e1, pb, pb}));
  EXPECT_EQ(g.kind, ContactKind::point);
  EXPECT_EQ(g.parameters[0].lo, 0.25);
  EXPECT_EQ(g.normal[1].hi, -1.0);
  // In 3D the point-edge normal is not defined by the rules: unresolved, parameters still.
  const Vector3d pc(0.25, 1, 1), pd(0.25, -1, -1);
  g = contact_geometry(EdgeEdgeQuery{pc, pc, e0, e1, pd, pd, e0, e1},
                       point_edge_ccd(PointEdgeQuery{pc, e0, e1, pd, e0, e1}));
  EXPECT_EQ(g.kind, ContactKind::unresolved);
  EXPECT_FALSE(g.normal_oriented);
  EXPECT_EQ(g.parameters[1].lo, 0.25);
}

TEST(ContactGeometry, DegenerateAndStartingContacts) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Touching at the start: at_start, the unoriented normal (b - a) x (c - a) = +z.
  const VertexFaceQuery start{Vector3d(0.25, 0.25, 0), a, b, c, Vector3d(0.25, 0.25, -1), a, b, c};
  ContactGeometry g = contact_geometry(start, vertex_face_ccd(start));
  EXPECT_EQ(g.kind, ContactKind::at_start);
  EXPECT_FALSE(g.normal_oriented);
  EXPECT_EQ(g.normal[2].lo, 1.0);
  EXPECT_EQ(g.parameters[1].lo, 0.25);
  // A triangle degenerate throughout (a segment): degenerate_triangle, the vertex the point.
  const Vector3d d(2, 0, 0);
  const VertexFaceQuery flat{Vector3d(0.5, 1, 0), a, b, d, Vector3d(0.5, -1, 0), a, b, d};
  g = contact_geometry(flat, vertex_face_ccd(flat));
  EXPECT_EQ(g.kind, ContactKind::degenerate_triangle);
  EXPECT_EQ(g.point[0].lo, 0.5);
  EXPECT_EQ(g.point[1].lo, 0.0);
  // Overlapping parallel edges sliding along each other: parallel_edges, the point in both
  // hulls.
  const EdgeEdgeQuery slide{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0),
                            Vector3d(3, 0, 0), Vector3d(2, 0, 0), Vector3d(3, 0, 0),
                            Vector3d(0.5, 0, 0), Vector3d(1.5, 0, 0)};
  const CcdResult r = edge_edge_ccd(slide);
  ASSERT_TRUE(r.collides);
  g = contact_geometry(slide, r);
  EXPECT_EQ(g.kind, ContactKind::parallel_edges);
  EXPECT_LE(g.point[1].lo, 0.0);
  EXPECT_GE(g.point[1].hi, 0.0);
  // A vertex sliding in the triangle's plane into it (coplanar throughout): coplanar. It enters
  // across the side (b, c), x + y = 1, at t = 1/2: barycentric coordinates (0, 1/2, 1/2).
  const VertexFaceQuery sliding{Vector3d(1, 1, 0), a, b, c, Vector3d(0, 0, 0), a, b, c};
  const CcdResult s = vertex_face_ccd(sliding);
  ASSERT_TRUE(s.collides);
  EXPECT_EQ(s.toi_lo, 0.5);
  g = contact_geometry(sliding, s);
  EXPECT_EQ(g.kind, ContactKind::coplanar);
  EXPECT_FALSE(g.normal_oriented);
  EXPECT_EQ(g.normal[2].lo, 1.0);  // the unoriented direction (b - a) x (c - a) = +z
  EXPECT_EQ(g.parameters[0].lo, 0.0);
  EXPECT_EQ(g.parameters[1].lo, 0.5);
  EXPECT_EQ(g.parameters[2].hi, 0.5);
  // Nearly degenerate but not throughout: a triangle that is a segment only at t = 1/2.
  const VertexFaceQuery pinch{Vector3d(0.25, 0.25, 1), a, b, Vector3d(0, 1, 0),
                              Vector3d(0.25, 0.25, -1), a, b, Vector3d(0, -1, 0)};
  const CcdResult pr = vertex_face_ccd(pinch);
  if (pr.collides) {
    const ContactKind k = contact_geometry(pinch, pr).kind;
    EXPECT_NE(k, ContactKind::degenerate_triangle);
    EXPECT_NE(k, ContactKind::coplanar);
  }
}

TEST(ContactGeometry, HugeAndTinyCoordinatesAreScaledExactly) {
  for (const double scale : {0x1p-1000, 0x1p+1000}) {
    const Vector3d a(0, 0, 0), b = Vector3d(1, 0, 0) * scale, c = Vector3d(0, 1, 0) * scale;
    const VertexFaceQuery fall{Vector3d(0.25, 0.5, 1) * scale, a, b, c,
                               Vector3d(0.25, 0.5, -1) * scale, a, b, c};
    const ContactGeometry g = contact_geometry(fall, vertex_face_ccd(fall));
    EXPECT_EQ(g.kind, ContactKind::point);
    EXPECT_EQ(g.parameters[2].lo, 0.5);
    EXPECT_EQ(g.parameters[2].hi, 0.5);
    EXPECT_EQ(g.normal[2].lo, 1.0);
    EXPECT_EQ(g.point[1].lo, 0.5 * scale);
  }
}

/// The exact position at the rational s of the body point at x0 under motion m.
RationalPoint rigid_position(const RigidMotion& m, const Vector3d& x0, const mpq_class& s) {
  const auto q = [](double x) { return mpq_class(x); };
  const mpq_class v[3] = {s * q(m.cayley.x()), s * q(m.cayley.y()), s * q(m.cayley.z())};
  const mpq_class r[3] = {q(x0.x()) - q(m.pivot.x()), q(x0.y()) - q(m.pivot.y()),
                          q(x0.z()) - q(m.pivot.z())};
  const mpq_class vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const mpq_class vr = v[0] * r[0] + v[1] * r[1] + v[2] * r[2];
  const mpq_class w[3] = {v[1] * r[2] - v[2] * r[1], v[2] * r[0] - v[0] * r[2],
                          v[0] * r[1] - v[1] * r[0]};
  const double c[3] = {m.pivot.x(), m.pivot.y(), m.pivot.z()};
  const double d[3] = {m.translation.x(), m.translation.y(), m.translation.z()};
  mpq_class out[3];
  for (int i = 0; i < 3; ++i)
    out[i] = q(c[i]) + s * q(d[i]) + ((1 - vv) * r[i] + 2 * v[i] * vr + 2 * w[i]) / (1 + vv);
  return {out[0], out[1], out[2]};
}

// A triangle turning about an axis through a vertex falling onto it (and a rotating edge
// against a static one): at rational s of the enclosure, the exact positions of the rational
// rigid motion give barycentric coordinates / edge parameters (clamped) inside the
// enclosures, the unit normal inside the normal's box, oriented as the exact determinant's
// sign at toi_lo (where toi_lo < s*).
TEST(ContactGeometry, RigidQueriesEncloseTheExactGeometry) {
  std::mt19937_64 rng(test_seed("contact_geometry_rigid"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int resolved = 0;
  for (int n = 0; n < 120; ++n) {
    const bool vf = n % 2 == 0;
    RigidMotion turn;
    turn.pivot = Vector3d(0.3 * u(rng), 0.3 * u(rng), 0.0);
    turn.cayley = Vector3d(0.2 * u(rng), 0.2 * u(rng), 0.5 * u(rng));
    turn.translation = Vector3d(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
    RigidMotion fall;
    fall.translation = Vector3d(0.1 * u(rng), 0.1 * u(rng), n % 4 < 2 ? -1.0 : 1.0);
    const double z = n % 4 < 2 ? 0.5 : -0.5;
    std::array<Vector3d, 4> x;  // the moving primitive first (vertex / edge a)
    RigidCcdResult r;
    ContactGeometry g;
    if (vf) {
      x = {Vector3d(0.2 + 0.1 * u(rng), 0.2 + 0.1 * u(rng), z), Vector3d(-1, -1, 0),
           Vector3d(2, -1, 0), Vector3d(-1, 2, 0)};
      const RigidVertexFaceQuery q{x[0], x[1], x[2], x[3], SideMotion::of(fall),
                                   SideMotion::of(turn)};
      r = vertex_face_ccd(q);
      if (!r.ccd.collides) continue;
      g = contact_geometry(q, r);
    } else {
      x = {Vector3d(-1, 0.1 * u(rng), z), Vector3d(1, 0.1 * u(rng), z),
           Vector3d(0.1 * u(rng), -1, 0), Vector3d(0.1 * u(rng), 1, 0)};
      const RigidEdgeEdgeQuery q{x[0], x[1], x[2], x[3], SideMotion::of(fall),
                                 SideMotion::of(turn)};
      r = edge_edge_ccd(q);
      if (!r.ccd.collides) continue;
      g = contact_geometry(q, r);
    }
    SCOPED_TRACE("n " + std::to_string(n));
    ASSERT_EQ(g.kind, ContactKind::point);
    ++resolved;
    const mpq_class lo(r.ccd.toi_lo), hi(r.ccd.toi_hi);
    const auto positions = [&](const mpq_class& s) {
      RationalQuery q{vf ? QueryType::vertex_face : QueryType::edge_edge, {}};
      const int moving = vf ? 1 : 2;  // the first `moving` points fall, the others turn
      for (int i = 0; i < 4; ++i) {
        q.points[i] = rigid_position(i < moving ? fall : turn, x[i], s);
        q.points[4 + i] = q.points[i];  // held: position_at(q, i, any t) is this point
      }
      return q;
    };
    for (const mpq_class& s : {lo, hi, mpq_class((lo + hi) / 2)}) {
      const RationalQuery at = positions(s);
      std::array<mpq_class, 3> param;
      ASSERT_TRUE(parameters_at(at, 0, &param));
      for (int i = 0; i < g.parameter_count; ++i)
        EXPECT_TRUE(contains(g.parameters[i], clamp01(param[i]))) << "parameter " << i;
      RationalVector dir = direction_at(at, 0);
      const mpq_class nn = dot(dir, dir);
      const int side = cgal_coplanarity_sign_at(positions(lo), 0);
      if (side != 0) {
        if (side < 0) dir = {-dir.x, -dir.y, -dir.z};
        EXPECT_TRUE(unit_component_in(dir.x, nn, g.normal[0]) &&
                    unit_component_in(dir.y, nn, g.normal[1]) &&
                    unit_component_in(dir.z, nn, g.normal[2]));
      }
    }
    // Coming from above (z > 0), the normal points up.
    EXPECT_GT(g.normal[2].lo * (z > 0 ? 1 : -1), 0.0);
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(resolved, 60);
}

// Rigid queries with a minimum separation: the closest points at s*, against the exact
// positions of the rational rigid motion at rational s of the enclosure.
TEST(ContactGeometry, RigidMinimumSeparationEnclosesTheClosestPoints) {
  std::mt19937_64 rng(test_seed("contact_geometry_rigid_separation"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int resolved = 0;
  for (int n = 0; n < 80; ++n) {
    const bool vf = n % 2 == 0;
    const double delta = n % 4 < 2 ? 0x1p-8 : 0.05;
    RigidMotion turn;
    turn.pivot = Vector3d(0.3 * u(rng), 0.3 * u(rng), 0.0);
    turn.cayley = Vector3d(0.05 * u(rng), 0.05 * u(rng), 0.5 * u(rng));
    RigidMotion fall;
    fall.translation = Vector3d(0.1 * u(rng), 0.1 * u(rng), -1.0);
    std::array<Vector3d, 4> x;
    RigidCcdResult r;
    ContactGeometry g;
    CcdOptions o;
    o.min_separation = delta;
    if (vf) {
      x = {Vector3d(0.2 + 0.1 * u(rng), 0.2 + 0.1 * u(rng), 0.5), Vector3d(-1, -1, 0),
           Vector3d(2, -1, 0), Vector3d(-1, 2, 0)};
      const RigidVertexFaceQuery q{x[0], x[1], x[2], x[3], SideMotion::of(fall),
                                   SideMotion::of(turn)};
      r = vertex_face_ccd(q, o);
      if (!r.ccd.collides || r.ccd.starts_within) continue;
      g = contact_geometry(q, r, delta);
    } else {
      x = {Vector3d(-1, 0.1 * u(rng), 0.5), Vector3d(1, 0.1 * u(rng), 0.5),
           Vector3d(0.1 * u(rng), -1, 0), Vector3d(0.1 * u(rng), 1, 0)};
      const RigidEdgeEdgeQuery q{x[0], x[1], x[2], x[3], SideMotion::of(fall),
                                 SideMotion::of(turn)};
      r = edge_edge_ccd(q, o);
      if (!r.ccd.collides || r.ccd.starts_within) continue;
      g = contact_geometry(q, r, delta);
    }
    SCOPED_TRACE("n " + std::to_string(n));
    if (g.kind != ContactKind::point) continue;
    ++resolved;
    const mpq_class lo(r.ccd.toi_lo), hi(r.ccd.toi_hi);
    for (const mpq_class& s : {lo, hi}) {
      RationalQuery at{vf ? QueryType::vertex_face : QueryType::edge_edge, {}};
      const int moving = vf ? 1 : 2;
      for (int i = 0; i < 4; ++i) {
        at.points[i] = rigid_position(i < moving ? fall : turn, x[i], s);
        at.points[4 + i] = at.points[i];
      }
      std::array<mpq_class, 3> param;
      ASSERT_TRUE(parameters_at(at, 0, &param));
      for (int i = 0; i < g.parameter_count; ++i)
        EXPECT_TRUE(contains(g.parameters[i], clamp01(param[i]))) << "parameter " << i;
      RationalVector dir = direction_at(at, 0);
      const mpq_class nn = dot(dir, dir);
      if (sgn(coplanarity_determinant_at(at, 0)) < 0) dir = {-dir.x, -dir.y, -dir.z};
      EXPECT_TRUE(unit_component_in(dir.x, nn, g.normal[0]) &&
                  unit_component_in(dir.y, nn, g.normal[1]) &&
                  unit_component_in(dir.z, nn, g.normal[2]));
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(resolved, 40);
}

// Scene::contact_geometry is the pair-level function on the contact's query: a sheet of two
// triangles falling onto a static floor (vertex-face and edge-edge contacts), every contact's
// geometry equal field by field to contact_geometry of its query and result.
TEST(ContactGeometry, SceneContactsGetTheirQueriesGeometry) {
  Scene scene;
  Positions floor(4, 3), sheet(4, 3);
  Triangles two(2, 3);
  floor << -2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0;
  sheet << -0.5, -0.5, 0.5, 0.7, -0.5, 0.25, 0.5, 0.6, 0.75, -0.5, 0.5, 0.5;
  two << 0, 1, 2, 0, 2, 3;
  scene.add_static_mesh(floor, two);
  const MeshId falling = scene.add_mesh(sheet, two);
  Positions down = sheet;
  down.col(2).array() -= 1.5;
  scene.set_motion(falling, sheet, down);
  const SceneResult result = scene.find_contacts();
  ASSERT_FALSE(result.contacts.empty());
  int points = 0;
  for (const SceneContact& c : result.contacts) {
    CcdResult r;
    r.collides = true;
    r.toi_lo = c.toi_lo;
    r.toi_hi = c.toi_hi;
    r.starts_within = c.starts_within;
    const ContactGeometry want =
        c.pair.type == QueryType::vertex_face
            ? contact_geometry(scene.vertex_face_query(c.pair), r)
            : contact_geometry(scene.edge_edge_query(c.pair), r);
    const ContactGeometry got = scene.contact_geometry(c);
    EXPECT_EQ(got.kind, want.kind);
    EXPECT_EQ(got.parameter_count, want.parameter_count);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(got.normal[i].lo, want.normal[i].lo);
      EXPECT_EQ(got.normal[i].hi, want.normal[i].hi);
      EXPECT_EQ(got.parameters[i].lo, want.parameters[i].lo);
      EXPECT_EQ(got.point[i].hi, want.point[i].hi);
    }
    points += got.kind == ContactKind::point;
  }
  EXPECT_GT(points, 0);
  // A rigid body turning as it falls: its contacts' geometry is the rigid queries'.
  Scene rigid_scene;
  rigid_scene.add_static_mesh(floor, two);
  const MeshId body = rigid_scene.add_rigid_body(sheet, two);
  rigid_scene.set_rigid_motion(body, RigidMotion::turn(Vector3d(0, 0, 0.5), Vector3d(0, 0, 1),
                                                       0.5, Vector3d(0, 0, -1.5)));
  const SceneResult rigid_result = rigid_scene.find_contacts();
  ASSERT_FALSE(rigid_result.contacts.empty());
  for (const SceneContact& c : rigid_result.contacts) {
    RigidCcdResult r;
    r.ccd.collides = true;
    r.ccd.toi_lo = c.toi_lo;
    r.ccd.toi_hi = c.toi_hi;
    r.ccd.starts_within = c.starts_within;
    const ContactGeometry want =
        c.pair.type == QueryType::vertex_face
            ? contact_geometry(rigid_scene.rigid_vertex_face_query(c.pair), r)
            : contact_geometry(rigid_scene.rigid_edge_edge_query(c.pair), r);
    const ContactGeometry got = rigid_scene.contact_geometry(c);
    EXPECT_EQ(got.kind, want.kind);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(got.normal[i].lo, want.normal[i].lo);
      EXPECT_EQ(got.parameters[i].hi, want.parameters[i].hi);
    }
  }
}

// With a minimum separation delta > 0: the closest points at t* (the distance there is delta).
// A vertex approaching the inside of a triangle and an edge approaching across another, at
// delta 2^-10 and 0.05: at rational t of the enclosure, the exact projection's barycentric
// coordinates / the lines' closest parameters (clamped) lie in the enclosures, and the exact
// normal direction, oriented by the exact determinant's sign at t (not 0: the distance is
// about delta), lies in the normal's box (sides, corners and ends: separation_contact_test).
TEST(ContactGeometry, MinimumSeparationEnclosesTheClosestPoints) {
  std::mt19937_64 rng(test_seed("contact_geometry_separation"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int resolved = 0;
  for (int n = 0; n < 200; ++n) {
    const bool vf = n % 2 == 0;
    const double delta = n % 4 < 2 ? 0x1p-10 : 0.05;
    const auto v = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
    std::array<Vector3d, 8> x;
    if (vf) {
      x = {Vector3d(0.25, 0.25, 0.5) + 0.05 * v(), Vector3d(0, 0, 0) + 0.05 * v(),
           Vector3d(1, 0, 0) + 0.05 * v(), Vector3d(0, 1, 0) + 0.05 * v(),
           Vector3d(0.3, 0.25, -0.5) + 0.05 * v(), Vector3d(0, 0, 0) + 0.05 * v(),
           Vector3d(1, 0, 0) + 0.05 * v(), Vector3d(0, 1, 0) + 0.05 * v()};
    } else {
      x = {Vector3d(-1, 0, 0.5) + 0.05 * v(), Vector3d(1, 0, 0.5) + 0.05 * v(),
           Vector3d(0, -1, 0) + 0.05 * v(), Vector3d(0, 1, 0) + 0.05 * v(),
           Vector3d(-1, 0, -0.5) + 0.05 * v(), Vector3d(1, 0, -0.5) + 0.05 * v(),
           Vector3d(0, -1, 0) + 0.05 * v(), Vector3d(0, 1, 0) + 0.05 * v()};
    }
    RationalQuery q{vf ? QueryType::vertex_face : QueryType::edge_edge, {}};
    for (int i = 0; i < 8; ++i)
      q.points[i] = {mpq_class(x[i].x()), mpq_class(x[i].y()), mpq_class(x[i].z())};
    CcdOptions o;
    o.min_separation = delta;
    const CcdResult r = double_api_ccd(q, o);
    if (!r.collides || r.starts_within) continue;
    std::array<Vector3d, 8> y = x;
    const ContactGeometry g =
        vf ? contact_geometry(VertexFaceQuery{y[0], y[1], y[2], y[3], y[4], y[5], y[6], y[7]}, r,
                              delta)
           : contact_geometry(EdgeEdgeQuery{y[0], y[1], y[2], y[3], y[4], y[5], y[6], y[7]}, r,
                              delta);
    SCOPED_TRACE(describe(q) + " delta " + std::to_string(delta));
    if (g.kind != ContactKind::point) continue;
    ++resolved;
    ASSERT_TRUE(g.normal_oriented);
    const mpq_class lo(r.toi_lo), hi(r.toi_hi);
    for (const mpq_class& t : {lo, hi, mpq_class((lo + hi) / 2)}) {
      std::array<mpq_class, 3> param;
      ASSERT_TRUE(parameters_at(q, t, &param));
      for (int i = 0; i < g.parameter_count; ++i)
        EXPECT_TRUE(contains(g.parameters[i], clamp01(param[i]))) << "parameter " << i;
      RationalVector dir = direction_at(q, t);
      const mpq_class nn = dot(dir, dir);
      const int side = sgn(coplanarity_determinant_at(q, t));
      ASSERT_NE(side, 0);
      if (side < 0) dir = {-dir.x, -dir.y, -dir.z};
      EXPECT_TRUE(unit_component_in(dir.x, nn, g.normal[0]) &&
                  unit_component_in(dir.y, nn, g.normal[1]) &&
                  unit_component_in(dir.z, nn, g.normal[2]));
    }
    EXPECT_GT(g.normal[2].lo, 0.5);  // from above
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(resolved, 120);
  // A negative delta is an error.
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const VertexFaceQuery beside{Vector3d(0.5, -0.01, 1), a, b, c, Vector3d(0.5, -0.01, -1), a, b, c};
  CcdOptions o;
  o.min_separation = 0.05;
  const CcdResult r = vertex_face_ccd(beside, o);
  ASSERT_TRUE(r.collides);
  EXPECT_THROW(contact_geometry(beside, r, -1.0), std::invalid_argument);
}

TEST(ContactGeometry, BadInputIsAnError) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), p(0.25, 0.25, 1);
  const VertexFaceQuery apart{p, a, b, c, p, a, b, c};
  const CcdResult none = vertex_face_ccd(apart);
  EXPECT_THROW(contact_geometry(apart, none), std::invalid_argument);
  CcdResult forged;
  forged.collides = true;
  forged.toi_lo = 0.5;
  forged.toi_hi = 0.25;
  EXPECT_THROW(contact_geometry(apart, forged), std::invalid_argument);
  const VertexFaceQuery nan{Vector3d(std::nan(""), 0, 0), a, b, c, p, a, b, c};
  forged.toi_hi = 0.75;
  EXPECT_THROW(contact_geometry(nan, forged), std::invalid_argument);
  EXPECT_STREQ(to_string(ContactKind::at_start), "at_start");
}

}  // namespace
}  // namespace exactccd::test
