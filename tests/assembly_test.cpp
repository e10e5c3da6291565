// The assembly demonstration (lock_and_key.hpp, rigid_broad_phase.hpp, assembly_step.hpp):
//  * the meshes are closed, the plate's triangulation covers exactly the ring between its
//    outlines, and the clearances are the designed ones;
//  * arc boxes hold exact positions of the rigid motion at rational parameters (positions from
//    the matrix form of the Cayley rotation, over the rationals), and are not vacuous;
//  * the arc-box broad phase keeps every pair that meets (random soups, motions about an axis,
//    all pairs decided); at a coarse resolution (8 segments), the plan's last insertion steps
//    and every turn decided through exactccd::Scene (arc boxes and cylinder ranges) equal every pair decided without it (brute force),
//    and the first contact is confirmed: the coplanarity of its four points changes sign across
//    the enclosure, the primitives are apart (exactly, CGAL) just before it and interpenetrate
//    just after it.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/gmpxx.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <random>
#include <set>

#include "corpus/assembly/assembly_step.hpp"
#include "corpus/assembly/lock_and_key.hpp"
#include "corpus/assembly/rigid_broad_phase.hpp"
#include "pipeline/scene/rigid_cylinder_ranges.hpp"
#include "corpus/rigid_exact_pose.hpp"

namespace {

using namespace exactccd;
using namespace exactccd::assembly;
using Eigen::Vector3d;
using Q3 = rigid_pose::RationalPosition;
constexpr double kPi = 3.14159265358979323846;

Q3 q3(const Vector3d& v) { return rigid_pose::exactly(v); }

/// x(s) = c + s d + C(s q) (x0 - c) over the rationals, C from its matrix form.
Q3 exact_position(const RigidMotion& m, const Vector3d& x0, const mpq_class& s) {
  return rigid_pose::exact_position(m, x0, s);
}

Vector3d row(const Positions& x, int i) { return x.row(i).transpose(); }

// ---------------------------------------------------------------------------------------------
// Meshes

/// Every directed edge has exactly one reversed partner: closed, consistently oriented.
void expect_closed(const Triangles& f, const char* what) {
  std::multiset<std::pair<int, int>> directed;
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) directed.insert({f(i, k), f(i, (k + 1) % 3)});
  std::size_t bad = 0;
  for (const auto& [a, b] : directed)
    if (directed.count({a, b}) != 1 || directed.count({b, a}) != 1) ++bad;
  EXPECT_EQ(bad, 0u) << what;
}

TEST(AssemblyMeshes, ClosedPartsAndThePlateCoversItsRing) {
  for (int segments : {16, 64, 1280}) {
    LockDesign design;
    design.segments = segments;
    const PartMesh key = make_key(design), lock = make_lock(design);
    EXPECT_EQ(key.mesh.triangles.rows(), 8 * segments + 12);
    expect_closed(key.mesh.triangles, "key");
    expect_closed(lock.mesh.triangles, "lock");
    // The plate's top (z = plate_top): counterclockwise triangles whose areas add up to the
    // outer polygon's minus the keyhole's.
    const Dimensions d = dimensions(design);
    const Part* plate = nullptr;
    for (const Part& p : lock.parts)
      if (p.name == "plate") plate = &p;
    ASSERT_NE(plate, nullptr);
    long double area = 0;
    int top = 0;
    for (int f = plate->triangle_begin; f < plate->triangle_end; ++f) {
      const Vector3d a = row(lock.mesh.positions, lock.mesh.triangles(f, 0)),
                     b = row(lock.mesh.positions, lock.mesh.triangles(f, 1)),
                     c = row(lock.mesh.positions, lock.mesh.triangles(f, 2));
      if (a.z() != d.plate_top || b.z() != d.plate_top || c.z() != d.plate_top) continue;
      const long double twice = (static_cast<long double>(b.x()) - a.x()) * (c.y() - a.y()) -
                                (static_cast<long double>(b.y()) - a.y()) * (c.x() - a.x());
      EXPECT_GT(twice, 0) << "plate triangle " << f << " at " << segments << " segments";
      area += twice / 2;
      ++top;
    }
    // Polygon areas by the shoelace formula over the plate's top vertices in outline order: the
    // keyhole's first, then the outer ring's (see make_lock).
    std::vector<Vector3d> outline;
    for (int v = plate->vertex_begin; v < plate->vertex_end; ++v)
      if (lock.mesh.positions(v, 2) == d.plate_top) outline.push_back(row(lock.mesh.positions, v));
    const std::size_t outer_n = static_cast<std::size_t>(segments),
                      hole_n = outline.size() - outer_n;
    const auto shoelace = [&](std::size_t first, std::size_t n) {
      long double s = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const Vector3d& p = outline[first + k];
        const Vector3d& q = outline[first + (k + 1) % n];
        s += static_cast<long double>(p.x()) * q.y() - static_cast<long double>(q.x()) * p.y();
      }
      return s / 2;
    };
    const long double expected = shoelace(hole_n, outer_n) - shoelace(0, hole_n);
    EXPECT_NEAR(static_cast<double>(area), static_cast<double>(expected), 1e-12);
    EXPECT_EQ(static_cast<std::size_t>(top), outer_n + hole_n);  // a ring: as many as vertices
  }
}

