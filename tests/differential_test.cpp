// Differential tests: the default path (Mode::filtered: culling, semi-static and interval
// filters, exact fallback) must give exactly the exact path's answer (Mode::exact) on every
// double query: the same verdict, the identical tightest TOI pair for toi_width = 0, and for a
// coarse toi_width an enclosure of t* no wider than asked. The exact path is an independent
// decision procedure (rational arithmetic, Sturm root isolation; exact/), so any difference is
// a bug in one of them.
//
// EXACTCCD_TEST_SEED overrides the seed, EXACTCCD_TEST_SCALE multiplies the query counts.
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "corpus/random_queries.hpp"
#include "corpus/simulation_queries.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/query_file.hpp"
#include "tests/test_scale.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

constexpr std::uint64_t kDefaultSeed = 0x5eed0fd1ffULL;
constexpr std::size_t kMaxReported = 10;

/// Collects the first disagreements from worker threads.
class DisagreementLog {
 public:
  void add(const std::string& where, const Disagreement& d) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++count_;
    if (reports_.size() < kMaxReported) reports_.push_back(where + ": " + d.report());
  }
  std::uint64_t count() const { return count_; }
  void print() const {
    for (const auto& r : reports_) ADD_FAILURE() << r;
  }

 private:
  std::mutex mutex_;
  std::uint64_t count_ = 0;
  std::vector<std::string> reports_;
};

std::string percent(std::uint64_t part, std::uint64_t whole) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%6.2f%%", whole ? 100.0 * double(part) / double(whole) : 0.0);
  return buf;
}

void print_header() {
  std::printf("%-36s %9s %9s", "generator", "queries", "collide");
  for (Stage st : default_path_stages()) std::printf(" %16s", to_string(st));
  std::printf(" %9s %8s\n", "fallback", "seconds");
}

/// Stage shares of the default path; "fallback" counts the queries it sent to the rational
/// exact path (Stage::exact).
void print_row(const std::string& name, const DifferentialStats& s, double seconds) {
  std::printf("%-36s %9llu %9llu", name.c_str(), static_cast<unsigned long long>(s.queries),
              static_cast<unsigned long long>(s.collisions));
  for (Stage st : default_path_stages())
    std::printf(" %16s", percent(s.stage[static_cast<int>(st)], s.queries).c_str());
  std::printf(" %9llu %8.2f\n",
              static_cast<unsigned long long>(s.stage[static_cast<int>(Stage::exact)]), seconds);
  std::fflush(stdout);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------------
// (a) The sample queries of the public benchmark

TEST(Differential, SampleQueriesDefaultEqualsExact) {
  struct Sample {
    std::string where;
    DoubleQuery query;
  };
  std::vector<Sample> samples;
  for (const std::string& path : find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
    const auto type = query_type_from_path(path);
    ASSERT_TRUE(type) << path;
    for (const QueryRecord& r : read_query_file(path, *type).queries) {
      Sample s{path + ":" + std::to_string(r.first_line), {}};
      s.query.type = *type;
      for (int i = 0; i < 8; ++i) {
        const RationalPoint& p = r.query.points[i];
        // The benchmark's coordinates are doubles written as exact fractions.
        ASSERT_TRUE(exact::to_double_exactly(p.x, &s.query.v[i].x()) &&
                    exact::to_double_exactly(p.y, &s.query.v[i].y()) &&
                    exact::to_double_exactly(p.z, &s.query.v[i].z()))
            << s.where << ": coordinate is not a double";
      }
      samples.push_back(std::move(s));
    }
  }
  ASSERT_GT(samples.size(), 5000u);  // the shipped set has 5,029 queries

  const auto start = std::chrono::steady_clock::now();
  DisagreementLog log;
  tbb::combinable<DifferentialStats> stats;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 16), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      std::mt19937_64 rng(mix64(i));  // picks the coarse toi_width and t_max
      const Disagreement d = differential_check(samples[i].query, rng, stats.local());
      if (!d.what.empty()) log.add(samples[i].where, d);
    }
  });
  const DifferentialStats total = stats.combine(
      [](DifferentialStats a, const DifferentialStats& b) { return a += b; });
  print_header();
  print_row("sample-queries", total, seconds_since(start));
  log.print();
  EXPECT_EQ(total.queries, samples.size());
  EXPECT_EQ(log.count(), 0u);
  EXPECT_EQ(total.disagreements, 0u);
}

// ---------------------------------------------------------------------------------------------
// (b) Seeded random queries from every generator

