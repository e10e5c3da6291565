#include "exact/integer_query.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/predicates/inclusion.hpp"
#include "exact/rational.hpp"

namespace exactccd::exact {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;
using Dyadic = IntegerQuery::Dyadic;

Dyadic dyadic(double x) {
  if (x == 0) return {};
  int e;
  const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1: exact
  return {static_cast<std::int64_t>(std::ldexp(m, 53)), e - 53};
}

/// z = d * 2^(d.exponent - common): the coordinate scaled to an integer.
void set_scaled(mpz_class& z, const Dyadic& d, int common) {
  z = static_cast<long>(d.mantissa);
  if (d.mantissa != 0) mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), d.exponent - common);
}

/// Per-thread temporaries: their limbs are reused from query to query.
struct Workspace {
  mpz_class a, b;                        // scratch
  mpz_class v0[3], dv[3], w0[3], dw[3], u0[3], du[3];
  mpz_class x0[3], x1[3], x2[3];         // cross(v, w) = x0 + t x1 + t^2 x2
  mpz_class r, term;                     // Horner
};
thread_local Workspace workspace;

/// out = first - second for the scaled coordinate k of two points, at t = 0 and t = 1.
void difference(const Dyadic (&c)[8][3], int common, int first, int second, mpz_class out0[3],
                mpz_class out1[3]) {
  Workspace& w = workspace;
  for (int k = 0; k < 3; ++k) {
    set_scaled(w.a, c[first][k], common);
    set_scaled(w.b, c[second][k], common);
    out0[k] = w.a - w.b;
    set_scaled(w.a, c[first + 4][k], common);
    set_scaled(w.b, c[second + 4][k], common);
    out1[k] = w.a - w.b;
    out1[k] -= out0[k];  // the change over the step
  }
}

/// out += p x q, componentwise, with add-multiply (no temporaries).
void add_cross(mpz_class out[3], const mpz_class p[3], const mpz_class q[3]) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpz_addmul(out[k].get_mpz_t(), p[i].get_mpz_t(), q[j].get_mpz_t());
    mpz_submul(out[k].get_mpz_t(), p[j].get_mpz_t(), q[i].get_mpz_t());
  }
}

void add_dot(mpz_class& out, const mpz_class p[3], const mpz_class q[3]) {
  for (int k = 0; k < 3; ++k) mpz_addmul(out.get_mpz_t(), p[k].get_mpz_t(), q[k].get_mpz_t());
}

/// Positions at t = tau 2^-k, scaled by 2^k: 2^k x0 + tau (x1 - x0), exact integers.
using Position = Vec3<FixedPoly<mpz_class, 0>>;
Position position_at(const Dyadic (&c)[8][3], int common, int point, long tau, long k) {
  Position p;
  mpz_class* out[3] = {&p.x.c[0], &p.y.c[0], &p.z.c[0]};
  for (int axis = 0; axis < 3; ++axis) {
    mpz_class x0, x1;
    set_scaled(x0, c[point][axis], common);
    set_scaled(x1, c[point + 4][axis], common);
    mpz_class& r = *out[axis];
    r = x1 - x0;
    r *= tau;
    mpz_mul_2exp(x0.get_mpz_t(), x0.get_mpz_t(), static_cast<mp_bitcnt_t>(k));
    r += x0;
  }
  return p;
}

}  // namespace