TEST(AssemblyMeshes, TheTightFitsHaveTheDesignedClearance) {
  for (int segments : {16, 1280}) {
    LockDesign design;
    design.segments = segments;
    const PartMesh key = make_key(design), lock = make_lock(design);
    const Dimensions d = dimensions(design);
    // The Scene's cylinder ranges about the z axis (proofs/scene.md#cylinder-ranges).
    const scene::AxisLine z{Vector3d::Zero(), Vector3d::UnitZ()};
    const auto range_of = [&](const PartMesh& pm, const std::string& part, bool lower) {
      const predicates::RoundingGuard upward;
      double best = lower ? INFINITY : 0;
      for (const Part& p : pm.parts) {
        if (p.name != part) continue;
        for (int f = p.triangle_begin; f < p.triangle_end; ++f) {
          const auto t = pm.mesh.triangles.row(f);
          const scene::CylinderRange r = scene::triangle_range(z, row(pm.mesh.positions, t[0]),
                                                 row(pm.mesh.positions, t[1]),
                                                 row(pm.mesh.positions, t[2]));
          best = lower ? std::min(best, r.rho2_lo) : std::max(best, r.rho2_hi);
        }
      }
      return std::sqrt(best);
    };
    // Radial gaps between the circumscribed circle inside and the inscribed one outside.
    const double pin_barrel =
        range_of(key, "barrel inner wall", true) - range_of(lock, "pin", false);
    const double bit_chamber =
        range_of(lock, "chamber inner wall", true) - range_of(key, "bit", false);
    for (double gap : {pin_barrel, bit_chamber}) {
      EXPECT_GT(gap, 0.99 * d.clearance) << segments;
      EXPECT_LT(gap, 1.01 * d.clearance) << segments;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Arc boxes and cylinder ranges

TEST(AssemblyBroadPhase, ArcBoxHoldsExactPositionsAndIsTight) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto point = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const double angle = (i % 4 == 0 ? 179.0 : (i % 4 == 1 ? 30.0 : 1e-3)) * u(rng) * kPi / 180;
    const Vector3d axis = i % 3 == 0 ? Vector3d::UnitZ() : point();
    if (axis.norm() < 1e-3 || angle == 0) continue;
    const Vector3d translation = i % 2 ? point() : Vector3d::Zero();
    const RigidMotion m = RigidMotion::turn(point(), axis, angle, translation);
    const Vector3d x0 = 2 * point();
    const Box3 box = arc_box(m, x0);
    for (int k = 0; k <= 16; ++k) {
      const mpq_class s(k, 16);
      const Q3 x = exact_position(m, x0, s);
      for (int a = 0; a < 3; ++a) {
        ASSERT_LE(mpq_class(box.lo[a]), x[a]) << "motion " << i << " s " << s << " axis " << a;
        ASSERT_GE(mpq_class(box.hi[a]), x[a]) << "motion " << i << " s " << s << " axis " << a;
      }
      ++checked;
    }
    // Not vacuous: for a pure rotation the box spans at most the chord plus twice the sagitta
    // bound, far less than the circle for small angles.
    if (translation.isZero()) {
      const double radius = (x0 - m.pivot).norm(), q2 = m.cayley.squaredNorm();
      const Vector3d end = position_at(m, x0, 1.0);
      for (int a = 0; a < 3; ++a)
        EXPECT_LE(box.hi[a] - box.lo[a],
                  std::abs(end[a] - x0[a]) + radius * q2 + 1e-12 * (1 + radius))
            << "motion " << i;
    }
  }
  EXPECT_GT(checked, 5000);
  // A pure translation's box is exactly its segment's.
  RigidMotion slide;
  slide.translation = Vector3d(0.5, -0.25, 0);
  const Box3 b = arc_box(slide, Vector3d(1, 1, 1));
  EXPECT_EQ(b.lo[0], 1);
  EXPECT_EQ(b.hi[0], 1.5);
  EXPECT_EQ(b.lo[1], 0.75);
  EXPECT_EQ(b.hi[2], 1);
}

/// Random triangles in [-1, 1]^3, as a soup.
scenes::Mesh random_soup(std::mt19937_64& rng, int triangles) {
  std::uniform_real_distribution<double> u(-1, 1);
  scenes::Mesh m;
  m.positions.resize(3 * triangles, 3);
  m.triangles.resize(triangles, 3);
  for (int f = 0; f < triangles; ++f)
    for (int k = 0; k < 3; ++k) {
      m.positions.row(3 * f + k) << u(rng), u(rng), u(rng);
      m.triangles(f, k) = 3 * f + k;
    }
  return m;
}

std::set<PairKey> keys_of(const Candidates& c) {
  std::set<PairKey> s;
  for (const auto& [k, l] : c.moving_vertex_static_face)
    s.insert({PairKind::key_vertex_lock_face, k, l});
  for (const auto& [k, l] : c.static_vertex_moving_face)
    s.insert({PairKind::lock_vertex_key_face, k, l});
  for (const auto& [k, l] : c.edge_edge) s.insert({PairKind::edge_edge, k, l});
  return s;
}

Candidates all_pairs(const Positions& moving, const Triangles& moving_f, const Edges& me,
                     const Positions& fixed, const Triangles& fixed_f, const Edges& fe);

TEST(AssemblyBroadPhase, KeepsEveryPairThatMeets) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t contacts = 0, culled = 0;
  for (int scene = 0; scene < 24; ++scene) {
    const scenes::Mesh fixed = random_soup(rng, 8), moving = random_soup(rng, 4);
    // Turns about lines parallel to x, y and z, some with a slide along them.
    const int index = scene % 3;
    const double au = 0.5 * u(rng), av = 0.5 * u(rng);
    Vector3d pivot = Vector3d(u(rng), u(rng), u(rng)), along = Vector3d::Zero(),
             slide = Vector3d::Zero();
    pivot[index == 0 ? 1 : 0] = au;
    pivot[index == 2 ? 1 : 2] = av;
    along[index] = 1;
    slide[index] = scene % 2 ? u(rng) : 0.0;
    const RigidMotion motion = scene % 4 == 3 ? RigidMotion{pivot, slide, Vector3d::Zero()}
                                              : RigidMotion::turn(pivot, along, 3 * u(rng), slide);
    RigidBroadPhase bp(fixed.positions, fixed.triangles, moving.triangles);
    const Candidates c = bp.rigid_step(moving.positions, motion);
    const Edges me = unique_edges(moving.triangles), fe = unique_edges(fixed.triangles);
    const StepMeshes m{&moving.triangles, &me, &fixed.positions, &fixed.triangles, &fe};
    const Candidates every =
        all_pairs(moving.positions, moving.triangles, me, fixed.positions, fixed.triangles, fe);
    const StepDecision all = decide_rigid(m, moving.positions, motion, every);
    const std::set<PairKey> kept = keys_of(c);
    for (const PairContact& p : all.contacts)
      EXPECT_TRUE(kept.count(p.pair)) << "scene " << scene << ": a meeting pair was dropped ("
                                      << to_string(p.pair.kind) << ")";
    contacts += all.contacts.size();
    culled += every.size() - c.size();
  }
  EXPECT_GT(contacts, 200u);  // enough pairs meet for the check to mean something
  EXPECT_GT(culled, 4000u);   // and the arc boxes do drop pairs (4,578 of them)
}

