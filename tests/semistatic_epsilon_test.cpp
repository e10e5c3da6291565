// The semi-static error constants computed from the filter's own code (compute_epsilon on the
// error-tracking type) against the literals kSingle and kTriple; mutants of the expression that
// this comparison catches; and the bound itself on random and adversarial inputs, against exact
// rational determinants.
// PROOF: proofs/filters.md#error-tracking, #lemma-det-error, #lemma-det-sum-error
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "exactccd/types.hpp"
#include "filters/coplanarity_semistatic.hpp"
#include "semistatic_epsilon.hpp"
#include "static_filter_error.hpp"
#include "test_support.hpp"

namespace {

using namespace exactccd;
using namespace exactccd::filters::semistatic;
using Eigen::Vector3d;
using test::pow2;

mpq_class q(double d) { return mpq_class(d); }
const mpq_class kU = q(kUnitRoundoff);

// A literal covers a computed constant when it is at least that constant (the filter is sound),
// and is tight when it exceeds it by at most a relative 2^-39 (the literals carry 1 + 2^-40).
bool covers(double literal, const mpq_class& computed) { return q(literal) >= computed; }
bool tight(double literal, const mpq_class& computed) {
  return q(literal) <= computed * (1 + pow2(-39));
}
double in_units_of_u(const mpq_class& x) { return mpq_class(x / kU).get_d(); }

TEST(SemistaticEpsilon, LiteralsCoverTheConstantsComputedFromTheCode) {
  const mpq_class single = compute_epsilon_single(), triple = compute_epsilon_triple();
  std::printf("computed: single %.17g u (kSingle %.17g u), triple %.17g u (kTriple %.17g u)\n",
              in_units_of_u(single), kSingle / kUnitRoundoff, in_units_of_u(triple),
              kTriple / kUnitRoundoff);
  EXPECT_TRUE(covers(kSingle, single));
  EXPECT_TRUE(covers(kTriple, triple));
}

TEST(SemistaticEpsilon, LiteralsAreNotLooserThanTheComputedConstants) {
  const mpq_class single = compute_epsilon_single(), triple = compute_epsilon_triple();
  // literal / computed - 1, in units of 2^-40.
  const auto excess = [](double literal, const mpq_class& computed) {
    return mpq_class((q(literal) / computed - 1) / pow2(-40)).get_d();
  };
  std::printf("kSingle / computed = 1 + %.6f * 2^-40, kTriple / computed = 1 + %.6f * 2^-40\n",
              excess(kSingle, single), excess(kTriple, triple));
  EXPECT_TRUE(tight(kSingle, single));
  EXPECT_TRUE(tight(kTriple, triple));
}

TEST(SemistaticEpsilon, ComputedErrorsLieWithinTheProofsHandBounds) {
  // proofs/filters.md#lemma-det-error: 46u <= error <= 46u + (640 - 46)u^2 + 2^-460, and
  // #lemma-det-sum-error: 168u <= error <= 168u + (3040 - 168)u^2 + 2^-460.
  const mpq_class single = single_determinant_error(), triple = triple_sum_error();
  const mpq_class u2 = kU * kU;
  std::printf("second-order terms: single %.6g u^2, triple %.6g u^2\n",
              mpq_class((single - 46 * kU) / u2).get_d(),
              mpq_class((triple - 168 * kU) / u2).get_d());
  EXPECT_GE(single, 46 * kU);
  EXPECT_LE(single, 46 * kU + 594 * u2 + pow2(-460));
  EXPECT_GE(triple, 168 * kU);
  EXPECT_LE(triple, 168 * kU + 2872 * u2 + pow2(-460));
}

TEST(SemistaticEpsilon, ErrorTypeFollowsTheRoundingRules) {
  // One rounded difference, one product, one sum, by hand: leaves (1, u/(1-u)).
  const SemistaticError x = SemistaticError::rounded_difference(0);
  const SemistaticError y = SemistaticError::rounded_difference(1);
  const mpq_class a = kU / (1 - kU);
  EXPECT_EQ(x.bound(), 1);
  EXPECT_EQ(x.error(), a);
  const SemistaticError p = x * y;  // degree (1, 1, 0): underflow 2^(-1075 + 400)
  EXPECT_EQ(p.bound(), 1 + kU + pow2(-675));
  EXPECT_EQ(p.error(), kU + pow2(-675) + 2 * a + a * a);
  const SemistaticError s = p - p;
  EXPECT_EQ(s.bound(), 2 * p.bound() * (1 + kU));
  EXPECT_EQ(s.error(), 2 * kU * p.bound() + 2 * p.error());
  EXPECT_EQ(s.degree(), (SemistaticError::Degree{1, 1, 0}));
}

// Mutants of det3 and of the Bernstein sum, evaluated on the same error type: each is an
// expression the filter might have been changed into; the comparisons above must notice.

// The six elementary products summed left to right (a different evaluation order).
template <class Vec3>
auto det3_expanded(const Vec3& v, const Vec3& w, const Vec3& u) {
  return (((((v.x() * w.y()) * u.z() - (v.x() * w.z()) * u.y()) + (v.y() * w.z()) * u.x()) -
           (v.y() * w.x()) * u.z()) +
          (v.z() * w.x()) * u.y()) -
         (v.z() * w.y()) * u.x();
}

// The 2x2 minors with one rounding dropped (an FMA, as a contracting compiler would emit).
template <class Vec3>
auto det3_fused_minors(const Vec3& v, const Vec3& w, const Vec3& u) {
  const auto mx = fused_multiply_add(w.y(), u.z(), -(w.z() * u.y()));
  const auto my = fused_multiply_add(w.z(), u.x(), -(w.x() * u.z()));
  const auto mz = fused_multiply_add(w.x(), u.y(), -(w.y() * u.x()));
  return (v.x() * mx + v.y() * my) + v.z() * mz;
}

// A typo mixing coordinates: w.z u.z instead of w.z u.y.
template <class Vec3>
auto det3_mixed_coordinates(const Vec3& v, const Vec3& w, const Vec3& u) {
  const auto mx = w.y() * u.z() - w.z() * u.z();
  const auto my = w.z() * u.x() - w.x() * u.z();
  const auto mz = w.x() * u.y() - w.y() * u.x();
  return (v.x() * mx + v.y() * my) + v.z() * mz;
}

TEST(SemistaticEpsilon, MutatedExpressionsAreCaught) {
  const ErrorVector3 v{}, w{}, u{};
  // Reordered: more error than kSingle covers (50u), so the soundness check fails on it.
  const mpq_class expanded = constant_covering(error_of_determinant_value(det3_expanded(v, w, u)));
  std::printf("expanded order: %.17g u\n", in_units_of_u(expanded));
  EXPECT_FALSE(covers(kSingle, expanded));
  // A rounding dropped: less error (43u), so the tightness check fails on it.
  const mpq_class fused =
      constant_covering(error_of_determinant_value(det3_fused_minors(v, w, u)));
  std::printf("fused minors: %.17g u\n", in_units_of_u(fused));
  EXPECT_TRUE(covers(kSingle, fused));
  EXPECT_FALSE(tight(kSingle, fused));
  // Expanded determinants in the Bernstein sum: 180u, more than kTriple covers.
  const mpq_class sum_of_expanded = constant_covering(error_of_determinant_value(
      (det3_expanded(v, w, u) + det3_expanded(v, w, u)) + det3_expanded(v, w, u)));
  std::printf("sum of expanded determinants: %.17g u\n", in_units_of_u(sum_of_expanded));
  EXPECT_FALSE(covers(kTriple, sum_of_expanded));
  // Mixed coordinates: no common scale, refused rather than given a constant.
  EXPECT_THROW(det3_mixed_coordinates(v, w, u), std::domain_error);
  // A minor alone is no determinant value (degree (0, 1, 1)).
  EXPECT_THROW(error_of_determinant_value(w.y() * u.z() - w.z() * u.y()), std::domain_error);
}

TEST(SemistaticEpsilon, OverflowOfTheModelIsReported) {
  // Degree 6 at column maxima up to 2^200 could reach 6^2 2^1200: reported, not bounded.
  const ErrorVector3 v{};
  const auto d = det3(v, v, v);
  EXPECT_THROW(d * d, std::overflow_error);
}

// ------------------------------------------------------------------------------------------
// The bound on inputs: |double det3 - exact determinant| <= kSingle Mx My Mz, with the threshold
// computed as the filter computes it, and the same for the Bernstein sums with kTriple.

using V3q = std::array<mpq_class, 3>;
V3q exact_difference(const Vector3d& head, const Vector3d& tail) {
  return {q(head.x()) - q(tail.x()), q(head.y()) - q(tail.y()), q(head.z()) - q(tail.z())};
}
mpq_class exact_det(const V3q& v, const V3q& w, const V3q& u) {
  return v[0] * (w[1] * u[2] - w[2] * u[1]) + v[1] * (w[2] * u[0] - w[0] * u[2]) +
         v[2] * (w[0] * u[1] - w[1] * u[0]);
}

// Does a product of a 2x2 minor underflow (where only the model's absolute term covers it)?
bool minor_product_underflows(const Vector3d& w0, const Vector3d& w1, const Vector3d& u0,
                              const Vector3d& u1) {
  for (const Vector3d* w : {&w0, &w1})
    for (const Vector3d* u : {&u0, &u1})
      for (int i = 0; i < 3; ++i) {
        const double p = (*w)[(i + 1) % 3] * (*u)[(i + 2) % 3];
        if (std::fpclassify(p) == FP_SUBNORMAL) return true;
      }
  return false;
}

struct BoundCheck {
  int checked = 0, outside_range = 0, undecidable = 0, underflowing = 0;
  double worst_single = 0, worst_triple = 0;  // |error| / (Mx My Mz), in units of u

