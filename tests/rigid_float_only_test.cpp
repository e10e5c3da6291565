// Mode::float_only of rigid-body CCD (core/float_only/rigid_float_only_ccd.hpp): the uncertified
// double test of rigid (and per-vertex linear) queries. It is for comparison only, so it is
// checked where a double test can be right: on random, well-conditioned rigid pairs (a clear
// transversal crossing inside the primitive, or a clear gap at every coplanar instant, judged
// here independently of the library from the positions alone) its verdict equals the certified
// one and its TOI is within a small relative error of the exact TOI; decided_by is float_only;
// the root finder finds the roots of a quintic; with a minimum separation it runs and agrees
// with the default mode on a clear pass; and a scene with a rigid body runs in Mode::float_only
// and returns the default mode's contact set on a well-conditioned scene.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "core/float_only/rigid_float_only_ccd.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;

CcdOptions mode_options(Mode mode, double t_max = 1.0) {
  CcdOptions o;
  o.mode = mode;
  o.t_max = t_max;
  return o;
}

// ---------------------------------------------------------------------------------------------
// The root finder

TEST(RigidFloatOnly, RootsOfAQuintic) {
  // (s - 0.1)(s - 0.3)(s - 0.5)(s - 0.7)(s - 0.9), expanded in doubles.
  predicates::FixedPoly<double, 5> g{{1.0, 0.0, 0.0, 0.0, 0.0, 0.0}};
  for (const double r : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    predicates::FixedPoly<double, 5> next{};
    for (int i = 0; i <= 5; ++i) next.c[i] = (i > 0 ? g.c[i - 1] : 0.0) - r * g.c[i];
    g = next;
  }
  double roots[5];
  ASSERT_EQ(float_only::polynomial_roots(g, 1.0, roots), 5);
  const double want[5] = {0.1, 0.3, 0.5, 0.7, 0.9};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(roots[i], want[i], 1e-12) << i;
  // Only those in [0, t_max], ascending.
  ASSERT_EQ(float_only::polynomial_roots(g, 0.6, roots), 3);
  EXPECT_NEAR(roots[2], 0.5, 1e-12);
  // A root at an end counts; the zero polynomial has none (the caller samples instead).
  const predicates::FixedPoly<double, 5> at_zero{{0.0, 1.0, 0.0, 0.0, 0.0, 0.0}};
  ASSERT_EQ(float_only::polynomial_roots(at_zero, 1.0, roots), 1);
  EXPECT_EQ(roots[0], 0.0);
  const predicates::FixedPoly<double, 5> at_one{{-1.0, 1.0, 0.0, 0.0, 0.0, 0.0}};
  ASSERT_EQ(float_only::polynomial_roots(at_one, 1.0, roots), 1);
  EXPECT_EQ(roots[0], 1.0);
  EXPECT_EQ(float_only::polynomial_roots(predicates::FixedPoly<double, 5>{}, 1.0, roots), 0);
  // No real root: s^2 + 1 (degree 2 in a degree-5 slot).
  const predicates::FixedPoly<double, 5> none{{1.0, 0.0, 1.0, 0.0, 0.0, 0.0}};
  EXPECT_EQ(float_only::polynomial_roots(none, 1.0, roots), 0);
}

// ---------------------------------------------------------------------------------------------
// Hand-made queries

