// Deciding one step of the assembly plan: every candidate pair of the broad phase through the
// per-query rigid CCD functions (exact), and the same step under the chord approximation (each
// key vertex on the straight line between its start and end positions, through the linear
// vertex_face_ccd / edge_edge_ccd) for comparison.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "corpus/assembly/rigid_broad_phase.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::assembly {

/// Which primitives a pair joins: the key's vertex and the lock's face, the lock's vertex and the
/// key's face, or an edge of each.
enum class PairKind : std::uint8_t { key_vertex_lock_face, lock_vertex_key_face, edge_edge };
const char* to_string(PairKind k);

struct PairKey {
  PairKind kind;
  std::int32_t key;   ///< the key's vertex, face or edge
  std::int32_t lock;  ///< the lock's face, vertex or edge
  bool operator<(const PairKey& o) const {
    return kind != o.kind ? kind < o.kind : (key != o.key ? key < o.key : lock < o.lock);
  }
  bool operator==(const PairKey& o) const {
    return kind == o.kind && key == o.key && lock == o.lock;
  }
};

struct PairContact {
  PairKey pair;
  double toi_lo = 0, toi_hi = 0;  ///< s (rigid) or t (chord)
  bool has_time = false;          ///< rigid: the time enclosure below is defined
  double time_lo = 0, time_hi = 0;
};

/// The meshes of a step: the key (moving) and the lock (static), with their edges.
struct StepMeshes {
  const Triangles* key_triangles;
  const Edges* key_edges;
  const Positions* lock_positions;
  const Triangles* lock_triangles;
  const Edges* lock_edges;
};

struct StepDecision {
  std::vector<PairContact> contacts;  ///< sorted by pair
  bool collides = false;
  PairContact earliest;  ///< the contact with the least toi_lo (ties: the least pair)
  std::size_t queries = 0;
  std::size_t decided_by_culling = 0, decided_by_filter = 0, decided_by_exact = 0;
};

/// The contacts of a Scene holding the key (rigid body `key`) and the lock (`lock`), as pairs of
/// the key and the lock (the Scene's edges are unique_edges'); `queries`: its candidates. The
/// decided_by counts are left 0 (the Scene does not report them).
StepDecision from_scene(const SceneResult& result, MeshId key, MeshId lock);

/// Every candidate through the rigid functions (key: `start` and `motion`; lock at rest), in
/// parallel (TBB, as many threads as the caller's arena allows).
StepDecision decide_rigid(const StepMeshes& m, const Positions& start, const RigidMotion& motion,
                          const Candidates& candidates, const CcdOptions& options = {});

/// Every candidate through the linear functions (key vertices from `start` to `end`).
StepDecision decide_linear(const StepMeshes& m, const Positions& start, const Positions& end,
                           const Candidates& candidates, const CcdOptions& options = {});

/// The rigid query of a pair.
RigidVertexFaceQuery rigid_vertex_face(const StepMeshes& m, const Positions& start,
                                       const RigidMotion& motion, const PairKey& p);
RigidEdgeEdgeQuery rigid_edge_edge(const StepMeshes& m, const Positions& start,
                                   const RigidMotion& motion, const PairKey& p);

/// Contacts in `a` whose pair is not in `b`.
std::size_t count_not_in(const std::vector<PairContact>& a, const std::vector<PairContact>& b);

}  // namespace exactccd::assembly