  // The differences as the filter's caller forms them (vertex-face: b - a, c - a, p - a).
  void run(const VertexFaceQuery& qv) {
    const Vector3d v0 = qv.b_t0 - qv.a_t0, v1 = qv.b_t1 - qv.a_t1, w0 = qv.c_t0 - qv.a_t0,
                   w1 = qv.c_t1 - qv.a_t1, u0 = qv.p_t0 - qv.a_t0, u1 = qv.p_t1 - qv.a_t1;
    // Column maxima and thresholds as coplanarity_cubic_root_free_semistatic computes them.
    Vector3d m = Vector3d::Zero();
    for (const Vector3d* e : {&v0, &v1, &w0, &w1, &u0, &u1}) m = m.cwiseMax(e->cwiseAbs());
    if (!(m.minCoeff() >= kMin && m.maxCoeff() <= kMax)) {
      ++outside_range;
      return;
    }
    const double scale = m.x() * m.y() * m.z();
    const double single = kSingle * scale, triple = kTriple * scale;

    const V3q ev0 = exact_difference(qv.b_t0, qv.a_t0), ev1 = exact_difference(qv.b_t1, qv.a_t1);
    const V3q ew0 = exact_difference(qv.c_t0, qv.a_t0), ew1 = exact_difference(qv.c_t1, qv.a_t1);
    const V3q eu0 = exact_difference(qv.p_t0, qv.a_t0), eu1 = exact_difference(qv.p_t1, qv.a_t1);
    const double computed[4] = {det3(v0, w0, u0), bernstein_b1_times_3(v0, v1, w0, w1, u0, u1),
                                bernstein_b2_times_3(v0, v1, w0, w1, u0, u1), det3(v1, w1, u1)};
    const mpq_class exact[4] = {
        exact_det(ev0, ew0, eu0),
        exact_det(ev1, ew0, eu0) + exact_det(ev0, ew1, eu0) + exact_det(ev0, ew0, eu1),
        exact_det(ev0, ew1, eu1) + exact_det(ev1, ew0, eu1) + exact_det(ev1, ew1, eu0),
        exact_det(ev1, ew1, eu1)};
    const mpq_class units = q(m.x()) * q(m.y()) * q(m.z()) * kU;
    for (int k = 0; k < 4; ++k) {
      const bool is_single = k == 0 || k == 3;
      const mpq_class error = abs(q(computed[k]) - exact[k]);
      ASSERT_LE(error, q(is_single ? single : triple))
          << "coefficient " << k << ": computed " << computed[k] << ", maxima " << m.transpose();
      const double ratio = mpq_class(error / units).get_d();
      double& worst = is_single ? worst_single : worst_triple;
      worst = std::max(worst, ratio);
    }
    undecidable += !(std::abs(computed[0]) > single && std::abs(computed[3]) > single);
    underflowing += minor_product_underflows(w0, w1, u0, u1);
    ++checked;
  }

