// Scene descriptions, printing, meshes and the brute-force reference shared by
// tests/scene_test.cpp and tests/extreme_scene_test.cpp.
//
// The reference is written from scene.hpp's rules only: every pair the rules allow (vertex-face:
// each vertex of mesh A against each triangle of mesh B; edge-edge: each edge against each later
// edge; never between two static meshes; within one moving mesh only with self_collision and never
// two primitives sharing a vertex) is decided one by one by the public per-pair functions
// vertex_face_ccd / edge_edge_ccd. The edges and the primitives' swept boxes are derived here
// independently of the library, so that its broad phase can be checked to be exact.
#pragma once

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "corpus/random_queries.hpp"  // hex
#include "exactccd/ccd.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

// ---------------------------------------------------------------------------------------------
// Scene descriptions and printing

/// One mesh of a test scene; `end` equals `start` for a static mesh.
struct MeshSpec {
  bool is_static = false;
  Positions start, end;
  Triangles triangles;
};
using SceneSpec = std::vector<MeshSpec>;

inline std::string describe(const ScenePair& p) {
  std::ostringstream s;
  if (p.type == QueryType::vertex_face)
    s << "vertex-face(mesh " << p.first_mesh << " vertex " << p.first_index << ", mesh "
      << p.second_mesh << " triangle " << p.second_index << ")";
  else
    s << "edge-edge(mesh " << p.first_mesh << " edge " << p.first_index << ", mesh "
      << p.second_mesh << " edge " << p.second_index << ")";
  return s.str();
}

inline std::string describe(const SceneContact& c) {
  return describe(c.pair) + " toi [" + hex(c.toi_lo) + ", " + hex(c.toi_hi) + "]";
}

/// The two candidate lists are equal (both sorted); else the counts and the first pair missing
/// on either side.
/// Every pair of `part` is in `all` (both sorted), else the first one missing.
inline ::testing::AssertionResult contains_pairs(const std::vector<ScenePair>& all,
                                                 const std::vector<ScenePair>& part) {
  std::vector<ScenePair> missing;
  std::set_difference(part.begin(), part.end(), all.begin(), all.end(),
                      std::back_inserter(missing));
  if (missing.empty()) return ::testing::AssertionSuccess();
  const ScenePair& p = missing.front();
  return ::testing::AssertionFailure()
         << missing.size() << " of " << part.size() << " pairs missing, first: type "
         << static_cast<int>(p.type) << " meshes " << p.first_mesh << "/" << p.second_mesh
         << " indices " << p.first_index << "/" << p.second_index;
}

inline ::testing::AssertionResult same_pairs(const std::vector<ScenePair>& got,
                                      const std::vector<ScenePair>& want) {
  // Report the first pair missing on either side (both lists are meant to be sorted).
  std::vector<ScenePair> missing, extra;
  std::set_difference(want.begin(), want.end(), got.begin(), got.end(),
                      std::back_inserter(missing));
  std::set_difference(got.begin(), got.end(), want.begin(), want.end(),
                      std::back_inserter(extra));
  if (!missing.empty() || !extra.empty() || got != want) {
    auto f = ::testing::AssertionFailure();
    f << got.size() << " pairs, expected " << want.size() << "; " << missing.size()
      << " missing, " << extra.size() << " extra";
    if (!missing.empty()) f << "; first missing " << describe(missing.front());
    if (!extra.empty()) f << "; first extra " << describe(extra.front());
    if (missing.empty() && extra.empty()) f << "; same set, different order or duplicates";
    return f;
  }
  return ::testing::AssertionSuccess();
}

inline bool same_contact(const SceneContact& a, const SceneContact& b) {
  return a.pair == b.pair && a.toi_lo == b.toi_lo && a.toi_hi == b.toi_hi;
}

inline ::testing::AssertionResult same_contacts(const std::vector<SceneContact>& got,
                                                const std::vector<SceneContact>& want) {
  const std::size_t n = std::min(got.size(), want.size());
  for (std::size_t k = 0; k < n; ++k)
    if (!same_contact(got[k], want[k]))
      return ::testing::AssertionFailure()
             << "contact " << k << " differs: got " << describe(got[k]) << ", expected "
             << describe(want[k]) << " (" << got.size() << " got, " << want.size()
             << " expected)";
  if (got.size() != want.size())
    return ::testing::AssertionFailure()
           << got.size() << " contacts, expected " << want.size() << "; first extra: "
           << (got.size() > n ? "got " + describe(got[n]) : "expected " + describe(want[n]));
  return ::testing::AssertionSuccess();
}