/// Queries per generator (each query type); the near-degenerate generators, where the filters
/// give up most often and the exact path is slowest, get fewer. The wide exponent spreads get
/// far fewer: in Mode::exact they cost (mean per query, single thread, at 547347a) about 1 ms
/// (+-100), 5 ms (+-300), 50 ms (+-1000, up to 0.5 s) and 0.08 ms (vf) / 1.5 ms (ee, up to
/// 46 ms) for huge_triangle_subnormal_motion, against 0.05-0.2 ms for the ordinary families;
/// raise them as the exact path gets faster. The total is 1,226,400 at scale 1.
std::uint64_t base_count(const Generator& g) {
  switch (g.family) {
    case Family::uniform_box: return 100000;
    case Family::small_integer_grid: return 50000;
    case Family::short_motion: return 100000;
    case Family::planted_contact: return 50000;
    case Family::planted_contact_ulps: return 50000;
    case Family::contact_at_endpoints: return 50000;
    case Family::coplanar_throughout: return 50000;
    case Family::degenerate_primitives: return 50000;
    case Family::wide_exponent_100: return 4000;
    case Family::wide_exponent_300: return 1000;
    case Family::wide_exponent_1000: return 200;
    case Family::huge_triangle_subnormal_motion: return 8000;
    case Family::resting_contact: return 50000;
    case Family::stacked_coplanar: return 50000;
  }
  return 0;
}

/// Runs `check` (differential_check or partial_interval_coarse_check) on `count(g)` seeded
/// queries of every generator, in parallel, printing a row per generator; returns the totals
/// and adds the disagreements to *disagreements.
template <class Count, class Check>
DifferentialStats run_generators(std::uint64_t seed, Count&& count, Check&& check,
                                 std::uint64_t* disagreements) {
  const auto start = std::chrono::steady_clock::now();
  DifferentialStats total;
  print_header();
  for (const Generator& g : all_generators()) {
    const auto gen_start = std::chrono::steady_clock::now();
    const std::uint64_t n = count(g);
    DisagreementLog log;
    tbb::combinable<DifferentialStats> stats;
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, n, 64), [&](const auto& r) {
      for (std::uint64_t i = r.begin(); i != r.end(); ++i) {
        std::mt19937_64 rng;
        const DoubleQuery q = generate(g, seed, i, rng);
        const Disagreement d = check(q, rng, stats.local());
        if (!d.what.empty()) log.add(g.name() + " #" + std::to_string(i), d);
      }
    });
    const DifferentialStats s = stats.combine(
        [](DifferentialStats a, const DifferentialStats& b) { return a += b; });
    print_row(g.name(), s, seconds_since(gen_start));
    log.print();
    EXPECT_EQ(s.queries, n) << g.name();
    total += s;
    *disagreements += log.count();
  }
  print_row("total", total, seconds_since(start));
  return total;
}

TEST(Differential, RandomQueriesDefaultEqualsExact) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const double scale = scale_from_environment();
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu EXACTCCD_TEST_SCALE=%g\n",
              static_cast<unsigned long long>(seed), scale);
  std::uint64_t total_disagreements = 0;
  const DifferentialStats total = run_generators(
      seed, [&](const Generator& g) { return scaled_count(base_count(g), scale); },
      [](const DoubleQuery& q, std::mt19937_64& rng, DifferentialStats& stats) {
        return differential_check(q, rng, stats);
      },
      &total_disagreements);
  std::printf("coarse-width checks %llu, t_max < 1 checks %llu\n",
              static_cast<unsigned long long>(total.width_checks),
              static_cast<unsigned long long>(total.t_max_checks));
  EXPECT_EQ(total_disagreements, 0u);
  if (scale >= 1) {
    EXPECT_GE(total.queries, 1000000u);
  }
  // The mix must reach every stage of the default path, or a stage could go untested.
  for (Stage st : default_path_stages())
    EXPECT_GT(total.stage[static_cast<int>(st)], 0u) << to_string(st);
}

/// t_max below 1 with a coarse toi_width, on the same seeded queries (the random test above
/// checks t_max < 1 at toi_width = 0 only, on one query in eight): partial_interval_coarse_check
/// on every query, both query types. "collide" counts contacts over [0, t_max].
TEST(Differential, RandomQueriesPartialIntervalCoarseWidth) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const double scale = scale_from_environment();
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu EXACTCCD_TEST_SCALE=%g\n",
              static_cast<unsigned long long>(seed), scale);
  std::uint64_t total_disagreements = 0;
  const DifferentialStats total = run_generators(
      seed, [&](const Generator& g) { return scaled_count(affordable_count(g, 5000), scale); },
      [](const DoubleQuery& q, std::mt19937_64& rng, DifferentialStats& stats) {
        return partial_interval_coarse_check(q, rng, stats);
      },
      &total_disagreements);
  EXPECT_EQ(total_disagreements, 0u);
  // Contacts before t_max must be common, or the coarse widths would go unchecked.
  EXPECT_GE(total.collisions, total.queries / 10);
}