  void report(const char* what, int n) const {
    std::printf("%s: %d/%d checked (%d outside the range, %d with |b0| or |b3| within the bound, "
                "%d with an underflowing product); worst |error| / (Mx My Mz): single %.3f u "
                "(kSingle %.0f u), triple %.3f u (kTriple %.0f u)\n",
                what, checked, n, outside_range, undecidable, underflowing, worst_single,
                kSingle / kUnitRoundoff, worst_triple, kTriple / kUnitRoundoff);
  }
};

// Per-coordinate exponents: each column has its own magnitude within the filter's range.
std::array<int, 3> column_exponents(std::mt19937_64& rng, int lo, int hi) {
  std::uniform_int_distribution<int> e(lo, hi);
  return {e(rng), e(rng), e(rng)};
}

TEST(SemistaticEpsilon, BoundHoldsOnRandomInputsOfWideMagnitude) {
  std::mt19937_64 rng(test::test_seed("SemistaticEpsilon.BoundHoldsOnRandomInputsOfWideMagnitude"));
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  BoundCheck check;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const std::array<int, 3> s = column_exponents(rng, -198, 198);
    auto r = [&]() -> Vector3d {
      return {std::ldexp(uni(rng), s[0]), std::ldexp(uni(rng), s[1]), std::ldexp(uni(rng), s[2])};
    };
    check.run({r(), r(), r(), r(), r(), r(), r(), r()});
    if (HasFatalFailure()) return;
  }
  check.report("uniform", n);
  EXPECT_GT(check.checked, n * 9 / 10);
}

