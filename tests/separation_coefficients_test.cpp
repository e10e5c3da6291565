// The region polynomials' enclosures from their exact coefficients
// (ExactSignsAtDoubles::*_coefficients), which the minimum-separation search falls back to when
// the enclosures computed from the coordinates cannot tell:
//  - each polynomial's enclosures hold its exact rational coefficients (core/predicates/
//    separation.hpp over the rationals) times one common positive scale, which is all the
//    search relies on (it reads signs only), on random queries, nearly parallel edges, sliding
//    vertices, zero coordinates and coordinates scaled by 2^+-500;
//  - each enclosure is one rounding wide (at most 2 ulps of its largest end), or below
//    2^-1000 of the largest coefficient;
//  - a query of the public benchmark whose edges stay within 2^-52 of parallel, which went to
//    the exact procedure before these enclosures, is decided by the filters with the exact
//    path's answer.
// PROOF: proofs/min_separation.md#exact-coefficients
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/predicates/separation.hpp"
#include "exactccd/ccd.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using CoefficientTable = predicates::SeparationCoefficientTable;
using Vertices = std::array<Eigen::Vector3d, 4>;
using Poly6 = predicates::FixedPoly<predicates::Interval, 6>;

struct Case {
  Vertices t0, t1;
  double delta = 0;
};

/// Every region polynomial's exact coefficients (index: the separation's numbering).
std::vector<std::vector<mpq_class>> rational_coefficients(const Case& c, bool vertex_face) {
  using P = predicates::FixedPoly<mpq_class, 1>;
  using Point = predicates::Vec3<P>;
  Point x[4];
  for (int i = 0; i < 4; ++i) {
    P p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = P{{mpq_class(c.t0[i][k]), mpq_class(c.t1[i][k]) - mpq_class(c.t0[i][k])}};
    x[i] = Point{p[0], p[1], p[2]};
  }
  const mpq_class d2 = mpq_class(c.delta) * mpq_class(c.delta);
  std::vector<std::vector<mpq_class>> out;
  auto take = [&out](const auto& g) { out.emplace_back(std::begin(g.c), std::end(g.c)); };
  if (vertex_face)
    predicates::vertex_face_separation(x[0], x[1], x[2], x[3], d2).for_each_polynomial(take);
  else
    predicates::edge_edge_separation(x[0], x[1], x[2], x[3], d2).for_each_polynomial(take);
  return out;
}

/// Some s > 0 with s c_i in [lo_i, hi_i] for every i: the intersection of the intervals of s
/// each coefficient allows is not empty and reaches above 0.
::testing::AssertionResult common_positive_scale(const std::vector<mpq_class>& exact,
                                                 const Poly6& enc) {
  bool bounded_below = false, bounded_above = false;
  mpq_class lower(0), upper(0);
  for (int i = 0; i < 7; ++i) {
    const mpq_class c = i < static_cast<int>(exact.size()) ? exact[i] : mpq_class(0);
    const mpq_class lo(enc.c[i].inf()), hi(enc.c[i].sup());
    if (sgn(c) == 0) {
      if (sgn(lo) > 0 || sgn(hi) < 0)
        return ::testing::AssertionFailure() << "coefficient " << i << " is 0, enclosure excludes 0";
      continue;
    }
    mpq_class a = lo / c, b = hi / c;
    if (sgn(c) < 0) std::swap(a, b);
    if (!bounded_below || a > lower) lower = a;
    if (!bounded_above || b < upper) upper = b;
    bounded_below = bounded_above = true;
  }
  if (!bounded_below) return ::testing::AssertionSuccess();  // the zero polynomial
  if (lower > upper || sgn(upper) <= 0)
    return ::testing::AssertionFailure() << "no common positive scale: [" << lower.get_d() << ", "
                                         << upper.get_d() << "]";
  return ::testing::AssertionSuccess();
}

/// Each enclosure one rounding wide: hi - lo <= 2 ulps of max(|lo|, |hi|), or both ends
/// within 2^-1000.
::testing::AssertionResult one_rounding_wide(const Poly6& enc) {
  for (int i = 0; i < 7; ++i) {
    const double lo = enc.c[i].inf(), hi = enc.c[i].sup();
    const double top = std::max(std::fabs(lo), std::fabs(hi));
    if (top <= 0x1p-1000) continue;
    const double ulp = std::nextafter(top, INFINITY) - top;
    if (!(hi - lo <= 2 * ulp))
      return ::testing::AssertionFailure() << "coefficient " << i << " [" << lo << ", " << hi << "]";
    if (top > 1) return ::testing::AssertionFailure() << "coefficient " << i << " above 1";
  }
  return ::testing::AssertionSuccess();
}

