// Scene-level CCD (core/include/exactccd/scene.hpp): meshes, their hierarchies, the broad
// phase and the parallel narrow phase. PROOF: proofs/scene.md
#include "exactccd/scene.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <mutex>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include "pipeline/ccd_options_check.hpp"
#include "pipeline/scene/bvh.hpp"
#include "pipeline/scene/plane_cull.hpp"
#include "pipeline/scene/rigid_boxes.hpp"
#include "pipeline/scene/rigid_cylinder_ranges.hpp"
#include "pipeline/scene/time_span.hpp"
#include "pipeline/scene/time_window.hpp"
#include "exactccd/ccd.hpp"

namespace exactccd {

bool operator<(const ScenePair& a, const ScenePair& b) {
  return std::tie(a.type, a.first_mesh, a.first_index, a.second_mesh, a.second_index) <
         std::tie(b.type, b.first_mesh, b.first_index, b.second_mesh, b.second_index);
}

const char* to_string(BroadPhase broad_phase) noexcept {
  switch (broad_phase) {
    case BroadPhase::swept_bvh: return "swept_bvh";
    case BroadPhase::static_bvh: return "static_bvh";
  }
  return "unknown";
}

namespace {

using scene::Box;
using scene::Bvh;

/// Which positions a hierarchy bounds.
enum class Span : int { swept = 0, start = 1, end = 2 };

/// The three hierarchies (vertices, edges, triangles) of one mesh over one span.
struct Hierarchies {
  Bvh vertices, edges, faces;
  /// Linear and static meshes, swept span: each primitive's boxes at t = 0 and t = 1 and each
  /// node's merge of them, for culling by time (time_span.hpp); empty otherwise.
  struct Motion {
    std::vector<scene::MotionBox> primitives, nodes;
  };
  Motion vertex_motion, edge_motion, face_motion;
  /// The motion boxes above are those of the current positions and delta.
  bool has_motion = false;
  bool built = false;
  bool stale = false;      ///< positions changed since the last refit
  double raised_by = 0.0;  ///< the min_separation the boxes' upper corners were raised by
};

/// What a mesh holds (scene.hpp): triangles with their sides, edges only, points only, or an
/// infinite static plane.
enum class MeshKind : std::uint8_t { triangles, edges, points, plane };

struct Mesh {
  MeshKind kind = MeshKind::triangles;
  bool is_static = false;
  bool is_rigid = false;  ///< a rigid body: moves with `motion`; `end` is for display only
  RigidMotion motion;     ///< a rigid body's motion (zero until set_rigid_motion)
  Positions start, end;
  Triangles triangles;
  Edges edges;
  /// Per vertex, whether it is a point (edge meshes and point sets: on none of the edges).
  std::vector<char> is_point;
  bool has_points = false;
  /// A plane's origin and normal (kind plane).
  Eigen::Vector3d plane_origin = Eigen::Vector3d::Zero(), plane_normal = Eigen::Vector3d::Zero();
  Hierarchies spans[3];
  /// Cylinder ranges of the start positions about recently used lines (rigid_cylinder_ranges.hpp),
  /// dropped when the start positions change.
  std::vector<std::shared_ptr<const scene::MeshCylinderRanges>> cylinder_cache;
};

/// At most this many lines' ranges are kept per mesh (a few bodies turning about different axes).
constexpr std::size_t kCylinderCacheSize = 4;

/// What a mesh's motion keeps (rigid_cylinder_ranges.hpp). Needs upward rounding.
scene::KeptAxes kept_axes_of(const Mesh& m) {
  if (m.is_static) return {scene::KeptAxes::any, scene::AxisLine{}};
  if (m.is_rigid) return scene::kept_axes(m.motion);
  return {};  // a linearly moving mesh
}

/// The mesh's ranges about `line`, from the cache or computed (and cached). Needs upward rounding.
std::shared_ptr<const scene::MeshCylinderRanges> cylinder_ranges(Mesh& m,
                                                                 const scene::AxisLine& line) {
  for (const auto& r : m.cylinder_cache)
    if (r->line == line) return r;
  auto r = std::make_shared<const scene::MeshCylinderRanges>(
      scene::mesh_ranges(line, m.start, m.edges, m.triangles));
  if (m.cylinder_cache.size() >= kCylinderCacheSize) m.cylinder_cache.erase(m.cylinder_cache.begin());
  m.cylinder_cache.push_back(r);
  return r;
}

/// The cylinder cull of one mesh pair: both sides' ranges about their common line, h widened by
/// each side's slide along it, the first side's ranges also widened by the minimum separation.
/// PROOF: proofs/scene.md#cylinder-ranges
struct CylinderCull {
  std::shared_ptr<const scene::MeshCylinderRanges> first, second;
};

/// The cull of the mesh pair (a, b) with minimum separation delta >= 0, or nullopt when no line
/// is kept by both motions (always when neither is a rigid body: scenes without rigid bodies are
/// unchanged).
std::optional<CylinderCull> cylinder_cull(std::vector<Mesh>& meshes, MeshId a, MeshId b,
                                          double delta) {
  Mesh& ma = meshes[a];
  Mesh& mb = meshes[b];
  if (a == b || !(ma.is_rigid || mb.is_rigid)) return std::nullopt;
  const predicates::RoundingGuard upward;
  const std::optional<scene::AxisLine> line =
      scene::common_axis(kept_axes_of(ma), kept_axes_of(mb));
  if (!line) return std::nullopt;
  const auto side = [&](Mesh& m) {
    auto r = cylinder_ranges(m, *line);
    if (!m.is_rigid || m.motion.translation.isZero(0)) return r;
    return std::shared_ptr<const scene::MeshCylinderRanges>(std::make_shared<
        const scene::MeshCylinderRanges>(scene::shifted(*r, scene::h_shift(*line, m.motion.translation))));
  };
  auto first = side(ma);
  // Widening one side by delta is enough: a pair within delta then has overlapping ranges.
  if (delta > 0.0)
    first = std::make_shared<const scene::MeshCylinderRanges>(scene::widened(*first, delta));
  return CylinderCull{first, side(mb)};
}

Edges edges_of(const Triangles& triangles) {
  std::vector<std::pair<std::int32_t, std::int32_t>> sides;
  sides.reserve(static_cast<std::size_t>(triangles.rows()) * 3);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = triangles(f, k), b = triangles(f, (k + 1) % 3);
      sides.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  Edges edges(static_cast<Eigen::Index>(sides.size()), 2);
  for (std::size_t e = 0; e < sides.size(); ++e) {
    edges(static_cast<Eigen::Index>(e), 0) = sides[e].first;
    edges(static_cast<Eigen::Index>(e), 1) = sides[e].second;
  }
  return edges;
}

void check_positions(const Positions& x, const char* what) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + what);
}

void check_triangles(const Triangles& triangles, Eigen::Index vertex_count) {
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (triangles(f, k) < 0 || triangles(f, k) >= vertex_count)
        throw std::invalid_argument("exactccd: triangle " + std::to_string(f) +
                                    " has a vertex index out of range");
    if (triangles(f, 0) == triangles(f, 1) || triangles(f, 1) == triangles(f, 2) ||
        triangles(f, 0) == triangles(f, 2))
      throw std::invalid_argument("exactccd: triangle " + std::to_string(f) +
                                  " repeats a vertex");
  }
  if (vertex_count > std::numeric_limits<std::int32_t>::max())
    throw std::invalid_argument("exactccd: too many vertices in one mesh");
}

void check_options(const SceneOptions& o) {
  check_ccd_options(o.ccd);
  if (o.max_threads < 0 || o.max_threads > kMaxThreads)
    throw std::invalid_argument("exactccd: max_threads must be in [0, " +
                                std::to_string(kMaxThreads) + "], not " +
                                std::to_string(o.max_threads));
  if (!(o.min_separation >= 0.0) || !std::isfinite(o.min_separation))
    throw std::invalid_argument(
        "exactccd: SceneOptions::min_separation must be finite and >= 0, got " +
        shortest_decimal(o.min_separation));
  // One place for the scene's delta: SceneOptions::min_separation, which the broad phase
  // inflates the boxes by and the scene copies into every pair's options.
  if (o.ccd.min_separation != 0.0)
    throw std::invalid_argument(
        "exactccd: give the scene's minimum separation as SceneOptions::min_separation; "
        "SceneOptions::ccd.min_separation must be left at 0 (the scene sets it to "
        "SceneOptions::min_separation for every pair)");
}

/// The options each pair is decided with: the caller's, with min_separation as the pairs' delta
/// (ccd.min_separation is 0 on entry, check_options).
SceneOptions with_pair_separation(SceneOptions o) {
  o.ccd.min_separation = o.min_separation;
  return o;
}

Eigen::Vector3d row(const Positions& x, std::int32_t i) { return x.row(i).transpose(); }

/// Rows of K vertex indices (edges: K = 2, triangles: K = 3).
template <int K>
using IndexRows = Eigen::Matrix<std::int32_t, Eigen::Dynamic, K, Eigen::RowMajor>;

/// Calls f(p, vertex) for every primitive p < count in parallel, vertex(k) its k-th vertex (p
/// itself for vertices: no index matrix), with the FP state the boxes need: min/max by
/// comparison with no denormals-are-zero, the raise by delta > 0 rounded upwards (min/max are
/// exact in either mode).
template <int K, class F>
void for_each_primitive(const IndexRows<K>* indices, Eigen::Index count, double delta, F&& f) {
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, count, 4096),
                    [&](const tbb::blocked_range<Eigen::Index>& r) {
                      const predicates::FpEnvironmentGuard fp(
                          delta > 0.0 ? predicates::Rounding::upward
                                      : predicates::Rounding::to_nearest);
                      for (Eigen::Index p = r.begin(); p != r.end(); ++p)
                        f(p, [&](int k) {
                          return indices ? (*indices)(p, k) : static_cast<std::int32_t>(p);
                        });
                    });
}

