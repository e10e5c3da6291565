// Rigid-body CCD (exactccd/rigid.hpp): hand-made rotations with known contact parameters (arcs
// that hit what the chord misses, a Pythagorean turn that meets at s = 1/2 exactly, an edge
// swept across a vertical edge), zero rotation against the linear API bit for bit, invariance
// under exact rigid transforms of the whole query, the filtered path against the exact path,
// and an independent check at rational parameters (positions from the matrix form of the
// motion, contact decided by CGAL's exact kernel): no contact before toi_lo, contact at every
// TOI that is a double. PROOF: proofs/rigid_ccd.md#tests
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "corpus/rigid_exact_pose.hpp"
#include "corpus/rigid_queries.hpp"
#include "exact/reference/rigid_ccd.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/rigid.hpp"
#include "sample_double_queries.hpp"
#include "test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

CcdOptions mode(Mode m) {
  CcdOptions o;
  o.mode = m;
  return o;
}

SideMotion at_rest() { return SideMotion::of(RigidMotion{}); }

// ---------------------------------------------------------------------------------------------
// Positions at a rational parameter, from the matrix form of the rotation
// (corpus/rigid_exact_pose.hpp; not the polynomial expansion the library uses).

using Q3 = rigid_pose::RationalPosition;
using rigid_pose::exactly;

Q3 q3(const Vector3d& v) { return exactly(v); }

Q3 rational_position(const SideMotion& side, int vertex, const Vector3d& x0, const mpq_class& s) {
  if (side.kind == PathKind::linear) {
    const Q3 a = q3(x0), b = q3(side.linear_end[vertex]);
    return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
  }
  return rigid_pose::exact_position(side.rigid, x0, s);
}

CgalPoint cgal(const Q3& x) { return CgalPoint(x[0], x[1], x[2]); }

bool cgal_contact_at(const RigidVertexFaceQuery& q, const mpq_class& s) {
  return cgal_point_in_triangle(cgal(rational_position(q.vertex, 0, q.p, s)),
                                cgal(rational_position(q.face, 0, q.a, s)),
                                cgal(rational_position(q.face, 1, q.b, s)),
                                cgal(rational_position(q.face, 2, q.c, s)));
}

bool cgal_contact_at(const RigidEdgeEdgeQuery& q, const mpq_class& s) {
  return cgal_segments_meet(cgal(rational_position(q.edge_a, 0, q.ea0, s)),
                            cgal(rational_position(q.edge_a, 1, q.ea1, s)),
                            cgal(rational_position(q.edge_b, 0, q.eb0, s)),
                            cgal(rational_position(q.edge_b, 1, q.eb1, s)));
}

// ---------------------------------------------------------------------------------------------
// Hand-made rotations

/// A quarter turn about z (q = (0, 0, 1)) of the point (1, 0, 0): its arc stays at radius 1,
/// its chord to (0, 1, 0) passes at radius 1/sqrt(2) on the bisector x = y.
RigidMotion quarter_turn() {
  RigidMotion m;
  m.cayley = Vector3d(0, 0, 1);
  return m;
}

/// A small static triangle in the plane x = y around the point at radius `radius` on the
/// bisector.
RigidVertexFaceQuery bisector_wall(double radius, double half_width) {
  const double r = radius / std::sqrt(2.0);
  const double w = half_width / std::sqrt(2.0);
  RigidVertexFaceQuery q;
  q.p = Vector3d(1, 0, 0);
  q.vertex = SideMotion::of(quarter_turn());
  q.a = Vector3d(r - w, r - w, -1);
  q.b = Vector3d(r + w, r + w, -1);
  q.c = Vector3d(r, r, 1);
  q.face = at_rest();
  return q;
}

