#include "exact/arithmetic/rational.hpp"

#include <cmath>
#include <limits>

namespace exactccd::exact {

namespace {
// mpq_get_d truncates towards zero; for |q| >= 2^1024 the result is +-inf (GMP follows the
// hardware's overflow), which we clamp to +-DBL_MAX before stepping.
double truncate(const Rational& q) {
  double d = q.get_d();
  if (std::isinf(d)) d = std::copysign(std::numeric_limits<double>::max(), d);
  return d;
}
}  // namespace

double round_down(const Rational& q) {
  const double d = truncate(q);
  if (cmp(Rational(d), q) <= 0) return d;  // q >= 0 (truncated down) or exact
  return std::nextafter(d, -std::numeric_limits<double>::infinity());
}

double round_up(const Rational& q) {
  const double d = truncate(q);
  if (cmp(Rational(d), q) >= 0) return d;
  return std::nextafter(d, std::numeric_limits<double>::infinity());
}

bool to_double_exactly(const Rational& q, double* d) {
  const double t = q.get_d();
  if (!std::isfinite(t) || cmp(Rational(t), q) != 0) return false;
  *d = t;
  return true;
}

}  // namespace exactccd::exact
