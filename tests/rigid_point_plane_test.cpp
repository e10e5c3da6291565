// A point of a rigid body against a static plane (rigid point_plane_ccd): against the rigid
// vertex-face query of a huge static triangle lying exactly in the plane (an independent path:
// the rigid coplanarity polynomial and the inclusion test; the same contact set wherever the
// crossing lies inside the triangle), Mode::filtered against Mode::exact, the time of pure
// rotations, t_max = 0, and bad input. And a rigid body in a Scene with a floor: the scene's
// point-plane contacts equal deciding each vertex by itself.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

/// A plane through `origin` with normal n = (1, 2, 2) or (0, 0, 1), and a triangle of side
/// about 2^21 lying exactly in it (corners origin + k u with u . n = 0 in small integers, k a
/// power of two: every coordinate is a double and every product exact).
struct Plane {
  Eigen::Vector3d origin, normal, a, b, c;
};

Plane plane(bool tilted, const Eigen::Vector3d& origin) {
  const double k = std::ldexp(1.0, 20);
  Plane p;
  p.origin = origin;
  Eigen::Vector3d u, v;
  if (tilted) {
    p.normal = Eigen::Vector3d(1, 2, 2);
    u = Eigen::Vector3d(2, -1, 0);
    v = Eigen::Vector3d(0, 1, -1);
  } else {
    p.normal = Eigen::Vector3d(0, 0, 1);
    u = Eigen::Vector3d(1, 0, 0);
    v = Eigen::Vector3d(0, 1, 0);
  }
  p.a = origin + k * u;
  p.b = origin + k * v;
  p.c = origin - k * (u + v);
  return p;
}

RigidMotion random_motion(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RigidMotion m;
  m.pivot = Eigen::Vector3d(u(rng), u(rng), u(rng));
  m.translation = Eigen::Vector3d(u(rng), u(rng), u(rng));
  m.cayley = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return m;
}