// ---------------------------------------------------------------------------------------------
// The independent reference

/// Distinct triangle sides (i < j), sorted: the header's definition of Scene::edges.
inline Edges derive_edges(const Triangles& triangles) {
  std::set<std::pair<std::int32_t, std::int32_t>> sides;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = triangles(f, k), b = triangles(f, (k + 1) % 3);
      sides.insert({std::min(a, b), std::max(a, b)});
    }
  Edges edges(static_cast<Eigen::Index>(sides.size()), 2);
  Eigen::Index e = 0;
  for (const auto& s : sides) {
    edges(e, 0) = s.first;
    edges(e, 1) = s.second;
    ++e;
  }
  return edges;
}

/// A closed axis-aligned box.
struct Box {
  std::array<double, 3> lo{{std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::infinity()}};
  std::array<double, 3> hi{{-std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity()}};
  void add(const Positions& x, std::int32_t v) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x(v, k));
      hi[k] = std::max(hi[k], x(v, k));
    }
  }
};

inline bool boxes_overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

/// Whether the boxes blended linearly from (a0 to a1) and (b0 to b1) overlap at some t in
/// [0, t_end], decided exactly over the rationals: each of the six conditions lo - hi <= 0 is
/// linear in t, so it holds on [0, r] or [r, 1] (or everywhere, or nowhere), and the boxes
/// overlap exactly where all six hold. The exact reference of the scene's time cull
/// (pipeline/scene/time_span.hpp computes a superset in doubles).
inline bool blended_boxes_meet_by(const Box& a0, const Box& a1, const Box& b0, const Box& b1,
                                  double t_end, double delta = 0.0) {
  const mpq_class d(delta);  // within delta: lo - hi - delta <= 0
  mpq_class lo(0), hi(t_end);
  auto keep = [&](const mpq_class& g0, const mpq_class& g1) {
    if (g0 <= 0 && g1 <= 0) return;
    if (g0 > 0 && g1 > 0) {
      lo = 1, hi = 0;
      return;
    }
    const mpq_class r = g0 / (g0 - g1);
    if (g0 > 0) lo = std::max(lo, r);
    else hi = std::min(hi, r);
  };
  for (int k = 0; k < 3; ++k) {
    keep(mpq_class(a0.lo[k]) - mpq_class(b0.hi[k]) - d,
         mpq_class(a1.lo[k]) - mpq_class(b1.hi[k]) - d);
    keep(mpq_class(b0.lo[k]) - mpq_class(a0.hi[k]) - d,
         mpq_class(b1.lo[k]) - mpq_class(a1.hi[k]) - d);
  }
  return lo <= hi;
}

/// Boxes of a primitive (its vertex list) at the start, at the end, and over the step (start and
/// end positions: each vertex's segment lies in it, hence the primitive at every time).
struct PrimitiveBoxes {
  Box start, end, swept;
};

struct RefMesh {
  const MeshSpec* spec = nullptr;
  Edges edges;
  std::vector<PrimitiveBoxes> vertex_boxes, edge_boxes, face_boxes;
};

inline PrimitiveBoxes boxes_of(const MeshSpec& m, std::initializer_list<std::int32_t> vertices) {
  PrimitiveBoxes b;
  for (std::int32_t v : vertices) {
    b.start.add(m.start, v);
    b.end.add(m.end, v);
    b.swept.add(m.start, v);
    b.swept.add(m.end, v);
  }
  return b;
}

/// The reference's view of `spec`, which must outlive it.
inline std::vector<RefMesh> prepare_reference(const SceneSpec& spec) {
  std::vector<RefMesh> meshes(spec.size());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    const MeshSpec& m = spec[i];
    RefMesh& r = meshes[i];
    r.spec = &m;
    r.edges = derive_edges(m.triangles);
    for (Eigen::Index v = 0; v < m.start.rows(); ++v)
      r.vertex_boxes.push_back(boxes_of(m, {static_cast<std::int32_t>(v)}));
    for (Eigen::Index e = 0; e < r.edges.rows(); ++e)
      r.edge_boxes.push_back(boxes_of(m, {r.edges(e, 0), r.edges(e, 1)}));
    for (Eigen::Index f = 0; f < m.triangles.rows(); ++f)
      r.face_boxes.push_back(
          boxes_of(m, {m.triangles(f, 0), m.triangles(f, 1), m.triangles(f, 2)}));
  }
  return meshes;
}

