#include "corpus/simulation_queries.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "corpus/broad_phase.hpp"

namespace exactccd::sim {

namespace {

// ---- Deterministic arithmetic -----------------------------------------------------------------
// Plain structs with every operation written out, so that the order of the IEEE operations is
// fixed by this file alone (no library reduction order, no vectorisation choices).

struct V3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Row-major 3x3 matrix.
struct M3 {
  std::array<double, 9> m{};
  V3 operator*(V3 v) const {
    return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
            m[6] * v.x + m[7] * v.y + m[8] * v.z};
  }
  M3 operator*(const M3& o) const {
    M3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[3 * i + j] =
            m[3 * i] * o.m[j] + m[3 * i + 1] * o.m[3 + j] + m[3 * i + 2] * o.m[6 + j];
    return r;
  }
};

// The rotation with Cayley parameter u (axis u / |u|, angle 2 atan |u|):
// R = ((1 - u.u) I + 2 u u^T + 2 [u]x) / (1 + u.u). Rational in u: no trigonometry.
M3 cayley_rotation(V3 u) {
  const double uu = dot(u, u), s = 1.0 / (1.0 + uu), d = 1.0 - uu;
  M3 r;
  r.m = {s * (d + 2.0 * u.x * u.x),       s * (2.0 * u.x * u.y - 2.0 * u.z),
         s * (2.0 * u.x * u.z + 2.0 * u.y), s * (2.0 * u.y * u.x + 2.0 * u.z),
         s * (d + 2.0 * u.y * u.y),       s * (2.0 * u.y * u.z - 2.0 * u.x),
         s * (2.0 * u.z * u.x - 2.0 * u.y), s * (2.0 * u.z * u.y + 2.0 * u.x),
         s * (d + 2.0 * u.z * u.z)};
  return r;
}

// SplitMix64 (Steele, Lea, Flood 2014): integer-only, so identical everywhere.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1): a 53-bit integer times 2^-53, exact.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }
  /// Uniform in [-1, 1).
  double symmetric() { return 2.0 * uniform() - 1.0; }
};

// Adding +0.0 turns -0.0 into +0.0 (and changes nothing else): the benchmark's fractions have
// no negative zero, so written queries read back bit-identical.
Eigen::Vector3d to_eigen(V3 v) { return {v.x + 0.0, v.y + 0.0, v.z + 0.0}; }

// ---- Meshes -------------------------------------------------------------------------------------

void build_edges(MeshTopology& mesh) {
  mesh.edges.clear();
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      mesh.edges.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(mesh.edges.begin(), mesh.edges.end());
  mesh.edges.erase(std::unique(mesh.edges.begin(), mesh.edges.end()), mesh.edges.end());
}

// The surface of the cube [-n, n]^3 cut into n x n cells per face, 2 triangles per cell, with
// vertices on the even lattice points; `lattice` receives their integer coordinates.
MeshTopology cube_lattice_mesh(int n, std::vector<std::array<int, 3>>& lattice) {
  MeshTopology mesh;
  std::map<std::array<int, 3>, std::uint32_t> index;
  auto vertex = [&](std::array<int, 3> p) {
    const auto [it, inserted] = index.emplace(p, static_cast<std::uint32_t>(lattice.size()));
    if (inserted) lattice.push_back(p);
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {-1, 1}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<std::uint32_t, 4> c;  // cell corners (i,j), (i+1,j), (i+1,j+1), (i,j+1)
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> p;
            p[axis] = side * n;
            p[u] = -n + 2 * (i + di[k]);
            p[v] = -n + 2 * (j + dj[k]);
            c[k] = vertex(p);
          }
          if (side > 0) {  // outward orientation
            mesh.triangles.push_back({c[0], c[1], c[2]});
            mesh.triangles.push_back({c[0], c[2], c[3]});
          } else {
            mesh.triangles.push_back({c[0], c[2], c[1]});
            mesh.triangles.push_back({c[0], c[3], c[2]});
          }
        }
    }
  mesh.vertex_count = lattice.size();
  build_edges(mesh);
  return mesh;
}