TEST(RigidFloatOnly, QuarterTurnIntoAWall) {
  // The README's example: (5, 0, 0) turned a quarter about z reaches (3, 4, 0) at s = 1/2.
  RigidVertexFaceQuery q;
  RigidMotion quarter;
  quarter.cayley = {0, 0, 1};
  q.p = {5, 0, 0};
  q.vertex = SideMotion::of(quarter);
  q.a = {2, 4, -1};
  q.b = {4, 4, -1};
  q.c = {3, 4, 1};
  const RigidCcdResult r = vertex_face_ccd(q, mode_options(Mode::float_only));
  EXPECT_TRUE(r.ccd.collides);
  EXPECT_EQ(r.ccd.decided_by, Stage::float_only);
  EXPECT_EQ(r.ccd.toi_lo, r.ccd.toi_hi);
  EXPECT_NEAR(r.ccd.toi_lo, 0.5, 1e-15);
  ASSERT_TRUE(r.has_time);  // a pure rotation against a static face
  const double t = std::atan(r.ccd.toi_lo) / std::atan(1.0);
  EXPECT_LE(r.time_lo, t + 1e-15);
  EXPECT_GE(r.time_hi, t - 1e-15);
  // Over [0, 0.4] the point has not reached the wall: no contact, +infinity.
  const RigidCcdResult early = vertex_face_ccd(q, mode_options(Mode::float_only, 0.4));
  EXPECT_FALSE(early.ccd.collides);
  EXPECT_EQ(early.ccd.toi_lo, kNoContactToi);
  EXPECT_EQ(early.ccd.toi_hi, kNoContactToi);
  EXPECT_EQ(early.ccd.decided_by, Stage::float_only);
}

TEST(RigidFloatOnly, MinSeparationAgreesOnAClearPass) {
  // The corner (5, 0, 0) turning a quarter about z passes a static triangle in the plane through
  // the axis and (3, 4, 0) (at s = 1/2), from radius 5 + gap out: its closest distance is gap,
  // and it crosses the triangle's plane there, transversally. float_only with min_separation
  // runs (no longer refused) and agrees with the default mode: within delta at gap = delta / 2,
  // not at gap = 2 delta.
  const double delta = 0.1;
  RigidMotion quarter;
  quarter.cayley = {0, 0, 1};
  const Vector3d radial(0.6, 0.8, 0), up(0, 0, 1);
  for (const double gap : {delta / 2, 2 * delta}) {
    SCOPED_TRACE("gap " + std::to_string(gap));
    RigidVertexFaceQuery q;
    q.p = {5, 0, 0};
    q.vertex = SideMotion::of(quarter);
    q.a = (5 + gap) * radial - up;
    q.b = (5 + gap) * radial + up;
    q.c = 7 * radial;
    CcdOptions options = mode_options(Mode::filtered);
    options.min_separation = delta;
    const RigidCcdResult certified = vertex_face_ccd(q, options);
    options.mode = Mode::float_only;
    const RigidCcdResult rough = vertex_face_ccd(q, options);
    EXPECT_EQ(certified.ccd.collides, gap < delta);
    EXPECT_EQ(rough.ccd.collides, certified.ccd.collides);
    EXPECT_EQ(rough.ccd.decided_by, Stage::float_only);
    if (!rough.ccd.collides) {
      EXPECT_EQ(rough.ccd.toi_lo, kNoContactToi);
    } else {
      // Conservative enough to be useful: not after the moment of closest approach.
      EXPECT_LE(rough.ccd.toi_lo, 0.5 + 1e-12);
      EXPECT_GE(rough.ccd.toi_lo, 0.0);
    }
  }
}

