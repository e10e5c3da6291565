#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "bindings.hpp"
#include "oracle/names.hpp"

namespace exactccd::python {

Mode parse_mode(const std::string& name) {
  if (const std::optional<Mode> mode = oracle::parse_mode_name(name)) return *mode;
  throw py::value_error("mode must be " + oracle::mode_names_text() + ", not \"" + name + "\"");
}

QueryType parse_query_type(const std::string& name) {
  if (name == "vertex-face" || name == "vf") return QueryType::vertex_face;
  if (name == "edge-edge" || name == "ee") return QueryType::edge_edge;
  throw py::value_error("type must be \"vertex-face\" (\"vf\") or \"edge-edge\" (\"ee\"), not \"" +
                        name + "\"");
}

CcdOptions make_options(double t_max, double toi_width, const std::string& mode,
                        double min_separation) {
  CcdOptions options;
  options.t_max = t_max;
  options.toi_width = toi_width;
  options.mode = parse_mode(mode);
  options.min_separation = min_separation;
  return options;
}

namespace {

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::ostringstream out;
  out << '(';
  for (std::size_t k = 0; k < shape.size(); ++k) {
    if (k > 0) out << ", ";
    if (shape[k] < 0)
      out << 'N';
    else
      out << shape[k];
  }
  out << (shape.size() == 1 ? ",)" : ")");
  return out.str();
}

}  // namespace

DoubleArray as_double_array(const py::handle& object, const std::vector<py::ssize_t>& shape,
                            const char* what) {
  // numpy's own conversion (lists, other dtypes, non-contiguous arrays); its errors (a string
  // that is not a number, a ragged list) are ValueError or TypeError already.
  py::module_ numpy = py::module_::import("numpy");
  DoubleArray array = DoubleArray::ensure(
      numpy.attr("ascontiguousarray")(object, py::arg("dtype") = numpy.attr("float64")));
  if (!array) throw py::type_error(std::string(what) + " must be an array of numbers");
  std::vector<py::ssize_t> got(array.shape(), array.shape() + array.ndim());
  bool matches = got.size() == shape.size();
  for (std::size_t k = 0; matches && k < shape.size(); ++k)
    matches = shape[k] < 0 || shape[k] == got[k];
  if (!matches)
    throw py::value_error(std::string(what) + " must have shape " + shape_text(shape) +
                          ", not " + shape_text(got));
  return array;
}

Eigen::Vector3d vector_of(const py::handle& object, const char* what) {
  const DoubleArray array = as_double_array(object, {3}, what);
  return {array.data()[0], array.data()[1], array.data()[2]};
}

const std::vector<std::string>& stage_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> found;
    for (int k = 0; k < 256; ++k) {
      const char* name = to_string(static_cast<Stage>(k));
      if (std::strcmp(name, "unknown") == 0) break;
      found.emplace_back(name);
    }
    return found;
  }();
  return names;
}

}  // namespace exactccd::python
