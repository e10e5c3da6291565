// Point-plane CCD (point_plane_ccd, proofs/point_plane.md#reduction). A static or translating
// plane spanned by integer points is the plane of a triangle far larger than the point's path,
// so the vertex-face query against that triangle (a different polynomial, the coplanarity
// cubic, and a different exact procedure) has the same contact set and the same distances:
// the answers must be equal, bit for bit, in every certified mode, with and without a minimum
// separation. Hand-made cases with known times (a rotating normal included), t_max = 0, the
// float_only comparison mode, and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <stdexcept>
#include <string>

#include "exactccd/ccd.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;

TEST(PointPlane, EqualsTheVertexFaceQueryOfAHugeTriangleInThePlane) {
  std::mt19937_64 rng(test_seed("point_plane"));
  std::uniform_int_distribution<int> small(-3, 3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int collisions = 0, count = 0;
  for (int n = 0; n < 300; ++n) {
    // Integer spanning vectors (not parallel) and an integer origin: every product exact.
    Vector3d s, r;
    do {
      s = Vector3d(small(rng), small(rng), small(rng));
      r = Vector3d(small(rng), small(rng), small(rng));
    } while (s.cross(r).isZero(0.0));
    const Vector3d o0(small(rng), small(rng), small(rng));
    const Vector3d shift = n % 3 == 0 ? Vector3d(small(rng), small(rng), small(rng))
                                      : Vector3d::Zero();  // a translating plane
    const Vector3d a = o0 - 1000 * s - 1000 * r, b = o0 + 2000 * s - 1000 * r,
                   c = o0 - 1000 * s + 2000 * r;
    const Vector3d normal = (b - a).cross(c - a);  // integers below 2^53: exact
    // The point starts near the plane and moves by up to 2 (dyadic: sometimes exactly onto it).
    const Vector3d p0 = o0 + 0.5 * u(rng) * s + 0.5 * u(rng) * r + 0.25 * u(rng) * normal / 9e6;
    const Vector3d p1 = n % 5 == 0 ? Vector3d(o0 + shift + 0.25 * s)
                                   : Vector3d(p0 + Vector3d(u(rng), u(rng), u(rng)));
    const PointPlaneQuery pp{p0, o0, normal, p1, o0 + shift, normal};
    const VertexFaceQuery vf{p0, a, b, c, p1, a + shift, b + shift, c + shift};
    for (const double delta : {0.0, 1e-3})
      for (const Mode mode : {Mode::filtered, Mode::exact}) {
        CcdOptions o;
        o.mode = mode;
        o.min_separation = delta;
        o.t_max = n % 4 == 0 ? 0.5 : 1.0;
        const CcdResult got = point_plane_ccd(pp, o), want = vertex_face_ccd(vf, o);
        SCOPED_TRACE("n " + std::to_string(n) + " delta " + std::to_string(delta) + " mode " +
                     to_string(mode));
        EXPECT_EQ(got.collides, want.collides);
        EXPECT_EQ(got.toi_lo, want.toi_lo);
        EXPECT_EQ(got.toi_hi, want.toi_hi);
        EXPECT_EQ(got.starts_within, want.starts_within);
        collisions += got.collides;
        ++count;
      }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(collisions, count / 4);
  EXPECT_LT(collisions, count * 3 / 4);
}

TEST(PointPlane, KnownTimes) {
  const Vector3d up(0, 0, 1), origin(0, 0, 0);
  // Falling from z = 1 to z = -1 onto the floor z = 0: t* = 1/2.
  CcdResult r = point_plane_ccd({Vector3d(5, 7, 1), origin, up, Vector3d(-3, 2, -1), origin, up});
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.5);
  EXPECT_EQ(r.toi_hi, 0.5);
  // The filter certifies it (a single crossing; the exact sign only at the double t* = 1/2),
  // and a crossing between two doubles, t* = 1/3, without the rational path.
  EXPECT_EQ(r.decided_by, Stage::exact_at_double);
  r = point_plane_ccd({Vector3d(0.5, 0.5, 0.05), origin, up, Vector3d(0.55, 0.5, -0.1), origin,
                       up});
  EXPECT_EQ(r.toi_lo, 0.33333333333333331);
  EXPECT_EQ(r.toi_hi, 0.33333333333333337);
  EXPECT_NE(r.decided_by, Stage::exact);
  // Within 0.25 of it first at t = 3/8.
  CcdOptions o;
  o.min_separation = 0.25;
  r = point_plane_ccd({Vector3d(5, 7, 1), origin, up, Vector3d(-3, 2, -1), origin, up}, o);
  EXPECT_EQ(r.toi_lo, 0.375);
  EXPECT_EQ(r.toi_hi, 0.375);
  // A plane rising from z = -1 to z = 1 under a point at rest at z = 0.5: t* = 3/4.
  r = point_plane_ccd({Vector3d(0, 0, 0.5), Vector3d(0, 0, -1), up, Vector3d(0, 0, 0.5),
                       Vector3d(0, 0, 1), up});
  EXPECT_EQ(r.toi_lo, 0.75);
  // A normal turning from +x to +z about the origin, the point (0, 0, 1) at rest:
  // f(t) = t, on the plane at the start only.
  r = point_plane_ccd({Vector3d(0, 0, 1), origin, Vector3d(1, 0, 0), Vector3d(0, 0, 1), origin,
                       up});
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.toi_hi, 0.0);
  EXPECT_TRUE(r.starts_within);
  // The normal turning from (1, 0, -1) to (1, 0, 1), the point (2, 0, 1) at rest:
  // f(t) = 2 + (2t - 1) > 0: never.
  r = point_plane_ccd({Vector3d(2, 0, 1), origin, Vector3d(1, 0, -1), Vector3d(2, 0, 1), origin,
                       Vector3d(1, 0, 1)});
  EXPECT_FALSE(r.collides);
  EXPECT_EQ(r.toi_lo, kNoContactToi);
  // A double root: the point at rest at the origin, the plane's origin moving from (1, 0, 0)
  // to (-1, 0, 0) and its normal from (1, 0, 0) to (-1, 0, 0), zero at t = 1/2 (there every
  // point is on the degenerate plane): f(t) = -(o . n) = -(1 - 2t)^2.
  r = point_plane_ccd({origin, Vector3d(1, 0, 0), Vector3d(1, 0, 0), origin, Vector3d(-1, 0, 0),
                       Vector3d(-1, 0, 0)});
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.5);
  EXPECT_EQ(r.toi_hi, 0.5);
}

