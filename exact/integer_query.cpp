#include "exact/integer_query.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/inclusion.hpp"
#include "exact/rational.hpp"

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
  const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1: exact
  return {static_cast<std::int64_t>(std::ldexp(m, 53)), e - 53};
}

mpz_class shifted(mpz_class z, long bits) {
  z <<= static_cast<mp_bitcnt_t>(bits);
  return z;
}

std::array<Vec3<mpz_class>, 8> integer_points(const std::array<const Eigen::Vector3d*, 8>& p) {
  Dyadic d[8][3];
  int common = INT_MAX;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      d[i][k] = dyadic(p[i]->coeff(k));
      if (d[i][k].mantissa != 0) common = std::min(common, d[i][k].exponent);
    }
  if (common == INT_MAX) common = 0;
  std::array<Vec3<mpz_class>, 8> out;
  for (int i = 0; i < 8; ++i) {
    mpz_class c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = shifted(mpz_class(static_cast<long>(d[i][k].mantissa)), d[i][k].exponent - common);
    out[i] = {c[0], c[1], c[2]};
  }
  return out;
}

MovingPoint<mpz_class> moving(const Vec3<mpz_class>& x0, const Vec3<mpz_class>& x1) {
  return predicates::linear_motion(x0, x1);
}

using Position = Vec3<FixedPoly<mpz_class, 0>>;

/// 2^k x(t) for t = tau 2^-k: 2^k x0 + tau (x1 - x0), exactly.
Position position_at(const Vec3<mpz_class>& x0, const Vec3<mpz_class>& x1, long tau, long k) {
  auto coord = [&](const mpz_class& a, const mpz_class& b) {
    mpz_class r = b - a;
    r *= tau;
    r += shifted(a, k);
    return FixedPoly<mpz_class, 0>{{r}};
  };
  return {coord(x0.x, x1.x), coord(x0.y, x1.y), coord(x0.z, x1.z)};
}

}  // namespace

IntegerQuery::IntegerQuery(const VertexFaceQuery& q)
    : type_(QueryType::vertex_face),
      points_(integer_points({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1,
                              &q.c_t1})) {
  const auto f = predicates::vertex_face_coplanarity_cubic(
      moving(points_[0], points_[4]), moving(points_[1], points_[5]),
      moving(points_[2], points_[6]), moving(points_[3], points_[7]));
  for (int i = 0; i < 4; ++i) cubic_[i] = f.c[i];
}

IntegerQuery::IntegerQuery(const EdgeEdgeQuery& q)
    : type_(QueryType::edge_edge),
      points_(integer_points({&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1,
                              &q.eb0_t1, &q.eb1_t1})) {
  const auto f = predicates::edge_edge_coplanarity_cubic(
      moving(points_[0], points_[4]), moving(points_[1], points_[5]),
      moving(points_[2], points_[6]), moving(points_[3], points_[7]));
  for (int i = 0; i < 4; ++i) cubic_[i] = f.c[i];
}

int IntegerQuery::cubic_sign_at(double t) const {
  if (t == 0) return sgn(cubic_[0]);
  // t = T 2^-k: 2^(3k) f(t) = ((c3 T + c2 2^k) T + c1 2^(2k)) T + c0 2^(3k), all integers.
  const Dyadic d = dyadic(t);
  if (d.exponent >= 0) {  // an integer t (only t = 1 can occur, as 2^52 * 2^-52 otherwise)
    const mpz_class tz = shifted(mpz_class(static_cast<long>(d.mantissa)), d.exponent);
    mpz_class r = cubic_[3];
    for (int i = 2; i >= 0; --i) r = r * tz + cubic_[i];
    return sgn(r);
  }
  const long T = static_cast<long>(d.mantissa), k = -d.exponent;
  mpz_class r = cubic_[3];
  for (int i = 2; i >= 0; --i) {
    r *= T;
    r += shifted(cubic_[i], k * (3 - i));
  }
  return sgn(r);
}

std::pair<double, double> IntegerQuery::bisect_root(double lo, double hi, double width) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int sign_lo = cubic_sign_at(lo);
  for (;;) {
    const double first = std::nextafter(lo, kInf), last = std::nextafter(hi, -kInf);
    if (first > last || (width > 0 && difference_at_most(hi, lo, width))) return {lo, hi};
    std::uint64_t a, b;
    std::memcpy(&a, &first, sizeof a);
    std::memcpy(&b, &last, sizeof b);
    const std::uint64_t mid_bits = a + (b - a) / 2;  // non-negative doubles: bit order = order
    double mid;
    std::memcpy(&mid, &mid_bits, sizeof mid);
    const int s = cubic_sign_at(mid);
    if (s == 0) return {mid, mid};
    (s == sign_lo ? lo : hi) = mid;
  }
}

bool IntegerQuery::contact_at(double t) const {
  long tau = 0, k = 0;
  if (t != 0) {
    const Dyadic d = dyadic(t);
    if (d.exponent >= 0) {  // t == 1 (t <= 1 always): positions at t = 1
      tau = 1;
    } else {
      tau = static_cast<long>(d.mantissa);
      k = -d.exponent;
    }
  }
  Position x[4];
  for (int i = 0; i < 4; ++i) x[i] = position_at(points_[i], points_[i + 4], tau, k);
  auto sign_at = [](const auto& q) { return sgn(q.c[0]); };
  return type_ == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

}  // namespace exactccd::exact
