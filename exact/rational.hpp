// Exact rationals (GMP, through gmpxx) and their exact relation to doubles.
#pragma once

#include <gmpxx.h>

namespace exactccd::exact {

using Rational = mpq_class;

/// Largest double <= q (q of any magnitude; -inf / +inf-free: |q| beyond DBL_MAX saturates
/// to -inf for negative q). Exact: GMP's mpq_get_d truncates towards zero.
double round_down(const Rational& q);
/// Smallest double >= q.
double round_up(const Rational& q);
/// True when q is exactly a finite double (and then sets *d to it).
bool to_double_exactly(const Rational& q, double* d);

inline int sign(const Rational& q) { return sgn(q); }

/// hi - lo <= width, decided exactly (the double subtraction could round down).
inline bool difference_at_most(double hi, double lo, double width) {
  return cmp(Rational(hi) - Rational(lo), Rational(width)) <= 0;
}

}  // namespace exactccd::exact
