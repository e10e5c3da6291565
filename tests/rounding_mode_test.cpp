// The default path under the caller's rounding mode, from several threads at once, and the
// build's floating-point contract (no contraction of a * b + c into a fused multiply-add).
//
// (a) The filters' proofs assume round-to-nearest for the plain double stages and set upward
//     rounding themselves for interval arithmetic; a caller may run with any of the four IEEE
//     modes. Every result must be the one obtained under FE_TONEAREST, and the caller's mode
//     must be the same after the call, including when the call throws.
// (b) The library has no shared mutable state (the rounding mode is per thread): the same
//     queries decided from several threads at once give the sequential results.
// (c) The certified error bounds count one rounding per operation; a build that fused
//     a * b + c (-ffp-contract=fast with FMA hardware) would break that count.
//
// This file is compiled with the library's floating-point flags (-frounding-math,
// -ffp-contract=off), so the compiler keeps the rounding-mode changes and the expressions here
// as written.
#include <gtest/gtest.h>

#include <atomic>
#include <cfenv>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/predicates/fp_environment.hpp"
#include "corpus/random_queries.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/query_file.hpp"
#include "filters/coplanarity_semistatic.hpp"
#include "tests/sample_double_queries.hpp"
#include "tests/test_scale.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

constexpr std::uint64_t kDefaultSeed = 0xf0e5;

struct RoundingMode {
  int mode;
  const char* name;
};
constexpr RoundingMode kModes[] = {{FE_TONEAREST, "FE_TONEAREST"},
                                   {FE_UPWARD, "FE_UPWARD"},
                                   {FE_DOWNWARD, "FE_DOWNWARD"},
                                   {FE_TOWARDZERO, "FE_TOWARDZERO"}};

/// Restores round-to-nearest when a test leaves early.
struct NearestOnExit {
  ~NearestOnExit() { std::fesetround(FE_TONEAREST); }
};

bool same(const CcdResult& a, const CcdResult& b) {
  // Bitwise-equal TOIs (0.0 and -0.0 would differ as results too, so compare bits).
  return a.collides == b.collides && std::memcmp(&a.toi_lo, &b.toi_lo, sizeof(double)) == 0 &&
         std::memcmp(&a.toi_hi, &b.toi_hi, sizeof(double)) == 0 && a.decided_by == b.decided_by;
}

struct Case {
  DoubleQuery query;
  CcdOptions options;
};

/// Sample queries (every 4th, for time) and random queries from every generator, each with
/// default options and with a coarse width over [0, 3/4]; plus some with Mode::exact and
/// Mode::float_only (the library promises mode-independent results for every Mode).
std::vector<Case> cases() {
  std::vector<Case> out;
  const CcdOptions coarse{0.75, 1e-6, Mode::filtered};
  std::size_t k = 0;
  for (const DoubleQuery& q : sample_double_queries()) {
    if (k++ % 4 != 0) continue;
    out.push_back({q, CcdOptions{}});
    out.push_back({q, coarse});
  }
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const std::uint64_t n = scaled_count(300, scale_from_environment());
  for (const Generator& g : all_generators())
    for (std::uint64_t i = 0; i < affordable_count(g, n); ++i) {
      const DoubleQuery q = generate(g, seed, i);
      out.push_back({q, CcdOptions{}});
      out.push_back({q, coarse});
      if (i % 16 == 0) out.push_back({q, CcdOptions{1.0, 0.0, Mode::exact}});
      // The uncertified float_only path computes its TOI in plain doubles: about one result
      // in eight changes with the rounding mode unless the library sets round-to-nearest
      // itself, so these cases are the ones that would catch a missing guard.
      if (i % 4 == 0) out.push_back({q, CcdOptions{1.0, 0.0, Mode::float_only}});
    }
  return out;
}

const std::vector<Case>& all_cases() {
  static const std::vector<Case> c = cases();
  return c;
}

// ---------------------------------------------------------------------------------------------
// (a) Caller's rounding mode

