/// \file
/// Scene-level CCD: whole triangle meshes over one time step.
///
/// A simulator hands over its meshes once (topology and positions) and then, each step, the
/// positions at the start and at the end of the step. `Scene::find_contacts` returns every
/// colliding vertex-face and edge-edge pair with its certified TOI interval; `earliest_contact`
/// returns only the first contact of the step and stops work that cannot lower it.
///
/// What is modelled: a moving mesh has positions at both ends of the step; a static mesh has one
/// set of positions and is never refitted; pairs between two static meshes are never tested; pairs
/// within one mesh (self-collision) that share a vertex are never candidates. Each vertex moves on
/// a straight line, exactly as in `vertex_face_ccd` / `edge_edge_ccd`, which decide every pair
/// (so the scene's answers are exact in the default mode).
///
/// Broad phase: a bounding volume hierarchy over the swept boxes of the primitives (the box of a
/// primitive's start and end positions), refitted every step and rebuilt only when it degrades
/// (Bridson et al. 2002; Redon et al. 2002). Boxes come from comparisons of the input doubles
/// only, so culling never drops a colliding pair. With a minimum separation delta
/// (SceneOptions::min_separation) every box's upper corner is raised by delta, rounded upwards,
/// so culling never drops a pair that comes within delta either. PROOF: proofs/scene.md
///
/// Rigid bodies (\ref rigid "rigid-body CCD"): `add_rigid_body` adds a mesh that moves as one
/// rigid body with the RigidMotion of `set_rigid_motion` (pivot, translation, Cayley vector) over
/// the step's parameter s in [0, 1]; the other meshes move as before, each vertex on a straight
/// line in s (static meshes stand still). Every pair involving a rigid body (rigid-rigid,
/// rigid-deformable, rigid-static; never two primitives of one rigid body, which cannot
/// collide with itself) is decided by the rigid vertex_face_ccd / edge_edge_ccd of rigid.hpp,
/// so its TOI is in s; pairs without a rigid body take exactly today's path. Their swept boxes
/// are certified interval enclosures of the vertices' arcs over pieces of [0, 1], raised by the
/// minimum separation as every box is, so SceneOptions::min_separation works with rigid bodies
/// too (each rigid pair decided with CcdOptions::min_separation = delta); with Mode::float_only
/// their pairs get the rigid functions' uncertified float_only test (for comparison only), the
/// others the linear one.
/// PROOF: proofs/scene.md (section 9, rigid bodies)
///
/// Codimensional scenes (\ref scene_kinds "kinds of meshes"): `add_edge_mesh` adds a mesh of
/// edges only (rods, hair, seams), `add_points` a point set (particles), `add_plane` an
/// infinite plane that never moves (a floor). Their pairs are the pairs of the primitives
/// present: every vertex against every triangle (vertex-face), every edge against every edge
/// (edge-edge), a point (a vertex of an edge mesh or point set on none of its edges) against
/// every edge (point-edge) and every other point (point-point), every vertex of a moving mesh
/// against every plane (point-plane). A pair of closed primitives that first comes within
/// delta at time t from apart at t = 0 holds a pair of these kinds that does so at t
/// (proofs/scene.md, section 10). A 2D scene (`Scene(SceneDimension::two)`) holds edge
/// meshes and point sets in the plane z = 0; its pairs are point-edge (every vertex against
/// every edge it is not on) and point-point, decided as point_edge_ccd_2d / point_point_ccd_2d.
///
/// Threads: the narrow phase runs in parallel (TBB); the results do not depend on the number of
/// threads. One Scene must not be used from two threads at once; distinct Scenes are independent.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "exactccd/contact.hpp"
#include "exactccd/export.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// A mesh's number in its Scene: 0, 1, ... in the order of add_mesh / add_static_mesh /
/// add_rigid_body.
using MeshId = std::uint32_t;

/// The space a scene lives in.
enum class SceneDimension : std::uint8_t {
  three,  ///< 3D: every kind of mesh
  two,    ///< the plane z = 0: edge meshes and point sets only (point-edge, point-point pairs)
};

