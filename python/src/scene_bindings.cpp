// The Scene API over numpy arrays: vertices (V, 3) float64, faces (F, 3) integer.
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <mutex>
#include <string>
#include <type_traits>

#include "bindings.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::python {

namespace {

Positions positions_of(const py::handle& object, const char* what) {
  const DoubleArray array = as_double_array(object, {-1, 3}, what);
  Positions positions(array.shape(0), 3);
  std::copy(array.data(), array.data() + array.size(), positions.data());
  return positions;
}

// Index rows (faces: 3 columns, edges: 2) from any integer array, each index checked against
// int32's range before narrowing (a cast would wrap an index around silently); the scene checks
// them against the vertex count. `what` names them in messages ("faces", "edges").
template <class Rows>
Rows index_rows_of(const py::handle& object, const char* what, const char* shape) {
  constexpr int kColumns = Rows::ColsAtCompileTime;
  py::module_ numpy = py::module_::import("numpy");
  const py::array array = numpy.attr("asarray")(object);
  if (array.size() > 0 && !numpy.attr("issubdtype")(array.dtype(), numpy.attr("integer")).cast<bool>())
    throw py::type_error(std::string(what) + " must be an integer array, not of dtype " +
                         std::string(py::str(array.dtype())));
  Rows rows;
  // Unsigned arrays read as uint64 (through int64, 2^64 - 1 would wrap round to -1).
  auto copy = [&](auto signed_or_unsigned) {
    using Index = decltype(signed_or_unsigned);
    const py::array_t<Index, py::array::c_style | py::array::forcecast> indices(array);
    if (indices.ndim() != 2 || indices.shape(1) != kColumns)
      throw py::value_error(std::string(what) + " must have shape " + shape);
    rows.resize(indices.shape(0), kColumns);
    for (py::ssize_t k = 0; k < indices.size(); ++k) {
      const Index v = indices.data()[k];
      const bool negative = std::is_signed_v<Index> && static_cast<std::int64_t>(v) < 0;
      if (negative || v > Index{std::numeric_limits<std::int32_t>::max()})
        throw py::value_error(std::string(what) + ": vertex index " + std::to_string(v) +
                              " out of range (0 to 2147483647, and below the vertex count)");
      // Row-major input, whatever the matrix's storage order.
      rows(k / kColumns, k % kColumns) = static_cast<std::int32_t>(v);
    }
  };
  if (array.dtype().kind() == 'u') copy(std::uint64_t{});
  else copy(std::int64_t{});
  return rows;
}

Triangles triangles_of(const py::handle& object) {
  return index_rows_of<Triangles>(object, "faces", "(F, 3)");
}

template <class Matrix>
py::array copy_to_array(const Matrix& matrix) {
  using Scalar = typename Matrix::Scalar;
  py::array_t<Scalar> array({static_cast<py::ssize_t>(matrix.rows()),
                             static_cast<py::ssize_t>(matrix.cols())});
  std::copy(matrix.data(), matrix.data() + matrix.size(), array.mutable_data());
  return array;
}

BroadPhase parse_broad_phase(const std::string& name) {
  for (const BroadPhase b : {BroadPhase::swept_bvh, BroadPhase::static_bvh})
    if (name == to_string(b)) return b;
  throw py::value_error(std::string("broad_phase must be \"") + to_string(BroadPhase::swept_bvh) +
                        "\" or \"" + to_string(BroadPhase::static_bvh) + "\", not \"" + name +
                        "\"");
}

SceneOptions scene_options(double t_max, double toi_width, const std::string& mode,
                           const std::string& broad_phase, bool self_collision, int max_threads,
                           bool record_candidates, double min_separation) {
  SceneOptions options;
  // The scene's delta is given once, as SceneOptions::min_separation (ccd.min_separation stays
  // 0: the scene sets it for every pair).
  options.ccd = make_options(t_max, toi_width, mode);
  options.min_separation = min_separation;
  options.broad_phase = parse_broad_phase(broad_phase);
  options.self_collision = self_collision;
  if (max_threads < 0 || max_threads > kMaxThreads)
    throw py::value_error("max_threads must be in [0, " + std::to_string(kMaxThreads) +
                          "] (0: every core), not " + std::to_string(max_threads));
  options.max_threads = max_threads;
  options.record_candidates = record_candidates;
  return options;
}

MeshId checked_mesh(const Scene& scene, MeshId mesh) {
  if (mesh >= scene.mesh_count())
    throw py::index_error("no mesh " + std::to_string(mesh) + " (the scene has " +
                          std::to_string(scene.mesh_count()) + ")");
  return mesh;
}

std::string pair_repr(const ScenePair& p) {
  return std::string("ScenePair('") + to_string(p.type) + "', " + std::to_string(p.first_mesh) +
         ", " + std::to_string(p.first_index) + ", " + std::to_string(p.second_mesh) + ", " +
         std::to_string(p.second_index) + ")";
}

std::string contact_repr(const SceneContact& c) {
  char toi[96];
  std::snprintf(toi, sizeof toi, ", toi_lo=%.17g, toi_hi=%.17g)", c.toi_lo, c.toi_hi);
  return "SceneContact(" + pair_repr(c.pair) + toi;
}

// Checks a pair's indices against the scene, which indexes its arrays without checks.
const ScenePair& checked_pair(const Scene& scene, const ScenePair& p) {
  checked_mesh(scene, p.first_mesh);
  checked_mesh(scene, p.second_mesh);
  const bool vf = p.type == QueryType::vertex_face;
  const auto first_count = vf ? scene.start_positions(p.first_mesh).rows()
                              : scene.edges(p.first_mesh).rows();
  const auto second_count = vf ? scene.triangles(p.second_mesh).rows()
                               : scene.edges(p.second_mesh).rows();
  if (p.first_index >= first_count || p.second_index >= second_count)
    throw py::index_error("pair index out of range: " + pair_repr(p));
  return p;
}

// A Scene with a lock: the C++ Scene must not be used from two threads at once, and its calls
// run without the GIL, so calls from several Python threads take turns. The GIL is released
// before the lock is taken (never held while waiting for it).
struct GuardedScene {
  Scene scene;
  std::mutex mutex;

