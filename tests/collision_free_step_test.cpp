// The collision-free step (exactccd/step.hpp, proofs/api_reductions.md#collision-free-step),
// checked against CGAL's exact kernel, which shares no code with the library: the squared
// distance at t = 0 decides starts_within, and at rational instants of [0, step] (the step's
// end included) it is at least effective_separation^2 and more than min_separation^2. The
// rational exact path (Mode::exact) confirms the whole interval and, when the step is
// limited, that the first time within effective_separation lies at or after it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/step.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;

VertexFaceQuery vertex_face_of(const RationalQuery& q) {
  return {to_vector(q.points[0]), to_vector(q.points[1]), to_vector(q.points[2]),
          to_vector(q.points[3]), to_vector(q.points[4]), to_vector(q.points[5]),
          to_vector(q.points[6]), to_vector(q.points[7])};
}

EdgeEdgeQuery edge_edge_of(const RationalQuery& q) {
  return {to_vector(q.points[0]), to_vector(q.points[1]), to_vector(q.points[2]),
          to_vector(q.points[3]), to_vector(q.points[4]), to_vector(q.points[5]),
          to_vector(q.points[6]), to_vector(q.points[7])};
}

StepResult step_of(const RationalQuery& q, const StepOptions& o) {
  return q.type == QueryType::vertex_face ? collision_free_step(vertex_face_of(q), o)
                                          : collision_free_step(edge_edge_of(q), o);
}

mpq_class squared(double x) { return mpq_class(x) * mpq_class(x); }

/// Every promise of StepResult, against CGAL and the rational exact path.
void expect_certified_step(const RationalQuery& q, const StepOptions& o, const StepResult& r) {
  const double delta = o.min_separation;
  ASSERT_GE(r.step, 0.0);
  ASSERT_LE(r.step, o.t_max);
  EXPECT_GE(r.effective_separation, delta);
  EXPECT_EQ(r.starts_within, cgal_squared_distance_at(q, 0) <= squared(delta));
  if (r.starts_within) {
    EXPECT_EQ(r.step, 0.0);
    EXPECT_TRUE(r.limited);
    return;
  }
  if (!r.limited) EXPECT_EQ(r.step, o.t_max);
  // The distance at rational instants of [0, step], its end included.
  const mpq_class step(r.step);
  for (int k = 0; k <= 8; ++k) {
    const mpq_class t = step * k / 8;
    const mpq_class d2 = cgal_squared_distance_at(q, t);
    EXPECT_GE(d2, squared(r.effective_separation)) << "at t = " << t.get_d();
    EXPECT_GT(d2, squared(delta)) << "at t = " << t.get_d();
  }
  // The whole of [0, step]: never within delta (rational exact path).
  CcdOptions exact;
  exact.mode = Mode::exact;
  exact.min_separation = delta;
  exact.t_max = r.step;
  EXPECT_FALSE(exact_ccd(q, exact).collides);
  // Limited: the first time within delta' is in [step, t_max]; otherwise there is none.
  exact.min_separation = r.effective_separation;
  exact.t_max = o.t_max;
  const CcdResult at_effective = exact_ccd(q, exact);
  EXPECT_EQ(at_effective.collides, r.limited);
  if (r.limited) EXPECT_GE(at_effective.toi_hi, r.step);
}

/// A vertex above a triangle, or a segment above another, at a gap from 0 to 0.5, moving by
/// random displacements that often cross.
RationalQuery approaching_query(std::mt19937_64& rng, QueryType type) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double gaps[5] = {0.0, 0x1p-40, 1e-3, 0.1, 0.5};
  const double gap = gaps[rng() % 5];
  std::array<Vector3d, 8> x;
  if (type == QueryType::vertex_face) {
    x[1] = {0, 0, 0}, x[2] = {1, 0, 0}, x[3] = {0, 1, 0};
    x[0] = {0.25, 0.25, gap};
    x[4] = x[0] + Vector3d(0.25 * u(rng), 0.25 * u(rng), -2 * gap - std::abs(u(rng)));
  } else {
    x[0] = {-1, 0, 0}, x[1] = {1, 0, 0};
    x[2] = {0, -1, gap}, x[3] = {0.5, 1, gap};
    x[4] = x[0] + Vector3d(0.25 * u(rng), 0.25 * u(rng), 0.5 * u(rng));
  }
  for (int i = 1; i < 4; ++i) x[4 + i] = x[i] + Vector3d(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
  if (type == QueryType::edge_edge) x[5] = x[1] + (x[4] - x[0]);
  RationalQuery q{type, {}};
  for (int i = 0; i < 8; ++i)
    q.points[i] = {mpq_class(x[i].x()), mpq_class(x[i].y()), mpq_class(x[i].z())};
  return q;
}

