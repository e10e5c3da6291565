// Signs of the minimum-separation region polynomials at doubles from double-double with a
// running error bound (core/predicates/double_double_bounds.hpp,
// ExactSignsAtDoubles::bounded_value, and the tightening's probes, ExactSignsAtDoubles::*_probe),
// against the same polynomials over the rationals (core/predicates/separation.hpp read in
// mpq_class), where it matters: at the two adjacent doubles around each root of every kernel
// polynomial (found by bisection over the rationals) and a few ulps either side, where the
// polynomial is about its slope times one ulp of t. Queries: random near unit scale, scaled by
// 2^+-500, coordinates 2^30 times their differences away from the origin, edges within 2^-40
// of parallel, a vertex sliding at distance delta, wide exponent spreads, and ones whose
// scaled coordinates underflow. It is not vacuous: the bounded path decides most of these
// signs (counted), and the exact integers the rest.
// PROOF: proofs/min_separation.md#double-double-signs
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "core/predicates/separation.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "separation_rational.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using Case = test::SeparationCase;
using test::rational_value;

// The kernel polynomials (those with a double-double form): vertex-face 0, the spheres 4, 8,
// 12, the projections 5, 6, 9, 10, 13, 14 and the capsules 7, 11, 15; edge-edge 0, the spheres
// 5-8 and 9-20 (projections and capsules).
const std::vector<int> kVertexFace = {0, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
const std::vector<int> kEdgeEdge = {0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};

struct Tally {
  long checked = 0, wrong = 0;
};

int sign_at(const exact::separation::ExactSignsAtDoubles& s, bool vf, int k, double t) {
  return vf ? s.vertex_face_sign(k, t) : s.edge_edge_sign(k, t);
}

/// The tightening's probe (the same sign, with a Newton guess from its value).
exact::separation::ExactSignsAtDoubles::Probe probe_at(
    const exact::separation::ExactSignsAtDoubles& s, bool vf, int k, double t) {
  return vf ? s.vertex_face_probe(k, t) : s.edge_edge_probe(k, t);
}

/// For every kernel polynomial with a sign change over [0, 1]: the adjacent doubles around a
/// root and three ulps either side, plus a few random times.
void check_case(const Case& c, bool vf, std::mt19937_64& rng, Tally* tally) {
  const exact::separation::ExactSignsAtDoubles signs(
      {&c.t0[0], &c.t0[1], &c.t0[2], &c.t0[3]}, {&c.t1[0], &c.t1[1], &c.t1[2], &c.t1[3]},
      c.delta);
  auto expect = [&](int k, double t, const std::string& where) {
    const int expected = sgn(rational_value(c, vf, k, t));
    const int got = sign_at(signs, vf, k, t);
    const auto probe = probe_at(signs, vf, k, t);
    ++tally->checked;
    if (got != expected || !probe.kernel || probe.sign != expected) {
      ++tally->wrong;
      ADD_FAILURE() << (vf ? "vertex-face " : "edge-edge ") << k << " at " << t << " ("
                    << where << "): " << got << ", probe " << probe.sign << ", exact "
                    << expected;
    }
  };
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const int k : vf ? kVertexFace : kEdgeEdge) {
    expect(k, unit(rng), "random");
    const int s0 = sgn(rational_value(c, vf, k, 0.0)), s1 = sgn(rational_value(c, vf, k, 1.0));
    if (s0 == 0 || s1 == 0 || s0 == s1) continue;
    double lo = 0.0, hi = 1.0;  // sign s0 at lo, the other at hi (or a root at a double)
    for (int i = 0; i < 80 && std::nextafter(lo, hi) < hi; ++i) {
      const double mid = lo + 0.5 * (hi - lo);
      const int s = sgn(rational_value(c, vf, k, mid));
      if (s == 0) {
        lo = hi = mid;
        break;
      }
      (s == s0 ? lo : hi) = mid;
    }
    double t = lo;
    for (int i = 0; i < 3 && t > 0; ++i) t = std::nextafter(t, 0.0);
    for (int i = 0; i < 8 && t <= 1.0; ++i, t = std::nextafter(t, 2.0)) expect(k, t, "near a root");
  }
}

double random_double(std::mt19937_64& rng, double scale) {
  return scale * std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
}

