// Demonstration scene "robust cloth" (issue 5): a cloth of N x N vertices (default 100 x 100)
// dropped with large time steps (default 1/30 s) on a sharp spike and a sharp wedge standing on
// a floor, where it drapes over them, piles up and folds onto itself. The cloth never passes
// through the obstacles or through itself; every step is certified by exact CCD and checked by
// an exact intersection test of every triangle pair.
//
//   exactccd_cloth [--n 100] [--steps 45] [--dt 0.0333] [--out bench/scenes/out/cloth]
//   exactccd_cloth --check-only        (20 x 20 cloth, 40 steps, writes nothing; for CTest)
//   python3 bench/scenes/plot_cloth.py bench/scenes/out/cloth        (the pictures)
//
// Scene (metres, z up): a floor (two triangles) at z = 1; an eight-sided spike 0.42 high with a
// sharp apex (8 triangles); a triangular prism ("wedge") 0.30 high with a ridge of about 44
// degrees (6 triangles); above them a square cloth of side 1, tilted by 60 degrees about the y
// axis (--tilt), its lowest edge 0.5 above the floor, with a gentle wrinkle of 5 mm.
//  - Tilted, not horizontal: the response below is inelastic and sticky, so a horizontal cloth
//    lands where it falls and never meets itself (--tilt 0: no cloth-cloth contact at all). A
//    tilted cloth falls onto a footprint half as wide as itself: it must fold onto itself.
//  - The wrinkle: an exactly planar cloth makes every self pair coplanar throughout the step,
//    the slowest case of the exact path.
//  - The floor at z = 1, not 0: near 0 the doubles are dense, and a cloth resting on a floor at
//    z = 0 would drive its gaps, step after step, into subnormal numbers; above z = 1 a gap is
//    at least the spacing of the doubles there (2^-52).
//
// Integrator: position-based dynamics (Mueller et al. 2007), all masses equal. Each step:
//   v <- (1 - damping) (v + dt g);  x* <- x + dt v;
//   `iterations` Gauss-Seidel sweeps, in a fixed order, over distance constraints: every mesh
//   edge (stretch and shear, stiffness 1) and every pair of vertices two apart along a grid line
//   (bending: stiffness k per sweep with 1 - (1 - k)^iterations = --bend);
//   x_end <- the collision response below;  v <- (x_end - x) / dt, then the response's rule.
// Plain double arithmetic in a fixed order, no threads: the run is deterministic (the CCD runs
// in parallel, but its results do not depend on the threads).
//
// Collision response: stop at the conservative TOI, pin when hit again (inelastic contact).
//   The step's motion goes from x (its start, which touches nothing) to x_end (initially x*).
//   Rounds: find_contacts (exact) on the motion x -> x_end; no contact: done. Otherwise, for
//   every cloth vertex of a colliding pair, with s its smallest toi_lo over its pairs:
//     - a vertex not yet stopped in this step is stopped short of its contact:
//       x_end <- x + (f s) (x_end - x), f = --stop-fraction (0.9). With f = 1 the vertex
//       ends touching, within rounding, and most stopped vertices (three quarters and more
//       during this scene's impact) are hit again in the next round and pinned, losing their
//       whole motion: the cloth then shows vertices hanging in the air. f = 0.9 leaves a gap
//       of a tenth of the approach. Where rounding puts x_end does not matter: the next round
//       checks the new motion.
//     - a vertex already stopped in an earlier round of this step is pinned: x_end <- x.
//   Termination: a colliding pair always has a vertex that is not pinned (a pair whose vertices
//   all stand still sits at its start positions, which touch nothing), so every round with a
//   contact stops or pins at least one more vertex. After --max-rounds rounds with contacts the
//   whole cloth is frozen for the step (x_end <- x, which touches nothing), counted as a frozen
//   step (expected 0).
//   Velocity: v <- (x_end - x) / dt; a pinned vertex gets v = 0; a stopped vertex loses the
//   component of v along each of its contact normals: the certified contact normal at the
//   exact time of impact (exactccd::contact_geometry: the triangle's normal for vertex-face, the
//   cross product of the two edges for edge-edge, at t*; the midpoint of its enclosure, made
//   unit), or, where the geometry is unresolved, that direction at the step's start
//   (--normal-at-start: always at the step's start, as before the contact geometry existed).
//
// Certificate: the last CCD call of every step found no contact for the final motion over the
// closed interval [0, 1]: no vertex-face or edge-edge pair touches at any instant of the step,
// the end included, so no triangle passes through another (the end state, contact-free, is the
// next step's start). Independently, after every step the program tests every pair of triangles
// not sharing a vertex at the end positions with the exact triangle-triangle test
// (`intersecting_triangle_pairs`) and counts the intersecting pairs as violations (expected 0;
// the program exits with status 1 otherwise).
//
// Outputs in --out DIR: summary.json (settings, the meshes, per-step statistics, frames, query
// counts); frames/step_SSSS.f64 (the cloth's vertex positions after step SSSS, step 0 the
// start: little-endian doubles, N*N rows of x, y, z); and the CCD queries of every
// --query-every-th step in the benchmark's CSV format, written by the scenes' shared
// QueryCsvWriter (queries/vertex-face/data_K.csv and queries/edge-edge/data_K.csv, K-th sampled
// step: 8 rows per query, exact fractions of the doubles, truth from the exact CCD), part of the
// scenes' simulation data set. Per sampled step: an even sample (fixed strides)
// of the first round's candidates, colliding ones up to half of the step's share of
// --max-queries, and in later rounds of the same step only the pairs with a vertex that the
// previous round moved (the others are the same queries again).
#include <CLI/CLI.hpp>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "corpus/meshes.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/discrete.hpp"
#include "exactccd/scene.hpp"