TEST(RigidFloatOnly, CoplanarThroughoutIsSampled) {
  // An edge turning in the plane z = 0 about the origin sweeps across a static edge of that
  // plane: the coplanarity polynomial vanishes identically, so the test samples the inclusion.
  // Edge a from (1, 0, 0) to (3, 0, 0) turned a quarter meets edge b, x = 2 for y in [2, 5],
  // first at b's end (2, 2, 0), when a points at 45 degrees: s = tan(pi / 8) = sqrt(2) - 1.
  RigidEdgeEdgeQuery q;
  RigidMotion quarter;
  quarter.cayley = {0, 0, 1};
  q.ea0 = {1, 0, 0};
  q.ea1 = {3, 0, 0};
  q.edge_a = SideMotion::of(quarter);
  q.eb0 = {2, 2, 0};
  q.eb1 = {2, 5, 0};
  const RigidCcdResult exact = edge_edge_ccd(q);
  const RigidCcdResult rough = edge_edge_ccd(q, mode_options(Mode::float_only));
  ASSERT_TRUE(exact.ccd.collides);
  ASSERT_TRUE(rough.ccd.collides);
  EXPECT_EQ(rough.ccd.decided_by, Stage::float_only);
  EXPECT_NEAR(rough.ccd.toi_lo, exact.ccd.toi_lo, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Random well-conditioned pairs

/// One side of a query and how its vertices move (positions in doubles: an independent
/// description of the motion, through the public position_at).
struct SidePath {
  SideMotion motion;
  Vector3d at(const Vector3d& x0, int index, double s) const {
    if (motion.kind == PathKind::rigid) return position_at(motion.rigid, x0, s);
    return x0 + s * (motion.linear_end[index] - x0);
  }
};

struct RandomPair {
  QueryType type;
  std::array<Vector3d, 4> start;
  SidePath first, second;
  int first_count() const { return type == QueryType::vertex_face ? 1 : 2; }
  std::array<Vector3d, 4> at(double s) const {
    std::array<Vector3d, 4> x;
    for (int i = 0; i < 4; ++i)
      x[i] = i < first_count() ? first.at(start[i], i, s)
                               : second.at(start[i], i - first_count(), s);
    return x;
  }
  RigidVertexFaceQuery vertex_face() const {
    RigidVertexFaceQuery q;
    q.p = start[0], q.a = start[1], q.b = start[2], q.c = start[3];
    q.vertex = first.motion;
    q.face = second.motion;
    return q;
  }
  RigidEdgeEdgeQuery edge_edge() const {
    RigidEdgeEdgeQuery q;
    q.ea0 = start[0], q.ea1 = start[1], q.eb0 = start[2], q.eb1 = start[3];
    q.edge_a = first.motion;
    q.edge_b = second.motion;
    return q;
  }
  RigidCcdResult decide(const CcdOptions& o) const {
    return type == QueryType::vertex_face ? vertex_face_ccd(vertex_face(), o)
                                          : edge_edge_ccd(edge_edge(), o);
  }
};

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }
  Vector3d point(double r = 1.0) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(engine_); }

 private:
  std::mt19937_64 engine_;
};

/// A side: turning (with a translation of the pivot), turning about a fixed pivot, straight
/// lines (a deformable mesh), or at rest.
SidePath random_side(Random& rng, const std::array<Vector3d, 4>& start, int begin, int count,
                     int kind) {
  SidePath side;
  if (kind <= 1) {
    RigidMotion m;
    m.pivot = rng.point();
    m.cayley = rng.point();  // up to about 120 degrees
    if (kind == 0) m.translation = rng.point();
    side.motion = SideMotion::of(m);
  } else {
    side.motion.kind = PathKind::linear;
    for (int i = 0; i < count; ++i)
      side.motion.linear_end[i] =
          kind == 2 ? Vector3d(start[begin + i] + rng.point()) : start[begin + i];
  }
  return side;
}

RandomPair random_pair(Random& rng, QueryType type) {
  RandomPair q;
  q.type = type;
  for (Vector3d& x : q.start) x = rng.point();
  const int first = q.first_count();
  // At least one side turns (kinds 0 and 1); the other anything.
  int kinds[2] = {rng.below(2), rng.below(4)};
  if (rng.below(2) == 1) std::swap(kinds[0], kinds[1]);
  q.first = random_side(rng, q.start, 0, first, kinds[0]);
  q.second = random_side(rng, q.start, first, 4 - first, kinds[1]);
  return q;
}

/// Moves side 0's start positions so that its primitive passes through side 1's at a random
/// s0 in [0.1, 0.9], at a random point well inside both: a crossing (usually transversal) there,
/// unless the pair meets earlier.
void aim(RandomPair& q, Random& rng) {
  const double s0 = rng.uniform(0.1, 0.9);
  const std::array<Vector3d, 4> x = q.at(s0);
  std::array<Vector3d, 2> target;
  if (q.type == QueryType::vertex_face) {
    const double a = rng.uniform(0.15, 1), b = rng.uniform(0.15, 1), c = rng.uniform(0.15, 1);
    target[0] = (a * x[1] + b * x[2] + c * x[3]) / (a + b + c);
  } else {
    const Vector3d y = x[2] + rng.uniform(0.15, 0.85) * (x[3] - x[2]);
    const Vector3d direction = rng.point();
    const double u = rng.uniform(0.15, 0.85);
    target = {y - u * direction, y + (1 - u) * direction};
  }
  SideMotion& m = q.first.motion;
  for (int i = 0; i < q.first_count(); ++i) {
    if (m.kind == PathKind::rigid) {
      // x(s0) = c + s0 d + C(s0 q) (x0 - c): x0 = c + C(-s0 q) (x(s0) - c - s0 d).
      RigidMotion back;
      back.cayley = -s0 * m.rigid.cayley;
      q.start[i] = m.rigid.pivot +
                   position_at(back, target[i] - m.rigid.pivot - s0 * m.rigid.translation, 1.0);
    } else {
      const Vector3d d = m.linear_end[i] - q.start[i];
      q.start[i] = target[i] - s0 * d;
      m.linear_end[i] = q.start[i] + d;
    }
  }
}