/// Calls f(pair, first boxes, second boxes) for every pair the scene's rules allow, in ScenePair
/// order (vertex-face before edge-edge, then first_mesh, first_index, second_mesh, second_index).
template <class F>
void for_each_allowed_pair(const std::vector<RefMesh>& meshes, bool self_collision, F&& f) {
  const auto mesh_count = static_cast<MeshId>(meshes.size());
  auto allowed_meshes = [&](MeshId a, MeshId b) {
    const bool sa = meshes[a].spec->is_static, sb = meshes[b].spec->is_static;
    if (a != b) return !(sa && sb);
    return self_collision && !sa;
  };
  for (MeshId a = 0; a < mesh_count; ++a)
    for (std::uint32_t v = 0; v < meshes[a].vertex_boxes.size(); ++v)
      for (MeshId b = 0; b < mesh_count; ++b) {
        if (!allowed_meshes(a, b)) continue;
        const Triangles& t = meshes[b].spec->triangles;
        for (std::uint32_t tri = 0; tri < meshes[b].face_boxes.size(); ++tri) {
          const auto vi = static_cast<std::int32_t>(v);
          if (a == b && (t(tri, 0) == vi || t(tri, 1) == vi || t(tri, 2) == vi)) continue;
          f(ScenePair{QueryType::vertex_face, a, v, b, tri}, meshes[a].vertex_boxes[v],
            meshes[b].face_boxes[tri]);
        }
      }
  for (MeshId a = 0; a < mesh_count; ++a)
    for (std::uint32_t i = 0; i < meshes[a].edge_boxes.size(); ++i)
      for (MeshId b = a; b < mesh_count; ++b) {
        if (!allowed_meshes(a, b)) continue;
        const Edges& ea = meshes[a].edges;
        const Edges& eb = meshes[b].edges;
        for (std::uint32_t j = (a == b ? i + 1 : 0); j < meshes[b].edge_boxes.size(); ++j) {
          if (a == b && (ea(i, 0) == eb(j, 0) || ea(i, 0) == eb(j, 1) || ea(i, 1) == eb(j, 0) ||
                         ea(i, 1) == eb(j, 1)))
            continue;
          f(ScenePair{QueryType::edge_edge, a, i, b, j}, meshes[a].edge_boxes[i],
            meshes[b].edge_boxes[j]);
        }
      }
}

inline Eigen::Vector3d point(const Positions& x, std::int32_t v) { return x.row(v).transpose(); }

inline VertexFaceQuery reference_vertex_face_query(const std::vector<RefMesh>& meshes,
                                                   const ScenePair& p) {
  const MeshSpec& a = *meshes[p.first_mesh].spec;
  const MeshSpec& b = *meshes[p.second_mesh].spec;
  const auto v = static_cast<std::int32_t>(p.first_index);
  const auto f = static_cast<Eigen::Index>(p.second_index);
  return {point(a.start, v),
          point(b.start, b.triangles(f, 0)),
          point(b.start, b.triangles(f, 1)),
          point(b.start, b.triangles(f, 2)),
          point(a.end, v),
          point(b.end, b.triangles(f, 0)),
          point(b.end, b.triangles(f, 1)),
          point(b.end, b.triangles(f, 2))};
}

inline EdgeEdgeQuery reference_edge_edge_query(const std::vector<RefMesh>& meshes,
                                               const ScenePair& p) {
  const MeshSpec& a = *meshes[p.first_mesh].spec;
  const MeshSpec& b = *meshes[p.second_mesh].spec;
  const Edges& ea = meshes[p.first_mesh].edges;
  const Edges& eb = meshes[p.second_mesh].edges;
  const auto i = static_cast<Eigen::Index>(p.first_index);
  const auto j = static_cast<Eigen::Index>(p.second_index);
  return {point(a.start, ea(i, 0)), point(a.start, ea(i, 1)), point(b.start, eb(j, 0)),
          point(b.start, eb(j, 1)), point(a.end, ea(i, 0)),   point(a.end, ea(i, 1)),
          point(b.end, eb(j, 0)),   point(b.end, eb(j, 1))};
}

struct Reference {
  std::uint64_t vertex_face_pairs = 0, edge_edge_pairs = 0;
  /// Colliding pairs, in ScenePair order, each with its per-pair TOI.
  std::vector<SceneContact> contacts;
  /// The subset whose boxes overlap at t = 0 or at t = 1 (what static_bvh can see).
  std::vector<SceneContact> instant_contacts;
  /// Pairs whose closed swept boxes overlap (the exact swept broad phase).
  std::vector<ScenePair> swept_overlaps;
  /// The subset whose boxes blended from start to end overlap at some t in [0, t_max]
  /// (blended_boxes_meet_by): the swept broad phase with its time cull keeps at least these.
  std::vector<ScenePair> timed_overlaps;
  /// Pairs whose closed boxes overlap at the start or at the end of the step.
  std::vector<ScenePair> instant_overlaps;
};

