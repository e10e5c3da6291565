// The library owns its floating-point state (proofs/filters.md#fp-environment): whatever the
// caller's control register holds (any rounding mode, flush-to-zero, denormals-are-zero,
// unmasked exceptions, sticky flags), every entry point computes under the state the proofs
// assume and gives the caller's register back bit for bit, on return and on throw.
//
// The state is read and written here as the hardware holds it (MXCSR on x86-64), never through
// fegetround: glibc's fegetround reads the x87 control word on x86-64 and cannot see a mode or
// a flush-to-zero bit that leaked into MXCSR.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <cfenv>
#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/predicates/fp_environment.hpp"
#include "corpus/random_queries.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/discrete.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/scene.hpp"
#include "tests/fp_host/issue9_query.hpp"
#include "tests/test_scale.hpp"

#if defined(__x86_64__)

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

using predicates::raw_fp_control;
using predicates::set_raw_fp_control;

constexpr unsigned kFtz = 0x8000, kDaz = 0x0040, kMasks = 0x1f80, kFlags = 0x003f;
constexpr unsigned kRoundingBits[] = {0x0000, 0x2000, 0x4000, 0x6000};  // N, down, up, zero
constexpr unsigned kClean = kMasks;                                    // the power-on default
// Invalid, divide-by-zero and overflow unmasked: a simulator catching NaNs runs like this.
constexpr unsigned kTrapping = kMasks & ~(0x0080u | 0x0200u | 0x0400u);

/// Runs f with MXCSR = state and returns MXCSR as f left it; the test's own code runs clean.
unsigned run_under(unsigned state, const std::function<void()>& f) {
  set_raw_fp_control(state);
  try {
    f();
  } catch (...) {
    const unsigned after = raw_fp_control();
    set_raw_fp_control(kClean);
    (void)after;
    throw;
  }
  const unsigned after = raw_fp_control();
  set_raw_fp_control(kClean);
  return after;
}

