// Extreme magnitudes: the default path (Mode::filtered) against the exact path (Mode::exact) on
// queries whose coordinates span the whole double range, from 2^-1074 (the smallest subnormal)
// to DBL_MAX: every scale 2^k, k in [-1074, 1023]; magnitudes mixed within one query (per-axis
// scales, tiny primitives against huge ones); subnormal coordinates next to normal ones;
// coordinates near +-DBL_MAX whose differences overflow.
//
// Every query is checked for: the same verdict and the identical tightest TOI pair at
// toi_width = 0; a coarse toi_width (both paths) giving an enclosure of the exact path's
// tightest pair no wider than asked; t_max below 1 (tightest and coarse). Where an answer is
// known independently of both paths it is checked too:
//  - a query rescaled exactly (a power of two per axis, no bit lost below 2^-1074) has the
//    answer of the query it came from (a linear map changes no contact time);
//  - a layered query (random_queries.hpp) comes with its answer computed in rationals.
// Where rescaling rounds (subnormals lose bits) the exact path on the rounded doubles decides.
// Each test prints how many queries collided and asserts a minimum, so that it cannot pass on
// trivial misses alone.
//
// EXACTCCD_TEST_SEED overrides the seed, EXACTCCD_TEST_SCALE multiplies the query counts (the
// sweep over every exponent runs at least once whatever the scale).
#include <gtest/gtest.h>

#include <cfloat>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "corpus/random_queries.hpp"
#include "tests/test_scale.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

constexpr std::uint64_t kDefaultSeed = 0xe47e3e3a9ULL;
constexpr std::size_t kMaxReported = 10;

/// What one test saw, and its first failures.
struct Tally {
  std::uint64_t queries = 0, contacts = 0;
  std::uint64_t independent = 0;  ///< queries with an answer known independently of both paths
  std::uint64_t rounded = 0;      ///< rescaled with rounding: only default versus exact
  std::uint64_t coarse_checks = 0, t_max_checks = 0;
  std::uint64_t failures = 0;
  std::vector<std::string> reports;
  double slowest_seconds = 0;  ///< the slowest query (all its checks), for the report
  std::string slowest;

  void fail(std::string report) {
    ++failures;
    if (reports.size() < kMaxReported) reports.push_back(std::move(report));
  }
};

/// The answer a query must have, where known independently of the paths under test.
struct Truth {
  /// The query was rescaled exactly from this one (decided here by the exact path: its
  /// coordinates have ordinary magnitudes, and scaling changes no answer).
  const DoubleQuery* original = nullptr;
  /// The query was built with this answer.
  const QueryWithAnswer* built = nullptr;

  std::string describe() const {
    std::string s;
    if (original) s += "\n rescaled from:" + random_queries::describe(*original);
    if (built)
      s += "\n built answer: " +
           (built->collides ? "collides at t* = " + built->toi.get_str() : std::string("none"));
    return s;
  }
};

/// [r.toi_lo, r.toi_hi] is the tightest pair of doubles around t: [t, t] when t is a double,
/// else two consecutive doubles strictly around it.
bool tightest_around(const CcdResult& r, const mpq_class& t) {
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  if (mpq_class(t.get_d()) == t) return lo == t && hi == t;
  return lo < t && t < hi && is_tightest_pair(r.toi_lo, r.toi_hi);
}

/// `r`, the exact path's tightest answer under `o` (toi_width = 0), against the known answer.
std::string check_truth(const CcdResult& r, const Truth& truth, const CcdOptions& o) {
  if (truth.original) {
    const CcdResult want = ccd(*truth.original, with_mode(o, Mode::exact));
    if (std::string w = check_tight(r, want); !w.empty())
      return "answer differs from the unscaled query's " + describe(want) + ": " + w;
  }
  if (truth.built) {
    const bool collides = truth.built->collides && truth.built->toi <= mpq_class(o.t_max);
    if (r.collides != collides) return "verdict differs from the built answer";
    if (collides && !tightest_around(r, truth.built->toi))
      return "TOI is not the tightest pair around the built t*";
  }
  return {};
}

