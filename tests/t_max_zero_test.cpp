// t_max = 0 asks for the state at t = 0 alone (pipeline/held_at_start.hpp,
// proofs/api_reductions.md#t-max-zero). Checked against CGAL's exact kernel at t = 0 (contact:
// the closed primitives share a point; minimum separation: their squared distance is at most
// delta^2), which shares no code with the library, in every certified mode and entry point
// (double, rational, rigid, scene), on queries built to touch or nearly touch at the start.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;

/// A query touching, nearly touching or apart at t = 0 (offset 0, a tiny or a moderate gap
/// along the normal or across the segments), then moving randomly.
RationalQuery query_near_start(std::mt19937_64& rng, QueryType type, int gap_kind) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double gaps[4] = {0.0, 0x1p-60, 1e-300, 0.25};
  const double gap = gaps[gap_kind] * (u(rng) < 0 ? -1.0 : 1.0);
  std::array<Vector3d, 8> x;
  if (type == QueryType::vertex_face) {
    // The triangle in z = 0; the vertex at dyadic barycentric coordinates, inside, on an edge or
    // at a corner, lifted by the gap.
    x[1] = {0, 0, 0}, x[2] = {1, 0, 0}, x[3] = {0, 1, 0};
    const double where[4][2] = {{0.25, 0.25}, {0.5, 0.0}, {0.0, 0.0}, {0.75, 0.5}};
    const auto& w = where[rng() % 4];
    x[0] = {w[0], w[1], gap};
  } else {
    // Two segments crossing (or touching at an end) in z = 0, the second lifted by the gap.
    x[0] = {-1, 0, 0}, x[1] = {1, 0, 0};
    const bool at_end = rng() % 3 == 0;
    x[2] = {at_end ? 1.0 : 0.0, at_end ? 0.0 : -1.0, gap}, x[3] = {0.5, 1, gap};
  }
  for (int i = 0; i < 4; ++i) x[4 + i] = x[i] + Vector3d(u(rng), u(rng), u(rng));
  RationalQuery q{type, {}};
  for (int i = 0; i < 8; ++i) q.points[i] = {mpq_class(x[i].x()), mpq_class(x[i].y()),
                                             mpq_class(x[i].z())};
  return q;
}

/// CGAL at t = 0: within delta (delta = 0: contact).
bool cgal_within_at_start(const RationalQuery& q, double delta) {
  if (delta == 0.0) return cgal_contact_at(q, 0);
  return cgal_squared_distance_at(q, 0) <= mpq_class(delta) * mpq_class(delta);
}

CcdOptions at_start(Mode mode, double delta) {
  CcdOptions o;
  o.t_max = 0.0;
  o.mode = mode;
  o.min_separation = delta;
  return o;
}

void expect_state_at_start(const CcdResult& r, bool within) {
  EXPECT_EQ(r.collides, within);
  if (within) {
    EXPECT_EQ(r.toi_lo, 0.0);
    EXPECT_EQ(r.toi_hi, 0.0);
  } else {
    EXPECT_EQ(r.toi_lo, std::numeric_limits<double>::infinity());
  }
}

TEST(TMaxZero, LinearQueriesAnswerTheStateAtTheStart) {
  std::mt19937_64 rng(test_seed("t_max_zero"));
  int within = 0, apart = 0;
  for (int n = 0; n < 400; ++n) {
    const QueryType type = n % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const RationalQuery q = query_near_start(rng, type, (n / 2) % 4);
    for (const double delta : {0.0, 0x1p-70, 1e-3}) {
      SCOPED_TRACE(describe(q) + " delta " + std::to_string(delta));
      const bool truth = cgal_within_at_start(q, delta);
      (truth ? within : apart)++;
      for (const Mode mode : {Mode::filtered, Mode::exact}) {
        expect_state_at_start(double_api_ccd(q, at_start(mode, delta)), truth);
      }
      expect_state_at_start(exact_ccd(q, at_start(Mode::exact, delta)), truth);
      // Consistent with the whole step: a contact at the start is the step's first, at 0.
      CcdOptions whole;
      whole.min_separation = delta;
      const CcdResult step = double_api_ccd(q, whole);
      EXPECT_EQ(truth, step.collides && step.toi_lo == 0.0);
    }
    if (::testing::Test::HasFailure()) break;
  }
  // Both answers well represented, touching at exactly 0 included.
  EXPECT_GT(within, 300);
  EXPECT_GT(apart, 300);
}