/// Every state a host may run in: 4 rounding modes x FTZ x DAZ x (masked | trapping), each with
/// and without sticky flags already raised.
std::vector<unsigned> hostile_states() {
  std::vector<unsigned> out;
  for (unsigned rc : kRoundingBits)
    for (unsigned ftz : {0u, kFtz})
      for (unsigned daz : {0u, kDaz})
        for (unsigned masks : {kMasks, kTrapping})
          for (unsigned flags : {0u, kFlags & ~0x01u})  // a raised IE flag would trap at once
            out.push_back(rc | ftz | daz | masks | flags);
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same(const CcdResult& a, const CcdResult& b) {
  return a.collides == b.collides && same_bits(a.toi_lo, b.toi_lo) &&
         same_bits(a.toi_hi, b.toi_hi) && a.decided_by == b.decided_by;
}

/// Decides q under every `step`-th host state from `first`: each result must equal `clean` and
/// each call must give the register back. Counts the checks; reports the first mismatches.
void check_under_states(const DoubleQuery& q, const CcdOptions& options, const CcdResult& clean,
                        const std::vector<unsigned>& states, std::size_t first,
                        std::size_t step, std::size_t* checks, std::size_t* mismatches) {
  for (std::size_t s = first; s < states.size(); s += step) {
    CcdResult r;
    const unsigned after = run_under(states[s], [&] { r = ccd(q, options); });
    ++*checks;
    if ((after != states[s] || !same(r, clean)) && ++*mismatches <= 5)
      ADD_FAILURE() << std::hex << "MXCSR " << states[s] << " left " << after << ": "
                    << describe(q) << " clean " << describe(clean) << " got " << describe(r);
  }
}

TEST(FpEnvironment, IssueExampleUnderFlushToZeroAndDenormalsAreZero) {
  const VertexFaceQuery q = issue9_query();
  // The exact path (rationals, no floating point) is the independent reference; the issue's
  // report gives the same tightest pair.
  const CcdResult exact = exact_ccd(to_rational(q));
  ASSERT_TRUE(exact.collides);
  EXPECT_EQ(exact.toi_lo, 0x1.b48d9299e2cf1p-3);
  EXPECT_EQ(exact.toi_hi, 0x1.b48d9299e2cf2p-3);
  for (unsigned state : hostile_states()) {
    for (Mode mode : {Mode::filtered, Mode::exact}) {
      CcdResult r;
      const unsigned after = run_under(state, [&] { r = vertex_face_ccd(q, {1.0, 0.0, mode}); });
      EXPECT_EQ(after, state) << std::hex << "MXCSR " << state << " not restored";
      EXPECT_TRUE(r.collides) << std::hex << "MXCSR " << state;
      EXPECT_TRUE(same_bits(r.toi_lo, exact.toi_lo) && same_bits(r.toi_hi, exact.toi_hi))
          << std::hex << "MXCSR " << state << ": " << describe(r);
    }
  }
}

/// Random queries of every generator scaled by 2^k down to the subnormal range (where the
/// scaling is inexact the scaled doubles are simply other inputs): every result under every
/// hostile state equals the clean one, and the clean one equals the exact path's.
TEST(FpEnvironment, ScaledRandomQueriesEqualCleanResultsUnderEveryHostState) {
  const std::uint64_t seed = seed_from_environment(0xf7e5);
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n", static_cast<unsigned long long>(seed));
  const std::vector<unsigned> states = hostile_states();
  const std::uint64_t per_scale = scaled_count(2, scale_from_environment());
  std::size_t checks = 0, contacts = 0, mismatches = 0;
  for (int k = -1034; k <= 0; k += 47) {
    const double scale = std::ldexp(1.0, k);
    for (const Generator& g : all_generators()) {
      for (std::uint64_t i = 0; i < affordable_count(g, per_scale); ++i) {
        DoubleQuery q = generate(g, seed, i);
        for (Eigen::Vector3d& v : q.v) v *= scale;
        const CcdResult clean = ccd(q, CcdOptions{});
        const CcdResult exact = ccd(q, CcdOptions{1.0, 0.0, Mode::exact});
        ASSERT_EQ(clean.collides, exact.collides) << describe(q);
        if (clean.collides) {
          ++contacts;
          ASSERT_TRUE(same_bits(clean.toi_lo, exact.toi_lo) &&
                      same_bits(clean.toi_hi, exact.toi_hi))
              << describe(q);
        }
        // Every 8th state per query keeps the test short; over the queries all are covered.
        check_under_states(q, CcdOptions{}, clean, states,
                           (i + static_cast<std::size_t>(k + 1034)) % 8, 8, &checks,
                           &mismatches);
      }
    }
  }
  std::printf("%zu checks, %zu contacts\n", checks, contacts);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(contacts, 20u);  // the sweep must exercise contacts, not only culled misses
}

/// Minimum-separation CCD under every host state: its whole-step test rounds to nearest with a
/// proven error bound (proofs/min_separation.md#whole-step), relying on the entry's
/// round-to-nearest, no flush-to-zero and no denormals-are-zero; the search sets upward
/// rounding itself. Random queries of the families whose exact procedure is affordable, scaled
/// by 2^k down to 2^-600 with delta scaled alike: every result equals the clean one, the clean
/// one the exact path's, and the register is given back.
TEST(FpEnvironment, MinimumSeparationEqualsCleanResultsUnderEveryHostState) {
  const std::uint64_t seed = seed_from_environment(0x5e9a);
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n", static_cast<unsigned long long>(seed));
  const std::vector<unsigned> states = hostile_states();
  std::size_t checks = 0, within = 0, mismatches = 0;
  for (int k = -600; k <= 0; k += 150) {
    for (const Generator& g : all_generators()) {
      if (g.family == Family::wide_exponent_300 || g.family == Family::wide_exponent_1000 ||
          g.family == Family::huge_triangle_subnormal_motion)
        continue;  // the exact reference would dominate the test's time
      DoubleQuery q = generate(g, seed, static_cast<std::uint64_t>(k + 600));
      for (Eigen::Vector3d& v : q.v) v = std::ldexp(1.0, k) * v;
      CcdOptions options;
      options.min_separation = std::ldexp(1.0, k - 5);
      const CcdResult clean = ccd(q, options);
      const CcdResult exact = ccd(q, with_mode(options, Mode::exact));
      ASSERT_EQ(clean.collides, exact.collides) << describe(q);
      if (clean.collides) {
        ++within;
        ASSERT_TRUE(same_bits(clean.toi_lo, exact.toi_lo) &&
                    same_bits(clean.toi_hi, exact.toi_hi))
            << describe(q);
      }
      check_under_states(q, options, clean, states, static_cast<std::size_t>(k + 600) % 4, 4,
                         &checks, &mismatches);
    }
  }
  std::printf("%zu checks, %zu within delta\n", checks, within);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(within, 5u);  // the sweep must reach the search and the exact stages, not only culling
}

/// Every mode, both query types, and the rational API leave the state as found; a throwing
/// call does too.
TEST(FpEnvironment, StateRestoredOnReturnAndOnThrowForEveryEntryPoint) {
  const VertexFaceQuery vf = issue9_query();
  EdgeEdgeQuery ee;
  ee.ea0_t0 = {0, 0, -1}, ee.ea1_t0 = {0, 0, 1}, ee.eb0_t0 = {-1, 1, 0}, ee.eb1_t0 = {1, 1, 0};
  ee.ea0_t1 = ee.ea0_t0, ee.ea1_t1 = ee.ea1_t0, ee.eb0_t1 = {-1, -1, 0}, ee.eb1_t1 = {1, -1, 0};
  const RationalQuery rq = to_rational(vf);
  VertexFaceQuery nan_query = vf;
  nan_query.p_t1.x() = std::nan("");
  for (unsigned state : hostile_states()) {
    for (Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
      EXPECT_EQ(run_under(state, [&] { vertex_face_ccd(vf, {1.0, 0.0, mode}); }), state);
      EXPECT_EQ(run_under(state, [&] { edge_edge_ccd(ee, {0.75, 1e-3, mode}); }), state);
    }
    EXPECT_EQ(run_under(state, [&] { exact_ccd(rq); }), state);
    // Throws: the register is read inside run_under before it rethrows.
    set_raw_fp_control(state);
    bool threw = false;
    try {
      vertex_face_ccd(nan_query);
    } catch (const std::invalid_argument&) {
      threw = true;
    }
    const unsigned after_throw = raw_fp_control();
    set_raw_fp_control(kClean);
    EXPECT_TRUE(threw);
    EXPECT_EQ(after_throw, state) << std::hex << "after a throw, MXCSR " << state;
  }
}

/// A two-mesh scene at the bottom of the normal range, where the boxes' comparisons and the
/// time-window culls meet subnormal differences: the scene's answers under FTZ|DAZ, from inside
/// a TBB arena created under that state (its workers inherit it), equal the clean answers.
TEST(FpEnvironment, SceneAndDiscreteUnderHostileStateFromInsideTheHostsArena) {
  const double s = 0x1p-1050;  // coordinates k * 2^-1050 are subnormal
  Positions sheet(4, 3), body_start(3, 3), body_end(3, 3);
  sheet << 0, 0, 0, 64 * s, 0, 0, 0, 64 * s, 0, 64 * s, 64 * s, 0;
  Triangles sheet_tris(2, 3);
  sheet_tris << 0, 1, 2, 1, 3, 2;
  body_start << 8 * s, 8 * s, 16 * s, 24 * s, 8 * s, 16 * s, 8 * s, 24 * s, 16 * s;
  body_end << 8 * s, 8 * s, -16 * s, 24 * s, 8 * s, -16 * s, 8 * s, 24 * s, -16 * s;
  Triangles body_tris(1, 3);
  body_tris << 0, 1, 2;

  Scene scene;
  scene.add_static_mesh(sheet, sheet_tris);
  const MeshId body = scene.add_mesh(body_start, body_tris);
  scene.set_motion(body, body_start, body_end);
  SceneOptions options;
  options.max_threads = 0;  // the caller's arena

  const SceneResult clean = scene.find_contacts(options);
  const EarliestContact clean_first = scene.earliest_contact(options);
  const std::vector<TrianglePair> clean_half = intersecting_triangle_pairs(scene, 0.5);
  ASSERT_FALSE(clean.contacts.empty());
  ASSERT_TRUE(clean_first.collides);
  ASSERT_FALSE(clean_half.empty());

  for (unsigned state : {kClean | kFtz | kDaz, 0x6000u | kFtz | kDaz | kTrapping}) {
    SceneResult r;
    EarliestContact first;
    std::vector<TrianglePair> half;
    unsigned after = 0;
    set_raw_fp_control(state);
    {
      tbb::task_arena arena(2);  // captures the hostile state for its workers
      arena.execute([&] {
        r = scene.find_contacts(options);
        first = scene.earliest_contact(options);
        half = intersecting_triangle_pairs(scene, 0.5);
      });
    }
    after = raw_fp_control();
    set_raw_fp_control(kClean);
    EXPECT_EQ(after, state);
    ASSERT_EQ(r.contacts.size(), clean.contacts.size()) << std::hex << state;
    for (std::size_t i = 0; i < r.contacts.size(); ++i) {
      EXPECT_TRUE(r.contacts[i].pair == clean.contacts[i].pair);
      EXPECT_TRUE(same_bits(r.contacts[i].toi_lo, clean.contacts[i].toi_lo));
      EXPECT_TRUE(same_bits(r.contacts[i].toi_hi, clean.contacts[i].toi_hi));
    }
    EXPECT_EQ(first.collides, clean_first.collides);
    EXPECT_TRUE(same_bits(first.contact.toi_lo, clean_first.contact.toi_lo));
    EXPECT_EQ(half.size(), clean_half.size());
  }
}

/// The x87 unit: the exact stage's wide-range interval filter computes its bounds in long double
/// (polynomials wider than 320 bits: the wide-exponent generators). A caller's x87 control word
/// with exceptions unmasked must not trap there, one with single precision and rounding toward
/// zero must not loosen the bounds, and both must come back unchanged.
TEST(FpEnvironment, X87ControlWordUnmaskedDoesNotTrapAndIsRestored) {
  const std::uint16_t trapping = 0x037f & ~(0x01 | 0x04 | 0x08);  // IM, ZM, OM cleared
  const std::uint16_t chopping_single = 0x0c7f;                     // RC toward zero, PC 24 bits
  std::uint16_t saved = 0, after = 0;
  asm volatile("fnstcw %0" : "=m"(saved));
  std::size_t wide_exact = 0;
  const std::uint64_t seed = seed_from_environment(0x87);
  for (const Generator& g : all_generators()) {
    const bool wide = g.name().find("wide_exponent") != std::string::npos;
    for (std::uint64_t i = 0; i < affordable_count(g, scaled_count(40, scale_from_environment()));
         ++i) {
      const DoubleQuery q = generate(g, seed, i);
      for (const Mode mode : {Mode::filtered, Mode::exact}) {
        const CcdOptions options = with_mode(CcdOptions{}, mode);
        const CcdResult clean = ccd(q, options);
        for (const std::uint16_t hostile : {trapping, chopping_single}) {
          asm volatile("fldcw %0" : : "m"(hostile));
          const CcdResult r = ccd(q, options);
          asm volatile("fnstcw %0" : "=m"(after));
          asm volatile("fldcw %0" : : "m"(saved));
          EXPECT_EQ(after, hostile);
          EXPECT_TRUE(same(r, clean)) << describe(q);
        }
        if (wide && clean.decided_by == Stage::exact) ++wide_exact;
      }
    }
  }
  EXPECT_GT(wide_exact, 0u);  // the wide-range filter actually ran
}

}  // namespace
}  // namespace exactccd::test

#else
TEST(FpEnvironment, OnlyOnX86_64) { GTEST_SKIP() << "the register-level tests read MXCSR"; }
#endif
