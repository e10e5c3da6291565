// The benchmark's CSV files: reading into arrays (or exact Fractions), listing, and formatting
// queries as CSV rows (the Python side writes them to a file safely).
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "exactccd/query_file.hpp"
#include "rational_conversion.hpp"

namespace exactccd::python {

namespace {

// Whether q is exactly a finite double (then *d is it). mpq_get_d truncates towards zero, so
// it returns q itself when q is a double; infinities (q beyond the doubles) are refused before
// converting back.
bool to_double_exactly(const mpq_class& q, double* d) {
  *d = q.get_d();
  return std::isfinite(*d) && cmp(q, mpq_class(*d)) == 0;
}

QueryType resolve_type(const std::string& path, const std::optional<std::string>& type) {
  if (type) return parse_query_type(*type);
  if (const std::optional<QueryType> found = query_type_from_path(path)) return *found;
  throw InputError(path, 0,
                   "cannot tell the query type: no folder named vertex-face or edge-edge in "
                   "the path (pass type=\"vertex-face\" or type=\"edge-edge\")");
}

QueryFile read(const std::string& path, const std::optional<std::string>& type) {
  const QueryType query_type = resolve_type(path, type);
  py::gil_scoped_release release;
  return read_query_file(path, query_type);
}

py::array_t<bool> truth_array(const QueryFile& file) {
  py::array_t<bool> truth(static_cast<py::ssize_t>(file.queries.size()));
  bool* out = truth.mutable_data();
  for (std::size_t i = 0; i < file.queries.size(); ++i) out[i] = file.queries[i].truth;
  return truth;
}

py::tuple read_doubles(const std::string& path, const std::optional<std::string>& type) {
  const QueryFile file = read(path, type);
  const auto n = static_cast<py::ssize_t>(file.queries.size());
  py::array_t<double> queries({n, py::ssize_t{8}, py::ssize_t{3}});
  double* out = queries.mutable_data();
  for (const QueryRecord& record : file.queries) {
    for (std::size_t row = 0; row < 8; ++row) {
      const RationalPoint& p = record.query.points[row];
      for (const mpq_class* q : {&p.x, &p.y, &p.z})
        if (!to_double_exactly(*q, out++))
          throw InputError(file.path, record.line_of_row(row),
                           "a coordinate is not exactly a double (read_query_file_exact reads "
                           "it as a fractions.Fraction)");
    }
  }
  return py::make_tuple(queries, truth_array(file), to_string(file.type));
}

py::tuple read_exact(const std::string& path, const std::optional<std::string>& type) {
  const QueryFile file = read(path, type);
  py::list queries;
  for (const QueryRecord& record : file.queries) {
    py::list points;
    for (const RationalPoint& p : record.query.points)
      points.append(py::make_tuple(to_fraction(p.x), to_fraction(p.y), to_fraction(p.z)));
    queries.append(points);
  }
  return py::make_tuple(queries, truth_array(file), to_string(file.type));
}

// A file of a point kind or the plane (pe, pe2d, pp, pp2d, pl) as an (N, rows, dimension)
// array of its exact doubles, its truth column and its kind's name.
py::tuple read_primitive_doubles(const std::string& path, const std::string& name) {
  const std::optional<PrimitiveKind> kind = primitive_kind_from_name(name);
  if (!kind) throw py::value_error("unknown point kind '" + name + "'");
  PrimitiveQueryFile file;
  {
    py::gil_scoped_release release;
    file = read_primitive_query_file(path, *kind);
  }
  const auto n = static_cast<py::ssize_t>(file.queries.size());
  const auto rows = static_cast<py::ssize_t>(rows_per_query(*kind));
  const int dimension = dimension_of(*kind);
  py::array_t<double> queries({n, rows, static_cast<py::ssize_t>(dimension)});
  py::array_t<bool> truth(n);
  double* out = queries.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const PrimitiveQueryRecord& record = file.queries[static_cast<std::size_t>(i)];
    truth.mutable_data()[i] = record.truth;
    for (std::size_t row = 0; row < record.points.size(); ++row) {
      const RationalPoint& p = record.points[row];
      const mpq_class* coordinates[3] = {&p.x, &p.y, &p.z};
      for (int k = 0; k < dimension; ++k)
        if (!to_double_exactly(*coordinates[k], out++))
          throw InputError(file.path, record.first_line + row,
                           "a coordinate is not exactly a double");
    }
  }
  return py::make_tuple(queries, truth, name);
}

// The CSV text of `queries` (N, 8, 3) with truth values `truth` (N,).
py::bytes format_rows(const py::handle& queries, const py::handle& truth) {
  const DoubleArray array = as_double_array(queries, {-1, 8, 3}, "queries");
  const auto n = array.shape(0);
  // As numbers, not as bools: a truth of 2 (or 0.5) is a mistake, not a collision.
  const py::array_t<double, py::array::c_style | py::array::forcecast> flags =
      py::module_::import("numpy").attr("ascontiguousarray")(truth, py::arg("dtype") = "float64");
  if (flags.ndim() != 1 || flags.shape(0) != n)
    throw py::value_error("truth must have shape (" + std::to_string(n) + ",), one value per query");
  std::string text;
  for (py::ssize_t i = 0; i < n; ++i) {
    const double flag = flags.data()[i];
    if (flag != 0.0 && flag != 1.0)
      throw py::value_error("truth[" + std::to_string(i) + "] is " +
                            std::string(py::repr(py::float_(flag))) +
                            ": each truth value is 0 (no collision) or 1 (collision)");
    try {
      append_query_rows(text, points_of(array.data() + 24 * i), flag == 1.0);
    } catch (const std::invalid_argument& e) {
      throw py::value_error("query " + std::to_string(i) + ": " + e.what());
    }
  }
  return py::bytes(text);
}

// The CSV text of queries of a point kind or the plane, (N, rows, dimension), with their truth.
py::bytes format_primitive_rows(const py::handle& queries, const py::handle& truth,
                                const std::string& name) {
  const std::optional<PrimitiveKind> kind = primitive_kind_from_name(name);
  if (!kind) throw py::value_error("unknown point kind '" + name + "'");
  const auto rows = static_cast<py::ssize_t>(rows_per_query(*kind));
  const int dimension = dimension_of(*kind);
  const DoubleArray array = as_double_array(queries, {-1, rows, dimension}, "queries");
  const auto n = array.shape(0);
  const py::array_t<double, py::array::c_style | py::array::forcecast> flags =
      py::module_::import("numpy").attr("ascontiguousarray")(truth, py::arg("dtype") = "float64");
  if (flags.ndim() != 1 || flags.shape(0) != n)
    throw py::value_error("truth must have shape (" + std::to_string(n) + ",), one value per query");
  std::string text;
  for (py::ssize_t i = 0; i < n; ++i) {
    const double flag = flags.data()[i];
    if (flag != 0.0 && flag != 1.0)
      throw py::value_error("truth[" + std::to_string(i) + "] is " +
                            std::string(py::repr(py::float_(flag))) +
                            ": each truth value is 0 (no collision) or 1 (collision)");
    std::string query;
    for (py::ssize_t r = 0; r < rows; ++r) {
      for (int k = 0; k < dimension; ++k) {
        const double x = array.data()[(i * rows + r) * dimension + k];
        if (!std::isfinite(x))
          throw py::value_error("query " + std::to_string(i) + ": non-finite coordinate");
        append_exact_fraction(query, x);
        query += ',';
      }
      query += flag == 1.0 ? "1\n" : "0\n";
    }
    text += query;
  }
  return py::bytes(text);
}

}  // namespace