namespace {

namespace fs = std::filesystem;
using exactccd::CcdResult;
using exactccd::Edges;
using exactccd::MeshId;
using exactccd::Positions;
using exactccd::QueryType;
using exactccd::Scene;
using exactccd::SceneContact;
using exactccd::ScenePair;
using exactccd::Triangles;
using Vec3 = Eigen::Vector3d;

constexpr double kFloorZ = 1.0;
constexpr double kGravity = 9.81;

struct Settings {
  int n = 100;             ///< vertices per side of the cloth
  int steps = 45;
  double dt = 1.0 / 30.0;  ///< seconds
  int iterations = 40;     ///< Gauss-Seidel sweeps per step
  double bend_stiffness = 0.3;  ///< of the bending constraints, after all sweeps (0..1)
  double damping = 0.01;   ///< fraction of the velocity lost per step
  double tilt_degrees = 60.0;  ///< of the cloth at the start, about the y axis
  int max_rounds = 50;
  double stop_fraction = 0.9;  ///< a stopped vertex goes this fraction of the way to its TOI
  int query_every = 5;     ///< write the queries of every k-th step (0: none)
  std::size_t max_queries = 50000;
  int frame_every = 2;
  int threads = 0;         ///< CCD threads; 0: TBB's default
  std::string out = "bench/scenes/out/cloth";
  bool check_only = false;
  bool normal_at_start = false;  ///< the response's normals at the step's start, not at t*
};

struct Mesh {
  Positions x;
  Triangles triangles;
};

// ---------------------------------------------------------------------------------------------
// Meshes

/// An n x n grid of side 1 centred on (cx, cy, cz), tilted by `tilt` radians about the y axis
/// (its edge at low x lowest), with a gentle wrinkle of 5 mm along its normal; two triangles per
/// cell with alternating diagonals (no preferred fold direction), wound so that their normals
/// point up.
Mesh cloth_mesh(int n, double cx, double cy, double cz, double tilt) {
  Mesh m;
  m.x.resize(static_cast<Eigen::Index>(n) * n, 3);
  const double pi = std::acos(-1.0);
  const double cos_tilt = std::cos(tilt), sin_tilt = std::sin(tilt);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = static_cast<double>(i) / (n - 1), w = static_cast<double>(j) / (n - 1);
      const double wrinkle = 0.005 * std::sin(2.0 * pi * u + 0.3) * std::sin(3.0 * pi * w + 0.7);
      const Eigen::Index v = static_cast<Eigen::Index>(j) * n + i;
      m.x(v, 0) = cx + (u - 0.5) * cos_tilt - wrinkle * sin_tilt;
      m.x(v, 1) = cy - 0.5 + w;
      m.x(v, 2) = cz + (u - 0.5) * sin_tilt + wrinkle * cos_tilt;
    }
  m.triangles.resize(2 * static_cast<Eigen::Index>(n - 1) * (n - 1), 3);
  Eigen::Index f = 0;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const std::int32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      if ((i + j) % 2 == 0) {
        m.triangles.row(f++) << a, b, d;
        m.triangles.row(f++) << a, d, c;
      } else {
        m.triangles.row(f++) << a, b, c;
        m.triangles.row(f++) << b, d, c;
      }
    }
  return m;
}

Mesh floor_mesh(double half) {
  Mesh m;
  m.x.resize(4, 3);
  m.x << -half, -half, kFloorZ, half, -half, kFloorZ, half, half, kFloorZ, -half, half, kFloorZ;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 2, 3;
  return m;
}

/// An eight-sided pyramid standing on the floor: base radius r, apex at height h (open base).
Mesh spike_mesh(double cx, double cy, double r, double h) {
  constexpr int kSides = 8;
  Mesh m;
  m.x.resize(kSides + 1, 3);
  const double pi = std::acos(-1.0);
  for (int k = 0; k < kSides; ++k) {
    const double a = 2.0 * pi * (k + 0.5) / kSides;
    m.x.row(k) << cx + r * std::cos(a), cy + r * std::sin(a), kFloorZ;
  }
  m.x.row(kSides) << cx, cy, kFloorZ + h;
  m.triangles.resize(kSides, 3);
  for (int k = 0; k < kSides; ++k) m.triangles.row(k) << k, (k + 1) % kSides, kSides;
  return m;
}

