// The 5,029 sample queries of the public CCD benchmark (Wang et al. 2021), decided by the exact
// path and by the double API, against the benchmark's own truth column.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace exactccd::test {
namespace {

// The benchmark's published counts (tests/data/sample-queries/README.md).
constexpr std::size_t kSampleQueryCount = 5029;
constexpr std::size_t kSampleCollisionCount = 329;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string list(const std::vector<std::string>& where) {
  std::string s;
  for (const auto& w : where) s += "\n  " + w;
  return s;
}

TEST(SampleQueries, AllQueriesAreRead) {
  const auto& queries = sample_queries();
  EXPECT_EQ(queries.size(), kSampleQueryCount);
  std::size_t truth_collisions = 0, vertex_face = 0;
  for (const auto& s : queries) {
    truth_collisions += s.truth;
    vertex_face += s.query.type == QueryType::vertex_face;
  }
  EXPECT_EQ(truth_collisions, kSampleCollisionCount);
  EXPECT_GT(vertex_face, 0u);
  EXPECT_LT(vertex_face, queries.size());
}

TEST(SampleQueries, ExactPathMatchesTruth) {
  std::vector<std::string> false_positives, false_negatives;
  std::size_t collisions = 0;
  for (const auto& s : sample_queries()) {
    const CcdResult r = exact_ccd(s.query);
    collisions += r.collides;
    if (r.collides && !s.truth) false_positives.push_back(s.where());
    if (!r.collides && s.truth) false_negatives.push_back(s.where());
  }
  EXPECT_TRUE(false_positives.empty()) << false_positives.size() << " false positives:"
                                       << list(false_positives);
  EXPECT_TRUE(false_negatives.empty()) << false_negatives.size() << " false negatives:"
                                       << list(false_negatives);
  EXPECT_EQ(collisions, kSampleCollisionCount);
}

// The README states every coordinate is exactly a double; the double API must then give the
// same verdict, and the very same enclosure as the rational API (both are exact).
TEST(SampleQueries, DoubleApiMatchesTruthAndRationalApi) {
  std::vector<std::string> not_doubles, false_positives, false_negatives, differ;
  std::size_t collisions = 0;
  for (const auto& s : sample_queries()) {
    if (!all_coordinates_are_doubles(s.query)) {
      not_doubles.push_back(s.where());
      continue;
    }
    const CcdResult r = double_api_ccd(s.query);
    const CcdResult e = exact_ccd(s.query);
    collisions += r.collides;
    if (r.collides && !s.truth) false_positives.push_back(s.where());
    if (!r.collides && s.truth) false_negatives.push_back(s.where());
    if (r.collides != e.collides || r.toi_lo != e.toi_lo || r.toi_hi != e.toi_hi)
      differ.push_back(s.where());
  }
  EXPECT_TRUE(not_doubles.empty()) << "coordinates that are not doubles:" << list(not_doubles);
  EXPECT_TRUE(false_positives.empty()) << false_positives.size() << " false positives:"
                                       << list(false_positives);
  EXPECT_TRUE(false_negatives.empty()) << false_negatives.size() << " false negatives:"
                                       << list(false_negatives);
  EXPECT_TRUE(differ.empty()) << "double and rational API differ:" << list(differ);
  EXPECT_EQ(collisions, kSampleCollisionCount);
}

// Shape of every result: a colliding one has 0 <= toi_lo <= toi_hi <= t_max, a free one reports
// +infinity, +infinity (the no-contact convention). Checked at t_max = 1 and at t_max = 1/2.
TEST(SampleQueries, ResultsAreWellFormed) {
  std::vector<std::string> bad;
  for (const double t_max : {1.0, 0.5}) {
    CcdOptions options;
    options.t_max = t_max;
    for (const auto& s : scaled_sample_queries()) {
      const CcdResult r = exact_ccd(s.query, options);
      const bool ok = r.collides
                          ? (0 <= r.toi_lo && r.toi_lo <= r.toi_hi && r.toi_hi <= t_max)
                          : (r.toi_lo == kInf && r.toi_hi == kInf);
      if (!ok || r.decided_by != Stage::exact)
        bad.push_back(s.where() + " (t_max " + std::to_string(t_max) + ")");
    }
  }
  EXPECT_TRUE(bad.empty()) << "malformed results:" << list(bad);
}

// An independent necessary condition for every "no collision" verdict: CGAL's exact kernel finds
// no contact at the rational times k/16.
TEST(SampleQueries, NoContactAtSampledTimesWhenFree) {
  std::vector<std::string> contradicted;
  std::size_t free_queries = 0, free_by_truth = 0;
  for (const auto& s : scaled_sample_queries()) {
    free_by_truth += !s.truth;
    if (exact_ccd(s.query).collides) continue;
    ++free_queries;
    for (int k = 0; k <= 16; ++k) {
      if (cgal_contact_at(s.query, mpq_class(k, 16))) {
        contradicted.push_back(s.where() + " has contact at t = " + std::to_string(k) + "/16");
        break;
      }
    }
  }
  EXPECT_EQ(free_queries, free_by_truth);
  EXPECT_TRUE(contradicted.empty()) << "reported free, yet:" << list(contradicted);
}

}  // namespace
}  // namespace exactccd::test