// A sphere of `radius` about the origin: the cube lattice pushed radially onto the sphere.
MeshTopology cube_sphere(int n, double radius, std::vector<V3>& points) {
  std::vector<std::array<int, 3>> lattice;
  MeshTopology mesh = cube_lattice_mesh(n, lattice);
  points.clear();
  for (const auto& p : lattice) {
    const V3 q{double(p[0]), double(p[1]), double(p[2])};
    points.push_back((radius / std::sqrt(dot(q, q))) * q);
  }
  return mesh;
}

// A cube of half side `half` about the origin, each face cut into n x n cells.
MeshTopology tessellated_box(int n, double half, std::vector<V3>& points) {
  std::vector<std::array<int, 3>> lattice;
  MeshTopology mesh = cube_lattice_mesh(n, lattice);
  points.clear();
  const double scale = half / n;
  for (const auto& p : lattice) points.push_back({scale * p[0], scale * p[1], scale * p[2]});
  return mesh;
}

// A square grid of r x r vertices (index y * r + x), each cell split along its diagonal
// (x, y) - (x + 1, y + 1).
MeshTopology grid_sheet(int r) {
  MeshTopology mesh;
  mesh.vertex_count = static_cast<std::size_t>(r) * r;
  for (int y = 0; y + 1 < r; ++y)
    for (int x = 0; x + 1 < r; ++x) {
      const std::uint32_t v00 = y * r + x, v10 = v00 + 1, v01 = v00 + r, v11 = v01 + 1;
      mesh.triangles.push_back({v00, v10, v11});
      mesh.triangles.push_back({v00, v11, v01});
    }
  build_edges(mesh);
  return mesh;
}

// ---- Scene (a): a sheet draping over a sphere -------------------------------------------------

constexpr double kSphereRadius = 0.5;
constexpr int kSphereCells = 8;       // per cube face side: 768 triangles
constexpr double kSheetSide = 1.6;    // wider than the sphere, so that it drapes
constexpr double kDropHeight = 0.03;  // initial gap between the sheet and the sphere's top
constexpr double kTimeStep = 0.005;
constexpr double kGravity = -9.81;
constexpr double kDamping = 0.99;     // velocity kept per step (air drag)
constexpr double kStretchStiffness = 0.5;
constexpr int kStretchIterations = 4;

class SheetScene {
 public:
  SheetScene(int resolution, SplitMix64& random) : sheet_(grid_sheet(resolution)) {
    sphere_ = cube_sphere(kSphereCells, kSphereRadius, sphere_points_);
    // Off-centre placement and slight wrinkles (a small fraction of the grid spacing), so that
    // the sheet slides off one side and its self-pairs are not all exactly coplanar.
    const double spacing = kSheetSide / (resolution - 1);
    const double offset_x = 0.1 * random.symmetric(), offset_y = 0.1 * random.symmetric();
    for (int y = 0; y < resolution; ++y)
      for (int x = 0; x < resolution; ++x)
        position_.push_back({offset_x - 0.5 * kSheetSide + spacing * x,
                             offset_y - 0.5 * kSheetSide + spacing * y,
                             kSphereRadius + kDropHeight + 0.02 * spacing * random.symmetric()});
    velocity_.assign(position_.size(), V3{});
    for (const auto& e : sheet_.edges) {
      const V3 d = position_[e[1]] - position_[e[0]];
      rest_length_.push_back(std::sqrt(dot(d, d)));
    }
  }

  const MeshTopology& sheet() const { return sheet_; }
  const MeshTopology& sphere() const { return sphere_; }
  const std::vector<V3>& sheet_positions() const { return position_; }
  const std::vector<V3>& sphere_points() const { return sphere_points_; }

