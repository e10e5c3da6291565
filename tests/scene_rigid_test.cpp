// Rigid bodies in the Scene (Scene::add_rigid_body / set_rigid_motion): every contact the scene
// reports equals the per-query rigid function on that pair and no colliding pair is dropped
// (brute force over every allowed pair of primitives), never a pair within one rigid body,
// earliest_contact equals find_contacts().earliest, a rigid body with q = 0 equals a moving mesh
// with the translated end positions, the certified arc boxes hold exact positions at rational s,
// bad input throws. PROOF: proofs/scene.md#rigid-bodies
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "pipeline/scene/rigid_boxes.hpp"
#include "pipeline/scene/rigid_cylinder_ranges.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "random_scenes.hpp"
#include "scene_support.hpp"
#include "test_scale.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;
using test::make_scene;  // scene_support's, for scenes without rigid bodies

// ---------------------------------------------------------------------------------------------
// Scenes with rigid bodies, and the reference written from scene.hpp's rules

enum class Kind { rigid, deformable, fixed };

struct Body {
  Kind kind = Kind::rigid;
  Positions start, end;  ///< end: a deformable mesh's (a fixed mesh's equals start)
  Triangles triangles;
  RigidMotion motion;    ///< a rigid body's
};
using Bodies = std::vector<Body>;

Body body_of(Kind kind, const MeshSpec& m) {
  Body b;
  b.kind = kind;
  b.start = m.start;
  b.end = kind == Kind::deformable ? m.end : m.start;
  b.triangles = m.triangles;
  return b;
}

Scene make_scene(const Bodies& bodies) {
  Scene scene;
  for (const Body& b : bodies) {
    switch (b.kind) {
      case Kind::fixed: scene.add_static_mesh(b.start, b.triangles); break;
      case Kind::deformable: {
        const MeshId id = scene.add_mesh(b.start, b.triangles);
        scene.set_motion(id, b.start, b.end);
        break;
      }
      case Kind::rigid: {
        const MeshId id = scene.add_rigid_body(b.start, b.triangles);
        scene.set_rigid_motion(id, b.motion);
        break;
      }
    }
  }
  return scene;
}

template <std::size_t N>
SideMotion side_of(const Body& b, const std::array<std::int32_t, N>& vertices) {
  if (b.kind == Kind::rigid) return SideMotion::of(b.motion);
  SideMotion s;
  s.kind = PathKind::linear;
  for (std::size_t i = 0; i < N; ++i) s.linear_end[i] = point(b.end, vertices[i]);
  return s;
}

struct RigidReference {
  std::uint64_t pairs = 0;
  std::uint64_t rigid_rigid = 0, rigid_deformable = 0, rigid_fixed = 0, without_rigid = 0;
  std::vector<SceneContact> contacts;  ///< in ScenePair order
};

bool allowed(const Bodies& bodies, MeshId a, MeshId b, bool self_collision) {
  if (bodies[a].kind == Kind::fixed && bodies[b].kind == Kind::fixed) return false;
  if (a == b) return self_collision && bodies[a].kind == Kind::deformable;
  return true;
}

/// Every allowed pair decided one by one: a pair with a rigid body by the rigid per-query
/// function, any other by the linear one (time = s).
RigidReference brute_force(const Bodies& bodies, const CcdOptions& ccd, bool self_collision) {
  RigidReference r;
  std::vector<Edges> edges;
  for (const Body& b : bodies) edges.push_back(derive_edges(b.triangles));
  const auto n = static_cast<MeshId>(bodies.size());
  const auto record = [&](const ScenePair& p, bool rigid, const CcdResult& c, bool has_time,
                          double time_lo, double time_hi) {
    ++r.pairs;
    const Kind ka = bodies[p.first_mesh].kind, kb = bodies[p.second_mesh].kind;
    if (!rigid)
      ++r.without_rigid;
    else if (ka == Kind::rigid && kb == Kind::rigid)
      ++r.rigid_rigid;
    else if (ka == Kind::fixed || kb == Kind::fixed)
      ++r.rigid_fixed;
    else
      ++r.rigid_deformable;
    if (c.collides)
      r.contacts.push_back({p, c.toi_lo, c.toi_hi, has_time, c.starts_within, time_lo, time_hi});
  };
  for (MeshId a = 0; a < n; ++a)
    for (std::int32_t v = 0; v < bodies[a].start.rows(); ++v)
      for (MeshId b = 0; b < n; ++b) {
        if (!allowed(bodies, a, b, self_collision)) continue;
        const Triangles& t = bodies[b].triangles;
        for (std::int32_t f = 0; f < t.rows(); ++f) {
          if (a == b && (t(f, 0) == v || t(f, 1) == v || t(f, 2) == v)) continue;
          const ScenePair p{QueryType::vertex_face, a, static_cast<std::uint32_t>(v), b,
                            static_cast<std::uint32_t>(f)};
          const std::array<std::int32_t, 1> vs{v};
          const std::array<std::int32_t, 3> ts{t(f, 0), t(f, 1), t(f, 2)};
          const Body &ba = bodies[a], &bb = bodies[b];
          if (ba.kind == Kind::rigid || bb.kind == Kind::rigid) {
            const RigidCcdResult c = vertex_face_ccd(
                RigidVertexFaceQuery{point(ba.start, v), point(bb.start, ts[0]),
                                     point(bb.start, ts[1]), point(bb.start, ts[2]),
                                     side_of(ba, vs), side_of(bb, ts)},
                ccd);
            record(p, true, c.ccd, c.has_time, c.time_lo, c.time_hi);
          } else {
            const CcdResult c = vertex_face_ccd(
                VertexFaceQuery{point(ba.start, v), point(bb.start, ts[0]), point(bb.start, ts[1]),
                                point(bb.start, ts[2]), point(ba.end, v), point(bb.end, ts[0]),
                                point(bb.end, ts[1]), point(bb.end, ts[2])},
                ccd);
            record(p, false, c, true, c.toi_lo, c.toi_hi);
          }
        }
      }
  for (MeshId a = 0; a < n; ++a)
    for (std::int32_t i = 0; i < edges[a].rows(); ++i)
      for (MeshId b = a; b < n; ++b) {
        if (!allowed(bodies, a, b, self_collision)) continue;
        const Edges &ea = edges[a], &eb = edges[b];
        for (std::int32_t j = (a == b ? i + 1 : 0); j < eb.rows(); ++j) {
          if (a == b && (ea(i, 0) == eb(j, 0) || ea(i, 0) == eb(j, 1) || ea(i, 1) == eb(j, 0) ||
                         ea(i, 1) == eb(j, 1)))
            continue;
          const ScenePair p{QueryType::edge_edge, a, static_cast<std::uint32_t>(i), b,
                            static_cast<std::uint32_t>(j)};
          const std::array<std::int32_t, 2> va{ea(i, 0), ea(i, 1)}, vb{eb(j, 0), eb(j, 1)};
          const Body &ba = bodies[a], &bb = bodies[b];
          if (ba.kind == Kind::rigid || bb.kind == Kind::rigid) {
            const RigidCcdResult c = edge_edge_ccd(
                RigidEdgeEdgeQuery{point(ba.start, va[0]), point(ba.start, va[1]),
                                   point(bb.start, vb[0]), point(bb.start, vb[1]), side_of(ba, va),
                                   side_of(bb, vb)},
                ccd);
            record(p, true, c.ccd, c.has_time, c.time_lo, c.time_hi);
          } else {
            const CcdResult c = edge_edge_ccd(
                EdgeEdgeQuery{point(ba.start, va[0]), point(ba.start, va[1]),
                              point(bb.start, vb[0]), point(bb.start, vb[1]), point(ba.end, va[0]),
                              point(ba.end, va[1]), point(bb.end, vb[0]), point(bb.end, vb[1])},
                ccd);
            record(p, false, c, true, c.toi_lo, c.toi_hi);
          }
        }
      }
  return r;
}

std::string describe_full(const SceneContact& c) {
  return describe(c) + (c.has_time ? " time [" + hex(c.time_lo) + ", " + hex(c.time_hi) + "]"
                                   : std::string(" no time"));
}

bool same_full(const SceneContact& a, const SceneContact& b) {
  return same_contact(a, b) && a.has_time == b.has_time &&
         (!a.has_time || (a.time_lo == b.time_lo && a.time_hi == b.time_hi));
}

::testing::AssertionResult same_full_contacts(const std::vector<SceneContact>& got,
                                              const std::vector<SceneContact>& want) {
  const std::size_t n = std::min(got.size(), want.size());
  for (std::size_t k = 0; k < n; ++k)
    if (!same_full(got[k], want[k]))
      return ::testing::AssertionFailure() << "contact " << k << ": got " << describe_full(got[k])
                                           << ", expected " << describe_full(want[k]);
  if (got.size() != want.size())
    return ::testing::AssertionFailure()
           << got.size() << " contacts, expected " << want.size() << "; first extra: "
           << (got.size() > n ? "got " + describe_full(got[n]) : "expected " + describe_full(want[n]));
  return ::testing::AssertionSuccess();
}

