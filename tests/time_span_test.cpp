// The scene's cull by time (pipeline/scene/time_span.hpp): overlap_span contains every time at
// which the blended boxes overlap, decided exactly over the rationals, in every rounding mode;
// and it does cut what it should. PROOF: proofs/scene.md#time-span
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cfenv>
#include <cmath>
#include <random>

#include "core/predicates/fp_environment.hpp"
#include "pipeline/scene/time_span.hpp"

namespace exactccd {
namespace {

using scene::Box;
using scene::MotionBox;
using scene::TimeSpan;

/// The exact times in [0, 1] at which the blended boxes overlap, or nothing (lo > hi).
struct ExactSpan {
  mpq_class lo = 0, hi = 1;
};

ExactSpan exact_span(const MotionBox& a, const MotionBox& b) {
  ExactSpan s;
  auto keep = [&](const mpq_class& g0, const mpq_class& g1) {
    if (g0 <= 0 && g1 <= 0) return;
    if (g0 > 0 && g1 > 0) {
      s.lo = 1, s.hi = 0;
      return;
    }
    const mpq_class r = g0 / (g0 - g1);
    if (g0 > 0) s.lo = std::max(s.lo, r);
    else s.hi = std::min(s.hi, r);
  };
  for (int k = 0; k < 3; ++k) {
    keep(mpq_class(a.at0.lo[k]) - mpq_class(b.at0.hi[k]),
         mpq_class(a.at1.lo[k]) - mpq_class(b.at1.hi[k]));
    keep(mpq_class(b.at0.lo[k]) - mpq_class(a.at0.hi[k]),
         mpq_class(b.at1.lo[k]) - mpq_class(a.at1.hi[k]));
  }
  return s;
}

Box random_box(std::mt19937_64& rng, double scale, double size) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Box b;
  for (int k = 0; k < 3; ++k) {
    const double c = scale * u(rng), h = size * std::abs(u(rng));
    b.lo[k] = c - h;
    b.hi[k] = c + h;
  }
  return b;
}

/// Counts of pairs whose exact span is empty, and of those that overlap_span also cut.
struct Tally {
  int exact_empty = 0, cut = 0, compared = 0;
};

void check_pair(const MotionBox& a, const MotionBox& b, Tally& tally) {
  const ExactSpan e = exact_span(a, b);
  const TimeSpan s = scene::overlap_span(a, b);
  ++tally.compared;
  if (e.lo > e.hi) {
    ++tally.exact_empty;
    if (s.empty()) ++tally.cut;
    return;
  }
  ASSERT_FALSE(s.empty()) << "a span with overlap was cut";
  EXPECT_LE(mpq_class(s.lo), e.lo);
  EXPECT_GE(mpq_class(s.hi), e.hi);
  EXPECT_TRUE(scene::may_meet_by(a, b, e.lo.get_d() <= 1.0 ? std::nextafter(e.lo.get_d(), 2.0)
                                                            : 1.0));
}

void random_pairs(int rounding, Tally& tally) {
  std::mt19937_64 rng(20261129);
  const int old = std::fegetround();
  std::fesetround(rounding);
  for (int n = 0; n < 20000 && !::testing::Test::HasFatalFailure(); ++n) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 200) - 100);
    const double size = scale * std::ldexp(1.0, -static_cast<int>(rng() % 20));
    MotionBox a{random_box(rng, scale, size), random_box(rng, scale, size)};
    MotionBox b{random_box(rng, scale, size), random_box(rng, scale, size)};
    if (n % 3 == 0) b.at0 = a.at0;  // touching at t = 0 (closed boxes)
    if (n % 5 == 0) {               // touching exactly at some axis at t = 1
      b.at1.lo[0] = a.at1.hi[0];
    }
    check_pair(a, b, tally);
  }
  std::fesetround(old);
}

TEST(TimeSpan, ContainsTheExactTimesOnRandomAndExtremeBoxes) {
  const predicates::FpEnvironmentGuard clean(predicates::Rounding::to_nearest);
  Tally tally;
  for (const int rounding : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
    SCOPED_TRACE(rounding);
    random_pairs(rounding, tally);
  }
  // Huge coordinates: differences overflow to infinity; the span must stay a superset.
  const double big = std::ldexp(1.0, 1023);
  MotionBox a{{{-big, -big, -big}, {big, big, big}}, {{big, big, big}, {big, big, big}}};
  MotionBox b{{{-big, 0, 0}, {-big, 0, 0}}, {{-big, -big, -big}, {-big, -big, -big}}};
  check_pair(a, b, tally);
  // One gap overflows at one end only: g0 = -2^1022 - 2^1022 is finite, g1 = 2^1023 + 2^1023
  // overflows to +infinity, while the exact root is 1/3 (no cut to a span near 0 allowed).
  const double half = std::ldexp(1.0, 1022);
  const MotionBox left{{{-half, 0, 0}, {-half, 1, 1}}, {{big, 0, 0}, {big, 1, 1}}};
  const MotionBox right{{{half, 0, 0}, {half, 1, 1}}, {{-big, 0, 0}, {-big, 1, 1}}};
  check_pair(left, right, tally);
  check_pair(right, left, tally);
  // The cull is not idle: most exactly empty spans are cut (all but a few within the slack).
  EXPECT_GT(tally.exact_empty, 1000);
  EXPECT_GT(tally.cut, tally.exact_empty * 9 / 10);
}

TEST(TimeSpan, BoxesPassingEachOtherAtDifferentTimesPerAxisAreCut) {
  // a moves right along x through b's x range during [0.4, 0.6]; along y it passes b's y range
  // during [0.1, 0.2]: the swept boxes overlap, the blended ones never do.
  const Box b{{0, 0, 0}, {1, 1, 1}};
  const MotionBox still{b, b};
  const MotionBox a{{{-5, 2, 0}, {-4, 3, 0.5}}, {{5, -18, 0}, {6, -17, 0.5}}};
  EXPECT_TRUE(scene::overlap_span(a, still).empty());
  EXPECT_FALSE(scene::may_meet_by(a, still, 1.0));
  // Shifted in time along y to meet the x passage: they overlap, around t = 1/2.
  const MotionBox c{{{-5, 11, 0}, {-4, 12, 0.5}}, {{5, -9, 0}, {6, -8, 0.5}}};
  const TimeSpan s = scene::overlap_span(c, still);
  ASSERT_FALSE(s.empty());
  EXPECT_LE(s.lo, 0.5);
  EXPECT_GE(s.hi, 0.5);
  EXPECT_FALSE(scene::may_meet_by(c, still, 0.25));  // not yet by t = 1/4
}

}  // namespace
}  // namespace exactccd
