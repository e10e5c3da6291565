// The extension module exactccd._exactccd; the package exactccd (python/exactccd/) wraps it.
#include "bindings.hpp"
#include "exactccd/query_file.hpp"

PYBIND11_MODULE(_exactccd, m) {
  namespace python = exactccd::python;
  m.doc() = "exactccd: exact continuous collision detection (the compiled part of the package)";
  m.attr("__version__") = EXACTCCD_PYTHON_VERSION;
  // Malformed input files; a ValueError, so that `except ValueError` catches every bad input.
  // (std::invalid_argument becomes ValueError through pybind11's own translation.)
  pybind11::register_exception<exactccd::InputError>(m, "InputError", PyExc_ValueError);
  python::bind_ccd(m);
  python::bind_batch(m);
  python::bind_rational(m);
  python::bind_query_files(m);
  python::bind_scene(m);
  python::bind_oracle(m);
  python::bind_rigid(m);
  python::bind_step(m);
}
