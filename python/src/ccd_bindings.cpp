// One query at a time: vertex_face_ccd, edge_edge_ccd and their result type.
#include <pybind11/stl.h>

#include <cstdio>

#include "bindings.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"

namespace exactccd::python {

namespace {

std::string repr(const CcdResult& r) {
  char text[160];
  std::snprintf(text, sizeof text, "CcdResult(collides=%s, toi_lo=%.17g, toi_hi=%.17g, stage='%s')",
                r.collides ? "True" : "False", r.toi_lo, r.toi_hi, to_string(r.decided_by));
  return text;
}

template <class Decide>
CcdResult decide_points(const py::handle& points, double t_max, double toi_width,
                        const std::string& mode, double min_separation, Decide decide) {
  const CcdOptions options = make_options(t_max, toi_width, mode, min_separation);
  const DoubleArray array = as_double_array(points, {8, 3}, "the query's points");
  const QueryPoints p = points_of(array.data());
  py::gil_scoped_release release;  // the exact path can take a while
  return decide(p, options);
}

/// k enclosures as a (k, 2) array of [lo, hi].
py::array_t<double> enclosures(const Enclosure* e, int k) {
  py::array_t<double> out({k, 2});
  auto v = out.mutable_unchecked<2>();
  for (int i = 0; i < k; ++i) {
    v(i, 0) = e[i].lo;
    v(i, 1) = e[i].hi;
  }
  return out;
}

}  // namespace

void bind_ccd(py::module_& m) {
  py::class_<ContactGeometry>(m, "ContactGeometry",
                              "The contact geometry at the exact earliest contact time t*, every "
                              "field a certified enclosure (C++: exactccd::contact_geometry).")
      .def_property_readonly(
          "parameters",
          [](const ContactGeometry& g) {
            return enclosures(g.parameters.data(), g.parameter_count);
          },
          "(k, 2) array of [lo, hi]: vertex-face the barycentric coordinates of the contact "
          "point with respect to (a, b, c); edge-edge the parameter on each edge (0 at ea0, eb0).")
      .def_property_readonly(
          "normal", [](const ContactGeometry& g) { return enclosures(g.normal.data(), 3); },
          "(3, 2) array of [lo, hi]: the unit normal from the face (edge b) towards the vertex "
          "(edge a) just before contact when normal_oriented; otherwise the unoriented direction "
          "or [-1, 1].")
      .def_property_readonly(
          "point", [](const ContactGeometry& g) { return enclosures(g.point.data(), 3); },
          "(3, 2) array of [lo, hi]: the contact point in space.")
      .def_property_readonly("kind", [](const ContactGeometry& g) { return to_string(g.kind); },
                             "\"point\", \"at_start\", \"unresolved\", \"degenerate_triangle\", "
                             "\"parallel_edges\" or \"coplanar\" (ContactKind).")
      .def_readonly("normal_oriented", &ContactGeometry::normal_oriented)
      .def("__repr__", [](const ContactGeometry& g) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "ContactGeometry(kind='%s', normal_oriented=%s, normal=[[%.17g, %.17g], "
                      "[%.17g, %.17g], [%.17g, %.17g]])",
                      to_string(g.kind), g.normal_oriented ? "True" : "False", g.normal[0].lo,
                      g.normal[0].hi, g.normal[1].lo, g.normal[1].hi, g.normal[2].lo,
                      g.normal[2].hi);
        return std::string(text);
      });
  m.def(
      "_contact_geometry",
      [](const py::handle& points, const std::string& type, const CcdResult& result,
         double min_separation) {
        const DoubleArray array = as_double_array(points, {8, 3}, "the query's points");
        const QueryPoints p = points_of(array.data());
        if (parse_query_type(type) == QueryType::vertex_face)
          return contact_geometry(
              VertexFaceQuery{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, result,
              min_separation);
        return contact_geometry(EdgeEdgeQuery{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]},
                                result, min_separation);
      },
      py::arg("points"), py::arg("type"), py::arg("result"), py::arg("min_separation") = 0.0);
  m.def(
      "_point_plane_contact_geometry",
      [](const py::handle& points, const CcdResult& result, double min_separation) {
        const DoubleArray array = as_double_array(points, {6, 3}, "the query's points");
        const double* d = array.data();
        return contact_geometry(PointPlaneQuery{row_of(d, 0), row_of(d, 1), row_of(d, 2),
                                                row_of(d, 3), row_of(d, 4), row_of(d, 5)},
                                result, min_separation);
      },
      py::arg("points"), py::arg("result"), py::arg("min_separation") = 0.0);

  py::class_<CcdResult>(m, "CcdResult",
                        "The result of one query: collides, [toi_lo, toi_hi] (the certified "
                        "enclosure of the earliest contact time when collides) and the stage "
                        "that decided it.",
                        py::dynamic_attr())
      .def_readonly("collides", &CcdResult::collides)
      .def_readonly("toi_lo", &CcdResult::toi_lo)
      .def_readonly("toi_hi", &CcdResult::toi_hi)
      .def_readonly("starts_within", &CcdResult::starts_within,
                    "The primitives already meet (are within min_separation) at t = 0: exact.")
      .def_property_readonly("stage", [](const CcdResult& r) { return to_string(r.decided_by); },
                             "The name of the stage that decided the query (STAGE_NAMES).")
      .def_property_readonly(
          "stage_code", [](const CcdResult& r) { return static_cast<int>(r.decided_by); },
          "The stage's code: its index in STAGE_NAMES.")
      .def("__repr__", &repr)
      .def("__eq__",
           [](const CcdResult& a, const CcdResult& b) {
             // TOIs are doubles in [0, t_max] or +infinity, never NaN: == compares them.
             return a.collides == b.collides && a.decided_by == b.decided_by &&
                    a.toi_lo == b.toi_lo && a.toi_hi == b.toi_hi &&
                    a.starts_within == b.starts_within;
           })
      .def("__bool__", [](const CcdResult& r) { return r.collides; });

  m.def(
      "_vertex_face_ccd",
      [](const py::handle& points, double t_max, double toi_width, const std::string& mode,
         double min_separation) {
        return decide_points(points, t_max, toi_width, mode, min_separation,
                             [](const QueryPoints& p, const CcdOptions& o) {
                               return vertex_face_ccd(
                                   {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, o);
                             });
      },
      py::arg("points"), py::arg("t_max"), py::arg("toi_width"), py::arg("mode"),
      py::arg("min_separation"));
  m.def(
      "_edge_edge_ccd",
      [](const py::handle& points, double t_max, double toi_width, const std::string& mode,
         double min_separation) {
        return decide_points(points, t_max, toi_width, mode, min_separation,
                             [](const QueryPoints& p, const CcdOptions& o) {
                               return edge_edge_ccd(
                                   {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, o);
                             });
      },
      py::arg("points"), py::arg("t_max"), py::arg("toi_width"), py::arg("mode"),
      py::arg("min_separation"));
  m.def(
      "_point_plane_ccd",
      [](const py::handle& points, double t_max, double toi_width, const std::string& mode,
         double min_separation) {
        const CcdOptions options = make_options(t_max, toi_width, mode, min_separation);
        const DoubleArray array = as_double_array(points, {6, 3}, "the query's points");
        const double* d = array.data();
        const PointPlaneQuery q{row_of(d, 0), row_of(d, 1), row_of(d, 2),
                                row_of(d, 3), row_of(d, 4), row_of(d, 5)};
        py::gil_scoped_release release;
        return point_plane_ccd(q, options);
      },
      py::arg("points"), py::arg("t_max"), py::arg("toi_width"), py::arg("mode"),
      py::arg("min_separation"));
  m.attr("STAGE_NAMES") = py::cast(stage_names());
  // The canonical names; the functions accept "default" too, the old name of "filtered".
  m.attr("MODE_NAMES") = py::cast(std::vector<std::string>{
      to_string(Mode::filtered), to_string(Mode::float_only), to_string(Mode::exact)});
  m.def(
      "_mode_name",
      [](const std::string& name) { return std::string(to_string(parse_mode(name))); },
      py::arg("name"),
      "The canonical name of mode `name` (\"default\" -> \"filtered\"); ValueError for an "
      "unknown name.");
}

}  // namespace exactccd::python