TEST(RigidCcd, ArcHitsTheWallTheChordMisses) {
  for (Mode m : {Mode::filtered, Mode::exact}) {
    const RigidCcdResult arc = vertex_face_ccd(bisector_wall(1.0, 0.1), mode(m));
    ASSERT_TRUE(arc.ccd.collides) << describe_result(arc.ccd);
    // The turn reaches 45 degrees at s = tan(pi / 8) = sqrt(2) - 1 (about 0.4142).
    const long double expected = std::sqrt(2.0L) - 1.0L;
    EXPECT_LE(arc.ccd.toi_lo, expected + 1e-15L);
    EXPECT_GE(arc.ccd.toi_hi, expected - 1e-15L);
    EXPECT_LE(arc.ccd.toi_hi - arc.ccd.toi_lo, 1e-15);
    // A pure rotation: the time is t = 2 atan(s) / (pi / 2) = 1/2 at that s.
    ASSERT_TRUE(arc.has_time);
    EXPECT_LE(arc.time_lo, 0.5);
    EXPECT_GE(arc.time_hi, 0.5);
    EXPECT_LE(arc.time_hi - arc.time_lo, 1e-15);

    // The chord (the same end positions on straight lines) passes at radius 0.707: it misses.
    RigidVertexFaceQuery chord = bisector_wall(1.0, 0.1);
    chord.vertex.kind = PathKind::linear;
    chord.vertex.linear_end[0] = Vector3d(0, 1, 0);
    EXPECT_FALSE(vertex_face_ccd(chord, mode(m)).ccd.collides);

    // A wall at radius 0.707 is hit by the chord and never by the arc.
    EXPECT_FALSE(vertex_face_ccd(bisector_wall(std::sqrt(0.5), 0.05), mode(m)).ccd.collides);
    RigidVertexFaceQuery inside = bisector_wall(std::sqrt(0.5), 0.05);
    inside.vertex = chord.vertex;
    EXPECT_TRUE(vertex_face_ccd(inside, mode(m)).ccd.collides);
  }
}

TEST(RigidCcd, PythagoreanTurnMeetsAtAHalfExactly) {
  // (5, 0, 0) turned about z with q = (0, 0, 1): at s = 1/2, C = [[3/5, -4/5], [4/5, 3/5]], so
  // the point is at (3, 4, 0) exactly; the static triangle lies in the plane y = 4 around it,
  // and y(s) = 5 * 2s / (1 + s^2) increases on [0, 1]: the first contact is s = 1/2.
  RigidVertexFaceQuery q;
  q.p = Vector3d(5, 0, 0);
  q.vertex = SideMotion::of(quarter_turn());
  q.a = Vector3d(2, 4, -1);
  q.b = Vector3d(4, 4, -1);
  q.c = Vector3d(3, 4, 1);
  q.face = at_rest();
  for (Mode m : {Mode::filtered, Mode::exact}) {
    const RigidCcdResult r = vertex_face_ccd(q, mode(m));
    ASSERT_TRUE(r.ccd.collides);
    EXPECT_EQ(r.ccd.toi_lo, 0.5) << describe_result(r.ccd);
    EXPECT_EQ(r.ccd.toi_hi, 0.5);
    // t = atan(1/2) / atan(1) = 0.5903344...
    const long double t = std::atan(0.5L) / std::atan(1.0L);
    EXPECT_LE(r.time_lo, t + 1e-16L);
    EXPECT_GE(r.time_hi, t - 1e-16L);
    EXPECT_TRUE(cgal_contact_at(q, mpq_class(1, 2)));
    EXPECT_FALSE(cgal_contact_at(q, mpq_class(1, 2) - mpq_class(1, 1 << 20)));
  }
  // t_max below 1/2: no contact.
  CcdOptions before;
  before.t_max = 0.25;
  EXPECT_FALSE(vertex_face_ccd(q, before).ccd.collides);
}

