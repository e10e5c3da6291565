// The Scene API over numpy arrays: vertices (V, 3) float64 ((V, 2) too in a 2D scene), faces
// (F, 3) and edges (E, 2) integer.
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
/// Scene's `dimension` argument: any Python object, checked by parse_dimension (ValueError for
/// anything but 3 or 2, floats and strings included), shown as "int" in signatures.
struct DimensionArgument {
  pybind11::object value;
};
}  // namespace exactccd::python

namespace pybind11::detail {
template <>
struct type_caster<exactccd::python::DimensionArgument> {
  PYBIND11_TYPE_CASTER(exactccd::python::DimensionArgument, const_name("int"));
  bool load(handle source, bool) {
    value.value = reinterpret_borrow<object>(source);
    return true;
  }
};
}  // namespace pybind11::detail

namespace exactccd::python {

namespace {

Positions positions_of(const py::handle& object, const char* what) {
  const DoubleArray array = as_double_array(object, {-1, 3}, what);
  Positions positions(array.shape(0), 3);
  std::copy(array.data(), array.data() + array.size(), positions.data());
  return positions;
}

// Positions of a scene of the given dimension: (V, 3) in 3D; (V, 3) or (V, 2) in 2D, a (V, 2)
// array embedded in the plane z = 0 (appending the double 0 rounds nothing; the scene checks
// that a (V, 3) array's z are 0).
Positions positions_of(const py::handle& object, const char* what, SceneDimension dimension) {
  if (dimension == SceneDimension::three) return positions_of(object, what);
  py::module_ numpy = py::module_::import("numpy");
  const DoubleArray array = DoubleArray::ensure(
      numpy.attr("ascontiguousarray")(object, py::arg("dtype") = numpy.attr("float64")));
  if (!array) throw py::type_error(std::string(what) + " must be an array of numbers");
  const py::ssize_t columns = array.ndim() == 2 ? array.shape(1) : 0;
  if (columns != 2 && columns != 3) {
    std::string got = "(";
    for (py::ssize_t k = 0; k < array.ndim(); ++k)
      got += (k > 0 ? ", " : "") + std::to_string(array.shape(k));
    throw py::value_error(std::string(what) + " must have shape (N, 2) or (N, 3) in a 2D "
                          "scene, not " + got + (array.ndim() == 1 ? ",)" : ")"));
  }
  Positions positions = Positions::Zero(array.shape(0), 3);
  for (py::ssize_t v = 0; v < array.shape(0); ++v)
    for (py::ssize_t k = 0; k < columns; ++k) positions(v, k) = array.data()[v * columns + k];
  return positions;
}

// The Python name of a dimension (3 or 2) and back.
int dimension_number(SceneDimension dimension) {
  return dimension == SceneDimension::two ? 2 : 3;
}

SceneDimension parse_dimension(const py::handle& object) {
  // An int (or numpy integer), not a bool or a float: Scene(2.5) is no dimension.
  const bool integral =
      !py::isinstance<py::bool_>(object) &&
      py::isinstance(object, py::module_::import("numbers").attr("Integral"));
  if (integral) {
    const py::int_ value(py::reinterpret_borrow<py::object>(object));
    if (value.equal(py::int_(3))) return SceneDimension::three;
    if (value.equal(py::int_(2))) return SceneDimension::two;
  }
  throw py::value_error("Scene(): dimension must be 3 or 2, not " +
                        std::string(py::repr(object)));
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

// A scene pair's type: the query-file names ("vertex-face" / "vf", "edge-edge" / "ee", as
// parse_query_type) and the point kinds of scenes ("point-edge" / "pe", "point-point" / "pp",
// "point-plane" / "pl", the primitive query files' kind names), or an exactccd.QueryType (a str).
QueryType parse_pair_type(const std::string& name) {
  for (const QueryType t : {QueryType::vertex_face, QueryType::edge_edge, QueryType::point_edge,
                            QueryType::point_point, QueryType::point_plane})
    if (name == to_string(t)) return t;
  if (name == "vf") return QueryType::vertex_face;
  if (name == "ee") return QueryType::edge_edge;
  if (name == "pe") return QueryType::point_edge;
  if (name == "pp") return QueryType::point_point;
  if (name == "pl") return QueryType::point_plane;
  throw py::value_error("type must be \"vertex-face\" (\"vf\"), \"edge-edge\" (\"ee\"), "
                        "\"point-edge\" (\"pe\"), \"point-point\" (\"pp\") or \"point-plane\" "
                        "(\"pl\"), not \"" + name + "\"");
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

// Checks a pair's indices against the scene, which indexes its arrays without checks: per
// type, first_index a vertex (an edge for edge-edge) of first_mesh, second_index a triangle
// (vertex-face), an edge (edge-edge, point-edge) or a vertex (point-point) of second_mesh; a
// point-plane pair's second_mesh must be a plane and its second_index 0.
const ScenePair& checked_pair(const Scene& scene, const ScenePair& p) {
  checked_mesh(scene, p.first_mesh);
  checked_mesh(scene, p.second_mesh);
  const auto vertices = [&](MeshId m) { return scene.start_positions(m).rows(); };
  const auto edges = [&](MeshId m) { return scene.edges(m).rows(); };
  Eigen::Index first_count = 0, second_count = 0;
  switch (p.type) {
    case QueryType::vertex_face:
      first_count = vertices(p.first_mesh);
      second_count = scene.triangles(p.second_mesh).rows();
      break;
    case QueryType::edge_edge:
      first_count = edges(p.first_mesh);
      second_count = edges(p.second_mesh);
      break;
    case QueryType::point_edge:
      first_count = vertices(p.first_mesh);
      second_count = edges(p.second_mesh);
      break;
    case QueryType::point_point:
      first_count = vertices(p.first_mesh);
      second_count = vertices(p.second_mesh);
      break;
    case QueryType::point_plane:
      if (!scene.is_plane(p.second_mesh))
        throw py::value_error("mesh " + std::to_string(p.second_mesh) +
                              " is not a plane (Scene.add_plane): " + pair_repr(p));
      first_count = vertices(p.first_mesh);
      second_count = 1;  // a plane's only index
      break;
  }
  if (p.first_index >= first_count || p.second_index >= second_count)
    throw py::index_error("pair index out of range: " + pair_repr(p));
  return p;
}

// A Scene with a lock: the C++ Scene must not be used from two threads at once, and its calls
// run without the GIL, so calls from several Python threads take turns. The GIL is released
// before the lock is taken (never held while waiting for it).
struct GuardedScene {
  explicit GuardedScene(SceneDimension d) : scene(d), dimension(d) {}

  Scene scene;
  const SceneDimension dimension;  // never changes: read without the lock
  std::mutex mutex;

  template <class Call>
  auto run(Call call) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex);
    return call(scene);
  }
};

template <std::size_t N>
py::array rows_of(const std::array<Eigen::Vector3d, N>& points) {
  Positions rows(static_cast<Eigen::Index>(N), 3);
  for (std::size_t r = 0; r < N; ++r)
    rows.row(static_cast<Eigen::Index>(r)) = points[r].transpose();
  return copy_to_array(rows);
}

py::array vector_array(const Eigen::Vector3d& v) {
  py::array_t<double> array(3);
  std::copy(v.data(), v.data() + 3, array.mutable_data());
  return array;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<ScenePair>(m, "ScenePair",
                        "A pair of primitives of a Scene: vertex-face (vertex first_index of "
                        "first_mesh, triangle second_index of second_mesh), edge-edge (indices "
                        "into Scene.edges(mesh)), point-edge (vertex first_index, edge "
                        "second_index), point-point (vertex first_index, vertex second_index) or "
                        "point-plane (vertex first_index, the plane second_mesh, second_index "
                        "0). ScenePair(type, first_mesh, first_index, second_mesh, "
                        "second_index), type a QueryType or its name (\"vertex-face\" / \"vf\", "
                        "\"edge-edge\" / \"ee\", \"point-edge\" / \"pe\", \"point-point\" / "
                        "\"pp\", \"point-plane\" / \"pl\").")
      .def(py::init([](const std::string& type, MeshId first_mesh, std::uint32_t first_index,
                       MeshId second_mesh, std::uint32_t second_index) {
             return ScenePair{parse_pair_type(type), first_mesh, first_index, second_mesh,
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
          "The pair's kind, an exactccd.QueryType: .vertex_face, .edge_edge, .point_edge, "
          ".point_point or .point_plane (equal to \"vertex-face\", \"edge-edge\", "
          "\"point-edge\", \"point-point\", \"point-plane\").")
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
      .def_readonly("point_candidates", &SceneStats::point_candidates,
                    "Point-edge, point-point and point-plane pairs that reached the narrow "
                    "phase.")
      .def_readonly("narrow_phase_tests", &SceneStats::narrow_phase_tests)
      .def_readonly("hierarchies_built", &SceneStats::hierarchies_built)
      .def_readonly("hierarchies_refitted", &SceneStats::hierarchies_refitted)
      .def_readonly("cylinder_culled", &SceneStats::cylinder_culled)
      .def_readonly("time_culled", &SceneStats::time_culled)
      .def("__repr__", [](const SceneStats& s) {
        return "SceneStats(vertex_face_candidates=" + std::to_string(s.vertex_face_candidates) +
               ", edge_edge_candidates=" + std::to_string(s.edge_edge_candidates) +
               ", point_candidates=" + std::to_string(s.point_candidates) +
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
                           "Meshes over one time step (exactccd/scene.hpp): triangle meshes, "
                           "edge meshes (rods), point sets, rigid bodies and static planes in 3D; "
                           "edge meshes and point sets in the plane z = 0 in a 2D scene "
                           "(Scene(dimension=2)). Calls from several Python threads are "
                           "serialised.")
      // Scene() and Scene(dimension), as C++'s two constructors (pybind11 lists both in the
      // message for wrong arguments).
      .def(py::init([] { return std::make_unique<GuardedScene>(SceneDimension::three); }),
           "An empty 3D scene.")
      .def(py::init([](const DimensionArgument& dimension) {
             return std::make_unique<GuardedScene>(parse_dimension(dimension.value));
           }),
           py::arg("dimension"),
           "An empty scene: dimension 3 (the default) or 2 (the plane z = 0: add_edge_mesh and "
           "add_points only; vertex arrays (V, 2), or (V, 3) with every z 0). ValueError for "
           "another dimension.")
      .def_property_readonly(
          "dimension", [](GuardedScene& g) { return dimension_number(g.dimension); },
          "3, or 2 for a scene in the plane z = 0.")
      .def(
          "add_mesh",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& faces) {
            const Positions positions = positions_of(vertices, "vertices", g.dimension);
            const Triangles triangles = triangles_of(faces);
            return g.run([&](Scene& s) { return s.add_mesh(positions, triangles); });
          },
          py::arg("vertices"), py::arg("faces"),
          "A moving mesh, at rest at `vertices` (V, 3) until set_motion; `faces` (F, 3) vertex "
          "indices. Returns its mesh id.")
      .def(
          "add_static_mesh",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& faces) {
            const Positions positions = positions_of(vertices, "vertices", g.dimension);
            const Triangles triangles = triangles_of(faces);
            return g.run([&](Scene& s) { return s.add_static_mesh(positions, triangles); });
          },
          py::arg("vertices"), py::arg("faces"), "A static mesh. Returns its mesh id.")
      .def(
          "add_rigid_body",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& faces) {
            const Positions positions = positions_of(vertices, "vertices", g.dimension);
            const Triangles triangles = triangles_of(faces);
            return g.run([&](Scene& s) { return s.add_rigid_body(positions, triangles); });
          },
          py::arg("vertices"), py::arg("faces"),
          "A rigid body, at rest at `vertices` (V, 3), its pose at s = 0 in world coordinates, "
          "until set_rigid_motion; never paired with itself. Returns its mesh id.")
      .def(
          "add_edge_mesh",
          [](GuardedScene& g, const py::handle& vertices, const py::handle& edges,
             bool is_static) {
            const Positions positions = positions_of(vertices, "vertices", g.dimension);
            const Edges rows = index_rows_of<Edges>(edges, "edges", "(E, 2)");
            return g.run([&](Scene& s) {
              return is_static ? s.add_static_edge_mesh(positions, rows)
                               : s.add_edge_mesh(positions, rows);
            });
          },
          py::arg("vertices"), py::arg("edges"), py::arg("static") = false,
          "A mesh of edges only (rods, hair, seams; polylines in a 2D scene): `vertices` (V, 3) "
          "(in a 2D scene (V, 2) too, or (V, 3) with z = 0), `edges` (E, 2) vertex indices, "
          "two distinct per row, none twice; Scene.edges(mesh) is `edges` as given (the indices "
          "of its edge pairs). Vertices on no edge are points. static=False: moving, at rest "
          "until set_motion; static=True: one set of positions for every step. Returns its "
          "mesh id.")
      .def(
          "add_points",
          [](GuardedScene& g, const py::handle& vertices) {
            const Positions positions = positions_of(vertices, "vertices", g.dimension);
            return g.run([&](Scene& s) { return s.add_points(positions); });
          },
          py::arg("vertices"),
          "A moving point set (particles), at rest at `vertices` (V, 3) (in a 2D scene (V, 2) "
          "too, or (V, 3) with z = 0) until set_motion. Returns its mesh id.")
      .def(
          "add_plane",
          [](GuardedScene& g, const py::handle& origin, const py::handle& normal) {
            const Eigen::Vector3d o = vector_of(origin, "origin");
            const Eigen::Vector3d n = vector_of(normal, "normal");
            return g.run([&](Scene& s) { return s.add_plane(o, n); });
          },
          py::arg("origin"), py::arg("normal"),
          "A static infinite plane {x : (x - origin) . normal = 0} (a floor; 3D scenes only): "
          "every vertex of every moving mesh is paired with it (point-plane pairs, decided as "
          "point_plane_ccd). `normal` any non-zero finite length. A mesh of no vertices; rigid "
          "bodies cannot meet a plane yet (find_contacts refuses a scene with both). ValueError "
          "for a non-finite value, a zero normal or a 2D scene. Returns its mesh id.")
      .def(
          "is_plane",
          [](GuardedScene& g, MeshId mesh) {
            return g.run([&](Scene& s) { return s.is_plane(checked_mesh(s, mesh)); });
          },
          py::arg("mesh"), "Whether the mesh was added by add_plane.")
      .def(
          "plane",
          [](GuardedScene& g, MeshId mesh) {
            const auto [origin, normal] =
                g.run([&](Scene& s) { return s.plane(checked_mesh(s, mesh)); });
            return py::make_tuple(vector_array(origin), vector_array(normal));
          },
          py::arg("mesh"),
          "A plane's (origin, normal) as given to add_plane, two float64 arrays of shape (3,). "
          "ValueError for a mesh that is not a plane.")
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
              const Positions from = positions_of(start, "start", g.dimension);
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
            const Positions from = positions_of(start, "start", g.dimension),
                            to = positions_of(end, "end", g.dimension);
            g.run([&](Scene& s) {
              s.set_motion(checked_mesh(s, mesh), from, to);
              return 0;
            });
          },
          py::arg("mesh"), py::arg("start"), py::arg("end"),
          "The step's motion of a moving mesh (triangle mesh, edge mesh or point set): vertex "
          "i from start[i] to end[i], (V, 3) arrays (in a 2D scene (V, 2) too, or (V, 3) with "
          "z = 0).")
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
          "The mesh's edges (E, 2), a copy: the indices of its edge-edge and point-edge pairs. "
          "For a triangle mesh its sides, i < j, sorted (or as given to set_edges); for an edge "
          "mesh the edges as given to add_edge_mesh; none for a point set or a plane.")
      .def(
          "start_positions",
          [](GuardedScene& g, MeshId mesh) {
            return copy_to_array(
                g.run([&](Scene& s) { return s.start_positions(checked_mesh(s, mesh)); }));
          },
          py::arg("mesh"),
          "The positions at the start of the step, (V, 3), a copy; in a 2D scene too (V, 3), "
          "z = 0 (take [:, :2] for the plane's coordinates); (0, 3) for a plane.")
      .def(
          "end_positions",
          [](GuardedScene& g, MeshId mesh) {
            return copy_to_array(
                g.run([&](Scene& s) { return s.end_positions(checked_mesh(s, mesh)); }));
          },
          py::arg("mesh"),
          "The positions at the end of the step, (V, 3) as start_positions (the start "
          "positions for a static mesh).")
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
          "Every colliding pair of the step (SceneResult): vertex-face, edge-edge, point-edge, "
          "point-point and point-plane pairs; with min_separation delta > 0, every pair that "
          "comes within delta (rigid bodies included). ValueError for a scene with both a "
          "plane and a rigid body.")
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
            return rows_of<8>({q.p_t0, q.a_t0, q.b_t0, q.c_t0, q.p_t1, q.a_t1, q.b_t1, q.c_t1});
          },
          py::arg("pair"), "The pair's query as an (8, 3) array in the benchmark's row order.")
      .def(
          "edge_edge_query",
          [](GuardedScene& g, const ScenePair& p) {
            if (p.type != QueryType::edge_edge)
              throw py::value_error("edge_edge_query needs an edge-edge pair");
            const EdgeEdgeQuery q =
                g.run([&](Scene& s) { return s.edge_edge_query(checked_pair(s, p)); });
            return rows_of<8>({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1,
                            q.eb1_t1});
          },
          py::arg("pair"), "The pair's query as an (8, 3) array in the benchmark's row order.")
      .def(
          "point_edge_query",
          [](GuardedScene& g, const ScenePair& p) {
            if (p.type != QueryType::point_edge)
              throw py::value_error("point_edge_query needs a point-edge pair");
            const PointEdgeQuery q =
                g.run([&](Scene& s) { return s.point_edge_query(checked_pair(s, p)); });
            return rows_of<6>({q.p_t0, q.e0_t0, q.e1_t0, q.p_t1, q.e0_t1, q.e1_t1});
          },
          py::arg("pair"),
          "The pair's query as a (6, 3) array, rows p, e0, e1 at t0 then at t1 (as "
          "point_edge_ccd takes it; in a 2D scene z = 0).")
      .def(
          "point_point_query",
          [](GuardedScene& g, const ScenePair& p) {
            if (p.type != QueryType::point_point)
              throw py::value_error("point_point_query needs a point-point pair");
            const PointPointQuery q =
                g.run([&](Scene& s) { return s.point_point_query(checked_pair(s, p)); });
            return rows_of<4>({q.p_t0, q.q_t0, q.p_t1, q.q_t1});
          },
          py::arg("pair"),
          "The pair's query as a (4, 3) array, rows p, q at t0 then at t1 (as point_point_ccd "
          "takes it; in a 2D scene z = 0).")
      .def(
          "point_plane_query",
          [](GuardedScene& g, const ScenePair& p) {
            if (p.type != QueryType::point_plane)
              throw py::value_error("point_plane_query needs a point-plane pair");
            const PointPlaneQuery q =
                g.run([&](Scene& s) { return s.point_plane_query(checked_pair(s, p)); });
            return rows_of<6>(
                {q.p_t0, q.origin_t0, q.normal_t0, q.p_t1, q.origin_t1, q.normal_t1});
          },
          py::arg("pair"),
          "The pair's query as a (6, 3) array, rows p, origin, normal at t0 then at t1 (the "
          "static plane repeated), as point_plane_ccd takes it.")
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
          "find_contacts or earliest_contact, `min_separation` the delta it was found with); "
          "a point-edge or point-point contact as the edge-edge geometry of its zero-length "
          "segments. ValueError for a point-plane contact (not available yet).");
}

}  // namespace exactccd::python
