// Exact power-of-two normalisation before the filters (pipeline/power_of_two_scaling.hpp):
//  - the normalising exponent: none for data near unit scale or when scaling would lose a bit,
//    else the one bringing the largest |coordinate| into [1/2, 1), exactly;
//  - magnitude independence: every sample query scaled (exactly) by 2^k, k in [-1000, 1000],
//    gets the unscaled query's verdict and TOI bit for bit in default mode, decided by the same
//    stage (so the filters, not the exact path, decide the scaled copies of the queries they
//    decide unscaled).
// EXACTCCD_TEST_SCALE scales the share of queries tried at each k.
// PROOF: proofs/filters.md#power-of-two-normalisation
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/predicates/double_bits.hpp"
#include "pipeline/power_of_two_scaling.hpp"
#include "corpus/random_queries.hpp"
#include "exact/arithmetic/rational.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

/// Every coordinate +-other, except one of the first point (tested first) which is `value`.
DoubleQuery query_with(double value, double other) {
  DoubleQuery q;
  q.type = QueryType::vertex_face;
  for (auto& p : q.v) p = {other, -other, other};
  q.v[0].y() = value;
  return q;
}

int normalising_exponent(const DoubleQuery& q) {
  return exactccd::detail::normalising_exponent(q.vertex_face());
}

TEST(PowerOfTwoNormalisation, NoneNearUnitScale) {
  EXPECT_EQ(normalising_exponent(query_with(0.75, 0.1)), 0);
  EXPECT_EQ(normalising_exponent(query_with(std::ldexp(1.0, 64), 0.1)), 0);
  EXPECT_EQ(normalising_exponent(query_with(std::ldexp(1.0, -64), 0.0)), 0);
  EXPECT_EQ(normalising_exponent(query_with(0.0, 0.0)), 0);  // all zero
  // Tiny parts next to a unit-scale largest coordinate are left alone too.
  EXPECT_EQ(normalising_exponent(query_with(1.0, std::ldexp(1.0, -1074))), 0);
  // The cheap test reads the first point: near unit scale there, nothing else is read (a
  // query left unnormalised is decided correctly all the same).
  DoubleQuery q = query_with(std::ldexp(1.0, 300), std::ldexp(1.0, 300));
  EXPECT_EQ(normalising_exponent(q), -301);
  q.v[0] = {0.5, 0.25, -0.125};
  EXPECT_EQ(normalising_exponent(q), 0);
  // Otherwise the largest coordinate of all points counts: a first point at the origin.
  q.v[0].setZero();
  EXPECT_EQ(normalising_exponent(q), -301);
  q.v[3].x() = std::ldexp(1.0, 400);
  EXPECT_EQ(normalising_exponent(q), -401);
}

TEST(PowerOfTwoNormalisation, BringsTheLargestCoordinateNearOne) {
  for (int e : {-1074, -1070, -1022, -1000, -500, -66, 66, 100, 700, 1000, 1023}) {
    const double big = std::ldexp(1.5, e <= -1074 ? e + 1 : e);
    const DoubleQuery q = query_with(-big, big / 4);
    const int s = normalising_exponent(q);
    ASSERT_NE(s, 0) << e;
    const VertexFaceQuery scaled = exactccd::detail::scaled_by_power_of_two(q.vertex_face(), s);
    EXPECT_GE(std::fabs(scaled.p_t0.y()), 0.5) << e;
    EXPECT_LT(std::fabs(scaled.p_t0.y()), 1.0) << e;
    EXPECT_EQ(std::ldexp(scaled.p_t0.y(), -s), -big) << e;  // exact
    EXPECT_EQ(std::ldexp(scaled.a_t1.x(), -s), big / 4) << e;
  }
  // The largest double and the smallest subnormal.
  EXPECT_EQ(normalising_exponent(query_with(DBL_MAX, 1.0)), -1024);
  EXPECT_EQ(normalising_exponent(query_with(std::ldexp(1.0, -1074), 0.0)), 1073);
}

TEST(PowerOfTwoNormalisation, NoneWhenABitWouldBeLost) {
  // Bringing 2^700 to [1/2, 1) is a scale by 2^-701: a coordinate 2^-373 lands on 2^-1074, the
  // last subnormal bit, and stays exact; 2^-374 would fall below it, so nothing is scaled.
  const double big = std::ldexp(1.0, 700);
  EXPECT_EQ(normalising_exponent(query_with(big, std::ldexp(1.0, -373))), -701);
  EXPECT_EQ(normalising_exponent(query_with(big, std::ldexp(1.0, -374))), 0);
  EXPECT_EQ(normalising_exponent(query_with(big, std::ldexp(1.0, -400))), 0);
  // A coordinate whose lowest set bit is lost, though the value itself is not tiny.
  const double odd = 1.0 + std::ldexp(1.0, -52);  // lowest bit 2^-52
  EXPECT_EQ(normalising_exponent(query_with(std::ldexp(1.0, 1023), odd)), 0);
  EXPECT_EQ(normalising_exponent(query_with(std::ldexp(1.0, 1000), odd)), -1001);
}

// ---- magnitude independence on the sample queries ----------------------------------------------

struct Loaded {
  DoubleQuery query;
  CcdResult unscaled;
};

const std::vector<Loaded>& loaded_sample() {
  static const std::vector<Loaded> all = [] {
    std::vector<Loaded> out;
    for (const SampleQuery& s : sample_queries()) {
      Loaded l;
      l.query.type = s.query.type;
      for (int i = 0; i < 8; ++i) {
        const auto& p = s.query.points[i];
        if (!exact::to_double_exactly(p.x, &l.query.v[i].x()) ||
            !exact::to_double_exactly(p.y, &l.query.v[i].y()) ||
            !exact::to_double_exactly(p.z, &l.query.v[i].z()))
          throw std::runtime_error("a sample coordinate is not a double");
      }
      l.unscaled = ccd(l.query, CcdOptions{});
      out.push_back(l);
    }
    return out;
  }();
  return all;
}