/// A triangular prism lying on the floor: ridge along y at x = cx, height h, base half-width
/// hw, from y0 to y1 (open base).
Mesh wedge_mesh(double cx, double y0, double y1, double hw, double h) {
  Mesh m;
  m.x.resize(6, 3);
  m.x << cx - hw, y0, kFloorZ,  // 0: base left, front
      cx + hw, y0, kFloorZ,     // 1: base right, front
      cx, y0, kFloorZ + h,      // 2: ridge, front
      cx - hw, y1, kFloorZ,     // 3: base left, back
      cx + hw, y1, kFloorZ,     // 4: base right, back
      cx, y1, kFloorZ + h;      // 5: ridge, back
  m.triangles.resize(6, 3);
  m.triangles << 0, 1, 2,  // front cap (wound so that normals point outwards)
      3, 5, 4,             // back cap
      0, 2, 5, 0, 5, 3,    // left slope
      1, 5, 2, 1, 4, 5;    // right slope
  return m;
}

// ---------------------------------------------------------------------------------------------
// Position-based dynamics

struct Constraint {
  std::int32_t i, j;
  double rest;
  double stiffness;  ///< per sweep
};

struct Cloth {
  int n = 0;
  Positions x, v;
  std::vector<Constraint> constraints;
};

Cloth make_cloth(const Mesh& mesh, const Edges& edges, int n, const Settings& s) {
  Cloth c;
  c.n = n;
  c.x = mesh.x;
  c.v = Positions::Zero(mesh.x.rows(), 3);
  const auto rest = [&](std::int32_t i, std::int32_t j) {
    return (c.x.row(i) - c.x.row(j)).norm();
  };
  for (Eigen::Index e = 0; e < edges.rows(); ++e)
    c.constraints.push_back({edges(e, 0), edges(e, 1), rest(edges(e, 0), edges(e, 1)), 1.0});
  // Stiffness per sweep k such that 1 - (1 - k)^iterations = bend_stiffness (Mueller et al.).
  const double k =
      1.0 - std::pow(1.0 - std::min(s.bend_stiffness, 0.999999), 1.0 / s.iterations);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t a = j * n + i;
      if (i + 2 < n) c.constraints.push_back({a, a + 2, rest(a, a + 2), k});
      if (j + 2 < n) c.constraints.push_back({a, a + 2 * n, rest(a, a + 2 * n), k});
    }
  return c;
}

/// x* from x and v (v is updated with gravity and damping).
Positions predict(Cloth& c, const Settings& s) {
  const Vec3 g(0.0, 0.0, -kGravity);
  Positions p(c.x.rows(), 3);
  for (Eigen::Index i = 0; i < c.x.rows(); ++i) {
    const Vec3 v = (1.0 - s.damping) * (c.v.row(i).transpose() + s.dt * g);
    c.v.row(i) = v.transpose();
    p.row(i) = c.x.row(i) + s.dt * v.transpose();
  }
  for (int sweep = 0; sweep < s.iterations; ++sweep)
    for (const Constraint& k : c.constraints) {
      const Vec3 d = p.row(k.j) - p.row(k.i);
      const double length = d.norm();
      if (length == 0.0) continue;
      const Vec3 correction = (0.5 * k.stiffness * (length - k.rest) / length) * d;
      p.row(k.i) += correction.transpose();
      p.row(k.j) -= correction.transpose();
    }
  return p;
}

// ---------------------------------------------------------------------------------------------
// One step: prediction, CCD rounds, response, check

struct StepStats {
  int step = 0;
  int rounds = 0;          ///< find_contacts calls with a contact (0: the proposal was clean)
  bool frozen = false;
  std::size_t obstacle_contacts = 0, self_contacts = 0;  ///< contacts of the proposed motion
  std::size_t vertex_face_contacts = 0, edge_edge_contacts = 0;  ///< same, by type
  std::size_t contacts_all_rounds = 0;
  std::size_t unresolved_normals = 0;  ///< contacts whose certified normal was unresolved
  std::size_t stopped = 0, pinned = 0;  ///< vertices at the end of the step
  std::uint64_t candidates = 0;         ///< of the proposed motion
  double ccd_ms = 0.0, check_ms = 0.0;
  std::size_t violations = 0;  ///< intersecting triangle pairs at the end of the step
  double lowest_z = 0.0, mean_speed = 0.0;
};

enum class VertexState : std::uint8_t { free, stopped, pinned };

/// The cloth vertices (indices into the cloth) of a pair; obstacles' vertices are omitted.
int cloth_vertices(const Scene& scene, MeshId cloth, const ScenePair& p, std::int32_t out[4]) {
  int count = 0;
  if (p.type == QueryType::vertex_face) {
    if (p.first_mesh == cloth) out[count++] = static_cast<std::int32_t>(p.first_index);
    if (p.second_mesh == cloth)
      for (int k = 0; k < 3; ++k) out[count++] = scene.triangles(cloth)(p.second_index, k);
  } else {
    if (p.first_mesh == cloth)
      for (int k = 0; k < 2; ++k) out[count++] = scene.edges(cloth)(p.first_index, k);
    if (p.second_mesh == cloth)
      for (int k = 0; k < 2; ++k) out[count++] = scene.edges(cloth)(p.second_index, k);
  }
  return count;
}

