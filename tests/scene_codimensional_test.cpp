// Codimensional, 2D and plane scenes (Scene::add_edge_mesh, add_points, add_plane,
// SceneDimension::two) against a brute-force reference written from scene.hpp's rules only:
// every pair of primitives the rules allow is decided one by one by the public per-pair
// functions (vertex_face_ccd, edge_edge_ccd, point_edge_ccd, point_point_ccd, point_plane_ccd,
// the 2D forms in a 2D scene), and the scene must return exactly the colliding ones with the
// same TOIs, in find_contacts (streamed and listed), earliest_contact and on 1 or 2 threads, with
// and without a minimum separation and self-collision. Plus the errors of bad input, the queries
// and contact geometry of the new pair kinds, and rigid bodies against points (their point-edge
// pairs against Mode::exact).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/scene.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

enum class Kind { triangles, edges, points, plane };

/// A mesh of a test scene as the reference sees it.
struct Spec {
  Kind kind = Kind::triangles;
  bool is_static = false;
  Positions start, end;
  Triangles triangles;
  Edges edges;  // edge meshes: as given; triangle meshes: filled from Scene::edges
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
};

std::string name(const ScenePair& p) {
  return std::string(to_string(p.type)) + "(" + std::to_string(p.first_mesh) + ":" +
         std::to_string(p.first_index) + ", " + std::to_string(p.second_mesh) + ":" +
         std::to_string(p.second_index) + ")";
}

Eigen::Vector3d at(const Positions& x, std::int64_t i) { return x.row(i).transpose(); }

bool on_edge(const Edges& e, Eigen::Index row, std::int64_t v) {
  return e(row, 0) == v || e(row, 1) == v;
}

/// The vertices of an edge mesh or point set that lie on none of its edges.
std::vector<char> points_of(const Spec& m) {
  std::vector<char> point(static_cast<std::size_t>(m.start.rows()),
                          m.kind == Kind::edges || m.kind == Kind::points);
  for (Eigen::Index e = 0; e < m.edges.rows(); ++e) point[m.edges(e, 0)] = point[m.edges(e, 1)] = 0;
  return point;
}

Eigen::Vector2d xy(const Eigen::Vector3d& v) { return v.head<2>(); }

