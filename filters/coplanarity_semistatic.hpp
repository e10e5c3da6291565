// Semi-static filter: certifies that the coplanarity cubic has no root in [0, 1], from its
// Bernstein coefficients computed in plain double arithmetic with a proven error bound.
//
// With the three difference vectors v(t), w(t), u(t) of the query (vertex-face: b-a, c-a, p-a;
// edge-edge: a1-a0, b0-a0, b1-a0), each linear in t, the cubic f(t) = det[v, w, u](t) has the
// Bernstein coefficients on [0, 1] (multilinearity of the determinant)
//   b0 = D(v0,w0,u0),  3 b1 = D(v1,w0,u0) + D(v0,w1,u0) + D(v0,w0,u1),
//   3 b2 = D(v0,w1,u1) + D(v1,w0,u1) + D(v1,w1,u0),  b3 = D(v1,w1,u1),
// where v0, v1 are the differences of the input doubles at t = 0 and t = 1 (one rounding each).
// All four certainly of one strict sign => f has that sign on [0, 1] (convex hull property).
// PROOF: proofs/filters.md#semistatic-bernstein
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

namespace exactccd::filters {

namespace semistatic {

constexpr double kUnitRoundoff = 0x1p-53;
/// |fl(D) - D| <= kSingle * Mx * My * Mz for one determinant of rounded differences evaluated by
/// det3, with the product itself rounded to nearest (proofs/filters.md#lemma-det-error). The
/// certified value evaluated from det3 itself is semistatic::compute_epsilon_single()
/// (tests/semistatic_epsilon.hpp): 46u + O(u^2); the literal is that first-order term times
/// (1 + 2^-40), and semistatic_epsilon_test checks that it covers the computed value, tightly.
constexpr double kSingle = 46.0 * kUnitRoundoff * (1.0 + 0x1p-40);
/// The same for a sum of three such determinants, bernstein_b1_times_3 and bernstein_b2_times_3
/// (proofs/filters.md#lemma-det-sum-error; computed: compute_epsilon_triple(), 168u + O(u^2)).
constexpr double kTriple = 168.0 * kUnitRoundoff * (1.0 + 0x1p-40);
/// Column maxima outside [kMin, kMax] could underflow or overflow: no decision then.
constexpr double kMin = 0x1p-200, kMax = 0x1p200;

/// det[v, w, u] = v . (w x u) in a fixed order, over any 3-vector type with x(), y(), z():
/// Eigen::Vector3d in the filter, error bounds in compute_epsilon
/// (tests/semistatic_epsilon.hpp), so the constants above are computed from this very code.
template <class Vec3>
EXACTCCD_CERTIFIED auto det3(const Vec3& v, const Vec3& w, const Vec3& u) {
  const auto mx = w.y() * u.z() - w.z() * u.y();
  const auto my = w.z() * u.x() - w.x() * u.z();
  const auto mz = w.x() * u.y() - w.y() * u.x();
  return (v.x() * mx + v.y() * my) + v.z() * mz;
}

/// 3 b1 = (D(v1,w0,u0) + D(v0,w1,u0)) + D(v0,w0,u1), in the order the filter uses.
template <class Vec3>
EXACTCCD_CERTIFIED auto bernstein_b1_times_3(const Vec3& v0, const Vec3& v1, const Vec3& w0,
                                             const Vec3& w1, const Vec3& u0, const Vec3& u1) {
  return (det3(v1, w0, u0) + det3(v0, w1, u0)) + det3(v0, w0, u1);
}

/// 3 b2 = (D(v0,w1,u1) + D(v1,w0,u1)) + D(v1,w1,u0), in the order the filter uses.
template <class Vec3>
EXACTCCD_CERTIFIED auto bernstein_b2_times_3(const Vec3& v0, const Vec3& v1, const Vec3& w0,
                                             const Vec3& w1, const Vec3& u0, const Vec3& u1) {
  return (det3(v0, w1, u1) + det3(v1, w0, u1)) + det3(v1, w1, u0);
}

}  // namespace semistatic

/// True only when the cubic certainly has no root in [0, 1]; false means "not decided here"
/// (never "has a root"). Differences: v0 = fl(b_t0 - a_t0) etc., computed by the caller.
EXACTCCD_CERTIFIED bool coplanarity_cubic_root_free_semistatic(
    const Eigen::Vector3d& v0, const Eigen::Vector3d& v1, const Eigen::Vector3d& w0,
    const Eigen::Vector3d& w1, const Eigen::Vector3d& u0, const Eigen::Vector3d& u1) {
  using namespace semistatic;
  const Eigen::Vector3d m = v0.cwiseAbs()
                                .cwiseMax(v1.cwiseAbs())
                                .cwiseMax(w0.cwiseAbs())
                                .cwiseMax(w1.cwiseAbs())
                                .cwiseMax(u0.cwiseAbs())
                                .cwiseMax(u1.cwiseAbs());
  // NaN-safe: a NaN fails both comparisons.
  if (!(m.minCoeff() >= kMin && m.maxCoeff() <= kMax)) return false;
  const double scale = m.x() * m.y() * m.z();
  const double single = kSingle * scale, triple = kTriple * scale;
  const double b0 = det3(v0, w0, u0);
  int s;
  if (b0 > single) s = 1;
  else if (b0 < -single) s = -1;
  else return false;
  const double b3 = det3(v1, w1, u1);
  if (!(s * b3 > single)) return false;
  const double b1 = bernstein_b1_times_3(v0, v1, w0, w1, u0, u1);
  if (!(s * b1 > triple)) return false;
  const double b2 = bernstein_b2_times_3(v0, v1, w0, w1, u0, u1);
  return s * b2 > triple;
}

}  // namespace exactccd::filters