/// The pair's unit contact normal at the start of the step (zero when degenerate).
Vec3 normal_at_start(const Scene& scene, const ScenePair& p) {
  Vec3 n;
  if (p.type == QueryType::vertex_face) {
    const auto q = scene.vertex_face_query(p);
    n = (q.b_t0 - q.a_t0).cross(q.c_t0 - q.a_t0);
  } else {
    const auto q = scene.edge_edge_query(p);
    n = (q.ea1_t0 - q.ea0_t0).cross(q.eb1_t0 - q.eb0_t0);
  }
  const double length = n.norm();
  return length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3::Zero();
}

/// The contact's certified normal at t* (contact_geometry), the midpoint of its enclosure made
/// unit; the normal at the step's start where it is unresolved (counted in *unresolved).
Vec3 contact_normal(const Scene& scene, const SceneContact& c, std::size_t* unresolved) {
  CcdResult r;
  r.collides = true;
  r.toi_lo = c.toi_lo;
  r.toi_hi = c.toi_hi;
  r.starts_within = c.starts_within;
  const exactccd::ContactGeometry g =
      c.pair.type == QueryType::vertex_face
          ? exactccd::contact_geometry(scene.vertex_face_query(c.pair), r)
          : exactccd::contact_geometry(scene.edge_edge_query(c.pair), r);
  if (g.kind == exactccd::ContactKind::unresolved) {
    ++*unresolved;
    return normal_at_start(scene, c.pair);
  }
  Vec3 n;
  for (int i = 0; i < 3; ++i) n[i] = 0.5 * (g.normal[i].lo + g.normal[i].hi);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// The query sample of one step (see the file's header): fixed strides over the colliding and
/// the other candidates, set from the first round so that the step yields about `budget`
/// queries, at most half of them colliding.
class StepSample {
 public:
  explicit StepSample(std::size_t budget) : budget_(budget) {}

  /// The pairs of `result` to write; in rounds after the first only those with a cloth vertex
  /// in `moved` (the others are the same queries as before).
  std::vector<ScenePair> select(const Scene& scene, MeshId cloth, const exactccd::SceneResult& result,
                                int round, const std::vector<std::uint8_t>& moved) {
    if (round == 1) {
      const std::size_t hits = result.contacts.size();
      const std::size_t others = result.candidates.size() - hits;
      const std::size_t hit_budget = std::max<std::size_t>(1, budget_ / 2);
      const std::size_t other_budget =
          std::max<std::size_t>(1, budget_ - std::min(hits, hit_budget));
      stride_[1] = std::max<std::size_t>(1, (hits + hit_budget - 1) / hit_budget);
      stride_[0] = std::max<std::size_t>(1, (others + other_budget - 1) / other_budget);
    }
    std::vector<ScenePair> chosen;
    std::size_t c = 0;  // walks the contacts; both lists are in pair order
    for (const ScenePair& pair : result.candidates) {
      while (c < result.contacts.size() && result.contacts[c].pair < pair) ++c;
      const int kind = c < result.contacts.size() && result.contacts[c].pair == pair ? 1 : 0;
      if (round > 1) {
        std::int32_t vs[4];
        const int k = cloth_vertices(scene, cloth, pair, vs);
        bool touches_moved = false;
        for (int a = 0; a < k; ++a) touches_moved |= moved[static_cast<std::size_t>(vs[a])] != 0;
        if (!touches_moved) continue;
      }
      if (seen_[kind]++ % stride_[kind] == 0) chosen.push_back(pair);
    }
    return chosen;
  }

 private:
  std::size_t budget_;
  std::size_t stride_[2] = {1, 1}, seen_[2] = {0, 0};  ///< [0]: not colliding, [1]: colliding
};

/// Advances the cloth by one step (see the file's header). With a `writer`, the step's queries
/// (a sample of about `query_budget`, see StepSample) are added to it.
StepStats advance(Scene& scene, MeshId cloth_id, Cloth& cloth, const Settings& s,
                  exactccd::scenes::QueryCsvWriter* writer, std::size_t query_budget) {
  StepStats st;
  const Positions start = cloth.x;
  Positions end = predict(cloth, s);
  const Eigen::Index nv = start.rows();
  std::vector<VertexState> state(static_cast<std::size_t>(nv), VertexState::free);
  std::vector<std::uint8_t> moved(static_cast<std::size_t>(nv), 1);  // end changed last round
  std::vector<double> toi(static_cast<std::size_t>(nv));
  std::vector<std::pair<std::int32_t, Vec3>> normals;  // (vertex, contact normal)
  StepSample sample(query_budget);

  exactccd::SceneOptions options;
  options.max_threads = s.threads;
  options.record_candidates = writer != nullptr;
  for (int round = 1;; ++round) {
    scene.set_motion(cloth_id, start, end);
    const auto t0 = std::chrono::steady_clock::now();
    exactccd::SceneResult result = scene.find_contacts(options);
    st.ccd_ms += ms_since(t0);
    if (round == 1)
      st.candidates = result.stats.vertex_face_candidates + result.stats.edge_edge_candidates;
    if (writer) {
      // The writer takes the candidates of a result; hand it the sample only.
      exactccd::SceneResult chosen;
      chosen.candidates = sample.select(scene, cloth_id, result, round, moved);
      chosen.contacts = result.contacts;
      writer->add_step(scene, chosen);
      result.candidates.clear();
    }

    if (round == 1) {
      for (const SceneContact& c : result.contacts) {
        const bool self = c.pair.first_mesh == cloth_id && c.pair.second_mesh == cloth_id;
        ++(self ? st.self_contacts : st.obstacle_contacts);
        ++(c.pair.type == QueryType::vertex_face ? st.vertex_face_contacts
                                                 : st.edge_edge_contacts);
      }
    }
    st.contacts_all_rounds += result.contacts.size();
    if (result.contacts.empty()) break;
    st.rounds = round;

    if (st.frozen)  // impossible when the start touches nothing (see the file's header)
      throw std::logic_error("contacts for a cloth standing still at step start");
    if (round > s.max_rounds) {
      // Fallback: freeze the cloth for this step; a motion of no vertex touches nothing.
      st.frozen = true;
      end = start;
      std::fill(state.begin(), state.end(), VertexState::pinned);
      continue;
    }

    std::fill(toi.begin(), toi.end(), std::numeric_limits<double>::infinity());
    for (const SceneContact& c : result.contacts) {
      std::int32_t vs[4];
      const int k = cloth_vertices(scene, cloth_id, c.pair, vs);
      const Vec3 normal = s.normal_at_start ? normal_at_start(scene, c.pair)
                                            : contact_normal(scene, c, &st.unresolved_normals);
      for (int a = 0; a < k; ++a) {
        double& t = toi[static_cast<std::size_t>(vs[a])];
        t = std::min(t, c.toi_lo);
        normals.emplace_back(vs[a], normal);
      }
    }
    std::fill(moved.begin(), moved.end(), 0);
    for (Eigen::Index i = 0; i < nv; ++i) {
      const double t = toi[static_cast<std::size_t>(i)];
      if (!(t <= 1.0)) continue;
      VertexState& vs = state[static_cast<std::size_t>(i)];
      const Vec3 before = end.row(i).transpose();
      if (vs == VertexState::free) {
        vs = VertexState::stopped;
        end.row(i) = start.row(i) + (s.stop_fraction * t) * (end.row(i) - start.row(i));
      } else {
        vs = VertexState::pinned;
        end.row(i) = start.row(i);
      }
      moved[static_cast<std::size_t>(i)] = end.row(i).transpose() != before ? 1 : 0;
    }
  }

  // Velocity update and the response's velocity rule.
  cloth.v = (end - start) / s.dt;
  std::stable_sort(normals.begin(), normals.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [i, normal] : normals) {
    if (state[static_cast<std::size_t>(i)] != VertexState::stopped) continue;
    if (normal.isZero()) {
      cloth.v.row(i).setZero();
      continue;
    }
    const Vec3 v = cloth.v.row(i).transpose();
    cloth.v.row(i) = (v - v.dot(normal) * normal).transpose();
  }
  for (Eigen::Index i = 0; i < nv; ++i) {
    const VertexState vs = state[static_cast<std::size_t>(i)];
    if (vs == VertexState::pinned) cloth.v.row(i).setZero();
    st.stopped += vs == VertexState::stopped;
    st.pinned += vs == VertexState::pinned;
  }
  cloth.x = end;

  // The independent check: no two triangles intersect at the end of the step.
  const auto t0 = std::chrono::steady_clock::now();
  st.violations = exactccd::intersecting_triangle_pairs(scene, 1.0, true).size();
  st.check_ms = ms_since(t0);
  st.lowest_z = cloth.x.col(2).minCoeff() - kFloorZ;
  st.mean_speed = cloth.v.rowwise().norm().mean();
  return st;
}

// ---------------------------------------------------------------------------------------------
// Output

void write_frame(const fs::path& file, const Positions& x) {
  std::ofstream out(file, std::ios::binary);
  // Positions is row-major: x, y, z of vertex 0, then vertex 1, ... (the machine's byte order,
  // little-endian on the platforms the project supports).
  out.write(reinterpret_cast<const char*>(x.data()),
            static_cast<std::streamsize>(x.size() * sizeof(double)));
  if (!out) throw std::runtime_error(file.string() + ": write failed");
}

nlohmann::json mesh_json(const Mesh& m) {
  nlohmann::json j;
  j["vertices"] = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.x.rows(); ++i)
    j["vertices"].push_back({m.x(i, 0), m.x(i, 1), m.x(i, 2)});
  j["triangles"] = nlohmann::json::array();
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f)
    j["triangles"].push_back({m.triangles(f, 0), m.triangles(f, 1), m.triangles(f, 2)});
  return j;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