/// Every colliding pair by the rules of scene.hpp, decided by the per-pair functions.
std::vector<SceneContact> reference(const std::vector<Spec>& meshes, bool planar, double delta,
                                    bool self) {
  CcdOptions o;
  o.min_separation = delta;
  std::vector<SceneContact> out;
  const auto keep = [&](QueryType type, MeshId a, std::int64_t i, MeshId b, std::int64_t j,
                        const CcdResult& r) {
    if (r.collides)
      out.push_back({{type, a, static_cast<std::uint32_t>(i), b, static_cast<std::uint32_t>(j)},
                     r.toi_lo, r.toi_hi, true, r.starts_within, r.toi_lo, r.toi_hi});
  };
  const auto visits = [&](MeshId a, MeshId b) {
    if (meshes[a].is_static && meshes[b].is_static) return false;
    return a != b || self;
  };
  const MeshId n = static_cast<MeshId>(meshes.size());
  for (MeshId a = 0; a < n; ++a) {
    const Spec& A = meshes[a];
    const std::vector<char> a_points = points_of(A);
    for (MeshId b = 0; b < n; ++b) {
      const Spec& B = meshes[b];
      if (B.kind == Kind::plane) {
        if (A.is_static || A.kind == Kind::plane) continue;
        for (Eigen::Index v = 0; v < A.start.rows(); ++v)
          keep(QueryType::point_plane, a, v, b, 0,
               point_plane_ccd({at(A.start, v), B.origin, B.normal, at(A.end, v), B.origin,
                                B.normal},
                               o));
        continue;
      }
      if (A.kind == Kind::plane || !visits(a, b)) continue;
      if (!planar) {
        for (Eigen::Index v = 0; v < A.start.rows(); ++v)  // vertex-face
          for (Eigen::Index f = 0; f < B.triangles.rows(); ++f) {
            if (a == b && (B.triangles(f, 0) == v || B.triangles(f, 1) == v ||
                           B.triangles(f, 2) == v))
              continue;
            const auto c = [&](const Positions& x, int k) { return at(x, B.triangles(f, k)); };
            keep(QueryType::vertex_face, a, v, b, f,
                 vertex_face_ccd({at(A.start, v), c(B.start, 0), c(B.start, 1), c(B.start, 2),
                                  at(A.end, v), c(B.end, 0), c(B.end, 1), c(B.end, 2)},
                                 o));
          }
        if (a <= b)  // edge-edge, (a, i) < (b, j)
          for (Eigen::Index i = 0; i < A.edges.rows(); ++i)
            for (Eigen::Index j = a == b ? i + 1 : 0; j < B.edges.rows(); ++j) {
              if (a == b && (on_edge(A.edges, i, B.edges(j, 0)) ||
                             on_edge(A.edges, i, B.edges(j, 1))))
                continue;
              const auto ea = [&](const Positions& x, int k) { return at(x, A.edges(i, k)); };
              const auto eb = [&](const Positions& x, int k) { return at(x, B.edges(j, k)); };
              keep(QueryType::edge_edge, a, i, b, j,
                   edge_edge_ccd({ea(A.start, 0), ea(A.start, 1), eb(B.start, 0),
                                  eb(B.start, 1), ea(A.end, 0), ea(A.end, 1), eb(B.end, 0),
                                  eb(B.end, 1)},
                                 o));
            }
      }
      for (Eigen::Index v = 0; v < A.start.rows(); ++v) {  // point-edge
        if (!planar && !a_points[v]) continue;
        if (planar && A.kind == Kind::triangles) continue;
        for (Eigen::Index e = 0; e < B.edges.rows(); ++e) {
          if (a == b && on_edge(B.edges, e, v)) continue;
          const auto ep = [&](const Positions& x, int k) { return at(x, B.edges(e, k)); };
          const CcdResult r =
              planar ? point_edge_ccd_2d({xy(at(A.start, v)), xy(ep(B.start, 0)),
                                          xy(ep(B.start, 1)), xy(at(A.end, v)),
                                          xy(ep(B.end, 0)), xy(ep(B.end, 1))},
                                         o)
                     : point_edge_ccd({at(A.start, v), ep(B.start, 0), ep(B.start, 1),
                                       at(A.end, v), ep(B.end, 0), ep(B.end, 1)},
                                      o);
          keep(QueryType::point_edge, a, v, b, e, r);
        }
      }
      if (a <= b) {  // point-point
        const std::vector<char> b_points = points_of(B);
        for (Eigen::Index i = 0; i < A.start.rows(); ++i)
          for (Eigen::Index j = a == b ? i + 1 : 0; j < B.start.rows(); ++j) {
            if (!a_points[i] || !b_points[j]) continue;
            const CcdResult r =
                planar ? point_point_ccd_2d({xy(at(A.start, i)), xy(at(B.start, j)),
                                             xy(at(A.end, i)), xy(at(B.end, j))},
                                            o)
                       : point_point_ccd({at(A.start, i), at(B.start, j), at(A.end, i),
                                          at(B.end, j)},
                                         o);
            keep(QueryType::point_point, a, i, b, j, r);
          }
      }
    }
  }
  std::sort(out.begin(), out.end(),
            [](const SceneContact& x, const SceneContact& y) { return x.pair < y.pair; });
  return out;
}

::testing::AssertionResult same(const std::vector<SceneContact>& got,
                                const std::vector<SceneContact>& want) {
  for (std::size_t k = 0; k < std::min(got.size(), want.size()); ++k)
    if (!(got[k].pair == want[k].pair) || got[k].toi_lo != want[k].toi_lo ||
        got[k].toi_hi != want[k].toi_hi || got[k].starts_within != want[k].starts_within)
      return ::testing::AssertionFailure()
             << "contact " << k << ": got " << name(got[k].pair) << " [" << got[k].toi_lo << ", "
             << got[k].toi_hi << "], expected " << name(want[k].pair) << " [" << want[k].toi_lo
             << ", " << want[k].toi_hi << "]";
  if (got.size() != want.size())
    return ::testing::AssertionFailure() << got.size() << " contacts, expected " << want.size()
                                         << (got.size() > want.size()
                                                 ? "; first extra " + name(got[want.size()].pair)
                                                 : "; first missing " + name(want[got.size()].pair));
  return ::testing::AssertionSuccess();
}

Positions random_positions(std::mt19937_64& rng, int n, const Eigen::Vector3d& lo, double size,
                           bool planar) {
  std::uniform_real_distribution<double> u(0.0, size);
  Positions x(n, 3);
  for (int v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) x(v, k) = planar && k == 2 ? 0.0 : lo[k] + u(rng);
  return x;
}