Case random_case(std::mt19937_64& rng, int kind) {
  Case c;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d offset =
      kind == 2 ? Eigen::Vector3d::Constant(std::ldexp(1.0, 30)) : Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) {
      c.t0[i][a] = random_double(rng, 1.0) + offset[a];
      c.t1[i][a] = c.t0[i][a] + random_double(rng, 0.5);
    }
  c.delta = std::ldexp(unit(rng), -static_cast<int>(1 + 20 * unit(rng)));
  switch (kind) {
    case 1: {  // scaled by 2^+-500
      const int e = unit(rng) < 0.5 ? 500 : -500;
      for (int i = 0; i < 4; ++i) {
        c.t0[i] *= std::ldexp(1.0, e);
        c.t1[i] *= std::ldexp(1.0, e);
      }
      c.delta = std::ldexp(c.delta, e);
      break;
    }
    case 3:  // the second edge within about 2^-40 of parallel to the first, at both ends
      for (int end = 0; end < 2; ++end) {
        auto& x = end == 0 ? c.t0 : c.t1;
        const Eigen::Vector3d u = x[1] - x[0];
        x[3] = x[2] + u * 0.75 + Eigen::Vector3d::Constant(std::ldexp(random_double(rng, 1), -40));
      }
      break;
    case 4:  // a vertex sliding at distance delta over the plane z = 0
      for (int i = 1; i < 4; ++i) c.t0[i][2] = c.t1[i][2] = 0.0;
      c.t0[0][2] = c.t1[0][2] = c.delta;
      break;
    case 5:  // exponents spread over +-300
      for (int i = 0; i < 4; ++i)
        for (int a = 0; a < 3; ++a) {
          c.t0[i][a] = std::ldexp(random_double(rng, 1), static_cast<int>(rng() % 600) - 300);
          c.t1[i][a] = std::ldexp(random_double(rng, 1), static_cast<int>(rng() % 600) - 300);
        }
      c.delta = std::ldexp(unit(rng), static_cast<int>(rng() % 600) - 300);
      break;
    case 6:  // one coordinate tiny against the others: its scaled value underflows
      c.t0[3][2] = std::ldexp(1.0, -1060);
      break;
    default: break;
  }
  return c;
}

TEST(DoubleDoubleSigns, EqualTheRationalSignsAtTheDoublesAroundEveryRoot) {
  std::mt19937_64 rng(2026);
  Tally tally;
  const std::uint64_t before = exact::separation::bounded_decisions_in_this_thread();
  const auto n = test::scaled_count(35, test::scale_from_environment());
  for (int kind = 0; kind <= 6; ++kind)
    for (std::uint64_t i = 0; i < n; ++i) {
      const Case c = random_case(rng, kind);
      check_case(c, i % 2 == 0, rng, &tally);
    }
  const std::uint64_t bounded = exact::separation::bounded_decisions_in_this_thread() - before;
  EXPECT_EQ(tally.wrong, 0);
  // Not vacuous: many roots were found, and the bounded path decided most signs.
  EXPECT_GT(tally.checked, static_cast<long>(20 * n));
  EXPECT_GT(bounded, static_cast<std::uint64_t>(tally.checked / 2))
      << bounded << " of " << tally.checked;
}

/// A coordinate whose scaled value is exactly halfway between 2^-1022 and the largest
/// subnormal: (2^53 - 1) 2^-1074 against coordinates in [1, 2) scales to (2^53 - 1) 2^-1075,
/// which rounds to 2^-1022, a normal double, though the exact value is not one. The
/// double-double path must not take it (its bound assumes exact inputs): the integers decide.
TEST(DoubleDoubleSigns, AScaledInputThatRoundsToTheSmallestNormalIsLeftToTheIntegers) {
  Case c;
  for (int i = 0; i < 4; ++i) {
    c.t0[i] = Eigen::Vector3d(1.0 + 0.25 * i, 1.5 - 0.125 * i, 1.0625 * (i % 2));
    c.t1[i] = c.t0[i] + Eigen::Vector3d(0.03125 * i, -0.0625, 0.5 * (i == 0));
  }
  c.t0[2][2] = std::nextafter(0x1p-1021, 0.0);  // (2^53 - 1) 2^-1074
  c.delta = 0.25;
  for (const bool vf : {true, false}) {
    const exact::separation::ExactSignsAtDoubles signs(
        {&c.t0[0], &c.t0[1], &c.t0[2], &c.t0[3]}, {&c.t1[0], &c.t1[1], &c.t1[2], &c.t1[3]},
        c.delta);
    for (const int k : vf ? kVertexFace : kEdgeEdge)
      for (const double t : {0.0, 0.375, 0.5, 1.0}) {
        const std::uint64_t before = exact::separation::bounded_decisions_in_this_thread();
        EXPECT_EQ(sign_at(signs, vf, k, t), sgn(rational_value(c, vf, k, t)))
            << (vf ? "vertex-face " : "edge-edge ") << k << " at " << t;
        EXPECT_EQ(probe_at(signs, vf, k, t).sign, sgn(rational_value(c, vf, k, t)));
        EXPECT_EQ(exact::separation::bounded_decisions_in_this_thread(), before)
            << (vf ? "vertex-face " : "edge-edge ") << k << " at " << t;
      }
  }
}

}  // namespace
}  // namespace exactccd