/// Coarse widths, from the smallest subnormal (below one ulp of any t* > 0) to DBL_MAX.
double random_coarse_width(std::mt19937_64& rng) {
  static constexpr double kWidths[] = {0x1p-1074, 0x1p-60, 1e-9,   1e-3,
                                       0.1,       0.5,     1.0,    DBL_MAX};
  return kWidths[detail::uniform_int(rng, 0, 7)];
}

/// t_max in (0, 1): the contact time or just before it, a subnormal or tiny one, or random.
double random_t_max(std::mt19937_64& rng, const CcdResult& whole) {
  double t = 0.5;
  switch (detail::uniform_int(rng, 0, 4)) {
    case 0: t = whole.collides ? whole.toi_hi : 0.5; break;
    case 1: t = whole.collides ? std::nextafter(whole.toi_lo, 0.0) : 0x1p-20; break;
    case 2: t = whole.collides ? 0.5 * whole.toi_lo : 0.25; break;
    case 3: t = std::ldexp(1.0, detail::uniform_int(rng, -1074, -900)); break;
    default: t = std::uniform_real_distribution<double>(0x1p-30, 1.0)(rng); break;
  }
  return t > 0 && t < 1 ? t : 0.5;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Every check on one query (see the file comment). `rng` picks the options.
void check_query_options(const std::string& where, const DoubleQuery& q, const Truth& truth,
                         std::mt19937_64& rng, Tally& tally) {
  const auto fail = [&](const std::string& what, const CcdOptions& o, const CcdResult& d,
                        const CcdResult& e) {
    tally.fail(where + ": " + what + "\n query:" + describe(q) + "\n options: " + describe(o) +
               "\n default: " + describe(d) + "\n exact:   " + describe(e) + truth.describe());
  };
  ++tally.queries;
  if (truth.original || truth.built) ++tally.independent;

  const CcdOptions whole;
  const CcdResult d = ccd(q, whole);
  const CcdResult e = ccd(q, with_mode(whole, Mode::exact));
  if (e.collides) ++tally.contacts;
  if (std::string w = check_tight(d, e); !w.empty()) return fail(w, whole, d, e);
  if (e.decided_by != Stage::exact)
    return fail("exact mode not decided by Stage::exact", whole, d, e);
  if (std::string w = check_truth(e, truth, whole); !w.empty()) return fail(w, whole, d, e);

  if (e.collides) {
    CcdOptions coarse;
    coarse.toi_width = random_coarse_width(rng);
    const CcdResult dc = ccd(q, coarse);
    const CcdResult ec = ccd(q, with_mode(coarse, Mode::exact));
    ++tally.coarse_checks;
    if (std::string w = check_coarse_toi(dc, e, coarse.toi_width); !w.empty())
      return fail(w, coarse, dc, e);
    if (std::string w = check_coarse_toi(ec, e, coarse.toi_width); !w.empty())
      return fail("exact mode: " + w, coarse, ec, e);
  }

  // t_max below 1, at toi_width = 0 or coarse.
  CcdOptions tight;
  tight.t_max = random_t_max(rng, e);
  CcdOptions partial = tight;
  if (detail::coin(rng)) partial.toi_width = random_coarse_width(rng);
  const CcdResult ep = ccd(q, with_mode(tight, Mode::exact));
  const CcdResult dp = ccd(q, partial);
  ++tally.t_max_checks;
  if (std::string w = check_truth(ep, truth, tight); !w.empty())
    return fail("t_max < 1, exact path at toi_width 0: " + w, partial, dp, ep);
  if (partial.toi_width == 0) {
    if (std::string w = check_tight(dp, ep); !w.empty())
      return fail("t_max < 1: " + w, partial, dp, ep);
  } else if (dp.collides != ep.collides) {
    return fail("t_max < 1, coarse toi_width: verdict differs", partial, dp, ep);
  } else if (ep.collides) {
    const CcdResult epc = ccd(q, with_mode(partial, Mode::exact));
    if (std::string w = check_coarse_toi(dp, ep, partial.toi_width); !w.empty())
      return fail("t_max < 1: " + w, partial, dp, ep);
    if (std::string w = check_coarse_toi(epc, ep, partial.toi_width); !w.empty())
      return fail("t_max < 1, exact mode: " + w, partial, epc, ep);
  }
}

/// check_query_options, timed (the slowest query is reported, never asserted on).
/// EXACTCCD_TEST_VERBOSE prints every query before it is checked, and its time.
void check_query(const std::string& where, const DoubleQuery& q, const Truth& truth,
                 std::mt19937_64& rng, Tally& tally) {
  static const bool verbose = std::getenv("EXACTCCD_TEST_VERBOSE") != nullptr;
  if (verbose) {
    std::printf("[ query    ] %s%s\n", where.c_str(), describe(q).c_str());
    std::fflush(stdout);
  }
  const auto start = std::chrono::steady_clock::now();
  check_query_options(where, q, truth, rng, tally);
  const double seconds = seconds_since(start);
  if (verbose) std::printf("[ took     ] %.3f s\n", seconds);
  if (seconds > tally.slowest_seconds) {
    tally.slowest_seconds = seconds;
    tally.slowest = where;
  }
}

/// Prints the tally and its failures; asserts no failure and at least `min_contacts` contacts.
void finish(const char* name, const Tally& t, std::chrono::steady_clock::time_point start,
            std::uint64_t min_contacts) {
  std::printf(
      "[ tally    ] %s: %llu queries, %llu collide, %llu with an independent answer, %llu "
      "rounded, %llu coarse-width and %llu t_max < 1 checks, %.2f s\n",
      name, static_cast<unsigned long long>(t.queries),
      static_cast<unsigned long long>(t.contacts), static_cast<unsigned long long>(t.independent),
      static_cast<unsigned long long>(t.rounded), static_cast<unsigned long long>(t.coarse_checks),
      static_cast<unsigned long long>(t.t_max_checks), seconds_since(start));
  std::printf("[ tally    ] slowest query %.3f s: %s\n", t.slowest_seconds, t.slowest.c_str());
  std::fflush(stdout);
  for (const std::string& r : t.reports) ADD_FAILURE() << r;
  EXPECT_EQ(t.failures, 0u);
  EXPECT_GE(t.contacts, min_contacts) << name << ": too few contacts, the test is too weak";
}

std::uint64_t seed() {
  static const std::uint64_t s = [] {
    const std::uint64_t v = seed_from_environment(kDefaultSeed);
    std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu EXACTCCD_TEST_SCALE=%g\n",
                static_cast<unsigned long long>(v), scale_from_environment());
    return v;
  }();
  return s;
}

