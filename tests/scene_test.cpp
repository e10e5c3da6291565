// Tests of the scene-level CCD (core/include/exactccd/scene.hpp).
//
// The reference (tests/scene_support.hpp) is a brute force written from the header's rules only:
// every pair the rules allow (vertex-face: each vertex of mesh A against each triangle of mesh B;
// edge-edge: each edge against each later edge; never between two static meshes; within one
// moving mesh only with self_collision and never two primitives sharing a vertex) is decided one
// by one by the public per-pair functions vertex_face_ccd / edge_edge_ccd with the same
// CcdOptions. The edges are derived there independently (distinct triangle sides (i < j),
// sorted), and the swept boxes of the primitives are computed there independently, so that the
// broad phase can be checked to be exact (candidates == pairs whose closed swept boxes overlap).
// A few scenes also have answers worked out by hand (dyadic coordinates, contacts at t = 0, 1/2
// and 1).
//
// EXACTCCD_TEST_SEED overrides the seed of the random scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/scene.hpp"
#include "random_scenes.hpp"
#include "scene_support.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using namespace test;  // scene_support.hpp: scenes, printing, meshes, the reference

// ---------------------------------------------------------------------------------------------
// Checking a step against the reference (same_pairs: scene_support.hpp)

void expect_accessors(const Scene& scene, const SceneSpec& spec,
                      const std::vector<RefMesh>& meshes) {
  ASSERT_EQ(scene.mesh_count(), spec.size());
  for (MeshId i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE("mesh " + std::to_string(i));
    EXPECT_EQ(scene.is_static(i), spec[i].is_static);
    EXPECT_TRUE(scene.triangles(i) == spec[i].triangles);
    EXPECT_TRUE(scene.edges(i) == meshes[i].edges)
        << scene.edges(i).rows() << " edges, expected " << meshes[i].edges.rows();
    EXPECT_TRUE(scene.start_positions(i) == spec[i].start);
    EXPECT_TRUE(scene.end_positions(i) == spec[i].end);
  }
}

bool same_query(const VertexFaceQuery& a, const VertexFaceQuery& b) {
  return a.p_t0 == b.p_t0 && a.a_t0 == b.a_t0 && a.b_t0 == b.b_t0 && a.c_t0 == b.c_t0 &&
         a.p_t1 == b.p_t1 && a.a_t1 == b.a_t1 && a.b_t1 == b.b_t1 && a.c_t1 == b.c_t1;
}
bool same_query(const EdgeEdgeQuery& a, const EdgeEdgeQuery& b) {
  return a.ea0_t0 == b.ea0_t0 && a.ea1_t0 == b.ea1_t0 && a.eb0_t0 == b.eb0_t0 &&
         a.eb1_t0 == b.eb1_t0 && a.ea0_t1 == b.ea0_t1 && a.ea1_t1 == b.ea1_t1 &&
         a.eb0_t1 == b.eb0_t1 && a.eb1_t1 == b.eb1_t1;
}

/// Everything the scene reports for one step, compared with the brute force: the contacts (pairs
/// and TOI doubles), the earliest contact, the candidates (exactly the pairs whose boxes
/// overlap), the statistics, earliest_contact(), and the pairs' queries. Returns the result of
/// find_contacts (with record_candidates) and the reference for further checks.
std::pair<SceneResult, Reference> check_step(Scene& scene, const SceneSpec& spec,
                                             const SceneOptions& options) {
  const std::vector<RefMesh> meshes = prepare_reference(spec);
  expect_accessors(scene, spec, meshes);
  Reference ref = brute_force(meshes, options.ccd, options.self_collision);
  const bool swept = options.broad_phase == BroadPhase::swept_bvh;
  const std::vector<SceneContact>& want = swept ? ref.contacts : ref.instant_contacts;
  const std::vector<ScenePair>& want_candidates = swept ? ref.swept_overlaps : ref.instant_overlaps;

  SceneOptions recording = options;
  recording.record_candidates = true;
  SceneResult got = scene.find_contacts(recording);
  EXPECT_TRUE(same_contacts(got.contacts, want));
  if (!want.empty()) {
    EXPECT_TRUE(same_contact(got.earliest, earliest_of(want)))
        << "earliest: got " << describe(got.earliest) << ", expected "
        << describe(earliest_of(want));
  } else {  // no contact: +infinity TOIs, so a minimum over scenes needs no check
    EXPECT_EQ(got.earliest.toi_lo, std::numeric_limits<double>::infinity());
    EXPECT_EQ(got.earliest.toi_hi, std::numeric_limits<double>::infinity());
  }
  if (swept) {
    // Culling by time keeps every pair whose blended boxes meet by t_max (decided exactly in
    // the reference) and nothing whose swept boxes do not overlap.
    EXPECT_TRUE(contains_pairs(got.candidates, ref.timed_overlaps));
    EXPECT_TRUE(contains_pairs(ref.swept_overlaps, got.candidates));
    if (got.stats.time_culled == 0) EXPECT_TRUE(same_pairs(got.candidates, ref.swept_overlaps));
  } else {
    EXPECT_TRUE(same_pairs(got.candidates, want_candidates));
    EXPECT_EQ(got.stats.time_culled, 0u);
  }

  std::uint64_t vf = 0, ee = 0;
  for (const ScenePair& p : got.candidates) (p.type == QueryType::vertex_face ? vf : ee)++;
  EXPECT_EQ(got.stats.vertex_face_candidates, vf);
  EXPECT_EQ(got.stats.edge_edge_candidates, ee);
  // find_contacts decides every candidate; at least the contacts, at most every allowed pair.
  EXPECT_EQ(got.stats.narrow_phase_tests, vf + ee);
  EXPECT_GE(vf + ee, want.size());
  EXPECT_LE(vf, ref.vertex_face_pairs);
  EXPECT_LE(ee, ref.edge_edge_pairs);

  // Without record_candidates: the same contacts, no candidate list.
  const SceneResult plain = scene.find_contacts(options);
  EXPECT_TRUE(same_contacts(plain.contacts, want));
  EXPECT_TRUE(plain.candidates.empty());
  EXPECT_EQ(plain.stats.vertex_face_candidates, vf);
  EXPECT_EQ(plain.stats.edge_edge_candidates, ee);
  // A second call in the same step is neither a first use nor a degradation: nothing is built.
  EXPECT_EQ(plain.stats.hierarchies_built, 0u);

  if (swept) {
    const EarliestContact e = scene.earliest_contact(options);
    EXPECT_EQ(e.collides, !want.empty());
    if (!want.empty()) {
      EXPECT_TRUE(same_contact(e.contact, earliest_of(want)))
          << "earliest_contact: got " << describe(e.contact) << ", expected "
          << describe(earliest_of(want));
    } else {
      EXPECT_EQ(e.contact.toi_lo, std::numeric_limits<double>::infinity());
      EXPECT_EQ(e.contact.toi_hi, std::numeric_limits<double>::infinity());
    }
    EXPECT_LE(e.stats.narrow_phase_tests, vf + ee);
  } else {
    EXPECT_THROW(scene.earliest_contact(options), std::invalid_argument);
  }

  for (const SceneContact& c : got.contacts) {
    if (c.pair.type == QueryType::vertex_face)
      EXPECT_TRUE(same_query(scene.vertex_face_query(c.pair),
                             reference_vertex_face_query(meshes, c.pair)))
          << describe(c.pair);
    else
      EXPECT_TRUE(same_query(scene.edge_edge_query(c.pair),
                             reference_edge_edge_query(meshes, c.pair)))
          << describe(c.pair);
  }
  return {std::move(got), std::move(ref)};
}