// ---------------------------------------------------------------------------------------------
// The plan at a coarse resolution

Candidates all_pairs(const Positions& moving, const Triangles& moving_f, const Edges& me,
                     const Positions& fixed, const Triangles& fixed_f, const Edges& fe) {
  Candidates c;
  for (int v = 0; v < moving.rows(); ++v)
    for (int f = 0; f < fixed_f.rows(); ++f) c.moving_vertex_static_face.push_back({v, f});
  for (int f = 0; f < moving_f.rows(); ++f)
    for (int v = 0; v < fixed.rows(); ++v) c.static_vertex_moving_face.push_back({f, v});
  for (int a = 0; a < me.rows(); ++a)
    for (int b = 0; b < fe.rows(); ++b) c.edge_edge.push_back({a, b});
  return c;
}

using CgalPoint = CGAL::Simple_cartesian<mpq_class>::Point_3;
CgalPoint cgal(const Q3& p) { return CgalPoint(p[0], p[1], p[2]); }

/// The four points of a pair at parameter s, exactly: vertex-face (p, a, b, c) or edge-edge.
std::array<Q3, 4> exact_points(const StepMeshes& m, const Positions& start,
                               const RigidMotion& motion, const PairKey& p, const mpq_class& s) {
  const RigidMotion rest;
  if (p.kind == PairKind::edge_edge) {
    const RigidEdgeEdgeQuery q = rigid_edge_edge(m, start, motion, p);
    return {exact_position(motion, q.ea0, s), exact_position(motion, q.ea1, s),
            exact_position(rest, q.eb0, s), exact_position(rest, q.eb1, s)};
  }
  const RigidVertexFaceQuery q = rigid_vertex_face(m, start, motion, p);
  const RigidMotion& vm = p.kind == PairKind::key_vertex_lock_face ? motion : rest;
  const RigidMotion& fm = p.kind == PairKind::key_vertex_lock_face ? rest : motion;
  return {exact_position(vm, q.p, s), exact_position(fm, q.a, s), exact_position(fm, q.b, s),
          exact_position(fm, q.c, s)};
}