/// A polyline through n random points near `lo` (each vertex on at most two edges), plus
/// `stray` vertices on no edge (points of the edge mesh).
Spec polyline(std::mt19937_64& rng, int n, int stray, const Eigen::Vector3d& lo, bool planar) {
  Spec m;
  m.kind = Kind::edges;
  m.start = random_positions(rng, n + stray, lo, 0.6, planar);
  m.edges.resize(n - 1, 2);
  for (int e = 0; e + 1 < n; ++e) {
    m.edges(e, 0) = e % 2 ? e + 1 : e;  // both orientations
    m.edges(e, 1) = e % 2 ? e : e + 1;
  }
  return m;
}

Spec points(std::mt19937_64& rng, int n, const Eigen::Vector3d& lo, bool planar) {
  Spec m;
  m.kind = Kind::points;
  m.start = random_positions(rng, n, lo, 0.6, planar);
  m.edges.resize(0, 2);
  return m;
}

Spec sheet(std::mt19937_64& rng, int n, const Eigen::Vector3d& lo) {
  Spec m;
  m.start.resize(n * n, 3);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      m.start.row(i * n + j) << lo.x() + 0.6 * i / (n - 1), lo.y() + 0.6 * j / (n - 1),
          lo.z() + jitter(rng);
  m.triangles.resize(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int v = i * n + j;
      m.triangles.row(f++) << v, v + n, v + 1;
      m.triangles.row(f++) << v + 1, v + n, v + n + 1;
    }
  return m;
}

/// Moves every vertex of the moving meshes by a random step of up to `reach` per axis; some
/// vertices land exactly on the plane z = 0 (the floor) or start on it.
void move(std::mt19937_64& rng, std::vector<Spec>& meshes, double reach, bool planar) {
  std::uniform_real_distribution<double> u(-reach, reach);
  std::uniform_int_distribution<int> pick(0, 9);
  for (Spec& m : meshes) {
    m.end = m.start;
    if (m.is_static || m.kind == Kind::plane) continue;
    for (Eigen::Index v = 0; v < m.start.rows(); ++v) {
      for (int k = 0; k < (planar ? 2 : 3); ++k) m.end(v, k) = m.start(v, k) + u(rng);
      if (!planar && pick(rng) == 0) m.end(v, 2) = 0.0;
      if (!planar && pick(rng) == 0) m.start(v, 2) = 0.0;
    }
  }
}

Scene build(std::vector<Spec>& meshes, bool planar) {
  Scene scene(planar ? SceneDimension::two : SceneDimension::three);
  for (Spec& m : meshes) {
    MeshId id = 0;
    switch (m.kind) {
      case Kind::triangles:
        id = m.is_static ? scene.add_static_mesh(m.start, m.triangles)
                         : scene.add_mesh(m.start, m.triangles);
        m.edges = scene.edges(id);
        break;
      case Kind::edges:
        id = m.is_static ? scene.add_static_edge_mesh(m.start, m.edges)
                         : scene.add_edge_mesh(m.start, m.edges);
        break;
      case Kind::points: id = scene.add_points(m.start); break;
      case Kind::plane: id = scene.add_plane(m.origin, m.normal); break;
    }
    if (!m.is_static && m.kind != Kind::plane) scene.set_motion(id, m.start, m.end);
  }
  return scene;
}

/// The scene's answers in every form against the reference.
void check_scene(std::vector<Spec> meshes, bool planar, const std::string& what,
                 std::size_t min_contacts) {
  Scene scene = build(meshes, planar);
  std::size_t point_kinds = 0;
  for (const double delta : {0.0, 0.01}) {
    for (const bool self : {true, false}) {
      SCOPED_TRACE(what + " delta " + std::to_string(delta) + " self " + std::to_string(self));
      const std::vector<SceneContact> want = reference(meshes, planar, delta, self);
      if (delta == 0.0 && self) {
        EXPECT_GE(want.size(), min_contacts);
        for (const SceneContact& c : want) point_kinds += c.pair.type >= QueryType::point_edge;
      }
      SceneOptions o;
      o.min_separation = delta;
      o.self_collision = self;
      for (const int threads : {1, 2}) {
        o.max_threads = threads;
        o.record_candidates = false;
        const SceneResult streamed = scene.find_contacts(o);
        EXPECT_TRUE(same(streamed.contacts, want)) << "streamed, threads " << threads;
        o.record_candidates = true;
        const SceneResult listed = scene.find_contacts(o);
        EXPECT_TRUE(same(listed.contacts, want)) << "listed, threads " << threads;
        o.record_candidates = false;
        const EarliestContact first = scene.earliest_contact(o);
        EXPECT_EQ(first.collides, !want.empty());
        EXPECT_TRUE(first.contact.pair == streamed.earliest.pair &&
                    first.contact.toi_lo == streamed.earliest.toi_lo &&
                    first.contact.toi_hi == streamed.earliest.toi_hi)
            << "earliest " << name(first.contact.pair) << " vs " << name(streamed.earliest.pair);
        std::uint64_t points_in = 0;
        for (const SceneContact& c : streamed.contacts)
          points_in += c.pair.type >= QueryType::point_edge;
        EXPECT_GE(streamed.stats.point_candidates, points_in);
      }
    }
  }
  EXPECT_GT(point_kinds, 0u) << what << ": no point pair collides; the test shows nothing";
}