std::pair<SceneResult, Reference> check_scene(const SceneSpec& spec,
                                              const SceneOptions& options = {}) {
  Scene scene = make_scene(spec);
  return check_step(scene, spec, options);
}

// ---------------------------------------------------------------------------------------------
// 1. Random scenes against the brute force

TEST(SceneRandom, EqualsBruteForce) {
  Rng rng(test_seed());
  std::uint64_t contacts = 0, candidates = 0, pairs = 0;
  const int scenes = static_cast<int>(test::scaled_count(40));
  for (int scene_index = 0; scene_index < scenes; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    SCOPED_TRACE("random scene " + std::to_string(scene_index));
    const auto [got, ref] = check_scene(spec);
    // The brute force enumerates pairs lexicographically by (type, first_mesh, first_index,
    // second_mesh, second_index): ScenePair's operator< must be that strict order.
    EXPECT_TRUE(std::adjacent_find(ref.swept_overlaps.begin(), ref.swept_overlaps.end(),
                                   [](const ScenePair& a, const ScenePair& b) {
                                     return !(a < b) || b < a;
                                   }) == ref.swept_overlaps.end());
    contacts += ref.contacts.size();
    candidates += ref.swept_overlaps.size();
    pairs += ref.vertex_face_pairs + ref.edge_edge_pairs;
    if (::testing::Test::HasFailure()) break;
  }
  std::cout << "[ info     ] " << pairs << " allowed pairs, " << candidates << " candidates, "
            << contacts << " contacts\n";
  // The generator must exercise the narrow phase, not only the culling.
  EXPECT_GT(contacts, test::scaled_count(100));
}

TEST(SceneTime, FarMovingMeshesAreCutByTimeAndEqualBruteForce) {
  // A sheet sweeping diagonally through a static floor by many of its cells, and two boxes
  // crossing the floor's corner along x and along y at different times: boxes over the step
  // overlap far more often than boxes at any one time (proofs/scene.md#time-span).
  MeshSpec floor = grid(9, 9, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  floor.is_static = true;
  MeshSpec sheet = grid(9, 9, {-0.75, 0.125, 0.5}, {1, 0, 0}, {0, 0.75, 0});
  for (Eigen::Index v = 0; v < sheet.start.rows(); ++v)
    sheet.end.row(v) = sheet.start.row(v) + Eigen::RowVector3d(1.5, 0.0, -1.0);
  MeshSpec along_x = box_mesh({-2, -0.25, -0.25}, {-1.75, 0, 0});
  along_x.end.col(0).array() += 4.0;
  MeshSpec along_y = box_mesh({1.125, 3, -0.25}, {1.375, 3.25, 0});
  along_y.end.col(1).array() -= 4.0;
  const SceneSpec spec{floor, sheet, along_x, along_y};
  Scene scene = make_scene(spec);
  for (const double t_max : {1.0, 0.375}) {
    SCOPED_TRACE("t_max " + std::to_string(t_max));
    SceneOptions o;
    o.ccd.t_max = t_max;
    const auto [got, ref] = check_step(scene, spec, o);
    EXPECT_GT(got.stats.time_culled, 0u);
    EXPECT_LT(got.candidates.size(), ref.swept_overlaps.size());
    EXPECT_EQ(ref.contacts.empty(), t_max < 0.5);  // the sheet reaches the floor at t = 1/2
    // Off: every pair whose swept boxes overlap, the same answers.
    SceneOptions off = o;
    off.cull_by_time = false;
    off.record_candidates = true;
    const SceneResult all = scene.find_contacts(off);
    EXPECT_EQ(all.stats.time_culled, 0u);
    EXPECT_TRUE(same_pairs(all.candidates, ref.swept_overlaps));
    EXPECT_TRUE(same_contacts(all.contacts, got.contacts));
  }
}

/// A one-triangle mesh with corners `corners` (rows), moved by `shift` over the step.
MeshSpec one_triangle(const Eigen::Matrix3d& corners, const Eigen::Vector3d& shift,
                      bool is_static) {
  MeshSpec m;
  m.is_static = is_static;
  m.start = corners;
  m.end = corners;
  m.end.rowwise() += shift.transpose();
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 2;
  return m;
}

TEST(SceneManyMeshes, DebrisAndParticlesEqualBruteForce) {
  // Many small meshes (debris, particles): the mesh pairs come from a hierarchy over the
  // meshes' boxes, not from every pair of meshes. Static one-triangle debris on a bumpy floor,
  // particles falling onto it (some exactly on a debris triangle at t = 0, some far away), and
  // small boxes sweeping through: every contact and candidate equal the brute force's.
  Rng rng(test_seed());
  const int side = static_cast<int>(at_least(scaled_count(24), 12));
  SceneSpec spec;
  std::vector<Eigen::Matrix3d> debris;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const Eigen::Vector3d c(i / 8.0 + uniform(rng, 0, 0.03), j / 8.0 + uniform(rng, 0, 0.03),
                              uniform(rng, -0.01, 0.01));
      Eigen::Matrix3d t;
      t.row(0) = c.transpose();
      t.row(1) = (c + Eigen::Vector3d(0.09, uniform(rng, -0.02, 0.02), 0.0)).transpose();
      t.row(2) = (c + Eigen::Vector3d(0.01, 0.08, uniform(rng, -0.02, 0.02))).transpose();
      debris.push_back(t);
      spec.push_back(one_triangle(t, Eigen::Vector3d::Zero(), true));
    }
  const double extent = side / 8.0;
  for (int p = 0; p < side * 2; ++p) {
    Eigen::Matrix3d t;
    if (p % 5 == 0) {  // lying exactly on a debris triangle at t = 0, sliding off it
      t = debris[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(debris.size()) - 1))];
    } else {
      const Eigen::Vector3d c(uniform(rng, 0, extent), uniform(rng, 0, extent),
                              p % 7 == 0 ? 50.0 : uniform(rng, 0.02, 0.3));
      for (int k = 0; k < 3; ++k)
        t.row(k) = (c + Eigen::Vector3d(uniform(rng, -0.04, 0.04), uniform(rng, -0.04, 0.04),
                                        uniform(rng, -0.02, 0.02)))
                       .transpose();
    }
    const Eigen::Vector3d fall(uniform(rng, -0.05, 0.05), uniform(rng, -0.05, 0.05),
                               p % 5 == 0 ? 0.0 : -uniform(rng, 0.0, 0.4));
    spec.push_back(one_triangle(t, fall, false));
  }
  for (int b = 0; b < 4; ++b) {
    const Eigen::Vector3d lo(uniform(rng, 0, extent - 0.2), -0.3, -0.05);
    MeshSpec box = box_mesh(lo, lo + Eigen::Vector3d(0.1, 0.1, 0.1));
    box.end.col(1).array() += extent + 0.3;
    spec.push_back(box);
  }
  const auto [got, ref] = check_scene(spec);
  std::cout << "[ info     ] " << spec.size() << " meshes, " << got.candidates.size()
            << " candidates, " << ref.contacts.size() << " contacts\n";
  EXPECT_GT(ref.contacts.size(), 0u);  // not a vacuous comparison
  // The older scheme finds its mesh pairs at the start and at the end the same way.
  SceneOptions instant;
  instant.broad_phase = BroadPhase::static_bvh;
  Scene scene = make_scene(spec);
  const auto [got_instant, ref_instant] = check_step(scene, spec, instant);
  EXPECT_GT(ref_instant.instant_contacts.size(), 0u);
}

