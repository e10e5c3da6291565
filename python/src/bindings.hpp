// Shared pieces of the Python module's bindings: conversions between Python objects and the
// library's types, and one bind_* function per part of the API.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <string>

#include "exactccd/rational_query.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::python {

namespace py = pybind11;

/// The benchmark's 8 points of one query, in its row order.
using QueryPoints = std::array<Eigen::Vector3d, 8>;

/// A C-contiguous float64 array (converted when it is not one).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The Mode named `name` ("filtered", "float_only", "exact": to_string(Mode); or "default", the
/// old name of "filtered": oracle::parse_mode_name); ValueError listing the names otherwise.
Mode parse_mode(const std::string& name);
/// "vertex-face" / "vf" or "edge-edge" / "ee"; ValueError otherwise.
QueryType parse_query_type(const std::string& name);

/// Options as given to the Python functions; their domain is checked by the library (ValueError).
/// min_separation: CcdOptions::min_separation (0: contact).
CcdOptions make_options(double t_max, double toi_width, const std::string& mode,
                        double min_separation = 0.0);

/// `object` as an array of the given shape (float64, C order), or ValueError naming `what` and
/// the shape received. shape entries < 0 match any length.
DoubleArray as_double_array(const py::handle& object, const std::vector<py::ssize_t>& shape,
                            const char* what);

/// A 3-vector from any array-like of 3 numbers, or ValueError naming `what`.
Eigen::Vector3d vector_of(const py::handle& object, const char* what);

/// Point `row` of an (8, 3) array.
inline Eigen::Vector3d row_of(const double* data, int row) {
  return {data[3 * row], data[3 * row + 1], data[3 * row + 2]};
}

/// The 8 points of an (8, 3) array.
inline QueryPoints points_of(const double* data) {
  QueryPoints points;
  for (int row = 0; row < 8; ++row) points[static_cast<std::size_t>(row)] = row_of(data, row);
  return points;
}

/// A rigid query side's motion: a RigidMotion, or a (vertices, 3) array of end positions
/// (straight lines); ValueError naming `what` otherwise.
SideMotion side_motion(const py::handle& motion, int vertices, const char* what);

/// The stage names in code order (to_string(Stage) for codes 0, 1, ... until "unknown").
const std::vector<std::string>& stage_names();

void bind_ccd(py::module_& m);
void bind_batch(py::module_& m);
void bind_rational(py::module_& m);
void bind_query_files(py::module_& m);
void bind_scene(py::module_& m);
void bind_oracle(py::module_& m);
void bind_rigid(py::module_& m);
void bind_step(py::module_& m);

}  // namespace exactccd::python
