// The contact geometry of point-plane queries (linear and rigid) against exact rational
// evaluation: the point's exact position at the rational times toi_lo and toi_hi (both in the
// enclosure of t*) lies in `point`; the exact unit normal side * n / |n| (side: the exact sign
// of the offset at t = 0) lies in `normal`, compared without rounding (squares over the
// rationals); kinds at the start and with a minimum separation (the closest point on the plane).
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/rigid.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

/// lo <= num / sqrt(norm2) <= hi, exactly (norm2 > 0).
bool within_unit(double lo, double hi, const mpq_class& num, const mpq_class& norm2) {
  const auto at_least = [&](double bound) {  // bound <= num / sqrt(norm2)
    const mpq_class b(bound);
    if (b <= 0 && num >= 0) return true;
    if (b > 0) return num > 0 && b * b * norm2 <= num * num;
    return num < 0 && b * b * norm2 >= num * num;  // both negative: |b| >= |x|
  };
  const auto at_most = [&](double bound) {  // num / sqrt(norm2) <= bound
    const mpq_class b(bound);
    if (b >= 0 && num <= 0) return true;
    if (b < 0) return num < 0 && b * b * norm2 <= num * num;
    return num > 0 && b * b * norm2 >= num * num;
  };
  return at_least(lo) && at_most(hi);
}

mpq_class q(double x) { return mpq_class(x); }

TEST(PointPlaneContact, LinearQueriesAgainstExactRationalEvaluation) {
  std::mt19937_64 rng(test_seed("point_plane_contact"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0, from_below = 0;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d n(u(rng), u(rng), 1.0 + u(rng));
    const Eigen::Vector3d o(u(rng), u(rng), u(rng));
    const Eigen::Vector3d p0 = o + Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Vector3d p1 = o + Eigen::Vector3d(u(rng), u(rng), u(rng));
    const PointPlaneQuery query{p0, o, n, p1, o, n};
    for (const double delta : {0.0, 0.1}) {
      CcdOptions opt;
      opt.min_separation = delta;
      const CcdResult r = point_plane_ccd(query, opt);
      if (!r.collides) continue;
      const ContactGeometry g = contact_geometry(query, r, delta);
      EXPECT_EQ(g.parameter_count, 0);
      mpq_class f0 = 0, nn = 0;
      for (int i = 0; i < 3; ++i) {
        f0 += (q(p0[i]) - q(o[i])) * q(n[i]);
        nn += q(n[i]) * q(n[i]);
      }
      if (r.starts_within) {
        EXPECT_EQ(g.kind, ContactKind::at_start);
        EXPECT_FALSE(g.normal_oriented);
      } else {
        ASSERT_EQ(g.kind, ContactKind::point) << k;
        EXPECT_TRUE(g.normal_oriented);
        ASSERT_NE(sgn(f0), 0);
        from_below += sgn(f0) < 0;
      }
      const int side = r.starts_within ? 1 : sgn(f0);
      for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(within_unit(g.normal[i].lo, g.normal[i].hi, side * q(n[i]), nn))
            << "query " << k << " axis " << i;
      // The exact position (or closest point on the plane) at the rational ends of [lo, hi].
      for (const double t : {r.toi_lo, r.toi_hi}) {
        mpq_class x[3], f = 0;
        for (int i = 0; i < 3; ++i) {
          x[i] = q(p0[i]) + q(t) * (q(p1[i]) - q(p0[i]));
          f += (x[i] - q(o[i])) * q(n[i]);
        }
        for (int i = 0; i < 3; ++i) {
          const mpq_class want = delta > 0 ? x[i] - f / nn * q(n[i]) : x[i];
          EXPECT_LE(q(g.point[i].lo), want) << "query " << k << " t " << t;
          EXPECT_GE(q(g.point[i].hi), want) << "query " << k << " t " << t;
        }
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(from_below, 10);
}

TEST(PointPlaneContact, RigidQuarterTurnOntoTheFloor) {
  // (0, 0, -1) turned a quarter about x through the origin reaches (0, 1, 0) at s = 1, from
  // below the floor z = 0: the normal is -z.
  RigidMotion quarter;
  quarter.cayley = Eigen::Vector3d(1, 0, 0);
  const RigidPointPlaneQuery query({0, 0, -1}, quarter, {0, 0, 0}, {0, 0, 4});
  const RigidCcdResult r = point_plane_ccd(query);
  ASSERT_TRUE(r.ccd.collides);
  const ContactGeometry g = contact_geometry(query, r);
  EXPECT_EQ(g.kind, ContactKind::point);
  EXPECT_TRUE(g.normal_oriented);
  EXPECT_EQ(g.normal[2].lo, -1.0);
  EXPECT_EQ(g.normal[2].hi, -1.0);
  const double at_end[3] = {0, 1, 0};
  for (int i = 0; i < 3; ++i) {
    EXPECT_LE(g.point[i].lo, at_end[i]);
    EXPECT_GE(g.point[i].hi, at_end[i]);
  }
  // Resting on the floor: at the start, unoriented.
  const RigidPointPlaneQuery resting({0.5, 0.5, 0}, RigidMotion{}, {0, 0, 0}, {0, 0, 1});
  const ContactGeometry s = contact_geometry(resting, point_plane_ccd(resting));
  EXPECT_EQ(s.kind, ContactKind::at_start);
  EXPECT_FALSE(s.normal_oriented);
  // Errors: no contact, a negative delta.
  const RigidPointPlaneQuery above({0, 0, 1}, RigidMotion{}, {0, 0, 0}, {0, 0, 1});
  EXPECT_THROW(contact_geometry(above, point_plane_ccd(above)), std::invalid_argument);
  EXPECT_THROW(contact_geometry(query, r, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace exactccd::test