TEST(SceneCodimensional, MixedScenesEqualTheBruteForceReference) {
  std::mt19937_64 rng(test_seed("scene_codimensional"));
  for (int round = 0; round < 6; ++round) {
    std::vector<Spec> meshes;
    meshes.push_back(sheet(rng, 4, {0.0, 0.0, 0.3}));
    meshes.push_back(polyline(rng, 8, 2, {0.1, 0.1, 0.1}, false));
    meshes.push_back(points(rng, 10, {0.0, 0.1, 0.0}, false));
    Spec wall = polyline(rng, 5, 0, {0.2, 0.0, 0.2}, false);
    wall.is_static = true;
    meshes.push_back(wall);
    Spec floor;
    floor.kind = Kind::plane;
    floor.is_static = true;
    floor.normal = Eigen::Vector3d(0, 0, round % 2 ? 1.0 : 3.0);  // a non-unit normal too
    meshes.push_back(floor);
    Spec tilted;
    tilted.kind = Kind::plane;
    tilted.is_static = true;
    tilted.origin = Eigen::Vector3d(0.3, 0.3, 0.3);
    tilted.normal = Eigen::Vector3d(1.0, -2.0, 0.5);
    meshes.push_back(tilted);
    move(rng, meshes, 0.3, false);
    check_scene(meshes, false, "3D round " + std::to_string(round), 20);
  }
}

TEST(SceneCodimensional, PlanarScenesEqualTheBruteForceReference) {
  std::mt19937_64 rng(test_seed("scene_codimensional_2d"));
  for (int round = 0; round < 6; ++round) {
    std::vector<Spec> meshes;
    meshes.push_back(polyline(rng, 10, 1, {0.0, 0.0, 0.0}, true));
    meshes.push_back(polyline(rng, 6, 0, {0.2, 0.1, 0.0}, true));
    meshes.push_back(points(rng, 12, {0.1, 0.0, 0.0}, true));
    Spec walls = polyline(rng, 5, 0, {0.0, 0.2, 0.0}, true);
    walls.is_static = true;
    meshes.push_back(walls);
    move(rng, meshes, 0.3, true);
    check_scene(meshes, true, "2D round " + std::to_string(round), 20);
  }
}

