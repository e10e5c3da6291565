// Rigid motion with a minimum separation (CcdOptions::min_separation > 0 on RigidVertexFaceQuery /
// RigidEdgeEdgeQuery): the default path against the exact procedure, bit for bit; CGAL's exact
// squared distances at sampled rational instants, on positions computed here from the public
// motion's definition (shares no reduction with exactccd); translations against the linear
// minimum-separation pipeline; a pure rotation with a closed-form answer; t_max and toi_width.
// PROOF: proofs/min_separation.md#rigid-separation, proofs/min_separation.md#rigid-separation-filter
#include <CGAL/Simple_cartesian.h>
#include <CGAL/mpq_class.h>
#include <CGAL/squared_distance_3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "corpus/rigid_queries.hpp"
#include "exact/arithmetic/dyadic.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/rigid.hpp"
#include "test_scale.hpp"
#include "test_support.hpp"

namespace exactccd {
namespace {

using Eigen::Vector3d;
using Kernel = CGAL::Simple_cartesian<mpq_class>;
using Point = Kernel::Point_3;

CcdOptions with(Mode mode, double delta, double t_max = 1.0, double toi_width = 0.0) {
  CcdOptions o;
  o.mode = mode;
  o.min_separation = delta;
  o.t_max = t_max;
  o.toi_width = toi_width;
  return o;
}

/// A vertex's position at the rational s, from the definition of the public motion
/// (rigid.hpp): a turn by the Cayley vector s q about the pivot, the pivot moved by s d; or the
/// straight line to the side's end.
Point position(const SideMotion& side, const Vector3d& x0, int index, const mpq_class& s) {
  auto q = [](double v) { return mpq_class(v); };
  if (side.kind == PathKind::linear) {
    const Vector3d& x1 = side.linear_end[index];
    return {q(x0.x()) + s * (q(x1.x()) - q(x0.x())), q(x0.y()) + s * (q(x1.y()) - q(x0.y())),
            q(x0.z()) + s * (q(x1.z()) - q(x0.z()))};
  }
  const RigidMotion& m = side.rigid;
  const mpq_class v[3] = {s * q(m.cayley.x()), s * q(m.cayley.y()), s * q(m.cayley.z())};
  const mpq_class r[3] = {q(x0.x()) - q(m.pivot.x()), q(x0.y()) - q(m.pivot.y()),
                          q(x0.z()) - q(m.pivot.z())};
  const mpq_class vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const mpq_class vr = v[0] * r[0] + v[1] * r[1] + v[2] * r[2];
  const mpq_class cross[3] = {v[1] * r[2] - v[2] * r[1], v[2] * r[0] - v[0] * r[2],
                              v[0] * r[1] - v[1] * r[0]};
  mpq_class out[3];
  for (int k = 0; k < 3; ++k)
    out[k] = q(m.pivot[k]) + s * q(m.translation[k]) +
             ((1 - vv) * r[k] + 2 * v[k] * vr + 2 * cross[k]) / (1 + vv);
  return {out[0], out[1], out[2]};
}

mpq_class squared_distance_at(const RigidVertexFaceQuery& q, const mpq_class& s) {
  return CGAL::squared_distance(
      position(q.vertex, q.p, 0, s),
      Kernel::Triangle_3(position(q.face, q.a, 0, s), position(q.face, q.b, 1, s),
                         position(q.face, q.c, 2, s)));
}

mpq_class squared_distance_at(const RigidEdgeEdgeQuery& q, const mpq_class& s) {
  return CGAL::squared_distance(
      Kernel::Segment_3(position(q.edge_a, q.ea0, 0, s), position(q.edge_a, q.ea1, 1, s)),
      Kernel::Segment_3(position(q.edge_b, q.eb0, 0, s), position(q.edge_b, q.eb1, 1, s)));
}

RigidCcdResult ccd(const RigidVertexFaceQuery& q, const CcdOptions& o) {
  return vertex_face_ccd(q, o);
}
RigidCcdResult ccd(const RigidEdgeEdgeQuery& q, const CcdOptions& o) { return edge_edge_ccd(q, o); }

struct Tally {
  int queries = 0, contacts = 0, exact_path = 0, within_checks = 0, before_checks = 0;
};

/// The default path equals the exact procedure; CGAL's distances agree with the answer at the
/// sampled instants (never within delta before toi_lo; within at toi_hi when the first instant
/// is entered transversally, as random data does with probability one; within at an exact TOI).
template <class Query>
void check(const Query& q, double delta, const CcdOptions& base, Tally* tally,
           const std::string& what) {
  CcdOptions exact_options = base, filtered_options = base;
  exact_options.mode = Mode::exact;
  exact_options.min_separation = filtered_options.min_separation = delta;
  filtered_options.mode = Mode::filtered;
  const CcdResult e = ccd(q, exact_options).ccd;
  const CcdResult f = ccd(q, filtered_options).ccd;
  ++tally->queries;
  tally->contacts += e.collides;
  tally->exact_path += f.decided_by == Stage::exact;
  ASSERT_TRUE(test::same_answer(e, f))
      << what << ": exact " << e.collides << " [" << e.toi_lo << ", " << e.toi_hi
      << "], filtered " << f.collides << " [" << f.toi_lo << ", " << f.toi_hi << "] by "
      << to_string(f.decided_by);
  const mpq_class delta2 = mpq_class(delta) * mpq_class(delta);
  constexpr int kSamples = 16;
  for (int k = 0; k <= kSamples; ++k) {
    const mpq_class s = mpq_class(k, kSamples) * mpq_class(base.t_max);
    if (e.collides && cmp(s, mpq_class(e.toi_lo)) >= 0) break;
    ++tally->before_checks;
    ASSERT_GT(cmp(squared_distance_at(q, s), delta2), 0) << what << ": within delta at " << s;
  }
  if (!e.collides) return;
  if (e.toi_lo < e.toi_hi) {
    ++tally->before_checks;
    ASSERT_GT(cmp(squared_distance_at(q, mpq_class(e.toi_lo)), delta2), 0) << what;
  }
  ++tally->within_checks;
  ASSERT_LE(cmp(squared_distance_at(q, mpq_class(e.toi_hi)), delta2), 0)
      << what << ": not within delta at toi_hi " << e.toi_hi;
}

TEST(RigidMinSeparation, FilteredEqualsExactAndCgalAgreesOnRandomPairs) {
  const std::uint64_t seed = test::test_seed("RigidMinSeparation.RandomPairs");
  const std::size_t n = test::at_least(test::scaled_count(10), 4);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Tally tally;
  int configuration = 0;
  for (rigid_queries::OtherMotion other :
       {rigid_queries::OtherMotion::rigid, rigid_queries::OtherMotion::linear,
        rigid_queries::OtherMotion::rest})
    for (double delta : {1e-3, 0.05, 0.3}) {
      rigid_queries::RigidQueryOptions o;
      o.other = other;
      const std::uint64_t s = seed + static_cast<std::uint64_t>(++configuration);
      const auto vf = rigid_queries::random_rigid_vertex_face(s, n, o);
      const auto ee = rigid_queries::random_rigid_edge_edge(s, n, o);
      for (std::size_t i = 0; i < n; ++i) {
        CcdOptions base;
        if (i % 3 == 1) base.t_max = 0.25 + 0.75 * u(rng);
        const std::string what = "configuration " + std::to_string(configuration) + " delta " +
                                 std::to_string(delta) + " query " + std::to_string(i);
        check(vf[i], delta, base, &tally, "vertex-face " + what);
        check(ee[i], delta, base, &tally, "edge-edge " + what);
        if (HasFatalFailure()) return;
      }
    }
  std::printf("%d queries, %d contacts, %d by the exact path; %d within and %d before checks\n",
              tally.queries, tally.contacts, tally.exact_path, tally.within_checks,
              tally.before_checks);
  EXPECT_GT(tally.contacts, tally.queries / 5);
  EXPECT_LT(tally.contacts, tally.queries);
  EXPECT_LT(tally.exact_path, tally.queries / 4);  // the filters decide most
}

/// Translations only (q = 0): the rigid query is the linear one, which the linear pipeline
/// decides with its own reduction (integer coordinates, degree <= 6).
TEST(RigidMinSeparation, TranslationsEqualTheLinearPipeline) {
  std::mt19937_64 rng(test::test_seed("RigidMinSeparation.Translations"));
  // Coordinates on a grid of 2^-12: every sum below is exact, so the linear query's ends are
  // the translates themselves.
  std::uniform_int_distribution<int> grid(-4096, 4096);
  auto point = [&]() -> Vector3d { return Vector3d(grid(rng), grid(rng), grid(rng)) * 0x1p-12; };
  const int n = static_cast<int>(test::at_least(test::scaled_count(60), 20));
  int contacts = 0, decided_by_search = 0;
  for (int i = 0; i < n; ++i) {
    const double delta = i % 2 ? 0.1 : 0.01;
    RigidVertexFaceQuery r;
    r.p = point();
    r.a = 0.5 * point();
    r.b = 0.5 * point();
    r.c = 0.5 * point();
    RigidMotion m;
    m.pivot = point();
    m.translation = 2.0 * (r.a + r.b - 2.0 * r.p) + 0.25 * point();  // through the triangle, mostly
    r.vertex = SideMotion::of(m);
    std::array<Vector3d, 3> face_end;
    if (i % 3 == 0) {
      r.face.kind = PathKind::linear;
      r.face.linear_end = {r.a + 0.25 * point(), r.b + 0.25 * point(), r.c + 0.25 * point()};
      face_end = r.face.linear_end;
    } else {
      RigidMotion f;
      f.pivot = point();
      f.translation = 0.5 * point();
      r.face = SideMotion::of(f);
      face_end = {r.a + f.translation, r.b + f.translation, r.c + f.translation};
    }
    const VertexFaceQuery l{r.p, r.a, r.b, r.c, r.p + m.translation,
                            face_end[0], face_end[1], face_end[2]};
    const CcdResult linear = vertex_face_ccd(l, with(Mode::filtered, delta));
    const CcdResult rigid = vertex_face_ccd(r, with(Mode::filtered, delta)).ccd;
    contacts += linear.collides;
    decided_by_search += linear.collides && linear.toi_lo > 0;
    ASSERT_TRUE(test::same_answer(linear, rigid))
        << "query " << i << ": linear " << linear.collides << " [" << linear.toi_lo << ", "
        << linear.toi_hi << "], rigid " << rigid.collides << " [" << rigid.toi_lo << ", "
        << rigid.toi_hi << "]";
  }
  std::printf("%d queries, %d contacts, %d after s = 0\n", n, contacts, decided_by_search);
  EXPECT_GT(decided_by_search, 0);
  EXPECT_LT(contacts, n);
}

/// A vertex on the unit circle about the z axis, turning by a quarter turn towards the wall
/// y = h: within delta first where sin(theta) = h - delta, theta(s) = 2 atan(s |q|).
TEST(RigidMinSeparation, PureRotationMeetsItsClosedForm) {
  for (const double delta : {0.25, 0.01, 1e-6}) {
    const double h = 0.75;
    RigidVertexFaceQuery q;
    q.p = Vector3d(1, 0, 0);
    q.vertex = SideMotion::of(RigidMotion::turn(Vector3d::Zero(), Vector3d(0, 0, 1), M_PI / 2));
    q.a = Vector3d(-4, h, -4);
    q.b = Vector3d(4, h, -4);
    q.c = Vector3d(0, h, 4);
    q.face = SideMotion::of(RigidMotion{});
    const RigidCcdResult r = vertex_face_ccd(q, with(Mode::filtered, delta));
    ASSERT_TRUE(r.ccd.collides) << delta;
    const double s_star = std::tan(std::asin(h - delta) / 2) / q.vertex.rigid.cayley.norm();
    EXPECT_LE(r.ccd.toi_lo, s_star * (1 + 1e-12)) << delta;
    EXPECT_GE(r.ccd.toi_hi, s_star * (1 - 1e-12)) << delta;
    EXPECT_TRUE(r.has_time);  // one side turns about a fixed axis, the other rests
    EXPECT_NEAR(r.time_lo, std::asin(h - delta) / (M_PI / 2), 1e-12) << delta;
    // Just outside delta at its closest: never within.
    q.a.y() = q.b.y() = q.c.y() = 1 + 2 * delta;
    EXPECT_FALSE(vertex_face_ccd(q, with(Mode::filtered, delta)).ccd.collides);
    EXPECT_FALSE(vertex_face_ccd(q, with(Mode::exact, delta)).ccd.collides);
  }
}

/// Touching at s = 0 within delta, and exactly at distance delta at s = 0: the TOI is 0.
TEST(RigidMinSeparation, WithinAtTheStartIsTimeZero) {
  RigidEdgeEdgeQuery q;
  q.ea0 = Vector3d(-1, 0, 0);
  q.ea1 = Vector3d(1, 0, 0);
  q.eb0 = Vector3d(0, -1, 0.5);
  q.eb1 = Vector3d(0, 1, 0.5);
  q.edge_a = SideMotion::of(RigidMotion::turn(Vector3d::Zero(), Vector3d(0, 0, 1), 1.0));
  q.edge_b = SideMotion::of(RigidMotion{});
  for (const double delta : {0.5, 0.75}) {
    for (Mode mode : {Mode::filtered, Mode::exact}) {
      const CcdResult r = edge_edge_ccd(q, with(mode, delta)).ccd;
      ASSERT_TRUE(r.collides) << delta;
      EXPECT_EQ(r.toi_lo, 0.0);
      EXPECT_EQ(r.toi_hi, 0.0);
    }
  }
  EXPECT_FALSE(edge_edge_ccd(q, with(Mode::filtered, 0.25)).ccd.collides);
}

/// toi_width > 0: an enclosure of the exact tightest pair no wider than asked.
TEST(RigidMinSeparation, CoarseWidthEnclosesTheTightestPair) {
  const auto vf = rigid_queries::random_rigid_vertex_face(
      test::test_seed("RigidMinSeparation.Width"), test::at_least(test::scaled_count(20), 8));
  int contacts = 0;
  for (std::size_t i = 0; i < vf.size(); ++i) {
    const CcdResult e = vertex_face_ccd(vf[i], with(Mode::exact, 0.02)).ccd;
    const CcdResult f = vertex_face_ccd(vf[i], with(Mode::filtered, 0.02, 1.0, 0x1p-12)).ccd;
    ASSERT_EQ(e.collides, f.collides) << i;
    if (!f.collides) continue;
    ++contacts;
    EXPECT_LE(f.toi_lo, e.toi_lo) << i;
    EXPECT_GE(f.toi_hi, e.toi_hi) << i;
    EXPECT_LE(mpq_class(f.toi_hi) - mpq_class(f.toi_lo), mpq_class(0x1p-12)) << i;
  }
  EXPECT_GT(contacts, 0);
}

/// Degenerate and extreme pairs: a triangle collapsed to a segment or a point, parallel and
/// collinear edges, nothing moving, huge and tiny scales, delta far below and far above the
/// primitives' size: the default path (conservative advancement, pieces, tightening) equals the
/// exact procedure.
TEST(RigidMinSeparation, DegenerateAndExtremePairsEqualExact) {
  std::mt19937_64 rng(test::test_seed("RigidMinSeparation.Degenerate"));
  std::uniform_int_distribution<int> grid(-8, 8);
  auto point = [&]() -> Vector3d { return Vector3d(grid(rng), grid(rng), grid(rng)) * 0.125; };
  auto turning = [&](double angle) {
    return SideMotion::of(RigidMotion::turn(point(), Vector3d(grid(rng), grid(rng), 1), angle,
                                            point()));
  };
  int contacts = 0, queries = 0;
  for (int i = 0; i < static_cast<int>(test::at_least(test::scaled_count(40), 16)); ++i) {
    const double scale = std::ldexp(1.0, i % 4 == 0 ? 600 : (i % 4 == 1 ? -600 : 0));
    for (const double delta_factor : {0x1p-40, 0x1p-4, 4.0}) {
      RigidVertexFaceQuery vf;
      vf.p = point();
      vf.a = point();
      vf.b = i % 3 == 0 ? vf.a : point();                        // a segment or a point
      vf.c = i % 3 == 0 ? vf.a : (i % 3 == 1 ? Vector3d(2 * vf.b - vf.a) : point());  // collinear
      vf.vertex = i % 5 == 0 ? SideMotion::of(RigidMotion{}) : turning(0.5 + 0.1 * (i % 7));
      vf.face = i % 2 == 0 ? SideMotion::of(RigidMotion{}) : turning(-1.0);
      RigidEdgeEdgeQuery ee;
      ee.ea0 = point();
      ee.ea1 = point();
      const Vector3d shift = point();
      ee.eb0 = i % 3 == 2 ? Vector3d(ee.ea0 + 0.25 * shift) : point();  // parallel
      ee.eb1 = i % 3 == 2 ? Vector3d(ee.ea1 + 0.25 * shift) : point();
      ee.edge_a = vf.vertex;
      ee.edge_b = vf.face;
      auto scaled = [scale](SideMotion m) {
        m.rigid.pivot *= scale;
        m.rigid.translation *= scale;
        return m;
      };
      vf.p *= scale, vf.a *= scale, vf.b *= scale, vf.c *= scale;
      vf.vertex = scaled(vf.vertex), vf.face = scaled(vf.face);
      ee.ea0 *= scale, ee.ea1 *= scale, ee.eb0 *= scale, ee.eb1 *= scale;
      ee.edge_a = scaled(ee.edge_a), ee.edge_b = scaled(ee.edge_b);
      const double delta = delta_factor * scale;
      for (int kind = 0; kind < 2; ++kind) {
        const CcdResult e = kind == 0 ? vertex_face_ccd(vf, with(Mode::exact, delta)).ccd
                                      : edge_edge_ccd(ee, with(Mode::exact, delta)).ccd;
        const CcdResult f = kind == 0 ? vertex_face_ccd(vf, with(Mode::filtered, delta)).ccd
                                      : edge_edge_ccd(ee, with(Mode::filtered, delta)).ccd;
        ++queries;
        contacts += e.collides;
        ASSERT_TRUE(test::same_answer(e, f))
            << (kind == 0 ? "vertex-face " : "edge-edge ") << i << " delta " << delta
            << ": exact " << e.collides << " [" << e.toi_lo << ", " << e.toi_hi << "], filtered "
            << f.collides << " [" << f.toi_lo << ", " << f.toi_hi << "]";
      }
    }
  }
  EXPECT_GT(contacts, queries / 5);
  EXPECT_LT(contacts, queries);
}

/// The exact dyadic type of the exact signs at doubles: ring expressions of doubles of any
/// exponents, signed as over the rationals (a and b may be one object).
TEST(RigidMinSeparation, DyadicRingOperationsAreExact) {
  std::mt19937_64 rng(test::test_seed("RigidMinSeparation.Dyadic"));
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1000, 1000);
  auto draw = [&] { return std::ldexp(mantissa(rng), rng() % 3 ? exponent(rng) % 60 : exponent(rng)); };
  for (int i = 0; i < 2000; ++i) {
    const double a = draw(), b = draw(), c = draw(), d = draw();
    const exact::Dyadic x = exact::Dyadic(a) * exact::Dyadic(b) - exact::Dyadic(c) * exact::Dyadic(d) +
                            exact::Dyadic(c);
    const mpq_class r = mpq_class(a) * mpq_class(b) - mpq_class(c) * mpq_class(d) + mpq_class(c);
    ASSERT_EQ(x.sign(), sgn(r)) << a << " " << b << " " << c << " " << d;
    const exact::Dyadic y(a);
    EXPECT_EQ((y - y).sign(), 0);
    EXPECT_EQ((y + y).sign(), a > 0 ? 1 : (a < 0 ? -1 : 0));
    EXPECT_EQ((-(y * y)).sign(), a != 0 ? -1 : 0);
  }
  EXPECT_EQ((exact::Dyadic(0x1p-1074) - exact::Dyadic(0x1p1023) + exact::Dyadic(0x1p1023)).sign(), 1);
}

TEST(RigidMinSeparation, BadDeltaIsRefused) {
  RigidVertexFaceQuery q;
  q.a = Vector3d(1, 0, 0);
  q.b = Vector3d(0, 1, 0);
  q.c = Vector3d(0, 0, 1);
  for (const double bad : {-1.0, std::nan(""), double(INFINITY)})
    EXPECT_THROW(vertex_face_ccd(q, with(Mode::filtered, bad)), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace exactccd