// CcdResult::starts_within over the whole step is the state at t = 0 too, whatever toi_width:
// with a wide width an enclosure [0, w] does not say whether t* = 0, and the held query decides.
TEST(TMaxZero, StartsWithinIsTheStateAtTheStart) {
  std::mt19937_64 rng(test_seed("starts_within"));
  int within = 0, near_start_only = 0;
  for (int n = 0; n < 300; ++n) {
    const QueryType type = n % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const RationalQuery q = query_near_start(rng, type, (n / 2) % 4);
    for (const double delta : {0.0, 1e-3})
      for (const double width : {0.0, 0.25}) {
        SCOPED_TRACE(describe(q) + " delta " + std::to_string(delta) + " width " +
                     std::to_string(width));
        const bool truth = cgal_within_at_start(q, delta);
        within += truth;
        CcdOptions o;
        o.min_separation = delta;
        o.toi_width = width;
        for (const Mode mode : {Mode::filtered, Mode::exact}) {
          o.mode = mode;
          const CcdResult r = double_api_ccd(q, o);
          EXPECT_EQ(r.starts_within, truth);
          if (r.collides && r.toi_lo == 0.0 && r.toi_hi > 0.0 && !truth) ++near_start_only;
        }
        EXPECT_EQ(exact_ccd(q, o).starts_within, truth);
        o.t_max = 0.0;
        EXPECT_EQ(double_api_ccd(q, o).starts_within, truth);
      }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(within, 200);
  // The case only the held query decides: an enclosure from 0 of a contact after the start.
  EXPECT_GT(near_start_only, 0);
}

TEST(TMaxZero, PointQueriesAnswerTheStateAtTheStart) {
  const Vector3d p(0.5, 0, 0), e0(0, 0, 0), e1(1, 0, 0), away(0, 0, 1);
  CcdOptions o = at_start(Mode::filtered, 0.0);
  expect_state_at_start(point_edge_ccd({p, e0, e1, p + away, e0, e1}, o), true);
  expect_state_at_start(point_edge_ccd({p + Vector3d(0, 0x1p-80, 0), e0, e1, p, e0, e1}, o),
                        false);
  expect_state_at_start(point_point_ccd({p, p, p + away, p}, o), true);
  expect_state_at_start(point_point_ccd({p, p + away, p, p}, o), false);
}

TEST(TMaxZero, RigidQueriesAnswerTheStateAtTheStart) {
  std::mt19937_64 rng(test_seed("t_max_zero_rigid"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 120; ++n) {
    const QueryType type = n % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const RationalQuery q = query_near_start(rng, type, (n / 2) % 4);
    RigidMotion turn;
    turn.pivot = Vector3d(u(rng), u(rng), u(rng));
    turn.cayley = Vector3d(u(rng), u(rng), u(rng));
    turn.translation = Vector3d(u(rng), u(rng), u(rng));
    for (const double delta : {0.0, 1e-3}) {
      SCOPED_TRACE(describe(q) + " delta " + std::to_string(delta));
      const bool truth = cgal_within_at_start(q, delta);
      for (const Mode mode : {Mode::filtered, Mode::exact}) {
        const CcdOptions o = at_start(mode, delta);
        const RigidCcdResult r =
            type == QueryType::vertex_face
                ? vertex_face_ccd(RigidVertexFaceQuery{to_vector(q.points[0]),
                                                       to_vector(q.points[1]),
                                                       to_vector(q.points[2]),
                                                       to_vector(q.points[3]),
                                                       SideMotion::of(turn), SideMotion::of({})},
                                  o)
                : edge_edge_ccd(RigidEdgeEdgeQuery{to_vector(q.points[0]),
                                                   to_vector(q.points[1]),
                                                   to_vector(q.points[2]),
                                                   to_vector(q.points[3]), SideMotion::of(turn),
                                                   SideMotion::of({})},
                                o);
        expect_state_at_start(r.ccd, truth);
        EXPECT_EQ(r.ccd.starts_within, truth);
        if (truth && r.has_time) EXPECT_EQ(r.time_lo, 0.0);
      }
    }
    if (::testing::Test::HasFailure()) break;
  }
}

TEST(TMaxZero, SceneAnswersTheStateAtTheStart) {
  // A sheet of two triangles resting on a floor (its vertices on the floor's plane, inside and
  // on its edges) and lifting off; a third mesh hovering 2^-60 above; both static pairs and
  // touching ones. Every pair of the scene checked against CGAL at t = 0.
  Scene scene;
  Positions floor(4, 3), sheet(4, 3), hover(3, 3);
  Triangles two(2, 3), one(1, 3);
  floor << -2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0;
  sheet << -0.5, -0.5, 0, 2, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0;
  hover << 1, 1, 0x1p-60, 1.5, 1, 0x1p-60, 1, 1.5, 0x1p-60;
  two << 0, 1, 2, 0, 2, 3;
  one << 0, 1, 2;
  scene.add_static_mesh(floor, two);
  const MeshId lifted = scene.add_mesh(sheet, two);
  Positions up = sheet;
  up.col(2).array() += 1.0;
  scene.set_motion(lifted, sheet, up);
  const MeshId hovering = scene.add_mesh(hover, one);
  Positions down = hover;
  down.col(2).array() -= 1.0;
  scene.set_motion(hovering, hover, down);
  // A tilted triangle beside the floor's corner: its box overlaps the floor's at the start (so no
  // cull by time removes it), it does not touch the floor there, and it slides into it later.
  Positions wedge(3, 3);
  wedge << 1.5, 2.5, -1, 2.5, 1.5, -1, 2.5, 2.5, 1;
  const MeshId sliding = scene.add_mesh(wedge, one);
  Positions slid = wedge;
  slid.col(0).array() -= 1.0;
  slid.col(1).array() -= 1.0;
  scene.set_motion(sliding, wedge, slid);
  SceneOptions whole_step;
  const SceneResult step = scene.find_contacts(whole_step);
  ASSERT_TRUE(std::any_of(step.contacts.begin(), step.contacts.end(), [&](const SceneContact& c) {
    return c.pair.first_mesh == sliding || c.pair.second_mesh == sliding;
  }));
  // Over the whole step, SceneContact::starts_within is the state at the start as well, in
  // find_contacts and earliest_contact (which decides its contacts again with the caller's
  // options) alike; with a wide toi_width too.
  std::size_t started = 0;
  for (const double width : {0.0, 0.5}) {
    whole_step.ccd.toi_width = width;
    for (const SceneContact& c : scene.find_contacts(whole_step).contacts) {
      const RationalQuery q = c.pair.type == QueryType::vertex_face
                                  ? to_rational(scene.vertex_face_query(c.pair))
                                  : to_rational(scene.edge_edge_query(c.pair));
      EXPECT_EQ(c.starts_within, cgal_within_at_start(q, 0.0)) << describe(q);
      started += c.starts_within;
    }
    const EarliestContact first = scene.earliest_contact(whole_step);
    EXPECT_TRUE(first.contact.starts_within);  // resting contact: the earliest is at t = 0
  }
  EXPECT_GT(started, 0u);
  whole_step.ccd.toi_width = 0.0;
  for (const double delta : {0.0, 1e-12}) {
    SCOPED_TRACE(delta);
    SceneOptions o;
    o.ccd.t_max = 0.0;
    o.min_separation = delta;
    const SceneResult all = scene.find_contacts(o);
    ASSERT_FALSE(all.contacts.empty());
    std::size_t expected = 0;
    for (const ScenePair& p : scene.find_contacts([&] {
           SceneOptions whole = o;
           whole.ccd.t_max = 1.0;
           whole.record_candidates = true;
           return whole;
         }()).candidates) {
      const RationalQuery q = p.type == QueryType::vertex_face
                                  ? to_rational(scene.vertex_face_query(p))
                                  : to_rational(scene.edge_edge_query(p));
      if (cgal_within_at_start(q, delta)) ++expected;
    }
    EXPECT_EQ(all.contacts.size(), expected);
    for (const SceneContact& c : all.contacts) {
      EXPECT_EQ(c.toi_lo, 0.0);
      EXPECT_EQ(c.toi_hi, 0.0);
      const RationalQuery q = c.pair.type == QueryType::vertex_face
                                  ? to_rational(scene.vertex_face_query(c.pair))
                                  : to_rational(scene.edge_edge_query(c.pair));
      EXPECT_TRUE(cgal_within_at_start(q, delta)) << describe(q);
    }
    const EarliestContact e = scene.earliest_contact(o);
    EXPECT_TRUE(e.collides);
    EXPECT_EQ(e.contact.pair, all.earliest.pair);
    EXPECT_EQ(e.contact.toi_lo, 0.0);
  }
}

}  // namespace
}  // namespace exactccd::test