/// The smallest toi_lo, ties by pair order; a default contact without any.
SceneContact earliest(const std::vector<SceneContact>& contacts) {
  SceneContact best;
  for (const SceneContact& c : contacts)
    if (c.toi_lo < best.toi_lo) best = c;
  return best;
}

/// find_contacts and earliest_contact against the brute force with these options; the
/// reference, for counting.
RigidReference check(const Bodies& bodies, const SceneOptions& o = {}) {
  const RigidReference ref = brute_force(bodies, o.ccd, o.self_collision);
  Scene scene = make_scene(bodies);
  SceneOptions with_candidates = o;
  with_candidates.record_candidates = true;
  const SceneResult got = scene.find_contacts(with_candidates);
  EXPECT_TRUE(same_full_contacts(got.contacts, ref.contacts));
  EXPECT_TRUE(same_full(got.earliest, earliest(ref.contacts))) << describe_full(got.earliest);
  for (const ScenePair& p : got.candidates)
    EXPECT_FALSE(p.first_mesh == p.second_mesh && bodies[p.first_mesh].kind == Kind::rigid)
        << "a pair within rigid body " << p.first_mesh << ": " << describe(p);
  EXPECT_EQ(got.stats.vertex_face_candidates + got.stats.edge_edge_candidates,
            got.candidates.size());
  const EarliestContact first = scene.earliest_contact(o);
  EXPECT_EQ(first.collides, !ref.contacts.empty());
  EXPECT_TRUE(same_full(first.contact, got.earliest))
      << describe_full(first.contact) << " vs " << describe_full(got.earliest);
  return ref;
}

struct Separated {
  RigidReference ref;  ///< the brute force at delta
  SceneStats stats;    ///< find_contacts' statistics
};

/// find_contacts and earliest_contact of `scene` (made from `bodies`) with minimum separation
/// delta (SceneOptions::min_separation) against the brute force over every allowed pair with the
/// per-query functions at the same delta (CcdOptions::min_separation): the same contacts, TOIs
/// and time fields, so no pair within delta is culled.
Separated check_separated(Scene& scene, const Bodies& bodies, double delta, SceneOptions o = {}) {
  SCOPED_TRACE("min_separation " + hex(delta));
  CcdOptions per_pair = o.ccd;
  per_pair.min_separation = delta;
  Separated out;
  out.ref = brute_force(bodies, per_pair, o.self_collision);
  o.min_separation = delta;
  const SceneResult got = scene.find_contacts(o);
  out.stats = got.stats;
  EXPECT_TRUE(same_full_contacts(got.contacts, out.ref.contacts));
  EXPECT_TRUE(same_full(got.earliest, earliest(out.ref.contacts))) << describe_full(got.earliest);
  const EarliestContact first = scene.earliest_contact(o);
  EXPECT_EQ(first.collides, !out.ref.contacts.empty());
  EXPECT_TRUE(same_full(first.contact, got.earliest))
      << describe_full(first.contact) << " vs " << describe_full(got.earliest);
  return out;
}

bool has_pair(const std::vector<SceneContact>& contacts, const ScenePair& p) {
  return std::any_of(contacts.begin(), contacts.end(),
                     [&](const SceneContact& c) { return c.pair == p; });
}

// ---------------------------------------------------------------------------------------------
// Random bodies and turns

Vector3d random_unit(Rng& rng) {
  Vector3d v;
  do {
    for (int k = 0; k < 3; ++k) v[k] = uniform(rng, -1, 1);
  } while (v.norm() < 0.1 || v.norm() > 1);
  return v.normalized();
}

struct TurnStyle {
  double max_degrees = 90;
  bool pure_rotation = false;
  double translation = 0.5;
};

RigidMotion random_turn(Rng& rng, const Vector3d& near, const TurnStyle& style) {
  const double angle = uniform(rng, -style.max_degrees, style.max_degrees) * M_PI / 180;
  Vector3d pivot = near;
  for (int k = 0; k < 3; ++k) pivot[k] += uniform(rng, -0.2, 0.2);
  Vector3d d = Vector3d::Zero();
  if (!style.pure_rotation)
    for (int k = 0; k < 3; ++k) d[k] = uniform(rng, -style.translation, style.translation);
  return RigidMotion::turn(pivot, random_unit(rng), angle, d);
}

Vector3d centre_of(const Positions& x) { return x.colwise().mean().transpose(); }

/// Two rigid bodies (a box and a soup) turning near each other, a static grid under them and a
/// deformable grid moving through: every kind of pair.
Bodies random_bodies(Rng& rng, const TurnStyle& style) {
  Bodies bodies;
  const Vector3d lo(uniform(rng, -0.3, 0), uniform(rng, -0.3, 0), uniform(rng, -0.1, 0.1));
  MeshSpec box = box_mesh(lo, lo + Vector3d(uniform(rng, 0.3, 0.6), uniform(rng, 0.3, 0.6),
                                            uniform(rng, 0.2, 0.5)));
  bodies.push_back(body_of(Kind::rigid, box));
  bodies.back().motion = random_turn(rng, centre_of(box.start), style);
  MeshSpec blob = soup(rng, uniform_int(rng, 4, 7), uniform_int(rng, 3, 7),
                       Vector3d(uniform(rng, 0.1, 0.5), uniform(rng, 0.1, 0.5), uniform(rng, 0, 0.3)),
                       uniform(rng, 0.15, 0.35));
  bodies.push_back(body_of(Kind::rigid, blob));
  bodies.back().motion = random_turn(rng, centre_of(blob.start), style);
  MeshSpec floor = grid(4, 4, Vector3d(-0.6, -0.6, uniform(rng, -0.2, -0.05)),
                        Vector3d(1.4, 0, 0), Vector3d(0, 1.4, 0));
  for (Eigen::Index r = 0; r < floor.start.rows(); ++r) floor.start(r, 2) += uniform(rng, -0.05, 0.05);
  bodies.push_back(body_of(Kind::fixed, floor));
  MeshSpec sheet = grid(3, 3, Vector3d(uniform(rng, -0.4, 0), uniform(rng, -0.4, 0), 0.6),
                        Vector3d(0.8, 0, 0.1), Vector3d(0, 0.8, -0.1));
  sheet.end = sheet.start;
  const Vector3d fall(uniform(rng, -0.2, 0.2), uniform(rng, -0.2, 0.2), uniform(rng, -1.0, -0.2));
  for (Eigen::Index r = 0; r < sheet.end.rows(); ++r)
    for (int k = 0; k < 3; ++k) sheet.end(r, k) += fall[k] + uniform(rng, -0.05, 0.05);
  bodies.push_back(body_of(Kind::deformable, sheet));
  return bodies;
}

struct Counts {
  std::uint64_t pairs = 0, contacts = 0, rigid_rigid = 0, rigid_deformable = 0, rigid_fixed = 0;
  std::uint64_t with_time = 0;
  void add(const RigidReference& r, const Bodies& bodies) {
    pairs += r.pairs;
    contacts += r.contacts.size();
    for (const SceneContact& c : r.contacts) {
      const Kind a = bodies[c.pair.first_mesh].kind, b = bodies[c.pair.second_mesh].kind;
      if (a == Kind::rigid && b == Kind::rigid) ++rigid_rigid;
      else if (a == Kind::fixed || b == Kind::fixed) rigid_fixed += a == Kind::rigid || b == Kind::rigid;
      else if (a == Kind::rigid || b == Kind::rigid) ++rigid_deformable;
      with_time += (a == Kind::rigid || b == Kind::rigid) && c.has_time;
    }
  }
  void print(const char* what) const {
    std::cout << "[ info     ] " << what << ": " << pairs << " pairs, " << contacts
              << " contacts (rigid-rigid " << rigid_rigid << ", rigid-deformable "
              << rigid_deformable << ", rigid-static " << rigid_fixed << "; rigid with a time "
              << with_time << ")\n";
  }
};

// ---------------------------------------------------------------------------------------------
// 1. The scene against the brute force

void random_scenes_equal_brute_force(std::uint64_t seed_offset, const TurnStyle& style,
                                     const char* name, bool expect_times) {
  Rng rng(test_seed() + seed_offset);
  Counts counts;
  const int scenes = static_cast<int>(at_least(scaled_count(4), 2));
  // Not a vacuous pass: contacts of every kind of pair with a rigid body (several at full
  // scale; at least one in a reduced run, which adds scenes, up to 12, until it has them).
  const std::uint64_t floor = scale_from_environment() >= 1 ? 4 : 1;
  auto reached = [&] {
    return counts.rigid_rigid >= floor && counts.rigid_deformable >= floor &&
           counts.rigid_fixed >= floor && (!expect_times || counts.with_time >= floor);
  };
  for (int s = 0; s < 12 && (s < scenes || !reached()); ++s) {
    SCOPED_TRACE(std::string(name) + " scene " + std::to_string(s));
    const Bodies bodies = random_bodies(rng, style);
    counts.add(check(bodies), bodies);
    if (::testing::Test::HasFailure()) break;
  }
  counts.print(name);
  EXPECT_GE(counts.rigid_rigid, floor);
  EXPECT_GE(counts.rigid_deformable, floor);
  EXPECT_GE(counts.rigid_fixed, floor);
  if (expect_times) EXPECT_GE(counts.with_time, floor);
}