/// The per-query random engine of query `index` of test `test`.
std::mt19937_64 query_rng(std::uint64_t test, std::uint64_t index) {
  return std::mt19937_64(mix64(mix64(seed() ^ mix64(test)) ^ index));
}

/// A base query of ordinary magnitude from the generators of the differential test (planted
/// contacts, degenerate primitives, coplanar motion, ... of both types; not the wide exponent
/// spreads, and before their power-of-two scaling), to be rescaled.
DoubleQuery base_query(std::mt19937_64& rng, QueryType type) {
  static const std::vector<Family> kOrdinary = [] {
    std::vector<Family> out;
    for (Family f : kAllFamilies)
      if (ordinary_magnitudes(f)) out.push_back(f);
    return out;
  }();
  const Family family =
      kOrdinary[detail::uniform_int(rng, 0, static_cast<int>(kOrdinary.size()) - 1)];
  return generate_unscaled(Generator{family, type}, rng(), 0);
}

/// A base query from the generators that plant contacts and degeneracies (most collide).
DoubleQuery contact_rich_base_query(std::mt19937_64& rng, QueryType type) {
  static constexpr Family kFamilies[] = {Family::planted_contact, Family::contact_at_endpoints,
                                         Family::degenerate_primitives,
                                         Family::coplanar_throughout};
  // One draw per statement (argument order is unspecified); the seed first, as GCC evaluated
  // the former one-call form.
  const std::uint64_t query_seed = rng();
  const Family family = kFamilies[detail::uniform_int(rng, 0, 3)];
  return generate_unscaled(Generator{family, type}, query_seed, 0);
}