/// Boxes of a mesh's primitives over a span: min/max of input doubles only, so exact. A moving
/// primitive stays in the box of its start and end positions (proofs/scene.md#swept-boxes).
/// With delta > 0 each box's upper corner is then raised by delta, rounded upwards
/// (proofs/scene.md#min-separation).
template <int K>
std::vector<Box> primitive_boxes(const Mesh& m, Span span, const IndexRows<K>* indices,
                                 Eigen::Index count, double delta) {
  std::vector<Box> boxes(static_cast<std::size_t>(count));
  const bool use_start = span != Span::end || m.is_static;
  const bool use_end = span != Span::start && !m.is_static;
  const Positions& first = use_start ? m.start : m.end;
  for_each_primitive<K>(indices, count, delta, [&](Eigen::Index p, const auto& vertex) {
    Box box = scene::point_box(first.row(vertex(0)));
    for (int k = 0; k < K; ++k) {
      if (use_start) scene::grow(box, m.start.row(vertex(k)));
      if (use_end) scene::grow(box, m.end.row(vertex(k)));
    }
    if (delta > 0.0) scene::raise_upper_corner(box, delta);
    boxes[static_cast<std::size_t>(p)] = box;
  });
  return boxes;
}

/// Each primitive's boxes at t = 0 and t = 1 (a static mesh's both at its positions), upper
/// corners raised by delta as in primitive_boxes. PROOF: proofs/scene.md#time-span
template <int K>
std::vector<scene::MotionBox> motion_boxes(const Mesh& m, const IndexRows<K>* indices,
                                           Eigen::Index count, double delta) {
  std::vector<scene::MotionBox> boxes(static_cast<std::size_t>(count));
  const Positions& last = m.is_static ? m.start : m.end;
  for_each_primitive<K>(indices, count, delta, [&](Eigen::Index p, const auto& vertex) {
    scene::MotionBox box{scene::point_box(m.start.row(vertex(0))),
                         scene::point_box(last.row(vertex(0)))};
    for (int k = 1; k < K; ++k) {
      scene::grow(box.at0, m.start.row(vertex(k)));
      scene::grow(box.at1, last.row(vertex(k)));
    }
    if (delta > 0.0) {
      scene::raise_upper_corner(box.at0, delta);
      scene::raise_upper_corner(box.at1, delta);
    }
    boxes[static_cast<std::size_t>(p)] = box;
  });
  return boxes;
}

/// Whether a moving mesh travels far for its size: at least half of its edges have an end moving
/// by more than the edge's length (max norms), as in a barrier method's trial step. Only then
/// do boxes over the step overlap much more often than the primitives' boxes at any one time,
/// and culling by time pays for its boxes (a speed heuristic only: the cull never changes an
/// answer).
bool moves_far(const Mesh& m) {
  if (m.is_static || m.edges.rows() == 0) return false;
  // A sample of about 1024 edges spread over the mesh decides it (a heuristic: sampling is
  // enough, and large meshes pay almost nothing for it).
  const Eigen::Index stride = std::max<Eigen::Index>(1, m.edges.rows() / 1024);
  Eigen::Index far = 0, seen = 0;
  for (Eigen::Index e = 0; e < m.edges.rows(); e += stride, ++seen) {
    const std::int32_t a = m.edges(e, 0), b = m.edges(e, 1);
    const double length = (m.start.row(a) - m.start.row(b)).cwiseAbs().maxCoeff();
    const double moved = std::max((m.end.row(a) - m.start.row(a)).cwiseAbs().maxCoeff(),
                                  (m.end.row(b) - m.start.row(b)).cwiseAbs().maxCoeff());
    if (moved > length) ++far;
  }
  return 2 * far >= seen;
}

/// The motion boxes of one hierarchy's primitives and their merges per node.
template <int K>
void set_motion(Hierarchies::Motion& motion, const Bvh& bvh, const Mesh& m,
                const IndexRows<K>* indices, Eigen::Index count, double delta) {
  motion.primitives = motion_boxes<K>(m, indices, count, delta);
  motion.nodes = bvh.node_values(motion.primitives, [](const scene::MotionBox& a,
                                                       const scene::MotionBox& b) {
    return scene::merge(a, b);
  });
}

/// Certified boxes of a rigid body's vertices over the span (swept: s in [0, 1]; start: s = 0;
/// end: s = 1): unions of interval enclosures of each vertex's arc over pieces of the span
/// (rigid_boxes.hpp, proofs/scene.md#rigid-boxes).
std::vector<Box> rigid_vertex_boxes(const Mesh& m, Span span) {
  const double s_lo = span == Span::end ? 1.0 : 0.0;
  const double s_hi = span == Span::start ? 0.0 : 1.0;
  const scene::Pieces ends = scene::pieces_for(m.motion, s_lo, s_hi);
  const scene::ArcPieces pieces = [&] {
    const predicates::RoundingGuard upward;  // Interval_nt<false>
    return scene::arc_pieces(m.motion.cayley, ends);
  }();
  std::vector<Box> boxes(static_cast<std::size_t>(m.start.rows()));
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, m.start.rows(), 1024),
                    [&](const tbb::blocked_range<Eigen::Index>& r) {
                      const predicates::RoundingGuard upward;
                      for (Eigen::Index v = r.begin(); v != r.end(); ++v) {
                        Box box = scene::empty_box();
                        const auto x0 = row(m.start, static_cast<std::int32_t>(v));
                        scene::grow_by_arc(box, scene::arc_point(m.motion, x0), pieces);
                        boxes[static_cast<std::size_t>(v)] = box;
                      }
                    });
  return boxes;
}

/// Boxes of primitives of K vertices (rows of `indices`) as the merge of their vertices' boxes:
/// each vertex lies in its box at every s of the span, so the primitive (their convex hull) lies
/// in the merge. With delta > 0 the upper corners are raised as in primitive_boxes.
template <int K>
std::vector<Box> merged_boxes(const std::vector<Box>& vertex_boxes, const IndexRows<K>& indices,
                              double delta) {
  std::vector<Box> boxes(static_cast<std::size_t>(indices.rows()));
  const predicates::FpEnvironmentGuard fp(delta > 0.0 ? predicates::Rounding::upward
                                                      : predicates::Rounding::to_nearest);
  for (Eigen::Index p = 0; p < indices.rows(); ++p) {
    Box box = vertex_boxes[static_cast<std::size_t>(indices(p, 0))];
    for (int k = 1; k < K; ++k)
      box = scene::merge(box, vertex_boxes[static_cast<std::size_t>(indices(p, k))]);
    if (delta > 0.0) scene::raise_upper_corner(box, delta);
    boxes[static_cast<std::size_t>(p)] = box;
  }
  return boxes;
}

void update(Bvh& bvh, const std::vector<Box>& boxes, bool built, SceneStats& stats) {
  if (built) {
    ++stats.hierarchies_refitted;
    if (bvh.refit_or_rebuild(boxes)) ++stats.hierarchies_built;
    return;
  }
  bvh.build(boxes);
  ++stats.hierarchies_built;
}

/// Builds, refits or rebuilds (when degraded) the hierarchies of one mesh over one span, boxes
/// raised by delta; a change of delta since the last call refits them as a change of positions.
/// With `with_motion` (swept span, a linear or static mesh) also the motion boxes for culling
/// by time.
Hierarchies& prepare(Mesh& m, Span span, double delta, SceneStats& stats,
                     bool with_motion = false) {
  // A static mesh has one set of positions: one set of hierarchies serves every span.
  Hierarchies& h = m.spans[m.is_static ? 0 : static_cast<int>(span)];
  with_motion = with_motion && !m.is_rigid;
  if (h.built && !h.stale && h.raised_by == delta && (!with_motion || h.has_motion)) return h;
  if (m.is_rigid) {
    std::vector<Box> vertex_boxes = rigid_vertex_boxes(m, span);
    update(h.edges, merged_boxes<2>(vertex_boxes, m.edges, delta), h.built, stats);
    update(h.faces, merged_boxes<3>(vertex_boxes, m.triangles, delta), h.built, stats);
    if (delta > 0.0) {
      const predicates::FpEnvironmentGuard upward(predicates::Rounding::upward);
      for (Box& box : vertex_boxes) scene::raise_upper_corner(box, delta);
    }
    update(h.vertices, vertex_boxes, h.built, stats);
    h.built = true;
    h.stale = false;
    h.raised_by = delta;
    return h;
  }
  update(h.vertices, primitive_boxes<1>(m, span, nullptr, m.start.rows(), delta), h.built, stats);
  update(h.edges, primitive_boxes<2>(m, span, &m.edges, m.edges.rows(), delta), h.built, stats);
  update(h.faces, primitive_boxes<3>(m, span, &m.triangles, m.triangles.rows(), delta), h.built,
         stats);
  h.has_motion = with_motion;
  if (with_motion) {
    set_motion<1>(h.vertex_motion, h.vertices, m, nullptr, m.start.rows(), delta);
    set_motion<2>(h.edge_motion, h.edges, m, &m.edges, m.edges.rows(), delta);
    set_motion<3>(h.face_motion, h.faces, m, &m.triangles, m.triangles.rows(), delta);
  } else {
    h.vertex_motion = h.edge_motion = h.face_motion = {};
  }
  h.built = true;
  h.stale = false;
  h.raised_by = delta;
  return h;
}

bool triangle_has_vertex(const Triangles& t, std::uint32_t f, std::int32_t v) {
  const auto fi = static_cast<Eigen::Index>(f);
  return t(fi, 0) == v || t(fi, 1) == v || t(fi, 2) == v;
}

bool edge_has_vertex(const Edges& e, std::uint32_t i, std::uint32_t v) {
  const auto a = static_cast<Eigen::Index>(i);
  const auto w = static_cast<std::int32_t>(v);
  return e(a, 0) == w || e(a, 1) == w;
}

bool edges_share_vertex(const Edges& e, std::uint32_t i, std::uint32_t j) {
  const auto a = static_cast<Eigen::Index>(i), b = static_cast<Eigen::Index>(j);
  return e(a, 0) == e(b, 0) || e(a, 0) == e(b, 1) || e(a, 1) == e(b, 0) || e(a, 1) == e(b, 1);
}

/// Whether a call visits the mesh pair (a, b), a <= b: not when both are static; (a, a) only
/// for a moving mesh (not a rigid body) with self-collision. Vertex-face visits such a pair in
/// both orders, edge-edge once.
bool visits(const std::vector<Mesh>& meshes, bool self, MeshId a, MeshId b) {
  if (meshes[a].is_static && meshes[b].is_static) return false;
  return a != b || (self && !meshes[a].is_rigid);
}

/// The box of every primitive in a mesh's hierarchies, or nullopt when they hold none.
std::optional<Box> bounds_of(const Hierarchies& h) {
  std::optional<Box> box;
  for (const Bvh* tree : {&h.vertices, &h.edges, &h.faces})
    if (!tree->empty()) box = box ? scene::merge(*box, tree->bounds()) : tree->bounds();
  return box;
}