TEST(SceneRigid, TurnsWithTranslationEqualBruteForce) {
  random_scenes_equal_brute_force(0, TurnStyle{90, false, 0.5}, "turns with translation", false);
}

TEST(SceneRigid, PureRotationsEqualBruteForce) {
  // Rigid-static pairs of a pure rotation have a contact time (RigidCcdResult::has_time).
  random_scenes_equal_brute_force(1, TurnStyle{120, true, 0}, "pure rotations", true);
}

TEST(SceneRigid, LargeAnglesEqualBruteForce) {
  random_scenes_equal_brute_force(2, TurnStyle{175, false, 0.2}, "angles up to 175 degrees",
                                  false);
}

TEST(SceneRigid, OptionsPassThrough) {
  // t_max < 1, a TOI width, the exact mode, one thread: each as the per-query function.
  Rng rng(test_seed() + 3);
  std::uint64_t contacts = 0;
  for (int s = 0; s < static_cast<int>(scaled_count(1)); ++s) {
    const Bodies bodies = random_bodies(rng, TurnStyle{100, false, 0.4});
    SceneOptions o;
    o.ccd.t_max = 0.625;
    SCOPED_TRACE("t_max 0.625, scene " + std::to_string(s));
    contacts += check(bodies, o).contacts.size();
    o.ccd.t_max = 1;
    o.ccd.toi_width = 1e-3;
    o.max_threads = 1;
    SCOPED_TRACE("toi_width 1e-3");
    check(bodies, o);
    o.ccd.toi_width = 0;
    o.ccd.mode = Mode::exact;
    SCOPED_TRACE("exact mode");
    contacts += check(bodies, o).contacts.size();
  }
  EXPECT_GT(contacts, 0u);
}

TEST(SceneRigid, ResultsDoNotDependOnThreadCount) {
  Rng rng(test_seed() + 4);
  const Bodies bodies = random_bodies(rng, TurnStyle{150, false, 0.5});
  Scene scene = make_scene(bodies);
  SceneOptions one;
  one.max_threads = 1;
  const SceneResult base = scene.find_contacts(one);
  for (int threads : {2, 3}) {
    SceneOptions o;
    o.max_threads = threads;
    EXPECT_TRUE(same_full_contacts(scene.find_contacts(o).contacts, base.contacts));
    EXPECT_TRUE(same_full(scene.earliest_contact(o).contact, base.earliest));
  }
}

TEST(SceneRigid, SteppingRefitsTheArcBoxes) {
  // One scene, new motions each step: the same as a fresh scene each time (refit, not stale).
  // Every other step a body starts from the pose the previous step ended in (end_positions,
  // through the overload with positions).
  Rng rng(test_seed() + 5);
  Bodies bodies = random_bodies(rng, TurnStyle{60, false, 0.3});
  Scene scene = make_scene(bodies);
  std::uint64_t contacts = 0;
  for (int step = 0; step < 4; ++step) {
    SCOPED_TRACE("step " + std::to_string(step));
    for (MeshId b : {0u, 1u}) {
      bodies[b].motion = random_turn(rng, centre_of(bodies[b].start),
                                     TurnStyle{step % 2 ? 160.0 : 20.0, step % 3 == 0, 0.6});
      if (step % 2) {
        bodies[b].start = scene.end_positions(b);
        scene.set_rigid_motion(b, bodies[b].start, bodies[b].motion);
      } else {
        scene.set_rigid_motion(b, bodies[b].motion);
      }
    }
    const RigidReference ref = brute_force(bodies, CcdOptions{}, true);
    EXPECT_TRUE(same_full_contacts(scene.find_contacts().contacts, ref.contacts));
    EXPECT_TRUE(same_full(scene.earliest_contact().contact, earliest(ref.contacts)));
    contacts += ref.contacts.size();
  }
  EXPECT_GT(contacts, 0u);
}

// ---------------------------------------------------------------------------------------------
// 2. The scene's rules for rigid bodies

TEST(SceneRigid, NoPairWithinOneRigidBody) {
  // Two triangles that cross each other (and touch along a shared edge region): as one
  // deformable mesh with self-collision they are in contact; as one rigid body never.
  MeshSpec m;
  m.start.resize(6, 3);
  m.start << 0, 0, 0, 1, 0, 0, 0, 1, 0,  //
      0.25, 0.25, -0.5, 0.25, 0.25, 0.5, 0.5, 0.1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 3, 4, 5;
  m.end = m.start;
  Bodies deformable{body_of(Kind::deformable, m)};
  EXPECT_FALSE(check(deformable).contacts.empty());  // the crossing is a contact
  Bodies rigid{body_of(Kind::rigid, m)};
  rigid[0].motion = RigidMotion::turn(Vector3d(0.1, 0.2, 0), Vector3d(0, 0, 1), 1.0);
  Scene scene = make_scene(rigid);
  SceneOptions o;
  o.record_candidates = true;
  const SceneResult r = scene.find_contacts(o);
  EXPECT_TRUE(r.contacts.empty());
  EXPECT_TRUE(r.candidates.empty());
  EXPECT_FALSE(scene.earliest_contact().collides);
  // Two copies as two rigid bodies meet (rigid-rigid pairs are tested).
  rigid.push_back(rigid[0]);
  EXPECT_FALSE(check(rigid).contacts.empty());
}

TEST(SceneRigid, ZeroRotationEqualsMovingMeshWithTranslatedEnds) {
  // q = 0: every point of the body moves on the line from x0 to x0 + d. With dyadic positions
  // and translation, x0 + d is exact, and the moving mesh with those end positions gives the
  // same contacts and TOIs (the rigid path with q = 0 is the linear one).
  Rng rng(test_seed() + 6);
  std::uint64_t contacts = 0;
  for (int s = 0; s < static_cast<int>(scaled_count(12)); ++s) {
    SCOPED_TRACE("scene " + std::to_string(s));
    Bodies bodies = random_bodies(rng, TurnStyle{0, false, 0.6});
    Bodies linear = bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      quantize(bodies[i].start, 6);
      quantize(bodies[i].end, 6);
      if (bodies[i].kind == Kind::fixed) bodies[i].end = bodies[i].start;
    }
    for (MeshId b : {0u, 1u}) {
      RigidMotion& m = bodies[b].motion;
      m.cayley.setZero();
      for (int k = 0; k < 3; ++k) m.translation[k] = std::ldexp(std::round(std::ldexp(m.translation[k], 6)), -6);
      m.pivot = Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      linear[i] = bodies[i];
      if (bodies[i].kind == Kind::rigid) {
        linear[i].kind = Kind::deformable;
        linear[i].end = bodies[i].start.rowwise() + bodies[i].motion.translation.transpose();
      }
    }
    // Same pairs: the rigid bodies' self-pairs are left out of the linear scene.
    SceneOptions o;
    o.self_collision = false;
    Scene rigid_scene = make_scene(bodies), linear_scene = make_scene(linear);
    const SceneResult r = rigid_scene.find_contacts(o), l = linear_scene.find_contacts(o);
    EXPECT_TRUE(same_full_contacts(r.contacts, l.contacts));
    EXPECT_TRUE(same_full(rigid_scene.earliest_contact(o).contact, l.earliest));
    contacts += r.contacts.size();
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GE(contacts, scaled_count(20));
}

TEST(SceneRigid, OneBodyAmongManyOneTriangleMeshesEqualsBruteForce) {
  // A turning box among static one-triangle meshes and small falling sheets (once, every pair
  // of meshes had a cylinder-cull slot: memory and time in the square of the mesh count). The
  // mesh pairs now come from a hierarchy over the meshes' boxes; the answers equal the brute
  // force's, contacts with the rigid body among them.
  Rng rng(test_seed() + 41);
  const int side = static_cast<int>(at_least(scaled_count(16), 8));
  Bodies bodies;
  MeshSpec box = box_mesh(Vector3d(0.3, 0.3, 0.05), Vector3d(0.7, 0.6, 0.3));
  bodies.push_back(body_of(Kind::rigid, box));
  bodies.back().motion = {centre_of(box.start), Vector3d(side / 16.0, 0.0, -0.05),
                          Vector3d(0.1, 0.2, 0.6)};
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      MeshSpec t;
      t.start.resize(3, 3);
      const Vector3d c(i / 8.0 + uniform(rng, 0, 0.03), j / 8.0 + uniform(rng, 0, 0.03),
                       uniform(rng, -0.02, 0.02));
      t.start.row(0) = c.transpose();
      t.start.row(1) = (c + Vector3d(0.09, 0.01, uniform(rng, -0.02, 0.02))).transpose();
      t.start.row(2) = (c + Vector3d(0.01, 0.08, uniform(rng, -0.02, 0.02))).transpose();
      t.end = t.start;
      t.triangles.resize(1, 3);
      t.triangles << 0, 1, 2;
      if ((i + j) % 11 == 0) {  // a small sheet falling from above instead
        t.start.col(2).array() += 0.4;
        t.end.col(2).array() += uniform(rng, 0.0, 0.3);
        bodies.push_back(body_of(Kind::deformable, t));
      } else {
        bodies.push_back(body_of(Kind::fixed, t));
      }
    }
  Counts counts;
  counts.add(check(bodies), bodies);
  counts.print("one rigid body among many meshes");
  EXPECT_GT(counts.rigid_fixed, 0u);  // not a vacuous comparison
}