/// Rescales `base` with `rescale` (which returns whether it was exact) and checks the result:
/// against the base's answer when exact, default versus exact otherwise.
template <class Rescale>
void check_rescaled(const std::string& where, const DoubleQuery& base, Rescale&& rescale,
                    std::mt19937_64& rng, Tally& tally) {
  DoubleQuery q = base;
  const bool exact = rescale(&q);
  if (!exact) ++tally.rounded;
  Truth truth;
  if (exact) truth.original = &base;
  check_query(where, q, truth, rng, tally);
}

std::string name_of(QueryType type) { return type == QueryType::vertex_face ? "vf" : "ee"; }

/// Runs f(where, type, rng) for `count` queries of one category of a test, types alternating,
/// each with its own random engine (query i can be replayed alone).
template <class F>
void for_each_query(std::uint64_t test, std::uint64_t category, std::uint64_t count, F&& f) {
  for (std::uint64_t i = 0; i < count; ++i) {
    std::mt19937_64 rng = query_rng(test * 16 + category, i);
    const QueryType type = i % 2 == 0 ? QueryType::vertex_face : QueryType::edge_edge;
    f(name_of(type) + " #" + std::to_string(category) + "." + std::to_string(i), type, rng);
  }
}

// ---------------------------------------------------------------------------------------------
// Every scale 2^k

// The whole query scaled by one power of two so that its largest coordinate lies in
// [2^k, 2^(k+1)), for every k in [-1074, 1023], both types at scale 1 (alternating below):
// exact down to k = -1022 + 52 for full-precision queries, and further for the generators'
// small dyadics; rounded (to subnormals, or to 0) below. Contacts are counted separately at
// the bottom (k < -1022), at the top (k >= 1000) and in between; every other exponent takes its
// queries from the generators that plant contacts.
TEST(ExtremeMagnitude, EveryScaleFromSubnormalToOverflow) {
  const auto start = std::chrono::steady_clock::now();
  Tally bottom, middle, top;
  const std::uint64_t per_exponent = scaled_count(2);  // at least one
  for (int k = -1074; k <= 1023; ++k)
    for (std::uint64_t j = 0; j < per_exponent; ++j) {
      const std::uint64_t index = static_cast<std::uint64_t>(k + 1074) * per_exponent + j;
      std::mt19937_64 rng = query_rng(1, index);
      const QueryType type = (k + j) % 2 == 0 ? QueryType::vertex_face : QueryType::edge_edge;
      // Every other exponent from the contact-rich generators, so that each range of
      // exponents sees contacts.
      const DoubleQuery base =
          k % 2 == 0 ? contact_rich_base_query(rng, type) : base_query(rng, type);
      check_rescaled(name_of(type) + " 2^" + std::to_string(k) + " #" + std::to_string(index),
                     base, [k](DoubleQuery* q) { return place_query(q, k); }, rng,
                     k < -1022 ? bottom : (k >= 1000 ? top : middle));
    }
  finish("every scale, 2^-1074 .. 2^-1023", bottom, start, bottom.queries / 5);
  finish("every scale, 2^-1022 .. 2^999", middle, start, middle.queries / 5);
  finish("every scale, 2^1000 .. 2^1023", top, start, top.queries / 5);
}