/// A pair's answer: the verdict with the TOI in s, and the contact time where defined.
struct Decision {
  CcdResult ccd;
  bool has_time = false;
  double time_lo = kNoContactToi, time_hi = kNoContactToi;

  SceneContact contact(const ScenePair& p) const {
    return {p, ccd.toi_lo, ccd.toi_hi, has_time, ccd.starts_within, time_lo, time_hi};
  }
};

}  // namespace

/// Per-thread values. TBB's default lookup (a hash table), not ets_key_per_instance: that one
/// takes a native thread-local key per instance and ignores a failure to get one, so very many
/// concurrent calls could exhaust the process's keys.
template <class T>
using PerThread = tbb::enumerable_thread_specific<T>;

/// Candidate pairs and, for each, the start of its time span (the earliest time its blended
/// boxes can overlap, time_span.hpp; 0 without the cull by time).
struct Candidates {
  std::vector<ScenePair> pairs;
  std::vector<double> starts;
  void add(const ScenePair& p, double start) {
    pairs.push_back(p);
    starts.push_back(start);
  }
};

struct Scene::Impl {
  std::vector<Mesh> meshes;
  SceneDimension dimension = SceneDimension::three;

  bool planar() const { return dimension == SceneDimension::two; }


  bool any_rigid() const {
    return std::any_of(meshes.begin(), meshes.end(), [](const Mesh& m) { return m.is_rigid; });
  }

  bool involves_rigid(const ScenePair& p) const {
    return meshes[p.first_mesh].is_rigid || meshes[p.second_mesh].is_rigid;
  }

  /// One side of a rigid query: the body's motion, or straight lines from start to end rows
  /// (equal for a static mesh) of the given vertices.
  template <std::size_t N>
  static SideMotion side_of(const Mesh& m, const std::array<std::int32_t, N>& vertices) {
    if (m.is_rigid) return SideMotion::of(m.motion);
    SideMotion side;
    side.kind = PathKind::linear;
    for (std::size_t i = 0; i < N; ++i) side.linear_end[i] = row(m.end, vertices[i]);
    return side;
  }

  RigidVertexFaceQuery rigid_vertex_face(const ScenePair& p) const {
    const Mesh& a = mesh(p.first_mesh);
    const Mesh& b = mesh(p.second_mesh);
    const std::array<std::int32_t, 1> v{static_cast<std::int32_t>(p.first_index)};
    const auto f = static_cast<Eigen::Index>(p.second_index);
    const std::array<std::int32_t, 3> t{b.triangles(f, 0), b.triangles(f, 1), b.triangles(f, 2)};
    return {row(a.start, v[0]), row(b.start, t[0]), row(b.start, t[1]), row(b.start, t[2]),
            side_of(a, v),      side_of(b, t)};
  }

  /// The segments of an edge-edge, point-edge or point-point pair: a point is the zero-length
  /// segment [v, v], exactly as point_edge_ccd and point_point_ccd reduce their queries to
  /// edge_edge_ccd (PROOF: proofs/api_reductions.md#point-primitives), so deciding the
  /// segments is deciding the pair.
  static std::array<std::int32_t, 2> segment(const Mesh& m, std::uint32_t index, bool is_edge) {
    if (!is_edge) return {static_cast<std::int32_t>(index), static_cast<std::int32_t>(index)};
    const auto e = static_cast<Eigen::Index>(index);
    return {m.edges(e, 0), m.edges(e, 1)};
  }
  static std::array<std::int32_t, 2> first_segment(const Mesh& m, const ScenePair& p) {
    return segment(m, p.first_index, p.type == QueryType::edge_edge);
  }
  static std::array<std::int32_t, 2> second_segment(const Mesh& m, const ScenePair& p) {
    return segment(m, p.second_index, p.type != QueryType::point_point);
  }

  RigidEdgeEdgeQuery rigid_edge_edge(const ScenePair& p) const {
    const Mesh& a = mesh(p.first_mesh);
    const Mesh& b = mesh(p.second_mesh);
    const std::array<std::int32_t, 2> ea = first_segment(a, p);
    const std::array<std::int32_t, 2> eb = second_segment(b, p);
    return {row(a.start, ea[0]), row(a.start, ea[1]), row(b.start, eb[0]), row(b.start, eb[1]),
            side_of(a, ea),      side_of(b, eb)};
  }

  /// Grows `box` to hold the given vertices of `m` over s in [0, window] (rigid_boxes.hpp).
  /// Needs upward rounding.
  template <std::size_t N>
  static void grow_over_window(Box& box, const Mesh& m, const std::array<std::int32_t, N>& vertices,
                               double window) {
    if (m.is_rigid) {
      const scene::ArcPieces pieces =
          scene::arc_pieces(m.motion.cayley, scene::pieces_for(m.motion, 0.0, window));
      for (std::int32_t v : vertices)
        scene::grow_by_arc(box, scene::arc_point(m.motion, row(m.start, v)), pieces);
      return;
    }
    for (std::int32_t v : vertices)
      scene::grow_by_segment(box, row(m.start, v), row(m.end, v), 0.0, window);
  }

  /// True when the two sides of a pair involving a rigid body cannot come within delta >= 0
  /// (0: meet) at any s in [0, window]: their certified boxes over the window are more than
  /// delta apart on some axis, the sum hi + delta rounded upwards as in time_window.hpp
  /// (proofs/scene.md#rigid-boxes, #min-separation). Needs upward rounding.
  template <std::size_t NA, std::size_t NB>
  static bool rigid_sides_disjoint(const Mesh& a, const std::array<std::int32_t, NA>& va,
                                   const Mesh& b, const std::array<std::int32_t, NB>& vb,
                                   double window, double delta) {
    Box box_a = scene::empty_box(), box_b = scene::empty_box();
    grow_over_window(box_a, a, va, window);
    grow_over_window(box_b, b, vb, window);
    for (int k = 0; k < 3; ++k)
      if (box_a.hi[k] + delta < box_b.lo[k] || box_b.hi[k] + delta < box_a.lo[k]) return true;
    return false;
  }

  bool rigid_disjoint_over_window(const ScenePair& p, double window, double delta) const {
    const Mesh& a = meshes[p.first_mesh];
    const Mesh& b = meshes[p.second_mesh];
    if (p.type == QueryType::point_plane) {
      Box box = scene::empty_box();
      grow_over_window(box, a, std::array<std::int32_t, 1>{static_cast<std::int32_t>(p.first_index)},
                       window);
      return scene::box_apart_from_plane(box.lo, box.hi, b.plane_origin, b.plane_normal, delta);
    }
    if (p.type == QueryType::vertex_face) {
      const auto f = static_cast<Eigen::Index>(p.second_index);
      return rigid_sides_disjoint(
          a, std::array<std::int32_t, 1>{static_cast<std::int32_t>(p.first_index)}, b,
          std::array<std::int32_t, 3>{b.triangles(f, 0), b.triangles(f, 1), b.triangles(f, 2)},
          window, delta);
    }
    return rigid_sides_disjoint(a, first_segment(a, p), b, second_segment(b, p), window, delta);
  }

  const Mesh& mesh(MeshId id) const {
    if (id >= meshes.size()) throw std::invalid_argument("exactccd: no mesh " + std::to_string(id));
    return meshes[id];
  }

  VertexFaceQuery vertex_face(const ScenePair& p) const {
    const Mesh& a = mesh(p.first_mesh);
    const Mesh& b = mesh(p.second_mesh);
    const auto v = static_cast<std::int32_t>(p.first_index);
    const auto f = static_cast<Eigen::Index>(p.second_index);
    return {row(a.start, v), row(b.start, b.triangles(f, 0)), row(b.start, b.triangles(f, 1)),
            row(b.start, b.triangles(f, 2)), row(a.end, v), row(b.end, b.triangles(f, 0)),
            row(b.end, b.triangles(f, 1)), row(b.end, b.triangles(f, 2))};
  }

  /// The edge-edge query of an edge-edge, point-edge or point-point pair (first_segment).
  EdgeEdgeQuery edge_edge(const ScenePair& p) const {
    const Mesh& a = mesh(p.first_mesh);
    const Mesh& b = mesh(p.second_mesh);
    const std::array<std::int32_t, 2> ea = first_segment(a, p);
    const std::array<std::int32_t, 2> eb = second_segment(b, p);
    return {row(a.start, ea[0]), row(a.start, ea[1]), row(b.start, eb[0]), row(b.start, eb[1]),
            row(a.end, ea[0]),   row(a.end, ea[1]),   row(b.end, eb[0]),   row(b.end, eb[1])};
  }

  /// A point-plane pair of a rigid body's vertex: its motion against the static plane.
  RigidPointPlaneQuery rigid_point_plane(const ScenePair& p) const {
    const Mesh& a = mesh(p.first_mesh);
    const Mesh& plane = mesh(p.second_mesh);
    return {row(a.start, static_cast<std::int32_t>(p.first_index)), a.motion, plane.plane_origin,
            plane.plane_normal};
  }

  /// A point-plane pair's query: the vertex's motion against the static plane.
  PointPlaneQuery point_plane(const ScenePair& p) const {
    const Mesh& a = mesh(p.first_mesh);
    const Mesh& plane = mesh(p.second_mesh);
    const auto v = static_cast<std::int32_t>(p.first_index);
    return {row(a.start, v), plane.plane_origin, plane.plane_normal,
            row(a.end, v),   plane.plane_origin, plane.plane_normal};
  }

  /// A mesh pair a call visits (a <= b) and its cylinder culls in both orders.
  struct MeshPair {
    MeshId a, b;
    std::optional<CylinderCull> ab, ba;  ///< cylinder_cull(a, b), cylinder_cull(b, a)
  };