TEST(PointPlane, StateAtTheStartAndFloatOnly) {
  const Vector3d up(0, 0, 1), origin(0, 0, 0);
  const PointPlaneQuery resting{Vector3d(1, 1, 0), origin, up, Vector3d(2, 1, 0), origin, up};
  CcdOptions o;
  o.t_max = 0.0;
  CcdResult r = point_plane_ccd(resting, o);
  EXPECT_TRUE(r.collides && r.starts_within);
  const PointPlaneQuery above{Vector3d(1, 1, 0x1p-70), origin, up, Vector3d(2, 1, -1), origin,
                              up};
  r = point_plane_ccd(above, o);
  EXPECT_FALSE(r.collides);
  o.t_max = 1.0;
  o.mode = Mode::float_only;
  r = point_plane_ccd({Vector3d(5, 7, 1), origin, up, Vector3d(-3, 2, -1), origin, up}, o);
  EXPECT_EQ(r.decided_by, Stage::float_only);
  EXPECT_NEAR(r.toi_lo, 0.5, 1e-12);
}

TEST(PointPlane, BadInputIsAClearError) {
  const Vector3d up(0, 0, 1), origin(0, 0, 0), p(1, 1, 1);
  const auto message = [](const PointPlaneQuery& q) -> std::string {
    try {
      point_plane_ccd(q);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message({p, origin, Vector3d::Zero(), p, origin, up}),
            "exactccd: point_plane_ccd: normal_t0 is zero: no plane");
  EXPECT_EQ(message({p, origin, up, p, origin, Vector3d::Zero()}),
            "exactccd: point_plane_ccd: normal_t1 is zero: no plane");
  EXPECT_EQ(message({p, Vector3d(0, std::nan(""), 0), up, p, origin, up}),
            "exactccd: non-finite coordinate in origin_t0");
  CcdOptions o;
  o.t_max = -1;
  EXPECT_THROW(point_plane_ccd({p, origin, up, p, origin, up}, o), std::invalid_argument);
}

// Contact times within a few units in the last place of a power of two 2^-k, where the spacing
// of the doubles halves: the filter's bisection must still end on the tightest pair, the exact
// path's (a midpoint rounded upwards lands on the upper end while a double is left between
// them; the fuzzer found it). Planes z = 0 and n = (0, 0, 1), the point from z = a to z = b.
TEST(PointPlane, TightestPairNextToPowersOfTwo) {
  std::mt19937_64 rng(test_seed("point_plane_powers_of_two"));
  std::uniform_int_distribution<int> ulps(-6, 6);
  int checked = 0;
  for (int k = 1; k <= 12; ++k)
    for (int n = 0; n < 60; ++n) {
      // t* = a / (a - b) near 2^-k: b = a (1 - 2^k), both nudged by a few ulps.
      double a = 1.0 + ulps(rng) * 0x1p-52;
      double b = a * (1.0 - std::ldexp(1.0, k));
      for (int j = ulps(rng); j != 0; j += j > 0 ? -1 : 1)
        b = std::nextafter(b, j > 0 ? 0.0 : -1e300);
      const Vector3d o(0, 0, 0), up(0, 0, 1);
      for (const double t_max : {1.0, 0.3, 0.7, std::ldexp(1.0, -k) * 1.5}) {
        CcdOptions opt;
        opt.t_max = std::min(t_max, 1.0);
        const PointPlaneQuery q{Vector3d(0.5, 0.25, a), o, up, Vector3d(0.25, 0.5, b), o, up};
        const CcdResult filtered = point_plane_ccd(q, opt);
        opt.mode = Mode::exact;
        const CcdResult exact = point_plane_ccd(q, opt);
        ASSERT_EQ(filtered.collides, exact.collides) << k << " " << n;
        EXPECT_EQ(filtered.toi_lo, exact.toi_lo) << "k " << k << " a " << a << " b " << b;
        EXPECT_EQ(filtered.toi_hi, exact.toi_hi) << "k " << k << " a " << a << " b " << b;
        checked += exact.collides;
      }
    }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace exactccd::test
