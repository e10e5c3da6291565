// Exact conversions between Python numbers (int, fractions.Fraction) and GMP rationals.
#pragma once

#include <gmpxx.h>
#include <pybind11/pybind11.h>

namespace exactccd::python {

/// `value` (an int, a fractions.Fraction or anything with integer numerator and denominator)
/// exactly; TypeError for a float or a non-number, naming `where`.
mpq_class to_mpq(const pybind11::handle& value, const char* where);

/// A fractions.Fraction equal to `q`.
pybind11::object to_fraction(const mpq_class& q);

}  // namespace exactccd::python