TEST(CollisionFreeStep, CertifiedOnApproachingQueries) {
  std::mt19937_64 rng(test_seed("collision_free_step"));
  int limited = 0, free = 0, within = 0, margin = 0;
  for (int n = 0; n < 160; ++n) {
    const QueryType type = n % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const RationalQuery q = approaching_query(rng, type);
    for (const double delta : {0.0, 1e-4, 0x1p-40})
      for (const double s : {0.8, 0.5, 1.0}) {
        StepOptions o;
        o.min_separation = delta;
        o.conservative_rescaling = s;
        o.t_max = n % 7 == 0 ? 0.5 : 1.0;
        SCOPED_TRACE(describe(q) + " delta " + std::to_string(delta) + " s " +
                     std::to_string(s));
        const StepResult r = step_of(q, o);
        expect_certified_step(q, o, r);
        within += r.starts_within;
        limited += r.limited && !r.starts_within;
        free += !r.limited;
        margin += r.effective_separation > delta;
        if (s == 1.0) EXPECT_EQ(r.effective_separation, delta);
      }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(limited, 100);
  EXPECT_GT(free, 20);
  EXPECT_GT(within, 20);
  EXPECT_GT(margin, 100);
}

TEST(CollisionFreeStep, CertifiedOnTheSampleQueries) {
  const auto& all = sample_queries();
  int n = 0;
  for (std::size_t i = 0; i < all.size(); i += 97) {
    const RationalQuery& q = all[i].query;
    if (!all_coordinates_are_doubles(q)) continue;
    for (const double delta : {0.0, 1e-6}) {
      SCOPED_TRACE(all[i].file + ":" + std::to_string(all[i].line) + " delta " +
                   std::to_string(delta));
      StepOptions o;
      o.min_separation = delta;
      expect_certified_step(q, o, step_of(q, o));
      ++n;
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(n, 20);
}

// ipc-toolkit's "Repeated CCD": step to the returned time, start the next query at the
// positions there (rounded to doubles, as a simulator stores them), and ask again. With the
// exact first time within delta as the step the second query starts at contact; with the
// collision-free step every step is positive and the pair never comes within delta.
TEST(CollisionFreeStep, RepeatedStepsNeverReachContact) {
  for (const double delta : {0.0, 1e-3}) {
    Vector3d p0(0.25, 0.25, 0.5);
    const Vector3d p1(0.3, 0.2, -1.0), a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    for (int k = 0; k < 12; ++k) {
      const VertexFaceQuery q{p0, a, b, c, p1, a, b, c};
      StepOptions o;
      o.min_separation = delta;
      const StepResult r = collision_free_step(q, o);
      ASSERT_FALSE(r.starts_within) << "step " << k;
      ASSERT_TRUE(r.limited);
      ASSERT_GT(r.step, 0.0) << "step " << k;
      p0 = (1 - r.step) * p0 + r.step * p1;
      ASSERT_GT(p0.z(), delta) << "step " << k;
    }
    // The gap shrank geometrically (to 1 - s = 0.2 of itself each time) but never closed. (Not
    // for ever: after about 25 such steps it is below the doubles' spacing at 1e-3, and the
    // rounded positions, not the step, close it.)
    EXPECT_LT(p0.z() - delta, 1e-6);
  }
}

// ipc-toolkit's "Repeated CCD", as its test runs it: step to the returned time, form the
// positions there in doubles as x0 + step (x1 - x0), and ask again over the motion from the
// start to them. The rounding slack keeps that second motion beyond delta': not limited, step 1.
TEST(CollisionFreeStep, AskingAgainUpToTheRoundedStepIsNotLimited) {
  std::mt19937_64 rng(test_seed("collision_free_step_repeat"));
  int repeated = 0;
  for (int n = 0; n < 200; ++n) {
    const QueryType type = n % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const RationalQuery q = approaching_query(rng, type);
    StepOptions o;
    o.min_separation = n % 3 == 0 ? 1e-4 : 0.0;
    o.conservative_rescaling = n % 4 == 0 ? 1.0 : 0.8;
    const StepResult r = step_of(q, o);
    if (!r.limited || r.starts_within) continue;
    RationalQuery again = q;
    for (int i = 0; i < 4; ++i) {
      const Vector3d x0 = to_vector(q.points[i]), x1 = to_vector(q.points[4 + i]);
      const Vector3d xt = (x1 - x0) * r.step + x0;
      again.points[4 + i] = {mpq_class(xt.x()), mpq_class(xt.y()), mpq_class(xt.z())};
    }
    SCOPED_TRACE(describe(q) + " step " + std::to_string(r.step));
    const StepResult second = step_of(again, o);
    EXPECT_FALSE(second.limited);
    EXPECT_EQ(second.step, 1.0);
    EXPECT_EQ(second.effective_separation, r.effective_separation);
    ++repeated;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(repeated, 80);
}

// max_margin caps the margin (ipc-toolkit's Tight Inclusion caps it at 1e-4): points 1 apart
// meeting at t = 1/2 step to 0.4 by the rule (s = 0.8 keeps 0.2 of the gap), to just before
// 1/2 - 5e-5 with the cap.
TEST(CollisionFreeStep, MaxMarginCapsTheMargin) {
  const PointPointQuery q{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0),
                          Vector3d(1, 0, 0)};
  StepResult r = collision_free_step(q);
  EXPECT_TRUE(r.limited);
  EXPECT_NEAR(r.step, 0.4, 1e-12);
  EXPECT_LT(r.step, 0.4);
  StepOptions o;
  o.max_margin = 1e-4;
  r = collision_free_step(q, o);
  EXPECT_EQ(r.effective_separation, 1e-4);
  EXPECT_NEAR(r.step, 0.5 - 0.5e-4, 1e-12);
  EXPECT_LT(r.step, 0.5 - 0.5e-4);
}

TEST(CollisionFreeStep, PointKindsAreTheirEdgeEdgeQueries) {
  std::mt19937_64 rng(test_seed("collision_free_step_points"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto v = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
  for (int n = 0; n < 100; ++n) {
    StepOptions o;
    o.min_separation = n % 2 ? 0.05 : 0.0;
    const Vector3d p0 = v(), e0 = v(), e1 = v(), p1 = v(), f0 = v(), f1 = v();
    const StepResult pe = collision_free_step(PointEdgeQuery{p0, e0, e1, p1, f0, f1}, o);
    const StepResult ee = collision_free_step(EdgeEdgeQuery{p0, p0, e0, e1, p1, p1, f0, f1}, o);
    EXPECT_EQ(pe.step, ee.step);
    EXPECT_EQ(pe.limited, ee.limited);
    EXPECT_EQ(pe.effective_separation, ee.effective_separation);
    const StepResult pp = collision_free_step(PointPointQuery{p0, e0, p1, f0}, o);
    const StepResult pp_ee =
        collision_free_step(EdgeEdgeQuery{p0, p0, e0, e0, p1, p1, f0, f0}, o);
    EXPECT_EQ(pp.step, pp_ee.step);
    EXPECT_EQ(pp.limited, pp_ee.limited);
    // 2D: the 3D query in z = 0.
    const auto flat = [](const Vector3d& x) { return Eigen::Vector2d(x.x(), x.y()); };
    const auto z0 = [](const Vector3d& x) { return Vector3d(x.x(), x.y(), 0.0); };
    const StepResult pe2 = collision_free_step(
        PointEdgeQuery2d{flat(p0), flat(e0), flat(e1), flat(p1), flat(f0), flat(f1)}, o);
    const StepResult pe3 =
        collision_free_step(PointEdgeQuery{z0(p0), z0(e0), z0(e1), z0(p1), z0(f0), z0(f1)}, o);
    EXPECT_EQ(pe2.step, pe3.step);
    EXPECT_EQ(pe2.limited, pe3.limited);
    const StepResult pp2 =
        collision_free_step(PointPointQuery2d{flat(p0), flat(e0), flat(p1), flat(e0)}, o);
    const StepResult pp3 = collision_free_step(PointPointQuery{z0(p0), z0(e0), z0(p1), z0(e0)}, o);
    EXPECT_EQ(pp2.step, pp3.step);
  }
}

TEST(CollisionFreeStep, RigidStepIsCertifiedByTheExactRigidPath) {
  std::mt19937_64 rng(test_seed("collision_free_step_rigid"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int limited = 0;
  for (int n = 0; n < 40; ++n) {
    RigidMotion turn;
    turn.pivot = Vector3d(u(rng), u(rng), u(rng));
    turn.cayley = Vector3d(u(rng), u(rng), u(rng));
    turn.translation = Vector3d(0, 0, -1) + 0.3 * Vector3d(u(rng), u(rng), u(rng));
    const RigidVertexFaceQuery q{Vector3d(0.25, 0.25, 0.4), Vector3d(-1, -1, 0),
                                 Vector3d(2, -1, 0),        Vector3d(-1, 2, 0),
                                 SideMotion::of(turn),      SideMotion::of({})};
    StepOptions o;
    o.min_separation = n % 2 ? 1e-3 : 0.0;
    const StepResult r = collision_free_step(q, o);
    ASSERT_FALSE(r.starts_within);
    limited += r.limited;
    CcdOptions exact;
    exact.mode = Mode::exact;
    exact.min_separation = r.effective_separation;
    const RigidCcdResult whole = vertex_face_ccd(q, exact);
    EXPECT_EQ(whole.ccd.collides, r.limited);
    if (r.limited) EXPECT_GE(whole.ccd.toi_hi, r.step);
    if (!r.limited) EXPECT_EQ(r.step, 1.0);
    // Never within delta on [0, step].
    exact.min_separation = o.min_separation;
    exact.t_max = r.step;
    EXPECT_FALSE(vertex_face_ccd(q, exact).ccd.collides);
  }
  EXPECT_GT(limited, 10);
}

TEST(CollisionFreeStep, ZeroTMaxAndTouchingStarts) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), p(0.25, 0.25, 0);
  StepOptions o;
  // Touching at the start: step 0, exact.
  StepResult r = collision_free_step(VertexFaceQuery{p, a, b, c, p + Vector3d(0, 0, 1), a, b, c});
  EXPECT_TRUE(r.starts_within);
  EXPECT_EQ(r.step, 0.0);
  EXPECT_EQ(r.effective_separation, 0.0);
  // 2^-80 above, falling through: a positive step, and not starting within.
  const Vector3d above(0.25, 0.25, 0x1p-80);
  r = collision_free_step(VertexFaceQuery{above, a, b, c, p - Vector3d(0, 0, 1), a, b, c});
  EXPECT_FALSE(r.starts_within);
  EXPECT_TRUE(r.limited);
  EXPECT_GT(r.step, 0.0);
  EXPECT_GT(r.effective_separation, 0.0);
  // t_max = 0: the state at the start.
  o.t_max = 0.0;
  r = collision_free_step(VertexFaceQuery{above, a, b, c, p - Vector3d(0, 0, 1), a, b, c}, o);
  EXPECT_FALSE(r.limited);
  EXPECT_EQ(r.step, 0.0);
}

// A distance estimate far from the truth only changes delta'. Points 2e308 apart (their distance
// in doubles overflows to infinity): delta' is the largest double, below the true distance.
// A segment 2e308 long (its estimate is NaN): no margin, delta' = delta, still a safe step.
TEST(CollisionFreeStep, HugeCoordinatesStayFiniteAndCertified) {
  const Vector3d far(-1e308, 0, 0), near(1e308, 0, 0);
  StepResult r = collision_free_step(PointPointQuery{near, far, far, far});
  EXPECT_TRUE(r.limited);
  EXPECT_EQ(r.effective_separation, std::numeric_limits<double>::max());
  EXPECT_GT(r.step, 0.05);
  EXPECT_LT(r.step, 0.15);
  const Vector3d p(0, 1e300, 0), e0(-1e308, 0, 0), e1(1e308, 0, 0);
  r = collision_free_step(PointEdgeQuery{p, e0, e1, Vector3d(0, -1e300, 0), e0, e1});
  EXPECT_TRUE(r.limited);
  EXPECT_FALSE(r.starts_within);
  EXPECT_GT(r.step, 0.0);
  EXPECT_LT(r.step, 0.5);
}

TEST(CollisionFreeStep, OptionsOutsideTheirDomainAreErrors) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), p(0.25, 0.25, 1);
  const VertexFaceQuery q{p, a, b, c, p, a, b, c};
  const auto error_of = [&](StepOptions o) -> std::string {
    try {
      collision_free_step(q, o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  StepOptions o;
  o.conservative_rescaling = 0.0;
  EXPECT_EQ(error_of(o), "exactccd: conservative_rescaling must lie in (0, 1], got 0");
  o.conservative_rescaling = 1.5;
  EXPECT_EQ(error_of(o), "exactccd: conservative_rescaling must lie in (0, 1], got 1.5");
  o.conservative_rescaling = std::nan("");
  EXPECT_NE(error_of(o), "");
  o = {};
  o.max_margin = -1;
  EXPECT_EQ(error_of(o), "exactccd: max_margin must be >= 0 (+infinity: no cap), got -1");
  o.max_margin = std::nan("");
  EXPECT_NE(error_of(o), "");
  o = {};
  o.t_max = 2;
  EXPECT_EQ(error_of(o), "exactccd: t_max must lie in [0, 1], got 2");
  o = {};
  o.min_separation = -1;
  EXPECT_EQ(error_of(o), "exactccd: min_separation must be finite and >= 0, got -1");
  const VertexFaceQuery bad{Vector3d(std::nan(""), 0, 0), a, b, c, p, a, b, c};
  EXPECT_THROW(collision_free_step(bad), std::invalid_argument);
}

}  // namespace
}  // namespace exactccd::test
