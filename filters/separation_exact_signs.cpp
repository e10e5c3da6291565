// PROOF: proofs/min_separation.md#interval-search
#include "filters/separation_exact_signs.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

#include "core/predicates/separation.hpp"

namespace exactccd::filters::separation {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;
using Point = Vec3<FixedPoly<mpz_class, 0>>;

/// d = mantissa 2^exponent with an integer mantissa (|mantissa| < 2^53); 0 for d = 0.
void split(double d, std::int64_t* mantissa, int* exponent) {
  int e = 0;
  const double f = std::frexp(d, &e);  // d = f 2^e, 0.5 <= |f| < 1
  *mantissa = static_cast<std::int64_t>(std::ldexp(f, 53));
  *exponent = e - 53;
}

/// d 2^-e_min as an integer (d's exponent >= e_min).
mpz_class scaled_integer(double d, int e_min) {
  if (d == 0) return 0;
  std::int64_t m = 0;
  int e = 0;
  split(d, &m, &e);
  mpz_class r(static_cast<long>(m));
  r <<= static_cast<mp_bitcnt_t>(e - e_min);
  return r;
}

Point point(const std::array<mpz_class, 3>& x) {
  return {FixedPoly<mpz_class, 0>{{x[0]}}, FixedPoly<mpz_class, 0>{{x[1]}},
          FixedPoly<mpz_class, 0>{{x[2]}}};
}

template <class Separation>
int sign_of_polynomial(const Separation& s, int k) {
  int sign = 0;
  s.for_each_polynomial([&sign](const auto& g) { sign = sgn(g.c[0]); }, k);
  return sign;
}

}  // namespace

ExactSignsAtDoubles::ExactSignsAtDoubles(const std::array<const Eigen::Vector3d*, 4>& t0,
                                         const std::array<const Eigen::Vector3d*, 4>& t1,
                                         double delta) {
  int e_min = INT_MAX;
  auto lower = [&e_min](double d) {
    if (d == 0) return;
    std::int64_t m = 0;
    int e = 0;
    split(d, &m, &e);
    e_min = std::min(e_min, e);
  };
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) {
      lower((*t0[i])[c]);
      lower((*t1[i])[c]);
    }
  lower(delta);
  if (e_min == INT_MAX) e_min = 0;  // all zero
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) {
      x0_[i][c] = scaled_integer((*t0[i])[c], e_min);
      dx_[i][c] = scaled_integer((*t1[i])[c], e_min) - x0_[i][c];
    }
  delta_ = scaled_integer(delta, e_min);
}

void ExactSignsAtDoubles::at(double t, std::array<Position, 4>* positions,
                             mpz_class* delta) const {
  // t = m 2^e (e <= 0 for t in (0, 1]): positions x0 + t dx times 2^-e = x0 2^-e + m dx.
  std::int64_t m = 0;
  int e = 0;
  if (t != 0) split(t, &m, &e);
  const mp_bitcnt_t shift = t == 0 ? 0 : static_cast<mp_bitcnt_t>(-e);
  const mpz_class mz(static_cast<long>(m));
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) (*positions)[i][c] = (x0_[i][c] << shift) + mz * dx_[i][c];
  *delta = delta_ << shift;
}

int ExactSignsAtDoubles::vertex_face_sign(int k, double t) const {
  std::array<Position, 4> x;
  mpz_class d;
  at(t, &x, &d);
  const mpz_class d2 = d * d;
  return sign_of_polynomial(
      predicates::vertex_face_separation(point(x[0]), point(x[1]), point(x[2]), point(x[3]), d2),
      k);
}

int ExactSignsAtDoubles::edge_edge_sign(int k, double t) const {
  std::array<Position, 4> x;
  mpz_class d;
  at(t, &x, &d);
  const mpz_class d2 = d * d;
  return sign_of_polynomial(
      predicates::edge_edge_separation(point(x[0]), point(x[1]), point(x[2]), point(x[3]), d2),
      k);
}

}  // namespace exactccd::filters::separation
