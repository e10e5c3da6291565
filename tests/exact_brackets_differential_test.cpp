// The exact stage at double brackets (exact/stages/algebraic_at_doubles.hpp: integer Bernstein
// coefficients, common factors, dyadic refinement) against the rational path it replaced and
// keeps as the reference (exact/reference/exact_ccd.hpp: GMP rationals and Sturm sequences), called
// directly, below the public API: the same verdict and the identical tightest TOI pair, and a
// coarse toi_width enclosure holding the reference's contact time, with t_max < 1 on one query
// in four. Random and adversarial generators (corpus/random_queries.hpp, every family and
// power-of-two scalings), the shipped degenerate suite, the sample and scene queries.
// EXACTCCD_TEST_SEED / EXACTCCD_TEST_SCALE as in differential_test.
// PROOF: proofs/exact_ccd.md#exact-at-double-brackets
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>

#include "corpus/random_queries.hpp"
#include "exact/stages/algebraic_at_doubles.hpp"
#include "exact/reference/exact_ccd.hpp"
#include "exactccd/query_file.hpp"
#include "test_support.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kDefaultSeed = 0xb4ac7e75ULL;

struct Tally {
  std::uint64_t queries = 0, collisions = 0, unresolved = 0, failures = 0;
  Tally& operator+=(const Tally& o) {
    queries += o.queries;
    collisions += o.collisions;
    unresolved += o.unresolved;
    failures += o.failures;
    return *this;
  }
};

class FailureLog {
 public:
  void add(const std::string& what) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (++count_ <= 10) std::printf("  MISMATCH %s\n", what.c_str());
  }
  std::uint64_t count() const { return count_; }

 private:
  std::mutex mutex_;
  std::uint64_t count_ = 0;
};

std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string describe(const CcdResult& r) {
  return r.collides ? "contact [" + hex(r.toi_lo) + ", " + hex(r.toi_hi) + "]" : "no contact";
}

std::optional<CcdResult> at_doubles(const DoubleQuery& q, const CcdOptions& o) {
  return q.type == QueryType::vertex_face ? exact::vertex_face_ccd_at_doubles(q.vertex_face(), o)
                                          : exact::edge_edge_ccd_at_doubles(q.edge_edge(), o);
}

CcdResult reference(const DoubleQuery& q, const CcdOptions& o) {
  return q.type == QueryType::vertex_face
             ? exact::vertex_face_ccd_exact(to_rational(q.vertex_face()), o)
             : exact::edge_edge_ccd_exact(to_rational(q.edge_edge()), o);
}

/// Compares the stage with the reference on q; returns "" or what differs.
std::string compare(const DoubleQuery& q, double t_max, Tally& tally) {
  ++tally.queries;
  CcdOptions o;
  o.t_max = t_max;
  o.toi_width = 0;
  const std::uint64_t unresolved_before = exact::unresolved_at_doubles_in_this_thread();
  const std::optional<CcdResult> fast = at_doubles(q, o);
  if (!fast) {
    ++tally.unresolved;
    if (exact::unresolved_at_doubles_in_this_thread() != unresolved_before + 1)
      return "nullopt without counting an unresolved query";
    return "";
  }
  const CcdResult ref = reference(q, o);
  if (fast->decided_by != Stage::exact) return "stage not exact";
  if (fast->collides != ref.collides || (ref.collides && (fast->toi_lo != ref.toi_lo ||
                                                          fast->toi_hi != ref.toi_hi)))
    return "t_max " + hex(t_max) + ": stage " + describe(*fast) + ", reference " + describe(ref);
  if (ref.collides) ++tally.collisions;
  if (!ref.collides) return "";
  // A coarse width: an enclosure of at most that width (or the tightest) holding the contact.
  CcdOptions coarse = o;
  coarse.toi_width = 0x1p-10;
  const std::optional<CcdResult> wide = at_doubles(q, coarse);
  if (!wide || !wide->collides) return "coarse width: no contact";
  const bool holds = wide->toi_lo <= ref.toi_lo && ref.toi_hi <= wide->toi_hi;
  const bool narrow = wide->toi_hi - wide->toi_lo <= coarse.toi_width ||
                      (wide->toi_lo == ref.toi_lo && wide->toi_hi == ref.toi_hi);
  if (!holds || !narrow)
    return "coarse width: " + describe(*wide) + " against tightest " + describe(ref);
  return "";
}

std::string point_rows(const DoubleQuery& q) {
  std::string s;
  for (const auto& p : q.v) s += "\n    " + hex(p.x()) + " " + hex(p.y()) + " " + hex(p.z());
  return s;
}