TEST(SceneRigid, PairsWithoutRigidBodiesAreUnchanged) {
  // Adding a rigid body far away changes no answer of the other pairs (and their time is s).
  Rng rng(test_seed() + 7);
  std::uint64_t contacts = 0;
  // At least the scaled count of scenes, and more (up to 20) until one has contacts.
  const int scenes = static_cast<int>(scaled_count(10));
  for (int s = 0; s < 20 && (s < scenes || contacts == 0); ++s) {
    const SceneSpec spec = random_scene(rng);
    Scene plain = make_scene(spec);  // scene_support's: no rigid body
    const SceneResult base = plain.find_contacts();
    Bodies bodies;
    for (const MeshSpec& m : spec) bodies.push_back(body_of(m.is_static ? Kind::fixed : Kind::deformable, m));
    MeshSpec far = box_mesh(Vector3d(50, 50, 50), Vector3d(51, 51, 51));
    bodies.push_back(body_of(Kind::rigid, far));
    bodies.back().motion = RigidMotion::turn(Vector3d(50.5, 50.5, 50.5), Vector3d(1, 2, 3), 2.5);
    Scene with_body = make_scene(bodies);
    const SceneResult r = with_body.find_contacts();
    EXPECT_TRUE(same_full_contacts(r.contacts, base.contacts));
    for (const SceneContact& c : base.contacts) {
      EXPECT_TRUE(c.has_time);
      EXPECT_EQ(c.time_lo, c.toi_lo);
      EXPECT_EQ(c.time_hi, c.toi_hi);
    }
    EXPECT_TRUE(same_full(with_body.earliest_contact().contact, base.earliest));
    contacts += base.contacts.size();
  }
  EXPECT_GT(contacts, 0u);
}

TEST(SceneRigid, EarliestContactSkipsPairsThatCannotLowerTheBound) {
  // A rigid grid turning down through a static grid: many colliding pairs; the earliest search
  // decides far fewer pairs than there are candidates, and still finds the earliest.
  MeshSpec plate = grid(9, 9, Vector3d(-1, -1, 0.05), Vector3d(2, 0, 0), Vector3d(0, 2, 0));
  MeshSpec floor = grid(9, 9, Vector3d(-1.2, -1.2, 0), Vector3d(2.4, 0, 0), Vector3d(0, 2.4, 0));
  Bodies bodies{body_of(Kind::rigid, plate), body_of(Kind::fixed, floor)};
  // Tilt by 0.7 rad about the y axis through the edge x = -1: the far edge (x = 1) sweeps down
  // through the floor early (near s = 0.034), the rest of the plate later.
  bodies[0].motion = RigidMotion::turn(Vector3d(-1, 0, 0.05), Vector3d(0, 1, 0), 0.7);
  const RigidReference ref = check(bodies);
  Scene scene = make_scene(bodies);
  const SceneResult all = scene.find_contacts();
  const EarliestContact first = scene.earliest_contact();
  const std::uint64_t candidates = all.stats.vertex_face_candidates + all.stats.edge_edge_candidates;
  std::cout << "[ info     ] " << ref.contacts.size() << " contacts, " << candidates
            << " candidates, earliest_contact decided " << first.stats.narrow_phase_tests << "\n";
  EXPECT_GT(ref.contacts.size(), 20u);
  EXPECT_LT(first.stats.narrow_phase_tests, candidates / 2);
  EXPECT_TRUE(same_full(first.contact, all.earliest));
}

TEST(SceneRigid, StaticSchemeRunsOnRigidBodies) {
  // The older scheme (boxes at s = 0 and at s = 1) sees a subset of the candidates; every
  // contact it reports is one of the swept scheme's.
  Rng rng(test_seed() + 8);
  for (int s = 0; s < 2; ++s) {
    Scene scene = make_scene(random_bodies(rng, TurnStyle{90, false, 0.5}));
    SceneOptions o;
    const SceneResult swept = scene.find_contacts(o);
    o.broad_phase = BroadPhase::static_bvh;
    const SceneResult instants = scene.find_contacts(o);
    for (const SceneContact& c : instants.contacts) {
      const auto it = std::find_if(swept.contacts.begin(), swept.contacts.end(),
                                   [&](const SceneContact& d) { return d.pair == c.pair; });
      ASSERT_NE(it, swept.contacts.end()) << describe(c);
      EXPECT_TRUE(same_full(*it, c));
    }
  }
}

TEST(SceneRigid, QueriesOfPairs) {
  Rng rng(test_seed() + 9);
  const Bodies bodies = random_bodies(rng, TurnStyle{90, false, 0.5});
  Scene scene = make_scene(bodies);
  const SceneResult r = scene.find_contacts();
  ASSERT_FALSE(r.contacts.empty());
  for (const SceneContact& c : r.contacts) {
    const bool rigid = bodies[c.pair.first_mesh].kind == Kind::rigid ||
                       bodies[c.pair.second_mesh].kind == Kind::rigid;
    if (c.pair.type == QueryType::vertex_face) {
      const RigidCcdResult d = vertex_face_ccd(scene.rigid_vertex_face_query(c.pair));
      EXPECT_EQ(d.ccd.toi_lo, c.toi_lo);
      if (rigid) EXPECT_THROW(scene.vertex_face_query(c.pair), std::invalid_argument);
    } else {
      const RigidCcdResult d = edge_edge_ccd(scene.rigid_edge_edge_query(c.pair));
      EXPECT_EQ(d.ccd.toi_lo, c.toi_lo);
      if (rigid) EXPECT_THROW(scene.edge_edge_query(c.pair), std::invalid_argument);
    }
  }
  EXPECT_TRUE(scene.is_rigid(0));
  EXPECT_FALSE(scene.is_rigid(2));
  EXPECT_FALSE(scene.is_static(0));
  EXPECT_EQ(scene.rigid_motion(1).cayley, bodies[1].motion.cayley);
  // end_positions of a rigid body: position_at(motion, x, 1), for display.
  const Vector3d x0 = point(bodies[0].start, 3);
  EXPECT_EQ(point(scene.end_positions(0), 3), position_at(bodies[0].motion, x0, 1.0));
}

TEST(SceneRigid, BadInputThrows) {
  MeshSpec box = box_mesh(Vector3d(0, 0, 0), Vector3d(1, 1, 1));
  Scene scene;
  const MeshId body = scene.add_rigid_body(box.start, box.triangles);
  const MeshId fixed = scene.add_static_mesh(box.start, box.triangles);
  const MeshId moving = scene.add_mesh(box.start, box.triangles);
  RigidMotion ok = RigidMotion::turn(Vector3d(0.5, 0.5, 0.5), Vector3d(0, 0, 1), 0.3);
  EXPECT_NO_THROW(scene.set_rigid_motion(body, ok));
  EXPECT_THROW(scene.set_rigid_motion(fixed, ok), std::invalid_argument);
  EXPECT_THROW(scene.set_rigid_motion(moving, ok), std::invalid_argument);
  EXPECT_THROW(scene.set_rigid_motion(7, ok), std::invalid_argument);
  EXPECT_THROW(scene.set_motion(body, box.start, box.start), std::invalid_argument);
  EXPECT_THROW(scene.rigid_motion(moving), std::invalid_argument);
  for (Vector3d RigidMotion::*field :
       {&RigidMotion::pivot, &RigidMotion::translation, &RigidMotion::cayley})
    for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
      RigidMotion m = ok;
      (m.*field)[1] = bad;
      EXPECT_THROW(scene.set_rigid_motion(body, m), std::invalid_argument);
    }
  EXPECT_EQ(scene.rigid_motion(body).cayley, ok.cayley);  // a refused motion changes nothing
  // The overload with new start positions.
  Positions moved = box.start.array() + 0.5;
  EXPECT_NO_THROW(scene.set_rigid_motion(body, moved, ok));
  EXPECT_EQ(scene.start_positions(body), moved);
  EXPECT_THROW(scene.set_rigid_motion(body, Positions(box.start.topRows(7)), ok),
               std::invalid_argument);
  Positions non_finite = box.start;
  non_finite(4, 2) = HUGE_VAL;
  EXPECT_THROW(scene.set_rigid_motion(body, non_finite, ok), std::invalid_argument);
  EXPECT_THROW(scene.set_rigid_motion(moving, box.start, ok), std::invalid_argument);
  RigidMotion nan_motion = ok;
  nan_motion.pivot.x() = std::nan("");
  EXPECT_THROW(scene.set_rigid_motion(body, box.start, nan_motion), std::invalid_argument);
  EXPECT_EQ(scene.start_positions(body), moved);  // refused calls change nothing
  Positions bad_positions = box.start;
  bad_positions(2, 1) = std::nan("");
  EXPECT_THROW(scene.add_rigid_body(bad_positions, box.triangles), std::invalid_argument);
  Triangles bad_triangles = box.triangles;
  bad_triangles(0, 0) = 8;
  EXPECT_THROW(scene.add_rigid_body(box.start, bad_triangles), std::invalid_argument);
  // The scene's minimum separation is checked as without a rigid body: finite and >= 0, given
  // once (SceneOptions::min_separation, never ccd.min_separation).
  SceneOptions o;
  for (double bad : {-1e-3, std::nan(""), HUGE_VAL}) {
    o.min_separation = bad;
    EXPECT_THROW(scene.find_contacts(o), std::invalid_argument) << bad;
    EXPECT_THROW(scene.earliest_contact(o), std::invalid_argument) << bad;
  }
  o.min_separation = 0;
  o.ccd.min_separation = 1e-3;
  EXPECT_THROW(scene.find_contacts(o), std::invalid_argument);
  // float_only runs the uncertified rigid test.
  o.ccd.min_separation = 0;
  o.ccd.mode = Mode::float_only;
  EXPECT_NO_THROW(scene.find_contacts(o));
  EXPECT_NO_THROW(scene.earliest_contact(o));
  // Without a rigid body both are allowed as before.
  Scene plain;
  plain.add_mesh(box.start, box.triangles);
  EXPECT_NO_THROW(plain.find_contacts(o));
  o.ccd.mode = Mode::filtered;
  o.min_separation = 1e-3;
  EXPECT_NO_THROW(plain.find_contacts(o));
}

