// Rigid-body CCD (exactccd/rigid.hpp): RigidMotion, the side motions and the two queries.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/rigid.hpp"

namespace exactccd::python {

SideMotion side_motion(const py::handle& motion, int vertices, const char* what) {
  if (py::isinstance<RigidMotion>(motion)) return SideMotion::of(motion.cast<RigidMotion>());
  const DoubleArray ends = as_double_array(motion, {vertices, 3}, what);
  SideMotion side;
  side.kind = PathKind::linear;
  for (int i = 0; i < vertices; ++i)
    side.linear_end[i] = Eigen::Vector3d(ends.data()[3 * i], ends.data()[3 * i + 1],
                                         ends.data()[3 * i + 2]);
  return side;
}

namespace {

/// A motion's vector, refused at once when not finite (a NaN motion would fail only when used).
Eigen::Vector3d finite_vector_of(const py::handle& object, const char* what) {
  const Eigen::Vector3d x = vector_of(object, what);
  if (!x.allFinite()) {
    char text[160];
    std::snprintf(text, sizeof text, "RigidMotion: %s must be finite, got (%.17g, %.17g, %.17g)",
                  what, x.x(), x.y(), x.z());
    throw py::value_error(text);
  }
  return x;
}

std::string repr(const RigidCcdResult& r) {
  char text[240];
  std::snprintf(text, sizeof text,
                "RigidCcdResult(collides=%s, toi_lo=%.17g, toi_hi=%.17g, has_time=%s, "
                "time_lo=%.17g, time_hi=%.17g, stage='%s')",
                r.ccd.collides ? "True" : "False", r.ccd.toi_lo, r.ccd.toi_hi,
                r.has_time ? "True" : "False", r.time_lo, r.time_hi, to_string(r.ccd.decided_by));
  return text;
}

RigidCcdResult decide(const RigidVertexFaceQuery& q, const CcdOptions& o) {
  return vertex_face_ccd(q, o);
}
RigidCcdResult decide(const RigidEdgeEdgeQuery& q, const CcdOptions& o) {
  return edge_edge_ccd(q, o);
}
RigidCcdResult decide(const RigidPointPlaneQuery& q, const CcdOptions& o) {
  return point_plane_ccd(q, o);
}

/// The result as a Python object, with its contact geometry in `contact` when asked for and it
/// collides (certified modes and contact only: ValueError otherwise).
template <class Query>
py::object with_contact(const Query& q, const CcdOptions& options, bool contact,
                        const char* function) {
  if (contact && options.mode == Mode::float_only)
    throw py::value_error(std::string(function) +
                          "(): contact=True needs a certified mode (\"filtered\" or \"exact\")");
  RigidCcdResult r;
  std::optional<ContactGeometry> g;
  {
    py::gil_scoped_release release;
    r = decide(q, options);
    if (contact && r.ccd.collides) g = contact_geometry(q, r, options.min_separation);
  }
  py::object out = py::cast(r);
  if (g) out.attr("__dict__")["contact"] = py::cast(*g);
  return out;
}

}  // namespace

void bind_rigid(py::module_& m) {
  py::class_<RigidMotion>(m, "RigidMotion",
                          "A rational rigid motion: at parameter s a point x0 is at pivot + s "
                          "translation + C(s cayley) (x0 - pivot), C the Cayley rotation.")
      .def(py::init([](const py::handle& pivot, const py::handle& translation,
                       const py::handle& cayley) {
             RigidMotion r;
             r.pivot = finite_vector_of(pivot, "pivot");
             r.translation = finite_vector_of(translation, "translation");
             r.cayley = finite_vector_of(cayley, "cayley");
             return r;
           }),
           py::arg("pivot") = py::make_tuple(0.0, 0.0, 0.0),
           py::arg("translation") = py::make_tuple(0.0, 0.0, 0.0),
           py::arg("cayley") = py::make_tuple(0.0, 0.0, 0.0))
      .def_static("turn", &RigidMotion::turn, py::arg("pivot"), py::arg("axis"), py::arg("angle"),
                  py::arg("translation") = Eigen::Vector3d::Zero(),
                  "The turn by `angle` radians (|angle| < pi) about the line through pivot along "
                  "axis, the pivot moving by translation (cayley rounded to doubles).")
      .def_readonly("pivot", &RigidMotion::pivot)
      .def_readonly("translation", &RigidMotion::translation)
      .def_readonly("cayley", &RigidMotion::cayley)
      .def("position_at",
           [](const RigidMotion& r, const py::handle& x0, double s) {
             return position_at(r, vector_of(x0, "x0"), s);
           },
           py::arg("x0"), py::arg("s"), "x(s) in double arithmetic (not certified).");

  py::class_<RigidCcdResult>(m, "RigidCcdResult",
                             "collides, the enclosure [toi_lo, toi_hi] of the first contact's "
                             "motion parameter s, and its time [time_lo, time_hi] when has_time.",
                             py::dynamic_attr())
      .def_property_readonly("collides", [](const RigidCcdResult& r) { return r.ccd.collides; })
      .def_property_readonly("toi_lo", [](const RigidCcdResult& r) { return r.ccd.toi_lo; })
      .def_property_readonly("toi_hi", [](const RigidCcdResult& r) { return r.ccd.toi_hi; })
      .def_property_readonly("starts_within",
                             [](const RigidCcdResult& r) { return r.ccd.starts_within; },
                             "The primitives already meet (are within min_separation) at s = 0.")
      .def_property_readonly("stage",
                             [](const RigidCcdResult& r) { return to_string(r.ccd.decided_by); })
      .def_readonly("has_time", &RigidCcdResult::has_time)
      .def_readonly("time_lo", &RigidCcdResult::time_lo)
      .def_readonly("time_hi", &RigidCcdResult::time_hi)
      .def("__repr__", &repr)
      .def("__bool__", [](const RigidCcdResult& r) { return r.ccd.collides; });

  m.def(
      "rigid_vertex_face_ccd",
      [](const py::handle& points, const py::handle& vertex_motion,
         const py::handle& face_motion, double t_max, double toi_width, const std::string& mode,
         double min_separation, bool contact) {
        const DoubleArray x = as_double_array(points, {4, 3}, "the points p, a, b, c");
        RigidVertexFaceQuery q;
        Eigen::Vector3d* rows[4] = {&q.p, &q.a, &q.b, &q.c};
        for (int i = 0; i < 4; ++i)
          *rows[i] = Eigen::Vector3d(x.data()[3 * i], x.data()[3 * i + 1], x.data()[3 * i + 2]);
        q.vertex = side_motion(vertex_motion, 1, "the vertex's end position");
        q.face = side_motion(face_motion, 3, "the face's end positions");
        const CcdOptions options = make_options(t_max, toi_width, mode, min_separation);
        return with_contact(q, options, contact, "rigid_vertex_face_ccd");
      },
      py::arg("points"), py::arg("vertex_motion"), py::arg("face_motion"), py::kw_only(),
      py::arg("t_max") = 1.0, py::arg("toi_width") = 0.0, py::arg("mode") = "filtered",
      py::arg("min_separation") = 0.0, py::arg("contact") = false,
      "Vertex p against the closed triangle (a, b, c): points = (4, 3) positions at s = 0; each "
      "motion a RigidMotion or an array of end positions (straight lines). mode: \"filtered\" "
      "(certified; \"default\" is its old name), \"exact\", or \"float_only\" (the uncertified "
      "double test, for comparison: toi_lo == toi_hi, stage \"float_only\"). min_separation: "
      "delta >= 0, finite; "
      "collides iff the vertex comes within Euclidean distance delta of the triangle, the TOI "
      "the earliest such s (0: contact). contact=True: a colliding result's `contact` is the "
      "certified contact geometry at s* (ContactGeometry).");
  m.def(
      "rigid_edge_edge_ccd",
      [](const py::handle& points, const py::handle& motion_a, const py::handle& motion_b,
         double t_max, double toi_width, const std::string& mode, double min_separation,
         bool contact) {
        const DoubleArray x = as_double_array(points, {4, 3}, "the points ea0, ea1, eb0, eb1");
        RigidEdgeEdgeQuery q;
        Eigen::Vector3d* rows[4] = {&q.ea0, &q.ea1, &q.eb0, &q.eb1};
        for (int i = 0; i < 4; ++i)
          *rows[i] = Eigen::Vector3d(x.data()[3 * i], x.data()[3 * i + 1], x.data()[3 * i + 2]);
        q.edge_a = side_motion(motion_a, 2, "edge a's end positions");
        q.edge_b = side_motion(motion_b, 2, "edge b's end positions");
        const CcdOptions options = make_options(t_max, toi_width, mode, min_separation);
        return with_contact(q, options, contact, "rigid_edge_edge_ccd");
      },
      py::arg("points"), py::arg("motion_a"), py::arg("motion_b"), py::kw_only(),
      py::arg("t_max") = 1.0, py::arg("toi_width") = 0.0, py::arg("mode") = "filtered",
      py::arg("min_separation") = 0.0, py::arg("contact") = false,
      "Closed segment [ea0, ea1] against [eb0, eb1]: points = (4, 3) positions at s = 0; each "
      "motion a RigidMotion or an array of end positions (straight lines). mode and "
      "min_separation: as rigid_vertex_face_ccd (delta: the distance between the segments).");
  m.def(
      "rigid_point_plane_ccd",
      [](const py::handle& p, const py::handle& motion, const py::handle& origin,
         const py::handle& normal, double t_max, double toi_width, const std::string& mode,
         double min_separation, bool contact) {
        if (!py::isinstance<RigidMotion>(motion))
          throw py::type_error("rigid_point_plane_ccd: motion must be an exactccd.RigidMotion");
        const RigidPointPlaneQuery q{vector_of(p, "p"), motion.cast<RigidMotion>(),
                                     vector_of(origin, "origin"), vector_of(normal, "normal")};
        const CcdOptions options = make_options(t_max, toi_width, mode, min_separation);
        return with_contact(q, options, contact, "rigid_point_plane_ccd");
      },
      py::arg("p"), py::arg("motion"), py::arg("origin"), py::arg("normal"), py::kw_only(),
      py::arg("t_max") = 1.0, py::arg("toi_width") = 0.0, py::arg("mode") = "filtered",
      py::arg("min_separation") = 0.0, py::arg("contact") = false,
      "A point of a rigid body (at p at s = 0, moving with the RigidMotion `motion`) against the "
      "static plane through `origin` with normal `normal` (non-zero): contact when the point is "
      "on the plane, with min_separation delta when within delta of it. mode as "
      "rigid_vertex_face_ccd. Returns a RigidCcdResult; contact=True: a colliding result's "
      "`contact` is the certified contact geometry at s* (the point, the plane's unit normal "
      "towards the side the point came from).");
}

}  // namespace exactccd::python