/// Vertex positions, one row (x, y, z) per vertex.
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Triangles, one row of three vertex indices per triangle.
using Triangles = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Edges, one row (i, j) with i < j per distinct triangle side, sorted.
using Edges = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// How candidate pairs are found.
enum class BroadPhase : std::uint8_t {
  /// The default: a hierarchy over swept boxes. Never drops a colliding pair.
  swept_bvh,
  /// For comparison only, the older scheme (Eckstein and Schoemer 1999; Lennerz et al. 1999):
  /// hierarchies over the positions at the start and at the end of the step; a pair is a
  /// candidate only when its boxes overlap at one of the two instants. It misses contacts in
  /// between (a thin object passed through within the step).
  static_bvh,
};

/// The broad phase's name. Never throws.
/// \param broad_phase a broad phase.
/// \return "swept_bvh" or "static_bvh" (a static string).
EXACTCCD_API const char* to_string(BroadPhase broad_phase) noexcept;

/// The most threads a call may ask for (SceneOptions::max_threads, Python's `threads`): TBB's
/// task arenas fail beyond it (a crash, not an error), so a larger request is refused.
constexpr int kMaxThreads = 65536;

/// Options of Scene::find_contacts and Scene::earliest_contact.
struct SceneOptions {
  /// Options of each pair's test (t_max, toi_width, mode), as in vertex_face_ccd; invalid ones
  /// throw std::invalid_argument. With a rigid body in the scene, t_max bounds the motion
  /// parameter s, and Mode::float_only runs the rigid pairs' uncertified float_only test
  /// (rigid.hpp). The scene's minimum separation is given once, as SceneOptions::min_separation
  /// below: ccd.min_separation must be left at 0 (the scene sets it to min_separation for every
  /// pair), else std::invalid_argument.
  CcdOptions ccd;
  /// Minimum separation delta >= 0 (\ref min_separation "minimum-separation CCD"): a pair is a
  /// contact when its closed primitives come within Euclidean distance delta, with the earliest
  /// such time as its TOI, exactly as vertex_face_ccd / edge_edge_ccd decide it with
  /// CcdOptions::min_separation = delta; the broad phase keeps every such pair. 0 (the default)
  /// is contact itself, the same answers as without this field. The only place to give the
  /// scene's delta (ccd.min_separation must stay 0). Must be finite and >= 0. With a rigid body
  /// in the scene its pairs are decided by the rigid functions with the same delta (the TOI in
  /// the motion parameter s), and the broad phase keeps every pair that comes within delta.
  double min_separation = 0.0;
  /// The broad phase (swept_bvh, the default, never drops a colliding pair).
  BroadPhase broad_phase = BroadPhase::swept_bvh;
  /// Test pairs within each moving mesh (pairs sharing a vertex excluded).
  bool self_collision = true;
  /// At most this many threads for the narrow phase; 0: TBB's default. Must be in
  /// [0, kMaxThreads].
  int max_threads = 0;
  /// Also return the candidate pairs (SceneResult::candidates), e.g. to write them as queries.
  bool record_candidates = false;
  /// Cut pairs of linearly moving or static meshes whose boxes, blended between t = 0 and
  /// t = 1, cannot overlap by t_max (SceneStats::time_culled). Never changes an answer; false
  /// only to measure what it saves.
  bool cull_by_time = true;
};

/// A pair of primitives of the scene.
///  vertex-face: vertex `first_index` of mesh `first_mesh`, triangle `second_index` of
///               `second_mesh` (the meshes may be equal: self-collision);
///  edge-edge:   edge `first_index` of `first_mesh` (an index into Scene::edges), edge
///               `second_index` of `second_mesh`, with (first_mesh, first_index) <
///               (second_mesh, second_index);
///  point-edge:  vertex `first_index` of `first_mesh`, edge `second_index` of `second_mesh`;
///  point-point: vertex `first_index` of `first_mesh`, vertex `second_index` of `second_mesh`,
///               with (first_mesh, first_index) < (second_mesh, second_index);
///  point-plane: vertex `first_index` of `first_mesh`, the plane `second_mesh` (added by
///               add_plane; second_index 0).
/// Pairs are ordered by (type, first_mesh, first_index, second_mesh, second_index), in the
/// order of QueryType (vertex-face first).
struct ScenePair {
  QueryType type = QueryType::vertex_face;  ///< the kind of the pair
  MeshId first_mesh = 0;                    ///< the mesh of the vertex, or of the first edge
  std::uint32_t first_index = 0;            ///< the vertex, or the first edge (Scene::edges)
  MeshId second_mesh = 0;  ///< the mesh of the triangle, edge or second point, or the plane
  std::uint32_t second_index = 0;  ///< the triangle, edge or second point (0 for a plane)

  /// Equal pairs: every field equal.