TEST(RoundingMode, ResultsUnderEveryCallerModeEqualRoundToNearest) {
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n",
              static_cast<unsigned long long>(seed_from_environment(kDefaultSeed)));
  NearestOnExit restore;
  const auto& all = all_cases();
  std::vector<CcdResult> nearest(all.size());
  ASSERT_EQ(std::fesetround(FE_TONEAREST), 0);
  for (std::size_t i = 0; i < all.size(); ++i) nearest[i] = ccd(all[i].query, all[i].options);

  std::size_t stages[kStageCount] = {};
  for (const CcdResult& r : nearest) ++stages[static_cast<int>(r.decided_by)];
  std::printf("%zu cases:", all.size());
  for (Stage s : default_path_stages()) std::printf(" %s %zu", to_string(s), stages[static_cast<int>(s)]);
  std::printf(" float_only %zu\n", stages[static_cast<int>(Stage::float_only)]);
  // Every stage must be exercised, or a mode-dependent stage could go unnoticed.
  for (Stage s : default_path_stages()) EXPECT_GT(stages[static_cast<int>(s)], 20u) << to_string(s);
  EXPECT_GT(stages[static_cast<int>(Stage::float_only)], scaled_count(500));

  for (const RoundingMode& m : kModes) {
    int mismatches = 0, mode_changes = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      ASSERT_EQ(std::fesetround(m.mode), 0) << m.name;
      // The register itself as well: fegetround reads only the x87 control word on x86-64.
      const unsigned control_before = predicates::raw_fp_control();
      const CcdResult r = ccd(all[i].query, all[i].options);
      const unsigned control_after = predicates::raw_fp_control();
      const int after = std::fegetround();
      std::fesetround(FE_TONEAREST);
      if ((after != m.mode || control_after != control_before) && ++mode_changes <= 5)
        ADD_FAILURE() << m.name << ": caller's rounding mode changed by the call\n"
                      << describe(all[i].query);
      if (!same(r, nearest[i]) && ++mismatches <= 5)
        ADD_FAILURE() << m.name << ": result differs from FE_TONEAREST\n query: "
                      << describe(all[i].query) << "\n options: " << describe(all[i].options)
                      << "\n under " << m.name << ": " << describe(r)
                      << "\n under FE_TONEAREST: " << describe(nearest[i]);
    }
    EXPECT_EQ(mismatches, 0) << m.name;
    EXPECT_EQ(mode_changes, 0) << m.name;
  }
}