int coplanarity_sign(const std::array<Q3, 4>& x) {
  return static_cast<int>(CGAL::orientation(cgal(x[0]), cgal(x[1]), cgal(x[2]), cgal(x[3])));
}

bool touching(const PairKey& p, const std::array<Q3, 4>& x) {
  if (p.kind == PairKind::edge_edge)
    return CGAL::do_intersect(CGAL::Simple_cartesian<mpq_class>::Segment_3(cgal(x[0]), cgal(x[1])),
                              CGAL::Simple_cartesian<mpq_class>::Segment_3(cgal(x[2]), cgal(x[3])));
  return CGAL::do_intersect(cgal(x[0]), CGAL::Simple_cartesian<mpq_class>::Triangle_3(
                                            cgal(x[1]), cgal(x[2]), cgal(x[3])));
}

/// The vertex's projection along the face's normal lies strictly inside the face (x: the
/// vertex, then the face's corners): the vertex is on the same side of the three walls through
/// the face's edges along its normal.
bool projects_inside_face(const std::array<Q3, 4>& x) {
  const Q3 &a = x[1], &b = x[2], &c = x[3];
  const Q3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const Q3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const auto side = [&](int i, int j) {
    const Q3 lifted{x[i][0] + n[0], x[i][1] + n[1], x[i][2] + n[2]};
    return static_cast<int>(
        CGAL::orientation(cgal(x[i]), cgal(x[j]), cgal(lifted), cgal(x[0])));
  };
  const int s1 = side(1, 2), s2 = side(2, 3), s3 = side(3, 1);
  return s1 != 0 && s1 == s2 && s2 == s3;
}