double coplanarity(QueryType type, const std::array<Vector3d, 4>& x) {
  return type == QueryType::vertex_face ? (x[2] - x[1]).cross(x[3] - x[1]).dot(x[0] - x[1])
                                        : (x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]);
}

/// How far inside the primitive the coplanar configuration x is: vertex-face, the least
/// barycentric coordinate of p's projection; edge-edge, the least of u, 1 - u, v, 1 - v at the
/// lines' closest points. Negative outside. NaN when the triangle is thin or the edges nearly
/// parallel (no clear answer).
double inclusion_margin(QueryType type, const std::array<Vector3d, 4>& x) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (type == QueryType::vertex_face) {
    const Vector3d v0 = x[2] - x[1], v1 = x[3] - x[1], v2 = x[0] - x[1];
    if (v0.cross(v1).norm() < 0.05) return nan;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1);
    const double d20 = v2.dot(v0), d21 = v2.dot(v1), den = d00 * d11 - d01 * d01;
    const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
    return std::min({1 - v - w, v, w});
  }
  const Vector3d da = x[1] - x[0], db = x[3] - x[2], r = x[0] - x[2];
  if (da.cross(db).norm() < 0.1 * da.norm() * db.norm() || da.norm() < 0.1 || db.norm() < 0.1)
    return nan;
  const double a = da.dot(da), b = da.dot(db), c = da.dot(r), e = db.dot(db), f = db.dot(r);
  const double den = a * e - b * b;
  const double u = (b * f - c * e) / den, v = (a * f - b * c) / den;
  return std::min({u, 1 - u, v, 1 - v});
}

/// The pair judged from its positions alone, in doubles on a fine grid of [0, t_max]: the
/// coplanarity determinant's sign changes, each refined by bisection, and the inclusion margin
/// at each. Clear when every root is simple (a steep crossing), away from the ends, with a
/// margin of at least 0.05 either way, and no near-root (a small local minimum of |det|).
struct Judgement {
  bool clear = false;
  bool contact = false;  // the first root with a positive margin
  double toi = kNoContactToi;
};

Judgement judge(const RandomPair& q, double t_max) {
  constexpr int kGrid = 2000;
  constexpr double kMargin = 0.05, kSteep = 1e-2, kNearRoot = 1e-3;
  Judgement j;
  const auto det = [&](double s) { return coplanarity(q.type, q.at(s)); };
  std::vector<double> value(kGrid + 1);
  for (int i = 0; i <= kGrid; ++i) value[i] = det(t_max * i / kGrid);
  for (int i = 0; i <= kGrid; ++i) {
    if (value[i] == 0) return j;
    // A small local minimum of |det| beside no sign change: a near-tangency (or two roots
    // between grid points).
    const auto same_side = [&](int k) { return (value[k] > 0) == (value[i] > 0); };
    const bool local_min =
        (i == 0 || (std::fabs(value[i]) < std::fabs(value[i - 1]) && same_side(i - 1))) &&
        (i == kGrid || (std::fabs(value[i]) < std::fabs(value[i + 1]) && same_side(i + 1)));
    if (local_min && std::fabs(value[i]) < kNearRoot) return j;
  }
  for (int i = 0; i < kGrid; ++i) {
    if ((value[i] > 0) == (value[i + 1] > 0)) continue;
    double lo = t_max * i / kGrid, hi = t_max * (i + 1) / kGrid;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((det(mid) > 0) == (value[i] > 0) ? lo : hi) = mid;
    }
    const double root = 0.5 * (lo + hi);
    if (root < 1e-3 || root > t_max - 1e-3) return j;
    constexpr double h = 1e-6;
    if (std::fabs(det(root + h) - det(root - h)) / (2 * h) < kSteep) return j;
    const double margin = inclusion_margin(q.type, q.at(root));
    if (!(std::fabs(margin) >= kMargin)) return j;  // NaN included
    if (margin > 0 && !j.contact) {
      j.contact = true;
      j.toi = root;
    }
  }
  j.clear = true;
  return j;
}