// ---------------------------------------------------------------------------------------------
// 3. The arc boxes (pipeline/scene/rigid_boxes.hpp) hold the exact positions

using Q3 = std::array<mpq_class, 3>;

/// The exact position at rational s, from the matrix form C(v) = ((1 - v.v) I + 2 v v^T +
/// 2 [v]x) / (1 + v.v) (not the polynomial expansion the library uses).
Q3 exact_position(const RigidMotion& m, const Vector3d& x0, const mpq_class& s) {
  Q3 c, d, q, r;
  for (int k = 0; k < 3; ++k) {
    c[k] = m.pivot[k];
    d[k] = m.translation[k];
    q[k] = m.cayley[k];
    r[k] = mpq_class(x0[k]) - c[k];
  }
  const Q3 v{s * q[0], s * q[1], s * q[2]};
  const mpq_class vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const mpq_class vr = v[0] * r[0] + v[1] * r[1] + v[2] * r[2];
  const Q3 vxr{v[1] * r[2] - v[2] * r[1], v[2] * r[0] - v[0] * r[2], v[0] * r[1] - v[1] * r[0]};
  Q3 x;
  for (int k = 0; k < 3; ++k)
    x[k] = c[k] + s * d[k] + ((1 - vv) * r[k] + 2 * v[k] * vr + 2 * vxr[k]) / (1 + vv);
  return x;
}

/// lo <= x <= hi, the ends possibly infinite.
bool inside(double lo, const mpq_class& x, double hi) {
  const bool above = lo == -HUGE_VAL || (lo != HUGE_VAL && mpq_class(lo) <= x);
  const bool below = hi == HUGE_VAL || (hi != -HUGE_VAL && x <= mpq_class(hi));
  return !std::isnan(lo) && !std::isnan(hi) && above && below;
}

scene::Box arc_box(const RigidMotion& m, const Vector3d& x0, double s_lo, double s_hi) {
  const scene::Pieces ends = scene::pieces_for(m, s_lo, s_hi);
  const predicates::RoundingGuard upward;
  scene::Box box = scene::empty_box();
  scene::grow_by_arc(box, scene::arc_point(m, x0), scene::arc_pieces(m.cayley, ends));
  return box;
}

TEST(SceneRigidBoxes, ArcBoxesHoldEveryExactPosition) {
  Rng rng(test_seed() + 10);
  std::uint64_t checked = 0;
  double worst_slack = 0;  // box width over the sampled extent's, less 1, relative to |x0 - c|
  const int motions = static_cast<int>(scaled_count(300));
  for (int i = 0; i < motions; ++i) {
    const double scale = std::array<double, 4>{1.0, 1e-7, 3e5, 1.0}[i % 4];
    const double degrees = std::array<double, 5>{0, 5, 45, 170, 179.9}[i % 5];
    const Vector3d pivot = scale * Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    Vector3d d = Vector3d::Zero();
    if (i % 3 != 0) d = scale * Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const RigidMotion m = degrees == 0 ? RigidMotion{pivot, d, Vector3d::Zero()}
                                       : RigidMotion::turn(pivot, random_unit(rng),
                                                           (i % 2 ? 1 : -1) * degrees * M_PI / 180, d);
    const Vector3d x0 = pivot + scale * Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const double window = i % 7 == 0 ? uniform(rng, 0, 1) : 1.0;
    const scene::Box box = arc_box(m, x0, 0.0, window);
    const scene::Pieces pieces = scene::pieces_for(m, 0.0, window);
    // Rational s: a fine uniform grid over the window and every piece end.
    std::vector<mpq_class> samples;
    const mpq_class w(window);
    for (int k = 0; k <= 256; ++k) samples.push_back(w * k / 256);
    for (int k = 0; k <= pieces.count; ++k) samples.push_back(mpq_class(pieces.ends[k]));
    std::array<mpq_class, 3> lo, hi;
    bool first = true;
    for (const mpq_class& s : samples) {
      const Q3 x = exact_position(m, x0, s);
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(inside(box.lo[k], x[k], box.hi[k]))
            << "motion " << i << " axis " << k << " s " << s.get_d() << ": " << x[k].get_d()
            << " outside [" << box.lo[k] << ", " << box.hi[k] << "]";
        if (first || x[k] < lo[k]) lo[k] = x[k];
        if (first || x[k] > hi[k]) hi[k] = x[k];
      }
      first = false;
      ++checked;
    }
    // Not so loose as to be useless: within 15% of |x0 - c| + |d| of the sampled extent.
    const double size = (x0 - pivot).norm() + d.norm();
    for (int k = 0; k < 3; ++k) {
      const double slack = ((box.hi[k] - box.lo[k]) - mpq_class(hi[k] - lo[k]).get_d()) / size;
      worst_slack = std::max(worst_slack, slack);
    }
  }
  std::cout << "[ info     ] " << checked << " exact positions inside their boxes; widest box "
            << "exceeds the sampled extent by " << worst_slack << " of |x0 - c| + |d|\n";
  EXPECT_LT(worst_slack, 0.15);
}

TEST(SceneRigidBoxes, PiecesCoverTheRange) {
  for (double degrees : {0.0, 1.0, 30.0, 90.0, 170.0, 179.99}) {
    const RigidMotion m =
        degrees == 0 ? RigidMotion{} : RigidMotion::turn(Vector3d::Zero(), Vector3d(1, 1, 0), degrees * M_PI / 180);
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{{0, 1}, {0, 0.3}, {1, 1}, {0, 0}}) {
      const scene::Pieces p = scene::pieces_for(m, lo, hi);
      ASSERT_GE(p.count, 1);
      ASSERT_LE(p.count, scene::Pieces::max_count);
      EXPECT_EQ(p.ends[0], lo);
      EXPECT_EQ(p.ends[p.count], hi);
      for (int k = 0; k < p.count; ++k) EXPECT_LE(p.ends[k], p.ends[k + 1]);
    }
  }
  // Equal turns per piece: 170 degrees in 31 pieces of at most pi / 32, no rotation in one.
  EXPECT_EQ(scene::pieces_for(RigidMotion::turn(Vector3d::Zero(), Vector3d(0, 0, 1), 170 * M_PI / 180), 0, 1).count, 31);
  EXPECT_EQ(scene::pieces_for(RigidMotion{}, 0, 1).count, 1);
}

TEST(SceneRigidBoxes, OverflowWidensInsteadOfShrinking) {
  // |q| = 1e300: |q|^2 overflows; the box must still hold the positions (here: the whole axis
  // where the arithmetic gave up).
  RigidMotion m;
  m.cayley = Vector3d(1e300, 0, 0);
  const Vector3d x0(0, 1, 0);
  const scene::Box box = arc_box(m, x0, 0, 1);
  for (const mpq_class& s : {mpq_class(0), mpq_class(1, 1000), mpq_class(1)}) {
    const Q3 x = exact_position(m, x0, s);
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(inside(box.lo[k], x[k], box.hi[k])) << k;
  }
}


// ---------------------------------------------------------------------------------------------
// 4. Bodies turning about one line: the cylinder cull (proofs/scene.md#cylinder-ranges)