TEST(RoundingMode, CallerModeRestoredWhenTheCallThrows) {
  NearestOnExit restore;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  DoubleQuery q = generate({Family::planted_contact, QueryType::vertex_face}, 1, 0);
  for (const RoundingMode& m : kModes) {
    for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
      for (Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
        q.type = type;
        // Non-finite coordinate (last vertex, last coordinate: after any early stage).
        DoubleQuery bad = q;
        bad.v[7].z() = nan;
        ASSERT_EQ(std::fesetround(m.mode), 0);
        const unsigned control = predicates::raw_fp_control();
        EXPECT_THROW(ccd(bad, CcdOptions{1.0, 0.0, mode}), std::invalid_argument) << m.name;
        EXPECT_EQ(predicates::raw_fp_control(), control) << m.name << " (NaN coordinate)";
        EXPECT_EQ(std::fegetround(), m.mode) << m.name << " (NaN coordinate)";
        bad.v[7].z() = q.v[7].z();
        bad.v[0].x() = -inf;
        EXPECT_THROW(ccd(bad, CcdOptions{1.0, 0.0, mode}), std::invalid_argument) << m.name;
        EXPECT_EQ(std::fegetround(), m.mode) << m.name << " (infinite coordinate)";
        // Options outside their domain.
        EXPECT_THROW(ccd(q, CcdOptions{nan, 0.0, mode}), std::invalid_argument) << m.name;
        EXPECT_EQ(std::fegetround(), m.mode) << m.name << " (NaN t_max)";
        EXPECT_THROW(ccd(q, CcdOptions{1.0, -1.0, mode}), std::invalid_argument) << m.name;
        EXPECT_EQ(std::fegetround(), m.mode) << m.name << " (negative toi_width)";
        EXPECT_EQ(predicates::raw_fp_control(), control) << m.name << " (after every throw)";
        std::fesetround(FE_TONEAREST);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// (b) Thread safety

TEST(ThreadSafety, ConcurrentCallsGiveSequentialResults) {
  const auto& all = all_cases();
  std::vector<CcdResult> sequential(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) sequential[i] = ccd(all[i].query, all[i].options);

  // Four threads, each deciding every case, in different orders (forward, backward, strided),
  // and two of them under non-nearest rounding modes: the modes are per thread.
  constexpr int kThreads = 4;
  std::vector<std::vector<CcdResult>> results(kThreads, std::vector<CcdResult>(all.size()));
  std::vector<int> modes_after(kThreads, -1);
  std::vector<int> controls_kept(kThreads, 0);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      const int mode = t == 1 ? FE_UPWARD : (t == 3 ? FE_DOWNWARD : FE_TONEAREST);
      std::fesetround(mode);
      const unsigned control = predicates::raw_fp_control();
      ++ready;
      while (ready.load() < kThreads) std::this_thread::yield();  // start together
      const std::size_t n = all.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = t == 0 ? k : t == 1 ? n - 1 - k : (k * 7919 + t) % n;
        results[t][i] = ccd(all[i].query, all[i].options);
      }
      modes_after[t] = std::fegetround();
      controls_kept[t] = predicates::raw_fp_control() == control;
      std::fesetround(FE_TONEAREST);
    });
  }
  for (auto& th : threads) th.join();
  ASSERT_EQ(all.size() % 7919 != 0, true);  // the stride visits every index
  for (int t = 0; t < kThreads; ++t) {
    int mismatches = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
      if (!same(results[t][i], sequential[i]) && ++mismatches <= 5)
        ADD_FAILURE() << "thread " << t << ": " << describe(all[i].query)
                      << "\n concurrent: " << describe(results[t][i])
                      << "\n sequential: " << describe(sequential[i]);
    EXPECT_EQ(mismatches, 0) << "thread " << t;
    EXPECT_EQ(modes_after[t], t == 1 ? FE_UPWARD : (t == 3 ? FE_DOWNWARD : FE_TONEAREST));
    EXPECT_TRUE(controls_kept[t]) << "thread " << t << ": FP control register changed";
  }
}

// ---------------------------------------------------------------------------------------------
// (c) No contraction into FMA

/// a * b + c in one expression; noinline with runtime arguments, so that the compiler cannot
/// fold it and contraction (if enabled) would be applied here.
[[gnu::noinline]] double multiply_add(double a, double b, double c) { return a * b + c; }

TEST(FloatingPointContract, MultiplyAddIsNotFused) {
  // a * b = 1 - 2^-60 exactly; rounded to nearest it is 1, so a * b - 1 is 0 when the product
  // is rounded first, and -2^-60 when fused.
  const double a = 1 + 0x1p-30, b = 1 - 0x1p-30;
  EXPECT_EQ(multiply_add(a, b, -1.0), 0.0)
      << "a * b + c was contracted into an FMA: build with -ffp-contract=off";
  // std::fma itself gives the fused value (checks the premise of the test).
  EXPECT_EQ(std::fma(a, b, -1.0), -0x1p-60);
}

TEST(FloatingPointContract, SemistaticDeterminantIsNotFused) {
  // det3 computes m_x = w_y u_z - w_z u_y with both products rounded. With w = (0, a, a) and
  // u = (0, b, b), m_x = a * b - a * b is 0 when both products are rounded, and -2^-60 when
  // either product is fused with the subtraction (whichever one the compiler picks); m_y and
  // m_z are 0 (zero x components). With v = (1, 0, 0) the determinant is m_x.
  volatile double va = 1 + 0x1p-30, vb = 1 - 0x1p-30;  // runtime values
  const double a = va, b = vb;
  const Eigen::Vector3d v(1, 0, 0), w(0, a, a), u(0, b, b);
  EXPECT_EQ(filters::semistatic::det3(v, w, u), 0.0)
      << "the semi-static determinant was contracted into FMAs";
}

}  // namespace
}  // namespace exactccd::test