void check(const Case& c, const std::string& what) {
  const exact::separation::ExactSignsAtDoubles signs(
      {&c.t0[0], &c.t0[1], &c.t0[2], &c.t0[3]}, {&c.t1[0], &c.t1[1], &c.t1[2], &c.t1[3]},
      c.delta);
  for (const bool vertex_face : {true, false}) {
    CoefficientTable table;
    if (vertex_face)
      signs.vertex_face_coefficients(&table);
    else
      signs.edge_edge_coefficients(&table);
    const auto exact = rational_coefficients(c, vertex_face);
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const std::string label =
          what + (vertex_face ? " vertex-face " : " edge-edge ") + std::to_string(k);
      EXPECT_TRUE(common_positive_scale(exact[k], table[k])) << label;
      EXPECT_TRUE(one_rounding_wide(table[k])) << label;
    }
  }
}

double random_coordinate(std::mt19937_64& rng) {
  return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng),
                    static_cast<int>(rng() % 8) - 4);
}

TEST(SeparationCoefficients, EncloseTheExactPolynomialsUpToOnePositiveScale) {
  std::mt19937_64 rng(20261124);
  const int n = static_cast<int>(test::at_least(test::scaled_count(300), 20));
  for (int i = 0; i < n; ++i) {
    Case c;
    for (int v = 0; v < 4; ++v)
      for (int k = 0; k < 3; ++k) {
        c.t0[v][k] = random_coordinate(rng);
        c.t1[v][k] = random_coordinate(rng);
      }
    switch (i % 5) {
      case 1:  // nearly parallel edges (edge-edge) and a vertex nearly on the face's plane
        for (int k = 0; k < 3; ++k) {
          c.t0[3][k] = c.t0[2][k] + (c.t0[1][k] - c.t0[0][k]) + std::ldexp(random_coordinate(rng), -50);
          c.t1[3][k] = c.t1[2][k] + (c.t1[1][k] - c.t1[0][k]) + std::ldexp(random_coordinate(rng), -50);
        }
        break;
      case 2:  // a vertex sliding within a static face's plane z = 0, the others static
        for (int v = 0; v < 4; ++v) {
          c.t0[v][2] = 0;
          if (v > 0) c.t1[v] = c.t0[v];
        }
        c.t1[0][2] = 0;
        break;
      case 3:  // zero coordinates
        c.t0[1].setZero();
        c.t1[2].setZero();
        break;
      default: break;
    }
    c.delta = std::ldexp(std::fabs(random_coordinate(rng)), -static_cast<int>(rng() % 40));
    check(c, "random " + std::to_string(i));
    for (const int e : {-500, 500}) {  // a power of two scales every coefficient alike
      Case s = c;
      for (int v = 0; v < 4; ++v) {
        s.t0[v] = std::ldexp(1.0, e) * s.t0[v];
        s.t1[v] = std::ldexp(1.0, e) * s.t1[v];
      }
      s.delta = std::ldexp(s.delta, e);
      check(s, "scaled " + std::to_string(e) + " " + std::to_string(i));
    }
  }
}

TEST(SeparationCoefficients, NearlyParallelEdgesOfTheBenchmarkAreDecidedByTheFilters) {
  // erleben-spikes/edge-edge/data_0_0.csv, query 4 (Wang et al. 2021, MIT licence): the edges'
  // cross product stays near 1.5e-16 while they are near 1 long, so the interior region's
  // polynomials are about 1e-18 with enclosures from the coordinates about 1e-16 wide.
  const EdgeEdgeQuery q{{0x1.5555555555555p-3, 0x1.1b04c62a8f4cep-1, 0x1.5555555555559p-3},
                        {0x0.0p+0, 0x1.8d82631547a67p+0, 0x0.0p+0},
                        {0x1.555555567a895p-3, 0x1.ddddddde7077dp-2, 0x1.555555567a895p-3},
                        {0x1.55555555e7ef5p-2, -0x1.11111110c7c41p-1, 0x1.55555555e7ef5p-2},
                        {0x1.5555555555551p-3, 0x1.d19e00ebc96bap-2, 0x1.5555555555559p-3},
                        {0x1.8000000000000p-56, 0x1.7467803af25afp+0, 0x1.e45cc660e5bf4p-55},
                        {0x1.555555567a895p-3, 0x1.ddddddde7077dp-2, 0x1.555555567a895p-3},
                        {0x1.55555555e7ef5p-2, -0x1.11111110c7c41p-1, 0x1.55555555e7ef5p-2}};
  CcdOptions options;
  options.min_separation = 0x1.ed25bd73a2771p-17;  // 1e-6 of the benchmark's size
  const CcdResult filtered = edge_edge_ccd(q, options);
  options.mode = Mode::exact;
  const CcdResult exact = edge_edge_ccd(q, options);
  EXPECT_EQ(filtered.decided_by, Stage::exact_at_double);
  ASSERT_TRUE(exact.collides);
  EXPECT_TRUE(filtered.collides);
  EXPECT_EQ(filtered.toi_lo, exact.toi_lo);
  EXPECT_EQ(filtered.toi_hi, exact.toi_hi);
}

}  // namespace
}  // namespace exactccd