TEST(RigidCcd, TurningEdgeSweepsAcrossAVerticalEdge) {
  // Edge a on the x axis from radius 1 to 3, turned a quarter about z; edge b vertical through
  // (1.2, 1.6) (radius 2 at angle phi = atan2(1.6, 1.2)): they meet at s = tan(phi / 2).
  RigidEdgeEdgeQuery q;
  q.ea0 = Vector3d(1, 0, 0);
  q.ea1 = Vector3d(3, 0, 0);
  q.edge_a = SideMotion::of(quarter_turn());
  q.eb0 = Vector3d(1.2, 1.6, -1);
  q.eb1 = Vector3d(1.2, 1.6, 1);
  q.edge_b = at_rest();
  const long double expected = std::tan(std::atan2(1.6L, 1.2L) / 2);  // of the doubles' values
  for (Mode m : {Mode::filtered, Mode::exact}) {
    const RigidCcdResult r = edge_edge_ccd(q, mode(m));
    ASSERT_TRUE(r.ccd.collides);
    EXPECT_LE(r.ccd.toi_lo, expected + 1e-12L);
    EXPECT_GE(r.ccd.toi_hi, expected - 1e-12L);
  }
  // Raised above the edge's plane: no contact; the whole turn of edge a stays at z = 0.
  q.eb0.z() = 0.5;
  EXPECT_FALSE(edge_edge_ccd(q).ccd.collides);
  EXPECT_FALSE(edge_edge_ccd(q, mode(Mode::exact)).ccd.collides);
}

