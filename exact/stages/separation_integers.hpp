// Exact values at double times of the minimum-separation region polynomials that the search
// tightens most (core/predicates/separation.hpp): polynomial 0 of both separations, the face or
// interior region's (W.m)^2 - delta^2 |m|^2 with m = U x V (vertex-face U, V, W = b - a, c - a,
// p - a; edge-edge a1 - a0, b1 - b0, a0 - b0), and the capsules' sides
// |W|^2 |E|^2 - (W.E)^2 - delta^2 |E|^2 of a vertex p against a segment [x, y] (W = p - x,
// E = y - x), both formed from differences of the moving vertices. Written once over staged
// integer types, as exact/stages/integer_cubic.hpp: FixedInt widths chosen from the proven
// bit-length bounds before computing (no allocation), or mpz_class throughout (beyond the widest of
// them, and as the tests' reference). Every double is an integer times the common power of two 2^E;
// at t = T 2^-k the differences are formed as 2^(k-E) times their values, which multiplies a
// polynomial homogeneous of degree d by 2^(d(k-E)) > 0.
// PROOF: proofs/min_separation.md#fixed-width-signs
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>

#include "exact/arithmetic/fixed_int.hpp"
#include "exact/arithmetic/integer_arithmetic.hpp"
#include "exact/arithmetic/integer_bounds.hpp"
#include "exact/stages/integer_cubic.hpp"

namespace exactccd::exact {

/// The four moving vertices (at t = 0 and t = 1) and delta as integers: each double is
/// X 2^E with X = mantissa 2^(exponent - E), |X| < 2^bits.
struct SeparationIntegers {
  Dyadic coords[2][4][3];  // [end][vertex][axis]
  Dyadic delta;
  int common_exponent = 0;  // E: the smallest exponent of a non-zero input
  int bits = 0;             // L (0 when all inputs are zero)
};

inline SeparationIntegers separation_integers(const std::array<const Eigen::Vector3d*, 4>& t0,
                                              const std::array<const Eigen::Vector3d*, 4>& t1,
                                              double delta) {
  SeparationIntegers q;
  int lowest = INT_MAX, highest = INT_MIN;
  auto take = [&lowest, &highest](double x, Dyadic* out) {
    *out = dyadic(x);
    if (out->mantissa == 0) return;
    lowest = std::min(lowest, out->exponent);
    highest = std::max(highest, out->exponent + mantissa_bits(out->mantissa));
  };
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) {
      take(t0[i]->coeff(c), &q.coords[0][i][c]);
      take(t1[i]->coeff(c), &q.coords[1][i][c]);
    }
  take(delta, &q.delta);
  if (lowest != INT_MAX) {
    q.common_exponent = lowest;
    q.bits = highest - lowest;
  }
  return q;
}

/// The vertices (origin, end) of three differences, in the separation's vertex order.
struct DifferenceVertices {
  int origin[3], end[3];
};
/// Vertex-face (p, a, b, c): U = b - a, V = c - a, W = p - a.
inline constexpr DifferenceVertices kVertexFaceRegion{{1, 1, 1}, {2, 3, 0}};
/// Edge-edge (a0, a1, b0, b1): U = a1 - a0, V = b1 - b0, W = a0 - b0.
inline constexpr DifferenceVertices kEdgeEdgeRegion{{0, 2, 2}, {1, 3, 0}};
/// The capsule of vertex p against the segment [x, y]: W = p - x, E = y - x (the third
/// difference repeats W). Vertex-face: p against ab, bc, ca (polynomials 7, 11, 15); edge-edge:
/// a0, a1 against [b0, b1], b0, b1 against [a0, a1] (polynomials 11, 14, 17, 20).
constexpr DifferenceVertices capsule_vertices(int p, int x, int y) { return {{x, x, x}, {p, y, p}}; }
inline constexpr DifferenceVertices kVertexFaceCapsules[3] = {
    capsule_vertices(0, 1, 2), capsule_vertices(0, 2, 3), capsule_vertices(0, 3, 1)};
inline constexpr DifferenceVertices kEdgeEdgeCapsules[4] = {
    capsule_vertices(0, 2, 3), capsule_vertices(1, 2, 3), capsule_vertices(2, 0, 1),
    capsule_vertices(3, 0, 1)};
/// The end sphere |p - v|^2 - delta^2: W = p - v (the other differences repeat it).
/// Vertex-face: p against a, b, c (polynomials 4, 8, 12); edge-edge: a0b0, a0b1, a1b0, a1b1
/// (polynomials 5-8).
constexpr DifferenceVertices sphere_vertices(int p, int v) { return {{v, v, v}, {p, p, p}}; }
inline constexpr DifferenceVertices kVertexFaceSpheres[3] = {
    sphere_vertices(0, 1), sphere_vertices(0, 2), sphere_vertices(0, 3)};