  /// The mesh pairs a call visits (`visits`) whose boxes overlap, the box of a mesh merging
  /// its hierarchies `at(mesh)` for every `at` given, sorted; pairs apart hold no pair of
  /// primitives whose boxes overlap (each primitive's box lies in its mesh's), so nothing is
  /// lost. Found by a hierarchy over the meshes' boxes: scenes of many small meshes cost time
  /// and memory in proportion to the pairs that come close, not to the square of their number.
  /// Then the cylinder culls (rigid bodies only), before the parallel traversals read them.
  /// PROOF: proofs/scene.md#broad-phase
  template <class... At>
  std::vector<MeshPair> close_mesh_pairs(const SceneOptions& o, const At&... at) {
    std::vector<Box> boxes;
    std::vector<MeshId> ids;  // the mesh of each box (meshes without primitives have none)
    for (MeshId m = 0; m < meshes.size(); ++m) {
      std::optional<Box> box;
      for (const std::optional<Box>& b : {bounds_of(at(meshes[m]))...})
        if (b) box = box ? scene::merge(*box, *b) : *b;
      if (!box) continue;
      boxes.push_back(*box);
      ids.push_back(m);
    }
    Bvh tree;
    tree.build(boxes);
    PerThread<std::vector<MeshPair>> found;
    tree.parallel_for_each_self_overlap([&](std::uint32_t i, std::uint32_t j) {
      const MeshId a = std::min(ids[i], ids[j]), b = std::max(ids[i], ids[j]);
      if (visits(meshes, o.self_collision, a, b)) found.local().push_back({a, b, {}, {}});
    });
    std::vector<MeshPair> pairs;
    for (MeshId m : ids)
      if (visits(meshes, o.self_collision, m, m)) pairs.push_back({m, m, {}, {}});
    for (const auto& part : found) pairs.insert(pairs.end(), part.begin(), part.end());
    std::sort(pairs.begin(), pairs.end(), [](const MeshPair& x, const MeshPair& y) {
      return std::tie(x.a, x.b) < std::tie(y.a, y.b);
    });
    if (any_rigid())
      for (MeshPair& p : pairs) {
        p.ab = cylinder_cull(meshes, p.a, p.b, o.min_separation);
        p.ba = cylinder_cull(meshes, p.b, p.a, o.min_separation);
      }
    return pairs;
  }

