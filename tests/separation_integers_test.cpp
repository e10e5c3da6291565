// The fixed-width exact values at double times of the minimum-separation region polynomial 0,
// the capsules' sides, the end spheres and the sides' projections
// (exact/stages/separation_integers.hpp) against GMP and the rationals:
//  - every FixedInt width at least the one its bound selects gives the same integer as the same
//    kernel in GMP, and that integer is 2^(d(k-E)) times the polynomial of
//    core/predicates/separation.hpp (degree d) evaluated over the rationals at the same time;
//  - on random queries of every coordinate spread (differences of 1, 2 and 3 limbs, and GMP),
//    on extreme ones (coordinates at the top of their range, many sign patterns) whose bit
//    bound sits at each width's limit and just beyond, scaled by 2^+-500, at times near 0 and 1;
//  - the filters' signs at doubles (ExactSignsAtDoubles) equal the rational signs, with no GMP
//    evaluation within the fixed widths.
// PROOF: proofs/min_separation.md#fixed-width-signs
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "core/predicates/separation.hpp"
#include "exact/arithmetic/integer_arithmetic.hpp"
#include "exact/stages/separation_integers.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "separation_rational.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using exact::DifferenceVertices;
using exact::SeparationIntegers;
using Vertices = std::array<Eigen::Vector3d, 4>;

using Case = test::SeparationCase;
using test::rational_value;

SeparationIntegers integers_of(const Case& c) {
  return exact::separation_integers({&c.t0[0], &c.t0[1], &c.t0[2], &c.t0[3]},
                                    {&c.t1[0], &c.t1[1], &c.t1[2], &c.t1[3]}, c.delta);
}

/// A kernel: the polynomial it computes, its vertices and its kind (degree in the
/// coordinates: 6 face-like, 4 capsule, 2 sphere and projection).
enum class Kind { face_like, capsule, sphere, projection };
struct Kernel {
  bool vertex_face;
  int poly;
  const DifferenceVertices* vertices;
  Kind kind;
};

// Written out against core/predicates/separation.hpp's numbering, not derived from the
// library's own mapping (ExactSignsAtDoubles::*_kernel), so that a wrong pointer there fails.
const Kernel kKernels[] = {
    {true, 0, &exact::kVertexFaceRegion, Kind::face_like},
    {true, 4, &exact::kVertexFaceSpheres[0], Kind::sphere},
    {true, 5, &exact::kVertexFaceCapsules[0], Kind::projection},
    {true, 6, &exact::kVertexFaceProjectionsFromY[0], Kind::projection},
    {true, 7, &exact::kVertexFaceCapsules[0], Kind::capsule},
    {true, 8, &exact::kVertexFaceSpheres[1], Kind::sphere},
    {true, 9, &exact::kVertexFaceCapsules[1], Kind::projection},
    {true, 10, &exact::kVertexFaceProjectionsFromY[1], Kind::projection},
    {true, 11, &exact::kVertexFaceCapsules[1], Kind::capsule},
    {true, 12, &exact::kVertexFaceSpheres[2], Kind::sphere},
    {true, 13, &exact::kVertexFaceCapsules[2], Kind::projection},
    {true, 14, &exact::kVertexFaceProjectionsFromY[2], Kind::projection},
    {true, 15, &exact::kVertexFaceCapsules[2], Kind::capsule},
    {false, 0, &exact::kEdgeEdgeRegion, Kind::face_like},
    {false, 5, &exact::kEdgeEdgeSpheres[0], Kind::sphere},
    {false, 6, &exact::kEdgeEdgeSpheres[1], Kind::sphere},
    {false, 7, &exact::kEdgeEdgeSpheres[2], Kind::sphere},
    {false, 8, &exact::kEdgeEdgeSpheres[3], Kind::sphere},
    {false, 9, &exact::kEdgeEdgeCapsules[0], Kind::projection},
    {false, 10, &exact::kEdgeEdgeProjectionsFromY[0], Kind::projection},
    {false, 11, &exact::kEdgeEdgeCapsules[0], Kind::capsule},
    {false, 12, &exact::kEdgeEdgeCapsules[1], Kind::projection},
    {false, 13, &exact::kEdgeEdgeProjectionsFromY[1], Kind::projection},
    {false, 14, &exact::kEdgeEdgeCapsules[1], Kind::capsule},
    {false, 15, &exact::kEdgeEdgeCapsules[2], Kind::projection},
    {false, 16, &exact::kEdgeEdgeProjectionsFromY[2], Kind::projection},
    {false, 17, &exact::kEdgeEdgeCapsules[2], Kind::capsule},
    {false, 18, &exact::kEdgeEdgeCapsules[3], Kind::projection},
    {false, 19, &exact::kEdgeEdgeProjectionsFromY[3], Kind::projection},
    {false, 20, &exact::kEdgeEdgeCapsules[3], Kind::capsule}};