inline constexpr DifferenceVertices kEdgeEdgeSpheres[4] = {
    sphere_vertices(0, 2), sphere_vertices(0, 3), sphere_vertices(1, 2), sphere_vertices(1, 3)};
/// A side's projection (p - x).(y - x) from the capsule's differences W = p - x, E = y - x:
/// capsule_vertices(p, x, y) for the projection from x, capsule_vertices(p, y, x) from y.
/// Vertex-face edge i (x, y = its first and second vertex): polynomials 5 + 4i, 6 + 4i;
/// edge-edge endpoint i: 9 + 3i, 10 + 3i.
inline constexpr DifferenceVertices kVertexFaceProjectionsFromY[3] = {
    capsule_vertices(0, 2, 1), capsule_vertices(0, 3, 2), capsule_vertices(0, 1, 3)};
inline constexpr DifferenceVertices kEdgeEdgeProjectionsFromY[4] = {
    capsule_vertices(0, 3, 2), capsule_vertices(1, 3, 2), capsule_vertices(2, 1, 0),
    capsule_vertices(3, 1, 0)};

/// The integer types of the stages: differences (and 2^k delta); products of two (cross
/// products, dot products of differences, squared delta); the dot product W.m; products of
/// four (|m|^2, a capsule's value); the face-like value. FixedInt widths grow from stage to
/// stage; GMP uses one type for all.
template <class DifferenceInt, class CrossInt, class DotInt, class NormInt, class ValueInt>
struct StageIntegers {
  using Difference = DifferenceInt;
  using Cross = CrossInt;
  using Dot = DotInt;
  using Norm = NormInt;
  using Value = ValueInt;
};

/// The widths for differences of Wd limbs: the stages of proofs/min_separation.md#fixed-width-signs.
template <int Wd>
using FixedStageIntegers = StageIntegers<FixedInt<Wd>, FixedInt<2 * Wd>, FixedInt<3 * Wd>,
                                               FixedInt<4 * Wd>, FixedInt<6 * Wd>>;
using GmpStageIntegers = StageIntegers<mpz_class, mpz_class, mpz_class, mpz_class, mpz_class>;

/// The widest differences computed in FixedInt (face-like values in FixedInt<18>); GMP
/// beyond.
inline constexpr int kMaxDifferenceLimbs = 3;

/// Bits bounding every intermediate of the differences at t = T 2^-k: B + 2 with B = L + k.
inline long separation_difference_bits(int coordinate_bits, unsigned k) {
  return static_cast<long>(coordinate_bits) + static_cast<long>(k) + 2;
}

/// The integer of an input: X = mantissa 2^(exponent - E), times 2^shift.
template <class Int>
Int separation_integer(const Dyadic& d, int common_exponent, unsigned shift) {
  if (d.mantissa == 0) return Int(0);
  return scaled_integer<Int>(d.mantissa,
                             static_cast<unsigned>(d.exponent - common_exponent) + shift);
}

/// U, V, W of t-independent integers: each component's difference d0 at t = 0 and its
/// change d1 - d0 over the step (|d0| < 2^(L+1), |d1 - d0| < 2^(L+2)), and X_delta.
template <class Int>
struct StepDifferences {
  Int d0[3][3], step[3][3];  // [U, V, W][axis]
  Int delta;
};

template <class Int>
StepDifferences<Int> step_differences(const SeparationIntegers& q,
                                               const DifferenceVertices& v) {
  const int E = q.common_exponent;
  StepDifferences<Int> r;
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) {
      Int d0 = separation_integer<Int>(q.coords[0][v.end[j]][c], E, 0);
      d0 -= separation_integer<Int>(q.coords[0][v.origin[j]][c], E, 0);
      Int step = separation_integer<Int>(q.coords[1][v.end[j]][c], E, 0);
      step -= separation_integer<Int>(q.coords[1][v.origin[j]][c], E, 0);
      step -= d0;
      r.d0[j][c] = d0;
      r.step[j][c] = step;
    }
  r.delta = separation_integer<Int>(q.delta, E, 0);
  return r;
}

/// The widest differences' integers: FixedInt<3> holds them when L + 2 <= 191, which every
/// fixed width (B + 2 <= 191, B >= L) implies.
using StoredStepDifferences = StepDifferences<FixedInt<kMaxDifferenceLimbs>>;

/// x in the type To: a FixedInt narrowed to fewer limbs (exact when its value fits), or as is.
template <class To, int N>
To narrowed(const FixedInt<N>& x) {
  return x.template resized<To::kLimbs>();
}
template <class To>
To narrowed(const mpz_class& x) {
  return x;
}

