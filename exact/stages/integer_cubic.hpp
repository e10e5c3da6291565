// Exact answers at double times in integer arithmetic, written once over the integer type and
// instantiated with FixedInt<N> (stack, N chosen from exact/arithmetic/integer_bounds.hpp) and with
// mpz_class (the reference, and the fallback beyond the largest fixed width):
//  - the coplanarity cubic's integer coefficients,
//  - 2^(3k) f(t) at a double t = T 2^-k,
//  - the contact test at a double t: the positions 2^k x(t) as integers, then the inclusion
//    predicates of core/predicates/inclusion.hpp with the exact sign of each value.
// Every input double is an integer times a common power of two 2^E; scaling space by 2^-E
// (a positive constant) changes no contact, no contact time and no sign used here.
// PROOF: proofs/filters.md#exact-at-double-times
#pragma once

#include <algorithm>
#include <climits>
#include <cstdint>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/inclusion.hpp"
#include "core/predicates/query_points.hpp"
#include "exact/arithmetic/fixed_int.hpp"
#include "exact/arithmetic/integer_arithmetic.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

/// x = mantissa 2^exponent with an odd mantissa (both 0 for x = 0). No default member values:
/// arrays of them are filled, never read before.
struct Dyadic {
  std::int64_t mantissa;
  int exponent;
};

inline Dyadic dyadic(double x) {
  const std::uint64_t bits = predicates::bits_of(x);
  const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
  int e = -1074;  // subnormal (or zero)
  if (biased != 0) {
    m |= std::uint64_t{1} << 52;
    e = biased - 1075;
  }
  if (m == 0) return {0, 0};
  const int zeros = __builtin_ctzll(m);
  m >>= zeros;
  const auto signed_m = static_cast<std::int64_t>(m);
  return {(bits >> 63) != 0 ? -signed_m : signed_m, e + zeros};
}

/// |m| as an unsigned integer (exact for every int64, the most negative included).
inline std::uint64_t magnitude_of(std::int64_t m) {
  return m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
}

/// The bits of |mantissa| (1 to 53).
inline int mantissa_bits(std::int64_t m) { return 64 - __builtin_clzll(magnitude_of(m)); }

/// A query's coordinates as integers: every input double is X 2^E with the integer
/// X = mantissa 2^(exponent - E), and |X| < 2^bits.
struct IntegerCoordinates {
  QueryType type = QueryType::vertex_face;
  Dyadic coords[8][3];      // benchmark row order
  int common_exponent = 0;  // E: the smallest exponent of a non-zero coordinate
  int bits = 0;             // L: the largest bit length of an X (0 when all are zero)
};

inline IntegerCoordinates integer_coordinates(QueryType type,
                                              const predicates::QueryPoints& p) {
  IntegerCoordinates q;
  q.type = type;
  int lowest = INT_MAX, highest = INT_MIN;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      const Dyadic d = dyadic(p[i]->coeff(k));
      q.coords[i][k] = d;
      if (d.mantissa == 0) continue;
      lowest = std::min(lowest, d.exponent);
      highest = std::max(highest, d.exponent + mantissa_bits(d.mantissa));
    }
  if (lowest != INT_MAX) {
    q.common_exponent = lowest;
    q.bits = highest - lowest;
  }
  return q;
}

inline IntegerCoordinates integer_coordinates(const VertexFaceQuery& q) {
  return integer_coordinates(QueryType::vertex_face, predicates::points_of(q));
}

inline IntegerCoordinates integer_coordinates(const EdgeEdgeQuery& q) {
  return integer_coordinates(QueryType::edge_edge, predicates::points_of(q));
}

/// A double t in [0, 1] as T 2^-k with T odd and T <= 2^k (t = 0: T = k = 0).
struct DyadicTime {
  std::uint64_t numerator = 0;  // T
  unsigned exponent = 0;        // k
};

/// False for t outside [0, 1] (NaN included).
inline bool dyadic_time(double t, DyadicTime* out) {
  if (!(t >= 0 && t <= 1)) return false;
  const Dyadic d = dyadic(t);
  out->numerator = static_cast<std::uint64_t>(d.mantissa);
  out->exponent = d.mantissa == 0 ? 0u : static_cast<unsigned>(-d.exponent);
  return true;
}

/// The integer X of row `row`, axis `axis`.
template <class Int>
EXACTCCD_FIXED_INLINE Int integer_coordinate(const IntegerCoordinates& q, int row, int axis) {
  const Dyadic& d = q.coords[row][axis];
  if (d.mantissa == 0) return Int(0);
  return scaled_integer<Int>(d.mantissa, static_cast<unsigned>(d.exponent - q.common_exponent));
}