// The same at random scales, more of them near the ends of the range.
TEST(ExtremeMagnitude, RandomScales) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  for_each_query(2, 0, scaled_count(2000), [&](const std::string& where, QueryType type,
                                         std::mt19937_64& rng) {
    const DoubleQuery base = base_query(rng, type);
    const int k = detail::random_exponent(rng);
    check_rescaled(where + " 2^" + std::to_string(k), base,
                   [k](DoubleQuery* q) { return place_query(q, k); }, rng, tally);
  });
  finish("random scales", tally, start, tally.queries / 5);
}

// ---------------------------------------------------------------------------------------------
// Mixed magnitudes within one query

// Each axis scaled by its own power of two (a linear map: no answer changes): x near 2^-1000,
// z near 2^1000, and so on; one query in four spans the whole range (one axis at the top, one
// near the bottom, one near 1).
TEST(ExtremeMagnitude, PerAxisScales) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  std::uint64_t i = 0;
  for_each_query(3, 0, scaled_count(1000), [&](const std::string& where, QueryType type,
                                         std::mt19937_64& rng) {
    const DoubleQuery base = base_query(rng, type);
    std::array<int, 3> top;
    for (int& t : top) t = detail::random_exponent(rng);
    if (i++ % 4 == 0)
      top = {1023, detail::uniform_int(rng, -1074, -954), detail::uniform_int(rng, -4, 4)};
    std::shuffle(top.begin(), top.end(), rng);
    check_rescaled(where + " 2^(" + std::to_string(top[0]) + ", " + std::to_string(top[1]) +
                       ", " + std::to_string(top[2]) + ")",
                   base, [&top](DoubleQuery* q) { return place_axes(q, top); }, rng, tally);
  });
  finish("per-axis scales", tally, start, tally.queries / 5);
}

// Layered queries (random_queries.hpp) with their exact answers: a needle through a huge
// triangle, a huge motion through a tiny one, a tiny edge across a huge one, contacts on edges
// and at vertices, one-ulp misses, contact times far below 2^-1074 or a hair below 1.
TEST(ExtremeMagnitude, LayeredQueriesHaveTheirBuiltAnswers) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  std::uint64_t built_contacts = 0;
  for_each_query(4, 0, scaled_count(2000), [&](const std::string& where, QueryType type,
                                         std::mt19937_64& rng) {
    const QueryWithAnswer built =
        type == QueryType::vertex_face ? layered_vertex_face(rng) : layered_edge_edge(rng);
    built_contacts += built.collides;
    Truth truth;
    truth.built = &built;
    check_query(where + " layered", built.query, truth, rng, tally);
  });
  std::printf("[ info     ] %llu of %llu built to collide\n",
              static_cast<unsigned long long>(built_contacts),
              static_cast<unsigned long long>(tally.queries));
  finish("layered", tally, start, tally.queries / 4);
}

// Random coordinates from a palette of two or three exponents per query over the whole range
// (zeros too): no structure, the exact path decides. These are the slowest queries for the
// exact path (exponents spread over +-1000 in one product: up to seconds), hence few. Contacts
// are rare among them, so near-degenerate ones are added: a layered contact with one
// coordinate moved by one ulp.
TEST(ExtremeMagnitude, RandomMixedMagnitudes) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  for_each_query(5, 0, scaled_count(40), [&](const std::string& where, QueryType type,
                                       std::mt19937_64& rng) {
    std::vector<int> palette(detail::uniform_int(rng, 2, 3));
    for (int& e : palette) e = detail::random_exponent(rng);
    check_query(where + " palette", random_mixed_magnitude_query(rng, type, palette), {}, rng,
                tally);
  });
  for_each_query(5, 1, scaled_count(300), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    DoubleQuery q =
        (type == QueryType::vertex_face ? layered_vertex_face(rng) : layered_edge_edge(rng)).query;
    double& c = q.v[detail::uniform_int(rng, 0, 7)][detail::uniform_int(rng, 0, 2)];
    const double moved = std::nextafter(c, detail::coin(rng) ? HUGE_VAL : -HUGE_VAL);
    if (std::isfinite(moved)) c = moved;
    check_query(where + " layered one ulp off", q, {}, rng, tally);
  });
  finish("random mixed magnitudes", tally, start, tally.queries / 5);
}