/// The generators must produce what they promise, or the differential test would be weaker
/// than it claims: the planted degeneracies are exact (the four points are coplanar at the
/// planted time, checked in rational arithmetic) whenever no perturbation or inexact scaling
/// followed. Edge-edge huge_triangle_subnormal_motion plants no time.
TEST(Differential, GeneratorsPlantWhatTheyClaim) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  for (const Generator& g : all_generators()) {
    if (g.family != Family::planted_contact && g.family != Family::contact_at_endpoints &&
        g.family != Family::resting_contact && g.family != Family::stacked_coplanar &&
        g.family != Family::huge_triangle_subnormal_motion)
      continue;
    const bool plants = !(g.family == Family::huge_triangle_subnormal_motion &&
                          g.type == QueryType::edge_edge);
    int planted = 0, coplanar_at_planted_time = 0;
    for (std::uint64_t i = 0; i < 4000; ++i) {
      const DoubleQuery q = generate(g, seed, i);
      if (!(q.planted_time >= 0)) continue;  // perturbed or inexactly scaled
      ++planted;
      // The four points at the planted time tc, in exact rationals, are coplanar: the
      // construction places them in a common plane (or on a line, or at a point) at tc.
      const mpq_class tc(q.planted_time);
      std::array<std::array<mpq_class, 3>, 4> x;
      for (int i2 = 0; i2 < 4; ++i2)
        for (int k = 0; k < 3; ++k)
          x[i2][k] = (1 - tc) * mpq_class(q.v[i2][k]) + tc * mpq_class(q.v[i2 + 4][k]);
      mpq_class m[3][3];
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[r][k] = x[r + 1][k] - x[0][k];
      const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      if (sgn(det) == 0) ++coplanar_at_planted_time;
    }
    if (plants)
      EXPECT_GT(planted, 200) << g.name();
    else
      EXPECT_EQ(planted, 0) << g.name();
    EXPECT_EQ(coplanar_at_planted_time, planted) << g.name();
  }
}

/// resting_contact puts the vertex on the face (the edges on each other) at t = 0: every query
/// left unperturbed (planted time 0, scaled by 2^k or not) is in contact from t = 0, and the
/// exact path says so.
TEST(Differential, RestingContactTouchesAtTimeZero) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    const Generator g{Family::resting_contact, type};
    int planted = 0, scaled = 0;
    for (std::uint64_t i = 0; i < 2000; ++i) {
      const DoubleQuery q = generate(g, seed, i);
      if (q.planted_time != 0) continue;  // perturbed: NaN
      ++planted;
      scaled += q.power_of_two != 0;
      const CcdResult r = ccd(q, with_mode(CcdOptions{}, Mode::exact));
      EXPECT_TRUE(r.collides && r.toi_lo == 0 && r.toi_hi == 0)
          << g.name() << " #" << i << ": " << describe(r) << "\n" << describe(q);
    }
    EXPECT_GT(planted, 600) << g.name();  // about half are unperturbed
    EXPECT_GT(scaled, 100) << g.name();   // a quarter of those scaled by 2^k
  }
}

