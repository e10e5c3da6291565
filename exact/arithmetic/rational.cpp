#include "exact/arithmetic/rational.hpp"

#include <cmath>
#include <limits>

#include "core/predicates/double_bits.hpp"

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

double round_nearest(const Rational& q) {
  const double lo = round_down(q), hi = round_up(q);
  if (lo == hi) return lo;
  constexpr double kMax = std::numeric_limits<double>::max();
  // Beyond the largest double: infinity from the midpoint between DBL_MAX and 2^1024 on.
  if (std::isinf(hi) || std::isinf(lo)) {
    const Rational limit = Rational(kMax) + Rational(std::ldexp(1.0, 970));
    if (sgn(q) > 0) return cmp(q, limit) >= 0 ? hi : kMax;
    return cmp(q, -limit) <= 0 ? lo : -kMax;
  }
  const int c = cmp(q - Rational(lo), Rational(hi) - q);
  if (c != 0) return c < 0 ? lo : hi;
  // A tie between two consecutive doubles: exactly one has an even significand, i.e. an even
  // bit pattern (consecutive doubles of one sign have consecutive bit patterns).
  return (predicates::bits_of(lo) & 1u) == 0 ? lo : hi;
}

bool to_double_exactly(const Rational& q, double* d) {
  const double t = q.get_d();
  if (!std::isfinite(t) || cmp(Rational(t), q) != 0) return false;
  *d = t;
  return true;
}

}  // namespace exactccd::exact