void check_random_pairs(QueryType type, std::uint64_t seed) {
  Random rng(seed);
  const std::uint64_t count = scaled_count(3000);
  const std::uint64_t floor = at_least(scaled_count(40), 10);
  std::uint64_t contacts = 0, gaps = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    RandomPair q = random_pair(rng, type);
    if (i % 2 == 0) aim(q, rng);
    const double t_max = i % 4 == 3 ? 0.75 : 1.0;
    const Judgement j = judge(q, t_max);
    if (!j.clear) continue;
    SCOPED_TRACE("query " + std::to_string(i) + " of seed " + std::to_string(seed) + ", " +
                 to_string(type) + ", t_max " + std::to_string(t_max));
    const RigidCcdResult certified = q.decide(mode_options(Mode::filtered, t_max));
    const RigidCcdResult rough = q.decide(mode_options(Mode::float_only, t_max));
    // The judgement from the positions agrees with the certified answer (a check of the
    // judgement itself), and so does float_only.
    ASSERT_EQ(certified.ccd.collides, j.contact);
    EXPECT_EQ(rough.ccd.collides, certified.ccd.collides);
    EXPECT_EQ(rough.ccd.decided_by, Stage::float_only);
    EXPECT_EQ(rough.ccd.toi_lo, rough.ccd.toi_hi);
    EXPECT_EQ(rough.has_time, certified.has_time);
    if (certified.ccd.collides) {
      ++contacts;
      EXPECT_NEAR(certified.ccd.toi_lo, j.toi, 1e-9);
      EXPECT_LE(std::fabs(rough.ccd.toi_lo - certified.ccd.toi_lo), 1e-9 * certified.ccd.toi_lo);
      if (rough.has_time) {
        EXPECT_LE(rough.time_lo, rough.time_hi);
        EXPECT_NEAR(rough.time_lo, certified.time_lo, 1e-8);
      }
    } else {
      ++gaps;
      EXPECT_EQ(rough.ccd.toi_lo, kNoContactToi);
      EXPECT_EQ(rough.ccd.toi_hi, kNoContactToi);
    }
  }
  std::cout << "[ counts   ] " << to_string(type) << ": " << contacts << " clear contacts, "
            << gaps << " clear gaps of " << count << " random pairs\n";
  EXPECT_GE(contacts, floor);
  EXPECT_GE(gaps, floor);
}

TEST(RigidFloatOnly, AgreesOnWellConditionedVertexFacePairs) {
  check_random_pairs(QueryType::vertex_face, test_seed("rigid float_only vertex-face"));
}

TEST(RigidFloatOnly, AgreesOnWellConditionedEdgeEdgePairs) {
  check_random_pairs(QueryType::edge_edge, test_seed("rigid float_only edge-edge") + 1);
}

// ---------------------------------------------------------------------------------------------
// A scene with a rigid body in Mode::float_only