TEST(SceneRandom, ScaledByPowersOfTwoGivesIdenticalContacts) {
  // Multiplying every coordinate by 2^k is exact and leaves every contact time unchanged, so
  // the contacts (pairs and TOI doubles) must be identical; 2^-27 ~ 7e-9 and 2^27 ~ 1.3e8.
  Rng rng(test_seed() + 1);
  for (int scene_index = 0; scene_index < 4; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    SCOPED_TRACE("random scene " + std::to_string(scene_index));
    Scene unit = make_scene(spec);
    const SceneResult base = unit.find_contacts();
    for (int k : {-27, 27}) {
      SCOPED_TRACE("scale 2^" + std::to_string(k));
      const auto [got, ref] = check_scene(scaled(spec, std::ldexp(1.0, k)));
      EXPECT_TRUE(same_contacts(got.contacts, base.contacts));
    }
  }
}

TEST(SceneRandom, HugeAndTinyScalesEqualBruteForce) {
  // 1e8 and 1e-8 are not powers of two: coordinates are rounded, the answers may change, and
  // the brute force on the same doubles decides.
  Rng rng(test_seed() + 2);
  for (int scene_index = 0; scene_index < 3; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    for (double factor : {1e-8, 1e8}) {
      SCOPED_TRACE("random scene " + std::to_string(scene_index) + " scaled by " + hex(factor));
      check_scene(scaled(spec, factor));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 2. Adversarial scenes

TEST(SceneAdversarial, HandComputedContactsAtZeroHalfAndOne) {
  // Mesh 0: static triangle T = (0,0,0), (1,0,0), (0,1,0) in the plane z = 0.
  // Mesh 1: four vertices and no triangle, moving straight down:
  //   P (1/4, 1/4, 1) -> (1/4, 1/4, 0)      reaches T's interior at t = 1;
  //   Q (1/4, 1/2, 0) -> (1/4, 1/2, -1)     is on T at t = 0;
  //   R (1/2, 1/2, 1/2) -> (1/2, 1/2, -1/2) crosses z = 0 at t = 1/2 on T's side x + y = 1;
  //   S (2, 2, 1) -> (2, 2, -1)             passes outside T.
  // Mesh 2: the vertical triangle M = (1/2, -1/2, 1), (1/2, 1/2, 1), (1/2, 0, 2) in the plane
  //   x = 1/2, moving down by 1: at t < 1 all of M is above z = 0; at t = 1 its bottom side
  //   (1/2, y, 0), |y| <= 1/2, lies on T's plane and meets T along (1/2, [0, 1/2], 0).
  MeshSpec t;
  t.is_static = true;
  t.start.resize(3, 3);
  t.start << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  t.triangles.resize(1, 3);
  t.triangles << 0, 1, 2;
  t.end = t.start;
  MeshSpec points;
  points.start.resize(4, 3);
  points.start << 0.25, 0.25, 1, 0.25, 0.5, 0, 0.5, 0.5, 0.5, 2, 2, 1;
  points.end.resize(4, 3);
  points.end << 0.25, 0.25, 0, 0.25, 0.5, -1, 0.5, 0.5, -0.5, 2, 2, -1;
  points.triangles.resize(0, 3);
  MeshSpec m;
  m.start.resize(3, 3);
  m.start << 0.5, -0.5, 1, 0.5, 0.5, 1, 0.5, 0, 2;
  m.end = m.start;
  m.end.col(2).array() -= 1.0;
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 2;
  const SceneSpec spec{t, points, m};

  // Edges of T: 0 = (0,1) on y = 0, 1 = (0,2) on x = 0, 2 = (1,2) on x + y = 1.
  // Edges of M: 0 = (0,1) its bottom side, 1 = (0,2), 2 = (1,2).
  using Q = QueryType;
  const std::vector<SceneContact> expected{
      {{Q::vertex_face, 1, 0, 0, 0}, 1.0, 1.0},  // P at t = 1
      {{Q::vertex_face, 1, 1, 0, 0}, 0.0, 0.0},  // Q at t = 0
      {{Q::vertex_face, 1, 2, 0, 0}, 0.5, 0.5},  // R at t = 1/2
      {{Q::vertex_face, 2, 1, 0, 0}, 1.0, 1.0},  // M's vertex (1/2, 1/2, 0) on T's side at t = 1
      {{Q::edge_edge, 0, 0, 2, 0}, 1.0, 1.0},    // M's bottom crosses T's side y = 0 at t = 1
      {{Q::edge_edge, 0, 2, 2, 0}, 1.0, 1.0},    // ... and touches x + y = 1 at its end
      {{Q::edge_edge, 0, 2, 2, 2}, 1.0, 1.0},    // M's side from (1/2, 1/2) touches x + y = 1
  };
  {
    const auto [got, ref] = check_scene(spec);
    EXPECT_TRUE(same_contacts(got.contacts, expected));
    EXPECT_TRUE(same_contact(got.earliest, expected[1]));
  }
  {
    // t_max = 1/2: the interval is closed, R's contact at exactly 1/2 counts.
    SceneOptions o;
    o.ccd.t_max = 0.5;
    const auto [got, ref] = check_scene(spec, o);
    EXPECT_TRUE(same_contacts(got.contacts, {expected[1], expected[2]}));
  }
  {
    SceneOptions o;
    o.ccd.t_max = 0.25;
    const auto [got, ref] = check_scene(spec, o);
    EXPECT_TRUE(same_contacts(got.contacts, {expected[1]}));
  }
}

TEST(SceneAdversarial, DuplicatedMeshesTouchEverywhereAtZero) {
  // Two moving copies with identical motion: every vertex lies on each triangle of the other
  // copy that holds its twin, and every edge on its twin, at every time, so those pairs collide
  // at exactly t = 0.
  MeshSpec a = grid(4, 3, {0, 0, 0}, {1, 0.25, 0.125}, {0, 1, 0.5});
  for (Eigen::Index r = 0; r < a.start.rows(); ++r) a.start(r, 2) += 0.0625 * (r % 3);
  a.end = a.start;
  a.end.col(0).array() += 0.375;
  a.end.col(2).array() -= 0.25;
  const SceneSpec spec{a, a};
  const auto checked = check_scene(spec);
  const SceneResult& got = checked.first;
  auto find = [&](const ScenePair& p) {
    return std::find_if(got.contacts.begin(), got.contacts.end(),
                        [&](const SceneContact& c) { return c.pair == p; });
  };
  const Edges edges = derive_edges(a.triangles);
  for (std::uint32_t v = 0; v < a.start.rows(); ++v)
    for (std::uint32_t f = 0; f < a.triangles.rows(); ++f) {
      const auto vi = static_cast<std::int32_t>(v);
      if (a.triangles(f, 0) != vi && a.triangles(f, 1) != vi && a.triangles(f, 2) != vi)
        continue;
      for (auto p : {ScenePair{QueryType::vertex_face, 0, v, 1, f},
                     ScenePair{QueryType::vertex_face, 1, v, 0, f}}) {
        const auto it = find(p);
        ASSERT_NE(it, got.contacts.end()) << describe(p);
        EXPECT_EQ(it->toi_lo, 0.0) << describe(p);
        EXPECT_EQ(it->toi_hi, 0.0) << describe(p);
      }
    }
  for (std::uint32_t e = 0; e < edges.rows(); ++e) {
    const auto it = find({QueryType::edge_edge, 0, e, 1, e});
    ASSERT_NE(it, got.contacts.end()) << "edge " << e;
    EXPECT_EQ(it->toi_lo, 0.0);
  }
  EXPECT_EQ(got.earliest.toi_lo, 0.0);
}

TEST(SceneAdversarial, CubeMovingOntoStaticCopyOfItself) {
  // A unit cube falls from height 2 onto a static copy of itself (ending exactly on it): its
  // bottom face z = 2(1 - t) first meets the copy's top face z = 1 at t = 1/2.
  MeshSpec fixed = box_mesh({0, 0, 0}, {1, 1, 1});
  fixed.is_static = true;
  MeshSpec falling = box_mesh({0, 0, 0}, {1, 1, 1});
  falling.end = falling.start;
  falling.start.col(2).array() += 2.0;
  const auto [got, ref] = check_scene({fixed, falling});
  ASSERT_FALSE(got.contacts.empty());
  EXPECT_EQ(got.earliest.toi_lo, 0.5);
  EXPECT_EQ(got.earliest.toi_hi, 0.5);
  // The falling cube's bottom corner (0,0,·) = vertex 0 reaches the top corner (0,0,1) of the
  // copy, a vertex of its top triangle 4 = (4,5,6), at t = 1/2.
  const ScenePair corner{QueryType::vertex_face, 1, 0, 0, 4};
  const auto it = std::find_if(got.contacts.begin(), got.contacts.end(),
                               [&](const SceneContact& c) { return c.pair == corner; });
  ASSERT_NE(it, got.contacts.end());
  EXPECT_EQ(it->toi_lo, 0.5);
}

TEST(SceneAdversarial, CoplanarSheetsSlidingInPlane) {
  // Two sheets in z = 0, one static, one sliding over it in x; and two moving sheets sliding
  // in opposite directions with a shared line. Every pair is coplanar at all times.
  MeshSpec fixed = grid(4, 4, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  fixed.is_static = true;
  MeshSpec sliding = grid(3, 4, {-1.25, 0.125, 0}, {1, 0, 0}, {0, 0.75, 0});
  sliding.end = sliding.start;
  sliding.end.col(0).array() += 0.75;
  check_scene({fixed, sliding});
  MeshSpec left = grid(3, 3, {0, 0, 0}, {0.5, 0, 0}, {0, 1, 0});
  MeshSpec right = grid(3, 3, {0.5, 0, 0}, {0.5, 0, 0}, {0, 1, 0});
  left.end = left.start;
  left.end.col(1).array() += 0.25;
  right.end = right.start;
  right.end.col(1).array() -= 0.25;
  check_scene({left, right});
}

TEST(SceneAdversarial, ZeroMotionContactsAreAtTimeZero) {
  // Nothing moves: a contact at any time is a contact at t = 0.
  Rng rng(test_seed() + 4);
  for (int scene_index = 0; scene_index < 4; ++scene_index) {
    SceneSpec spec = random_scene(rng);
    for (MeshSpec& m : spec) m.end = m.start;
    SCOPED_TRACE("random scene " + std::to_string(scene_index));
    const auto [got, ref] = check_scene(spec);
    for (const SceneContact& c : got.contacts) {
      EXPECT_EQ(c.toi_lo, 0.0) << describe(c);
      EXPECT_EQ(c.toi_hi, 0.0) << describe(c);
    }
  }
}

TEST(SceneAdversarial, DegenerateTriangles) {
  // Triangles with collinear vertices and with two vertices at one position (distinct indices),
  // and a vertex-only mesh: they are the segments and points they are.
  MeshSpec flat;
  flat.start.resize(6, 3);
  flat.start << 0, 0, 0, 0.5, 0.5, 0, 1, 1, 0,  // collinear
      0, 1, 0, 0, 1, 0, 1, 0, 0;                 // vertices 3 and 4 coincide
  flat.triangles.resize(3, 3);
  flat.triangles << 0, 1, 2, 3, 4, 5, 2, 4, 0;
  flat.end = flat.start;
  flat.end.col(2).array() += 0.5;
  MeshSpec sheet = grid(3, 3, {-0.25, -0.25, 0.25}, {1.5, 0, 0}, {0, 1.5, 0});
  sheet.is_static = true;
  MeshSpec needle;  // a segment-triangle whose end moves across the collinear triangle's line
  needle.start.resize(3, 3);
  needle.start << 0.75, 0.25, 0.5, 0.25, 0.75, 0.5, 0.5, 0.5, 0.5;
  needle.end = needle.start;
  needle.end.col(2).array() -= 0.5;
  needle.triangles.resize(1, 3);
  needle.triangles << 0, 1, 2;
  MeshSpec points;
  points.start.resize(2, 3);
  points.start << 0.5, 0.5, -1, 0.25, 0.75, 1;
  points.end.resize(2, 3);
  points.end << 0.5, 0.5, 1, 0.25, 0.75, -1;
  points.triangles.resize(0, 3);
  const auto [got, ref] = check_scene({flat, sheet, needle, points});
  EXPECT_FALSE(got.contacts.empty());
}

/// Rotates the vertices with x > fold_x about the line x = fold_x, z = 0 by `angle` (radians),
/// in the xz-plane: the end positions of a fold (each vertex moves on the chord).
Positions folded(const Positions& flat, double fold_x, double angle) {
  Positions x = flat;
  for (Eigen::Index r = 0; r < x.rows(); ++r) {
    const double d = flat(r, 0) - fold_x;
    if (d <= 0) continue;
    x(r, 0) = fold_x + d * std::cos(angle);
    x(r, 2) = flat(r, 2) + d * std::sin(angle);
  }
  return x;
}

TEST(SceneAdversarial, ClothFoldingOntoItself) {
  // A 9 x 9 grid folds about its middle line: first to upright, then past flat so that the
  // folding half passes through the other half (self-collision), then away again.
  MeshSpec cloth = grid(9, 9, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const Positions flat = cloth.start;
  const double pi = std::acos(-1.0);
  const std::vector<Positions> keyframes{flat, folded(flat, 0.5, pi / 2),
                                         folded(flat, 0.5, pi + 0.25), folded(flat, 0.5, pi - 0.5)};
  Scene scene;
  const MeshId id = scene.add_mesh(flat, cloth.triangles);
  std::size_t contacts = 0;
  for (std::size_t step = 0; step + 1 < keyframes.size(); ++step) {
    SCOPED_TRACE("step " + std::to_string(step));
    cloth.start = keyframes[step];
    cloth.end = keyframes[step + 1];
    scene.set_motion(id, cloth.start, cloth.end);
    contacts += check_step(scene, {cloth}, {}).first.contacts.size();
  }
  EXPECT_GT(contacts, 0u);
}

// ---------------------------------------------------------------------------------------------
// 3. Thread-count invariance

/// A 31 x 31 vertex grid (1,800 triangles) with a small bump falling onto a static box, its
/// part x > 0.7 folding over; keyframe k of `steps`.
std::vector<SceneSpec> falling_cloth_steps(int steps) {
  MeshSpec cloth = grid(31, 31, {0, 0, 0.05}, {1, 0, 0}, {0, 1, 0});
  for (Eigen::Index r = 0; r < cloth.start.rows(); ++r)
    cloth.start(r, 2) += 0.004 * std::sin(7.0 * cloth.start(r, 0) + 5.0 * cloth.start(r, 1));
  MeshSpec box = box_mesh({0.2, 0.2, -0.5}, {0.8, 0.8, 0.0});
  box.is_static = true;
  auto keyframe = [&](int k) {
    Positions x = folded(cloth.start, 0.7, 0.6 * k);
    x.col(2).array() -= 0.03 * k;
    return x;
  };
  std::vector<SceneSpec> out;
  for (int k = 0; k < steps; ++k) {
    MeshSpec c = cloth;
    c.start = keyframe(k);
    c.end = keyframe(k + 1);
    out.push_back({box, c});
  }
  return out;
}

TEST(SceneThreads, ResultsDoNotDependOnThreadCount) {
  const std::vector<SceneSpec> steps = falling_cloth_steps(3);
  std::vector<std::vector<SceneResult>> results;  // [threads][step]
  std::vector<std::vector<EarliestContact>> earliest;
  for (int threads : {1, 2, 4, 8}) {
    Scene scene;
    scene.add_static_mesh(steps[0][0].start, steps[0][0].triangles);
    const MeshId cloth = scene.add_mesh(steps[0][1].start, steps[0][1].triangles);
    SceneOptions o;
    o.max_threads = threads;
    o.record_candidates = true;
    results.emplace_back();
    earliest.emplace_back();
    for (const SceneSpec& s : steps) {
      scene.set_motion(cloth, s[1].start, s[1].end);
      results.back().push_back(scene.find_contacts(o));
      earliest.back().push_back(scene.earliest_contact(o));
    }
  }
  std::size_t contacts = 0;
  for (std::size_t step = 0; step < steps.size(); ++step) {
    const SceneResult& one = results[0][step];
    contacts += one.contacts.size();
    for (std::size_t t = 1; t < results.size(); ++t) {
      SCOPED_TRACE("step " + std::to_string(step) + ", thread setting " + std::to_string(t));
      const SceneResult& r = results[t][step];
      EXPECT_TRUE(same_contacts(r.contacts, one.contacts));
      EXPECT_TRUE(same_pairs(r.candidates, one.candidates));
      EXPECT_EQ(r.stats.vertex_face_candidates, one.stats.vertex_face_candidates);
      EXPECT_EQ(r.stats.edge_edge_candidates, one.stats.edge_edge_candidates);
      EXPECT_EQ(r.stats.narrow_phase_tests, one.stats.narrow_phase_tests);
      if (!one.contacts.empty()) {
        EXPECT_TRUE(same_contact(r.earliest, one.earliest));
      }
      EXPECT_EQ(earliest[t][step].collides, earliest[0][step].collides);
      if (earliest[0][step].collides) {
        EXPECT_TRUE(same_contact(earliest[t][step].contact, earliest[0][step].contact));
      }
    }
    EXPECT_EQ(earliest[0][step].collides, !one.contacts.empty());
    if (!one.contacts.empty()) {
      EXPECT_TRUE(same_contact(earliest[0][step].contact, one.earliest));
    }
  }
  std::cout << "[ info     ] " << contacts << " contacts over " << steps.size() << " steps, "
            << results[0].back().candidates.size() << " candidates in the last\n";
  EXPECT_GT(contacts, 0u);
}

TEST(SceneThreads, LargeSceneEqualsBruteForce) {
  // The step of the falling cloth where it reaches the box and folds (about 5.6 million allowed
  // pairs), with the default thread count.
  const SceneSpec spec = falling_cloth_steps(2)[1];
  const auto [got, ref] = check_scene(spec);
  std::cout << "[ info     ] " << ref.vertex_face_pairs + ref.edge_edge_pairs << " allowed pairs, "
            << ref.swept_overlaps.size() << " candidates, " << ref.contacts.size()
            << " contacts\n";
  EXPECT_FALSE(got.contacts.empty());
}

TEST(SceneThreads, TiedContactsAgreeWithBruteForceForEveryThreadCount) {
  // Many pairs with exactly the same contact time: earliest_contact's pruning must still return
  // the first of them in pair order, whichever thread finds which pair first.
  MeshSpec fixed = box_mesh({0, 0, 0}, {1, 1, 1});
  fixed.is_static = true;
  MeshSpec falling = box_mesh({0, 0, 0}, {1, 1, 1});
  falling.end = falling.start;
  falling.start.col(2).array() += 2.0;
  MeshSpec sheet = grid(4, 4, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  sheet.end = sheet.start;
  sheet.end.col(0).array() += 0.5;
  // Falling from height 3 instead: first contact at t = 2/3, not a double (toi_lo < toi_hi).
  MeshSpec falling_from_3 = falling;
  falling_from_3.start.col(2).array() += 1.0;
  const std::vector<SceneSpec> scenes{{fixed, falling},        {falling, falling},
                                      {sheet, sheet},          {fixed, sheet, falling},
                                      {fixed, falling_from_3}, {sheet, fixed, falling_from_3}};
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    SCOPED_TRACE("scene " + std::to_string(i));
    const auto [want, ref] = check_scene(scenes[i]);  // the default thread count
    for (int threads : {1, 2, 4, 8}) {
      SCOPED_TRACE("max_threads " + std::to_string(threads));
      SceneOptions o;
      o.max_threads = threads;
      Scene scene = make_scene(scenes[i]);
      for (int call = 0; call < 2; ++call) {
        const SceneResult got = scene.find_contacts(o);
        EXPECT_TRUE(same_contacts(got.contacts, ref.contacts));
        const EarliestContact e = scene.earliest_contact(o);
        ASSERT_TRUE(e.collides);
        EXPECT_TRUE(same_contact(e.contact, earliest_of(ref.contacts)))
            << "got " << describe(e.contact) << ", expected "
            << describe(earliest_of(ref.contacts));
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 4. Static rules

TEST(SceneStaticRules, TwoStaticMeshesAreNeverTested) {
  MeshSpec a = box_mesh({0, 0, 0}, {1, 1, 1});
  a.is_static = true;
  MeshSpec b = box_mesh({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});  // overlapping, and a copy of a
  b.is_static = true;
  const auto [got, ref] = check_scene({a, b, a});
  EXPECT_EQ(ref.vertex_face_pairs + ref.edge_edge_pairs, 0u);
  EXPECT_TRUE(got.contacts.empty());
  EXPECT_TRUE(got.candidates.empty());
  EXPECT_EQ(got.stats.narrow_phase_tests, 0u);
  Scene scene = make_scene({a, b});
  EXPECT_FALSE(scene.earliest_contact().collides);
}

TEST(SceneStaticRules, StaticVertexAgainstMovingTriangle) {
  // Mesh 0: static triangle (0,0,0), (1,0,0), (0,1,0). Mesh 1: a large horizontal triangle
  // (-1,-1,z), (3,-1,z), (-1,3,z) moving from z = 1 to z = -1; its projection holds the static
  // triangle and its sides stay away from it, so the only contacts are the three static
  // vertices against the moving triangle, at t = 1/2.
  MeshSpec s;
  s.is_static = true;
  s.start.resize(3, 3);
  s.start << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  s.end = s.start;
  s.triangles.resize(1, 3);
  s.triangles << 0, 1, 2;
  MeshSpec m;
  m.start.resize(3, 3);
  m.start << -1, -1, 1, 3, -1, 1, -1, 3, 1;
  m.end = m.start;
  m.end.col(2).array() = -1;
  m.triangles = s.triangles;
  const auto [got, ref] = check_scene({s, m});
  std::vector<SceneContact> expected;
  for (std::uint32_t v = 0; v < 3; ++v)
    expected.push_back({{QueryType::vertex_face, 0, v, 1, 0}, 0.5, 0.5});
  EXPECT_TRUE(same_contacts(got.contacts, expected));
}

TEST(SceneStaticRules, SelfCollisionFalseDropsExactlyTheSelfPairs) {
  Rng rng(test_seed() + 5);
  // The folding cloth of ClothFoldingOntoItself (self contacts) plus random meshes.
  MeshSpec cloth = grid(7, 7, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  cloth.start = folded(cloth.start, 0.5, std::acos(-1.0) / 2);
  cloth.end = folded(grid(7, 7, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}).start, 0.5,
                     std::acos(-1.0) + 0.25);
  std::size_t self_contacts = 0;
  for (int scene_index = 0; scene_index < 3; ++scene_index) {
    SceneSpec spec = random_scene(rng);
    spec.push_back(cloth);
    SCOPED_TRACE("scene " + std::to_string(scene_index));
    SceneOptions with, without;
    without.self_collision = false;
    const auto [all, ref_all] = check_scene(spec, with);
    const auto [other, ref_other] = check_scene(spec, without);
    std::vector<SceneContact> expected;
    for (const SceneContact& c : all.contacts)
      if (c.pair.first_mesh != c.pair.second_mesh) expected.push_back(c);
    self_contacts += all.contacts.size() - expected.size();
    EXPECT_TRUE(same_contacts(other.contacts, expected));
    std::vector<ScenePair> expected_candidates;
    for (const ScenePair& p : all.candidates)
      if (p.first_mesh != p.second_mesh) expected_candidates.push_back(p);
    EXPECT_TRUE(same_pairs(other.candidates, expected_candidates));
  }
  EXPECT_GT(self_contacts, 0u);
}

// ---------------------------------------------------------------------------------------------
// 5. Steps: refit and rebuild

TEST(SceneSteps, SteppingEqualsAFreshSceneEachStep) {
  Rng rng(test_seed() + 6);
  for (int scene_index = 0; scene_index < 3; ++scene_index) {
    SCOPED_TRACE("scene " + std::to_string(scene_index));
    SceneSpec spec = random_scene(rng);
    // Also a moving point cloud (no edges, no triangles) and a moving empty mesh: hierarchies
    // with no primitives are built and refitted too.
    MeshSpec cloud;
    cloud.start.resize(5, 3);
    for (Eigen::Index r = 0; r < 5; ++r)
      for (int k = 0; k < 3; ++k) cloud.start(r, k) = uniform(rng, 0, 1);
    cloud.end = cloud.start;
    cloud.triangles.resize(0, 3);
    MeshSpec empty;
    empty.start.resize(0, 3);
    empty.end = empty.start;
    empty.triangles.resize(0, 3);
    spec.push_back(cloud);
    spec.push_back(empty);
    // Small, smooth motions: each step moves every vertex by a bounded translation plus a
    // little jitter, keeping the hierarchies' shape good (refit only).
    Scene stepped;
    for (const MeshSpec& m : spec)
      if (m.is_static) stepped.add_static_mesh(m.start, m.triangles);
      else stepped.add_mesh(m.start, m.triangles);
    std::vector<Eigen::Vector3d> velocity(spec.size());
    for (auto& v : velocity)
      for (int k = 0; k < 3; ++k) v[k] = uniform(rng, -0.02, 0.02);
    for (int step = 0; step < 4; ++step) {
      SCOPED_TRACE("step " + std::to_string(step));
      for (std::size_t i = 0; i < spec.size(); ++i) {
        MeshSpec& m = spec[i];
        if (m.is_static) continue;
        m.start = m.end;
        for (Eigen::Index r = 0; r < m.end.rows(); ++r)
          for (int k = 0; k < 3; ++k) m.end(r, k) += velocity[i][k] + uniform(rng, -1e-3, 1e-3);
        stepped.set_motion(static_cast<MeshId>(i), m.start, m.end);
      }
      const auto [got, ref] = check_step(stepped, spec, {});
      // The hierarchies of the start and of the end positions follow the steps too.
      SceneOptions static_bvh;
      static_bvh.broad_phase = BroadPhase::static_bvh;
      check_step(stepped, spec, static_bvh);
      Scene fresh = make_scene(spec);
      SceneOptions recording;
      recording.record_candidates = true;
      const SceneResult fresh_result = fresh.find_contacts(recording);
      EXPECT_TRUE(same_contacts(got.contacts, fresh_result.contacts));
      EXPECT_TRUE(same_pairs(got.candidates, fresh_result.candidates));
      EXPECT_GT(fresh_result.stats.hierarchies_built, 0u);
      if (step == 0) {
        EXPECT_GT(got.stats.hierarchies_built, 0u);
      } else {
        // check_step's first call of this step: refits the moved meshes, builds nothing.
        EXPECT_EQ(got.stats.hierarchies_built, 0u);
        EXPECT_GT(got.stats.hierarchies_refitted, 0u);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 6. Options

TEST(SceneOptionsTest, TmaxAndToiWidthPassThrough) {
  Rng rng(test_seed() + 7);
  for (int scene_index = 0; scene_index < 4; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    SCOPED_TRACE("scene " + std::to_string(scene_index));
    for (double t_max : {0.25, 0.7}) {
      SceneOptions o;
      o.ccd.t_max = t_max;
      check_scene(spec, o);
    }
    SceneOptions wide;
    wide.ccd.toi_width = 0.01;
    check_scene(spec, wide);
    SceneOptions both;
    both.ccd.t_max = 0.5;
    both.ccd.toi_width = 1e-6;
    check_scene(spec, both);
  }
}

TEST(SceneOptionsTest, ExactModeEqualsDefault) {
  Rng rng(test_seed() + 8);
  for (int scene_index = 0; scene_index < 3; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    SCOPED_TRACE("scene " + std::to_string(scene_index));
    SceneOptions exact;
    exact.ccd.mode = Mode::exact;
    Scene scene = make_scene(spec);
    const SceneResult a = scene.find_contacts();
    const SceneResult b = scene.find_contacts(exact);
    EXPECT_TRUE(same_contacts(b.contacts, a.contacts));
    if (!a.contacts.empty()) {
      EXPECT_TRUE(same_contact(b.earliest, a.earliest));
    }
  }
}

TEST(SceneOptionsTest, StaticBvhSeesOnlyInstantOverlapsAndMissesTunnelling) {
  // A small triangle falls from z = 1 to z = -1 through a large static triangle at z = 0: its
  // boxes at t = 0 and t = 1 are far from the static one, so static_bvh cannot see the contact
  // (its three vertices cross the static triangle at t = 1/2).
  MeshSpec wall;
  wall.is_static = true;
  wall.start.resize(3, 3);
  wall.start << -1, -1, 0, 3, -1, 0, -1, 3, 0;
  wall.end = wall.start;
  wall.triangles.resize(1, 3);
  wall.triangles << 0, 1, 2;
  MeshSpec bullet;
  bullet.start.resize(3, 3);
  bullet.start << 0, 0, 1, 0.125, 0, 1, 0, 0.125, 1;
  bullet.end = bullet.start;
  bullet.end.col(2).array() = -1;
  bullet.triangles = wall.triangles;
  SceneOptions static_bvh;
  static_bvh.broad_phase = BroadPhase::static_bvh;
  const auto [swept, ref] = check_scene({wall, bullet});
  std::vector<SceneContact> tunnelling;
  for (std::uint32_t v = 0; v < 3; ++v)
    tunnelling.push_back({{QueryType::vertex_face, 1, v, 0, 0}, 0.5, 0.5});
  EXPECT_TRUE(same_contacts(swept.contacts, tunnelling));
  const auto [missed, ref2] = check_scene({wall, bullet}, static_bvh);
  EXPECT_TRUE(missed.contacts.empty());
  EXPECT_TRUE(missed.candidates.empty());

  // Random scenes: static_bvh's contacts are the swept ones whose boxes overlap at t = 0 or 1.
  Rng rng(test_seed() + 9);
  for (int scene_index = 0; scene_index < 4; ++scene_index) {
    SceneSpec spec = random_scene(rng);
    spec.push_back(wall);
    spec.push_back(bullet);
    SCOPED_TRACE("scene " + std::to_string(scene_index));
    const auto [s, r] = check_scene(spec, static_bvh);
    Scene scene = make_scene(spec);
    const SceneResult all = scene.find_contacts();
    EXPECT_TRUE(std::includes(all.contacts.begin(), all.contacts.end(), s.contacts.begin(),
                              s.contacts.end(), [](const SceneContact& a, const SceneContact& b) {
                                return a.pair < b.pair;
                              }));
    EXPECT_LT(s.contacts.size(), all.contacts.size());  // at least the planted one is missed
  }
}

TEST(SceneOptionsTest, BadInputThrows) {
  Positions tri_positions(3, 3);
  tri_positions << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  Triangles tri(1, 3);
  tri << 0, 1, 2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  Scene scene;
  Positions bad = tri_positions;
  bad(1, 2) = nan;
  EXPECT_THROW(scene.add_mesh(bad, tri), std::invalid_argument);
  EXPECT_THROW(scene.add_static_mesh(bad, tri), std::invalid_argument);
  bad(1, 2) = inf;
  EXPECT_THROW(scene.add_mesh(bad, tri), std::invalid_argument);
  for (auto row : {Eigen::Vector3i(0, 1, 3), Eigen::Vector3i(-1, 1, 2), Eigen::Vector3i(0, 1, 1),
                   Eigen::Vector3i(2, 1, 2)}) {
    Triangles t(1, 3);
    t.row(0) = row.transpose().cast<std::int32_t>();
    EXPECT_THROW(scene.add_mesh(tri_positions, t), std::invalid_argument) << row.transpose();
    EXPECT_THROW(scene.add_static_mesh(tri_positions, t), std::invalid_argument)
        << row.transpose();
  }
  EXPECT_EQ(scene.mesh_count(), 0u);  // failed additions add nothing

  const MeshId moving = scene.add_mesh(tri_positions, tri);
  const MeshId fixed = scene.add_static_mesh(tri_positions, tri);
  EXPECT_EQ(scene.mesh_count(), 2u);
  EXPECT_THROW(scene.set_motion(fixed, tri_positions, tri_positions), std::invalid_argument);
  EXPECT_THROW(scene.set_motion(moving, tri_positions.topRows(2), tri_positions),
               std::invalid_argument);
  EXPECT_THROW(scene.set_motion(moving, tri_positions, tri_positions.topRows(2)),
               std::invalid_argument);
  bad = tri_positions;
  bad(0, 0) = nan;
  EXPECT_THROW(scene.set_motion(moving, bad, tri_positions), std::invalid_argument);
  EXPECT_THROW(scene.set_motion(moving, tri_positions, bad), std::invalid_argument);
  bad(0, 0) = -inf;
  EXPECT_THROW(scene.set_motion(moving, tri_positions, bad), std::invalid_argument);

  // Bad options (the per-pair functions' domain, and the thread count).
  for (double t_max : {-0x1p-1074, -0.5, 1.5, nan}) {  // 0: the state at the start, allowed
    SceneOptions o;
    o.ccd.t_max = t_max;
    EXPECT_THROW(scene.find_contacts(o), std::invalid_argument) << t_max;
    EXPECT_THROW(scene.earliest_contact(o), std::invalid_argument) << t_max;
  }
  for (double width : {-1.0, nan, inf}) {
    SceneOptions o;
    o.ccd.toi_width = width;
    EXPECT_THROW(scene.find_contacts(o), std::invalid_argument) << width;
  }
  // -1, and one past kMaxThreads (TBB's arena crashed there before it was refused).
  for (int threads : {-1, kMaxThreads + 1, std::numeric_limits<int>::max()}) {
    SceneOptions o;
    o.max_threads = threads;
    EXPECT_THROW(scene.find_contacts(o), std::invalid_argument) << threads;
    EXPECT_THROW(scene.earliest_contact(o), std::invalid_argument) << threads;
  }
  SceneOptions static_bvh;
  static_bvh.broad_phase = BroadPhase::static_bvh;
  EXPECT_THROW(scene.earliest_contact(static_bvh), std::invalid_argument);
  // The scene still works after the rejected calls.
  EXPECT_NO_THROW(scene.find_contacts());
}

TEST(SceneOptionsTest, EmptyScene) {
  Scene scene;
  EXPECT_EQ(scene.mesh_count(), 0u);
  const SceneResult r = scene.find_contacts();
  EXPECT_TRUE(r.contacts.empty());
  EXPECT_FALSE(scene.earliest_contact().collides);
}

}  // namespace
}  // namespace exactccd