  /// One step: semi-implicit Euler with gravity and drag, stretch limiting along the mesh
  /// edges (Gauss-Seidel in a fixed order: a weak spring keeping the sheet coherent), then
  /// vertices that would end inside the sphere pushed back to its surface, their velocity
  /// into the sphere removed.
  void advance() {
    std::vector<V3> next(position_.size());
    for (std::size_t i = 0; i < position_.size(); ++i) {
      V3& v = velocity_[i];
      v.z = v.z + kTimeStep * kGravity;
      v = kDamping * v;
      next[i] = position_[i] + kTimeStep * v;
    }
    for (int iteration = 0; iteration < kStretchIterations; ++iteration)
      for (std::size_t k = 0; k < sheet_.edges.size(); ++k) {
        V3& a = next[sheet_.edges[k][0]];
        V3& b = next[sheet_.edges[k][1]];
        const V3 d = b - a;
        const double length = std::sqrt(dot(d, d));
        if (!(length > rest_length_[k])) continue;  // cloth resists stretching only
        const V3 correction = (0.5 * kStretchStiffness * (length - rest_length_[k]) / length) * d;
        a = a + correction;
        b = b - correction;
      }
    for (std::size_t i = 0; i < next.size(); ++i) {
      V3& p = next[i];
      V3 v = (1.0 / kTimeStep) * (p - position_[i]);
      const double squared = dot(p, p);  // the sphere is centred at the origin
      if (squared < kSphereRadius * kSphereRadius && squared > 0.0) {
        p = (kSphereRadius / std::sqrt(squared)) * p;
        v = (1.0 / kTimeStep) * (p - position_[i]);
        const double inward = dot(v, p) / dot(p, p);
        if (inward < 0.0) v = v - inward * p;
      }
      velocity_[i] = v;
    }
    position_ = std::move(next);
  }

 private:
  MeshTopology sheet_, sphere_;
  std::vector<V3> sphere_points_, position_, velocity_;
  std::vector<double> rest_length_;
};

// ---- Scene (b): two rigid bodies passing each other --------------------------------------------

constexpr int kBodyCells = 6;           // per cube face side: 432 triangles per body
constexpr double kBodySphereRadius = 0.3;
constexpr double kBodyBoxHalf = 0.25;
constexpr double kBodiesX = 4.0;        // scene (b) lies apart from scene (a)
constexpr double kBodyTravel = 0.35;    // each body travels 2 * kBodyTravel along x
constexpr double kBodiesClosest = 0.42; // y offset of the paths: less than the radii's sum

struct RigidBody {
  MeshTopology mesh;
  std::vector<V3> local;
  M3 rotation, step_rotation;

  std::vector<Eigen::Vector3d> placed(V3 centre) const {
    std::vector<Eigen::Vector3d> out;
    out.reserve(local.size());
    for (const V3& p : local) out.push_back(to_eigen(centre + rotation * p));
    return out;
  }
};

V3 random_cayley_parameter(SplitMix64& random) {
  return {random.symmetric(), random.symmetric(), random.symmetric()};
}

}  // namespace

const char* to_string(PairKind kind) noexcept {
  switch (kind) {
    case PairKind::sheet_sphere: return "sheet_sphere";
    case PairKind::sheet_self: return "sheet_self";
    case PairKind::body_body: return "body_body";
  }
  return "unknown";
}

SimulationConfig small_simulation_config() {
  SimulationConfig config;
  config.sheet_resolution = 12;
  config.steps = 48;
  return config;
}

void validate(const SimulationConfig& config) {
  if (config.sheet_resolution < 2 || config.sheet_resolution > 1024)
    throw std::invalid_argument("simulation: sheet resolution must lie in [2, 1024], got " +
                                std::to_string(config.sheet_resolution));
  if (config.steps < 1 || config.steps > 100000)
    throw std::invalid_argument("simulation: steps must lie in [1, 100000], got " +
                                std::to_string(config.steps));
}