/// A generic scene: a cube (its corners turned off the axes) turning and translating through a
/// tilted static sheet, and a deformable pair of triangles falling across the cube's path.
Scene well_conditioned_scene() {
  Scene scene;
  Positions cube(8, 3);
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  RigidMotion tilt;  // a fixed generic orientation of the cube, applied in doubles
  tilt.cayley = {0.17, -0.23, 0.11};
  for (int i = 0; i < 8; ++i)
    cube.row(i) = position_at(tilt, Vector3d(corners[i][0], corners[i][1], corners[i][2]), 1.0)
                      .transpose() +
                  Eigen::RowVector3d(-0.53, -0.47, 1.31);
  Triangles cube_faces(12, 3);
  cube_faces << 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7,
      2, 7, 6, 3, 0, 4, 3, 4, 7;
  const MeshId body = scene.add_rigid_body(cube, cube_faces);
  RigidMotion motion;
  motion.pivot = {0.03, -0.02, 1.8};
  motion.translation = {0.21, 0.13, -2.3};
  motion.cayley = {0.31, -0.42, 0.27};
  scene.set_rigid_motion(body, motion);

  // A 5 x 5-vertex sheet about z = 0.1, tilted, its vertices jittered (fixed values).
  constexpr int n = 5;
  Positions sheet(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      const double x = -1.5 + 3.0 * i / (n - 1) + 0.013 * ((i * 7 + k * 3) % 5 - 2);
      const double y = -1.5 + 3.0 * k / (n - 1) + 0.011 * ((i * 3 + k * 5) % 7 - 3);
      sheet.row(i * n + k) << x, y, 0.1 + 0.07 * x - 0.05 * y + 0.009 * ((i + 2 * k) % 3 - 1);
    }
  Triangles sheet_faces(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int k = 0; k + 1 < n; ++k) {
      const int v = i * n + k;
      sheet_faces.row(f++) << v, v + n, v + n + 1;
      sheet_faces.row(f++) << v, v + n + 1, v + 1;
    }
  scene.add_static_mesh(sheet, sheet_faces);

  Positions flap_start(4, 3), flap_end(4, 3);
  flap_start << -0.41, -0.77, 1.63, 0.52, -0.69, 1.71, 0.47, 0.38, 1.58, -0.36, 0.29, 1.67;
  flap_end = flap_start;
  flap_end.col(0).array() += 0.37;
  flap_end.col(2).array() -= 1.93;
  Triangles flap_faces(2, 3);
  flap_faces << 0, 1, 2, 0, 2, 3;
  const MeshId flap = scene.add_mesh(flap_start, flap_faces);
  scene.set_motion(flap, flap_start, flap_end);
  return scene;
}

TEST(RigidFloatOnly, SceneWithARigidBodyRunsAndFindsTheSameContacts) {
  Scene scene = well_conditioned_scene();
  SceneOptions certified;
  certified.self_collision = false;
  SceneOptions rough = certified;
  rough.ccd.mode = Mode::float_only;
  const SceneResult want = scene.find_contacts(certified);
  const SceneResult got = scene.find_contacts(rough);
  ASSERT_GT(want.contacts.size(), 10u);
  bool rigid_pair = false, linear_pair = false;
  ASSERT_EQ(got.contacts.size(), want.contacts.size());
  for (std::size_t i = 0; i < want.contacts.size(); ++i) {
    const SceneContact &w = want.contacts[i], &g = got.contacts[i];
    ASSERT_TRUE(g.pair == w.pair) << i;
    EXPECT_EQ(g.toi_lo, g.toi_hi);
    EXPECT_LE(std::fabs(g.toi_lo - w.toi_lo), 1e-9 * w.toi_lo) << i;
    EXPECT_EQ(g.has_time, w.has_time);
    const bool involves_rigid =
        scene.is_rigid(w.pair.first_mesh) || scene.is_rigid(w.pair.second_mesh);
    (involves_rigid ? rigid_pair : linear_pair) = true;
  }
  EXPECT_TRUE(rigid_pair);
  EXPECT_TRUE(linear_pair);
  // The earliest contact too, through earliest_contact's pruned search.
  const EarliestContact first = scene.earliest_contact(rough);
  ASSERT_TRUE(first.collides);
  EXPECT_TRUE(first.contact.pair == want.earliest.pair);
  EXPECT_LE(std::fabs(first.contact.toi_lo - want.earliest.toi_lo), 1e-9);
  EXPECT_TRUE(first.contact.pair == got.earliest.pair);
  EXPECT_EQ(first.contact.toi_lo, got.earliest.toi_lo);
}

}  // namespace
}  // namespace exactccd::test
