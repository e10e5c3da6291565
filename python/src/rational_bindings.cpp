// The exact oracle over rational coordinates: Python ints and fractions.Fraction, converted
// exactly (through their integers' hexadecimal digits, never through a float).
#include <gmpxx.h>

#include <string>

#include "bindings.hpp"
#include "rational_conversion.hpp"

namespace exactccd::python {

namespace {

mpz_class to_mpz(const py::handle& integer) {
  // Hexadecimal: exact, and free of Python's limit on decimal digits of large ints.
  const std::string digits = py::str(py::module_::import("builtins").attr("format")(integer, "x"));
  return mpz_class(digits, 16);
}

}  // namespace

mpq_class to_mpq(const py::handle& value, const char* where) {
  if (PyFloat_Check(value.ptr()) || PyComplex_Check(value.ptr()))
    throw py::type_error(std::string(where) +
                         ": must be int or fractions.Fraction, not " +
                         std::string(py::str(value.get_type().attr("__name__"))) +
                         " (fractions.Fraction(x) is the exact value of a float x)");
  if (py::hasattr(value, "numerator") && py::hasattr(value, "denominator")) {
    const py::object num = value.attr("numerator"), den = value.attr("denominator");
    if (PyIndex_Check(num.ptr()) && PyIndex_Check(den.ptr())) {
      mpq_class q(to_mpz(py::reinterpret_steal<py::object>(PyNumber_Index(num.ptr()))),
                  to_mpz(py::reinterpret_steal<py::object>(PyNumber_Index(den.ptr()))));
      if (q.get_den() == 0) throw py::value_error(std::string(where) + ": zero denominator");
      q.canonicalize();
      return q;
    }
  }
  if (PyIndex_Check(value.ptr()))
    return mpq_class(to_mpz(py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()))));
  throw py::type_error(std::string(where) + ": must be int or fractions.Fraction, not " +
                       std::string(py::str(value.get_type().attr("__name__"))));
}

py::object to_fraction(const mpq_class& q) {
  // Looked up per call (sys.modules caches the import): a static py::object would be released
  // after the interpreter has finalised, at exit.
  const py::object fraction = py::module_::import("fractions").attr("Fraction");
  const auto as_int = [](const mpz_class& z) {
    const std::string hex = z.get_str(16);
    return py::reinterpret_steal<py::object>(PyLong_FromString(hex.c_str(), nullptr, 16));
  };
  return fraction(as_int(q.get_num()), as_int(q.get_den()));
}

namespace {

RationalQuery rational_query(const py::handle& points, QueryType type) {
  RationalQuery query;
  query.type = type;
  const py::sequence rows = py::reinterpret_borrow<py::sequence>(points);
  if (!py::isinstance<py::sequence>(points) || py::len(rows) != 8)
    throw py::value_error("points must be a sequence of 8 points (the benchmark's rows)");
  for (std::size_t row = 0; row < 8; ++row) {
    const py::object point = rows[row];
    if (!py::isinstance<py::sequence>(point) || py::len(point) != 3)
      throw py::value_error("points[" + std::to_string(row) + "] must hold 3 coordinates");
    const py::sequence xyz = py::reinterpret_borrow<py::sequence>(point);
    RationalPoint& p = query.points[row];
    mpq_class* coordinates[3] = {&p.x, &p.y, &p.z};
    for (std::size_t k = 0; k < 3; ++k)
      *coordinates[k] =
          to_mpq(xyz[k],
                 ("points[" + std::to_string(row) + "][" + std::to_string(k) + "]").c_str());
  }
  return query;
}

}  // namespace

void bind_rational(py::module_& m) {
  m.def(
      "exact_ccd",
      [](const py::handle& points, const std::string& type, double t_max, double toi_width,
         const py::handle& min_separation) {
        const RationalQuery query = rational_query(points, parse_query_type(type));
        const mpq_class delta = to_mpq(min_separation, "min_separation");
        CcdOptions options;
        options.t_max = t_max;
        options.toi_width = toi_width;
        py::gil_scoped_release release;
        return exact_ccd(query, delta, options);  // delta = 0: contact, as exact_ccd(query)
      },
      py::arg("points"), py::arg("type"), py::kw_only(), py::arg("t_max") = 1.0,
      py::arg("toi_width") = 0.0, py::arg("min_separation") = 0,
      R"(Decides one query exactly from rational coordinates.

points: 8 points of 3 coordinates each (int or fractions.Fraction, taken exactly; float is
refused), in the benchmark's row order (vertex-face: p, a, b, c at t0 then at t1; edge-edge:
ea0, ea1, eb0, eb1 at t0 then at t1). type: "vertex-face" ("vf") or "edge-edge" ("ee").
min_separation: the minimum separation delta >= 0 as an int or fractions.Fraction (any
rational, taken exactly): collides iff the primitives come within Euclidean distance delta,
the TOI the earliest such time; 0 is contact.
Returns a CcdResult (stage "exact"). Raises ValueError for options outside their domain (a
negative min_separation among them), TypeError for a float coordinate or min_separation.)");
}

}  // namespace exactccd::python