int run(Settings s) {
  const auto run_start = std::chrono::steady_clock::now();
  Scene scene;
  const Mesh floor = floor_mesh(1.2);
  const Mesh spike = spike_mesh(-0.2, -0.1, 0.05, 0.42);
  const Mesh wedge = wedge_mesh(0.2, -0.3, 0.25, 0.12, 0.30);
  // The cloth's lowest edge 0.5 above the floor (above the spike's apex).
  const double tilt = s.tilt_degrees * std::acos(-1.0) / 180.0;
  const Mesh cloth_start =
      cloth_mesh(s.n, 0.0, 0.0, kFloorZ + 0.5 + 0.5 * std::sin(tilt), tilt);
  scene.add_static_mesh(floor.x, floor.triangles);
  scene.add_static_mesh(spike.x, spike.triangles);
  scene.add_static_mesh(wedge.x, wedge.triangles);
  const MeshId cloth_id = scene.add_mesh(cloth_start.x, cloth_start.triangles);
  Cloth cloth = make_cloth(cloth_start, scene.edges(cloth_id), s.n, s);

  // The start state must touch nothing: no contact for the motion that stands still, and no
  // intersecting triangles.
  exactccd::SceneOptions still;
  still.max_threads = s.threads;
  const std::size_t start_contacts = scene.find_contacts(still).contacts.size();
  const std::size_t start_intersections =
      exactccd::intersecting_triangle_pairs(scene, 0.0, true).size();
  if (start_contacts != 0 || start_intersections != 0) {
    std::fprintf(stderr, "exactccd_cloth: the start state is not contact-free (%zu contacts, %zu "
                         "intersecting triangle pairs)\n", start_contacts, start_intersections);
    return 2;
  }

  const fs::path out_dir(s.out);
  std::vector<std::pair<int, std::string>> frames;  // (step, file)
  if (!s.check_only) {
    fs::create_directories(out_dir / "frames");
    for (const auto& entry : fs::directory_iterator(out_dir / "frames"))
      if (entry.path().extension() == ".f64") fs::remove(entry.path());
  }
  auto save_frame = [&](int step) {
    if (s.check_only) return;
    if (!frames.empty() && frames.back().first == step) return;
    char name[32];
    std::snprintf(name, sizeof name, "step_%04d.f64", step);
    write_frame(out_dir / "frames" / name, cloth.x);
    frames.emplace_back(step, std::string("frames/") + name);
  };
  save_frame(0);

  const bool record = !s.check_only && s.query_every > 0 && s.max_queries > 0;
  const int sampled_steps = record ? s.steps / s.query_every : 0;
  const std::size_t budget_per_step =
      sampled_steps > 0 ? s.max_queries * 4 / 5 / static_cast<std::size_t>(sampled_steps) : 0;
  std::optional<exactccd::scenes::QueryCsvWriter> writer;
  if (record) writer.emplace((out_dir).string());
  exactccd::scenes::QueryBatch queries;  // totals over the batches (one per sampled step)
  std::size_t query_files = 0;

  std::vector<StepStats> stats;
  int first_contact_step = -1, first_self_contact_step = -1;
  for (int step = 1; step <= s.steps; ++step) {
    const bool sample = record && step % s.query_every == 0 &&
                        queries.vertex_face + queries.edge_edge < s.max_queries;
    StepStats st =
        advance(scene, cloth_id, cloth, s, sample ? &*writer : nullptr, budget_per_step);
    if (sample) {
      const exactccd::scenes::QueryBatch batch = writer->flush();
      queries.vertex_face += batch.vertex_face;
      queries.edge_edge += batch.edge_edge;
      queries.vertex_face_colliding += batch.vertex_face_colliding;
      queries.edge_edge_colliding += batch.edge_edge_colliding;
      query_files = batch.index + 1;
    }
    st.step = step;
    stats.push_back(st);
    const bool contact = st.obstacle_contacts + st.self_contacts > 0;
    if (contact && first_contact_step < 0) first_contact_step = step;
    if (st.self_contacts > 0 && first_self_contact_step < 0) first_self_contact_step = step;
    if ((s.frame_every > 0 && step % s.frame_every == 0) || step == first_contact_step ||
        step == first_self_contact_step || step == s.steps)
      save_frame(step);
    if (!s.check_only && (step % 10 == 0 || step == s.steps))
      std::fprintf(stderr, "step %d/%d: %zu contacts, %d rounds, CCD %.0f ms\n", step, s.steps,
                   st.obstacle_contacts + st.self_contacts, st.rounds, st.ccd_ms);
  }
  const double run_seconds = ms_since(run_start) / 1000.0;

  // Totals.
  std::size_t total_obstacle = 0, total_self = 0, total_vf = 0, total_ee = 0, violations = 0,
              frozen = 0, steps_with_contact = 0, max_pinned = 0;
  int max_rounds = 0;
  std::size_t unresolved = 0;
  std::vector<double> ccd_ms, check_ms;
  for (const StepStats& st : stats) {
    total_obstacle += st.obstacle_contacts;
    total_self += st.self_contacts;
    total_vf += st.vertex_face_contacts;
    total_ee += st.edge_edge_contacts;
    violations += st.violations;
    frozen += st.frozen;
    steps_with_contact += st.rounds > 0;
    max_pinned = std::max(max_pinned, st.pinned);
    max_rounds = std::max(max_rounds, st.rounds);
    unresolved += st.unresolved_normals;
    ccd_ms.push_back(st.ccd_ms);
    check_ms.push_back(st.check_ms);
  }

  const std::size_t vertices = static_cast<std::size_t>(cloth.x.rows());
  const std::size_t triangles = static_cast<std::size_t>(scene.triangles(cloth_id).rows());
  std::printf("exactccd_cloth: %d x %d cloth (%zu vertices, %zu triangles) dropped on a spike "
              "and a wedge\n", s.n, s.n, vertices, triangles);
  std::printf("  integrator     position-based dynamics, %d sweeps, dt = %.4g s, %d steps "
              "(%.2f s)\n", s.iterations, s.dt, s.steps, s.steps * s.dt);
  std::printf("  response       stop each contact vertex at %.2g of the way to its conservative "
              "TOI, pin it at its\n                 start if hit again; remove its velocity along "
              "the contact normals (pinned: all)\n", s.stop_fraction);
  if (s.normal_at_start)
    std::printf("  normals        at the step's start (--normal-at-start)\n");
  else
    std::printf("  normals        certified, at the time of impact (contact_geometry); %zu "
                "unresolved, taken at the step's start\n", unresolved);
  std::printf("  contacts       %zu (%zu cloth-obstacle, %zu cloth-cloth; %zu vertex-face, %zu "
              "edge-edge) in %zu of %d steps\n", total_obstacle + total_self, total_obstacle,
              total_self, total_vf, total_ee, steps_with_contact, s.steps);
  std::printf("  rounds         at most %d per step; frozen steps %zu; at most %zu vertices "
              "pinned in a step\n", max_rounds, frozen, max_pinned);
  std::printf("  time per step  CCD %.1f ms (median; all rounds), intersection check %.1f ms "
              "(median)\n", median(ccd_ms), median(check_ms));
  std::printf("  violations     %zu intersecting triangle pairs after %d steps (exact test of "
              "every pair)\n", violations, s.steps);
  if (record)
    std::printf("  queries        %zu vertex-face (%zu colliding), %zu edge-edge (%zu colliding) "
                "from every %d-th step\n", queries.vertex_face, queries.vertex_face_colliding,
                queries.edge_edge, queries.edge_edge_colliding, s.query_every);
  std::printf("  run time       %.1f s\n", run_seconds);

  if (!s.check_only) {
    nlohmann::json j;
    j["scene"] = "cloth";
    j["settings"] = {{"n", s.n},
                     {"steps", s.steps},
                     {"dt", s.dt},
                     {"iterations", s.iterations},
                     {"bend_stiffness", s.bend_stiffness},
                     {"damping", s.damping},
                     {"tilt_degrees", s.tilt_degrees},
                     {"max_rounds", s.max_rounds},
                     {"stop_fraction", s.stop_fraction},
                     {"normals", s.normal_at_start ? "at the step's start" : "certified, at t*"},
                     {"gravity", kGravity},
                     {"floor_z", kFloorZ}};
    j["response"] =
        "stop each contact vertex at stop_fraction of the way to its position at the smallest "
        "conservative TOI (toi_lo) of its contacts; pin it at its start if it is in a contact "
        "again in a later round of the step; repeat until the exact CCD finds no contact; "
        "velocity (x_end - x)/dt with its components along the contact normals removed "
        "(pinned vertices: zero); the normals are the certified contact normals at the exact "
        "time of impact (contact_geometry), or at the step's start where unresolved or with "
        "--normal-at-start";
    j["cloth"] = {{"n", s.n}, {"vertices", vertices}, {"triangles", triangles},
                  {"frame_format", "little-endian float64, row-major (vertices x 3)"},
                  {"triangles_list", mesh_json(cloth_start)["triangles"]}};
    j["obstacles"] = {{"floor", mesh_json(floor)},
                      {"spike", mesh_json(spike)},
                      {"wedge", mesh_json(wedge)}};
    nlohmann::json per_step = nlohmann::json::array();
    for (const StepStats& st : stats)
      per_step.push_back({{"step", st.step},
                          {"rounds", st.rounds},
                          {"frozen", st.frozen},
                          {"obstacle_contacts", st.obstacle_contacts},
                          {"self_contacts", st.self_contacts},
                          {"vertex_face_contacts", st.vertex_face_contacts},
                          {"edge_edge_contacts", st.edge_edge_contacts},
                          {"contacts_all_rounds", st.contacts_all_rounds},
                          {"unresolved_normals", st.unresolved_normals},
                          {"stopped", st.stopped},
                          {"pinned", st.pinned},
                          {"candidates", st.candidates},
                          {"ccd_ms", st.ccd_ms},
                          {"check_ms", st.check_ms},
                          {"violations", st.violations},
                          {"lowest_z", st.lowest_z},
                          {"mean_speed", st.mean_speed}});
    j["steps"] = per_step;
    nlohmann::json frame_list = nlohmann::json::array();
    for (const auto& [step, file] : frames) frame_list.push_back({{"step", step}, {"file", file}});
    j["frames"] = frame_list;
    j["events"] = {{"first_contact_step", first_contact_step},
                   {"first_self_contact_step", first_self_contact_step}};
    j["totals"] = {{"contacts", total_obstacle + total_self},
                   {"obstacle_contacts", total_obstacle},
                   {"self_contacts", total_self},
                   {"vertex_face_contacts", total_vf},
                   {"edge_edge_contacts", total_ee},
                   {"max_rounds", max_rounds},
                   {"unresolved_normals", unresolved},
                   {"frozen_steps", frozen},
                   {"ccd_ms_median", median(ccd_ms)},
                   {"check_ms_median", median(check_ms)},
                   {"violations", violations},
                   {"run_seconds", run_seconds}};
    if (record) {
      j["queries"] = {
          {"every", s.query_every},
          {"files", "queries/{vertex-face,edge-edge}/data_K.csv, K = 0 .. " +
                        std::to_string(query_files) + " - 1: one per sampled step"},
          {"vertex_face", queries.vertex_face},
          {"vertex_face_collisions", queries.vertex_face_colliding},
          {"edge_edge", queries.edge_edge},
          {"edge_edge_collisions", queries.edge_edge_colliding},
          {"selection", "per sampled step: fixed-stride samples of the first round's colliding "
                        "and other candidates (colliding up to half of the step's share); later "
                        "rounds add only the pairs with a vertex the previous round moved"}};
    }
    std::ofstream(out_dir / "summary.json") << j.dump(1) << '\n';
    std::printf("  output         %s (summary.json, %zu frames%s)\n", out_dir.string().c_str(),
                frames.size(), record ? ", queries/" : "");
  }
  if (violations != 0) {
    std::fprintf(stderr, "exactccd_cloth: %zu intersecting triangle pairs\n", violations);
    return 1;
  }
  if (s.check_only && (total_obstacle == 0 || total_self == 0)) {
    std::fprintf(stderr, "exactccd_cloth: the run did not exercise the response (%zu "
                         "cloth-obstacle, %zu cloth-cloth contacts)\n", total_obstacle,
                 total_self);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Settings s;
  CLI::App app{"exactccd_cloth: a cloth dropped with large time steps on a spike and a wedge; "
               "certified free of intersections by exact CCD, checked by an exact "
               "triangle-triangle test every step"};
  app.add_option("--n", s.n, "vertices per side of the cloth")->check(CLI::Range(4, 2000));
  app.add_option("--steps", s.steps, "time steps")->check(CLI::Range(1, 100000));
  app.add_option("--dt", s.dt, "time step (s)")->check(CLI::Range(1e-6, 1.0));
  app.add_option("--iterations", s.iterations, "constraint sweeps per step")
      ->check(CLI::Range(1, 10000));
  app.add_option("--bend", s.bend_stiffness, "bending stiffness (0..1)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--tilt", s.tilt_degrees, "tilt of the cloth at the start (degrees)")
      ->check(CLI::Range(0.0, 90.0));
  app.add_option("--damping", s.damping, "fraction of velocity lost per step")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--stop-fraction", s.stop_fraction,
                 "a stopped vertex goes this fraction of the way to its TOI")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-rounds", s.max_rounds, "response rounds before the cloth is frozen")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--query-every", s.query_every, "write the queries of every k-th step (0: none)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--max-queries", s.max_queries,
                 "about this many queries written in all (both types)");
  app.add_option("--frame-every", s.frame_every, "save the cloth every k-th step (0: events only)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--threads", s.threads, "CCD threads (0: all)")->check(CLI::NonNegativeNumber);
  app.add_option("--out", s.out, "output folder");
  app.add_flag("--normal-at-start", s.normal_at_start,
               "respond along the contact normals at the step's start (the old rule), not along "
               "the certified normals at the time of impact");
  bool check_only = false;
  app.add_flag("--check-only", check_only,
               "short run (20 x 20 cloth, 40 steps unless given) writing nothing; exit status 0 "
               "iff the cloth touched the obstacles and itself and no triangles intersect");
  CLI11_PARSE(app, argc, argv);
  if (check_only) {
    s.check_only = true;
    if (app.count("--n") == 0) s.n = 20;
    if (app.count("--steps") == 0) s.steps = 40;
  }
  try {
    return run(s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exactccd_cloth: %s\n", e.what());
    return 3;
  }
}