  friend bool operator==(const ScenePair& a, const ScenePair& b) {
    return a.type == b.type && a.first_mesh == b.first_mesh && a.first_index == b.first_index &&
           a.second_mesh == b.second_mesh && a.second_index == b.second_index;
  }
  /// The pair order: (type, first_mesh, first_index, second_mesh, second_index).
  friend EXACTCCD_API bool operator<(const ScenePair& a, const ScenePair& b);
};

/// A colliding pair and its certified TOI interval, exactly as the pair's CCD test returns it.
/// Default-constructed (no contact): +infinity TOIs (\ref no_contact_toi).
///
/// The TOI is in the step's parameter s, along which every deformable vertex moves on its
/// straight line and every rigid body with its RigidMotion: for a pair without a rigid body that
/// is the time t of the step, for a pair involving a rigid body the motion parameter s of
/// rigid.hpp. The time fields give the contact in time where it is defined.
struct SceneContact {
  ScenePair pair;                  ///< the pair of primitives
  double toi_lo = kNoContactToi;   ///< the pair's CcdResult::toi_lo (in s)
  double toi_hi = kNoContactToi;   ///< the pair's CcdResult::toi_hi (in s)
  /// Whether time_lo / time_hi enclose the contact time: always for a pair without a rigid body
  /// (time = s), and RigidCcdResult::has_time for a pair involving one (pure rotations of one
  /// common rate, or no rotation).
  bool has_time = false;
  /// The pair already meets (is within SceneOptions::min_separation) at the start of the step:
  /// its CcdResult::starts_within, exact. (Beside has_time: the struct stays 64 bytes.)
  bool starts_within = false;
  double time_lo = kNoContactToi;  ///< lower end of the contact time (see has_time)
  double time_hi = kNoContactToi;  ///< upper end of the contact time (see has_time)
};

/// Work counts of one call (for statistics and benchmarks).
struct SceneStats {
  /// Pairs whose boxes overlap (the narrow phase's input; boxes raised by min_separation), per
  /// type; for earliest_contact, those its traversal reached before its bound cut the rest.
  std::uint64_t vertex_face_candidates = 0;
  /// Edge-edge pairs whose boxes overlap.
  std::uint64_t edge_edge_candidates = 0;
  /// Point-edge, point-point and point-plane pairs that reached the narrow phase (a point's
  /// box overlaps the other's, or its path may come within delta of the plane).
  std::uint64_t point_candidates = 0;
  /// Pairs the narrow phase decided (earliest_contact skips pairs that cannot lower the bound).
  std::uint64_t narrow_phase_tests = 0;
  /// Hierarchies built from scratch (first use or degradation) during the call.
  std::uint32_t hierarchies_built = 0;
  /// Hierarchies refitted during the call.
  std::uint32_t hierarchies_refitted = 0;
  /// Cuts by the cylinder ranges (both sides turn about one line, or slide along it, or rest;
  /// proofs/scene.md, section 9.3) during the hierarchies' traversal: pairs of nodes whose boxes
  /// overlap but whose ranges are apart (each cut once, whatever it holds) and pairs of
  /// primitives the same. Their pairs are not candidates, never tested. 0 in scenes without
  /// rigid bodies. With BroadPhase::static_bvh, counted per span.
  std::uint64_t cylinder_culled = 0;
  /// Cuts by time (BroadPhase::swept_bvh, pairs of linearly moving or static meshes;
  /// proofs/scene.md, section 5a): pairs of nodes, and pairs of primitives, whose boxes over the
  /// step overlap but whose boxes blended between t = 0 and t = 1 cannot overlap at any time in
  /// [0, t_max] (for earliest_contact: in [0, T] for its bound T as it falls; each cut once).
  /// Their pairs are not candidates, never tested.
  std::uint64_t time_culled = 0;
};

/// The answer of Scene::find_contacts.
struct SceneResult {
  /// Every colliding pair, in ScenePair order.
  std::vector<SceneContact> contacts;
  /// The earliest contact: the smallest toi_lo, ties broken by ScenePair order. Without
  /// contacts, a default SceneContact (+infinity TOIs).
  SceneContact earliest;
  /// Every candidate pair in ScenePair order, when SceneOptions::record_candidates.
  std::vector<ScenePair> candidates;
  SceneStats stats;  ///< work counts of the call
};

