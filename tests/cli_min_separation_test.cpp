// `exactccd check|grade|bench --min-separation`: the run's delta reaches every decision, the
// JSON reports it, bad deltas are refused. PROOF: proofs/min_separation.md#pipeline
#include "cli_fixture.hpp"

namespace cli_test {
namespace {

// kHalfThirdNever's vertex falls towards the triangle's interior from height 1 at speed 2, 3
// and 0: with delta = 1/8 it first comes within delta at 1 - 2t = 1/8 (t = 7/16, a double),
// at 1 - 3t = 1/8 (t = 7/24, between two doubles), and never.
constexpr const char* kDelta = "0.125";

TEST_F(CliTest, CheckDecidesWithTheRunsMinimumSeparation) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path out = dir_ / "out.csv";
  const RunResult r =
      run({"check", "--min-separation", kDelta, "--json", "--out", out.string(), file.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["min_separation"].get<double>(), 0.125);
  EXPECT_EQ(j["false_positives"].get<int>(), 0);
  EXPECT_EQ(j["false_negatives"].get<int>(), 0);
  const std::vector<std::string> lines = lines_of(read_text(out));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(split(lines[0], ',')[3], "0.4375");
  EXPECT_EQ(split(lines[0], ',')[4], "0.4375");
  const double lo = std::stod(split(lines[1], ',')[3]), hi = std::stod(split(lines[1], ',')[4]);
  EXPECT_LT(lo, 7.0 / 24.0 + 1e-15);
  EXPECT_GT(hi, 7.0 / 24.0 - 1e-15);
  EXPECT_EQ(std::nextafter(lo, 1.0), hi);  // the tightest pair of doubles around 7/24
  EXPECT_EQ(split(lines[2], ',')[2], "0");
  // The exact mode agrees line for line.
  const fs::path exact_out = dir_ / "exact.csv";
  ASSERT_EQ(run({"check", "--min-separation", kDelta, "--mode", "exact", "--out",
                 exact_out.string(), file.string()})
                .status,
            0);
  EXPECT_EQ(read_text(exact_out), read_text(out));
}

TEST_F(CliTest, GradeJudgesTimesAgainstTheFirstTimeWithinDelta) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  // 0.45 is conservative for contact (t* = 1/2) but later than 7/16 at delta = 1/8.
  const fs::path answers = write_file("answers.txt", "1,0.45\n1,0.25\n0\n");
  EXPECT_EQ(run({"grade", "--queries", file.string(), "--answers", answers.string()}).status, 0);
  const RunResult r = run({"grade", "--min-separation", kDelta, "--json", "--queries",
                           file.string(), "--answers", answers.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["min_separation"].get<double>(), 0.125);
  EXPECT_EQ(j["non_conservative_tois"].get<int>(), 1);
  const fs::path good = write_file("good.txt", "1,0.4375\n1,0.29\n0\n");
  EXPECT_EQ(run({"grade", "--min-separation", kDelta, "--queries", file.string(), "--answers",
                 good.string()})
                .status,
            0);
}

TEST_F(CliTest, BenchRunsEachSeparationAgainstTheExactPath) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  const RunResult r = run({"bench", "--json", "--repetitions", "1", "--modes",
                           "float_only,filtered", "--min-separation", "0,0.125", file.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 4u);
  for (const auto& row : j) {
    const double delta = row["min_separation"].get<double>();
    EXPECT_TRUE(delta == 0.0 || delta == 0.125);
    EXPECT_EQ(row["truth"].get<std::string>(), delta > 0 ? "exact path" : "truth column");
    if (delta > 0 && row["mode"] == "filtered") {
      EXPECT_EQ(row["false_positives"].get<int>(), 0);
      EXPECT_EQ(row["false_negatives"].get<int>(), 0);
      EXPECT_EQ(row["late_tois"].get<int>(), 0);
      EXPECT_EQ(row["max_toi_error"].get<double>(), 0.0);
    }
  }
  // Relative: 0.125 of the data set's size (the box diagonal: x, y in [0, 1], z in [-2, 1]).
  const RunResult relative = run({"bench", "--json", "--repetitions", "1", "--modes", "filtered",
                                  "--min-separation", "0.125", "--relative-separation",
                                  file.string()});
  ASSERT_EQ(relative.status, 0) << relative.err;
  const auto row = nlohmann::json::parse(relative.out)[0];
  EXPECT_DOUBLE_EQ(row["min_separation"].get<double>(), 0.125 * std::sqrt(11.0));
  // The report's minimum-separation section reads the size and the factor back.
  EXPECT_DOUBLE_EQ(row["size"].get<double>(), std::sqrt(11.0));
  EXPECT_EQ(row["min_separation_factor"].get<double>(), 0.125);
  EXPECT_FALSE(j[0].contains("min_separation_factor"));  // absolute deltas carry none
}

TEST_F(CliTest, RejectsNegativeOrNonFiniteMinimumSeparation) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path answers = write_file("answers.txt", "1\n1\n0\n");
  for (const char* delta : {"-1", "-1e-300", "nan", "inf", ""}) {
    SCOPED_TRACE(delta);
    expect_bad_input(run({"check", "--min-separation", delta, file.string()}),
                     {"--min-separation"});
    expect_bad_input(run({"grade", "--min-separation", delta, "--queries", file.string(),
                          "--answers", answers.string()}),
                     {"--min-separation"});
    expect_bad_input(run({"bench", "--min-separation", delta, "--repetitions", "1",
                          file.string()}),
                     {"--min-separation"});
  }
}

}  // namespace
}  // namespace cli_test
