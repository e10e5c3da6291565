// Simulation-like CCD queries: the vertex-face and edge-edge pairs a simulator's broad phase
// hands to its narrow phase, from two scenes moving over a number of time steps:
//  (a) a finely tessellated square sheet falling under gravity onto a static tessellated
//      sphere and draping over it (sheet-sphere pairs and sheet self-pairs);
//  (b) two tessellated rigid bodies (a sphere and a box) passing close to each other while
//      translating and rotating (body-body pairs).
// At every step, each pair whose swept bounding boxes overlap (closed boxes: touching counts)
// becomes one query, with the positions at the start and at the end of the step as its rows.
//
// Determinism: the motion uses only IEEE-754 +, -, *, / and sqrt on doubles, in a fixed order
// (no libm transcendental functions: rotations are rational (Cayley) parametrised), and the
// library is built without floating-point contraction, so one config gives bit-identical
// queries on every machine.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "exactccd/rational_query.hpp"

namespace exactccd::sim {

/// Which scene pair a query comes from.
enum class PairKind : std::uint8_t {
  sheet_sphere,  ///< sheet against the static sphere (both directions for vertex-face)
  sheet_self,    ///< sheet against itself, pairs sharing a vertex excluded
  body_body,     ///< rigid sphere against rigid box (both directions for vertex-face)
};

const char* to_string(PairKind kind) noexcept;

struct SimulationQuery {
  QueryType type = QueryType::vertex_face;
  /// Benchmark row order: vertex-face p, a, b, c at the step's start, then at its end;
  /// edge-edge ea0, ea1, eb0, eb1 at the start, then at the end.
  std::array<Eigen::Vector3d, 8> points;
  PairKind kind = PairKind::sheet_sphere;
};

/// The defaults give about 1.2 million queries.
struct SimulationConfig {
  int sheet_resolution = 36;  ///< sheet vertices per side (>= 2): resolution^2 vertices
  int steps = 120;            ///< time steps (>= 1) of both scenes
  std::uint64_t seed = 1;     ///< sheet placement and wrinkles, bodies' initial orientation
};

/// About 50,000 queries, for tests and CI.
SimulationConfig small_simulation_config();

/// Throws std::invalid_argument unless sheet_resolution in [2, 1024] and steps in [1, 100000].
void validate(const SimulationConfig& config);

/// All queries of all steps, step by step (within a step: sheet-sphere, sheet self, then
/// body-body pairs; vertex-face before edge-edge). All coordinates are finite doubles.
std::vector<SimulationQuery> generate_simulation_queries(const SimulationConfig& config);

// ---- The pieces, for tests of the broad phase -----------------------------------------------

/// Connectivity of a triangle mesh; `edges` are the distinct triangle sides, each with its
/// smaller vertex index first.
struct MeshTopology {
  std::size_t vertex_count = 0;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 2>> edges;
};

/// A mesh over one step: each vertex moves linearly from start[i] to end[i].
struct MovingMesh {
  const MeshTopology* topology = nullptr;
  std::vector<Eigen::Vector3d> start, end;
};

/// Two meshes of a step whose primitives are paired (first == second: self-pairs).
struct MeshPair {
  std::size_t first = 0, second = 0;
  PairKind kind = PairKind::sheet_sphere;
};

struct SimulationStep {
  int index = 0;
  std::vector<MovingMesh> meshes;
  std::vector<MeshPair> pairs;
};

/// Runs both scenes and calls `visit` once per step, in order. The step (its meshes'
/// topologies included) is valid only during the call.
void simulate(const SimulationConfig& config,
              const std::function<void(const SimulationStep&)>& visit);

/// Appends the queries of one step: for each mesh pair, every vertex-face pair (vertices of
/// the first mesh against triangles of the second and, for two different meshes, the reverse)
/// and every edge-edge pair whose swept boxes overlap, found with a uniform-grid broad phase.
/// Self-pairs exclude primitives sharing a vertex and list each edge pair once.
void append_step_queries(const SimulationStep& step, std::vector<SimulationQuery>& out);

}  // namespace exactccd::sim