/// The answer of Scene::earliest_contact.
struct EarliestContact {
  /// True iff some pair collides (find_contacts would return contacts).
  bool collides = false;
  /// Exactly SceneResult::earliest of find_contacts with the same options (+infinity TOIs
  /// without contact).
  SceneContact contact;
  SceneStats stats;  ///< work counts of the call
};

/// Meshes and their motion over one time step, with the state kept between steps (the
/// hierarchies). Movable, not copyable.
class EXACTCCD_API Scene {
 public:
  /// An empty 3D scene.
  Scene();
  /// An empty scene in the given space (SceneDimension::two: the plane z = 0).
  /// \param dimension three or two.
  explicit Scene(SceneDimension dimension);
  /// Frees the meshes and hierarchies.
  ~Scene();
  /// Takes the other scene's meshes; the other is left empty.
  Scene(Scene&&) noexcept;
  /// Takes the other scene's meshes; the other is left empty.
  /// \return this scene.
  Scene& operator=(Scene&&) noexcept;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// A moving mesh, at rest at `positions` until set_motion. Throws std::invalid_argument for
  /// non-finite coordinates, indices out of range, or a triangle repeating a vertex.
  /// \param positions the vertices, finite.
  /// \param triangles indices into `positions`, three distinct per row.
  /// \return the new mesh's id.
  /// \throws std::invalid_argument as above.
  MeshId add_mesh(const Positions& positions, const Triangles& triangles);
  /// A static mesh: one set of positions for every step.
  /// \param positions the vertices, finite.
  /// \param triangles indices into `positions`, three distinct per row.
  /// \return the new mesh's id.
  /// \throws std::invalid_argument as add_mesh.
  MeshId add_static_mesh(const Positions& positions, const Triangles& triangles);
  /// A rigid body: a mesh that moves as one rigid body, at rest at `positions` (its pose at
  /// s = 0, world coordinates) until set_rigid_motion. Never paired with itself. Throws
  /// std::invalid_argument as add_mesh.
  /// \param positions the vertices at s = 0, finite.
  /// \param triangles indices into `positions`, three distinct per row.
  /// \return the new mesh's id.
  /// \throws std::invalid_argument as add_mesh.
  MeshId add_rigid_body(const Positions& positions, const Triangles& triangles);
  /// The step's motion of a rigid body: vertex i is at position_at(motion, x_i, s) for s in
  /// [0, 1], x_i its position given to add_rigid_body (exactly, as rigid.hpp's queries).
  /// \param body a rigid body of this scene.
  /// \param motion finite pivot, translation and Cayley vector (every double used exactly).
  /// \throws std::invalid_argument for an unknown id, a mesh that is not a rigid body, or a
  ///         non-finite field.
  void set_rigid_motion(MeshId body, const RigidMotion& motion);
  /// The step's motion of a rigid body from new positions: its vertices are at `start` at
  /// s = 0 (e.g. the pose the previous step ended in, rounded to doubles) and move with
  /// `motion`. Later calls of the other overload keep these positions.
  /// \param body a rigid body of this scene.
  /// \param start the vertices at s = 0, one finite row per vertex (a rigid body stays rigid
  ///        only when `start` is congruent to its earlier positions; that is not checked).
  /// \param motion finite pivot, translation and Cayley vector.
  /// \throws std::invalid_argument as the other overload, or for a wrong row count or
  ///         non-finite positions.
  void set_rigid_motion(MeshId body, const Positions& start, const RigidMotion& motion);
  /// The step's motion of a moving mesh: every vertex from start.row(i) to end.row(i). Throws
  /// std::invalid_argument for a static mesh or a rigid body, a wrong row count or non-finite
  /// coordinates.
  /// \param mesh a moving mesh of this scene.
  /// \param start positions at the start of the step, one row per vertex.
  /// \param end positions at the end of the step, one row per vertex.
  /// \throws std::invalid_argument as above, or for an unknown mesh.
  void set_motion(MeshId mesh, const Positions& start, const Positions& end);
  /// A moving mesh of edges only (rods, hair, seams; in a 2D scene, polylines), at rest at
  /// `positions` until set_motion. Scene::edges(mesh) is `edges` as given (the numbering of its
  /// pairs). Its vertices on no edge are points (point-edge, point-point pairs). In a 2D scene
  /// every z coordinate must be 0.
  /// \param positions the vertices, finite.
  /// \param edges one row per edge, two distinct vertex indices, no edge twice.
  /// \return the new mesh's id.
  /// \throws std::invalid_argument for non-finite coordinates, an index out of range, an edge
  ///         repeating a vertex or given twice, or (2D) a non-zero z.
  MeshId add_edge_mesh(const Positions& positions, const Edges& edges);
  /// A static mesh of edges only: one set of positions for every step (walls of a 2D scene).
  /// \param positions the vertices, finite.
  /// \param edges as add_edge_mesh.
  /// \return the new mesh's id.
  /// \throws std::invalid_argument as add_edge_mesh.
  MeshId add_static_edge_mesh(const Positions& positions, const Edges& edges);
  /// A moving point set (particles), at rest at `positions` until set_motion: every vertex is
  /// a point. In a 2D scene every z coordinate must be 0.
  /// \param positions the points, finite.
  /// \return the new mesh's id.
  /// \throws std::invalid_argument for non-finite coordinates or (2D) a non-zero z.
  MeshId add_points(const Positions& positions);
  /// An infinite plane that never moves, {x : (x - origin) . normal = 0} (the usual floor): a
  /// mesh of no vertices, paired with every vertex of every moving (not static) mesh, decided
  /// as point_plane_ccd. A vertex whose path stays more than delta to one side is cut by one
  /// certified test per vertex, with no cost per triangle. 3D scenes only. A rigid body's
  /// vertices meet it by the rigid point_plane_ccd (rigid.hpp), each cut first by its
  /// certified box over the step.
  /// \param origin a point of the plane, finite.
  /// \param normal its normal (any non-zero finite length).
  /// \return the plane's mesh id (the second_mesh of its pairs).
  /// \throws std::invalid_argument for a non-finite value, a zero normal, or a 2D scene.
  MeshId add_plane(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal);