bool same_bits(double a, double b) { return predicates::bits_of(a) == predicates::bits_of(b); }

TEST(PowerOfTwoNormalisation, SampleQueriesScaledByAnyPowerOfTwoKeepTheirAnswerAndStage) {
  const std::vector<Loaded>& sample = loaded_sample();
  // Every query at the k listed here; at the other k in [-1000, 1000], every stride-th query
  // (a different subset at each k).
  const std::vector<int> every_query = {-1000, -950, -900, -500, -65, -64, -1,
                                        1,     64,   65,   500,  900, 950, 1000};
  const auto stride =
      static_cast<std::size_t>(std::max(1.0, std::round(20.0 / scale_from_environment())));
  std::uint64_t checked = 0, not_exact = 0, filter_decided = 0;
  std::uint64_t stage_count[kStageCount] = {};
  for (int k = -1000; k <= 1000; ++k) {
    if (k == 0) continue;
    const bool all = std::find(every_query.begin(), every_query.end(), k) != every_query.end();
    for (std::size_t i = all ? 0 : static_cast<std::size_t>(k + 1000) % stride; i < sample.size();
         i += all ? 1 : stride) {
      const Loaded& l = sample[i];
      DoubleQuery scaled = l.query;
      if (!scale_if_exact(&scaled, k)) {
        ++not_exact;
        continue;
      }
      const CcdResult r = ccd(scaled, CcdOptions{});
      ++checked;
      ++stage_count[static_cast<int>(r.decided_by)];
      ASSERT_EQ(r.collides, l.unscaled.collides) << "k = " << k << "\n" << describe(l.query);
      if (r.collides) {
        ASSERT_TRUE(same_bits(r.toi_lo, l.unscaled.toi_lo)) << "k = " << k << "\n"
                                                            << describe(l.query);
        ASSERT_TRUE(same_bits(r.toi_hi, l.unscaled.toi_hi)) << "k = " << k << "\n"
                                                            << describe(l.query);
      }
      // The same stage decides: the float stages keep what they decide unscaled, at every
      // magnitude (|k| <= 900 is what the issue asks; every exact scaling is checked).
      ASSERT_EQ(r.decided_by, l.unscaled.decided_by)
          << "k = " << k << ", unscaled " << to_string(l.unscaled.decided_by) << ", scaled "
          << to_string(r.decided_by) << "\n"
          << describe(l.query);
      filter_decided += r.decided_by == Stage::filter || r.decided_by == Stage::filter_exact_toi;
    }
  }
  std::printf(
      "%llu scaled queries checked (%llu scalings not exact, skipped); %llu decided by "
      "the filters\n",
      static_cast<unsigned long long>(checked), static_cast<unsigned long long>(not_exact),
      static_cast<unsigned long long>(filter_decided));
  for (Stage s : default_path_stages())
    std::printf("  %-17s %llu\n", to_string(s),
                static_cast<unsigned long long>(stage_count[static_cast<int>(s)]));
  EXPECT_GT(checked, 100000u / stride);
  EXPECT_GT(filter_decided, checked / 3);
}

TEST(PowerOfTwoNormalisation, RandomFamiliesScaledKeepTheirAnswer) {
  // Planted contacts (exact TOIs at dyadic times), near misses and degenerate primitives,
  // scaled to the ends of the range: the same verdict and TOI as unscaled, also with t_max < 1
  // and a coarse width (an enclosure of the exact contact time either way).
  const std::uint64_t seed = seed_from_environment(0x5ca1e);
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 pick(seed);
  std::uint64_t checked = 0;
  const std::uint64_t n = scaled_count(150, scale_from_environment());
  std::uint64_t queries = 0;
  for (const Generator& g : all_generators()) {
    for (std::uint64_t i = 0; i < affordable_count(g, n); ++i, ++queries) {
      const DoubleQuery q = generate(g, seed, i);
      const CcdResult base = ccd(q, CcdOptions{});
      const CcdResult base_coarse = ccd(q, CcdOptions{0.75, 1e-4, Mode::filtered});
      for (int k : {-1000, -700, -300, 300, 700, 1000, static_cast<int>(pick() % 2001) - 1000}) {
        DoubleQuery scaled = q;
        if (!scale_if_exact(&scaled, k)) continue;
        const CcdResult r = ccd(scaled, CcdOptions{});
        ++checked;
        ASSERT_EQ(r.collides, base.collides) << "k = " << k << "\n" << describe(q);
        if (r.collides) {
          ASSERT_TRUE(same_bits(r.toi_lo, base.toi_lo)) << "k = " << k << "\n" << describe(q);
          ASSERT_TRUE(same_bits(r.toi_hi, base.toi_hi)) << "k = " << k << "\n" << describe(q);
        }
        const CcdResult coarse = ccd(scaled, CcdOptions{0.75, 1e-4, Mode::filtered});
        ASSERT_EQ(coarse.collides, base_coarse.collides) << "k = " << k << "\n" << describe(q);
        if (coarse.collides) {
          // Both enclose the exact first contact: their intersection is not empty.
          ASSERT_LE(coarse.toi_lo, base_coarse.toi_hi) << "k = " << k << "\n" << describe(q);
          ASSERT_LE(base_coarse.toi_lo, coarse.toi_hi) << "k = " << k << "\n" << describe(q);
        }
      }
    }
  }
  EXPECT_GT(checked, queries * 3);
}

}  // namespace
}  // namespace exactccd::test
