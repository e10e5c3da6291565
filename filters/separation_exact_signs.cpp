// PROOF: proofs/min_separation.md#interval-search
#include "filters/separation_exact_signs.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

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

/// The exponent of t's last bit: t = m 2^e with an integer m (0 for t = 0).
long ulp_exponent(double t) {
  if (t == 0) return 0;
  std::int64_t m = 0;
  int e = 0;
  split(t, &m, &e);
  return e;
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

void ExactSignsAtDoubles::at(double t, long shift, std::array<Position, 4>* positions,
                             mpz_class* delta) const {
  // t = m 2^e: positions (x0 + t dx) 2^shift = x0 2^shift + m dx 2^(shift + e), exactly.
  std::int64_t m = 0;
  int e = 0;
  if (t != 0) split(t, &m, &e);
  const mpz_class mz(static_cast<long>(m));
  const mp_bitcnt_t up = static_cast<mp_bitcnt_t>(shift);
  const mp_bitcnt_t up_m = t == 0 ? 0 : static_cast<mp_bitcnt_t>(shift + e);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      (*positions)[i][c] = (x0_[i][c] << up) + ((mz * dx_[i][c]) << up_m);
  *delta = delta_ << up;
}

template <class Make>
mpz_class ExactSignsAtDoubles::value(const Make& make, int k, double t, long shift) const {
  std::array<Position, 4> x;
  mpz_class d;
  at(t, shift, &x, &d);
  const mpz_class d2 = d * d;
  mpz_class v;
  make(point(x[0]), point(x[1]), point(x[2]), point(x[3]), d2)
      .for_each_polynomial([&v](const auto& g) { v = g.c[0]; }, k);
  return v;
}

template <class Make>
double ExactSignsAtDoubles::secant(const Make& make, int k, double lo, double hi) const {
  // One scale for both ends (the finer ulp's), so that the values are comparable.
  const long shift = std::max(-ulp_exponent(lo), -ulp_exponent(hi));
  const mpz_class v_lo = value(make, k, lo, shift), v_hi = value(make, k, hi, shift);
  const mpz_class diff = v_lo - v_hi;
  if (sgn(diff) == 0) return std::numeric_limits<double>::quiet_NaN();
  long e_num = 0, e_den = 0;
  const double num = mpz_get_d_2exp(&e_num, v_lo.get_mpz_t());
  const double den = mpz_get_d_2exp(&e_den, diff.get_mpz_t());
  return lo + (hi - lo) * std::ldexp(num / den, static_cast<int>(e_num - e_den));
}

namespace {

struct MakeVertexFace {
  template <class Point, class NT>
  auto operator()(const Point& p, const Point& a, const Point& b, const Point& c,
                  const NT& d2) const {
    return predicates::vertex_face_separation(p, a, b, c, d2);
  }
};

struct MakeEdgeEdge {
  template <class Point, class NT>
  auto operator()(const Point& a0, const Point& a1, const Point& b0, const Point& b1,
                  const NT& d2) const {
    return predicates::edge_edge_separation(a0, a1, b0, b1, d2);
  }
};

}  // namespace

int ExactSignsAtDoubles::vertex_face_sign(int k, double t) const {
  return sgn(value(MakeVertexFace{}, k, t, -ulp_exponent(t)));
}

int ExactSignsAtDoubles::edge_edge_sign(int k, double t) const {
  return sgn(value(MakeEdgeEdge{}, k, t, -ulp_exponent(t)));
}

double ExactSignsAtDoubles::vertex_face_secant(int k, double lo, double hi) const {
  return secant(MakeVertexFace{}, k, lo, hi);
}

double ExactSignsAtDoubles::edge_edge_secant(int k, double lo, double hi) const {
  return secant(MakeEdgeEdge{}, k, lo, hi);
}

}  // namespace exactccd::filters::separation