  /// The simulator's own numbering of a mesh's edges: `edges` must hold every side of the
  /// mesh's triangles exactly once, in any order and either orientation (libigl's `edges`, for
  /// one, sorts by (j, i)); from then on Scene::edges(mesh) is `edges` as given, and every
  /// edge-edge ScenePair of the mesh indexes into it. The default numbering (sorted (i, j),
  /// i < j) stays until this is called. Clears the mesh's hierarchies (rebuilt on next use).
  /// \param mesh a mesh of this scene.
  /// \param edges one row per edge, two vertex indices.
  /// \throws std::invalid_argument for an unknown mesh, an index out of range, a repeated
  ///         vertex, an edge that is no side of a triangle, an edge given twice, or a side
  ///         missing (the message names the row or the side).
  void set_edges(MeshId mesh, const Edges& edges);

  /// \return the number of meshes added (planes included).
  std::size_t mesh_count() const;
  /// \return the scene's space.
  SceneDimension dimension() const;
  /// Whether `mesh` was added by add_plane. Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return true for a plane.
  bool is_plane(MeshId mesh) const;
  /// A plane's origin and normal as given. Throws std::invalid_argument for another mesh.
  /// \param plane a plane of this scene.
  /// \return {origin, normal}.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> plane(MeshId plane) const;
  /// Whether `mesh` was added by add_static_mesh. Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return true for a static mesh.
  bool is_static(MeshId mesh) const;
  /// Whether `mesh` was added by add_rigid_body. Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return true for a rigid body.
  bool is_rigid(MeshId mesh) const;
  /// A rigid body's motion (the zero motion until set_rigid_motion). Throws
  /// std::invalid_argument for a mesh that is not a rigid body.
  /// \param body a rigid body of this scene.
  /// \return its motion.
  const RigidMotion& rigid_motion(MeshId body) const;
  /// The mesh's triangles. Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return the triangles as given.
  const Triangles& triangles(MeshId mesh) const;
  /// The mesh's edges (the indices of edge-edge pairs). Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return the distinct triangle sides, sorted.
  const Edges& edges(MeshId mesh) const;
  /// The positions at the start of the step (s = 0). Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return one row per vertex.
  const Positions& start_positions(MeshId mesh) const;
  /// The positions at the end of the step; equal to start_positions for a static mesh. For a
  /// rigid body, position_at(motion, x, 1) rounded to doubles: for display only (the scene
  /// decides with the exact motion). Precondition: mesh < mesh_count().
  /// \param mesh a mesh of this scene.
  /// \return one row per vertex.
  const Positions& end_positions(MeshId mesh) const;