/// t_max: 1 on three queries in four, else a random double in (0, 1).
double t_max_for(std::uint64_t seed, std::uint64_t index) {
  const std::uint64_t h = mix64(seed ^ mix64(index ^ 0x7a3c));
  if (h % 4 != 0) return 1.0;
  const double t = static_cast<double>(h >> 11) * 0x1p-53;
  return t > 0 ? t : 0.5;
}

std::uint64_t base_count(const Generator& g) {
  // The reference costs 20-100 us per query; wide exponents cost it far more.
  const std::string name = g.name();
  if (name.find("wide_exponent") != std::string::npos ||
      name.find("subnormal") != std::string::npos)
    return 150;
  return 8000;
}

TEST(ExactBracketsDifferential, RandomAndAdversarialGenerators) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const double scale = scale_from_environment();
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu EXACTCCD_TEST_SCALE=%g\n",
              static_cast<unsigned long long>(seed), scale);
  Tally total;
  FailureLog log;
  for (const Generator& g : all_generators()) {
    const std::uint64_t n = scaled_count(base_count(g), scale);
    const auto start = std::chrono::steady_clock::now();
    tbb::combinable<Tally> tallies;
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, n, 16), [&](const auto& r) {
      for (std::uint64_t i = r.begin(); i != r.end(); ++i) {
        const DoubleQuery q = generate(g, seed, i);
        const std::string what = compare(q, t_max_for(seed, i), tallies.local());
        if (!what.empty()) log.add(g.name() + " #" + std::to_string(i) + ": " + what + point_rows(q));
      }
    });
    const Tally t = tallies.combine([](Tally a, const Tally& b) { return a += b; });
    std::printf("%-36s %8llu queries %8llu contacts %6llu to the rational path %7.1f s\n",
                g.name().c_str(), static_cast<unsigned long long>(t.queries),
                static_cast<unsigned long long>(t.collisions),
                static_cast<unsigned long long>(t.unresolved),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    total += t;
  }
  std::printf("total %llu queries, %llu contacts, %llu to the rational path\n",
              static_cast<unsigned long long>(total.queries),
              static_cast<unsigned long long>(total.collisions),
              static_cast<unsigned long long>(total.unresolved));
  EXPECT_EQ(log.count(), 0u);
  EXPECT_GT(total.collisions, total.queries / 20);  // contacts are exercised, not only misses
  // The rational path is a last resort: it must stay rare on every kind of input.
  EXPECT_LE(total.unresolved, total.queries / 1000);
}

/// Every query of the files under `root`, in parallel.
Tally compare_files(const fs::path& root, FailureLog& log) {
  std::vector<std::pair<std::string, DoubleQuery>> queries;
  for (const std::string& path : find_query_files(root.string())) {
    const auto type = query_type_from_path(path);
    if (!type) continue;
    for (const QueryRecord& r : read_query_file(path, *type).queries) {
      if (!all_coordinates_are_doubles(r.query)) continue;
      DoubleQuery q;
      q.type = *type;
      for (int i = 0; i < 8; ++i) q.v[static_cast<std::size_t>(i)] = to_vector(r.query.points[i]);
      queries.emplace_back(path + ":" + std::to_string(r.first_line), q);
    }
  }
  const std::size_t stride = subset_stride();
  tbb::combinable<Tally> tallies;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 8), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      if (i % stride != 0) continue;
      const auto& [where, q] = queries[i];
      for (double t_max : {1.0, 0.5, 0x1.5555555555555p-2}) {
        const std::string what = compare(q, t_max, tallies.local());
        if (!what.empty()) log.add(where + ": " + what);
      }
    }
  });
  const Tally t = tallies.combine([](Tally a, const Tally& b) { return a += b; });
  std::printf("%s: %llu comparisons, %llu contacts, %llu to the rational path\n",
              root.string().c_str(), static_cast<unsigned long long>(t.queries),
              static_cast<unsigned long long>(t.collisions),
              static_cast<unsigned long long>(t.unresolved));
  return t;
}

TEST(ExactBracketsDifferential, ShippedDataSets) {
  FailureLog log;
  for (const char* set : {"degenerate-suite", "sample-queries", "scene-queries"}) {
    const Tally t = compare_files(fs::path(EXACTCCD_TEST_DATA) / set, log);
    EXPECT_GT(t.queries, 0u) << set;
    EXPECT_LE(t.unresolved, t.queries / 200) << set;
  }
  EXPECT_EQ(log.count(), 0u);
}

}  // namespace
}  // namespace exactccd::test