/// The integer types of the cubic's three stages: the coordinates and their differences, the
/// cross products, the dot products (the coefficients). FixedInt widths grow from stage to stage
/// (exact/arithmetic/integer_bounds.hpp); GMP uses one type for all three.
template <class DifferenceInt, class CrossInt, class CoefficientInt>
struct CubicIntegers {
  using Difference = DifferenceInt;
  using Cross = CrossInt;
  using Coefficient = CoefficientInt;
};

template <class Int>
using SameCubicIntegers = CubicIntegers<Int, Int, Int>;

namespace detail {

/// out0 = X_first - O0 at t = 0 and out1 = its change over the step, per axis, with O0, O1 the
/// origin's coordinates at t = 0 and t = 1. (The first point's coordinates are formed where
/// they are used: cheaper than storing all 24 first.)
template <class Int>
void difference(const IntegerCoordinates& q, int first, const Int (&origin0)[3],
                const Int (&origin1)[3], Int (&out0)[3], Int (&out1)[3]) {
  for (int k = 0; k < 3; ++k) {
    out0[k] = integer_coordinate<Int>(q, first, k);
    out0[k] -= origin0[k];
    out1[k] = integer_coordinate<Int>(q, first + 4, k);
    out1[k] -= origin1[k];
    out1[k] -= out0[k];
  }
}

/// out += p x q, componentwise.
template <class Out, class Int>
void add_cross(Out (&out)[3], const Int (&p)[3], const Int (&q)[3]) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    add_product(out[k], p[i], q[j]);
    sub_product(out[k], p[j], q[i]);
  }
}

template <class Out, class Cross, class Int>
void add_dot(Out& out, const Cross (&p)[3], const Int (&q)[3]) {
  for (int k = 0; k < 3; ++k) add_product(out, p[k], q[k]);
}

}  // namespace detail

// The same cubics as core/predicates/coplanarity_cubic.hpp, expanded for in-place integer
// arithmetic (tests/filters_test.cpp checks the two agree): with v, w, u the difference
// vectors (vertex-face b-a, c-a, p-a; edge-edge a1-a0, b0-a0, b1-a0), each v0 + t dv,
// f(t) = (v x w) . u = sum c[i] t^i, scaled by 2^(-3E).
template <class Ints>
void coplanarity_coefficients(const IntegerCoordinates& q, typename Ints::Coefficient (&c)[4]) {
  using D = typename Ints::Difference;
  using X = typename Ints::Cross;
  using C = typename Ints::Coefficient;
  const bool vf = q.type == QueryType::vertex_face;
  // Row indices at t = 0 (the t = 1 row is index + 4).
  // vertex-face rows p, a, b, c: v = b - a, w = c - a, u = p - a;
  // edge-edge rows a0, a1, b0, b1: v = a1 - a0, w = b0 - a0, u = b1 - a0.
  const int origin = vf ? 1 : 0, v_end = vf ? 2 : 1, w_end = vf ? 3 : 2, u_end = vf ? 0 : 3;
  D v0[3], dv[3], w0[3], dw[3], u0[3], du[3];
  const D o0[3] = {integer_coordinate<D>(q, origin, 0), integer_coordinate<D>(q, origin, 1),
                   integer_coordinate<D>(q, origin, 2)};
  const D o1[3] = {integer_coordinate<D>(q, origin + 4, 0),
                   integer_coordinate<D>(q, origin + 4, 1),
                   integer_coordinate<D>(q, origin + 4, 2)};
  detail::difference(q, v_end, o0, o1, v0, dv);
  detail::difference(q, w_end, o0, o1, w0, dw);
  detail::difference(q, u_end, o0, o1, u0, du);
  X x0[3] = {X(0), X(0), X(0)}, x1[3] = {X(0), X(0), X(0)},
    x2[3] = {X(0), X(0), X(0)};  // v x w = x0 + t x1 + t^2 x2
  detail::add_cross(x0, v0, w0);
  detail::add_cross(x1, v0, dw);
  detail::add_cross(x1, dv, w0);
  detail::add_cross(x2, dv, dw);
  for (C& ci : c) ci = C(0);
  detail::add_dot(c[0], x0, u0);
  detail::add_dot(c[1], x0, du);
  detail::add_dot(c[1], x1, u0);
  detail::add_dot(c[2], x1, du);
  detail::add_dot(c[2], x2, u0);
  detail::add_dot(c[3], x2, du);
}

