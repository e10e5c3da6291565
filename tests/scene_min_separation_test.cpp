// Tests of the scene's minimum separation (SceneOptions::min_separation, proofs/scene.md,
// section "min-separation").
//
// The reference is the brute force of tests/scene_support.hpp's rules: every pair the scene's
// rules allow, decided one by one by vertex_face_ccd / edge_edge_ccd with
// CcdOptions::min_separation = delta. The expected candidates are computed here independently of
// the library's arithmetic: a pair is a candidate iff on every axis its swept boxes (from
// scene_support.hpp) are at most delta apart as the raised boxes decide it, hi1 + delta rounded
// up to a double (with exact rationals, not the FPU's rounding mode) >= lo2 and the same the
// other way. For delta = 0 that is today's "closed boxes overlap" and the contacts are today's.
//
// Scenes: random ones (tests/random_scenes.hpp), steps of the simulation-like scenes
// (corpus/simulation_queries.hpp: a sheet draping over a sphere, two rigid bodies passing
// close), and hand-made pairs whose boxes are apart by less than delta without touching (the
// pairs a broad phase without the raise would drop), with TOIs worked out by hand.
//
// EXACTCCD_TEST_SEED overrides the seed of the random scenes.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "corpus/simulation_queries.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/scene.hpp"
#include "random_scenes.hpp"
#include "scene_support.hpp"
#include "test_scale.hpp"