  /// Every colliding pair of the step.
  /// \param options the pairs' test options and the broad phase.
  /// \return the contacts in pair order, the earliest, the statistics.
  /// \throws std::invalid_argument for bad options (see CcdOptions, SceneOptions).
  SceneResult find_contacts(const SceneOptions& options = {});
  /// Only the earliest contact of the step; stops work that cannot lower it.
  /// \param options as find_contacts; the broad phase must be swept_bvh.
  /// \return exactly find_contacts(options).earliest, and whether there is a contact.
  /// \throws std::invalid_argument for bad options or another broad phase.
  EarliestContact earliest_contact(const SceneOptions& options = {});

  /// The pair's query, rows as in the benchmark (start positions, then end positions).
  /// Precondition: a vertex-face pair of this scene without a rigid body (std::invalid_argument
  /// otherwise: its motion is not linear; see rigid_vertex_face_query).
  /// \param pair a vertex-face pair (e.g. from SceneResult::contacts).
  /// \return the query its test decides.
  VertexFaceQuery vertex_face_query(const ScenePair& pair) const;
  /// The pair's query, rows as in the benchmark (start positions, then end positions).
  /// Precondition: an edge-edge pair of this scene without a rigid body (std::invalid_argument
  /// otherwise; see rigid_edge_edge_query).
  /// \param pair an edge-edge pair (e.g. from SceneResult::contacts).
  /// \return the query its test decides.
  EdgeEdgeQuery edge_edge_query(const ScenePair& pair) const;
  /// The pair's query (start positions, then end positions). Precondition: a point-edge pair
  /// of this scene (std::invalid_argument otherwise).
  /// \param pair a point-edge pair.
  /// \return the query its test decides (point_edge_ccd; in 2D, point_edge_ccd_2d's embedding).
  PointEdgeQuery point_edge_query(const ScenePair& pair) const;
  /// The pair's query. Precondition: a point-point pair of this scene.
  /// \param pair a point-point pair.
  /// \return the query its test decides (point_point_ccd).
  PointPointQuery point_point_query(const ScenePair& pair) const;
  /// The pair's query: the vertex's motion against the static plane (origin and normal
  /// repeated at t1). Precondition: a point-plane pair of this scene whose vertex is not a
  /// rigid body's (std::invalid_argument otherwise).
  /// \param pair a point-plane pair.
  /// \return the query its test decides (point_plane_ccd).
  PointPlaneQuery point_plane_query(const ScenePair& pair) const;
  /// A point-plane pair of a rigid body's vertex as the rigid query its test decides.
  /// \param pair a point-plane pair whose first mesh is a rigid body.
  /// \return the query (point_plane_ccd of rigid.hpp).
  /// \throws std::invalid_argument for another pair.
  RigidPointPlaneQuery rigid_point_plane_query(const ScenePair& pair) const;
  /// Any vertex-face pair of this scene as a rigid query: a rigid body's side with its
  /// RigidMotion, a deformable or static mesh's side linear (PathKind::linear, end positions as
  /// set_motion gave them). For a pair involving a rigid body, the query its test decides; for
  /// the others it gives the same answer as vertex_face_query's. Throws std::invalid_argument
  /// for an edge-edge pair or an index out of range.
  /// \param pair a vertex-face pair of this scene.
  /// \return the query.
  RigidVertexFaceQuery rigid_vertex_face_query(const ScenePair& pair) const;
  /// Any edge-edge, point-edge or point-point pair of this scene as a rigid query (as
  /// rigid_vertex_face_query; a point is the zero-length segment [v, v], as point_edge_ccd
  /// decides it).
  /// \param pair an edge-edge, point-edge or point-point pair of this scene.
  /// \return the query.
  RigidEdgeEdgeQuery rigid_edge_edge_query(const ScenePair& pair) const;
  /// The certified contact geometry of a contact of this scene (contact_geometry of its pair's
  /// query, the rigid one when a rigid body takes part, at the contact's enclosure of t*, in s
  /// for rigid pairs; a point-edge or point-point pair as the edge-edge query of its
  /// zero-length segments; a point-plane pair as its point-plane query). `min_separation`: the SceneOptions::min_separation the contact was found
  /// with (the closest points' geometry when > 0).
  /// \param contact a contact of this scene.
  /// \param min_separation the delta of the call that found it (0: contact).
  /// \return the enclosures at t*.
  /// \throws std::invalid_argument for a pair out of range or a negative delta.
  ContactGeometry contact_geometry(const SceneContact& contact,
                                   double min_separation = 0.0) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace exactccd