/// One query in four of every generator is its unscaled query times 2^k, k uniform in
/// [-1000, 1000], when every product is exact; the query's stream continues as without the
/// scaling, and the query is the same when regenerated alone.
TEST(Differential, PowerOfTwoScalingIsExactAndReproducible) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  int far = 0;  // scaled by 2^k with |k| >= 500
  for (const Generator& g : all_generators()) {
    int drawn = 0, scaled = 0;
    for (std::uint64_t i = 0; i < 400; ++i) {
      std::mt19937_64 rng, unscaled_rng;
      const DoubleQuery q = generate(g, seed, i, rng);
      const DoubleQuery u = generate_unscaled(g, seed, i, unscaled_rng);
      ASSERT_EQ(rng(), unscaled_rng()) << g.name() << " #" << i;
      const int k = power_of_two_exponent(seed, g, i);
      ASSERT_TRUE(k >= -1000 && k <= 1000);
      drawn += k != 0;
      ASSERT_TRUE(q.power_of_two == 0 || q.power_of_two == k) << g.name() << " #" << i;
      scaled += q.power_of_two != 0;
      far += std::abs(q.power_of_two) >= 500;
      bool exact = true;
      for (int p = 0; p < 8; ++p)
        for (int c = 0; c < 3; ++c) {
          const double x = u.v[p][c], y = q.v[p][c];
          if (q.power_of_two == 0) {
            EXPECT_TRUE(std::memcmp(&x, &y, sizeof x) == 0) << g.name() << " #" << i;
          } else {
            mpq_class expected(x);  // x 2^k, exactly
            if (k > 0)
              mpq_mul_2exp(expected.get_mpq_t(), expected.get_mpq_t(), static_cast<unsigned>(k));
            else
              mpq_div_2exp(expected.get_mpq_t(), expected.get_mpq_t(), static_cast<unsigned>(-k));
            EXPECT_EQ(mpq_class(y), expected) << g.name() << " #" << i;
          }
          // An unscaled query whose scaling was drawn was left alone only if it was inexact.
          if (k != 0 && q.power_of_two == 0) {
            const double s = std::ldexp(x, k);
            exact = exact && std::isfinite(s) && std::ldexp(s, -k) == x;
          }
        }
      if (k != 0 && q.power_of_two == 0) EXPECT_FALSE(exact) << g.name() << " #" << i;
      const DoubleQuery again = generate(g, seed, i);
      EXPECT_TRUE(again.v == q.v) << g.name() << " #" << i;
    }
    // About one in four drawn (100 of 400; 5 standard deviations are about 43).
    EXPECT_GT(drawn, 57) << g.name();
    EXPECT_LT(drawn, 143) << g.name();
    // Wide spreads overflow or underflow under most k; the ordinary families rarely do.
    if (g.family != Family::wide_exponent_300 && g.family != Family::wide_exponent_1000 &&
        g.family != Family::huge_triangle_subnormal_motion)
      EXPECT_GT(scaled, drawn / 2) << g.name();
  }
  EXPECT_GT(far, 100);
}

// ---------------------------------------------------------------------------------------------
// (c) Simulation-like queries

/// At least 50,000 queries of the simulation-like generator (a sheet draping over a sphere, two
/// rigid bodies passing close): the queries a broad phase hands to a narrow phase, with
/// resting and sliding contact, shared planes and tiny gaps.
TEST(Differential, SimulationQueriesDefaultEqualsExact) {
  const sim::SimulationConfig config = sim::small_simulation_config();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<sim::SimulationQuery> queries = sim::generate_simulation_queries(config);
  std::printf("generated %zu simulation queries in %.2f s (sheet %d, steps %d, seed %llu)\n",
              queries.size(), seconds_since(start), config.sheet_resolution, config.steps,
              static_cast<unsigned long long>(config.seed));
  ASSERT_GE(queries.size(), 50000u);

  print_header();
  for (sim::PairKind kind :
       {sim::PairKind::sheet_sphere, sim::PairKind::sheet_self, sim::PairKind::body_body}) {
    for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
      std::vector<std::size_t> indices;
      for (std::size_t i = 0; i < queries.size(); i += subset_stride())
        if (queries[i].kind == kind && queries[i].type == type) indices.push_back(i);
      const auto part_start = std::chrono::steady_clock::now();
      const std::string name = std::string(type == QueryType::vertex_face ? "vf/" : "ee/") +
                               "sim_" + sim::to_string(kind);
      DisagreementLog log;
      tbb::combinable<DifferentialStats> stats;
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, indices.size(), 64),
                        [&](const auto& r) {
                          for (std::size_t k = r.begin(); k != r.end(); ++k) {
                            const std::size_t i = indices[k];
                            DoubleQuery q;
                            q.type = queries[i].type;
                            q.v = queries[i].points;
                            std::mt19937_64 rng(mix64(i));
                            const Disagreement d = differential_check(q, rng, stats.local());
                            if (!d.what.empty()) log.add(name + " #" + std::to_string(i), d);
                          }
                        });
      const DifferentialStats s = stats.combine(
          [](DifferentialStats a, const DifferentialStats& b) { return a += b; });
      print_row(name, s, seconds_since(part_start));
      log.print();
      EXPECT_EQ(s.queries, indices.size());
      EXPECT_EQ(log.count(), 0u) << name;
    }
  }
}

}  // namespace
}  // namespace exactccd::test
