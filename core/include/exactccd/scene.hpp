// Scene-level CCD: whole triangle meshes over one time step.
//
// A simulator hands over its meshes once (topology and positions) and then, each step, the
// positions at the start and at the end of the step. `Scene::find_contacts` returns every
// colliding vertex-face and edge-edge pair with its certified TOI interval; `earliest_contact`
// returns only the first contact of the step and stops work that cannot lower it.
//
// What is modelled: a moving mesh has positions at both ends of the step; a static mesh has one
// set of positions and is never refitted; pairs between two static meshes are never tested; pairs
// within one mesh (self-collision) that share a vertex are never candidates. Each vertex moves on
// a straight line, exactly as in `vertex_face_ccd` / `edge_edge_ccd`, which decide every pair
// (so the scene's answers are exact in the default mode).
//
// Broad phase: a bounding volume hierarchy over the swept boxes of the primitives (the box of a
// primitive's start and end positions), refitted every step and rebuilt only when it degrades
// (Bridson et al. 2002; Redon et al. 2002). Boxes come from comparisons of the input doubles
// only, so culling never drops a colliding pair. PROOF: proofs/scene.md
//
// Threads: the narrow phase runs in parallel (TBB); the results do not depend on the number of
// threads. One Scene must not be used from two threads at once; distinct Scenes are independent.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd {

using MeshId = std::uint32_t;

/// Vertex positions, one row (x, y, z) per vertex.
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Triangles, one row of three vertex indices per triangle.
using Triangles = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Edges, one row (i, j) with i < j per distinct triangle side, sorted.
using Edges = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 2, Eigen::RowMajor>;

enum class BroadPhase : std::uint8_t {
  /// The default: a hierarchy over swept boxes. Never drops a colliding pair.
  swept_bvh,
  /// For comparison only, the older scheme (Eckstein and Schoemer 1999; Lennerz et al. 1999):
  /// hierarchies over the positions at the start and at the end of the step; a pair is a
  /// candidate only when its boxes overlap at one of the two instants. It misses contacts in
  /// between (a thin object passed through within the step).
  static_bvh,
};

const char* to_string(BroadPhase broad_phase) noexcept;

struct SceneOptions {
  /// Options of each pair's test (t_max, toi_width, mode), as in vertex_face_ccd.
  CcdOptions ccd;
  BroadPhase broad_phase = BroadPhase::swept_bvh;
  /// Test pairs within each moving mesh (pairs sharing a vertex excluded).
  bool self_collision = true;
  /// At most this many threads for the narrow phase; 0: TBB's default.
  int max_threads = 0;
  /// Also return the candidate pairs (SceneResult::candidates), e.g. to write them as queries.
  bool record_candidates = false;
};

/// A vertex-face or edge-edge pair of primitives of the scene.
///  vertex-face: vertex `first_index` of mesh `first_mesh`, triangle `second_index` of
///               `second_mesh` (the meshes may be equal: self-collision);
///  edge-edge:   edge `first_index` of `first_mesh` (an index into Scene::edges), edge
///               `second_index` of `second_mesh`, with (first_mesh, first_index) <
///               (second_mesh, second_index).
/// Pairs are ordered by (type, first_mesh, first_index, second_mesh, second_index), vertex-face
/// before edge-edge.
struct ScenePair {
  QueryType type = QueryType::vertex_face;
  MeshId first_mesh = 0;
  std::uint32_t first_index = 0;
  MeshId second_mesh = 0;
  std::uint32_t second_index = 0;

  friend bool operator==(const ScenePair& a, const ScenePair& b) {
    return a.type == b.type && a.first_mesh == b.first_mesh && a.first_index == b.first_index &&
           a.second_mesh == b.second_mesh && a.second_index == b.second_index;
  }
  friend bool operator<(const ScenePair& a, const ScenePair& b);
};

/// A colliding pair and its certified TOI interval, exactly as the pair's CCD test returns it.
struct SceneContact {
  ScenePair pair;
  double toi_lo = 0.0;
  double toi_hi = 0.0;
};

struct SceneStats {
  /// Pairs whose boxes overlap (the narrow phase's input), per type.
  std::uint64_t vertex_face_candidates = 0;
  std::uint64_t edge_edge_candidates = 0;
  /// Pairs the narrow phase decided (earliest_contact skips pairs that cannot lower the bound).
  std::uint64_t narrow_phase_tests = 0;
  /// Hierarchies built from scratch (first use or degradation) and refitted during the call.
  std::uint32_t hierarchies_built = 0;
  std::uint32_t hierarchies_refitted = 0;
};

struct SceneResult {
  /// Every colliding pair, in ScenePair order.
  std::vector<SceneContact> contacts;
  /// The earliest contact: the smallest toi_lo, ties broken by ScenePair order. Meaningful only
  /// when !contacts.empty().
  SceneContact earliest;
  /// Every candidate pair in ScenePair order, when SceneOptions::record_candidates.
  std::vector<ScenePair> candidates;
  SceneStats stats;
};

struct EarliestContact {
  bool collides = false;
  /// Exactly SceneResult::earliest of find_contacts with the same options.
  SceneContact contact;
  SceneStats stats;
};

class Scene {
 public:
  Scene();
  ~Scene();
  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// A moving mesh, at rest at `positions` until set_motion. Throws std::invalid_argument for
  /// non-finite coordinates, indices out of range, or a triangle repeating a vertex.
  MeshId add_mesh(const Positions& positions, const Triangles& triangles);
  /// A static mesh: one set of positions for every step.
  MeshId add_static_mesh(const Positions& positions, const Triangles& triangles);
  /// The step's motion of a moving mesh: every vertex from start.row(i) to end.row(i). Throws
  /// std::invalid_argument for a static mesh, a wrong row count or non-finite coordinates.
  void set_motion(MeshId mesh, const Positions& start, const Positions& end);

  std::size_t mesh_count() const;
  bool is_static(MeshId mesh) const;
  const Triangles& triangles(MeshId mesh) const;
  const Edges& edges(MeshId mesh) const;
  const Positions& start_positions(MeshId mesh) const;
  /// Equal to start_positions for a static mesh.
  const Positions& end_positions(MeshId mesh) const;

  /// Every colliding pair of the step. Throws std::invalid_argument for bad options.
  SceneResult find_contacts(const SceneOptions& options = {});
  /// Only the earliest contact of the step (swept_bvh only; throws std::invalid_argument for
  /// another broad phase).
  EarliestContact earliest_contact(const SceneOptions& options = {});

  /// The pair's query, rows as in the benchmark (start positions, then end positions).
  VertexFaceQuery vertex_face_query(const ScenePair& pair) const;
  EdgeEdgeQuery edge_edge_query(const ScenePair& pair) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace exactccd