TEST(RigidPointPlane, EqualsTheVertexFaceQueryOfAHugeTriangleInThePlane) {
  std::mt19937_64 rng(test_seed("rigid_point_plane"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int contacts = 0, checked = 0;
  for (int k = 0; k < 400; ++k) {
    const bool tilted = k % 2 == 1;
    // Small-integer origins: the triangle's corners stay exact.
    const Plane pl = plane(tilted, Eigen::Vector3d(std::round(u(rng)), 0, std::round(u(rng))));
    RigidMotion m = random_motion(rng);
    if (k % 5 == 0) m.translation.setZero();  // pure rotations
    if (k % 7 == 0) m.cayley.setZero();       // pure translations
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    for (const double delta : {0.0, 0.125}) {
      CcdOptions o;
      o.min_separation = delta;
      const RigidCcdResult r = point_plane_ccd({p, m, pl.origin, pl.normal}, o);
      RigidVertexFaceQuery vf{p, pl.a, pl.b, pl.c, SideMotion::of(m), SideMotion{}};
      vf.face.kind = PathKind::linear;
      vf.face.linear_end = {pl.a, pl.b, pl.c};
      const RigidCcdResult want = vertex_face_ccd(vf, o);
      ASSERT_EQ(r.ccd.collides, want.ccd.collides) << "query " << k << " delta " << delta;
      ++checked;
      if (!r.ccd.collides) continue;
      ++contacts;
      EXPECT_EQ(r.ccd.toi_lo, want.ccd.toi_lo) << "query " << k << " delta " << delta;
      EXPECT_EQ(r.ccd.toi_hi, want.ccd.toi_hi) << "query " << k << " delta " << delta;
      EXPECT_EQ(r.ccd.starts_within, want.ccd.starts_within);
      EXPECT_EQ(r.has_time, want.has_time);
      if (r.has_time) {
        EXPECT_EQ(r.time_lo, want.time_lo);
        EXPECT_EQ(r.time_hi, want.time_hi);
      }
      CcdOptions exact = o;
      exact.mode = Mode::exact;
      const RigidCcdResult e = point_plane_ccd({p, m, pl.origin, pl.normal}, exact);
      EXPECT_EQ(e.ccd.toi_lo, r.ccd.toi_lo);
      EXPECT_EQ(e.ccd.toi_hi, r.ccd.toi_hi);
    }
  }
  EXPECT_GT(contacts, checked / 5) << "too few contacts: the test shows little";
  EXPECT_LT(contacts, checked) << "every query collides: the test shows little";
}

TEST(RigidPointPlane, TouchingAndRestingAndTMaxZero) {
  RigidMotion still;  // at rest on the floor z = 0
  const RigidCcdResult on = point_plane_ccd({{0.5, 0.25, 0.0}, still, {0, 0, 0}, {0, 0, 3}});
  EXPECT_TRUE(on.ccd.collides);
  EXPECT_EQ(on.ccd.toi_lo, 0.0);
  EXPECT_EQ(on.ccd.toi_hi, 0.0);
  EXPECT_TRUE(on.ccd.starts_within);
  // A quarter turn about the x axis through the origin (Cayley vector (1, 0, 0): exactly 90
  // degrees at s = 1): (0, 1, 1) goes to (0, -1, 1), its z = sin + cos >= 1 on the way: no
  // contact; (0, 0, -1) goes to (0, 1, 0), on the floor at s = 1 exactly.
  RigidMotion quarter;
  quarter.cayley = Eigen::Vector3d(1, 0, 0);
  const RigidCcdResult high = point_plane_ccd({{0, 1, 1}, quarter, {0, 0, 0}, {0, 0, 1}});
  EXPECT_FALSE(high.ccd.collides);
  EXPECT_TRUE(high.has_time);
  const RigidCcdResult up = point_plane_ccd({{0, 0, -1}, quarter, {0, 0, 0}, {0, 0, 1}});
  EXPECT_TRUE(up.ccd.collides);
  EXPECT_EQ(up.ccd.toi_lo, 1.0);
  EXPECT_EQ(up.ccd.toi_hi, 1.0);
  EXPECT_TRUE(up.has_time);  // a pure rotation: t(1) = 1
  EXPECT_LE(up.time_lo, 1.0);
  EXPECT_GT(up.time_lo, 0.999);
  CcdOptions o;
  o.t_max = 0.0;
  EXPECT_FALSE(point_plane_ccd({{0, 0, -1}, quarter, {0, 0, 0}, {0, 0, 1}}, o).ccd.collides);
  o.min_separation = 1.0;
  const RigidCcdResult start = point_plane_ccd({{0, 0, -1}, quarter, {0, 0, 0}, {0, 0, 1}}, o);
  EXPECT_TRUE(start.ccd.collides);
  EXPECT_TRUE(start.ccd.starts_within);
}

TEST(RigidPointPlane, FloatOnlyRunsAndBadInputIsRefused) {
  std::mt19937_64 rng(test_seed("rigid_point_plane_float"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int agree = 0;
  for (int k = 0; k < 200; ++k) {
    const RigidPointPlaneQuery q{{u(rng), u(rng), u(rng)}, random_motion(rng), {0, 0, 0},
                                 {u(rng), u(rng), 1.0}};
    CcdOptions f;
    f.mode = Mode::float_only;
    agree += point_plane_ccd(q, f).ccd.collides == point_plane_ccd(q).ccd.collides;
  }
  EXPECT_GT(agree, 190);  // uncertified, but it is the same polynomial in doubles
  const RigidMotion m;
  EXPECT_THROW(point_plane_ccd({{0, 0, 0}, m, {0, 0, 0}, {0, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(point_plane_ccd({{0, 0, NAN}, m, {0, 0, 0}, {0, 0, 1}}), std::invalid_argument);
  RigidMotion bad;
  bad.cayley = Eigen::Vector3d(INFINITY, 0, 0);
  EXPECT_THROW(point_plane_ccd({{0, 0, 0}, bad, {0, 0, 0}, {0, 0, 1}}), std::invalid_argument);
}

/// A turning, falling box corner set (a small rigid mesh) over a floor and a tilted plane: the
/// scene's point-plane contacts are exactly each vertex decided by itself, with and without a
/// minimum separation, and earliest_contact agrees.
TEST(RigidPointPlane, RigidBodiesInAScene) {
  std::mt19937_64 rng(test_seed("rigid_point_plane_scene"));
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::size_t contacts = 0;
  for (int round = 0; round < 5; ++round) {
    Positions x(12, 3);
    for (int v = 0; v < 12; ++v) x.row(v) << u(rng), u(rng), 0.3 + u(rng);
    Triangles t(4, 3);
    t << 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11;
    Scene scene;
    const MeshId body = scene.add_rigid_body(x, t);
    RigidMotion m;
    m.pivot = Eigen::Vector3d(0, 0, 0.3);
    m.translation = Eigen::Vector3d(0.1, 0, -0.4 - 0.1 * round);
    m.cayley = Eigen::Vector3d(0.3, -0.2, 0.1);
    scene.set_rigid_motion(body, m);
    const Eigen::Vector3d n0(0, 0, 1), n1(1, 1, 4), o1(0, 0, -0.1);
    const MeshId floor = scene.add_plane(Eigen::Vector3d::Zero(), n0);
    const MeshId tilted = scene.add_plane(o1, n1);
    for (const double delta : {0.0, 0.05}) {
      SceneOptions so;
      so.min_separation = delta;
      const SceneResult res = scene.find_contacts(so);
      std::vector<SceneContact> want;
      CcdOptions o;
      o.min_separation = delta;
      for (const MeshId plane : {floor, tilted})
        for (std::uint32_t v = 0; v < 12; ++v) {
          const RigidCcdResult r = point_plane_ccd(
              {x.row(v).transpose(), m, plane == floor ? Eigen::Vector3d::Zero() : o1,
               plane == floor ? n0 : n1},
              o);
          if (r.ccd.collides)
            want.push_back({{QueryType::point_plane, body, v, plane, 0}, r.ccd.toi_lo,
                            r.ccd.toi_hi});
        }
      std::sort(want.begin(), want.end(),
                [](const SceneContact& a, const SceneContact& b) { return a.pair < b.pair; });
      std::vector<SceneContact> got;
      for (const SceneContact& c : res.contacts)
        if (c.pair.type == QueryType::point_plane) got.push_back(c);
      ASSERT_EQ(got.size(), want.size()) << "round " << round << " delta " << delta;
      for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_TRUE(got[k].pair == want[k].pair);
        EXPECT_EQ(got[k].toi_lo, want[k].toi_lo);
        EXPECT_EQ(got[k].toi_hi, want[k].toi_hi);
        EXPECT_EQ(scene.rigid_point_plane_query(got[k].pair).motion.cayley, m.cayley);
      }
      contacts += got.size();
      const EarliestContact first = scene.earliest_contact(so);
      EXPECT_TRUE(first.contact.pair == res.earliest.pair);
      EXPECT_EQ(first.contact.toi_lo, res.earliest.toi_lo);
      if (!got.empty()) {
        EXPECT_THROW(scene.point_plane_query(got[0].pair), std::invalid_argument);
      }
    }
  }
  EXPECT_GT(contacts, 10u);
}

}  // namespace
}  // namespace exactccd::test