/// Every allowed pair decided by the per-pair function with `ccd`.
inline Reference brute_force(const std::vector<RefMesh>& meshes, const CcdOptions& ccd,
                             bool self_collision) {
  Reference r;
  for_each_allowed_pair(
      meshes, self_collision, [&](const ScenePair& p, const PrimitiveBoxes& a,
                                  const PrimitiveBoxes& b) {
        const CcdResult c =
            p.type == QueryType::vertex_face
                ? vertex_face_ccd(reference_vertex_face_query(meshes, p), ccd)
                : edge_edge_ccd(reference_edge_edge_query(meshes, p), ccd);
        (p.type == QueryType::vertex_face ? r.vertex_face_pairs : r.edge_edge_pairs)++;
        const bool instant = boxes_overlap(a.start, b.start) || boxes_overlap(a.end, b.end);
        if (boxes_overlap(a.swept, b.swept)) {
          r.swept_overlaps.push_back(p);
          if (blended_boxes_meet_by(a.start, a.end, b.start, b.end, ccd.t_max))
            r.timed_overlaps.push_back(p);
        }
        if (instant) r.instant_overlaps.push_back(p);
        if (c.collides) {
          r.contacts.push_back({p, c.toi_lo, c.toi_hi});
          if (instant) r.instant_contacts.push_back(r.contacts.back());
        }
      });
  return r;
}

/// The smallest toi_lo, ties broken by pair order (the list is in pair order).
inline SceneContact earliest_of(const std::vector<SceneContact>& contacts) {
  SceneContact best = contacts.front();
  for (const SceneContact& c : contacts)
    if (c.toi_lo < best.toi_lo) best = c;
  return best;
}

// ---------------------------------------------------------------------------------------------
// Building scenes

inline Scene make_scene(const SceneSpec& spec) {
  Scene scene;
  for (const MeshSpec& m : spec) {
    if (m.is_static) {
      scene.add_static_mesh(m.start, m.triangles);
    } else {
      const MeshId id = scene.add_mesh(m.start, m.triangles);
      scene.set_motion(id, m.start, m.end);
    }
  }
  return scene;
}

/// An nx x ny grid of vertices origin + i/(nx-1) u + j/(ny-1) v, each quad split in two; nx - 1
/// and ny - 1 powers of two keep dyadic coordinates dyadic.
inline MeshSpec grid(int nx, int ny, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                     const Eigen::Vector3d& v) {
  MeshSpec m;
  m.start.resize(nx * ny, 3);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      m.start.row(i + nx * j) =
          (origin + (double(i) / (nx - 1)) * u + (double(j) / (ny - 1)) * v).transpose();
  m.triangles.resize(2 * (nx - 1) * (ny - 1), 3);
  int f = 0;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = i + nx * j, b = a + 1, c = a + 1 + nx, d = a + nx;
      m.triangles.row(f++) << a, b, c;
      m.triangles.row(f++) << a, c, d;
    }
  m.end = m.start;
  return m;
}

/// The box [lo, hi] as 8 vertices and 12 outward triangles.
inline MeshSpec box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  MeshSpec m;
  m.start.resize(8, 3);
  for (int k = 0; k < 8; ++k)
    m.start.row(k) << ((k & 1) ? hi.x() : lo.x()), ((k & 2) ? hi.y() : lo.y()),
        ((k & 4) ? hi.z() : lo.z());
  m.triangles.resize(12, 3);
  m.triangles << 0, 2, 1, 1, 2, 3,  // z = lo
      4, 5, 6, 5, 7, 6,             // z = hi
      0, 1, 4, 1, 5, 4,             // y = lo
      2, 6, 3, 3, 6, 7,             // y = hi
      0, 4, 2, 2, 4, 6,             // x = lo
      1, 3, 5, 3, 7, 5;             // x = hi
  m.end = m.start;
  return m;
}

/// The same scene with every coordinate multiplied by `factor` (rounded unless a power of two).
inline SceneSpec scaled(SceneSpec spec, double factor) {
  for (MeshSpec& m : spec) {
    m.start *= factor;
    m.end *= factor;
  }
  return spec;
}

}  // namespace exactccd::test