TEST(SemistaticEpsilon, BoundHoldsOnNearSingularInputs) {
  // p exactly in the triangle's plane at t = 0 and t = 1 (small integers), all points translated
  // by one random offset of at most 8 (so that the inputs carry full 53-bit mantissas and their
  // differences are rounded), p nudged by a few ulps, and each column scaled by its own power of
  // two (exact): b0 and b3 of the exact differences are of the order of the rounding noise.
  std::mt19937_64 rng(test::test_seed("SemistaticEpsilon.BoundHoldsOnNearSingularInputs"));
  std::uniform_int_distribution<int> coord(-64, 64), frac(-4, 8), ulps(0, 3), lift(-20, 3);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  BoundCheck check;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const std::array<int, 3> s = column_exponents(rng, -190, 160);
    auto point = [&]() -> Vector3d { return Vector3d(coord(rng), coord(rng), coord(rng)); };
    VertexFaceQuery qv{point(), point(), point(), point(), point(), point(), point(), point()};
    qv.p_t0 = qv.a_t0 + (qv.b_t0 - qv.a_t0) * (frac(rng) / 4.0) +
              (qv.c_t0 - qv.a_t0) * (frac(rng) / 4.0);
    qv.p_t1 = qv.a_t1 + (qv.b_t1 - qv.a_t1) * (frac(rng) / 4.0) +
              (qv.c_t1 - qv.a_t1) * (frac(rng) / 4.0);
    Vector3d offset;
    for (int k = 0; k < 3; ++k) offset[k] = std::ldexp(uni(rng), lift(rng));
    for (Vector3d* p : {&qv.p_t0, &qv.a_t0, &qv.b_t0, &qv.c_t0, &qv.p_t1, &qv.a_t1, &qv.b_t1,
                        &qv.c_t1})
      for (int k = 0; k < 3; ++k) {
        (*p)[k] += offset[k];
        if (p == &qv.p_t0 || p == &qv.p_t1)
          for (int j = ulps(rng); j > 0; --j) (*p)[k] = std::nextafter((*p)[k], 1e300);
        (*p)[k] = std::ldexp((*p)[k], s[k]);
      }
    check.run(qv);
    if (HasFatalFailure()) return;
  }
  check.report("near-singular", n);
  EXPECT_GT(check.checked, n * 9 / 10);
  // Adversarial indeed: most of these are too close to singular for the filter.
  EXPECT_GT(check.undecidable, check.checked / 2);
}

TEST(SemistaticEpsilon, BoundHoldsWithEntriesFarBelowTheColumnMaximum) {
  // Columns near 2^-200 or 2^200, entries down to subnormal: products underflow, where only the
  // model's absolute term covers the rounding; and the largest products the range allows.
  std::mt19937_64 rng(
      test::test_seed("SemistaticEpsilon.BoundHoldsWithEntriesFarBelowTheColumnMaximum"));
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::uniform_int_distribution<int> drop(0, 880), coin(0, 3);
  BoundCheck check;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const bool tiny = i % 2 == 0;
    const std::array<int, 3> s =
        tiny ? column_exponents(rng, -200, -190) : column_exponents(rng, 190, 200);
    auto r = [&]() -> Vector3d {
      Vector3d p;
      for (int k = 0; k < 3; ++k)
        p[k] = std::ldexp(uni(rng), s[k] - (tiny && coin(rng) != 0 ? drop(rng) : 0));
      return p;
    };
    check.run({r(), r(), r(), r(), r(), r(), r(), r()});
    if (HasFatalFailure()) return;
  }
  check.report("far below the maximum", n);
  EXPECT_GT(check.checked, n / 4);
  EXPECT_GT(check.underflowing, 0);
}

}  // namespace