long degree_of(Kind kind) {
  switch (kind) {
    case Kind::face_like: return 6;
    case Kind::capsule: return 4;
    default: return 2;
  }
}

template <class Ints>
mpz_class kernel_value(const Kernel& kernel, const SeparationIntegers& q, std::uint64_t T,
                       unsigned k) {
  const auto differences =
      exact::step_differences<typename Ints::Difference>(q, *kernel.vertices);
  switch (kernel.kind) {
    case Kind::face_like: return exact::to_mpz(exact::face_like_value<Ints>(differences, T, k));
    case Kind::capsule: return exact::to_mpz(exact::capsule_value<Ints>(differences, T, k));
    case Kind::sphere: return exact::to_mpz(exact::sphere_value<Ints>(differences, T, k));
    default: return exact::to_mpz(exact::projection_value<Ints>(differences, T, k));
  }
}

/// Checks the case at t in every width that its bound admits; returns the width selected
/// (0: GMP).
int check(const Case& c, double t, const char* what) {
  exact::DyadicTime d;
  EXPECT_TRUE(exact::dyadic_time(t, &d));
  const SeparationIntegers q = integers_of(c);
  const int selected = exact::fixed_limbs_for(exact::separation_difference_bits(q.bits, d.exponent));
  for (const Kernel& kernel : kKernels) {
    const std::string label = std::string(what) + (kernel.vertex_face ? " vertex-face " : " edge-edge ") +
                              std::to_string(kernel.poly);
    const std::uint64_t T = d.numerator;
    const unsigned k = d.exponent;
    const mpz_class gmp = kernel_value<exact::GmpStageIntegers>(kernel, q, T, k);
    // The reference: 2^(deg (k - E)) g(t) over the rationals.
    mpq_class expected = rational_value(c, kernel.vertex_face, kernel.poly, t);
    const long scale = degree_of(kernel.kind) * (static_cast<long>(k) - q.common_exponent);
    if (scale >= 0)
      mpq_mul_2exp(expected.get_mpq_t(), expected.get_mpq_t(), static_cast<mp_bitcnt_t>(scale));
    else
      mpq_div_2exp(expected.get_mpq_t(), expected.get_mpq_t(), static_cast<mp_bitcnt_t>(-scale));
    EXPECT_EQ(mpq_class(gmp), expected) << label << " t " << t;
    if (selected >= 1 && selected <= 1)
      EXPECT_EQ(kernel_value<exact::FixedStageIntegers<1>>(kernel, q, T, k), gmp) << label << " width 1";
    if (selected >= 1 && selected <= 2)
      EXPECT_EQ(kernel_value<exact::FixedStageIntegers<2>>(kernel, q, T, k), gmp) << label << " width 2";
    if (selected >= 1 && selected <= 3)
      EXPECT_EQ(kernel_value<exact::FixedStageIntegers<3>>(kernel, q, T, k), gmp) << label << " width 3";
    // The filters' interface: the same sign, in GMP only beyond the fixed widths.
    const exact::separation::ExactSignsAtDoubles signs(
        {&c.t0[0], &c.t0[1], &c.t0[2], &c.t0[3]}, {&c.t1[0], &c.t1[1], &c.t1[2], &c.t1[3]},
        c.delta);
    const std::uint64_t before = exact::separation::gmp_evaluations_in_this_thread();
    const int s = kernel.vertex_face ? signs.vertex_face_sign(kernel.poly, t)
                                     : signs.edge_edge_sign(kernel.poly, t);
    EXPECT_EQ(s, sgn(expected)) << label;
    const bool used_gmp = exact::separation::gmp_evaluations_in_this_thread() != before;
    // (Within the fixed widths GMP is never used; beyond them the double-double signs with
    // an error bound decide most, double_double_signs_test.)
    if (selected >= 1 && selected <= exact::kMaxDifferenceLimbs) EXPECT_FALSE(used_gmp) << label;
  }
  return selected;
}