/// (X_delta 2^k)^2, a product of two differences' width.
template <class Ints, class Int>
typename Ints::Cross squared_delta(const StepDifferences<Int>& in, unsigned k) {
  using D = typename Ints::Difference;
  D delta(0);
  add_shifted(delta, narrowed<D>(in.delta), k);
  typename Ints::Cross r(0);
  add_product(r, delta, delta);
  return r;
}

/// The differences at t = T 2^-k, times 2^(k - E): 2^k d0 + T (d1 - d0).
template <class D, class Int>
void differences_at(const StepDifferences<Int>& in, std::uint64_t T, unsigned k, D (&d)[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) {
      D v = narrowed<D>(in.step[j][c]);
      multiply_by(v, T);
      add_shifted(v, narrowed<D>(in.d0[j][c]), k);
      d[j][c] = v;
    }
}

/// 2^(6(k - E)) g(t) at t = T 2^-k (T <= 2^k, i.e. t <= 1), g = (W.m)^2 - delta^2 |m|^2, from
/// the differences (in a type that holds their values).
template <class Ints, class Int>
typename Ints::Value face_like_value(const StepDifferences<Int>& in, std::uint64_t T,
                                     unsigned k) {
  using D = typename Ints::Difference;
  using X = typename Ints::Cross;
  D d[3][3];
  differences_at(in, T, k, d);
  X m[3] = {X(0), X(0), X(0)};
  for (int c = 0; c < 3; ++c) {
    const int i = (c + 1) % 3, j = (c + 2) % 3;
    add_product(m[c], d[0][i], d[1][j]);
    sub_product(m[c], d[0][j], d[1][i]);
  }
  typename Ints::Dot wm(0);
  for (int c = 0; c < 3; ++c) add_product(wm, m[c], d[2][c]);
  typename Ints::Norm m2(0);
  for (int c = 0; c < 3; ++c) add_product(m2, m[c], m[c]);
  const X delta2 = squared_delta<Ints>(in, k);
  typename Ints::Value g(0);
  add_product(g, wm, wm);
  sub_product(g, delta2, m2);
  return g;
}

/// 2^(4(k - E)) c(t) at t = T 2^-k for a capsule's c = |W|^2 |E|^2 - (W.E)^2 - delta^2 |E|^2
/// (differences from capsule_vertices).
template <class Ints, class Int>
typename Ints::Norm capsule_value(const StepDifferences<Int>& in, std::uint64_t T, unsigned k) {
  using D = typename Ints::Difference;
  using X = typename Ints::Cross;
  D d[3][3];
  differences_at(in, T, k, d);
  X ww(0), ee(0), we(0);
  for (int c = 0; c < 3; ++c) {
    add_product(ww, d[0][c], d[0][c]);
    add_product(ee, d[1][c], d[1][c]);
    add_product(we, d[0][c], d[1][c]);
  }
  const X delta2 = squared_delta<Ints>(in, k);
  typename Ints::Norm v(0);
  add_product(v, ww, ee);
  sub_product(v, we, we);
  sub_product(v, delta2, ee);
  return v;
}

/// 2^(2(k - E)) s(t) at t = T 2^-k for an end sphere's s = |W|^2 - delta^2 (differences from
/// sphere_vertices).
template <class Ints, class Int>
typename Ints::Cross sphere_value(const StepDifferences<Int>& in, std::uint64_t T, unsigned k) {
  using D = typename Ints::Difference;
  D d[3][3];
  differences_at(in, T, k, d);
  typename Ints::Cross v(0);
  for (int c = 0; c < 3; ++c) add_product(v, d[0][c], d[0][c]);
  v -= squared_delta<Ints>(in, k);
  return v;
}

/// 2^(2(k - E)) W.E at t = T 2^-k (a side's projection; differences from capsule_vertices).
template <class Ints, class Int>
typename Ints::Cross projection_value(const StepDifferences<Int>& in, std::uint64_t T,
                                      unsigned k) {
  using D = typename Ints::Difference;
  D d[3][3];
  differences_at(in, T, k, d);
  typename Ints::Cross v(0);
  for (int c = 0; c < 3; ++c) add_product(v, d[0][c], d[1][c]);
  return v;
}

/// The same from the query's integers.
template <class Ints>
typename Ints::Value face_like_value(const SeparationIntegers& q, const DifferenceVertices& v,
                                     std::uint64_t T, unsigned k) {
  return face_like_value<Ints>(step_differences<typename Ints::Difference>(q, v), T, k);
}
template <class Ints>
typename Ints::Norm capsule_value(const SeparationIntegers& q, const DifferenceVertices& v,
                                  std::uint64_t T, unsigned k) {
  return capsule_value<Ints>(step_differences<typename Ints::Difference>(q, v), T, k);
}

}  // namespace exactccd::exact