// ---------------------------------------------------------------------------------------------
// Subnormal coordinates

/// A top exponent for place_axes / place_query in the subnormal range.
int subnormal_exponent(std::mt19937_64& rng) { return detail::uniform_int(rng, -1074, -1023); }

/// ... among the smallest normal exponents, or near 1.
int normal_exponent(std::mt19937_64& rng) {
  return detail::coin(rng) ? detail::uniform_int(rng, -1022, -1000)
                           : detail::uniform_int(rng, -2, 2);
}

// Subnormals next to normal values: each axis placed in the subnormal range or among normal
// values (base queries with planted contacts and degeneracies); the whole query placed as low
// as it stays exact (subnormal, or its smallest coordinates subnormal);
// near-degenerate at the bottom of the range (placed subnormal, then moved by a few ulps of
// 2^-1074); random palettes of subnormal and normal exponents (slow in the exact path: few).
TEST(ExtremeMagnitude, SubnormalCoordinates) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  for_each_query(6, 0, scaled_count(600), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    std::array<int, 3> top;
    for (int& t : top) t = detail::coin(rng) ? subnormal_exponent(rng) : normal_exponent(rng);
    top[detail::uniform_int(rng, 0, 2)] = subnormal_exponent(rng);
    const DoubleQuery base = base_query(rng, type);
    check_rescaled(where + " axes", base, [&top](DoubleQuery* q) { return place_axes(q, top); },
                   rng, tally);
  });
  for_each_query(6, 1, scaled_count(300), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    // As low as keeps every bit: all subnormal where the base's digits fit below 2^-1022,
    // else its smallest coordinates subnormal; rounded where even that does not fit.
    const DoubleQuery base = base_query(rng, type);
    const int lowest = lowest_exact_top(base);
    const int top = lowest <= -1023  ? detail::uniform_int(rng, lowest, -1023)
                    : lowest <= -960 ? lowest
                                     : detail::uniform_int(rng, -1040, -1023);
    check_rescaled(where + " whole", base, [top](DoubleQuery* q) { return place_query(q, top); },
                   rng, tally);
  });
  for_each_query(6, 2, scaled_count(300), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    DoubleQuery q = base_query(rng, type);
    place_query(&q, detail::uniform_int(rng, -1030, -1023));
    detail::perturb_ulps(rng, q.v);
    check_query(where + " ulps off", q, {}, rng, tally);
  });
  for_each_query(6, 3, scaled_count(60), [&](const std::string& where, QueryType type,
                                       std::mt19937_64& rng) {
    const std::vector<int> palette{subnormal_exponent(rng), normal_exponent(rng),
                                   subnormal_exponent(rng)};
    check_query(where + " palette", random_mixed_magnitude_query(rng, type, palette), {}, rng,
                tally);
  });
  finish("subnormal", tally, start, tally.queries / 5);
}

// ---------------------------------------------------------------------------------------------
// Differences that overflow

/// Some coordinate difference on one axis overflows in double.
bool has_overflowing_difference(const DoubleQuery& q) {
  for (int k = 0; k < 3; ++k)
    for (const auto& a : q.v)
      for (const auto& b : q.v)
        if (std::isinf(a[k] - b[k])) return true;
  return false;
}

