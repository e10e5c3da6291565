// The whole-step separating-direction test of minimum-separation CCD
// (filters/separation_directions.hpp, WholeStepGaps::apart_along), computed rounding to
// nearest with the error bound of proofs/min_separation.md#whole-step (Lemma W), against
// exact rational arithmetic:
//  - it never claims "apart" unless the exact gap along s exceeds delta |s| at both ends, on
//    cases built at the boundary (delta within a few ulps of gap / |s|, both ends), near the
//    origin and 2^30 times their size away from it (rounding errors far above delta), with
//    coordinates and directions scaled by 2^+-500, tiny and huge directions, products that
//    underflow, and points that overflow;
//  - it is not vacuous: with delta a millionth below gap / |s| it claims "apart" on (nearly)
//    all of them.
// PROOF: proofs/min_separation.md#whole-step
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <random>

#include "filters/separation_directions.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using filters::separation::InputVertices;
using filters::separation::WholeStepGaps;

mpq_class dot(const Eigen::Vector3d& s, const Eigen::Vector3d& x) {
  return mpq_class(s[0]) * x[0] + mpq_class(s[1]) * x[1] + mpq_class(s[2]) * x[2];
}

/// The exact gap along s at one end: min over the first N1 points of s.x - max over the rest.
template <std::size_t N1>
mpq_class exact_gap(const Eigen::Vector3d& s, const std::array<Eigen::Vector3d, 4>& x) {
  mpq_class lo = dot(s, x[0]), hi = dot(s, x[N1]);
  for (std::size_t i = 0; i < N1; ++i) lo = std::min(lo, dot(s, x[i]));
  for (std::size_t i = N1; i < 4; ++i) hi = std::max(hi, dot(s, x[i]));
  return lo - hi;
}

/// gap > delta |s| exactly: gap > 0 and gap^2 > delta^2 |s|^2.
bool exceeds(const mpq_class& gap, const Eigen::Vector3d& s, double delta) {
  const mpq_class d(delta);
  return sgn(gap) > 0 && gap * gap > d * d * dot(s, s);
}

struct Case {
  std::array<Eigen::Vector3d, 4> t0, t1;
  Eigen::Vector3d s;
};

template <std::size_t N1>
bool claims_apart(const Case& c, double delta) {
  const InputVertices<4> a{&c.t0[0], &c.t0[1], &c.t0[2], &c.t0[3]};
  const InputVertices<4> b{&c.t1[0], &c.t1[1], &c.t1[2], &c.t1[3]};
  return WholeStepGaps<N1>(a, b, delta).apart_along(c.s);
}

/// The delta, as a double, nearest the smaller end's gap / |s|.
template <std::size_t N1>
double boundary_delta(const Case& c) {
  const mpq_class g = std::min(exact_gap<N1>(c.s, c.t0), exact_gap<N1>(c.s, c.t1));
  const mpq_class ratio = g * g / dot(c.s, c.s);  // (gap / |s|)^2, of moderate size
  return sgn(g) > 0 ? std::sqrt(ratio.get_d()) : 0.0;
}

Eigen::Vector3d random_vector(std::mt19937_64& rng, int exponent) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Eigen::Vector3d(std::ldexp(u(rng), exponent), std::ldexp(u(rng), exponent),
                         std::ldexp(u(rng), exponent));
}

/// A first primitive on s's positive side of the second, by an offset along s.
Case random_case(std::mt19937_64& rng, std::size_t n1, int point_exponent, int s_exponent) {
  Case c;
  c.s = random_vector(rng, s_exponent);
  const Eigen::Vector3d unit = c.s.stableNormalized();
  const double offset = std::ldexp(2.0 + std::uniform_real_distribution<double>(0, 1)(rng),
                                   point_exponent);
  // Half the cases far from the origin (2^30 times their size): the dot products are then
  // large against the gap, and their rounding errors matter.
  const Eigen::Vector3d far =
      rng() % 2 ? random_vector(rng, point_exponent + 30) : Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 4; ++i) {
    const double side = i < n1 ? 1.0 : -1.0;
    c.t0[i] = random_vector(rng, point_exponent) + side * offset * unit + far;
    c.t1[i] = random_vector(rng, point_exponent) + side * offset * unit + far;
  }
  return c;
}

template <std::size_t N1>
void check_boundary(const Case& c, int* claimed_below, int* cases) {
  const double at = boundary_delta<N1>(c);
  if (!(at > 0) || !std::isfinite(at)) return;
  ++*cases;
  for (int k = -4; k <= 4; ++k) {  // delta within 4 ulps of the boundary: often not apart
    double delta = at;
    for (int j = 0; j < std::abs(k); ++j) delta = std::nextafter(delta, k > 0 ? INFINITY : 0.0);
    if (claims_apart<N1>(c, delta)) {
      EXPECT_TRUE(exceeds(exact_gap<N1>(c.s, c.t0), c.s, delta) &&
                  exceeds(exact_gap<N1>(c.s, c.t1), c.s, delta))
          << "claimed apart at delta " << delta << " (boundary " << at << ")";
    }
  }
  *claimed_below += claims_apart<N1>(c, at * (1 - 1e-6));
}

TEST(WholeStepGaps, NeverClaimsApartUnlessTheExactGapExceedsDeltaAtBothEnds) {
  std::mt19937_64 rng(1124);
  const int n = static_cast<int>(test::at_least(test::scaled_count(4000), 400));
  int claimed = 0, cases = 0;
  for (int i = 0; i < n; ++i) {
    // Coordinates at 2^0, 2^+-500; directions at 2^0, 2^+-600 (rescaled inside) and 2^-540
    // (products with 2^-500 coordinates underflow).
    const int point_exponent = (i % 3 == 0) ? 0 : (i % 3 == 1 ? 500 : -500);
    const int s_exponent = (i % 4 == 0) ? 0 : (i % 4 == 1 ? 600 : (i % 4 == 2 ? -600 : -540));
    if (i % 2 == 0)
      check_boundary<1>(random_case(rng, 1, point_exponent, s_exponent), &claimed, &cases);
    else
      check_boundary<2>(random_case(rng, 2, point_exponent, s_exponent), &claimed, &cases);
  }
  EXPECT_GE(cases, n / 2);
  // Not vacuous: a millionth below the boundary, the bound (a few ulps) is far smaller.
  EXPECT_GE(claimed, cases * 9 / 10) << claimed << " of " << cases;
}

TEST(WholeStepGaps, ClaimsNothingOnOverflowOrAZeroDirection) {
  Case c;
  const double big = 0x1p+1020;
  c.t0 = {Eigen::Vector3d(big, 0, 0), Eigen::Vector3d(big, 0, 0), Eigen::Vector3d(-big, 0, 0),
          Eigen::Vector3d(-big, 0, 0)};
  c.t1 = c.t0;
  c.s = Eigen::Vector3d(16, 0, 0);  // s.x overflows: nothing claimed, though the gap is huge
  EXPECT_FALSE(claims_apart<2>(c, 1.0));
  c.s = Eigen::Vector3d(0.25, 0, 0);  // the same gap, representable: apart
  EXPECT_TRUE(claims_apart<2>(c, 1.0));
  c.s = Eigen::Vector3d(0, 0, 0);
  EXPECT_FALSE(claims_apart<2>(c, 1.0));
}

}  // namespace
}  // namespace exactccd