TEST(RigidCcd, AxisThroughThePrimitiveAndCoplanarThroughout) {
  // A triangle in the plane z = 0 turning about z through its own corner, and a vertex in the
  // same plane at rest: coplanar throughout; the triangle sweeps over the vertex at the angle of
  // the vertex (the corner's edge reaches it first).
  RigidVertexFaceQuery q;
  q.a = Vector3d(0, 0, 0);
  q.b = Vector3d(2, 0, 0);
  q.c = Vector3d(2, -1, 0);
  q.face = SideMotion::of(quarter_turn());
  q.p = Vector3d(0.6, 0.8, 0);  // angle atan2(0.8, 0.6), radius 1: reached by edge (a, b)
  q.vertex = at_rest();
  const long double expected = std::tan(std::atan2(0.8L, 0.6L) / 2);
  for (Mode m : {Mode::filtered, Mode::exact}) {
    const RigidCcdResult r = vertex_face_ccd(q, mode(m));
    ASSERT_TRUE(r.ccd.collides);
    EXPECT_LE(r.ccd.toi_lo, expected + 1e-12L);
    EXPECT_GE(r.ccd.toi_hi, expected - 1e-12L);
  }
  // The vertex on the rotation axis (the corner a stays there): contact at s = 0.
  q.p = Vector3d(0, 0, 0);
  EXPECT_EQ(vertex_face_ccd(q).ccd.toi_lo, 0.0);
  EXPECT_EQ(vertex_face_ccd(q).ccd.toi_hi, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Zero rotation is the linear API

TEST(RigidCcd, LinearSidesEqualTheLinearApiOnTheSampleQueries) {
  int contacts = 0, compared = 0;
  const auto& all = sample_double_queries();
  for (std::size_t i = 0; i < all.size(); i += subset_stride() * 4) {
    const DoubleQuery& d = all[i];
    SideMotion first, second;
    first.kind = second.kind = PathKind::linear;
    for (Mode m : {Mode::filtered, Mode::exact}) {
      CcdResult linear, rigid;
      if (d.type == QueryType::vertex_face) {
        first.linear_end[0] = d.v[4];
        second.linear_end = {d.v[5], d.v[6], d.v[7]};
        linear = vertex_face_ccd(d.vertex_face(), mode(Mode::exact));
        rigid = vertex_face_ccd(RigidVertexFaceQuery{d.v[0], d.v[1], d.v[2], d.v[3], first, second},
                                mode(m)).ccd;
      } else {
        first.linear_end = {d.v[4], d.v[5], Vector3d::Zero()};
        second.linear_end = {d.v[6], d.v[7], Vector3d::Zero()};
        linear = edge_edge_ccd(d.edge_edge(), mode(Mode::exact));
        rigid = edge_edge_ccd(RigidEdgeEdgeQuery{d.v[0], d.v[1], d.v[2], d.v[3], first, second},
                              mode(m)).ccd;
      }
      ASSERT_TRUE(same_answer(linear, rigid))
          << "sample query " << i << ": linear " << describe_result(linear) << ", rigid "
          << describe_result(rigid);
      contacts += linear.collides;
      ++compared;
    }
  }
  // Not a vacuous pass: contacts among the compared queries (a twentieth of them at full
  // scale; the sanitizer run's few queries hold at least one).
  EXPECT_GT(contacts, 0);
  if (scale_from_environment() >= 1) EXPECT_GT(contacts, compared / 20);
}

TEST(RigidCcd, ZeroRotationTranslationsEqualLinearMotion) {
  std::mt19937_64 rng(test_seed("RigidCcd.ZeroRotation"));
  // Coordinates k / 16 with |k| <= 64: every sum x0 + d is exact, so the linear query is the
  // rigid one exactly; many of these small-grid queries collide or touch.
  std::uniform_int_distribution<int> k(-64, 64);
  auto grid = [&] {
    const double x = k(rng) / 16.0;
    const double y = k(rng) / 16.0;
    const double z = k(rng) / 16.0;
    return Vector3d(x, y, z);
  };
  int contacts = 0;
  const int n = static_cast<int>(scaled_count(4000));
  for (int i = 0; i < n; ++i) {
    RigidMotion ma, mb;
    ma.pivot = grid();
    ma.translation = grid();
    mb.pivot = grid();
    mb.translation = grid();
    Vector3d x[4];
    for (Vector3d& v : x) v = grid() / 4;
    const auto A = SideMotion::of(ma), B = SideMotion::of(mb);
    const CcdResult vf_rigid = vertex_face_ccd(RigidVertexFaceQuery{x[0], x[1], x[2], x[3], A, B}).ccd;
    const CcdResult vf_linear = vertex_face_ccd(
        VertexFaceQuery{x[0], x[1], x[2], x[3], x[0] + ma.translation, x[1] + mb.translation,
                        x[2] + mb.translation, x[3] + mb.translation},
        mode(Mode::exact));
    ASSERT_TRUE(same_answer(vf_rigid, vf_linear)) << i << ": " << describe_result(vf_rigid) << " vs "
                                                  << describe_result(vf_linear);
    const CcdResult ee_rigid = edge_edge_ccd(RigidEdgeEdgeQuery{x[0], x[1], x[2], x[3], A, B}).ccd;
    const CcdResult ee_linear = edge_edge_ccd(
        EdgeEdgeQuery{x[0], x[1], x[2], x[3], x[0] + ma.translation, x[1] + ma.translation,
                      x[2] + mb.translation, x[3] + mb.translation},
        mode(Mode::exact));
    ASSERT_TRUE(same_answer(ee_rigid, ee_linear)) << i;
    contacts += vf_linear.collides + ee_linear.collides;
  }
  EXPECT_GT(contacts, n / 50);
}

// ---------------------------------------------------------------------------------------------
// Random rigid pairs near contact

struct Tally {
  int contacts = 0, queries = 0;
};

template <class Query>
void check_against_independent_test(const Query& q, const RigidCcdResult& r, int index) {
  // No contact at 16 rational parameters before toi_lo (all of [0, t_max] without contact).
  const mpq_class end = r.ccd.collides ? mpq_class(r.ccd.toi_lo) : mpq_class(1);
  for (int j = 0; j < 16; ++j) {
    const mpq_class s = end * j / 16;
    if (r.ccd.collides && s >= end) break;
    ASSERT_FALSE(cgal_contact_at(q, s)) << "query " << index << ": contact at s = " << s
                                        << " before " << describe_result(r.ccd);
  }
  if (r.ccd.collides && r.ccd.toi_lo == r.ccd.toi_hi)
    ASSERT_TRUE(cgal_contact_at(q, mpq_class(r.ccd.toi_lo))) << "query " << index;
}

template <class Query, class Ccd>
Tally differential(const std::vector<Query>& queries, Ccd&& ccd) {
  Tally t;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const RigidCcdResult exact = ccd(queries[i], mode(Mode::exact));
    const RigidCcdResult filtered = ccd(queries[i], mode(Mode::filtered));
    EXPECT_TRUE(same_answer(exact.ccd, filtered.ccd))
        << "query " << i << ": exact " << describe_result(exact.ccd) << ", filtered "
        << describe_result(filtered.ccd);
    check_against_independent_test(queries[i], exact, static_cast<int>(i));
    t.contacts += exact.ccd.collides;
    ++t.queries;
  }
  return t;
}

TEST(RigidCcd, FilteredEqualsExactAndIndependentChecksOnRandomPairsNearContact) {
  const std::uint64_t seed = test_seed("RigidCcd.RandomPairs");
  const std::size_t n = at_least(scaled_count(75), 10);
  auto vertex_face = [](const auto& q, const CcdOptions& c) { return vertex_face_ccd(q, c); };
  auto edge_edge = [](const auto& q, const CcdOptions& c) { return edge_edge_ccd(q, c); };
  for (rigid_queries::OtherMotion other :
       {rigid_queries::OtherMotion::rigid, rigid_queries::OtherMotion::linear,
        rigid_queries::OtherMotion::rest}) {
    // Offsets up to a quarter of the size (most collide) and up to 1024 sizes (most miss).
    Tally vf, ee;
    for (double offset_scale : {1.0, 4096.0}) {
      rigid_queries::RigidQueryOptions o;
      o.other = other;
      o.offset_scale = offset_scale;
      const Tally v =
          differential(rigid_queries::random_rigid_vertex_face(seed, n, o), vertex_face);
      const Tally e = differential(rigid_queries::random_rigid_edge_edge(seed, n, o), edge_edge);
      vf.contacts += v.contacts, vf.queries += v.queries;
      ee.contacts += e.contacts, ee.queries += e.queries;
    }
    // Not a vacuous pass: contacts and misses of each kind.
    for (const Tally& t : {vf, ee}) {
      EXPECT_GT(t.contacts, t.queries / 8);
      EXPECT_LT(t.contacts, t.queries);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Invariance under exact rigid transforms of the whole query

/// x -> M x with M a signed permutation (exact in doubles); a rotation conjugated by M is the
/// rotation with Cayley vector det(M) M q ([M v]x = det(M) M [v]x M^T).
struct SignedPermutation {
  Matrix3d m;
  double det;
  Vector3d point(const Vector3d& x) const { return m * x; }
  RigidMotion motion(const RigidMotion& r) const {
    return {m * r.pivot, m * r.translation, det * (m * r.cayley)};
  }
  SideMotion side(const SideMotion& s) const {
    SideMotion out = s;
    out.rigid = motion(s.rigid);
    for (auto& e : out.linear_end) e = m * e;
    return out;
  }
};

struct PowerOfTwo {
  double f;
  Vector3d point(const Vector3d& x) const { return f * x; }
  SideMotion side(const SideMotion& s) const {
    SideMotion out = s;
    out.rigid.pivot *= f;
    out.rigid.translation *= f;  // the Cayley vector (an angle) is unchanged
    for (auto& e : out.linear_end) e *= f;
    return out;
  }
};

template <class T>
RigidVertexFaceQuery transformed(const RigidVertexFaceQuery& q, const T& t) {
  return {t.point(q.p), t.point(q.a), t.point(q.b), t.point(q.c), t.side(q.vertex), t.side(q.face)};
}

template <class T>
RigidEdgeEdgeQuery transformed(const RigidEdgeEdgeQuery& q, const T& t) {
  return {t.point(q.ea0), t.point(q.ea1), t.point(q.eb0), t.point(q.eb1), t.side(q.edge_a),
          t.side(q.edge_b)};
}

TEST(RigidCcd, InvariantUnderSignedPermutationsAndPowersOfTwo) {
  const std::uint64_t seed = test_seed("RigidCcd.Invariance");
  std::mt19937_64 rng(seed);
  rigid_queries::RigidQueryOptions o;
  o.other = rigid_queries::OtherMotion::linear;
  const auto vf = rigid_queries::random_rigid_vertex_face(seed + 1, scaled_count(60), o);
  const auto ee = rigid_queries::random_rigid_edge_edge(seed + 1, scaled_count(60));
  std::vector<SignedPermutation> perms;
  const int orders[3][3] = {{1, 0, 2}, {2, 0, 1}, {0, 1, 2}};
  for (const auto& order : orders)
    for (double flip : {1.0, -1.0}) {
      Matrix3d m = Matrix3d::Zero();
      for (int i = 0; i < 3; ++i) m(i, order[i]) = 1;
      m(0, order[0]) = flip;
      perms.push_back({m, m.determinant()});
    }
  int contacts = 0;
  for (std::size_t i = 0; i < vf.size(); ++i) {
    const RigidCcdResult base = vertex_face_ccd(vf[i]);
    contacts += base.ccd.collides;
    for (const auto& p : perms)
      ASSERT_TRUE(same_answer(base.ccd, vertex_face_ccd(transformed(vf[i], p)).ccd)) << i;
    for (double f : {0x1p-300, 0x1p-5, 0x1p40, 0x1p500})
      ASSERT_TRUE(same_answer(base.ccd, vertex_face_ccd(transformed(vf[i], PowerOfTwo{f})).ccd))
          << i << " scaled by " << f;
  }
  for (std::size_t i = 0; i < ee.size(); ++i) {
    const RigidCcdResult base = edge_edge_ccd(ee[i]);
    contacts += base.ccd.collides;
    for (const auto& p : perms)
      ASSERT_TRUE(same_answer(base.ccd, edge_edge_ccd(transformed(ee[i], p)).ccd)) << i;
    ASSERT_TRUE(same_answer(base.ccd, edge_edge_ccd(transformed(ee[i], PowerOfTwo{0x1p-200})).ccd));
  }
  EXPECT_GT(contacts, static_cast<int>(vf.size() + ee.size()) / 8);
}

// ---------------------------------------------------------------------------------------------
// Degrees (proofs/rigid_ccd.md#degree)

exact::RationalRigidQuery rational_query(QueryType type, const std::array<Vector3d, 4>& x,
                                         const SideMotion& first, const SideMotion& second) {
  exact::RationalRigidQuery q;
  q.type = type;
  auto vec = [](const Vector3d& v) {
    return predicates::Vec3<mpq_class>{mpq_class(v.x()), mpq_class(v.y()), mpq_class(v.z())};
  };
  for (int i = 0; i < 4; ++i) q.start[i] = vec(x[i]);
  const SideMotion* sides[2] = {&first, &second};
  for (int k = 0; k < 2; ++k) {
    q.side[k].rigid = sides[k]->kind == PathKind::rigid;
    q.side[k].motion = {vec(sides[k]->rigid.pivot), vec(sides[k]->rigid.translation),
                        vec(sides[k]->rigid.cayley)};
    for (int i = 0; i < 3; ++i) q.side[k].end[i] = vec(sides[k]->linear_end[i]);
  }
  return q;
}

TEST(RigidCcd, CoplanarityDegreeBoundsAfterDividingTheDenominators) {
  const std::uint64_t seed = test_seed("RigidCcd.Degrees");
  rigid_queries::RigidQueryOptions rigid, linear;
  linear.other = rigid_queries::OtherMotion::linear;
  // (options, edge-edge?, bound): both rigid 5 and 5; a linear vertex against a rigid face 3; a
  // rigid edge against a linear one 4. Generic queries reach the bound (it is not loose).
  struct Case {
    rigid_queries::RigidQueryOptions options;
    bool edge_edge;
    int bound;
  };
  for (const Case& c : {Case{rigid, false, 5}, Case{linear, false, 3}, Case{rigid, true, 5},
                        Case{linear, true, 4}}) {
    int at_bound = 0;
    for (int i = 0; i < 40; ++i) {
      exact::RationalRigidQuery q;
      if (c.edge_edge) {
        const auto e = rigid_queries::random_rigid_edge_edge(seed, 40, c.options)[i];
        q = rational_query(QueryType::edge_edge, {e.ea0, e.ea1, e.eb0, e.eb1}, e.edge_a, e.edge_b);
      } else {
        const auto v = rigid_queries::random_rigid_vertex_face(seed, 40, c.options)[i];
        q = rational_query(QueryType::vertex_face, {v.p, v.a, v.b, v.c}, v.vertex, v.face);
      }
      const int d = exact::rigid_coplanarity_polynomial(q).degree();
      EXPECT_LE(d, c.bound) << (c.edge_edge ? "edge-edge " : "vertex-face ") << i;
      at_bound += d == c.bound;
    }
    EXPECT_GT(at_bound, 30) << "bound " << c.bound;
  }
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(RigidCcd, BadInputThrowsClearly) {
  RigidVertexFaceQuery q = bisector_wall(1.0, 0.1);
  q.vertex.rigid.cayley.x() = std::nan("");
  EXPECT_THROW(vertex_face_ccd(q), std::invalid_argument);
  q = bisector_wall(1.0, 0.1);
  q.c.z() = INFINITY;
  EXPECT_THROW(vertex_face_ccd(q), std::invalid_argument);
  q = bisector_wall(1.0, 0.1);
  // Mode::float_only runs (the uncertified double test: tests/rigid_float_only_test.cpp).
  EXPECT_EQ(vertex_face_ccd(q, mode(Mode::float_only)).ccd.decided_by, Stage::float_only);
  CcdOptions separated;  // a minimum separation must be finite and >= 0
  separated.min_separation = -1e-3;
  EXPECT_THROW(vertex_face_ccd(q, separated), std::invalid_argument);
  CcdOptions bad_t;  // t_max = 0 is the state at the start (t_max_zero_test); beyond [0, 1] not
  bad_t.t_max = -0x1p-1074;
  EXPECT_THROW(vertex_face_ccd(q, bad_t), std::invalid_argument);
  bad_t.t_max = 0x1.0000000000001p0;
  EXPECT_THROW(vertex_face_ccd(q, bad_t), std::invalid_argument);
  EXPECT_THROW(RigidMotion::turn(Vector3d::Zero(), Vector3d::Zero(), 1.0), std::invalid_argument);
  EXPECT_THROW(RigidMotion::turn(Vector3d::Zero(), Vector3d::UnitZ(), 3.5), std::invalid_argument);
  // An axis whose norm overflows ([1e308, 1e308, 1e308]) or underflows ([0, 0, 1e-320]) in
  // doubles is a good direction: the turn about it is the turn about its unit vector.
  const Vector3d diagonal = Vector3d::Ones().normalized();
  EXPECT_EQ(RigidMotion::turn(Vector3d::Zero(), Vector3d::Constant(1e308), 1.0).cayley,
            RigidMotion::turn(Vector3d::Zero(), diagonal, 1.0).cayley);
  EXPECT_EQ(RigidMotion::turn(Vector3d::Zero(), Vector3d(0, 0, 1e-320), 1.0).cayley,
            RigidMotion::turn(Vector3d::Zero(), Vector3d::UnitZ(), 1.0).cayley);
  EXPECT_EQ(RigidMotion::turn(Vector3d::Zero(), Vector3d(0, -4.9e-324, 0), 1.0).cayley,
            RigidMotion::turn(Vector3d::Zero(), -Vector3d::UnitY(), 1.0).cayley);
  // Huge coordinates and a huge Cayley vector (a turn close to 180 degrees) are valid input.
  q = bisector_wall(1.0, 0.1);
  q.vertex.rigid.cayley = Vector3d(0, 0, 1e300);
  EXPECT_NO_THROW(vertex_face_ccd(q));
  EXPECT_TRUE(same_answer(vertex_face_ccd(q).ccd, vertex_face_ccd(q, mode(Mode::exact)).ccd));
}

}  // namespace
}  // namespace exactccd::test