// Coordinates near +-DBL_MAX of both signs: b - a overflows to infinity in double, and the
// answer must still be exact. Base queries centred (each axis' extremes made opposite, where
// exact) and placed with the largest coordinate of the query (or of each axis) in
// [2^1023, DBL_MAX] (mostly) or a little lower; layered queries scaled up to the top; random
// coordinates near the top (slow in the exact path: few).
/// n, but at least `floor`: the share of overflowing queries checked below is a proportion,
/// which the few queries of a reduced-scale run (sanitizers) would not estimate reliably.

TEST(ExtremeMagnitude, OverflowingDifferences) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  std::uint64_t overflowing = 0;
  const auto top = [](std::mt19937_64& rng) {
    return detail::coin(rng, 4) ? detail::uniform_int(rng, 1019, 1022) : 1023;
  };
  for_each_query(7, 0, at_least(scaled_count(400), 80), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    DoubleQuery base = base_query(rng, type);
    center_axes(&base);
    const int t = top(rng);
    DoubleQuery q = base;
    place_query(&q, t);
    overflowing += has_overflowing_difference(q);
    check_rescaled(where + " whole", base, [t](DoubleQuery* p) { return place_query(p, t); },
                   rng, tally);
  });
  for_each_query(7, 1, at_least(scaled_count(400), 80), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    DoubleQuery base = base_query(rng, type);
    center_axes(&base);
    const std::array<int, 3> tops{top(rng), top(rng), top(rng)};
    DoubleQuery q = base;
    place_axes(&q, tops);
    overflowing += has_overflowing_difference(q);
    check_rescaled(where + " axes", base, [&tops](DoubleQuery* p) { return place_axes(p, tops); },
                   rng, tally);
  });
  for_each_query(7, 2, at_least(scaled_count(400), 80), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    QueryWithAnswer built =
        type == QueryType::vertex_face ? layered_vertex_face(rng) : layered_edge_edge(rng);
    // Each axis scaled up (exactly) until its largest coordinate is in [2^1023, DBL_MAX]: the
    // answer is kept.
    ASSERT_TRUE(place_axes(&built.query, {1023, 1023, 1023})) << where << ": scaling up rounded";
    overflowing += has_overflowing_difference(built.query);
    Truth truth;
    truth.built = &built;
    check_query(where + " layered", built.query, truth, rng, tally);
  });
  for_each_query(7, 3, at_least(scaled_count(150), 30), [&](const std::string& where, QueryType type,
                                        std::mt19937_64& rng) {
    const std::vector<int> palette{1023, top(rng), detail::uniform_int(rng, -4, 1023)};
    const DoubleQuery q = random_mixed_magnitude_query(rng, type, palette);
    overflowing += has_overflowing_difference(q);
    check_query(where + " palette", q, {}, rng, tally);
  });
  const std::uint64_t n = tally.queries;
  std::printf("[ info     ] %llu of %llu queries have a coordinate difference that overflows\n",
              static_cast<unsigned long long>(overflowing), static_cast<unsigned long long>(n));
  EXPECT_GE(overflowing, n / 2);  // about 65% at full scale
  finish("overflowing differences", tally, start, n / 5);
}