  template <class Call>
  auto run(Call call) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex);
    return call(scene);
  }
};

py::array rows_of(const std::array<Eigen::Vector3d, 8>& points) {
  Positions rows(8, 3);
  for (int r = 0; r < 8; ++r) rows.row(r) = points[r].transpose();
  return copy_to_array(rows);
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<ScenePair>(m, "ScenePair",
                        "A vertex-face pair (vertex first_index of first_mesh, triangle "
                        "second_index of second_mesh) or an edge-edge pair (indices into "
                        "Scene.edges(mesh)).")
      .def(py::init([](const std::string& type, MeshId first_mesh, std::uint32_t first_index,
                       MeshId second_mesh, std::uint32_t second_index) {
             return ScenePair{parse_query_type(type), first_mesh, first_index, second_mesh,
                              second_index};
           }),
           py::arg("type"), py::arg("first_mesh"), py::arg("first_index"),
           py::arg("second_mesh"), py::arg("second_index"))
      .def_property_readonly(
          "type",
          [](const ScenePair& p) {
            // exactccd.QueryType: an enum whose members are also their names as strings.
            return py::module_::import("exactccd").attr("QueryType")(to_string(p.type));
          },
          "exactccd.QueryType.vertex_face or .edge_edge (equal to \"vertex-face\", "
          "\"edge-edge\").")
      .def_readonly("first_mesh", &ScenePair::first_mesh)
      .def_readonly("first_index", &ScenePair::first_index)
      .def_readonly("second_mesh", &ScenePair::second_mesh)
      .def_readonly("second_index", &ScenePair::second_index)
      .def("__eq__", [](const ScenePair& a, const ScenePair& b) { return a == b; })
      .def("__lt__", [](const ScenePair& a, const ScenePair& b) { return a < b; })
      .def("__hash__", [](const ScenePair& p) {
        return py::hash(py::make_tuple(static_cast<int>(p.type), p.first_mesh, p.first_index,
                                       p.second_mesh, p.second_index));
      })
      .def("__repr__", &pair_repr);

  py::class_<SceneContact>(m, "SceneContact",
                           "A colliding pair and its certified TOI interval (in the step's "
                           "parameter s; for a pair with a rigid body the motion parameter of "
                           "its RigidMotion), and the contact time where defined.")
      .def_readonly("pair", &SceneContact::pair)
      .def_readonly("toi_lo", &SceneContact::toi_lo)
      .def_readonly("toi_hi", &SceneContact::toi_hi)
      .def_readonly("has_time", &SceneContact::has_time,
                    "Whether time_lo / time_hi enclose the contact time (always without a rigid "
                    "body; for a rigid body, pure rotations of one rate or no rotation).")
      .def_readonly("time_lo", &SceneContact::time_lo)
      .def_readonly("time_hi", &SceneContact::time_hi)
      .def_readonly("starts_within", &SceneContact::starts_within,
                    "The pair already meets (is within min_separation) at the start: exact.")
      .def("__repr__", &contact_repr);

  py::class_<SceneStats>(m, "SceneStats")
      .def_readonly("vertex_face_candidates", &SceneStats::vertex_face_candidates)
      .def_readonly("edge_edge_candidates", &SceneStats::edge_edge_candidates)
      .def_readonly("narrow_phase_tests", &SceneStats::narrow_phase_tests)
      .def_readonly("hierarchies_built", &SceneStats::hierarchies_built)
      .def_readonly("hierarchies_refitted", &SceneStats::hierarchies_refitted)
      .def_readonly("cylinder_culled", &SceneStats::cylinder_culled)
      .def_readonly("time_culled", &SceneStats::time_culled)
      .def("__repr__", [](const SceneStats& s) {
        return "SceneStats(vertex_face_candidates=" + std::to_string(s.vertex_face_candidates) +
               ", edge_edge_candidates=" + std::to_string(s.edge_edge_candidates) +
               ", narrow_phase_tests=" + std::to_string(s.narrow_phase_tests) +
               ", hierarchies_built=" + std::to_string(s.hierarchies_built) +
               ", hierarchies_refitted=" + std::to_string(s.hierarchies_refitted) +
               ", cylinder_culled=" + std::to_string(s.cylinder_culled) +
               ", time_culled=" + std::to_string(s.time_culled) + ")";
      });

  py::class_<SceneResult>(m, "SceneResult")
      .def_readonly("contacts", &SceneResult::contacts, "Every colliding pair, in pair order.")
      .def_readonly("earliest", &SceneResult::earliest,
                    "The contact with the smallest toi_lo (ties: pair order); without contacts, "
                    "toi_lo = toi_hi = +inf, as in C++.")
      .def_readonly("candidates", &SceneResult::candidates,
                    "Every candidate pair (with record_candidates=True).")
      .def_readonly("stats", &SceneResult::stats);

  py::class_<EarliestContact>(m, "EarliestContact")
      .def_readonly("collides", &EarliestContact::collides)
      .def_readonly("contact", &EarliestContact::contact,
                    "The earliest contact; without one (collides False), toi_lo = toi_hi = +inf, "
                    "as in C++.")
      .def_readonly("stats", &EarliestContact::stats);

  py::class_<GuardedScene>(m, "Scene",
                           "Whole triangle meshes over one time step (exactccd/scene.hpp). Calls "
                           "from several Python threads are serialised.")
      .def(py::init<>())
      .def(
          "add_mesh",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& faces) {
            const Positions positions = positions_of(vertices, "vertices");
            const Triangles triangles = triangles_of(faces);
            return g.run([&](Scene& s) { return s.add_mesh(positions, triangles); });
          },
          py::arg("vertices"), py::arg("faces"),
          "A moving mesh, at rest at `vertices` (V, 3) until set_motion; `faces` (F, 3) vertex "
          "indices. Returns its mesh id.")
      .def(
          "add_static_mesh",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& faces) {
            const Positions positions = positions_of(vertices, "vertices");
            const Triangles triangles = triangles_of(faces);
            return g.run([&](Scene& s) { return s.add_static_mesh(positions, triangles); });
          },
          py::arg("vertices"), py::arg("faces"), "A static mesh. Returns its mesh id.")
      .def(
          "add_rigid_body",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& faces) {
            const Positions positions = positions_of(vertices, "vertices");
            const Triangles triangles = triangles_of(faces);
            return g.run([&](Scene& s) { return s.add_rigid_body(positions, triangles); });
          },
          py::arg("vertices"), py::arg("faces"),
          "A rigid body, at rest at `vertices` (V, 3), its pose at s = 0 in world coordinates, "
          "until set_rigid_motion; never paired with itself. Returns its mesh id.")
      .def(
          "set_rigid_motion",
          [](GuardedScene& g, MeshId body, const py::handle& motion, const py::handle& pivot,
             const py::handle& translation, const py::handle& cayley, const py::handle& start) {
            RigidMotion m;
            if (!motion.is_none()) {
              if (!pivot.is_none() || !translation.is_none() || !cayley.is_none())
                throw py::value_error(
                    "set_rigid_motion: give a RigidMotion or pivot / translation / cayley, "
                    "not both");
              if (!py::isinstance<RigidMotion>(motion))
                throw py::type_error("set_rigid_motion: motion must be an exactccd.RigidMotion");
              m = motion.cast<RigidMotion>();
            } else {
              if (!pivot.is_none()) m.pivot = vector_of(pivot, "pivot");
              if (!translation.is_none()) m.translation = vector_of(translation, "translation");
              if (!cayley.is_none()) m.cayley = vector_of(cayley, "cayley");
            }
            if (start.is_none()) {
              g.run([&](Scene& s) {
                s.set_rigid_motion(checked_mesh(s, body), m);
                return 0;
              });
            } else {
              const Positions from = positions_of(start, "start");
              g.run([&](Scene& s) {
                s.set_rigid_motion(checked_mesh(s, body), from, m);
                return 0;
              });
            }
          },
          py::arg("body"), py::arg("motion") = py::none(), py::kw_only(),
          py::arg("pivot") = py::none(), py::arg("translation") = py::none(),
          py::arg("cayley") = py::none(), py::arg("start") = py::none(),
          "The step's rigid motion of a rigid body: an exactccd.RigidMotion, or its fields as "
          "keywords (zero when left out). The point at x0 is at pivot + s translation + "
          "C(s cayley) (x0 - pivot) for s in [0, 1], cayley = tan(theta / 2) * unit axis (see "
          "RigidMotion.turn). `start` (V, 3): new positions at s = 0 (e.g. the previous step's "
          "end pose), else the current ones. ValueError for a mesh that is not a rigid body or "
          "non-finite input.")
      .def(
          "is_rigid",
          [](GuardedScene& g, MeshId mesh) {
            return g.run([&](Scene& s) { return s.is_rigid(checked_mesh(s, mesh)); });
          },
          py::arg("mesh"))
      .def(
          "rigid_motion",
          [](GuardedScene& g, MeshId body) {
            return g.run([&](Scene& s) { return s.rigid_motion(checked_mesh(s, body)); });
          },
          py::arg("body"), "A rigid body's motion (an exactccd.RigidMotion).")
      .def(
          "set_motion",
          [](GuardedScene& g, MeshId mesh, const py::handle& start, const py::handle& end) {
            const Positions from = positions_of(start, "start"), to = positions_of(end, "end");
            g.run([&](Scene& s) {
              s.set_motion(checked_mesh(s, mesh), from, to);
              return 0;
            });
          },
          py::arg("mesh"), py::arg("start"), py::arg("end"),
          "The step's motion of a moving mesh: vertex i from start[i] to end[i].")
      .def(
          "set_edges",
          [](GuardedScene& g, MeshId mesh, const py::handle& edges) {
            const Edges rows = index_rows_of<Edges>(edges, "edges", "(E, 2)");
            g.run([&](Scene& s) {
              s.set_edges(checked_mesh(s, mesh), rows);
              return 0;
            });
          },
          py::arg("mesh"), py::arg("edges"),
          "The simulator's own edge numbering of a mesh (an (E, 2) integer array holding every "
          "side of its triangles once, any order and orientation, e.g. libigl's edges): edge-edge "
          "pairs index into it from then on.")
      .def_property_readonly("mesh_count",
                             [](GuardedScene& g) {
                               return g.run([](Scene& s) { return s.mesh_count(); });
                             })
      .def(
          "is_static",
          [](GuardedScene& g, MeshId mesh) {
            return g.run([&](Scene& s) { return s.is_static(checked_mesh(s, mesh)); });
          },
          py::arg("mesh"))
      .def(
          "triangles",
          [](GuardedScene& g, MeshId mesh) {
            return copy_to_array(g.run([&](Scene& s) { return s.triangles(checked_mesh(s, mesh)); }));
          },
          py::arg("mesh"), "The mesh's triangles (F, 3), a copy.")
      .def(
          "edges",
          [](GuardedScene& g, MeshId mesh) {
            return copy_to_array(g.run([&](Scene& s) { return s.edges(checked_mesh(s, mesh)); }));
          },
          py::arg("mesh"),
          "The mesh's edges (E, 2), i < j, sorted: the indices of edge-edge pairs (a copy).")
      .def(
          "start_positions",
          [](GuardedScene& g, MeshId mesh) {
            return copy_to_array(
                g.run([&](Scene& s) { return s.start_positions(checked_mesh(s, mesh)); }));
          },
          py::arg("mesh"))
      .def(
          "end_positions",
          [](GuardedScene& g, MeshId mesh) {
            return copy_to_array(
                g.run([&](Scene& s) { return s.end_positions(checked_mesh(s, mesh)); }));
          },
          py::arg("mesh"))
      .def(
          "find_contacts",
          [](GuardedScene& g, double t_max, double toi_width, const std::string& mode,
             const std::string& broad_phase, bool self_collision, int max_threads,
             bool record_candidates, double min_separation) {
            const SceneOptions o =
                scene_options(t_max, toi_width, mode, broad_phase, self_collision, max_threads,
                              record_candidates, min_separation);
            return g.run([&](Scene& s) { return s.find_contacts(o); });
          },
          py::kw_only(), py::arg("t_max") = 1.0, py::arg("toi_width") = 0.0,
          py::arg("mode") = "filtered", py::arg("broad_phase") = "swept_bvh",
          py::arg("self_collision") = true, py::arg("max_threads") = 0,
          py::arg("record_candidates") = false, py::arg("min_separation") = 0.0,
          "Every colliding pair of the step (SceneResult); with min_separation delta > 0, every "
          "pair that comes within delta (rigid bodies included).")
      .def(
          "earliest_contact",
          [](GuardedScene& g, double t_max, double toi_width, const std::string& mode,
             const std::string& broad_phase, bool self_collision, int max_threads,
             bool record_candidates, double min_separation) {
            const SceneOptions o =
                scene_options(t_max, toi_width, mode, broad_phase, self_collision, max_threads,
                              record_candidates, min_separation);
            return g.run([&](Scene& s) { return s.earliest_contact(o); });
          },
          py::kw_only(), py::arg("t_max") = 1.0, py::arg("toi_width") = 0.0,
          py::arg("mode") = "filtered", py::arg("broad_phase") = "swept_bvh",
          py::arg("self_collision") = true, py::arg("max_threads") = 0,
          py::arg("record_candidates") = false, py::arg("min_separation") = 0.0,
          "Only the earliest contact (within min_separation) of the step (EarliestContact; "
          "swept_bvh only).")
      .def(
          "vertex_face_query",
          [](GuardedScene& g, const ScenePair& p) {
            if (p.type != QueryType::vertex_face)
              throw py::value_error("vertex_face_query needs a vertex-face pair");
            const VertexFaceQuery q =
                g.run([&](Scene& s) { return s.vertex_face_query(checked_pair(s, p)); });
            return rows_of({q.p_t0, q.a_t0, q.b_t0, q.c_t0, q.p_t1, q.a_t1, q.b_t1, q.c_t1});
          },
          py::arg("pair"), "The pair's query as an (8, 3) array in the benchmark's row order.")
      .def(
          "edge_edge_query",
          [](GuardedScene& g, const ScenePair& p) {
            if (p.type != QueryType::edge_edge)
              throw py::value_error("edge_edge_query needs an edge-edge pair");
            const EdgeEdgeQuery q =
                g.run([&](Scene& s) { return s.edge_edge_query(checked_pair(s, p)); });
            return rows_of({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1,
                            q.eb1_t1});
          },
          py::arg("pair"), "The pair's query as an (8, 3) array in the benchmark's row order.")
      .def(
          "contact_geometry",
          [](GuardedScene& g, const SceneContact& c, double min_separation) {
            return g.run([&](Scene& s) {
              checked_pair(s, c.pair);
              return s.contact_geometry(c, min_separation);
            });
          },
          py::arg("contact"), py::arg("min_separation") = 0.0,
          "The certified contact geometry (ContactGeometry) of a contact of this scene (from "
          "find_contacts or earliest_contact with min_separation 0).");
}

}  // namespace exactccd::python
