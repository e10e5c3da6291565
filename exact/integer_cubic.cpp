#include "exact/integer_cubic.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/predicates/coplanarity_cubic.hpp"

namespace exactccd::exact {

namespace {

using predicates::FixedPoly;
using predicates::MovingPoint;
using predicates::Vec3;

/// x = mantissa * 2^exponent with an integer mantissa of at most 53 bits.
struct Dyadic {
  std::int64_t mantissa = 0;
  int exponent = 0;
};

Dyadic dyadic(double x) {
  if (x == 0) return {};
  int e;
  const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1
  return {static_cast<std::int64_t>(std::ldexp(m, 53)), e - 53};
}

mpz_class scaled(const Dyadic& d, int common_exponent) {
  mpz_class z(static_cast<long>(d.mantissa));
  z <<= static_cast<mp_bitcnt_t>(d.exponent - common_exponent);
  return z;
}

template <class MakeCubic>
void integer_coefficients(const Eigen::Vector3d* const* points, MakeCubic make, mpz_class* c) {
  Dyadic d[8][3];
  int common = INT_MAX;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      d[i][k] = dyadic(points[i]->coeff(k));
      if (d[i][k].mantissa != 0) common = std::min(common, d[i][k].exponent);
    }
  if (common == INT_MAX) common = 0;
  MovingPoint<mpz_class> m[4];
  for (int i = 0; i < 4; ++i) {
    const Vec3<mpz_class> x0{scaled(d[i][0], common), scaled(d[i][1], common),
                             scaled(d[i][2], common)};
    const Vec3<mpz_class> x1{scaled(d[i + 4][0], common), scaled(d[i + 4][1], common),
                             scaled(d[i + 4][2], common)};
    m[i] = predicates::linear_motion(x0, x1);
  }
  const FixedPoly<mpz_class, 3> f = make(m[0], m[1], m[2], m[3]);
  for (int i = 0; i < 4; ++i) c[i] = f.c[i];
}

}  // namespace

IntegerCubic::IntegerCubic(const VertexFaceQuery& q) {
  const Eigen::Vector3d* p[8] = {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0,
                                 &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1};
  integer_coefficients(p, predicates::vertex_face_coplanarity_cubic<mpz_class>, c_);
}

IntegerCubic::IntegerCubic(const EdgeEdgeQuery& q) {
  const Eigen::Vector3d* p[8] = {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0,
                                 &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
  integer_coefficients(p, predicates::edge_edge_coplanarity_cubic<mpz_class>, c_);
}

int IntegerCubic::sign_at(double t) const {
  if (t == 0) return sgn(c_[0]);
  // t = T 2^-k: 2^(3k) f(t) = ((c3 T + c2 2^k) T + c1 2^(2k)) T + c0 2^(3k), all integers.
  const Dyadic d = dyadic(t);
  const long T = static_cast<long>(d.mantissa);
  if (d.exponent >= 0) {  // t >= 1 is an integer (only t == 1 occurs here)
    mpz_class tz(T);
    tz <<= static_cast<mp_bitcnt_t>(d.exponent);
    mpz_class r = c_[3];
    for (int i = 2; i >= 0; --i) r = r * tz + c_[i];
    return sgn(r);
  }
  const auto k = static_cast<mp_bitcnt_t>(-d.exponent);
  mpz_class r = c_[3], term;
  for (int i = 2; i >= 0; --i) {
    r *= T;
    term = c_[i];
    term <<= k * static_cast<mp_bitcnt_t>(3 - i);
    r += term;
  }
  return sgn(r);
}

std::pair<double, double> IntegerCubic::bisect_root(double lo, double hi, double width) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int sign_lo = sign_at(lo);
  for (;;) {
    const double first = std::nextafter(lo, kInf), last = std::nextafter(hi, -kInf);
    if (first > last || (width > 0 && hi - lo <= width)) return {lo, hi};
    std::uint64_t a, b;
    std::memcpy(&a, &first, sizeof a);
    std::memcpy(&b, &last, sizeof b);
    const std::uint64_t mid_bits = a + (b - a) / 2;  // non-negative doubles: bit order = order
    double mid;
    std::memcpy(&mid, &mid_bits, sizeof mid);
    const int s = sign_at(mid);
    if (s == 0) return {mid, mid};
    (s == sign_lo ? lo : hi) = mid;
  }
}

}  // namespace exactccd::exact