  /// Calls sink(pair, start) (concurrently) for every candidate pair of the hierarchies
  /// `at(mesh)` (one span) of the mesh pairs `pairs`: pairs of primitives whose boxes overlap,
  /// pairs within a mesh sharing a vertex excluded, pairs whose cylinder ranges are apart (the
  /// pair's culls) counted in `culled` and excluded. With `by_time` (the swept span), pairs of
  /// linear or static meshes whose blended boxes cannot overlap by until() (read at each test:
  /// a bound that only decreases, time_span.hpp) are cut with their nodes, each cut counted in
  /// `time_culled`; `start` is the start of the pair's time span (0 without motion boxes).
  template <class At, class Sink, class Until>
  void gather_candidates(const At& at, const std::vector<MeshPair>& pairs, const Sink& sink,
                         PerThread<std::uint64_t>& culled, bool by_time,
                         const Until& until,
                         PerThread<std::uint64_t>& time_culled, double delta) const {
    // The motions of a mesh pair when culling by time applies to it, else nullptr.
    const auto motions = [&](MeshId a, MeshId b, auto member) {
      using Motion = Hierarchies::Motion;
      const Mesh& ma = meshes[a];
      const Mesh& mb = meshes[b];
      const bool applies = by_time && at(ma).has_motion && at(mb).has_motion;
      return std::pair<const Motion*, const Motion*>(
          applies ? &(at(ma).*member.first) : nullptr, applies ? &(at(mb).*member.second) : nullptr);
    };
    const auto time_keep = [&](const Hierarchies::Motion* ma, const Hierarchies::Motion* mb) {
      return [ma, mb, &until, &time_culled](std::uint32_t i, std::uint32_t j) {
        if (scene::may_meet_by(ma->nodes[i], mb->nodes[j], until())) return true;
        ++time_culled.local();
        return false;
      };
    };
    // The start of a pair's time span, or +infinity when it cannot meet by until() (counted).
    const auto time_start = [&](const Hierarchies::Motion* ma, const Hierarchies::Motion* mb,
                                std::uint32_t i, std::uint32_t j) {
      if (!ma) return 0.0;
      const scene::TimeSpan span = scene::overlap_span(ma->primitives[i], mb->primitives[j]);
      if (!span.empty() && span.lo <= until()) return span.lo;
      ++time_culled.local();
      return std::numeric_limits<double>::infinity();
    };
    const auto vertex_face = [&](MeshId a, MeshId b, const std::optional<CylinderCull>& cull) {
      const Mesh& mb = meshes[b];
      const Bvh& va = at(meshes[a]).vertices;
      const Bvh& fb = at(mb).faces;
      const auto [mv, mf] = motions(
          a, b, std::make_pair(&Hierarchies::vertex_motion, &Hierarchies::face_motion));
      const auto pair = [&, mv = mv, mf = mf](std::uint32_t v, std::uint32_t f) {
        if (a == b && triangle_has_vertex(mb.triangles, f, static_cast<std::int32_t>(v))) return;
        if (cull && scene::apart(cull->first->vertices[v], cull->second->faces[f])) {
          ++culled.local();
          return;
        }
        const double start = time_start(mv, mf, v, f);
        if (start == std::numeric_limits<double>::infinity()) return;
        sink(ScenePair{QueryType::vertex_face, a, v, b, f}, start);
      };
      if (cull)
        va.parallel_for_each_overlap(fb, pair,
                                     node_cull(va, cull->first->vertices, fb, cull->second->faces,
                                               culled));
      else if (mv)
        va.parallel_for_each_overlap(fb, pair, time_keep(mv, mf));
      else
        va.parallel_for_each_overlap(fb, pair);
    };
    const auto edge_edge = [&](MeshId a, MeshId b, const std::optional<CylinderCull>& cull) {
      const Mesh& ma = meshes[a];
      const auto [ea_motion, eb_motion] =
          motions(a, b, std::make_pair(&Hierarchies::edge_motion, &Hierarchies::edge_motion));
      if (a == b) {
        const auto pair = [&, m = ea_motion](std::uint32_t i, std::uint32_t j) {
          if (edges_share_vertex(ma.edges, i, j)) return;
          const double start = time_start(m, m, i, j);
          if (start == std::numeric_limits<double>::infinity()) return;
          sink(ScenePair{QueryType::edge_edge, a, std::min(i, j), a, std::max(i, j)}, start);
        };
        if (ea_motion)
          at(ma).edges.parallel_for_each_self_overlap(pair, time_keep(ea_motion, ea_motion));
        else
          at(ma).edges.parallel_for_each_self_overlap(pair);
      } else {
        const Bvh& ea = at(ma).edges;
        const Bvh& eb = at(meshes[b]).edges;
        const auto pair = [&, m0 = ea_motion, m1 = eb_motion](std::uint32_t i, std::uint32_t j) {
          if (cull && scene::apart(cull->first->edges[i], cull->second->edges[j])) {
            ++culled.local();
            return;
          }
          const double start = time_start(m0, m1, i, j);
          if (start == std::numeric_limits<double>::infinity()) return;
          sink(ScenePair{QueryType::edge_edge, a, i, b, j}, start);
        };
        if (cull)
          ea.parallel_for_each_overlap(
              eb, pair, node_cull(ea, cull->first->edges, eb, cull->second->edges, culled));
        else if (ea_motion)
          ea.parallel_for_each_overlap(eb, pair, time_keep(ea_motion, eb_motion));
        else
          ea.parallel_for_each_overlap(eb, pair);
      }
    };
    // A mesh's points against another's edges: in 3D the points of edge meshes and point sets
    // (a vertex on an edge meets an edge only where that edge does: edge-edge covers it), in
    // 2D every vertex, which covers the edges too (proofs/scene.md#codimensional).
    const bool every_vertex = planar();
    const auto point_edge = [&](MeshId a, MeshId b, const std::optional<CylinderCull>& cull) {
      const Mesh& ma = meshes[a];
      const Mesh& mb = meshes[b];
      if (!(every_vertex || ma.has_points) || mb.edges.rows() == 0) return;
      const Bvh& va = at(ma).vertices;
      const Bvh& eb = at(mb).edges;
      const auto [mv, me] = motions(
          a, b, std::make_pair(&Hierarchies::vertex_motion, &Hierarchies::edge_motion));
      const auto pair = [&, mv = mv, me = me](std::uint32_t v, std::uint32_t e) {
        if (!every_vertex && !ma.is_point[v]) return;
        if (a == b && edge_has_vertex(mb.edges, e, v)) return;
        if (cull && scene::apart(cull->first->vertices[v], cull->second->edges[e])) {
          ++culled.local();
          return;
        }
        const double start = time_start(mv, me, v, e);
        if (start == std::numeric_limits<double>::infinity()) return;
        sink(ScenePair{QueryType::point_edge, a, v, b, e}, start);
      };
      if (cull)
        va.parallel_for_each_overlap(eb, pair,
                                     node_cull(va, cull->first->vertices, eb, cull->second->edges,
                                               culled));
      else if (mv)
        va.parallel_for_each_overlap(eb, pair, time_keep(mv, me));
      else
        va.parallel_for_each_overlap(eb, pair);
    };
    // Points against points (rigid bodies have none: no cylinder cull).
    const auto point_point = [&](MeshId a, MeshId b) {
      const Mesh& ma = meshes[a];
      const Mesh& mb = meshes[b];
      if (!ma.has_points || !mb.has_points) return;
      const auto [m0, m1] = motions(
          a, b, std::make_pair(&Hierarchies::vertex_motion, &Hierarchies::vertex_motion));
      const auto pair = [&, m0 = m0, m1 = m1](std::uint32_t i, std::uint32_t j) {
        if (!ma.is_point[i] || !mb.is_point[j]) return;
        const double start = time_start(m0, m1, i, j);
        if (start == std::numeric_limits<double>::infinity()) return;
        if (a == b)
          sink(ScenePair{QueryType::point_point, a, std::min(i, j), a, std::max(i, j)}, start);
        else
          sink(ScenePair{QueryType::point_point, a, i, b, j}, start);
      };
      const Bvh& va = at(ma).vertices;
      if (a == b) {
        if (m0)
          va.parallel_for_each_self_overlap(pair, time_keep(m0, m0));
        else
          va.parallel_for_each_self_overlap(pair);
      } else if (m0) {
        va.parallel_for_each_overlap(at(mb).vertices, pair, time_keep(m0, m1));
      } else {
        va.parallel_for_each_overlap(at(mb).vertices, pair);
      }
    };
    // Many small meshes: the mesh pairs in parallel too (each traversal is itself parallel).
    tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t k) {
      const MeshPair& p = pairs[k];
      if (!planar()) {  // a 2D scene has no triangles, and point-edge covers its edges
        vertex_face(p.a, p.b, p.ab);
        if (p.a != p.b) vertex_face(p.b, p.a, p.ba);
        edge_edge(p.a, p.b, p.ab);
      }
      point_edge(p.a, p.b, p.ab);
      if (p.a != p.b) point_edge(p.b, p.a, p.ba);
      point_point(p.a, p.b);
    });
    plane_candidates(at, sink, until, delta);
  }

  /// A rigid body's vertices against a plane: each vertex's certified box in the hierarchy
  /// `vertices` (rigid_vertex_boxes, upper corners raised by delta: a larger box) against the
  /// plane (box_apart_from_plane). PROOF: proofs/scene.md#planes
  template <class Sink>
  void rigid_plane_candidates(MeshId id, const Bvh& vertices, MeshId plane, const Sink& sink,
                              double delta) const {
    const Mesh& pm = meshes[plane];
    std::vector<std::uint32_t> near;
    {
      const predicates::RoundingGuard upward;
      const auto count = static_cast<std::uint32_t>(meshes[id].start.rows());
      for (std::uint32_t v = 0; v < count; ++v) {
        const Box& box = vertices.box(v);
        if (!scene::box_apart_from_plane(box.lo, box.hi, pm.plane_origin, pm.plane_normal,
                                         delta))
          near.push_back(v);
      }
    }
    for (const std::uint32_t v : near)
      sink(ScenePair{QueryType::point_plane, id, v, plane, 0}, 0.0);
  }

  /// Every vertex of a moving mesh against every plane, cut by apart_from_plane over
  /// [0, until()] (one certified test per vertex: no hierarchy, no cost per triangle).
  /// PROOF: proofs/scene.md#planes
  template <class At, class Sink, class Until>
  void plane_candidates(const At& at, const Sink& sink, const Until& until, double delta) const {
    for (MeshId plane = 0; plane < meshes.size(); ++plane) {
      const Mesh& pm = meshes[plane];
      if (pm.kind != MeshKind::plane) continue;
      for (MeshId id = 0; id < meshes.size(); ++id) {
        const Mesh& m = meshes[id];
        if (m.is_static) continue;  // planes and static meshes never move
        if (m.is_rigid) {
          rigid_plane_candidates(id, at(m).vertices, plane, sink, delta);
          continue;
        }
        tbb::parallel_for(
            tbb::blocked_range<Eigen::Index>(0, m.start.rows(), 4096),
            [&](const tbb::blocked_range<Eigen::Index>& r) {
              std::vector<std::uint32_t> near;  // the sink runs in the caller's FP state
              {
                const double window = std::min(1.0, until());
                const predicates::RoundingGuard upward;
                for (Eigen::Index v = r.begin(); v != r.end(); ++v) {
                  const auto vi = static_cast<std::int32_t>(v);
                  if (!scene::apart_from_plane(row(m.start, vi), row(m.end, vi),
                                               pm.plane_origin, pm.plane_normal, delta, window))
                    near.push_back(static_cast<std::uint32_t>(v));
                }
              }
              for (const std::uint32_t v : near)
                sink(ScenePair{QueryType::point_plane, id, v, plane, 0}, 0.0);
            });
      }
    }
  }

  /// The node test of a traversal with a cylinder cull: a node's ranges merge those of the
  /// primitives below it, so apart nodes hold no pair that is not apart (each cut counted).
  struct NodeCull {
    std::vector<scene::CylinderRange> first, second;
    PerThread<std::uint64_t>* culled;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      if (!scene::apart(first[a], second[b])) return true;
      ++culled->local();
      return false;
    }
  };
  static NodeCull node_cull(const Bvh& a, const std::vector<scene::CylinderRange>& ra,
                            const Bvh& b, const std::vector<scene::CylinderRange>& rb,
                            PerThread<std::uint64_t>& culled) {
    return {a.node_values(ra, scene::merge_ranges), b.node_values(rb, scene::merge_ranges),
            &culled};
  }

  static std::uint64_t total(const PerThread<std::uint64_t>& counts) {
    std::uint64_t sum = 0;
    for (std::uint64_t c : counts) sum += c;
    return sum;
  }

  static const Hierarchies& swept(const Mesh& m) { return m.spans[0]; }

  /// The swept hierarchies, ready to traverse: the mesh pairs, and whether to cull by time (when
  /// some linearly moving mesh travels far for its size, moves_far).
  struct SweptScene {
    std::vector<MeshPair> pairs;
    bool by_time = false;
    double delta = 0.0;  ///< the minimum separation the boxes are raised by
  };
  SweptScene prepare_swept(const SceneOptions& o, SceneStats& stats) {
    SweptScene s;
    s.by_time = o.cull_by_time && std::any_of(meshes.begin(), meshes.end(), [](const Mesh& m) {
                  return !m.is_rigid && moves_far(m);
                });
    for (Mesh& m : meshes) prepare(m, Span::swept, o.min_separation, stats, s.by_time);
    s.delta = o.min_separation;
    s.pairs = close_mesh_pairs(o, swept);
    return s;
  }

  /// Calls sink(pair, start) for every candidate pair of the swept hierarchies that can meet
  /// by until() (gather_candidates), counting the culls in the stats.
  template <class Sink, class Until>
  void swept_candidates(const SweptScene& s, const Sink& sink, const Until& until,
                        SceneStats& stats) {
    PerThread<std::uint64_t> culled(0), time_culled(0);
    gather_candidates(swept, s.pairs, sink, culled, s.by_time, until, time_culled, s.delta);
    stats.cylinder_culled += total(culled);
    stats.time_culled += total(time_culled);
  }
  /// Every candidate pair of the swept hierarchies that can meet by t_max, in no particular
  /// order, with their spans' starts.
  Candidates swept_candidates(const SceneOptions& o, SceneStats& stats) {
    const SweptScene s = prepare_swept(o, stats);
    PerThread<Candidates> found;
    const double t_max = o.ccd.t_max;
    swept_candidates(
        s, [&](const ScenePair& p, double start) { found.local().add(p, start); },
        [t_max] { return t_max; }, stats);
    return concatenate(found);
  }

  static Candidates concatenate(PerThread<Candidates>& parts) {
    std::size_t total = 0;
    for (const Candidates& part : parts) total += part.pairs.size();
    Candidates all;
    all.pairs.reserve(total);
    all.starts.reserve(total);
    for (const Candidates& part : parts) {
      all.pairs.insert(all.pairs.end(), part.pairs.begin(), part.pairs.end());
      all.starts.insert(all.starts.end(), part.starts.begin(), part.starts.end());
    }
    return all;
  }

  /// The candidates of the older scheme: pairs whose boxes overlap at the start or at the end,
  /// sorted, each once.
  std::vector<ScenePair> static_candidates(const SceneOptions& o, SceneStats& stats) {
    PerThread<Candidates> found;
    PerThread<std::uint64_t> culled(0), unused(0);
    for (Span span : {Span::start, Span::end}) {
      for (Mesh& m : meshes) prepare(m, span, o.min_separation, stats);
      const auto at = [span](const Mesh& m) -> const Hierarchies& {
        return m.spans[m.is_static ? 0 : static_cast<int>(span)];
      };
      gather_candidates(
          at, close_mesh_pairs(o, at),
          [&](const ScenePair& p, double start) { found.local().add(p, start); }, culled, false,
          [] { return 1.0; }, unused, o.min_separation);
    }
    stats.cylinder_culled += total(culled);
    std::vector<ScenePair> all = std::move(concatenate(found).pairs);
    tbb::parallel_sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
  }

  static CcdResult decide_query(const VertexFaceQuery& q, const CcdOptions& options) {
    return vertex_face_ccd(q, options);
  }
  static CcdResult decide_query(const EdgeEdgeQuery& q, const CcdOptions& options) {
    return edge_edge_ccd(q, options);
  }
  static CcdResult decide_query(const PointPlaneQuery& q, const CcdOptions& options) {
    return point_plane_ccd(q, options);
  }

  /// The pair's test over [0, options.t_max] (point-edge and point-point as the edge-edge
  /// query of their zero-length segments: exactly point_edge_ccd and point_point_ccd).
  CcdResult test(const ScenePair& p, const CcdOptions& options) const {
    switch (p.type) {
      case QueryType::vertex_face: return vertex_face_ccd(vertex_face(p), options);
      case QueryType::point_plane: return point_plane_ccd(point_plane(p), options);
      default: return edge_edge_ccd(edge_edge(p), options);
    }
  }

  /// The rigid test of a pair involving a rigid body (rigid.hpp).
  RigidCcdResult rigid_test(const ScenePair& p, const CcdOptions& options) const {
    switch (p.type) {
      case QueryType::vertex_face: return vertex_face_ccd(rigid_vertex_face(p), options);
      case QueryType::point_plane: return point_plane_ccd(rigid_point_plane(p), options);
      default: return edge_edge_ccd(rigid_edge_edge(p), options);
    }
  }

  static Decision with_time(const RigidCcdResult& r) {
    return {r.ccd, r.has_time, r.time_lo, r.time_hi};
  }

  /// The pair's answer over [0, options.t_max]: a pair involving a rigid body by the rigid test
  /// of rigid.hpp, any other by `test` (time = s).
  Decision decide(const ScenePair& p, const CcdOptions& options) const {
    if (involves_rigid(p)) return with_time(rigid_test(p, options));
    const CcdResult c = test(p, options);
    return {c, true, c.toi_lo, c.toi_hi};
  }

  SceneResult find_contacts(const SceneOptions& o) {
    if (o.broad_phase == BroadPhase::swept_bvh && !o.record_candidates) return streamed_contacts(o);
    SceneResult result;
    std::vector<ScenePair> candidates = o.broad_phase == BroadPhase::swept_bvh
                                            ? std::move(swept_candidates(o, result.stats).pairs)
                                            : static_candidates(o, result.stats);
    // The narrow phase over a flat list: work stealing balances clusters of costly pairs.
    PerThread<std::vector<SceneContact>> found;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        const predicates::RoundToNearestGuard fp;
                        auto& local = found.local();
                        for (std::size_t k = r.begin(); k != r.end(); ++k) {
                          const Decision d = decide(candidates[k], o.ccd);
                          if (d.ccd.collides) local.push_back(d.contact(candidates[k]));
                        }
                      });
    for (const auto& part : found)
      result.contacts.insert(result.contacts.end(), part.begin(), part.end());
    count(candidates, result.stats);
    result.stats.narrow_phase_tests = candidates.size();
    // Sorted output: the same whatever the number of threads and the order they ran in.
    const auto by_pair = [](const SceneContact& a, const SceneContact& b) { return a.pair < b.pair; };
    tbb::parallel_sort(result.contacts.begin(), result.contacts.end(), by_pair);
    if (o.record_candidates) {
      tbb::parallel_sort(candidates.begin(), candidates.end());
      result.candidates = std::move(candidates);
    }
    result.earliest = earliest_of(result.contacts);
    return result;
  }

  /// find_contacts without a list of candidates: each pair is decided as the traversal meets
  /// it (memory independent of the candidate count; the traversal's tasks spread the work).
  SceneResult streamed_contacts(const SceneOptions& o) {
    SceneResult result;
    struct Local {
      std::vector<SceneContact> contacts;
      SceneStats counts;  // candidates per type
    };
    PerThread<Local> locals;
    const double t_max = o.ccd.t_max;
    swept_candidates(
        prepare_swept(o, result.stats),
        [&](const ScenePair& p, double) {
          Local& local = locals.local();
          ++candidates_of(p.type, local.counts);
          const Decision d = decide(p, o.ccd);
          if (d.ccd.collides) local.contacts.push_back(d.contact(p));
        },
        [t_max] { return t_max; }, result.stats);
    for (const Local& local : locals) {
      result.contacts.insert(result.contacts.end(), local.contacts.begin(), local.contacts.end());
      add_candidates(local.counts, result.stats);
    }
    result.stats.narrow_phase_tests = result.stats.vertex_face_candidates +
                                      result.stats.edge_edge_candidates +
                                      result.stats.point_candidates;
    // Sorted output: the same whatever the number of threads and the order they ran in.
    tbb::parallel_sort(result.contacts.begin(), result.contacts.end(),
                       [](const SceneContact& a, const SceneContact& b) { return a.pair < b.pair; });
    result.earliest = earliest_of(result.contacts);
    return result;
  }

  static std::uint64_t& candidates_of(QueryType type, SceneStats& stats) {
    switch (type) {
      case QueryType::vertex_face: return stats.vertex_face_candidates;
      case QueryType::edge_edge: return stats.edge_edge_candidates;
      default: return stats.point_candidates;
    }
  }
  static void add_candidates(const SceneStats& from, SceneStats& to) {
    to.vertex_face_candidates += from.vertex_face_candidates;
    to.edge_edge_candidates += from.edge_edge_candidates;
    to.point_candidates += from.point_candidates;
  }
  static void count(const std::vector<ScenePair>& candidates, SceneStats& stats) {
    for (const ScenePair& p : candidates) ++candidates_of(p.type, stats);
  }

  /// Smallest toi_lo, ties broken by pair order (`contacts` sorted by pair). A contact's toi_lo
  /// is finite, so starting from the no-contact +infinity needs no special case for none.
  static SceneContact earliest_of(const std::vector<SceneContact>& contacts) {
    SceneContact best;
    for (const SceneContact& c : contacts)
      if (c.toi_lo < best.toi_lo) best = c;
    return best;
  }

  EarliestContact earliest_contact(const SceneOptions& o);

  /// Orders the candidates by their spans' starts in kSpanBuckets buckets of equal width (a
  /// counting sort: linear time, and enough to meet early contacts first), order kept within
  /// a bucket. Nothing to do when every start is 0 (no cull by time).
  static void order_by_span_start(Candidates& c) {
    constexpr int kSpanBuckets = 64;
    if (std::all_of(c.starts.begin(), c.starts.end(), [](double t) { return t == 0.0; })) return;
    const auto bucket = [](double t) {
      return std::min(kSpanBuckets - 1, static_cast<int>(std::max(t, 0.0) * kSpanBuckets));
    };
    std::array<std::size_t, kSpanBuckets + 1> first{};
    for (const double t : c.starts) ++first[bucket(t) + 1];
    for (int b = 0; b < kSpanBuckets; ++b) first[b + 1] += first[b];
    Candidates ordered;
    ordered.pairs.resize(c.pairs.size());
    ordered.starts.resize(c.starts.size());
    for (std::size_t k = 0; k < c.pairs.size(); ++k) {
      const std::size_t at = first[bucket(c.starts[k])]++;
      ordered.pairs[at] = c.pairs[k];
      ordered.starts[at] = c.starts[k];
    }
    c = std::move(ordered);
  }
};