/// The pair kinds' queries are the pair's primitives at t0 and t1, and the contact geometry of a
/// point pair is that of the zero-length segment its test decides.
TEST(SceneCodimensional, QueriesAndContactGeometryOfPointPairs) {
  Scene scene;
  Positions rod(2, 3), dots(2, 3);
  rod << -1, 0, 0, 1, 0, 0;
  dots << 0.25, 0.5, 0, 0.5, 0.5, 1;  // the first falls onto the rod, the second onto the first
  const MeshId r = scene.add_edge_mesh(rod, (Edges(1, 2) << 0, 1).finished());
  const MeshId d = scene.add_points(dots);
  Positions dots_end = dots;
  dots_end.row(0) << 0.25, -0.5, 0;
  dots_end.row(1) << 0.25, -0.5, 0;
  scene.set_motion(d, dots, dots_end);
  const MeshId floor = scene.add_plane(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(0, 0, 2));
  const SceneResult res = scene.find_contacts();
  std::vector<QueryType> kinds;
  for (const SceneContact& c : res.contacts) kinds.push_back(c.pair.type);
  ASSERT_EQ(kinds, (std::vector<QueryType>{QueryType::point_edge, QueryType::point_point,
                                           QueryType::point_plane}));
  const SceneContact& pe = res.contacts[0];
  EXPECT_EQ(pe.pair.first_mesh, d);
  EXPECT_EQ(pe.pair.second_mesh, r);
  EXPECT_LE(pe.toi_lo, 0.5);  // y from 0.5 to -0.5: on the rod at t = 1/2
  EXPECT_GE(pe.toi_hi, 0.5);
  const PointEdgeQuery q = scene.point_edge_query(pe.pair);
  EXPECT_EQ(q.p_t1, Eigen::Vector3d(0.25, -0.5, 0));
  EXPECT_EQ(q.e1_t0, Eigen::Vector3d(1, 0, 0));
  const ContactGeometry g = scene.contact_geometry(pe);
  EXPECT_EQ(g.parameter_count, 2);
  EXPECT_EQ(g.parameters[0].lo, 0.0);  // the point: the zero-length segment's parameter
  EXPECT_EQ(g.parameters[0].hi, 0.0);
  EXPECT_LE(g.parameters[1].lo, 0.625);  // at x = 0.25 on [-1, 1]
  EXPECT_GE(g.parameters[1].hi, 0.625);
  const ContactGeometry same = contact_geometry(
      EdgeEdgeQuery{q.p_t0, q.p_t0, q.e0_t0, q.e1_t0, q.p_t1, q.p_t1, q.e0_t1, q.e1_t1},
      CcdResult{true, pe.toi_lo, pe.toi_hi, Stage::exact, pe.starts_within});
  EXPECT_EQ(g.parameters[1].lo, same.parameters[1].lo);
  EXPECT_EQ(g.parameters[1].hi, same.parameters[1].hi);
  const SceneContact& on_plane = res.contacts[2];
  const PointPlaneQuery pl = scene.point_plane_query(on_plane.pair);
  EXPECT_EQ(on_plane.pair.second_mesh, floor);
  EXPECT_EQ(on_plane.pair.first_index, 1u);
  EXPECT_EQ(pl.normal_t1, Eigen::Vector3d(0, 0, 2));
  EXPECT_LE(on_plane.toi_lo, 0.5);  // the second point: z from 1 to 0 crosses 0.5 at t = 1/2
  EXPECT_GE(on_plane.toi_hi, 0.5);
  const ContactGeometry on = scene.contact_geometry(on_plane);  // from above: +z
  EXPECT_EQ(on.kind, ContactKind::point);
  EXPECT_TRUE(on.normal_oriented);
  EXPECT_EQ(on.normal[2].lo, 1.0);
  EXPECT_EQ(on.normal[2].hi, 1.0);
  EXPECT_EQ(on.parameter_count, 0);
  const PointPointQuery pp = scene.point_point_query(res.contacts[1].pair);
  EXPECT_EQ(pp.q_t0, Eigen::Vector3d(0.5, 0.5, 1));
  EXPECT_LE(res.contacts[1].toi_lo, 1.0);  // both points end at (0.25, -0.5, 0)
  EXPECT_THROW(scene.point_edge_query(res.contacts[1].pair), std::invalid_argument);
  EXPECT_THROW(scene.vertex_face_query(res.contacts[0].pair), std::invalid_argument);
  EXPECT_TRUE(scene.is_plane(floor));
  EXPECT_FALSE(scene.is_plane(r));
  EXPECT_EQ(scene.plane(floor).second, Eigen::Vector3d(0, 0, 2));
  EXPECT_THROW(scene.plane(r), std::invalid_argument);
}