/// The same in one integer type.
template <class Int>
void coplanarity_coefficients(const IntegerCoordinates& q, Int (&c)[4]) {
  coplanarity_coefficients<SameCubicIntegers<Int>>(q, c);
}

/// 2^(3k) f(T 2^-k) = ((c3 T + c2 2^k) T + c1 2^(2k)) T + c0 2^(3k), an exact integer with the
/// sign of f(t). `Factor` is std::uint64_t (T), or an integer type for t >= 2^53 (k = 0).
template <class Int, class Factor>
Int scaled_cubic_value(const Int (&c)[4], const Factor& T, unsigned k) {
  Int r = c[3];
  for (int i = 2; i >= 0; --i) {
    multiply_by(r, T);
    add_shifted(r, c[i], k * static_cast<unsigned>(3 - i));
  }
  return r;
}

namespace detail {

/// 2^k x(t) = 2^k x0 + tau (x1 - x0) for point i (rows i and i + 4) along `axis`, at
/// t = tau 2^-k: an exact integer.
template <class Int>
Int position_at_time(const IntegerCoordinates& q, int i, int axis, std::uint64_t tau,
                     unsigned k) {
  Int r = integer_coordinate<Int>(q, i + 4, axis);
  const Int x0 = integer_coordinate<Int>(q, i, axis);
  r -= x0;
  multiply_by(r, tau);
  add_shifted(r, x0, k);
  return r;
}

}  // namespace detail

/// Exact contact test at t = tau 2^-k in [0, 1], where the cubic vanishes (coplanar): the
/// positions 2^k x(t) = 2^k x0 + tau (x1 - x0) are exact integers, and scaling space by 2^k
/// changes no incidence.
template <class Int>
bool contact_at_time(const IntegerCoordinates& q, std::uint64_t tau, unsigned k) {
  using Position = predicates::Vec3<predicates::FixedPoly<Int, 0>>;
  Position x[4];
  for (int i = 0; i < 4; ++i) {
    x[i].x.c[0] = detail::position_at_time<Int>(q, i, 0, tau, k);
    x[i].y.c[0] = detail::position_at_time<Int>(q, i, 1, tau, k);
    x[i].z.c[0] = detail::position_at_time<Int>(q, i, 2, tau, k);
  }
  auto sign_at = [](const predicates::FixedPoly<Int, 0>& p) { return sign_of(p.c[0]); };
  return q.type == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

/// The bits of the contact test's positions, their differences and every intermediate of their
/// computation, with one to spare: below 2^(L+k+1) (proofs/filters.md#fixed-size-exact-at-doubles,
/// Lemma F4), so that in P limbs with L + k + 2 <= 64P - 1 every value of the inclusion
/// predicates, below 2^(2(L+k)+4) <= 2^(128P-2), fits 2P limbs.
constexpr long contact_position_bits(long coordinate_bits, long time_exponent) {
  return coordinate_bits + time_exponent + 2;
}

/// A position, or a difference of positions, in P limbs whose products are formed exactly in
/// 2P limbs (FixedInt::product): the contact test without full-width multiplications.
template <int P>
struct WideningInt {
  FixedInt<P> value;
};

template <int P>
EXACTCCD_FIXED_INLINE WideningInt<P> operator-(const WideningInt<P>& a, const WideningInt<P>& b) {
  return {a.value - b.value};
}

template <int P>
EXACTCCD_FIXED_INLINE FixedInt<2 * P> operator*(const WideningInt<P>& a, const WideningInt<P>& b) {
  return FixedInt<2 * P>::product(a.value, b.value);
}

/// contact_at_time with the positions in P limbs (contact_position_bits(L, k) <= 64P - 1) and
/// every product, orientation, cross-product component and dot product in 2P limbs: the same
/// values, exact by the same bounds, with narrower multiplications.
template <int P>
bool contact_at_time_widening(const IntegerCoordinates& q, std::uint64_t tau, unsigned k) {
  using Position = predicates::Vec3<WideningInt<P>>;
  Position x[4];
  for (int i = 0; i < 4; ++i) {
    x[i].x.value = detail::position_at_time<FixedInt<P>>(q, i, 0, tau, k);
    x[i].y.value = detail::position_at_time<FixedInt<P>>(q, i, 1, tau, k);
    x[i].z.value = detail::position_at_time<FixedInt<P>>(q, i, 2, tau, k);
  }
  auto sign_at = [](const FixedInt<2 * P>& v) { return sign_of(v); };
  return q.type == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

}  // namespace exactccd::exact