/// The earliest contact with pruning. A shared bound T only decreases; every pair is tested
/// over [0, T] only (after a certified cull over that window). When a test finds contact with
/// interval [lo, hi], T becomes the double just above hi + toi_width: any pair whose contact time
/// exceeds that bound has a toi_lo strictly above the found pair's, so it cannot be the earliest
/// (proofs/scene.md#earliest-contact). Pairs found along the way are decided again with the
/// caller's options at the end, so the answer is exactly find_contacts' earliest, whatever the
/// order in which threads met the pairs.
EarliestContact Scene::Impl::earliest_contact(const SceneOptions& o) {
  EarliestContact out;
  const double t_max = o.ccd.t_max;
  std::atomic<double> bound{t_max};
  // Contacts at t = 0: the smallest pair known to have toi_lo = 0 with the caller's options
  // (its final answer). No pair after it in pair order can be the earliest (a tie at 0 goes to
  // the smaller pair, and no toi_lo is below 0), so such pairs are skipped: a step whose
  // earliest contact is at t = 0 decides only the pairs before the best one found so far.
  // Threads read the shared pair under the lock only when its version has changed.
  std::mutex zero_lock;
  std::atomic<std::uint64_t> zero_version{0};
  ScenePair zero_pair;
  struct Local {
    std::vector<SceneContact> contacts;
    std::uint64_t tests = 0;
    SceneStats counts;  // candidates per type
    std::uint64_t seen_version = 0;
    ScenePair below;  // zero_pair as of seen_version (> 0)
  };
  PerThread<Local> locals;
  // Decides one candidate over [0, bound] (after a certified cull over that window).
  const auto decide_one = [&](const ScenePair& p, Local& local) {
    const double window = bound.load(std::memory_order_relaxed);
    if (zero_version.load(std::memory_order_acquire) != local.seen_version) {
      const std::lock_guard<std::mutex> hold(zero_lock);
      local.seen_version = zero_version.load(std::memory_order_relaxed);
      local.below = zero_pair;
    }
    if (local.seen_version > 0 && !(p < local.below)) return;  // cannot beat a contact at 0
    CcdOptions options = o.ccd;
    // A subnormal bound (a contact at exactly t = 0 was found) is decided over [0, t_max]
    // instead: the same first contact when it lies below the bound, and the filters, whose
    // arithmetic has no room below the smallest normal double, would leave every such pair to
    // the exact path.
    options.t_max = window < std::numeric_limits<double>::min() ? t_max : window;
    // One query per pair: culled over the window when the bound has shrunk, else decided.
    // The window culls hold upward rounding (time_window.hpp), set only when the bound has
    // shrunk (an MXCSR write per pair costs as much as a filtered test).
    const auto culled_over_window = [&](const auto& cull) {
      if (!(window < t_max)) return false;
      const predicates::RoundingGuard upward;
      return cull();
    };
    const auto decide_linear = [&](const auto& query) -> std::optional<CcdResult> {
      if (culled_over_window(
              [&] { return scene::disjoint_over_window(query, window, o.min_separation); }))
        return std::nullopt;
      ++local.tests;
      return decide_query(query, options);
    };
    std::optional<CcdResult> decided;
    if (involves_rigid(p)) {
      // The same over the arcs: certified boxes over [0, window], then the rigid test.
      if (!culled_over_window(
              [&] { return rigid_disjoint_over_window(p, window, o.min_separation); })) {
        ++local.tests;
        decided = rigid_test(p, options).ccd;
      }
    } else if (p.type == QueryType::vertex_face) {
      decided = decide_linear(vertex_face(p));
    } else if (p.type == QueryType::point_plane) {
      decided = decide_linear(point_plane(p));
    } else {
      decided = decide_linear(edge_edge(p));
    }
    if (!decided || !decided->collides) return;
    const CcdResult& r = *decided;
    local.contacts.push_back({p, r.toi_lo, r.toi_hi});
    if (r.toi_lo == 0.0 && options.t_max == t_max) {  // the caller's options: final
      const std::lock_guard<std::mutex> hold(zero_lock);
      if (zero_version.load(std::memory_order_relaxed) == 0 || p < zero_pair) {
        zero_pair = p;
        zero_version.fetch_add(1, std::memory_order_release);
      }
    }
    const double next = std::min(
        t_max,
        std::nextafter(r.toi_hi + o.ccd.toi_width, std::numeric_limits<double>::infinity()));
    double current = bound.load(std::memory_order_relaxed);
    while (next < current && !bound.compare_exchange_weak(current, next)) {
    }
  };
  // One traversal, cut by the bound as it falls: pairs whose spans start at 0 (close at the
  // start: touching, resting, neighbours) are decided as the traversal meets them, so a contact
  // at or near t = 0 shrinks the rest of the traversal at once; the others are kept for later.
  PerThread<Candidates> later;
  const SweptScene swept_scene = prepare_swept(o, out.stats);
  swept_candidates(
      swept_scene,
      [&](const ScenePair& p, double start) {
        Local& local = locals.local();
        ++candidates_of(p.type, local.counts);
        if (start == 0.0)
          decide_one(p, local);
        else
          later.local().add(p, start);
      },
      [&bound] { return bound.load(std::memory_order_relaxed); }, out.stats);
  // Then the rest, earliest span first (in buckets: linear time), so that early contacts lower
  // the bound soon; a pair whose span starts after the bound cannot meet by it and is skipped.
  Candidates rest = concatenate(later);
  order_by_span_start(rest);
  const auto batch = tbb::blocked_range<std::size_t>(0, rest.pairs.size(), 64);
  tbb::parallel_for(batch, [&](const tbb::blocked_range<std::size_t>& range) {
    // A worker may run with the host's FP state (proofs/filters.md#fp-environment).
    const predicates::RoundToNearestGuard fp;
    Local& local = locals.local();
    for (std::size_t k = range.begin(); k != range.end(); ++k)
      if (rest.starts[k] <= bound.load(std::memory_order_relaxed)) decide_one(rest.pairs[k], local);
  });
  const double final_bound = bound.load();
  std::vector<SceneContact> found;
  for (Local& local : locals) {
    out.stats.narrow_phase_tests += local.tests;
    Impl::add_candidates(local.counts, out.stats);
    for (const SceneContact& c : local.contacts)
      if (c.toi_lo <= final_bound) found.push_back(c);
  }
  if (found.empty()) return out;
  // Decide the survivors again over the caller's window: their intervals are then exactly
  // those find_contacts reports.
  for (SceneContact& c : found) c = decide(c.pair, o.ccd).contact(c.pair);
  std::sort(found.begin(), found.end(),
            [](const SceneContact& a, const SceneContact& b) { return a.pair < b.pair; });
  out.collides = true;
  out.contact = earliest_of(found);
  return out;
}

