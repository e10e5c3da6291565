// Tests of the oracle's library API (oracle/check.hpp, oracle/grade.hpp), which the distributed
// check and grade run one shard at a time: the shards of a file add up to the whole file, and
// the whole file is what its truth column says.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "oracle/check.hpp"
#include "oracle/grade.hpp"
#include "oracle/names.hpp"

namespace {

namespace fs = std::filesystem;
using namespace exactccd;
using namespace exactccd::oracle;

std::vector<std::string> unit_test_files() {
  return find_query_files(std::string(EXACTCCD_SAMPLE_QUERIES) + "/unit-tests");
}

void expect_same_counts(const CheckTally& a, const CheckTally& b, const std::string& where) {
  EXPECT_EQ(a.queries, b.queries) << where;
  EXPECT_EQ(a.collisions, b.collisions) << where;
  EXPECT_EQ(a.false_positives, b.false_positives) << where;
  EXPECT_EQ(a.false_negatives, b.false_negatives) << where;
  for (const Stage s : all_stages()) EXPECT_EQ(a.stage_count(s), b.stage_count(s)) << where;
}

TEST(OracleCheck, WholeFileAgreesWithItsTruthColumn) {
  const std::vector<std::string> files = unit_test_files();
  ASSERT_EQ(files.size(), 4u);
  for (const std::string& path : files) {
    const QueryFile input = read_query_file(path, *query_type_from_path(path));
    std::size_t contacts = 0;
    for (const QueryRecord& r : input.queries) contacts += r.truth;
    std::vector<std::size_t> visited;
    const CheckTally whole =
        check_file(path, std::nullopt, CheckSettings{},
                   [&](std::size_t index, std::size_t count, const CcdResult&) {
                     EXPECT_EQ(count, input.queries.size());
                     visited.push_back(index);
                   });
    EXPECT_EQ(whole.file, path);
    EXPECT_EQ(whole.queries, input.queries.size()) << path;
    EXPECT_EQ(whole.collisions, contacts) << path;
    EXPECT_EQ(whole.disagreements(), 0u) << path;
    ASSERT_EQ(visited.size(), input.queries.size());
    for (std::size_t i = 0; i < visited.size(); ++i) EXPECT_EQ(visited[i], i);
  }
}

TEST(OracleCheck, ShardsAddUpToTheWholeFile) {
  for (const std::string& path : unit_test_files()) {
    const QueryFile input = read_query_file(path, *query_type_from_path(path));
    const std::size_t n = input.queries.size();
    ASSERT_GE(n, 2u);
    for (const Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
      CheckSettings settings;
      settings.mode = mode;
      const CheckTally whole = check_queries(input, 0, n, settings);
      for (const std::size_t split : {std::size_t{0}, std::size_t{1}, n / 2, n - 1, n}) {
        CheckTally sum = check_queries(input, 0, split, settings);
        sum.add(check_queries(input, split, n + 7, settings));  // the end is clipped
        expect_same_counts(sum, whole, path + " split at " + std::to_string(split));
      }
      EXPECT_EQ(check_queries(input, n, n + 1, settings).queries, 0u);
    }
  }
}

class OracleGrade : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("exactccd-oracle-test-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  fs::path dir_;
};

TEST_F(OracleGrade, ShardsAddUpToTheWholeFile) {
  const std::string path = unit_test_files().front();
  const QueryFile input = read_query_file(path, *query_type_from_path(path));
  const std::size_t n = input.queries.size();
  // The truth column as answers, with the first answer flipped and every contact given the
  // latest toi, 1: a false positive or negative at 0 and late TOIs wherever t* < 1.
  const fs::path answers_path = dir_ / "answers.txt";
  {
    std::ofstream out(answers_path);
    for (std::size_t i = 0; i < n; ++i) {
      const bool says = input.queries[i].truth != (i == 0);
      out << (says ? "1,1" : "0") << '\n';
    }
  }
  const GradeFindings whole = grade_file(path, answers_path.string(), std::nullopt, 1.0);
  EXPECT_EQ(whole.queries, n);
  EXPECT_EQ(whole.false_positives.size() + whole.false_negatives.size(), 1u);
  EXPECT_FALSE(whole.all_good());

  const std::vector<Answer> answers = read_answers_file(answers_path.string(), n, path, 1.0);
  for (const std::size_t split : {std::size_t{0}, std::size_t{1}, n / 2, n}) {
    GradeFindings a = grade_answers(input, answers, 1.0, 0, split);
    const GradeFindings b = grade_answers(input, answers, 1.0, split, n + 3);
    EXPECT_EQ(a.queries + b.queries, whole.queries);
    EXPECT_EQ(a.tois_given + b.tois_given, whole.tois_given);
    for (auto [to, from] : {std::pair{&a.false_positives, &b.false_positives},
                            std::pair{&a.false_negatives, &b.false_negatives},
                            std::pair{&a.non_conservative, &b.non_conservative}})
      to->insert(to->end(), from->begin(), from->end());
    EXPECT_EQ(a.false_positives, whole.false_positives) << split;
    EXPECT_EQ(a.false_negatives, whole.false_negatives) << split;
    EXPECT_EQ(a.non_conservative, whole.non_conservative) << split;
  }
}

}  // namespace