/// An open tube: an n-gon of radius r about the line through c along the unit vector a (e1, e2
/// completing the frame), from height z0 to z1, turned by `phase` radians.
Body tube(Kind kind, const Vector3d& c, const Vector3d& a, const Vector3d& e1, const Vector3d& e2,
          double r, int n, double z0, double z1, double phase) {
  Body b;
  b.kind = kind;
  b.start.resize(2 * n, 3);
  b.triangles.resize(2 * n, 3);
  for (int k = 0; k < n; ++k) {
    const double phi = phase + 2 * M_PI * k / n;
    const Vector3d around = c + r * std::cos(phi) * e1 + r * std::sin(phi) * e2;
    b.start.row(k) = (around + z0 * a).transpose();
    b.start.row(n + k) = (around + z1 * a).transpose();
    const int k1 = (k + 1) % n;
    b.triangles.row(2 * k) << k, k1, n + k;
    b.triangles.row(2 * k + 1) << k1, n + k1, n + k;
  }
  b.end = b.start;
  return b;
}

/// The inradius of the regular n-gon of circumradius r.
double inradius(double r, int n) { return r * std::cos(M_PI / n); }

struct CoaxialCase {
  const char* name;
  bool tilted;          ///< the axis along (1, 2, 2) / 3 (else along z)
  bool outer_rigid;     ///< the outer tube turns the other way (else it is static)
  bool slide;           ///< the inner tube also slides along the axis
  double gap;           ///< inner circumradius = outer inradius - gap (< 0: interference)
  double outer_offset;  ///< the outer tube's pivot moved off the axis (no common line)
  bool stacked = false;  ///< the outer tube instead of the inner's size, above it: met by sliding
};

/// The scene's contacts and earliest contact equal the brute force (with minimum separation
/// delta); returns the stats of find_contacts.
SceneStats coaxial_scene(const CoaxialCase& k, std::uint64_t* contacts, double delta = 0) {
  SCOPED_TRACE(k.name);
  const Vector3d c(0.25, -0.5, 0.125);
  // Directions whose multiples below are exact, so "parallel" is decided exactly.
  const Vector3d dir = k.tilted ? Vector3d(1, 2, 2) : Vector3d(0, 0, 1);
  const Vector3d a = dir.normalized();
  const Vector3d e1 = k.tilted ? Vector3d(2, -2, 1) / 3 : Vector3d(1, 0, 0);
  const Vector3d e2 = a.cross(e1);
  const int n = 12;
  const double r_outer = 1.0;
  Bodies bodies;
  bodies.push_back(tube(Kind::rigid, c, a, e1, e2, inradius(r_outer, n) - k.gap, n, 0.0, 1.0, 0.01));
  if (k.stacked)  // the slide (1/16 of dir) takes the inner tube's top 1/16 into it
    bodies.push_back(tube(k.outer_rigid ? Kind::rigid : Kind::fixed, c, a, e1, e2,
                          inradius(r_outer, n) - k.gap, n, 1.0 + dir.norm() / 32, 2.0, 0.3));
  else
    bodies.push_back(tube(k.outer_rigid ? Kind::rigid : Kind::fixed, c, a, e1, e2, r_outer, n,
                          -0.5, 1.5, 0.0));
  // A Cayley vector dir / 4: 2 atan(0.25) = 28 degrees about z, 2 atan(0.75) = 74 degrees about
  // the tilted axis (|dir| = 3); the outer one turns back by half as much.
  bodies[0].motion = {c, k.slide ? Vector3d(dir / 16) : Vector3d::Zero(), dir / 4};
  if (k.outer_rigid) {
    const Vector3d off = k.outer_offset * e1;
    bodies[1].motion = {c + off, Vector3d::Zero(), -dir / 8};
  }
  Scene scene = make_scene(bodies);
  const RigidReference ref = delta > 0 ? check_separated(scene, bodies, delta).ref : check(bodies);
  *contacts = ref.contacts.size();
  SceneOptions o;
  o.min_separation = delta;
  const SceneResult got = scene.find_contacts(o);
  std::cout << "[ info     ] " << k.name << (delta > 0 ? " within " + hex(delta) : "") << ": "
            << ref.pairs << " pairs, "
            << ref.contacts.size() << " contacts, "
            << got.stats.vertex_face_candidates + got.stats.edge_edge_candidates
            << " candidates, " << got.stats.cylinder_culled << " culled by the cylinder ranges\n";
  return got.stats;
}

TEST(SceneRigid, CoaxialTurnsEqualBruteForceAndAreCulled) {
  const double tight = std::ldexp(1.0, -20);
  const CoaxialCase cases[] = {
      {"z axis, static outer, clearance 2^-20", false, false, false, tight, 0},
      {"z axis, static outer, interference", false, false, false, -0.02, 0},
      {"z axis, static outer, sliding, interference", false, false, true, -0.02, 0},
      {"tilted axis, both turning, clearance 2^-20", true, true, false, tight, 0},
      {"tilted axis, both turning, sliding, interference", true, true, true, -0.02, 0},
      // Met only by sliding along the axis: culling by the heights at rest would miss it.
      {"tilted axis, sliding into a tube above", true, false, true, tight, 0, true},
  };
  for (const CoaxialCase& k : cases) {
    std::uint64_t contacts = 0;
    const SceneStats stats = coaxial_scene(k, &contacts);
    if (k.gap > 0 && !k.stacked) {
      EXPECT_EQ(contacts, 0u) << k.name;
      // Clearance: every pair of a wall with the other wall is apart in distance to the axis.
      EXPECT_GT(stats.cylinder_culled, 0u) << k.name;
    } else {
      EXPECT_GT(contacts, 0u) << k.name;  // not a vacuous comparison
      // e.g. the outer corners vs the inner faces (the stacked tubes: only the widened heights
      // keep their pairs; all the cull could drop the boxes drop)
      if (!k.stacked) EXPECT_GT(stats.cylinder_culled, 0u) << k.name;
    }
  }
}

TEST(SceneRigid, CylinderCullNeedsExactlyOneLine) {
  // The outer tube turns about a line 2^-30 away from the inner's: no common line, no cull,
  // and the answers still equal the brute force.
  std::uint64_t contacts = 0;
  const SceneStats off = coaxial_scene(
      {"z axis, outer pivot 2^-30 off the axis", false, true, false, -0.02, std::ldexp(1.0, -30)},
      &contacts);
  EXPECT_EQ(off.cylinder_culled, 0u);
  EXPECT_GT(contacts, 0u);
  // Scenes without rigid bodies never use it.
  Scene plain;
  plain.add_static_mesh(tube(Kind::fixed, Vector3d::Zero(), Vector3d::UnitZ(), Vector3d::UnitX(),
                             Vector3d::UnitY(), 1, 12, 0, 1, 0).start,
                        tube(Kind::fixed, Vector3d::Zero(), Vector3d::UnitZ(), Vector3d::UnitX(),
                             Vector3d::UnitY(), 1, 12, 0, 1, 0).triangles);
  const Body inner = tube(Kind::deformable, Vector3d::Zero(), Vector3d::UnitZ(), Vector3d::UnitX(),
                          Vector3d::UnitY(), 0.9, 12, 0, 1, 0);
  const MeshId id = plain.add_mesh(inner.start, inner.triangles);
  Positions end = inner.start;
  end.col(2).array() += 0.5;
  plain.set_motion(id, inner.start, end);
  EXPECT_EQ(plain.find_contacts({}).stats.cylinder_culled, 0u);
}

/// Exact |(x - p) x u|^2 and (x - p) . u of a rational point.
std::array<mpq_class, 2> exact_cylinder(const scene::AxisLine& l, const Q3& x) {
  Q3 r, u;
  for (int k = 0; k < 3; ++k) {
    r[k] = x[k] - mpq_class(l.point[k]);
    u[k] = mpq_class(l.direction[k]);
  }
  const Q3 w{r[1] * u[2] - r[2] * u[1], r[2] * u[0] - r[0] * u[2], r[0] * u[1] - r[1] * u[0]};
  return {w[0] * w[0] + w[1] * w[1] + w[2] * w[2], r[0] * u[0] + r[1] * u[1] + r[2] * u[2]};
}