void bind_query_files(py::module_& m) {
  m.def("_read_query_file", &read_doubles, py::arg("path"), py::arg("type"));
  m.def("_read_query_file_exact", &read_exact, py::arg("path"), py::arg("type"));
  m.def("_read_primitive_query_file", &read_primitive_doubles, py::arg("path"), py::arg("kind"));
  m.def("_format_query_rows", &format_rows, py::arg("queries"), py::arg("truth"));
  m.def("_format_primitive_rows", &format_primitive_rows, py::arg("queries"), py::arg("truth"),
        py::arg("kind"));
  m.def(
      "find_query_files",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return find_query_files(path);
      },
      py::arg("path"),
      "The query files of `path`: itself when it is a file; for a directory, every "
      "vertex-face/*.csv and edge-edge/*.csv below it, sorted (TOI sidecars toi_*.csv "
      "excluded). Raises InputError when there is none or the path cannot be read.");
  m.def(
      "query_type_from_path",
      [](const std::string& path) -> std::optional<std::string> {
        if (const auto type = query_type_from_path(path)) return std::string(to_string(*type));
        return std::nullopt;
      },
      py::arg("path"),
      "\"vertex-face\" or \"edge-edge\" from the nearest folder of that name in `path`, or None.");
}

}  // namespace exactccd::python