namespace exactccd::test {
namespace {

// ---------------------------------------------------------------------------------------------
// The reference

/// The smallest double >= x (x well inside the double range). mpq's get_d truncates towards
/// zero, so one step up at most.
double round_up(const mpq_class& x) {
  double d = x.get_d();
  if (mpq_class(d) < x) d = std::nextafter(d, std::numeric_limits<double>::infinity());
  return d;
}

/// The meshes with every swept box's upper corner raised by delta, each sum rounded up to a
/// double exactly: two raised boxes overlap iff on every axis up(a.hi + delta) >= b.lo and
/// up(b.hi + delta) >= a.lo.
std::vector<RefMesh> raised_swept_boxes(std::vector<RefMesh> meshes, double delta) {
  for (RefMesh& m : meshes)
    for (auto* boxes : {&m.vertex_boxes, &m.edge_boxes, &m.face_boxes})
      for (PrimitiveBoxes& b : *boxes)
        for (double& hi : b.swept.hi) hi = round_up(mpq_class(hi) + mpq_class(delta));
  return meshes;
}

/// The boxes (not raised) of the pair's first and second primitive.
std::pair<const PrimitiveBoxes*, const PrimitiveBoxes*> boxes_of_pair(
    const std::vector<RefMesh>& meshes, const ScenePair& p) {
  const RefMesh& a = meshes[p.first_mesh];
  const RefMesh& b = meshes[p.second_mesh];
  if (p.type == QueryType::vertex_face)
    return {&a.vertex_boxes[p.first_index], &b.face_boxes[p.second_index]};
  return {&a.edge_boxes[p.first_index], &b.edge_boxes[p.second_index]};
}

struct SeparationReference {
  std::uint64_t pairs = 0;              ///< allowed pairs
  std::vector<SceneContact> contacts;   ///< pairs within delta, in pair order, per-pair TOIs
  std::vector<ScenePair> candidates;    ///< pairs whose raised swept boxes overlap
  /// The subset whose boxes blended from start to end come within delta by t_max (exactly).
  std::vector<ScenePair> timed;
  /// Contacts whose swept boxes (not raised) are disjoint: dropped without the raise.
  std::uint64_t apart_but_within = 0;
};

SeparationReference brute_force_within(const std::vector<RefMesh>& meshes, const CcdOptions& ccd,
                                       bool self_collision) {
  SeparationReference r;
  const std::vector<RefMesh> raised = raised_swept_boxes(meshes, ccd.min_separation);
  for_each_allowed_pair(raised, self_collision, [&](const ScenePair& p, const PrimitiveBoxes& a,
                                                    const PrimitiveBoxes& b) {
    ++r.pairs;
    const CcdResult c = p.type == QueryType::vertex_face
                            ? vertex_face_ccd(reference_vertex_face_query(meshes, p), ccd)
                            : edge_edge_ccd(reference_edge_edge_query(meshes, p), ccd);
    if (boxes_overlap(a.swept, b.swept)) {
      r.candidates.push_back(p);
      const auto [first, second] = boxes_of_pair(meshes, p);
      if (blended_boxes_meet_by(first->start, first->end, second->start, second->end, ccd.t_max,
                                ccd.min_separation))
        r.timed.push_back(p);
    }
    if (c.collides) {
      r.contacts.push_back({p, c.toi_lo, c.toi_hi});
      const auto [first, second] = boxes_of_pair(meshes, p);
      if (!boxes_overlap(first->swept, second->swept)) ++r.apart_but_within;
    }
  });
  return r;
}


/// find_contacts (contacts, earliest, candidates, counts) and earliest_contact of `scene` with
/// `options` against the brute force with delta = options.min_separation. Returns the reference.
SeparationReference check_step(Scene& scene, const SceneSpec& spec, const SceneOptions& options) {
  const std::vector<RefMesh> meshes = prepare_reference(spec);
  CcdOptions ccd = options.ccd;
  ccd.min_separation = options.min_separation;
  SeparationReference ref = brute_force_within(meshes, ccd, options.self_collision);

  SceneOptions recording = options;
  recording.record_candidates = true;
  const SceneResult got = scene.find_contacts(recording);
  EXPECT_TRUE(same_contacts(got.contacts, ref.contacts));
  // Culling by time keeps every pair whose blended boxes come within delta by t_max and
  // nothing whose raised swept boxes do not overlap.
  EXPECT_TRUE(contains_pairs(got.candidates, ref.timed));
  EXPECT_TRUE(contains_pairs(ref.candidates, got.candidates));
  if (got.stats.time_culled == 0) EXPECT_TRUE(same_pairs(got.candidates, ref.candidates));
  EXPECT_EQ(got.stats.vertex_face_candidates + got.stats.edge_edge_candidates,
            got.candidates.size());
  EXPECT_EQ(got.stats.narrow_phase_tests, got.candidates.size());
  const EarliestContact e = scene.earliest_contact(options);
  EXPECT_EQ(e.collides, !ref.contacts.empty());
  if (ref.contacts.empty()) {
    EXPECT_EQ(got.earliest.toi_lo, std::numeric_limits<double>::infinity());
    EXPECT_EQ(e.contact.toi_lo, std::numeric_limits<double>::infinity());
  } else {
    const SceneContact want = earliest_of(ref.contacts);
    EXPECT_TRUE(same_contact(got.earliest, want))
        << "find_contacts: " << describe(got.earliest) << ", expected " << describe(want);
    EXPECT_TRUE(same_contact(e.contact, want))
        << "earliest_contact: " << describe(e.contact) << ", expected " << describe(want);
  }
  return ref;
}

/// contacts(larger delta) includes contacts(smaller delta), never with a later toi_lo.
::testing::AssertionResult includes_no_later(const std::vector<SceneContact>& larger,
                                             const std::vector<SceneContact>& smaller) {
  auto it = larger.begin();
  for (const SceneContact& c : smaller) {
    while (it != larger.end() && it->pair < c.pair) ++it;
    if (it == larger.end() || !(it->pair == c.pair))
      return ::testing::AssertionFailure() << describe(c) << " lost with a larger delta";
    if (it->toi_lo > c.toi_lo)
      return ::testing::AssertionFailure()
             << describe(*it) << " later than " << describe(c) << " with a larger delta";
  }
  return ::testing::AssertionSuccess();
}

// ---------------------------------------------------------------------------------------------
// Random scenes

TEST(SceneMinSeparation, RandomScenesEqualBruteForce) {
  // Coordinates about [0, 1]; deltas from a tight one to a percent of the scene. One Scene per
  // spec serves every delta in turn (0 again at the end): its hierarchies must follow the delta
  // as they follow the positions. (Few scenes: a pair within delta at a time t > 0 takes the
  // exact procedure for its TOI, about a millisecond, three times here.)
  Rng rng(test_seed() + 101);
  const double deltas[] = {0.0, 0x1p-12, 0.01, 0.0};
  std::uint64_t contacts = 0, apart_but_within = 0, grown = 0;
  const int scenes = static_cast<int>(test::at_least(test::scaled_count(6), 2));
  for (int scene_index = 0; scene_index < scenes; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    Scene scene = make_scene(spec);
    std::vector<std::vector<SceneContact>> by_delta;
    for (double delta : deltas) {
      SCOPED_TRACE("random scene " + std::to_string(scene_index) + ", delta " + hex(delta));
      SceneOptions o;
      o.min_separation = delta;
      const SeparationReference ref = check_step(scene, spec, o);
      if (!by_delta.empty() && delta > 0) {
        EXPECT_TRUE(includes_no_later(ref.contacts, by_delta.back()));
        if (ref.contacts.size() > by_delta.back().size())
          grown += ref.contacts.size() - by_delta.back().size();
      }
      by_delta.push_back(ref.contacts);
      contacts += ref.contacts.size();
      apart_but_within += ref.apart_but_within;
    }
    // delta = 0 is today's scene: the same contacts as the default options, and as a scene
    // that never saw a delta.
    Scene fresh = make_scene(spec);
    EXPECT_TRUE(same_contacts(fresh.find_contacts().contacts, by_delta[0]));
    EXPECT_TRUE(same_contacts(by_delta[3], by_delta[0]));
    if (::testing::Test::HasFailure()) break;
  }
  std::cout << "[ info     ] " << contacts << " contacts, " << grown
            << " gained with a larger delta, " << apart_but_within
            << " with swept boxes apart (within delta only)\n";
  EXPECT_GT(grown, 0u);
  // Pairs within delta whose swept boxes are apart (the case the raise is for) occur here only
  // now and then (about one a scene); BoxesApartByLessThanDeltaAreKept makes them certain.
}

TEST(SceneMinSeparation, OptionsPassThroughWithDelta) {
  // t_max, toi_width, exact mode and the older broad phase's exclusion of earliest_contact, all
  // with a delta.
  Rng rng(test_seed() + 102);
  for (int scene_index = 0; scene_index < 2; ++scene_index) {
    const SceneSpec spec = random_scene(rng);
    Scene scene = make_scene(spec);
    SCOPED_TRACE("random scene " + std::to_string(scene_index));
    SceneOptions o;
    o.min_separation = 0.01;
    o.ccd.t_max = 0.4;
    check_step(scene, spec, o);
    o.ccd.t_max = 1.0;
    o.ccd.toi_width = 1e-3;
    check_step(scene, spec, o);
    // The scene's delta is given once: ccd.min_separation, even equal to it, is refused.
    SceneOptions twice = o;
    twice.ccd.min_separation = o.min_separation;
    EXPECT_THROW(scene.find_contacts(twice), std::invalid_argument);
    SceneOptions exact;
    exact.min_separation = 0.01;
    exact.ccd.mode = Mode::exact;
    SceneOptions filtered = exact;
    filtered.ccd.mode = Mode::filtered;
    EXPECT_TRUE(same_contacts(scene.find_contacts(exact).contacts,
                              scene.find_contacts(filtered).contacts));
    // The older scheme sees the pairs whose raised boxes overlap at t = 0 or t = 1: a subset
    // of the swept contacts, the same TOIs.
    SceneOptions instants = filtered;
    instants.broad_phase = BroadPhase::static_bvh;
    const std::vector<SceneContact> seen = scene.find_contacts(instants).contacts;
    const std::vector<SceneContact> all = scene.find_contacts(filtered).contacts;
    for (const SceneContact& c : seen)
      EXPECT_TRUE(std::any_of(all.begin(), all.end(),
                              [&](const SceneContact& a) { return same_contact(a, c); }))
          << describe(c);
    EXPECT_THROW(scene.earliest_contact(instants), std::invalid_argument);
  }
}

// ---------------------------------------------------------------------------------------------
// Hand-made pairs apart by less than delta

MeshSpec static_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c) {
  MeshSpec m;
  m.is_static = true;
  m.start.resize(3, 3);
  m.start.row(0) = a.transpose();
  m.start.row(1) = b.transpose();
  m.start.row(2) = c.transpose();
  m.end = m.start;
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 2;
  return m;
}

/// One vertex (no triangle) moving from p0 to p1.
MeshSpec moving_point(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) {
  MeshSpec m;
  m.start.resize(1, 3);
  m.start.row(0) = p0.transpose();
  m.end.resize(1, 3);
  m.end.row(0) = p1.transpose();
  m.triangles.resize(0, 3);
  return m;
}

TEST(SceneMinSeparation, BoxesApartByLessThanDeltaAreKept) {
  // delta = 5/64. A 3-4-5 triangle of distances makes the TOIs dyadic: a point at height
  // g = 3/64 over the plane z = 0 is within delta of a point there iff their horizontal
  // distance is at most 4/64 = 1/16.
  const double delta = 5.0 / 64, g = 3.0 / 64;
  const MeshSpec floor_triangle = static_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  // (a) A vertex at height g moving along x from -1 to 1 over y = 1/4: its box is g above the
  //     triangle's (apart, not touching); it comes within delta of the triangle's side x = 0 when
  //     x = -1/16, at t = (1 - 1/16) / 2 = 15/32.
  const MeshSpec gliding = moving_point({-1, 0.25, g}, {1, 0.25, g});
  // (b) At rest g above and 4/64 beyond the triangle's corner on both x and y (distance
  //     sqrt(41)/64 > delta): the raised boxes overlap (a candidate) but it never comes within.
  const MeshSpec beside = moving_point({-1.0 / 16, -1.0 / 16, g}, {-1.0 / 16, -1.0 / 16, g});
  const SceneSpec vertex_face{floor_triangle, gliding, beside};
  SceneOptions o;
  o.min_separation = delta;
  Scene scene = make_scene(vertex_face);
  const SeparationReference ref = check_step(scene, vertex_face, o);
  const std::vector<SceneContact> want{{{QueryType::vertex_face, 1, 0, 0, 0}, 15.0 / 32,
                                        15.0 / 32}};
  EXPECT_TRUE(same_contacts(ref.contacts, want));  // the reference agrees with the hand
  EXPECT_EQ(ref.apart_but_within, 1u);
  const SceneResult got = scene.find_contacts(o);
  EXPECT_TRUE(same_contacts(got.contacts, want));
  EXPECT_EQ(got.stats.vertex_face_candidates, 2u);  // (a) and (b)
  // Without the delta neither pair is a candidate: their boxes do not touch.
  const SceneResult plain = scene.find_contacts();
  EXPECT_TRUE(plain.contacts.empty());
  EXPECT_EQ(plain.stats.vertex_face_candidates + plain.stats.edge_edge_candidates, 0u);

  // (c) Edge-edge: a static edge on the x axis and an edge along y at height g over x = 1/2,
  //     y from s - 1/4 to s + 1/4 with s moving from -1 to 1: within delta once its upper end
  //     reaches y = -1/16, at s = -5/16, t = 11/32.
  MeshSpec axis = static_triangle({0, 0, 0}, {1, 0, 0}, {0.5, -0.5, -1});
  MeshSpec crossing;
  crossing.start.resize(3, 3);
  crossing.start << 0.5, -1.25, g, 0.5, -0.75, g, 0.5, -1, 1;
  crossing.end = crossing.start;
  crossing.end.col(1).array() += 2.0;
  crossing.triangles.resize(1, 3);
  crossing.triangles << 0, 1, 2;
  const SceneSpec edge_edge{axis, crossing};
  Scene edges = make_scene(edge_edge);
  const SeparationReference edge_ref = check_step(edges, edge_edge, o);
  const ScenePair wanted_pair{QueryType::edge_edge, 0, 0, 1, 0};  // edges (0,1) and (0,1)
  const auto it = std::find_if(edge_ref.contacts.begin(), edge_ref.contacts.end(),
                               [&](const SceneContact& c) { return c.pair == wanted_pair; });
  ASSERT_NE(it, edge_ref.contacts.end());
  EXPECT_EQ(it->toi_lo, 11.0 / 32);
  EXPECT_EQ(it->toi_hi, 11.0 / 32);
  EXPECT_GT(edge_ref.apart_but_within, 0u);
  EXPECT_EQ(edges.earliest_contact(o).contact.toi_lo, 11.0 / 32);
  SceneOptions recording;
  recording.record_candidates = true;
  const std::vector<ScenePair> plain_candidates = edges.find_contacts(recording).candidates;
  EXPECT_TRUE(std::find(plain_candidates.begin(), plain_candidates.end(), wanted_pair) ==
              plain_candidates.end());  // boxes g apart: dropped without the delta

  // (d) Exactly delta apart counts (closed): a vertex resting delta above the triangle's
  //     interior is a contact at t = 0; one ulp higher it is not, nor a candidate.
  for (const double height : {delta, std::nextafter(delta, 1.0)}) {
    SCOPED_TRACE("height " + hex(height));
    const SceneSpec resting{floor_triangle, moving_point({0.25, 0.25, height},
                                                          {0.25, 0.25, height})};
    Scene s = make_scene(resting);
    const SeparationReference r = check_step(s, resting, o);
    EXPECT_EQ(r.contacts.size(), height == delta ? 1u : 0u);
    EXPECT_EQ(r.candidates.size(), height == delta ? 1u : 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Simulation-like steps

/// The scenes of one simulation step as scene specs: the sheet (moving) over the static sphere,
/// and the two rigid bodies (moving).
std::vector<SceneSpec> specs_of(const sim::SimulationStep& step) {
  auto mesh_of = [&](std::size_t index, bool is_static) {
    const sim::MovingMesh& m = step.meshes[index];
    MeshSpec spec;
    spec.is_static = is_static;
    const auto n = static_cast<Eigen::Index>(m.topology->vertex_count);
    spec.start.resize(n, 3);
    spec.end.resize(n, 3);
    for (Eigen::Index v = 0; v < n; ++v) {
      spec.start.row(v) = m.start[static_cast<std::size_t>(v)].transpose();
      spec.end.row(v) = m.end[static_cast<std::size_t>(v)].transpose();
    }
    spec.triangles.resize(static_cast<Eigen::Index>(m.topology->triangles.size()), 3);
    for (std::size_t f = 0; f < m.topology->triangles.size(); ++f)
      for (int k = 0; k < 3; ++k)
        spec.triangles(static_cast<Eigen::Index>(f), k) =
            static_cast<std::int32_t>(m.topology->triangles[f][static_cast<std::size_t>(k)]);
    return spec;
  };
  return {{mesh_of(0, false), mesh_of(1, true)}, {mesh_of(2, false), mesh_of(3, false)}};
}

TEST(SceneMinSeparation, SimulationStepsEqualBruteForce) {
  // The small simulation (12 x 12 sheet, 48 steps): the sheet reaches the sphere after about 16
  // steps, the bodies pass closest halfway. Deltas relative to the sheet's side (1.6).
  const sim::SimulationConfig config = sim::small_simulation_config();
  const double size = 1.6;
  const double deltas[] = {0.0, 1e-4 * size, 3e-3 * size};
  std::vector<std::vector<SceneSpec>> steps;
  sim::simulate(config, [&](const sim::SimulationStep& step) {
    if (step.index == 16 || step.index == 24 || step.index == 32)
      steps.push_back(specs_of(step));
  });
  ASSERT_FALSE(steps.empty());
  std::uint64_t contacts[3] = {0, 0, 0}, apart_but_within = 0;
  for (std::size_t s = 0; s < steps.size(); ++s)
    for (std::size_t part = 0; part < steps[s].size(); ++part) {
      const SceneSpec& spec = steps[s][part];
      Scene scene = make_scene(spec);
      for (int d = 0; d < 3; ++d) {
        SCOPED_TRACE("step " + std::to_string(s) + ", part " + std::to_string(part) +
                     ", delta " + hex(deltas[d]));
        SceneOptions o;
        o.min_separation = deltas[d];
        const SeparationReference ref = check_step(scene, spec, o);
        contacts[d] += ref.contacts.size();
        apart_but_within += ref.apart_but_within;
        // Thread count changes nothing.
        SceneOptions one = o;
        one.max_threads = 1;
        EXPECT_TRUE(same_contacts(scene.find_contacts(one).contacts, ref.contacts));
      }
      if (::testing::Test::HasFailure()) return;
    }
  std::cout << "[ info     ] contacts with delta 0, 1e-4, 3e-3 of the size: " << contacts[0]
            << ", " << contacts[1] << ", " << contacts[2] << "; " << apart_but_within
            << " with swept boxes apart\n";
  EXPECT_GT(contacts[0], 0u);
  EXPECT_GT(contacts[2], contacts[0]);
  EXPECT_GT(apart_but_within, 0u);
}

// ---------------------------------------------------------------------------------------------
// Options

TEST(SceneMinSeparation, BadSeparationThrows) {
  Scene scene = make_scene({moving_point({0, 0, 0}, {1, 0, 0}),
                            static_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0})});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double delta : {-1e-300, -1.0, nan, inf, -inf}) {
    SceneOptions o;
    o.min_separation = delta;
    EXPECT_THROW(scene.find_contacts(o), std::invalid_argument) << delta;
    EXPECT_THROW(scene.earliest_contact(o), std::invalid_argument) << delta;
  }
  // The scene's delta is SceneOptions::min_separation alone: ccd.min_separation must stay 0
  // (a per-pair delta the broad phase was not told of would drop pairs; one equal to it would
  // be a second place to give it). Refused, whatever SceneOptions::min_separation is.
  SceneOptions only_pairs;
  only_pairs.ccd.min_separation = 0.1;
  for (const double scene_delta : {0.0, 0.1, 0.2}) {
    SceneOptions o = only_pairs;
    o.min_separation = scene_delta;
    try {
      scene.find_contacts(o);
      ADD_FAILURE() << "ccd.min_separation " << o.ccd.min_separation << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("SceneOptions::min_separation"), std::string::npos)
          << e.what();
    }
    EXPECT_THROW(scene.earliest_contact(o), std::invalid_argument);
  }
  SceneOptions once;
  once.min_separation = 0.1;
  EXPECT_NO_THROW(scene.find_contacts(once));
  EXPECT_FALSE(scene.find_contacts().contacts.empty());  // still works after the refusals
}

}  // namespace
}  // namespace exactccd::test