// Hand-built queries at the limits, with answers worked out by hand. M = DBL_MAX, m = 2^-1074
// (the smallest subnormal). Vertex-face: the triangle (-h, -h), (h, -h), (-h, h) (the closed
// region x >= -h, y >= -h, x + y <= 0) at height 0, and p falling through it along z; the
// z difference 2M overflows. Edge-edge: (-M, 0, 0)-(M, 0, 0) at rest, a second edge along y
// falling through z = 0 at t = 1/2.
TEST(ExtremeMagnitude, HandBuiltAtTheLimits) {
  const double M = std::numeric_limits<double>::max();
  const double m = std::numeric_limits<double>::denorm_min();
  const mpq_class qM(M), qm(m);
  struct Case {
    const char* what;
    DoubleQuery q;
    bool collides;
    mpq_class toi;
  };
  std::vector<Case> cases;
  const auto vf = [](Eigen::Vector3d p0, Eigen::Vector3d p1, double za0, double za1, double h) {
    DoubleQuery q;
    q.type = QueryType::vertex_face;
    q.v = {p0, {-h, -h, za0}, {h, -h, za0}, {-h, h, za0},
           p1, {-h, -h, za1}, {h, -h, za1}, {-h, h, za1}};
    return q;
  };
  const mpq_class half(1, 2);
  // p from z = M to z = -M crosses z = 0 at t = 1/2.
  cases.push_back({"inside the largest triangle",
                   vf({-M / 2, -M / 2, M}, {-M / 2, -M / 2, -M}, 0, 0, M), true, half});
  cases.push_back({"at a vertex", vf({M, -M, M}, {M, -M, -M}, 0, 0, M), true, half});
  cases.push_back({"on the hypotenuse at (0, 0)", vf({0, 0, M}, {0, 0, -M}, 0, 0, M), true, half});
  cases.push_back(
      {"on the hypotenuse at (m, -m)", vf({m, -m, M}, {m, -m, -M}, 0, 0, M), true, half});
  cases.push_back({"outside the hypotenuse at (m, m)", vf({m, m, M}, {m, m, -M}, 0, 0, M), false,
                   mpq_class(0)});
  {
    const double below = std::nextafter(-M / 2, -M);  // one ulp below the vertex (-M/2, -M/2)
    cases.push_back({"one ulp off a vertex",
                     vf({-M / 2, below, M}, {-M / 2, below, -M}, 0, 0, M / 2), false,
                     mpq_class(0)});
  }
  // The smallest triangle (h = m) and p from M to -M/2 through its hypotenuse: t* = 2/3.
  cases.push_back({"smallest triangle, huge motion", vf({0, 0, M}, {0, 0, -M / 2}, 0, 0, m), true,
                   mpq_class(2, 3)});
  // The triangle (h = 1) rises from -M to M, p stays at height m: (1 - t)(-M) + t M = m at
  // t* = (M + m) / 2M, just above 1/2 and not a double.
  cases.push_back({"rising triangle, p at height m", vf({0, 0, m}, {0, 0, m}, -M, M, 1.0), true,
                   mpq_class((qM + qm) / (2 * qM))});
  // p falls from m to -M: t* = m / (M + m) ~ 2^-2098, far below the smallest subnormal.
  cases.push_back({"contact time below 2^-1074", vf({0, 0, m}, {0, 0, -M}, 0, 0, 1.0), true,
                   mpq_class(qm / (qM + qm))});
  {
    DoubleQuery q;
    q.type = QueryType::edge_edge;
    q.v = {Eigen::Vector3d(-M, 0, 0), {M, 0, 0}, {0, -M, M}, {0, M, M},
           {-M, 0, 0},               {M, 0, 0}, {0, -M, -M}, {0, M, -M}};
    cases.push_back({"edges crossing at the origin", q, true, half});
    DoubleQuery r = q;  // the falling edge at x = M: touches the resting edge's end (M, 0, 0)
    for (int i : {2, 3, 6, 7}) r.v[i].x() = M;
    cases.push_back({"edge touching the other's end", r, true, half});
    DoubleQuery s = r;  // ... shortened to y >= m: misses y = 0
    s.v[2].y() = s.v[6].y() = m;
    cases.push_back({"edge missing the other's end by m", s, false, mpq_class(0)});
  }

  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(seed());
  std::uint64_t colliding = 0;
  for (const Case& c : cases) {
    QueryWithAnswer built{c.q, c.collides, c.toi};
    Truth truth;
    truth.built = &built;
    colliding += c.collides;
    // Several times: the coarse width and t_max are drawn at random.
    for (int repeat = 0; repeat < 8; ++repeat) check_query(c.what, c.q, truth, rng, tally);
  }
  finish("hand-built", tally, start, 8 * colliding);
}

}  // namespace
}  // namespace exactccd::test
