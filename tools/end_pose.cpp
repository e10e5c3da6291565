#include "end_pose.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <string>

#include "corpus/rigid_exact_pose.hpp"
#include "exactccd/query_file.hpp"

namespace exactccd::cli {

namespace {

/// The double nearest to q (ties to even), or +-infinity beyond the largest double. Exact: the
/// mantissa is the rounded integer quotient q / 2^e for the exponent e of q's last bit.
double nearest_double(const mpq_class& q) {
  if (sgn(q) == 0) return 0.0;
  const mpq_class a = abs(q);
  // 2^e <= a < 2^(e + 1).
  long e = static_cast<long>(mpz_sizeinbase(a.get_num_mpz_t(), 2)) -
           static_cast<long>(mpz_sizeinbase(a.get_den_mpz_t(), 2));
  mpq_class power(1);
  if (e >= 0)
    mpq_mul_2exp(power.get_mpq_t(), power.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_div_2exp(power.get_mpq_t(), power.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  if (a < power) --e;
  if (e > std::numeric_limits<double>::max_exponent)
    return sgn(q) * std::numeric_limits<double>::infinity();
  // The unit of the last place: 2^(e - 52), at least 2^-1074 (subnormals).
  const long ulp = std::max<long>(e - 52, -1074);
  mpq_class scaled = a;
  if (ulp >= 0)
    mpq_div_2exp(scaled.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(ulp));
  else
    mpq_mul_2exp(scaled.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(-ulp));
  mpz_class mantissa;
  mpz_fdiv_q(mantissa.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
  const mpq_class rest = scaled - mantissa;
  if (rest > mpq_class(1, 2) || (rest == mpq_class(1, 2) && mpz_odd_p(mantissa.get_mpz_t())))
    ++mantissa;
  // mantissa <= 2^53: exact as a double; ldexp is exact or overflows to infinity.
  return sgn(q) * std::ldexp(mantissa.get_d(), static_cast<int>(ulp));
}

}  // namespace

Positions rounded_end_pose(const Positions& start, const RigidMotion& m, double* rounding,
                           const std::string& what) {
  Positions end(start.rows(), 3);
  mpq_class largest(0);
  for (Eigen::Index v = 0; v < start.rows(); ++v) {
    const rigid_pose::RationalPosition at_end =
        rigid_pose::exact_position(m, start.row(v).transpose(), mpq_class(1));
    for (int i = 0; i < 3; ++i) {
      const mpq_class& exact = at_end[i];
      const double rounded = nearest_double(exact);
      if (!std::isfinite(rounded))
        throw InputError(what, 0,
                         "the pose at the end of a step is beyond the doubles (vertex " +
                             std::to_string(v) + ")");
      end(v, i) = rounded;
      const mpq_class error = abs(mpq_class(rounded) - exact);
      if (error > largest) largest = error;
    }
  }
  // An upper bound as a double: get_d truncates, the next double up is above. (Below the
  // normal range get_d may give 0; the smallest normal double is then a bound.)
  const double truncated = largest.get_d();
  if (mpq_class(truncated) == largest)
    *rounding = truncated;
  else if (truncated == 0.0)
    *rounding = std::numeric_limits<double>::min();
  else
    *rounding = std::nextafter(truncated, std::numeric_limits<double>::infinity());
  return end;
}

}  // namespace exactccd::cli