// The same cubics as core/predicates/coplanarity_cubic.hpp, expanded for in-place integer
// arithmetic (tests/filters_test.cpp checks the two agree): with v, w, u the difference
// vectors (vertex-face b-a, c-a, p-a; edge-edge a1-a0, b0-a0, b1-a0), each v0 + t dv,
// f(t) = (v x w) . u.
void IntegerQuery::compute_cubic() {
  int common = INT_MAX;
  for (const auto& point : coords_)
    for (const Dyadic& d : point)
      if (d.mantissa != 0) common = std::min(common, d.exponent);
  common_exponent_ = common == INT_MAX ? 0 : common;
  const bool vf = type_ == QueryType::vertex_face;
  // Row indices at t = 0 (the t = 1 row is index + 4).
  // vertex-face rows p, a, b, c: v = b - a, w = c - a, u = p - a;
  // edge-edge rows a0, a1, b0, b1: v = a1 - a0, w = b0 - a0, u = b1 - a0.
  const int origin = vf ? 1 : 0, v_end = vf ? 2 : 1, w_end = vf ? 3 : 2, u_end = vf ? 0 : 3;
  Workspace& ws = workspace;
  difference(coords_, common_exponent_, v_end, origin, ws.v0, ws.dv);
  difference(coords_, common_exponent_, w_end, origin, ws.w0, ws.dw);
  difference(coords_, common_exponent_, u_end, origin, ws.u0, ws.du);
  for (int k = 0; k < 3; ++k) ws.x0[k] = 0, ws.x1[k] = 0, ws.x2[k] = 0;
  add_cross(ws.x0, ws.v0, ws.w0);
  add_cross(ws.x1, ws.v0, ws.dw);
  add_cross(ws.x1, ws.dv, ws.w0);
  add_cross(ws.x2, ws.dv, ws.dw);
  for (auto& c : cubic_) c = 0;
  add_dot(cubic_[0], ws.x0, ws.u0);
  add_dot(cubic_[1], ws.x0, ws.du);
  add_dot(cubic_[1], ws.x1, ws.u0);
  add_dot(cubic_[2], ws.x1, ws.du);
  add_dot(cubic_[2], ws.x2, ws.u0);
  add_dot(cubic_[3], ws.x2, ws.du);
}

IntegerQuery::IntegerQuery(const VertexFaceQuery& q) : type_(QueryType::vertex_face) {
  const Eigen::Vector3d* p[8] = {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0,
                                 &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1};
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords_[i][k] = dyadic(p[i]->coeff(k));
  compute_cubic();
}

IntegerQuery::IntegerQuery(const EdgeEdgeQuery& q) : type_(QueryType::edge_edge) {
  const Eigen::Vector3d* p[8] = {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0,
                                 &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords_[i][k] = dyadic(p[i]->coeff(k));
  compute_cubic();
}

int IntegerQuery::cubic_sign_at(double t) const {
  if (t == 0) return sgn(cubic_[0]);
  // t = T 2^-k: 2^(3k) f(t) = ((c3 T + c2 2^k) T + c1 2^(2k)) T + c0 2^(3k), all integers.
  const Dyadic d = dyadic(t);
  Workspace& ws = workspace;
  if (d.exponent >= 0) {  // an integer t; t <= 1 makes this t == 1 only for exponent 0 forms
    mpz_class tz = static_cast<long>(d.mantissa);
    mpz_mul_2exp(tz.get_mpz_t(), tz.get_mpz_t(), static_cast<mp_bitcnt_t>(d.exponent));
    ws.r = cubic_[3];
    for (int i = 2; i >= 0; --i) {
      ws.r *= tz;
      ws.r += cubic_[i];
    }
    return sgn(ws.r);
  }
  const long T = static_cast<long>(d.mantissa);
  const auto k = static_cast<mp_bitcnt_t>(-d.exponent);
  ws.r = cubic_[3];
  for (int i = 2; i >= 0; --i) {
    ws.r *= T;
    mpz_mul_2exp(ws.term.get_mpz_t(), cubic_[i].get_mpz_t(), k * static_cast<mp_bitcnt_t>(3 - i));
    ws.r += ws.term;
  }
  return sgn(ws.r);
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
  for (int i = 0; i < 4; ++i) x[i] = position_at(coords_, common_exponent_, i, tau, k);
  auto sign_at = [](const auto& q) { return sgn(q.c[0]); };
  return type_ == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

}  // namespace exactccd::exact
