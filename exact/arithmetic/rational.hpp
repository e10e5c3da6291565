// Exact rationals (GMP, through gmpxx) and their exact relation to doubles.
#pragma once

#include <gmpxx.h>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

namespace exactccd::exact {

using Rational = mpq_class;

/// The largest double <= q, for q of any magnitude: -inf when q < -DBL_MAX, DBL_MAX when
/// q > DBL_MAX. Exact: GMP's mpq_get_d truncates towards zero, then one exact comparison.
double round_down(const Rational& q);
/// The smallest double >= q: +inf when q > DBL_MAX, -DBL_MAX when q < -DBL_MAX.
double round_up(const Rational& q);
/// The double nearest to q, ties to even (IEEE round to nearest), subnormals included; +-inf
/// from +-(DBL_MAX + half its ulp) on, as a correctly rounded conversion gives.
double round_nearest(const Rational& q);
/// True when q is exactly a finite double (and then sets *d to it).
bool to_double_exactly(const Rational& q, double* d);

inline int sign(const Rational& q) { return sgn(q); }

/// hi - lo <= width, decided exactly (the double subtraction could round down).
inline bool difference_at_most(double hi, double lo, double width) {
  return cmp(Rational(hi) - Rational(lo), Rational(width)) <= 0;
}

}  // namespace exactccd::exact