TEST(SceneRigidCylinders, RangesHoldExactPointsAlongMotionsAboutTheLine) {
  // Random segments and triangles (some with an edge along the axis, some crossing it), rational
  // points of them moved along the exact motion at rational s: inside the ranges (h widened by
  // the slide). Also: the common line is found only for the same line.
  Rng rng(test_seed() + 41);
  std::uint64_t checked = 0;
  const int trials = static_cast<int>(scaled_count(300));
  for (int i = 0; i < trials; ++i) {
    const Vector3d dir = std::array<Vector3d, 3>{Vector3d(0, 0, 1), Vector3d(1, 2, 2),
                                                 Vector3d(0, -0.5, 0)}[i % 3];
    // A pivot of few bits: c + 2 dir is then exact, the same line for the exact test.
    const Vector3d c = (64 * Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)))
                           .array().round().matrix() / 64;
    const double t = std::array<double, 3>{0.125, 0.75, 3.0}[i % 3 == 0 ? 0 : (i % 2 ? 1 : 2)];
    const RigidMotion m{c, i % 4 == 0 ? Vector3d(dir * 0.375) : Vector3d::Zero(), dir * t};
    const predicates::RoundingGuard upward;
    const auto line = scene::common_axis(scene::kept_axes(m),
                                         scene::KeptAxes{scene::KeptAxes::any, scene::AxisLine{}});
    ASSERT_TRUE(line.has_value()) << i;
    // The same line seen from another pivot on it and another angle; a shifted one is not.
    EXPECT_TRUE(scene::common_axis(scene::kept_axes(m),
                                   scene::kept_axes({Vector3d(c + 2 * dir), Vector3d::Zero(), -dir}))
                    .has_value());
    EXPECT_FALSE(scene::common_axis(
                     scene::kept_axes(m),
                     scene::kept_axes({Vector3d(c + Vector3d(0.001, 0.002, 0.004)), Vector3d::Zero(), dir}))
                     .has_value());
    std::array<Vector3d, 3> v;
    for (Vector3d& x : v) x = c + Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    if (i % 5 == 1) v[1] = v[0] + 0.5 * dir;      // an edge along the axis
    if (i % 5 == 2) v[2] = c + uniform(rng, -1, 1) * dir;  // a vertex on the axis
    const auto shift = scene::h_shift(*line, m.translation);
    const auto widen = [&](scene::CylinderRange r) {
      r.h_lo = (predicates::Interval(r.h_lo) + shift[0]).inf();
      r.h_hi = (predicates::Interval(r.h_hi) + shift[1]).sup();
      return r;
    };
    const scene::CylinderRange seg = widen(scene::segment_range(*line, v[0], v[1]));
    const scene::CylinderRange tri = widen(scene::triangle_range(*line, v[0], v[1], v[2]));
    for (int j = 0; j < 24; ++j) {
      // A rational point of the triangle (and one of the segment), then moved.
      const mpq_class a(uniform_int(rng, 0, 16), 16), b(uniform_int(rng, 0, 16), 16);
      const mpq_class wa = a, wb = (1 - a) * b, wc = (1 - a) * (1 - b);
      const mpq_class s(uniform_int(rng, 0, 64), 64);
      Q3 on_tri, on_seg;
      for (int k = 0; k < 3; ++k) {
        on_tri[k] = wa * v[0][k] + wb * v[1][k] + wc * v[2][k];
        on_seg[k] = a * v[0][k] + (1 - a) * v[1][k];
      }
      // exact_position moves a double start point: move the rational point by the motion's
      // action on the vertices (an affine map), i.e. the same weights of the moved vertices.
      Q3 moved_tri, moved_seg;
      std::array<Q3, 3> mv;
      for (int q = 0; q < 3; ++q) mv[q] = exact_position(m, v[q], s);
      for (int k = 0; k < 3; ++k) {
        moved_tri[k] = wa * mv[0][k] + wb * mv[1][k] + wc * mv[2][k];
        moved_seg[k] = a * mv[0][k] + (1 - a) * mv[1][k];
      }
      for (const auto& [x, r] : {std::pair<Q3, scene::CylinderRange>{moved_tri, tri},
                                 std::pair<Q3, scene::CylinderRange>{moved_seg, seg}}) {
        const auto e = exact_cylinder(*line, x);
        ASSERT_TRUE(inside(r.rho2_lo, e[0], r.rho2_hi))
            << "trial " << i << ": |w|^2 " << e[0].get_d() << " outside [" << r.rho2_lo << ", "
            << r.rho2_hi << "]";
        ASSERT_TRUE(inside(r.h_lo, e[1], r.h_hi))
            << "trial " << i << ": h " << e[1].get_d() << " outside [" << r.h_lo << ", " << r.h_hi
            << "]";
        ++checked;
      }
    }
  }
  std::cout << "[ info     ] " << checked << " exact points of moving primitives inside their "
            << "cylinder ranges\n";
}

// ---------------------------------------------------------------------------------------------
// 5. Minimum separation with rigid bodies (proofs/scene.md#min-separation, #rigid-bodies)

TEST(SceneRigid, MinSeparationEqualsBruteForce) {
  // Random scenes of every kind of pair with a rigid body, at delta = 1e-3 and at delta = 0.05
  // (a tenth of the bodies' size: many pairs apart at contact come within it). One Scene for
  // every delta and then 0 again: the raised arc boxes are refitted when delta changes.
  Rng rng(test_seed() + 60);
  std::uint64_t contacts = 0, new_rigid = 0;
  for (int s = 0; s < 2; ++s) {
    SCOPED_TRACE("scene " + std::to_string(s));
    const Bodies bodies = random_bodies(rng, TurnStyle{90, false, 0.5});
    Scene scene = make_scene(bodies);
    const RigidReference touching = brute_force(bodies, CcdOptions{}, true);
    for (double delta : {1e-3, 0.05}) {
      const RigidReference ref = check_separated(scene, bodies, delta).ref;
      contacts += ref.contacts.size();
      for (const SceneContact& c : touching.contacts)  // a contact is within every delta
        EXPECT_TRUE(has_pair(ref.contacts, c.pair)) << describe(c);
      for (const SceneContact& c : ref.contacts)
        new_rigid += !has_pair(touching.contacts, c.pair) &&
                     (bodies[c.pair.first_mesh].kind == Kind::rigid ||
                      bodies[c.pair.second_mesh].kind == Kind::rigid);
    }
    EXPECT_TRUE(same_full_contacts(scene.find_contacts().contacts, touching.contacts));
    if (::testing::Test::HasFailure()) break;
  }
  std::cout << "[ info     ] " << contacts << " contacts within delta, " << new_rigid
            << " of them pairs with a rigid body that never touch\n";
  EXPECT_GT(new_rigid, 0u);  // not a vacuous comparison: delta turns pairs into contacts
}

/// A flat triangle of a rigid body turning a quarter about the z axis (its corner (5, 0, 0)
/// passes (3, 4, 0) at s = 1/2) and a static triangle `gap` away from the region it sweeps:
/// above it (z = gap: the arc boxes, exactly flat, and the cylinder heights are `gap` apart) or
/// beside it (in the plane through the axis and (3, 4, 0), from radius 5 + gap: the distances to
/// the axis are `gap` apart). The closest distance is `gap`. With `crossing`, a static triangle
/// the rigid one crosses later (about s = 3/4), listed first so that earliest_contact meets it
/// first on one thread and then decides the others over a shortened window.
Bodies turning_past(double gap, bool above, bool rigid_first, bool crossing = false) {
  Body turning;
  turning.kind = Kind::rigid;
  turning.start.resize(3, 3);
  turning.start << 5, 0, 0, 4, 0, 0, 4.5, 0.5, 0;
  turning.triangles.resize(1, 3);
  turning.triangles << 0, 1, 2;
  turning.end = turning.start;
  turning.motion.cayley = Vector3d(0, 0, 1);
  const auto flat = [](Kind kind, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    Body w;
    w.kind = kind;
    w.start.resize(3, 3);
    w.start << a.transpose(), b.transpose(), c.transpose();
    w.triangles.resize(1, 3);
    w.triangles << 0, 1, 2;
    w.end = w.start;
    return w;
  };
  const Vector3d radial(0.6, 0.8, 0), up(0, 0, 1);
  const Body wall = above ? flat(Kind::fixed, Vector3d(2.5, 3.5, gap), Vector3d(3.5, 3.5, gap),
                                 Vector3d(3, 4.5, gap))
                          : flat(Kind::fixed, (5 + gap) * radial - up, (5 + gap) * radial + up,
                                 7 * radial);
  Bodies bodies;
  if (crossing) {  // the radial plane at s = 3/4: direction (0.28, 0.96, 0)
    const Vector3d late(0.28, 0.96, 0);
    bodies.push_back(flat(Kind::fixed, 3 * late - up, 3 * late + up, 6 * late));
  }
  if (rigid_first) {
    bodies.push_back(turning);
    bodies.push_back(wall);
  } else {
    bodies.push_back(wall);
    bodies.push_back(turning);
  }
  return bodies;
}