void simulate(const SimulationConfig& config,
              const std::function<void(const SimulationStep&)>& visit) {
  validate(config);
  SplitMix64 random{config.seed};
  SheetScene sheet(config.sheet_resolution, random);

  RigidBody ball, box;
  ball.mesh = cube_sphere(kBodyCells, kBodySphereRadius, ball.local);
  box.mesh = tessellated_box(kBodyCells, kBodyBoxHalf, box.local);
  ball.rotation = cayley_rotation(random_cayley_parameter(random));
  box.rotation = cayley_rotation(random_cayley_parameter(random));
  // About 3.8 and 4.4 degrees per step about fixed axes.
  ball.step_rotation = cayley_rotation({1.0 / 40, 1.0 / 60, 1.0 / 90});
  box.step_rotation = cayley_rotation({-1.0 / 50, 1.0 / 35, 1.0 / 70});
  const double lateral_jitter = 0.02 * random.symmetric();
  auto ball_centre = [&](int k) {
    return V3{kBodiesX - kBodyTravel + 2.0 * kBodyTravel * k / config.steps, 0.0, 0.0};
  };
  auto box_centre = [&](int k) {
    return V3{kBodiesX + kBodyTravel - 2.0 * kBodyTravel * k / config.steps,
              kBodiesClosest + lateral_jitter, 0.05};
  };

  std::vector<Eigen::Vector3d> sphere_points;
  for (const V3& p : sheet.sphere_points()) sphere_points.push_back(to_eigen(p));

  // Meshes: 0 sheet, 1 static sphere, 2 ball, 3 box.
  SimulationStep step;
  step.meshes.resize(4);
  step.meshes[0].topology = &sheet.sheet();
  step.meshes[1].topology = &sheet.sphere();
  step.meshes[1].start = step.meshes[1].end = sphere_points;
  step.meshes[2].topology = &ball.mesh;
  step.meshes[3].topology = &box.mesh;
  step.pairs = {{0, 1, PairKind::sheet_sphere},
                {0, 0, PairKind::sheet_self},
                {2, 3, PairKind::body_body}};

  auto sheet_now = [&sheet] {
    std::vector<Eigen::Vector3d> out;
    out.reserve(sheet.sheet_positions().size());
    for (const V3& p : sheet.sheet_positions()) out.push_back(to_eigen(p));
    return out;
  };
  step.meshes[0].end = sheet_now();
  step.meshes[2].end = ball.placed(ball_centre(0));
  step.meshes[3].end = box.placed(box_centre(0));
  for (int k = 0; k < config.steps; ++k) {
    step.index = k;
    sheet.advance();
    ball.rotation = ball.step_rotation * ball.rotation;
    box.rotation = box.step_rotation * box.rotation;
    for (const int m : {0, 2, 3}) step.meshes[m].start = std::move(step.meshes[m].end);
    step.meshes[0].end = sheet_now();
    step.meshes[2].end = ball.placed(ball_centre(k + 1));
    step.meshes[3].end = box.placed(box_centre(k + 1));
    visit(step);
  }
}

namespace {

Box swept_box(const MovingMesh& m, std::initializer_list<std::uint32_t> vertices) {
  Box b;
  const Eigen::Vector3d& first = m.start[*vertices.begin()];
  for (int k = 0; k < 3; ++k) b.lo[k] = b.hi[k] = first[k];
  for (const std::uint32_t v : vertices)
    for (const Eigen::Vector3d* p : {&m.start[v], &m.end[v]})
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], (*p)[k]);
        b.hi[k] = std::max(b.hi[k], (*p)[k]);
      }
  return b;
}

std::vector<Box> vertex_boxes(const MovingMesh& m) {
  std::vector<Box> boxes;
  boxes.reserve(m.topology->vertex_count);
  for (std::uint32_t v = 0; v < m.topology->vertex_count; ++v)
    boxes.push_back(swept_box(m, {v}));
  return boxes;
}