/// m 2^e for an odd 53-bit m of random sign.
double random_double(std::mt19937_64& rng, int e) {
  const auto m = static_cast<double>((rng() >> 11) | (std::uint64_t{1} << 52) | 1);
  return std::ldexp(rng() % 2 ? m : -m, e);
}

TEST(SeparationIntegers, RandomQueriesEveryWidthEqualGmpAndRationals) {
  std::mt19937_64 rng(11);
  int seen[4] = {0, 0, 0, 0};  // GMP, widths 1 to 3
  // A floor: every width must be reached at any EXACTCCD_TEST_SCALE.
  const auto n = static_cast<int>(test::at_least(test::scaled_count(400), 200));
  for (int i = 0; i < n; ++i) {
    // Coordinates of exponents in [-60 - spread, -60], delta small; motions small or not.
    const int spread = static_cast<int>(rng() % 160);
    const int scale = i % 5 == 0 ? (i % 10 == 0 ? 500 : -500) : 0;
    Case c;
    for (int v = 0; v < 4; ++v)
      for (int k = 0; k < 3; ++k) {
        const int e = scale - 60 - static_cast<int>(rng() % (spread + 1));
        c.t0[v][k] = random_double(rng, e);
        c.t1[v][k] = rng() % 3 == 0 ? c.t0[v][k] : random_double(rng, e);
      }
    c.delta = std::ldexp(1.0, scale - 10 - static_cast<int>(rng() % 20));
    std::uniform_real_distribution<double> uniform(0, 1);
    for (const double t : {0.0, 1.0, uniform(rng), std::nextafter(1.0, 0.0),
                           std::ldexp(uniform(rng), -static_cast<int>(rng() % 80))}) {
      const int w = check(c, t, "random");
      ++seen[w >= 1 && w <= 3 ? w : 0];
    }
  }
  for (int w = 0; w < 4; ++w) EXPECT_GT(seen[w], 0) << "width " << w << " never reached";
}

TEST(SeparationIntegers, ExtremeCoordinatesAtEachWidthLimit) {
  // Coordinates +-(2^53 - 1) 2^e at the top of their range and the smallest input 2^(e - L +
  // 53) fixing the common exponent, so that L + k sits at each width's limit and just above;
  // every sign pattern of the vertices (their differences and cross products at their
  // largest) at t = 1 - 2^-k.
  const double top = 0x1.fffffffffffffp0;
  int checked = 0;
  for (int wd = 1; wd <= 4; ++wd) {
    for (int slack = -1; slack <= 2; ++slack) {
      // difference bits = L + k + 2 = 64 wd - 1 - slack.
      const int k = 53;
      const int L = 64 * wd - 3 - slack - k;
      if (L < 54) continue;
      for (unsigned pattern = 0; pattern < 256; pattern += 1 + pattern % 7) {
        Case c;
        for (int v = 0; v < 4; ++v)
          for (int a = 0; a < 3; ++a) {
            const bool negative = ((pattern >> v) & 1) != ((pattern >> (4 + a)) & 1);
            c.t0[v][a] = negative ? -top : top;
            c.t1[v][a] = (((pattern >> ((v + a) % 8)) & 1) != 0) ? -c.t0[v][a] : c.t0[v][a];
          }
        c.t1[3][2] = std::ldexp(1.0, 1 - L);  // the smallest input: L bits in all
        c.delta = top;
        const double t = 1.0 - std::ldexp(1.0, -k);
        check(c, t, "extreme");
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace exactccd
