// The collision-free step of barrier methods (exactccd/step.hpp): StepResult and the steps of a
// linear query (vertex-face, edge-edge; the point kinds reach it as edge-edge in Python) and of
// the two rigid queries.
#include <pybind11/stl.h>

#include <cstdio>
#include <limits>

#include "bindings.hpp"
#include "exactccd/step.hpp"

namespace exactccd::python {

namespace {

std::string repr(const StepResult& r) {
  char text[200];
  std::snprintf(text, sizeof text,
                "StepResult(step=%.17g, limited=%s, starts_within=%s, "
                "effective_separation=%.17g)",
                r.step, r.limited ? "True" : "False", r.starts_within ? "True" : "False",
                r.effective_separation);
  return text;
}

StepOptions step_options(double t_max, double min_separation, double conservative_rescaling,
                         double max_margin) {
  StepOptions o;
  o.max_margin = max_margin;
  o.t_max = t_max;
  o.min_separation = min_separation;
  o.conservative_rescaling = conservative_rescaling;
  return o;
}

/// Rows 0-3 of a (4, 3) array.
std::array<Eigen::Vector3d, 4> four_points(const py::handle& points, const char* what) {
  const DoubleArray x = as_double_array(points, {4, 3}, what);
  return {row_of(x.data(), 0), row_of(x.data(), 1), row_of(x.data(), 2), row_of(x.data(), 3)};
}

}  // namespace

void bind_step(py::module_& m) {
  py::class_<StepResult>(m, "StepResult",
                         "A collision-free step: the distance exceeds min_separation, and is at "
                         "least effective_separation, at every t in [0, step]; limited: the "
                         "primitives come within effective_separation before t_max; "
                         "starts_within: within min_separation at t = 0 (step 0). Certified.")
      .def_readonly("step", &StepResult::step)
      .def_readonly("limited", &StepResult::limited)
      .def_readonly("starts_within", &StepResult::starts_within)
      .def_readonly("effective_separation", &StepResult::effective_separation)
      .def("__repr__", &repr);

  m.def(
      "_collision_free_step",
      [](const py::handle& points, const std::string& type, double t_max, double min_separation,
         double conservative_rescaling, double max_margin) {
        const DoubleArray array = as_double_array(points, {8, 3}, "the query's points");
        const QueryPoints p = points_of(array.data());
        const QueryType kind = parse_query_type(type);
        const StepOptions o = step_options(t_max, min_separation, conservative_rescaling, max_margin);
        py::gil_scoped_release release;
        if (kind == QueryType::vertex_face)
          return collision_free_step(
              VertexFaceQuery{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, o);
        return collision_free_step(EdgeEdgeQuery{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]},
                                   o);
      },
      py::arg("points"), py::arg("type"), py::arg("t_max"), py::arg("min_separation"),
      py::arg("conservative_rescaling"), py::arg("max_margin"));
  m.def(
      "rigid_vertex_face_collision_free_step",
      [](const py::handle& points, const py::handle& vertex_motion,
         const py::handle& face_motion, double t_max, double min_separation,
         double conservative_rescaling, double max_margin) {
        const auto x = four_points(points, "the points p, a, b, c");
        const RigidVertexFaceQuery q{x[0], x[1], x[2], x[3],
                                     side_motion(vertex_motion, 1, "the vertex's end position"),
                                     side_motion(face_motion, 3, "the face's end positions")};
        const StepOptions o = step_options(t_max, min_separation, conservative_rescaling, max_margin);
        py::gil_scoped_release release;
        return collision_free_step(q, o);
      },
      py::arg("points"), py::arg("vertex_motion"), py::arg("face_motion"), py::kw_only(),
      py::arg("t_max") = 1.0, py::arg("min_separation") = 0.0,
      py::arg("conservative_rescaling") = 0.8,
      py::arg("max_margin") = std::numeric_limits<double>::infinity(),
      "The collision-free step (in s) of vertex p against the triangle (a, b, c) under rigid "
      "motion: arguments as rigid_vertex_face_ccd; conservative_rescaling s in (0, 1]: the step "
      "keeps distance >= min_separation + (1 - s)(d0 - min_separation), d0 the distance at "
      "s = 0; max_margin caps that margin (ipc-toolkit's Tight Inclusion: 1e-4).");
  m.def(
      "rigid_edge_edge_collision_free_step",
      [](const py::handle& points, const py::handle& motion_a, const py::handle& motion_b,
         double t_max, double min_separation, double conservative_rescaling, double max_margin) {
        const auto x = four_points(points, "the points ea0, ea1, eb0, eb1");
        const RigidEdgeEdgeQuery q{x[0], x[1], x[2], x[3],
                                   side_motion(motion_a, 2, "edge a's end positions"),
                                   side_motion(motion_b, 2, "edge b's end positions")};
        const StepOptions o = step_options(t_max, min_separation, conservative_rescaling, max_margin);
        py::gil_scoped_release release;
        return collision_free_step(q, o);
      },
      py::arg("points"), py::arg("motion_a"), py::arg("motion_b"), py::kw_only(),
      py::arg("t_max") = 1.0, py::arg("min_separation") = 0.0,
      py::arg("conservative_rescaling") = 0.8,
      py::arg("max_margin") = std::numeric_limits<double>::infinity(),
      "The collision-free step (in s) of segments [ea0, ea1] and [eb0, eb1] under rigid motion: "
      "as rigid_vertex_face_collision_free_step.");
}

}  // namespace exactccd::python