Scene::Scene() : impl_(std::make_unique<Impl>()) {}
Scene::Scene(SceneDimension dimension) : impl_(std::make_unique<Impl>()) {
  if (dimension != SceneDimension::three && dimension != SceneDimension::two)
    throw std::invalid_argument("exactccd: a scene's dimension is three or two");
  impl_->dimension = dimension;
}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

namespace {

/// In a 2D scene every z coordinate is 0 (the plane the scene lives in).
void check_planar(const Positions& x, const char* what) {
  for (Eigen::Index v = 0; v < x.rows(); ++v)
    if (x(v, 2) != 0.0)
      throw std::invalid_argument(std::string("exactccd: a 2D scene lives in the plane z = 0, but ") +
                                  what + " has z = " + shortest_decimal(x(v, 2)) + " at row " +
                                  std::to_string(v));
}

/// An edge as its vertices (smaller first) and its row.
using EdgeRow = std::pair<std::pair<std::int32_t, std::int32_t>, Eigen::Index>;

/// The edges checked (in range, two distinct vertices, none given twice either way round) and
/// sorted by their vertices; messages start with `what` ("exactccd: " or "exactccd: set_edges: ").
std::vector<EdgeRow> checked_sorted_edges(const Edges& edges, Eigen::Index vertex_count,
                                          const std::string& what) {
  if (vertex_count > std::numeric_limits<std::int32_t>::max())
    throw std::invalid_argument(what + "too many vertices in one mesh");
  std::vector<EdgeRow> sorted;
  sorted.reserve(static_cast<std::size_t>(edges.rows()));
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    const std::int32_t a = edges(e, 0), b = edges(e, 1);
    if (a < 0 || a >= vertex_count || b < 0 || b >= vertex_count)
      throw std::invalid_argument(what + "edge " + std::to_string(e) +
                                  " has a vertex index out of range");
    if (a == b) throw std::invalid_argument(what + "edge " + std::to_string(e) + " repeats a vertex");
    sorted.push_back({{std::min(a, b), std::max(a, b)}, e});
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k].first == sorted[k - 1].first)
      throw std::invalid_argument(what + "edge " + std::to_string(sorted[k].second) +
                                  " repeats edge " + std::to_string(sorted[k - 1].second));
  return sorted;
}

/// Marks the vertices on none of the mesh's edges as points.
void mark_points(Mesh& m) {
  m.is_point.assign(static_cast<std::size_t>(m.start.rows()), 1);
  for (Eigen::Index e = 0; e < m.edges.rows(); ++e) {
    m.is_point[static_cast<std::size_t>(m.edges(e, 0))] = 0;
    m.is_point[static_cast<std::size_t>(m.edges(e, 1))] = 0;
  }
  m.has_points = std::find(m.is_point.begin(), m.is_point.end(), 1) != m.is_point.end();
}

}  // namespace

SceneDimension Scene::dimension() const { return impl_->dimension; }

MeshId Scene::add_edge_mesh(const Positions& positions, const Edges& edges) {
  check_positions(positions, "the mesh's positions");
  if (impl_->planar()) check_planar(positions, "the mesh's positions");
  checked_sorted_edges(edges, positions.rows(), "exactccd: ");
  Mesh m;
  m.kind = MeshKind::edges;
  m.start = positions;
  m.end = positions;
  m.edges = edges;
  mark_points(m);
  impl_->meshes.push_back(std::move(m));
  return static_cast<MeshId>(impl_->meshes.size() - 1);
}

MeshId Scene::add_static_edge_mesh(const Positions& positions, const Edges& edges) {
  const MeshId id = add_edge_mesh(positions, edges);
  impl_->meshes[id].is_static = true;
  return id;
}

MeshId Scene::add_points(const Positions& positions) {
  const MeshId id = add_edge_mesh(positions, Edges(0, 2));
  impl_->meshes[id].kind = MeshKind::points;
  return id;
}

MeshId Scene::add_plane(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal) {
  if (impl_->planar())
    throw std::invalid_argument(
        "exactccd: add_plane in a 2D scene (a wall of a 2D scene is a static edge mesh)");
  if (!origin.allFinite() || !normal.allFinite())
    throw std::invalid_argument("exactccd: add_plane: non-finite origin or normal");
  if (normal.isZero(0))
    throw std::invalid_argument("exactccd: add_plane: the normal is zero");
  Mesh m;
  m.kind = MeshKind::plane;
  m.is_static = true;
  m.plane_origin = origin;
  m.plane_normal = normal;
  m.start = Positions(0, 3);
  m.end = m.start;
  m.edges = Edges(0, 2);
  impl_->meshes.push_back(std::move(m));
  return static_cast<MeshId>(impl_->meshes.size() - 1);
}

MeshId Scene::add_mesh(const Positions& positions, const Triangles& triangles) {
  if (impl_->planar())
    throw std::invalid_argument("exactccd: a 2D scene holds edge meshes and point sets, not "
                                "triangle meshes (add_edge_mesh, add_points)");
  check_positions(positions, "the mesh's positions");
  check_triangles(triangles, positions.rows());
  Mesh m;
  m.start = positions;
  m.end = positions;
  m.triangles = triangles;
  m.edges = edges_of(triangles);
  impl_->meshes.push_back(std::move(m));
  return static_cast<MeshId>(impl_->meshes.size() - 1);
}

void Scene::set_edges(MeshId id, const Edges& edges) {
  if (id >= impl_->meshes.size())
    throw std::invalid_argument("exactccd: set_edges: no mesh " + std::to_string(id));
  Mesh& m = impl_->meshes[id];
  if (m.kind != MeshKind::triangles)
    throw std::invalid_argument("exactccd: set_edges: mesh " + std::to_string(id) +
                                " is not a triangle mesh (an edge mesh keeps the edges "
                                "add_edge_mesh was given)");
  const Edges sides = edges_of(m.triangles);  // sorted (i, j), i < j, each side once
  const std::vector<EdgeRow> given =
      checked_sorted_edges(edges, m.start.rows(), "exactccd: set_edges: ");
  Eigen::Index k = 0;  // the next side of the triangles to find
  for (std::size_t g = 0; g < given.size(); ++g) {
    const auto& [side, row] = given[g];  // distinct (checked_sorted_edges)
    while (k < sides.rows() && std::make_pair(sides(k, 0), sides(k, 1)) < side) ++k;
    if (k == sides.rows() || std::make_pair(sides(k, 0), sides(k, 1)) != side)
      throw std::invalid_argument("exactccd: set_edges: edge " + std::to_string(row) + " (" +
                                  std::to_string(side.first) + ", " +
                                  std::to_string(side.second) +
                                  ") is no side of a triangle of mesh " + std::to_string(id));
  }
  if (given.size() != static_cast<std::size_t>(sides.rows())) {
    // Every given edge is a distinct side: some side is missing. Name the first.
    std::size_t g = 0;
    for (Eigen::Index s = 0; s < sides.rows(); ++s, ++g)
      if (g == given.size() || given[g].first != std::make_pair(sides(s, 0), sides(s, 1)))
        throw std::invalid_argument("exactccd: set_edges: the side (" +
                                    std::to_string(sides(s, 0)) + ", " +
                                    std::to_string(sides(s, 1)) + ") of mesh " +
                                    std::to_string(id) + " is missing");
  }
  m.edges = edges;
  for (Hierarchies& h : m.spans) h = Hierarchies{};
  m.cylinder_cache.clear();
}

MeshId Scene::add_static_mesh(const Positions& positions, const Triangles& triangles) {
  const MeshId id = add_mesh(positions, triangles);
  impl_->meshes[id].is_static = true;
  return id;
}

MeshId Scene::add_rigid_body(const Positions& positions, const Triangles& triangles) {
  const MeshId id = add_mesh(positions, triangles);
  impl_->meshes[id].is_rigid = true;
  return id;
}

namespace {

/// The body's mesh for set_rigid_motion, after checking the id, the kind and the motion.
Mesh& rigid_body_for_motion(std::vector<Mesh>& meshes, MeshId id, const RigidMotion& motion) {
  if (id >= meshes.size()) throw std::invalid_argument("exactccd: no mesh " + std::to_string(id));
  Mesh& m = meshes[id];
  if (!m.is_rigid)
    throw std::invalid_argument("exactccd: set_rigid_motion on mesh " + std::to_string(id) +
                                ", which is not a rigid body (add it with add_rigid_body)");
  if (!motion.pivot.allFinite() || !motion.translation.allFinite() ||
      !motion.cayley.allFinite())
    throw std::invalid_argument("exactccd: non-finite pivot, translation or cayley in the rigid "
                                "motion of mesh " + std::to_string(id));
  return m;
}

/// Sets the motion; the end positions (display only) the same whatever the caller's FP state.
void apply_rigid_motion(Mesh& m, const RigidMotion& motion) {
  const predicates::RoundToNearestGuard fp;
  m.motion = motion;
  for (Eigen::Index v = 0; v < m.start.rows(); ++v)
    m.end.row(v) = position_at(motion, row(m.start, static_cast<std::int32_t>(v)), 1.0).transpose();
  for (Hierarchies& h : m.spans) h.stale = true;
}

}  // namespace

void Scene::set_rigid_motion(MeshId id, const RigidMotion& motion) {
  apply_rigid_motion(rigid_body_for_motion(impl_->meshes, id, motion), motion);
}

void Scene::set_rigid_motion(MeshId id, const Positions& start, const RigidMotion& motion) {
  Mesh& m = rigid_body_for_motion(impl_->meshes, id, motion);
  if (start.rows() != m.start.rows())
    throw std::invalid_argument("exactccd: set_rigid_motion needs one row per vertex of the body");
  check_positions(start, "the start positions");
  if (start != m.start) m.cylinder_cache.clear();
  m.start = start;
  apply_rigid_motion(m, motion);
}