TEST(AssemblyDemo, CoarsePlanEqualsBruteForceAndConfirmsItsFirstContact) {
  LockDesign design;
  design.segments = 8;
  const PartMesh key = make_key(design), lock = make_lock(design);
  const Edges ke = unique_edges(key.mesh.triangles), le = unique_edges(lock.mesh.triangles);
  const StepMeshes m{&key.mesh.triangles, &ke, &lock.mesh.positions, &lock.mesh.triangles, &le};
  const Candidates every = all_pairs(key.mesh.positions, key.mesh.triangles, ke,
                                     lock.mesh.positions, lock.mesh.triangles, le);
  // The demonstration's path: the lock a static mesh, the key a rigid body of one Scene.
  Scene scene;
  const MeshId lock_id = scene.add_static_mesh(lock.mesh.positions, lock.mesh.triangles);
  const MeshId key_id = scene.add_rigid_body(key.mesh.positions, key.mesh.triangles);
  ASSERT_TRUE(scene.edges(key_id).rows() == ke.rows() && scene.edges(key_id) == ke);
  ASSERT_TRUE(scene.edges(lock_id).rows() == le.rows() && scene.edges(lock_id) == le);
  Plan plan;
  plan.turn_to_degrees = 120;
  int contact_steps = 0;
  std::size_t culled_by_cylinders = 0;
  for (const PlanStep& step : plan_steps(design, plan)) {
    // Brute force on the last insertion steps (the barrel over the pin) and every turn.
    if (step.phase == "insert" && step.index < 6) continue;
    const Positions start = key_positions_at_start(key, design, step);
    scene.set_rigid_motion(key_id, start, step.motion);
    const SceneResult result = scene.find_contacts({});
    culled_by_cylinders += result.stats.cylinder_culled;
    const StepDecision fast = from_scene(result, key_id, lock_id);
    const StepDecision brute = decide_rigid(m, start, step.motion, every);
    const std::string at = step.phase + " " + std::to_string(step.index);
    ASSERT_EQ(fast.contacts.size(), brute.contacts.size()) << at;
    for (std::size_t i = 0; i < fast.contacts.size(); ++i) {
      EXPECT_TRUE(fast.contacts[i].pair == brute.contacts[i].pair) << at;
      EXPECT_EQ(fast.contacts[i].toi_lo, brute.contacts[i].toi_lo) << at;
      EXPECT_EQ(fast.contacts[i].toi_hi, brute.contacts[i].toi_hi) << at;
      EXPECT_EQ(fast.contacts[i].has_time, brute.contacts[i].has_time) << at;
      EXPECT_EQ(fast.contacts[i].time_lo, brute.contacts[i].time_lo) << at;
      EXPECT_EQ(fast.contacts[i].time_hi, brute.contacts[i].time_hi) << at;
    }
    ASSERT_EQ(fast.collides, brute.collides) << at;
    if (fast.collides) EXPECT_TRUE(fast.earliest.pair == brute.earliest.pair) << at;
    if (!fast.collides) continue;
    ++contact_steps;
    // Only the step that reaches the stop (90 to 105 degrees) makes contact.
    EXPECT_EQ(step.phase, "turn");
    EXPECT_LT(step.angle_from, design.stop_degrees);
    EXPECT_GT(step.angle_to, design.stop_degrees);
    const PairContact& e = fast.earliest;
    ASSERT_TRUE(e.has_time);
    EXPECT_LE(e.time_lo, e.time_hi);
    EXPECT_EQ(key.part_of_triangle(e.pair.key), "bit");
    EXPECT_EQ(lock.part_of_vertex(e.pair.lock), "stop rib");
    ASSERT_EQ(e.pair.kind, PairKind::lock_vertex_key_face);
    // The four points are coplanar at an s in [toi_lo, toi_hi]: the sign changes (or vanishes)
    // across it; apart just before, the rib's corner through the bit's face just after.
    const mpq_class lo(e.toi_lo), hi(e.toi_hi), eps(1, 1 << 30);
    const int before_sign = coplanarity_sign(exact_points(m, start, step.motion, e.pair, lo));
    const int after_sign = coplanarity_sign(exact_points(m, start, step.motion, e.pair, hi));
    EXPECT_LE(before_sign * after_sign, 0);
    EXPECT_NE(before_sign, 0);
    const auto just_before = exact_points(m, start, step.motion, e.pair, lo - eps);
    const auto just_after = exact_points(m, start, step.motion, e.pair, hi + eps);
    EXPECT_FALSE(touching(e.pair, just_before));
    EXPECT_EQ(coplanarity_sign(just_before), before_sign);
    EXPECT_EQ(coplanarity_sign(just_after), -before_sign);
    EXPECT_TRUE(projects_inside_face(just_after));
  }
  EXPECT_EQ(contact_steps, 1);
  EXPECT_GT(culled_by_cylinders, 1000u);  // the cylinder ranges did cull
}

}  // namespace