TEST(SceneRigid, MinSeparationKeepsPairsTheBoxesAndCylindersSeparate) {
  // Each pair is gap = delta / 2 apart at its closest: without delta its arc boxes and its
  // cylinder heights (above) or its distances to the common axis (beside) are apart, so the
  // broad phase drops it; with delta it must keep it (boxes raised by delta, cylinder ranges
  // widened by delta) and find the contacts the per-query functions find. At gap = 2 delta: no
  // contact, and the broad phase still drops the pairs (above: no candidate; beside: by the
  // cylinder ranges). Both mesh orders (either side of a pair is the widened one).
  const double delta = 1e-3;
  for (bool above : {true, false})
    for (bool rigid_first : {true, false}) {
      SCOPED_TRACE(std::string(above ? "above" : "beside") +
                   (rigid_first ? ", rigid body first" : ", static wall first"));
      Bodies bodies = turning_past(delta / 2, above, rigid_first);
      Scene scene = make_scene(bodies);
      // What the broad phase drops without delta, and at gap = 2 delta with it.
      const auto dropped = [above](const SceneStats& stats) {
        return above ? stats.vertex_face_candidates + stats.edge_edge_candidates == 0
                     : stats.cylinder_culled > 0;
      };
      const Separated none = check_separated(scene, bodies, 0.0);
      EXPECT_TRUE(none.ref.contacts.empty());
      EXPECT_TRUE(dropped(none.stats));
      const Separated within = check_separated(scene, bodies, delta);
      EXPECT_FALSE(within.ref.contacts.empty());
      // The rigid corner against the wall's triangle is one of them.
      const MeshId rigid = rigid_first ? 0 : 1, wall = 1 - rigid;
      EXPECT_TRUE(has_pair(within.ref.contacts, {QueryType::vertex_face, rigid, 0, wall, 0}));
      bodies = turning_past(2 * delta, above, rigid_first);
      Scene apart = make_scene(bodies);
      const Separated far = check_separated(apart, bodies, delta);
      EXPECT_TRUE(far.ref.contacts.empty());
      EXPECT_TRUE(dropped(far.stats));
    }
}

TEST(SceneRigid, MinSeparationEarliestContactWindowKeepsPairsWithinDelta) {
  // On one thread earliest_contact first meets the crossing at about s = 3/4 (listed first) and
  // then decides the triangle above over [0, bound]: their boxes over that window are gap
  // apart, less than delta, so the window cull must keep them; the earliest contact within
  // delta is the one above, near s = 1/2.
  const double delta = 1e-3;
  for (bool rigid_first : {true, false}) {
    SCOPED_TRACE(rigid_first ? "rigid body first" : "static wall first");
    const Bodies bodies = turning_past(delta / 2, true, rigid_first, true);
    Scene scene = make_scene(bodies);
    SceneOptions one;
    one.max_threads = 1;
    const Separated within = check_separated(scene, bodies, delta, one);
    const SceneContact first = earliest(within.ref.contacts);
    EXPECT_LT(first.toi_hi, 0.6) << describe_full(first);
    EXPECT_NE(first.pair.first_mesh, 0u);  // not the crossing wall's
    EXPECT_NE(first.pair.second_mesh, 0u);
    // Without delta only the crossing remains.
    const Separated touching = check_separated(scene, bodies, 0.0, one);
    EXPECT_GT(earliest(touching.ref.contacts).toi_lo, 0.6);
  }
}

TEST(SceneRigid, MinSeparationOptionsPassThrough) {
  // t_max, toi_width, the exact mode and the older scheme with delta > 0: each as the per-query
  // function (the older scheme: every contact it reports is one of the swept scheme's).
  const double delta = 1e-3;
  const Bodies bodies = turning_past(delta / 2, true, true, true);
  Scene scene = make_scene(bodies);
  SceneOptions o;
  o.ccd.t_max = 0.625;
  EXPECT_FALSE(check_separated(scene, bodies, delta, o).ref.contacts.empty());
  o.ccd.t_max = 1;
  o.ccd.toi_width = 1e-3;
  check_separated(scene, bodies, delta, o);
  o.ccd.toi_width = 0;
  o.ccd.mode = Mode::exact;
  check_separated(scene, bodies, delta, o);
  o.ccd.mode = Mode::filtered;
  o.min_separation = delta;
  const SceneResult swept = scene.find_contacts(o);
  o.broad_phase = BroadPhase::static_bvh;
  for (const SceneContact& c : scene.find_contacts(o).contacts) {
    ASSERT_TRUE(has_pair(swept.contacts, c.pair)) << describe(c);
  }
}

TEST(SceneRigid, MinSeparationCoaxialTurnsEqualBruteForce) {
  // The coaxial walls 2^-20 apart: within delta = 2^-18 they are contacts (the cylinder ranges,
  // widened by delta, must keep them); within 2^-22 they are not, and the widened ranges still
  // cull. (The tilted axis within 2^-18, many near-tangent rigid pairs, takes seconds: the
  // z axis stands for it.)
  const double tight = std::ldexp(1.0, -20);
  const CoaxialCase z_axis{"z axis, static outer, clearance 2^-20", false, false, false, tight, 0};
  const CoaxialCase tilted{"tilted axis, both turning, clearance 2^-20", true, true, false, tight, 0};
  for (const CoaxialCase& k : {z_axis, tilted}) {
    std::uint64_t contacts = 0;
    const SceneStats near = coaxial_scene(k, &contacts, std::ldexp(1.0, -22));
    EXPECT_EQ(contacts, 0u) << k.name;
    EXPECT_GT(near.cylinder_culled, 0u) << k.name;
  }
  std::uint64_t contacts = 0;
  coaxial_scene(z_axis, &contacts, std::ldexp(1.0, -18));
  EXPECT_GT(contacts, 0u);
}

TEST(SceneRigidCylinders, WidenedRangesHoldPointsWithinDelta) {
  // Rational points within delta of random points, segments and triangles (each offset
  // coordinate at most delta / 2, so the offset is at most delta sqrt(3) / 2): inside the ranges
  // widened by delta (scene::widened), which are not much wider than that.
  Rng rng(test_seed() + 61);
  std::uint64_t checked = 0;
  const int trials = static_cast<int>(scaled_count(200));
  for (int i = 0; i < trials; ++i) {
    const Vector3d dir = std::array<Vector3d, 3>{Vector3d(0, 0, 1), Vector3d(1, 2, 2),
                                                 Vector3d(0, -0.5, 0)}[i % 3];
    const double delta = std::array<double, 3>{1e-3, 0.25, std::ldexp(1.0, -30)}[(i / 3) % 3];
    const Vector3d c(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    std::array<Vector3d, 3> v;
    for (Vector3d& x : v) x = c + Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    if (i % 5 == 1) v[2] = c + uniform(rng, -1, 1) * dir;  // a vertex on the axis
    const scene::AxisLine line{c, dir};
    scene::MeshCylinderRanges r, w;
    {
      const predicates::RoundingGuard upward;
      r.line = line;
      r.vertices = {scene::point_range(line, v[0])};
      r.edges = {scene::segment_range(line, v[0], v[1])};
      r.faces = {scene::triangle_range(line, v[0], v[1], v[2])};
      w = scene::widened(r, delta);
    }
    // Not so loose as to be useless: every end moves by about |u| delta.
    const double reach = 1.01 * dir.norm() * delta + 1e-12;
    const auto near_tight = [&](const scene::CylinderRange& tight, const scene::CylinderRange& wide) {
      EXPECT_LE(wide.h_hi - tight.h_hi, reach) << i;
      EXPECT_LE(tight.h_lo - wide.h_lo, reach) << i;
      EXPECT_LE(std::sqrt(wide.rho2_hi) - std::sqrt(tight.rho2_hi), reach) << i;
      EXPECT_LE(std::sqrt(tight.rho2_lo) - std::sqrt(wide.rho2_lo), reach) << i;
    };
    near_tight(r.vertices[0], w.vertices[0]);
    near_tight(r.edges[0], w.edges[0]);
    near_tight(r.faces[0], w.faces[0]);
    for (int j = 0; j < 24; ++j) {
      const mpq_class a(uniform_int(rng, 0, 16), 16), b(uniform_int(rng, 0, 16), 16);
      const mpq_class wa = a, wb = (1 - a) * b, wc = (1 - a) * (1 - b);
      Q3 offset;
      for (int k = 0; k < 3; ++k) offset[k] = mpq_class(delta) * uniform_int(rng, -16, 16) / 32;
      Q3 on_point, on_seg, on_tri;
      for (int k = 0; k < 3; ++k) {
        on_point[k] = mpq_class(v[0][k]) + offset[k];
        on_seg[k] = a * v[0][k] + (1 - a) * v[1][k] + offset[k];
        on_tri[k] = wa * v[0][k] + wb * v[1][k] + wc * v[2][k] + offset[k];
      }
      for (const auto& [x, range] : {std::pair<Q3, scene::CylinderRange>{on_point, w.vertices[0]},
                                     std::pair<Q3, scene::CylinderRange>{on_seg, w.edges[0]},
                                     std::pair<Q3, scene::CylinderRange>{on_tri, w.faces[0]}}) {
        const auto e = exact_cylinder(line, x);
        ASSERT_TRUE(inside(range.rho2_lo, e[0], range.rho2_hi))
            << "trial " << i << ": |w|^2 " << e[0].get_d() << " outside [" << range.rho2_lo
            << ", " << range.rho2_hi << "]";
        ASSERT_TRUE(inside(range.h_lo, e[1], range.h_hi))
            << "trial " << i << ": h " << e[1].get_d() << " outside [" << range.h_lo << ", "
            << range.h_hi << "]";
        ++checked;
      }
    }
  }
  std::cout << "[ info     ] " << checked << " exact points within delta of primitives inside "
            << "their widened cylinder ranges\n";
}

}  // namespace
}  // namespace exactccd::test