void Scene::set_motion(MeshId id, const Positions& start, const Positions& end) {
  impl_->mesh(id);
  Mesh& m = impl_->meshes[id];
  if (m.kind == MeshKind::plane)
    throw std::invalid_argument("exactccd: set_motion on plane " + std::to_string(id) +
                                " (a plane never moves)");
  if (m.is_static) throw std::invalid_argument("exactccd: set_motion on a static mesh");
  if (m.is_rigid)
    throw std::invalid_argument("exactccd: set_motion on rigid body " + std::to_string(id) +
                                " (a rigid body moves with set_rigid_motion)");
  if (start.rows() != m.start.rows() || end.rows() != m.start.rows())
    throw std::invalid_argument("exactccd: set_motion needs one row per vertex of the mesh");
  check_positions(start, "the start positions");
  check_positions(end, "the end positions");
  if (impl_->planar()) {
    check_planar(start, "the start positions");
    check_planar(end, "the end positions");
  }
  m.start = start;
  m.end = end;
  m.cylinder_cache.clear();
  for (Hierarchies& h : m.spans) h.stale = true;
}

std::size_t Scene::mesh_count() const { return impl_->meshes.size(); }
bool Scene::is_static(MeshId id) const { return impl_->mesh(id).is_static; }
bool Scene::is_rigid(MeshId id) const { return impl_->mesh(id).is_rigid; }
bool Scene::is_plane(MeshId id) const { return impl_->mesh(id).kind == MeshKind::plane; }

std::pair<Eigen::Vector3d, Eigen::Vector3d> Scene::plane(MeshId id) const {
  const Mesh& m = impl_->mesh(id);
  if (m.kind != MeshKind::plane)
    throw std::invalid_argument("exactccd: plane(" + std::to_string(id) + "): not a plane");
  return {m.plane_origin, m.plane_normal};
}

const RigidMotion& Scene::rigid_motion(MeshId id) const {
  const Mesh& m = impl_->mesh(id);
  if (!m.is_rigid)
    throw std::invalid_argument("exactccd: rigid_motion of mesh " + std::to_string(id) +
                                ", which is not a rigid body");
  return m.motion;
}
const Triangles& Scene::triangles(MeshId id) const { return impl_->mesh(id).triangles; }
const Edges& Scene::edges(MeshId id) const { return impl_->mesh(id).edges; }
const Positions& Scene::start_positions(MeshId id) const { return impl_->mesh(id).start; }
const Positions& Scene::end_positions(MeshId id) const { return impl_->mesh(id).end; }

namespace {

/// Runs f in an arena of at most max_threads threads (0: the caller's arena).
template <class F>
auto with_threads(int max_threads, F&& f) {
  if (max_threads == 0) return f();
  tbb::task_arena arena(max_threads);
  return arena.execute(f);
}

}  // namespace

SceneResult Scene::find_contacts(const SceneOptions& options) {
  const predicates::RoundToNearestGuard fp;
  check_options(options);
  const SceneOptions o = with_pair_separation(options);
  return with_threads(o.max_threads, [&] { return impl_->find_contacts(o); });
}

EarliestContact Scene::earliest_contact(const SceneOptions& options) {
  const predicates::RoundToNearestGuard fp;
  check_options(options);
  if (options.broad_phase != BroadPhase::swept_bvh)
    throw std::invalid_argument("exactccd: earliest_contact needs the swept_bvh broad phase");
  const SceneOptions o = with_pair_separation(options);
  return with_threads(o.max_threads, [&] { return impl_->earliest_contact(o); });
}

VertexFaceQuery Scene::vertex_face_query(const ScenePair& pair) const {
  if (pair.type != QueryType::vertex_face)
    throw std::invalid_argument(std::string("exactccd: vertex_face_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  if (pair.first_index >= a.start.rows() || pair.second_index >= b.triangles.rows())
    throw std::invalid_argument("exactccd: pair index out of range");
  if (impl_->involves_rigid(pair))
    throw std::invalid_argument(
        "exactccd: vertex_face_query of a pair with a rigid body (use rigid_vertex_face_query)");
  return impl_->vertex_face(pair);
}

namespace {

/// The pair's indices against its meshes' sizes (each kind indexes what it names).
void check_indices(const ScenePair& pair, std::size_t first_count, std::size_t second_count) {
  if (pair.first_index >= first_count || pair.second_index >= second_count)
    throw std::invalid_argument("exactccd: pair index out of range");
}

std::size_t rows_of(const Positions& x) { return static_cast<std::size_t>(x.rows()); }
std::size_t rows_of(const Edges& e) { return static_cast<std::size_t>(e.rows()); }

}  // namespace

PointEdgeQuery Scene::point_edge_query(const ScenePair& pair) const {
  if (pair.type != QueryType::point_edge)
    throw std::invalid_argument(std::string("exactccd: point_edge_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  check_indices(pair, rows_of(a.start), rows_of(b.edges));
  const EdgeEdgeQuery q = impl_->edge_edge(pair);
  return {q.ea0_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.eb0_t1, q.eb1_t1};
}

PointPointQuery Scene::point_point_query(const ScenePair& pair) const {
  if (pair.type != QueryType::point_point)
    throw std::invalid_argument(std::string("exactccd: point_point_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  check_indices(pair, rows_of(a.start), rows_of(b.start));
  const EdgeEdgeQuery q = impl_->edge_edge(pair);
  return {q.ea0_t0, q.eb0_t0, q.ea0_t1, q.eb0_t1};
}

PointPlaneQuery Scene::point_plane_query(const ScenePair& pair) const {
  if (pair.type != QueryType::point_plane)
    throw std::invalid_argument(std::string("exactccd: point_plane_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  if (b.kind != MeshKind::plane)
    throw std::invalid_argument("exactccd: point_plane_query: mesh " +
                                std::to_string(pair.second_mesh) + " is not a plane");
  check_indices(pair, rows_of(a.start), 1);
  if (a.is_rigid)
    throw std::invalid_argument(
        "exactccd: point_plane_query of a rigid body's vertex (use rigid_point_plane_query)");
  return impl_->point_plane(pair);
}

RigidPointPlaneQuery Scene::rigid_point_plane_query(const ScenePair& pair) const {
  if (pair.type != QueryType::point_plane)
    throw std::invalid_argument(std::string("exactccd: rigid_point_plane_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  if (b.kind != MeshKind::plane)
    throw std::invalid_argument("exactccd: rigid_point_plane_query: mesh " +
                                std::to_string(pair.second_mesh) + " is not a plane");
  if (!a.is_rigid)
    throw std::invalid_argument("exactccd: rigid_point_plane_query: mesh " +
                                std::to_string(pair.first_mesh) +
                                " is not a rigid body (use point_plane_query)");
  check_indices(pair, rows_of(a.start), 1);
  return impl_->rigid_point_plane(pair);
}

EdgeEdgeQuery Scene::edge_edge_query(const ScenePair& pair) const {
  if (pair.type != QueryType::edge_edge)
    throw std::invalid_argument(std::string("exactccd: edge_edge_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  if (pair.first_index >= a.edges.rows() || pair.second_index >= b.edges.rows())
    throw std::invalid_argument("exactccd: pair index out of range");
  if (impl_->involves_rigid(pair))
    throw std::invalid_argument(
        "exactccd: edge_edge_query of a pair with a rigid body (use rigid_edge_edge_query)");
  return impl_->edge_edge(pair);
}

RigidVertexFaceQuery Scene::rigid_vertex_face_query(const ScenePair& pair) const {
  if (pair.type != QueryType::vertex_face)
    throw std::invalid_argument(std::string("exactccd: rigid_vertex_face_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  if (pair.first_index >= a.start.rows() || pair.second_index >= b.triangles.rows())
    throw std::invalid_argument("exactccd: pair index out of range");
  return impl_->rigid_vertex_face(pair);
}

ContactGeometry Scene::contact_geometry(const SceneContact& contact,
                                        double min_separation) const {
  const ScenePair& pair = contact.pair;
  CcdResult r;
  r.collides = true;
  r.toi_lo = contact.toi_lo;
  r.toi_hi = contact.toi_hi;
  r.starts_within = contact.starts_within;
  const bool rigid = is_rigid(pair.first_mesh) || is_rigid(pair.second_mesh);
  if (pair.type == QueryType::point_plane) {
    if (!rigid) return exactccd::contact_geometry(point_plane_query(pair), r, min_separation);
    RigidCcdResult rr;
    rr.ccd = r;
    return exactccd::contact_geometry(rigid_point_plane_query(pair), rr, min_separation);
  }
  if (rigid) {
    RigidCcdResult rr;
    rr.ccd = r;
    if (pair.type == QueryType::vertex_face)
      return exactccd::contact_geometry(rigid_vertex_face_query(pair), rr, min_separation);
    return exactccd::contact_geometry(rigid_edge_edge_query(pair), rr, min_separation);
  }
  if (pair.type == QueryType::vertex_face)
    return exactccd::contact_geometry(vertex_face_query(pair), r, min_separation);
  if (pair.type == QueryType::edge_edge)
    return exactccd::contact_geometry(edge_edge_query(pair), r, min_separation);
  // A point as the zero-length segment its test decides (parameter [0, 0] on it).
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  check_indices(pair, rows_of(a.start),
                pair.type == QueryType::point_point ? rows_of(b.start) : rows_of(b.edges));
  return exactccd::contact_geometry(impl_->edge_edge(pair), r, min_separation);
}

RigidEdgeEdgeQuery Scene::rigid_edge_edge_query(const ScenePair& pair) const {
  if (pair.type == QueryType::vertex_face || pair.type == QueryType::point_plane)
    throw std::invalid_argument(std::string("exactccd: rigid_edge_edge_query of a ") +
                                to_string(pair.type) + " pair");
  const Mesh& a = impl_->mesh(pair.first_mesh);
  const Mesh& b = impl_->mesh(pair.second_mesh);
  check_indices(pair, pair.type == QueryType::edge_edge ? rows_of(a.edges) : rows_of(a.start),
                pair.type == QueryType::point_point ? rows_of(b.start) : rows_of(b.edges));
  return impl_->rigid_edge_edge(pair);
}

}  // namespace exactccd