std::vector<Box> triangle_boxes(const MovingMesh& m) {
  std::vector<Box> boxes;
  boxes.reserve(m.topology->triangles.size());
  for (const auto& t : m.topology->triangles) boxes.push_back(swept_box(m, {t[0], t[1], t[2]}));
  return boxes;
}

std::vector<Box> edge_boxes(const MovingMesh& m) {
  std::vector<Box> boxes;
  boxes.reserve(m.topology->edges.size());
  for (const auto& e : m.topology->edges) boxes.push_back(swept_box(m, {e[0], e[1]}));
  return boxes;
}

// The query of `of_first` (vertices of `first`) against `of_second` (vertices of `second`):
// rows first then second at the step's start, then the same at its end (benchmark order).
template <std::size_t N1, std::size_t N2>
SimulationQuery make_query(QueryType type, PairKind kind, const MovingMesh& first,
                           const std::array<std::uint32_t, N1>& of_first,
                           const MovingMesh& second,
                           const std::array<std::uint32_t, N2>& of_second) {
  static_assert(N1 + N2 == 4, "a query has 4 points per time");
  SimulationQuery q;
  q.type = type;
  q.kind = kind;
  for (int time = 0; time < 2; ++time) {
    const auto& p = time == 0 ? first.start : first.end;
    const auto& r = time == 0 ? second.start : second.end;
    for (std::size_t k = 0; k < N1; ++k) q.points[4 * time + k] = p[of_first[k]];
    for (std::size_t k = 0; k < N2; ++k) q.points[4 * time + N1 + k] = r[of_second[k]];
  }
  return q;
}

void append_vertex_face(const MovingMesh& vertices_of, const std::vector<Box>& vertex_box,
                        const MovingMesh& triangles_of, const std::vector<Box>& triangle_box,
                        bool same_mesh, PairKind kind, std::vector<SimulationQuery>& out) {
  for (const auto& [v, t] : overlapping_pairs(vertex_box, triangle_box)) {
    const auto& tri = triangles_of.topology->triangles[t];
    if (same_mesh && (tri[0] == v || tri[1] == v || tri[2] == v)) continue;
    out.push_back(make_query(QueryType::vertex_face, kind, vertices_of,
                             std::array<std::uint32_t, 1>{v}, triangles_of, tri));
  }
}

}  // namespace

void append_step_queries(const SimulationStep& step, std::vector<SimulationQuery>& out) {
  for (const MeshPair& pair : step.pairs) {
    const MovingMesh& a = step.meshes.at(pair.first);
    const MovingMesh& b = step.meshes.at(pair.second);
    const bool same = pair.first == pair.second;
    const std::vector<Box> a_vertices = vertex_boxes(a), a_triangles = triangle_boxes(a);
    const std::vector<Box> a_edges = edge_boxes(a);
    append_vertex_face(a, a_vertices, b, same ? a_triangles : triangle_boxes(b), same, pair.kind,
                       out);
    if (!same) append_vertex_face(b, vertex_boxes(b), a, a_triangles, false, pair.kind, out);
    const std::vector<Box> b_edges = same ? std::vector<Box>{} : edge_boxes(b);
    const auto& ea = a.topology->edges;
    const auto& eb = b.topology->edges;
    for (const auto& [i, j] : overlapping_pairs(a_edges, same ? a_edges : b_edges)) {
      if (same) {
        if (j <= i) continue;  // each unordered pair once
        if (ea[i][0] == ea[j][0] || ea[i][0] == ea[j][1] || ea[i][1] == ea[j][0] ||
            ea[i][1] == ea[j][1])
          continue;
      }
      const auto& e = ea[i];
      const auto& f = same ? ea[j] : eb[j];
      out.push_back(make_query(QueryType::edge_edge, pair.kind, a, e, b, f));
    }
  }
}

std::vector<SimulationQuery> generate_simulation_queries(const SimulationConfig& config) {
  std::vector<SimulationQuery> queries;
  simulate(config, [&queries](const SimulationStep& step) { append_step_queries(step, queries); });
  return queries;
}

}  // namespace exactccd::sim