/// A point set against a turning rigid body: the point-edge pairs (a point against a rigid edge,
/// decided as the rigid edge-edge query of a zero-length segment) agree with Mode::exact, and
/// the scene agrees with deciding each pair by itself.
TEST(SceneCodimensional, PointsAgainstARigidBody) {
  std::mt19937_64 rng(test_seed("scene_codimensional_rigid"));
  Spec body = sheet(rng, 4, {-0.3, -0.3, 0.0});
  Scene scene;
  const MeshId b = scene.add_rigid_body(body.start, body.triangles);
  RigidMotion turn;
  turn.pivot = Eigen::Vector3d(0, 0, 0);
  turn.cayley = Eigen::Vector3d(0.4, 0.1, 0.0);
  turn.translation = Eigen::Vector3d(0.0, 0.0, 0.05);
  scene.set_rigid_motion(b, turn);
  Spec dots = points(rng, 40, {-0.3, -0.3, -0.3}, false);
  const MeshId d = scene.add_points(dots.start);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Positions end = dots.start;
  for (Eigen::Index v = 0; v < end.rows(); ++v) end(v, 2) += u(rng);
  scene.set_motion(d, dots.start, end);
  std::size_t point_edge = 0;
  for (const double delta : {0.0, 0.02}) {
    SceneOptions o;
    o.min_separation = delta;
    o.record_candidates = true;
    const SceneResult res = scene.find_contacts(o);
    std::vector<SceneContact> by_pair;
    CcdOptions exact;
    exact.mode = Mode::exact;
    exact.min_separation = delta;
    CcdOptions filtered;
    filtered.min_separation = delta;
    for (const ScenePair& p : res.candidates) {
      if (p.type != QueryType::point_edge) continue;
      const RigidEdgeEdgeQuery q = scene.rigid_edge_edge_query(p);
      const RigidCcdResult f = edge_edge_ccd(q, filtered);
      const RigidCcdResult e = edge_edge_ccd(q, exact);
      ASSERT_EQ(f.ccd.collides, e.ccd.collides) << name(p);
      if (f.ccd.collides) {
        EXPECT_LE(e.ccd.toi_lo, f.ccd.toi_hi) << name(p);  // the enclosures overlap
        EXPECT_LE(f.ccd.toi_lo, e.ccd.toi_hi) << name(p);
        ++point_edge;
        by_pair.push_back({p, f.ccd.toi_lo, f.ccd.toi_hi});
      }
    }
    std::vector<SceneContact> got;
    for (const SceneContact& c : res.contacts)
      if (c.pair.type == QueryType::point_edge) got.push_back(c);
    ASSERT_EQ(got.size(), by_pair.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_TRUE(got[k].pair == by_pair[k].pair);
      EXPECT_EQ(got[k].toi_lo, by_pair[k].toi_lo);
    }
  }
  EXPECT_GT(point_edge, 0u) << "no point meets a rigid edge; the test shows nothing";
}

TEST(SceneCodimensional, BadInputIsRefusedWithAClearMessage) {
  const auto message = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  Positions flat(3, 3);
  flat << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  Positions raised = flat;
  raised(2, 2) = 1e-300;
  Scene planar(SceneDimension::two);
  EXPECT_NE(message([&] { planar.add_points(raised); }).find("z = 1e-300 at row 2"),
            std::string::npos);
  EXPECT_NE(message([&] { planar.add_mesh(flat, (Triangles(1, 3) << 0, 1, 2).finished()); })
                .find("not triangle meshes"),
            std::string::npos);
  EXPECT_NE(message([&] { planar.add_plane({0, 0, 0}, {0, 0, 1}); }).find("2D scene"),
            std::string::npos);
  const MeshId dots = planar.add_points(flat);
  EXPECT_NE(message([&] { planar.set_motion(dots, flat, raised); }).find("z = 1e-300"),
            std::string::npos);
  EXPECT_EQ(planar.dimension(), SceneDimension::two);

  Scene scene;
  EXPECT_NE(message([&] { scene.add_plane({0, 0, 0}, {0, 0, 0}); }).find("normal is zero"),
            std::string::npos);
  EXPECT_NE(message([&] { scene.add_plane({0, 0, NAN}, {0, 0, 1}); }).find("non-finite"),
            std::string::npos);
  EXPECT_NE(message([&] { scene.add_edge_mesh(flat, (Edges(2, 2) << 0, 1, 1, 0).finished()); })
                .find("edge 1 repeats edge 0"),
            std::string::npos);
  EXPECT_NE(message([&] { scene.add_edge_mesh(flat, (Edges(1, 2) << 0, 3).finished()); })
                .find("out of range"),
            std::string::npos);
  EXPECT_NE(message([&] { scene.add_edge_mesh(flat, (Edges(1, 2) << 2, 2).finished()); })
                .find("repeats a vertex"),
            std::string::npos);
  const MeshId rod = scene.add_edge_mesh(flat, (Edges(1, 2) << 0, 1).finished());
  EXPECT_NE(message([&] { scene.set_edges(rod, (Edges(1, 2) << 0, 1).finished()); })
                .find("not a triangle mesh"),
            std::string::npos);
  const MeshId plane = scene.add_plane({0, 0, -1}, {0, 0, 1});
  EXPECT_NE(message([&] { scene.set_motion(plane, Positions(0, 3), Positions(0, 3)); })
                .find("never moves"),
            std::string::npos);
  EXPECT_NE(message([&] { scene.rigid_point_plane_query({QueryType::point_plane, rod, 0, plane, 0}); })
                .find("not a rigid body"),
            std::string::npos);
}

}  // namespace
}  // namespace exactccd::test
