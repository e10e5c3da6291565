// Tests of the `exactccd` command (tools/): runs the built binary on files written into a fresh
// temporary directory. Expected values come from the benchmark's truth column, read here with
// a parser of this file's own, and from hand-made queries whose contact times are worked out
// by hand; none from the command's or the library's code.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace {

using namespace cli_test;

// The truth column of a benchmark CSV file, one value per query (8 rows each), read
// independently of exactccd's reader.
std::vector<bool> read_truth_column(const fs::path& path) {
  std::vector<bool> truth;
  std::size_t rows = 0;
  for (const std::string& line : lines_of(read_text(path))) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const bool value = std::stoi(line.substr(line.rfind(',') + 1)) == 1;
    if (rows++ % 8 == 0)
      truth.push_back(value);
    else
      EXPECT_EQ(truth.back(), value) << path << " row " << rows;
  }
  EXPECT_EQ(rows % 8, 0u) << path;
  return truth;
}

// Every query file of the sample set (key: the canonical path) with its truth column.
std::map<std::string, std::vector<bool>> sample_truth() {
  std::map<std::string, std::vector<bool>> files;
  for (const auto& entry : fs::recursive_directory_iterator(EXACTCCD_SAMPLE_QUERIES)) {
    const fs::path& p = entry.path();
    const fs::path folder = p.parent_path().filename();
    if (p.extension() == ".csv" && (folder == "vertex-face" || folder == "edge-edge"))
      files[fs::weakly_canonical(p).string()] = read_truth_column(p);
  }
  return files;
}

std::vector<std::size_t> indices(const nlohmann::json& j, const char* key) {
  return j.at(key).get<std::vector<std::size_t>>();
}

// ---- check: bad input ----------------------------------------------------------------------

TEST_F(CliTest, CheckRejectsWrongColumnCount) {
  expect_check_rejects(replace_line(kHalfThirdNever, 3, "1,1,0,1,0"), 3);
}

TEST_F(CliTest, CheckRejectsNonIntegerField) {
  expect_check_rejects(replace_line(kHalfThirdNever, 5, "1,4,1.5,4,-1,1,1"), 5);
}

TEST_F(CliTest, CheckRejectsZeroDenominator) {
  expect_check_rejects(replace_line(kHalfThirdNever, 2, "0,1,0,0,0,1,1"), 2);
}

TEST_F(CliTest, CheckRejectsQueryCutShort) {
  // 12 rows: the second query stops after 4 of its 8 rows, at the file's last line.
  const std::vector<std::string> lines = lines_of(kHalfThirdNever);
  std::string text;
  for (std::size_t i = 0; i < 12; ++i) text += lines[i] + "\n";
  expect_check_rejects(text, 12);
}

TEST_F(CliTest, CheckRejectsTruthDifferingWithinQuery) {
  expect_check_rejects(replace_line(kHalfThirdNever, 4, "0,1,1,1,0,1,0"), 4);
}

TEST_F(CliTest, CheckRejectsNanField) {
  expect_check_rejects(replace_line(kHalfThirdNever, 6, "nan,1,0,1,0,1,1"), 6);
}

TEST_F(CliTest, CheckRejectsInfField) {
  expect_check_rejects(replace_line(kHalfThirdNever, 7, "1,1,-inf,1,0,1,1"), 7);
}

TEST_F(CliTest, CheckRejectsMissingFile) {
  const fs::path missing = dir_ / "vertex-face" / "missing.csv";
  expect_bad_input(run({"check", missing.string()}), {missing.string()});
}

TEST_F(CliTest, CheckRejectsDirectoryWithoutCsvFiles) {
  write_file("empty/vertex-face/notes.txt", "not a query file\n");
  write_file("empty/misc/untyped.csv", falling_vertex_query(-1, 1));  // not in a typed folder
  const fs::path dir = dir_ / "empty";
  expect_bad_input(run({"check", dir.string()}), {dir.string()});
}

TEST_F(CliTest, CheckRejectsUnknownQueryTypeUnlessGiven) {
  const fs::path file = write_file("misc/untyped.csv", falling_vertex_query(-1, 1));
  expect_bad_input(run({"check", file.string()}), {file.string(), "type"});
  const RunResult typed = run({"check", "--type", "vf", file.string()});
  EXPECT_EQ(typed.status, 0) << typed.err;
  expect_bad_input(run({"check", "--type", "triangle", file.string()}), {"--type"});
}

TEST_F(CliTest, RejectsTMaxOutsideUnitInterval) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path answers = write_file("answers.txt", "1\n1\n0\n");
  for (const char* t_max : {"0", "-0.5", "1.5", "nan", "inf"}) {
    SCOPED_TRACE(t_max);
    expect_bad_input(run({"check", "--t-max", t_max, file.string()}), {"--t-max"});
    expect_bad_input(
        run({"grade", "--t-max", t_max, "--queries", file.string(), "--answers", answers.string()}),
        {"--t-max"});
  }
}

TEST_F(CliTest, RejectsBadCommandLine) {
  expect_bad_input(run({}), {});
  expect_bad_input(run({"frobnicate"}), {"unknown subcommand 'frobnicate'"});
  expect_bad_input(run({"check"}), {"PATH"});
  expect_bad_input(run({"grade", "--queries", kSampleFile.string()}), {"--answers"});
}

TEST_F(CliTest, CheckRejectsUnwritableOutFile) {
  const fs::path out = dir_ / "no-such-folder" / "out.txt";
  expect_bad_input(run({"check", "--out", out.string(), kSampleFile.string()}), {out.string()});
}

// ---- grade: bad input ----------------------------------------------------------------------

TEST_F(CliTest, GradeRejectsMalformedQueriesFile) {
  const fs::path queries =
      write_file("vertex-face/bad.csv", replace_line(kHalfThirdNever, 9, "1,4,1,4,x,1,1"));
  const fs::path answers = write_file("answers.txt", "1\n1\n0\n");
  expect_bad_input(run({"grade", "--queries", queries.string(), "--answers", answers.string()}),
                   {queries.string() + ":9:"});
}

TEST_F(CliTest, GradeRejectsMalformedAnswerLine) {
  const fs::path answers = dir_ / "answers.txt";
  for (const char* bad : {"2", "yes", "", "1;0.5", "01", "1 0"}) {
    SCOPED_TRACE(bad);
    expect_bad_input(grade(std::string("1\n") + bad + "\n0\n"), {answers.string() + ":2:"});
  }
}

TEST_F(CliTest, GradeRejectsToiThatIsNotANumber) {
  const fs::path answers = dir_ / "answers.txt";
  for (const char* bad : {"1,abc", "1,", "1,0.5x", "1,0.5,0.6"}) {
    SCOPED_TRACE(bad);
    expect_bad_input(grade(std::string(bad) + "\n1\n0\n"), {answers.string() + ":1:"});
  }
}

TEST_F(CliTest, GradeRejectsNanOrInfToi) {
  const fs::path answers = dir_ / "answers.txt";
  for (const char* bad : {"1,nan", "1,NaN", "1,inf", "1,-inf", "1,infinity", "1,1e999"}) {
    SCOPED_TRACE(bad);
    expect_bad_input(grade(std::string("1\n") + bad + "\n0\n"), {answers.string() + ":2:"});
  }
}

TEST_F(CliTest, GradeRejectsToiOnNoCollisionLine) {
  for (const char* bad : {"0,0.5", "0,-inf", "0,nan", "0,", "0,1e999"}) {
    SCOPED_TRACE(bad);
    expect_bad_input(grade(std::string("1\n1\n") + bad + "\n"),
                     {(dir_ / "answers.txt").string() + ":3:"});
  }
}

// The no-contact TOI of the +infinity convention is accepted on a `0` line (and only there).
TEST_F(CliTest, GradeAcceptsInfinityToiOnNoCollisionLine) {
  for (const char* no_contact : {"0,inf", "0,+inf", "0,Infinity", "0, INF "}) {
    SCOPED_TRACE(no_contact);
    const RunResult r = grade(std::string("1,0.5\n1,0.25\n") + no_contact + "\n");
    EXPECT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = parse_json(r);
    EXPECT_EQ(j.value("queries", 0u), 3u);
    EXPECT_EQ(j.value("false_positives", 1u), 0u);
    EXPECT_EQ(j.value("false_negatives", 1u), 0u);
    EXPECT_EQ(j.value("tois_given", 0u), 2u);
    EXPECT_EQ(j.value("non_conservative_tois", 1u), 0u);
  }
}

// Blank lines after the last answer (an editor's final newline, twice) are no answers; a blank
// line before an answer is an error at its own line.
TEST_F(CliTest, GradeIgnoresBlankLinesOnlyAtTheEnd) {
  for (const char* end : {"\n", "\n\n", "\n \n\t\n"}) {
    SCOPED_TRACE(end);
    const RunResult r = grade(std::string("1,0.5\n1,0.25\n0") + end);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(parse_json(r).value("queries", 0u), 3u);
  }
  const fs::path answers = dir_ / "answers.txt";
  expect_bad_input(grade("1,0.5\n\n1,0.25\n0\n"), {answers.string() + ":2:", "blank line"});
  // 3 answers and a blank line for 3 queries: complete, not "more answer lines".
  EXPECT_EQ(grade("1,0.5\n1,0.25\n0\n\n").status, 0);
}

TEST_F(CliTest, GradeNamesWhatANoCollisionLineTakes) {
  expect_bad_input(grade("1\n1\n0,nan\n"),
                   {(dir_ / "answers.txt").string() + ":3:", "takes no toi, or 'inf'", "'0,nan'"});
}

TEST_F(CliTest, GradeRejectsTooFewAnswers) {
  expect_bad_input(grade("1\n1\n"), {(dir_ / "answers.txt").string(), "queries.csv"});
}

TEST_F(CliTest, GradeRejectsTooManyAnswers) {
  expect_bad_input(grade("1\n1\n0\n0\n"), {(dir_ / "answers.txt").string() + ":4:"});
}

TEST_F(CliTest, GradeRejectsMissingAnswersFile) {
  const fs::path queries = write_file("vertex-face/queries.csv", kHalfThirdNever);
  const fs::path missing = dir_ / "missing-answers.txt";
  expect_bad_input(run({"grade", "--queries", queries.string(), "--answers", missing.string()}),
                   {missing.string()});
}

// ---- check: results ------------------------------------------------------------------------

TEST_F(CliTest, CheckOneSampleFilePrintsTruthTotals) {
  const std::vector<bool> truth = read_truth_column(kSampleFile);
  const std::size_t collide = std::count(truth.begin(), truth.end(), true);
  ASSERT_GT(collide, 0u);
  ASSERT_LT(collide, truth.size());  // both outcomes present

  const RunResult r = run({"check", "--format", "wide", kSampleFile.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // in particular no progress: stderr is not a terminal here
  std::size_t total_rows = 0;
  for (const std::string& line : lines_of(r.out)) {
    // TOTAL and the file's row: queries, collisions, agree, disagree, false_pos, false_neg, µs.
    std::istringstream fields(line);
    std::string name;
    fields >> name;
    if (name != "TOTAL" && name != kSampleFile.string()) continue;
    total_rows += name == "TOTAL";
    std::size_t queries, collisions, agree, disagree, false_pos, false_neg;
    double micros;
    ASSERT_TRUE(fields >> queries >> collisions >> agree >> disagree >> false_pos >> false_neg >>
                micros)
        << line;
    EXPECT_EQ(queries, truth.size()) << line;
    EXPECT_EQ(collisions, collide) << line;
    EXPECT_EQ(agree, truth.size()) << line;
    EXPECT_EQ(disagree, 0u) << line;
    EXPECT_EQ(false_pos, 0u) << line;
    EXPECT_EQ(false_neg, 0u) << line;
    EXPECT_GT(micros, 0.0) << line;
  }
  EXPECT_EQ(total_rows, 1u) << r.out;
}

TEST_F(CliTest, CheckJsonOnWholeSampleSetMatchesTruth) {
  const auto truth = sample_truth();
  std::size_t queries = 0, collide = 0;
  for (const auto& [file, values] : truth) {
    queries += values.size();
    collide += std::count(values.begin(), values.end(), true);
  }
  // The sample set's README: 5,029 queries, 329 of them collide.
  ASSERT_EQ(queries, 5029u);
  ASSERT_EQ(collide, 329u);

  const RunResult r = run({"check", "--json", EXACTCCD_SAMPLE_QUERIES});
  EXPECT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = parse_json(r);
  EXPECT_EQ(j.value("queries", 0u), queries);
  EXPECT_EQ(j.value("collisions", 0u), collide);
  EXPECT_EQ(j.value("false_positives", 1u), 0u);
  EXPECT_EQ(j.value("false_negatives", 1u), 0u);
  EXPECT_GT(j.value("seconds", 0.0), 0.0);
  ASSERT_TRUE(j.contains("files") && j["files"].is_array()) << r.out;
  EXPECT_EQ(j["files"].size(), truth.size());
  for (const nlohmann::json& f : j["files"]) {
    const std::string name = fs::weakly_canonical(f.value("file", "")).string();
    ASSERT_EQ(truth.count(name), 1u) << name;
    const std::vector<bool>& values = truth.at(name);
    EXPECT_EQ(f.value("queries", 0u), values.size()) << name;
    EXPECT_EQ(f.value("collisions", 0u),
              static_cast<std::size_t>(std::count(values.begin(), values.end(), true)))
        << name;
    EXPECT_EQ(f.value("false_positives", 1u), 0u) << name;
    EXPECT_EQ(f.value("false_negatives", 1u), 0u) << name;
  }
}

TEST_F(CliTest, CheckOutWritesOneWellFormedLinePerQuery) {
  const auto truth = sample_truth();
  const fs::path out = dir_ / "results.csv";
  const RunResult r = run({"check", "--out", out.string(), EXACTCCD_SAMPLE_QUERIES});
  EXPECT_EQ(r.status, 0) << r.err;

  const std::vector<std::string> lines = lines_of(read_text(out));
  EXPECT_EQ(lines.size(), 5029u);
  std::map<std::string, std::size_t> next_index;  // indices run 0, 1, ... within each file
  std::size_t ones = 0;
  for (const std::string& line : lines) {
    const std::vector<std::string> f = split(line, ',');
    ASSERT_EQ(f.size(), 5u) << line;
    const std::string name = fs::weakly_canonical(f[0]).string();
    ASSERT_EQ(truth.count(name), 1u) << line;
    const std::size_t index = next_index[name]++;
    ASSERT_EQ(f[1], std::to_string(index)) << line;
    ASSERT_TRUE(f[2] == "0" || f[2] == "1") << line;
    const bool collides = f[2] == "1";
    EXPECT_EQ(collides, truth.at(name).at(index)) << line;
    if (!collides) {  // no contact: +infinity, written "inf" (strtod, Python's float read it)
      EXPECT_EQ(f[3], "inf") << line;
      EXPECT_EQ(f[4], "inf") << line;
      continue;
    }
    ++ones;
    std::size_t used_lo = 0, used_hi = 0;
    const double lo = std::stod(f[3], &used_lo), hi = std::stod(f[4], &used_hi);
    EXPECT_EQ(used_lo, f[3].size()) << line;
    EXPECT_EQ(used_hi, f[4].size()) << line;
    EXPECT_TRUE(0.0 <= lo && lo <= hi && hi <= 1.0) << line;
    // toi_width 0: the tightest enclosure, one double or two consecutive doubles.
    EXPECT_TRUE(hi == lo || hi == std::nextafter(lo, 2.0)) << line;
  }
  EXPECT_EQ(ones, 329u);
  for (const auto& [name, values] : truth) EXPECT_EQ(next_index[name], values.size()) << name;
}

TEST_F(CliTest, CheckReportsDisagreementsWithTruthColumn) {
  // The falling vertex meets the triangle at t = 1/2 but is labelled 0; the resting one never
  // does but is labelled 1.
  const fs::path file = write_file("vertex-face/mislabelled.csv",
                                   falling_vertex_query(-1, 0) + falling_vertex_query(1, 1));
  const RunResult r = run({"check", "--json", file.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  const nlohmann::json j = parse_json(r);
  EXPECT_EQ(j.value("queries", 0u), 2u);
  EXPECT_EQ(j.value("collisions", 0u), 1u);
  EXPECT_EQ(j.value("false_positives", 0u), 1u);
  EXPECT_EQ(j.value("false_negatives", 0u), 1u);
}

TEST_F(CliTest, CheckTMaxClosesTheIntervalAtTMax) {
  // Contact at exactly t = 1/2 (labelled 0): outside [0, 1/4], inside the closed [0, 1/2].
  const fs::path file = write_file("vertex-face/half.csv", falling_vertex_query(-1, 0));
  const RunResult before = run({"check", "--json", "--t-max", "0.25", file.string()});
  EXPECT_EQ(before.status, 0) << before.err;
  EXPECT_EQ(parse_json(before).value("collisions", 1u), 0u);
  const RunResult at = run({"check", "--json", "--t-max", "0.5", file.string()});
  EXPECT_EQ(at.status, 1) << at.err;
  EXPECT_EQ(parse_json(at).value("collisions", 0u), 1u);
}

TEST_F(CliTest, HelpDocumentsExitStatuses) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--help"}, {"check", "--help"}, {"grade", "--help"},
        {"simulate", "--help"}, {"bench", "--help"}}) {
    const RunResult r = run(args);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("Exit status"), std::string::npos) << r.out;
  }
}

// ---- check --mode --------------------------------------------------------------------------

// The stage counts of a JSON object, checked to add up to its queries and to match the
// shares (count / queries).
std::map<std::string, std::size_t> stage_counts(const nlohmann::json& j) {
  std::map<std::string, std::size_t> counts;
  std::size_t sum = 0;
  for (const auto& [stage, count] : j.at("stage_counts").items()) {
    counts[stage] = count.get<std::size_t>();
    sum += counts[stage];
    EXPECT_EQ(j.at("stage_share").at(stage).get<double>(),
              static_cast<double>(counts[stage]) / j.at("queries").get<double>())
        << stage;
  }
  EXPECT_EQ(sum, j.at("queries").get<std::size_t>());
  EXPECT_EQ(j.at("stage_share").size(), j.at("stage_counts").size());
  return counts;
}

TEST_F(CliTest, CheckEachModeOnOneSampleFile) {
  const std::vector<bool> truth = read_truth_column(kSampleFile);
  const std::size_t collide = std::count(truth.begin(), truth.end(), true);
  for (const std::string mode : {"float_only", "filtered", "exact"}) {
    SCOPED_TRACE(mode);
    const RunResult r = run({"check", "--json", "--mode", mode, kSampleFile.string()});
    const nlohmann::json j = parse_json(r);
    EXPECT_EQ(j.value("mode", ""), mode);
    EXPECT_EQ(j.value("queries", 0u), truth.size());
    const std::size_t false_pos = j.value("false_positives", 0u);
    const std::size_t false_neg = j.value("false_negatives", 0u);
    // Reported collisions are the truth's, plus false positives, less false negatives.
    EXPECT_EQ(j.value("collisions", 0u) + false_neg, collide + false_pos);
    EXPECT_EQ(r.status, false_pos + false_neg == 0 ? 0 : 1) << r.err;
    const auto counts = stage_counts(j);
    if (mode == "float_only") {
      EXPECT_EQ(counts.at("float_only"), truth.size());
    } else {
      // The certified modes are exact: the truth column's answer on every query.
      EXPECT_EQ(false_pos, 0u);
      EXPECT_EQ(false_neg, 0u);
      EXPECT_EQ(counts.count("float_only"), 0u);
      if (mode == "exact") EXPECT_EQ(counts.at("exact"), truth.size());
    }
  }
}

TEST_F(CliTest, CheckTableNamesModeAndStageColumns) {
  for (const char* format : {"table", "wide"}) {
    SCOPED_TRACE(format);
    const RunResult r = run({"check", "--format", format, "--mode", "exact", kSampleFile.string()});
    EXPECT_EQ(r.status, 0) << r.err;
    const std::vector<std::string> lines = lines_of(r.out);
    ASSERT_GE(lines.size(), 3u) << r.out;
    EXPECT_EQ(lines[0].rfind("mode: exact", 0), 0u) << r.out;
    EXPECT_NE(lines[1].find(" exact"), std::string::npos) << r.out;  // the stage column
    EXPECT_NE(lines.back().find(std::string(format) == "wide" ? "100.00%" : "100.0%"),
              std::string::npos)
        << r.out;  // all by the exact stage
  }
}

// The default table fits a 100-column terminal however long the paths (the shipped sample's
// 26 files in 13 folders), keeps every file's counts (TOTAL equal to the wide table's), and
// tells the type folders apart; --format csv gives the wide table's numbers, one row per file
// and TOTAL, parseable; --json is --format json.
TEST_F(CliTest, CheckFormatsTableWithin100ColumnsCsvAndJson) {
  const std::string sample = kSampleFile.parent_path().parent_path().parent_path().string();
  const RunResult table = run({"check", sample});
  ASSERT_EQ(table.status, 0) << table.err;
  const std::vector<std::string> rows = lines_of(table.out);
  std::size_t vf = 0, ee = 0;
  for (const std::string& row : rows) {
    EXPECT_LE(row.size(), 100u) << row;
    vf += row.find("/vf/") != std::string::npos || row.rfind("vf/", 0) == 0;
    ee += row.find("/ee/") != std::string::npos || row.rfind("ee/", 0) == 0;
  }
  EXPECT_GT(vf, 0u) << table.out;
  EXPECT_GT(ee, 0u) << table.out;

  const RunResult csv = run({"check", "--format", "csv", sample});
  ASSERT_EQ(csv.status, 0) << csv.err;
  const std::vector<std::string> lines = lines_of(csv.out);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0].rfind("file,queries,collisions,agree,disagree,false_positives,"
                           "false_negatives,us_per_query,share_",
                           0),
            0u)
      << lines[0];
  EXPECT_EQ(lines.size(), rows.size() - 1) << "one CSV row per table row, header included";
  const std::string& total = lines.back();
  EXPECT_EQ(total.rfind("TOTAL,", 0), 0u) << total;
  std::istringstream fields(total.substr(6));
  std::size_t queries = 0, collisions = 0;
  char comma = 0;
  ASSERT_TRUE(fields >> queries >> comma >> collisions) << total;

  const RunResult json = run({"check", "--json", sample});
  const RunResult json_format = run({"check", "--format", "json", sample});
  const nlohmann::json a = parse_json(json), b = parse_json(json_format);
  EXPECT_EQ(a.value("queries", 0u), queries);
  EXPECT_EQ(a.value("collisions", 0u), collisions);
  EXPECT_EQ(b.value("queries", 0u), queries);
  expect_bad_input(run({"check", "--format", "xml", sample}), {"--format"});
}

TEST_F(CliTest, CheckOnlyExactModeDecidesNonDoubleCoordinates) {
  // The falling vertex (contact at t = 1/2) with p_t1.x = 1/3, which no double equals; at
  // t = 1/2, p = (7/24, 1/4, 0) lies inside the triangle. A blank line before the query (blank
  // lines may stand between queries) puts the fifth row (p_t1) on line 6.
  std::vector<std::string> rows = lines_of(falling_vertex_query(-1, 1));
  rows[4] = "1,3,1,4,-1,1,1";
  std::string text = "\n";
  for (const std::string& row : rows) text += row + "\n";
  const fs::path file = write_file("vertex-face/third.csv", text);
  for (const char* mode : {"filtered", "float_only"}) {
    SCOPED_TRACE(mode);
    expect_bad_input(run({"check", "--mode", mode, file.string()}), {file.string() + ":6:"});
  }
  const RunResult exact = run({"check", "--json", "--mode", "exact", file.string()});
  EXPECT_EQ(exact.status, 0) << exact.err;
  const nlohmann::json j = parse_json(exact);
  EXPECT_EQ(j.value("collisions", 0u), 1u);
  EXPECT_EQ(j.value("false_negatives", 1u), 0u);
  // The bench times the double API, so it rejects the file too.
  expect_bad_input(run({"bench", "--repetitions", "1", file.string()}), {file.string() + ":6:"});
}

TEST_F(CliTest, CheckRejectsUnknownMode) {
  // The message lists the valid names, the alias too.
  expect_bad_input(run({"check", "--mode", "fast", kSampleFile.string()}),
                   {"--mode", "'fast'", "\"float_only\"", "\"filtered\"", "\"exact\"",
                    "\"default\""});
  expect_bad_input(run({"check", "--mode", "Filtered", kSampleFile.string()}), {"--mode"});
}

// Mode::filtered is printed "filtered"; "default", its name before, is still accepted as an
// alias (old scripts, A/B runs against an older binary): the same decisions, printed as
// "filtered". The help names both.
TEST_F(CliTest, CheckAcceptsDefaultAsTheOldNameOfFiltered) {
  std::map<std::string, std::string> answers;
  for (const std::string mode : {"filtered", "default"}) {
    SCOPED_TRACE(mode);
    const fs::path out = dir_ / ("answers-" + mode + ".csv");
    const RunResult r =
        run({"check", "--json", "--mode", mode, "--out", out.string(), kSampleFile.string()});
    EXPECT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = parse_json(r);
    EXPECT_EQ(j.value("mode", ""), "filtered");
    EXPECT_EQ(j.value("false_positives", 1u), 0u);
    EXPECT_EQ(j.value("false_negatives", 1u), 0u);
    answers[mode] = read_text(out);
    EXPECT_FALSE(answers[mode].empty());

    const RunResult table = run({"check", "--mode", mode, kSampleFile.string()});
    EXPECT_EQ(table.status, 0) << table.err;
    EXPECT_EQ(table.out.rfind("mode: filtered", 0), 0u) << table.out;
  }
  EXPECT_EQ(answers["filtered"], answers["default"]);  // identical verdicts and TOIs
  // Without --mode: filtered.
  EXPECT_EQ(parse_json(run({"check", "--json", kSampleFile.string()})).value("mode", ""),
            "filtered");
  const RunResult help = run({"check", "--help"});
  EXPECT_EQ(help.status, 0) << help.err;
  EXPECT_NE(help.out.find("filtered"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("'default' is accepted as the old name of"), std::string::npos)
      << help.out;
  // bench --modes takes the alias too, and prints the canonical name.
  const RunResult bench = run({"bench", "--json", "--repetitions", "1", "--modes",
                               "default,exact", kSampleFile.string()});
  EXPECT_EQ(bench.status, 0) << bench.err;
  const nlohmann::json b = parse_json(bench);
  ASSERT_TRUE(b.is_array() && b.size() == 2u) << bench.out;
  EXPECT_EQ(b[0].value("mode", ""), "filtered");
  EXPECT_EQ(b[1].value("mode", ""), "exact");
}

// ---- bench ---------------------------------------------------------------------------------

// The keys every bench JSON object has, with their types.
void expect_bench_object(const nlohmann::json& j) {
  EXPECT_TRUE(j.at("dataset").is_string());
  EXPECT_TRUE(j.at("mode").is_string());
  EXPECT_TRUE(j.at("queries").is_number_unsigned());
  EXPECT_TRUE(j.at("mean_ns").is_number());
  EXPECT_TRUE(j.at("median_ns").is_number());
  EXPECT_TRUE(j.at("max_ns").is_number());
  // max_ns is the slowest query re-timed (its fastest repeat), the median one of single timings
  // on a busy machine: no order between them can be asserted (timings are not tested).
  EXPECT_GT(j.at("max_ns").get<double>(), 0.0);
  EXPECT_TRUE(j.at("false_positives").is_number_unsigned());
  EXPECT_TRUE(j.at("false_negatives").is_number_unsigned());
  EXPECT_TRUE(j.at("stage_share").is_object());
  EXPECT_GT(j.at("mean_ns").get<double>(), 0.0);
  stage_counts(j);
}

TEST_F(CliTest, BenchJsonOnOneFileHasOneObjectPerMode) {
  const std::vector<bool> truth = read_truth_column(kSampleFile);
  const RunResult r = run({"bench", "--json", "--repetitions", "1", kSampleFile.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = parse_json(r);
  ASSERT_TRUE(j.is_array()) << r.out;
  ASSERT_EQ(j.size(), 3u) << r.out;
  const std::vector<std::string> modes = {"float_only", "filtered", "exact"};
  for (std::size_t k = 0; k < 3; ++k) {
    SCOPED_TRACE(modes[k]);
    expect_bench_object(j[k]);
    EXPECT_EQ(j[k].value("dataset", ""), kSampleFile.string());
    EXPECT_EQ(j[k].value("mode", ""), modes[k]);
    EXPECT_EQ(j[k].value("queries", 0u), truth.size());
    if (modes[k] != "float_only") {
      EXPECT_EQ(j[k].value("false_positives", 1u), 0u);
      EXPECT_EQ(j[k].value("false_negatives", 1u), 0u);
    }
  }
  EXPECT_EQ(j[0].at("stage_share").value("float_only", 0.0), 1.0);
  EXPECT_EQ(j[2].at("stage_share").value("exact", 0.0), 1.0);
}

TEST_F(CliTest, BenchSimulationIsDecidedExactlyByTheFilteredMode) {
  const RunResult r = run({"bench", "--json", "--repetitions", "1", "--modes", "filtered",
                           "--simulation", "--resolution", "4", "--steps", "8"});
  EXPECT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = parse_json(r);
  ASSERT_TRUE(j.is_array() && j.size() == 1u) << r.out;
  expect_bench_object(j[0]);
  EXPECT_EQ(j[0].value("dataset", ""), "simulation");
  EXPECT_EQ(j[0].value("mode", ""), "filtered");
  EXPECT_GT(j[0].value("queries", 0u), 0u);
  EXPECT_EQ(j[0].value("false_positives", 1u), 0u);
  EXPECT_EQ(j[0].value("false_negatives", 1u), 0u);
}

TEST_F(CliTest, BenchWithoutPathRunsTheSampleQueries) {
  const RunResult r = run({"bench", "--repetitions", "1", "--modes", "exact"});
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string sample_line = std::string(EXACTCCD_SAMPLE_QUERIES) + ": 5029 queries";
  EXPECT_NE(r.out.find(sample_line), std::string::npos) << r.out;
}

TEST_F(CliTest, BenchRejectsBadCommandLine) {
  expect_bad_input(run({"bench", "--modes", "fast", kSampleFile.string()}),
                   {"--modes", "'fast'", "\"float_only\"", "\"filtered\"", "\"exact\""});
  expect_bad_input(run({"bench", "--modes", "filtered,fast", kSampleFile.string()}),
                   {"--modes", "'fast'"});
  expect_bad_input(run({"bench", "--repetitions", "0", kSampleFile.string()}), {"--repetitions"});
  expect_bad_input(run({"bench", "--resolution", "8", kSampleFile.string()}),
                   {"--resolution", "--simulation"});
  const fs::path missing = dir_ / "missing";
  expect_bad_input(run({"bench", missing.string()}), {missing.string()});
}

TEST_F(CliTest, BenchRigidTimesBothModesWithoutDisagreement) {
  const RunResult r = run({"bench", "--rigid", "--rigid-count", "60", "--seed", "3",
                           "--repetitions", "1", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = parse_json(r);
  ASSERT_TRUE(j.is_object()) << r.out;
  EXPECT_EQ(j.value("queries", 0u), 60u);
  EXPECT_EQ(j.value("vertex_face", 0u), 30u);
  EXPECT_EQ(j.value("edge_edge", 0u), 30u);
  EXPECT_EQ(j.value("seed", 0u), 3u);
  EXPECT_EQ(j.value("disagreements", 1u), 0u);
  EXPECT_TRUE(j.at("mean_ratio_filtered_over_exact").is_number());
  const nlohmann::json& modes = j.at("modes");
  ASSERT_EQ(modes.size(), 2u) << r.out;
  EXPECT_EQ(modes[0].value("mode", ""), "filtered");
  EXPECT_EQ(modes[1].value("mode", ""), "exact");
  for (const nlohmann::json& m : modes) {
    EXPECT_GT(m.value("mean_ns", 0.0), 0.0);
    EXPECT_TRUE(m.at("median_ns").is_number());
    double shares = 0;
    for (const auto& share : m.at("stage_share").items()) shares += share.value().get<double>();
    EXPECT_NEAR(shares, 1.0, 1e-12);
  }
  // Both modes find the same contacts (some, not all), and the filtered mode decides most of
  // them in floating point.
  EXPECT_EQ(modes[0].value("contacts", 0u), modes[1].value("contacts", 1u));
  EXPECT_GT(modes[0].value("contacts", 0u), 0u);
  EXPECT_LT(modes[0].value("contacts", 60u), 60u);
  EXPECT_EQ(modes[1].at("stage_share").value("exact", 0.0), 1.0);
  EXPECT_GT(modes[0].at("stage_share").value("filter", 0.0), 0.5);

  const RunResult text = run({"bench", "--rigid", "--rigid-count", "12", "--repetitions", "1",
                              "--modes", "filtered,exact"});
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("filtered / exact: mean"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("12 queries (6 vertex-face, 6 edge-edge"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("disagreements between modes (verdict, toi_lo, toi_hi): 0"),
            std::string::npos)
      << text.out;
}

TEST_F(CliTest, BenchBarrierStepsRunsTheTrialStepsThroughTheScene) {
  // Two small steps as JSON lines: earliest_contact checked against find_contacts' earliest
  // (exit status 0); the resting step's earliest contact is at t = 0.
  const RunResult r = run({"bench", "--barrier-steps", "--barrier-scale", "0.02", "--barrier-step",
                           "resting_slide", "--barrier-step", "twisted_rods", "--repetitions", "1",
                           "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  std::vector<nlohmann::json> steps;
  while (std::getline(lines, line)) steps.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(steps.size(), 2u) << r.out;
  EXPECT_EQ(steps[0].value("step", ""), "resting_slide");
  EXPECT_EQ(steps[1].value("step", ""), "twisted_rods");
  EXPECT_EQ(steps[0].value("earliest", 1.0), 0.0);

  for (const nlohmann::json& s : steps) {
    EXPECT_GT(s.value("candidates", 0u), 0u);
    EXPECT_GT(s.value("contacts", 0u), 0u);
    EXPECT_EQ(s.at("earliest_contact_ms").size(), 2u);
  }
  // Options of other benchmarks, a second delta, an unknown step: bad command lines.
  expect_bad_input(run({"bench", "--barrier-steps", "--rigid-count", "5"}),
                   {"--rigid-count", "--barrier-steps"});
  expect_bad_input(run({"bench", "--barrier-steps", "--min-separation", "0,0.1"}),
                   {"one --min-separation"});
  expect_bad_input(run({"bench", "--barrier-steps", "--min-separation", "-1"}),
                   {"minimum separation"});
  expect_bad_input(run({"bench", "--barrier-steps", "--barrier-step", "juggling"}),
                   {"--barrier-step"});
  expect_bad_input(run({"bench", "--barrier-scale", "0.1"}), {"--barrier-scale", "--barrier-steps"});
  expect_bad_input(run({"bench", "--barrier-steps", "--rigid"}), {"--rigid", "--barrier-steps"});
}

TEST_F(CliTest, BenchRigidGradesFloatOnlyAgainstTheCertifiedMode) {
  // float_only (uncertified) runs on rigid pairs too; it is graded against the first certified
  // mode and never counted as a disagreement (exit status 0). "default": the old name of
  // filtered, printed "filtered".
  const RunResult r = run({"bench", "--rigid", "--rigid-count", "30", "--seed", "3",
                           "--repetitions", "1", "--modes", "default,float_only", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = parse_json(r);
  ASSERT_TRUE(j.is_object()) << r.out;
  EXPECT_EQ(j.value("disagreements", 1u), 0u);
  const nlohmann::json& modes = j.at("modes");
  ASSERT_EQ(modes.size(), 2u) << r.out;
  EXPECT_EQ(modes[1].value("mode", ""), "float_only");
  EXPECT_EQ(modes[0].value("mode", ""), "filtered");
  EXPECT_EQ(modes[1].value("graded_against", ""), "filtered");
  EXPECT_TRUE(modes[1].at("false_positives").is_number());
  EXPECT_TRUE(modes[1].at("false_negatives").is_number());
  EXPECT_TRUE(modes[1].at("late_tois").is_number());
  EXPECT_EQ(modes[1].at("stage_share").value("float_only", 0.0), 1.0);
  EXPECT_EQ(modes[0].at("stage_share").value("float_only", 1.0), 0.0);
  const RunResult text = run({"bench", "--rigid", "--rigid-count", "12", "--repetitions", "1",
                              "--modes", "exact,float_only"});
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("float_only against exact"), std::string::npos) << text.out;
}

TEST_F(CliTest, BenchRigidRejectsBadCommandLine) {
  expect_bad_input(run({"bench", "--rigid", kSampleFile.string()}), {"--rigid", "PATH"});
  expect_bad_input(run({"bench", "--rigid-count", "10"}), {"--rigid-count", "--rigid"});
  expect_bad_input(run({"bench", "--rigid", "--rigid-count", "0"}), {"--rigid-count"});
  expect_bad_input(run({"bench", "--rigid", "--resolution", "4"}), {"--resolution"});
}

// ---- grade: results ------------------------------------------------------------------------

TEST_F(CliTest, GradeAnswersFromTruthColumnAreAllCorrect) {
  const std::vector<bool> truth = read_truth_column(kSampleFile);
  std::string answers;
  for (const bool t : truth) answers += t ? "1\n" : "0\n";
  const fs::path answers_file = write_file("answers.txt", answers);
  const RunResult r = run(
      {"grade", "--json", "--queries", kSampleFile.string(), "--answers", answers_file.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = parse_json(r);
  EXPECT_EQ(j.value("queries", 0u), truth.size());
  EXPECT_EQ(j.value("false_positives", 1u), 0u);
  EXPECT_EQ(j.value("false_negatives", 1u), 0u);
  EXPECT_EQ(j.value("non_conservative_tois", 1u), 0u);
}

TEST_F(CliTest, GradeReportsFlippedAnswerAtItsIndex) {
  const std::vector<bool> truth = read_truth_column(kSampleFile);
  for (const bool flipped_truth : {true, false}) {
    SCOPED_TRACE(flipped_truth);
    // Flip the last query whose truth is `flipped_truth` (not index 0: indices are 0-based).
    const std::size_t k = truth.rend() - std::find(truth.rbegin(), truth.rend(), flipped_truth) - 1;
    ASSERT_LT(k, truth.size());
    std::string answers;
    for (std::size_t i = 0; i < truth.size(); ++i) answers += truth[i] != (i == k) ? "1\n" : "0\n";
    const fs::path answers_file = write_file("answers.txt", answers);
    const RunResult r = run(
        {"grade", "--json", "--queries", kSampleFile.string(), "--answers", answers_file.string()});
    EXPECT_EQ(r.status, 1) << r.err;
    const nlohmann::json j = parse_json(r);
    const std::vector<std::size_t> expected = {k}, none = {};
    EXPECT_EQ(indices(j, "false_negative_indices"), flipped_truth ? expected : none);
    EXPECT_EQ(indices(j, "false_positive_indices"), flipped_truth ? none : expected);
    EXPECT_EQ(j.value("false_negatives", 9u), flipped_truth ? 1u : 0u);
    EXPECT_EQ(j.value("false_positives", 9u), flipped_truth ? 0u : 1u);
    EXPECT_EQ(j.value("non_conservative_tois", 9u), 0u);
  }
}

TEST_F(CliTest, GradeTextListsFirstTwentyIndicesAndCount) {
  const std::vector<bool> truth = read_truth_column(kSampleFile);
  std::vector<std::size_t> colliding;
  for (std::size_t i = 0; i < truth.size(); ++i)
    if (truth[i]) colliding.push_back(i);
  ASSERT_GT(colliding.size(), 20u);
  std::string all_zero;
  for (std::size_t i = 0; i < truth.size(); ++i) all_zero += "0\n";
  const fs::path answers_file = write_file("answers.txt", all_zero);
  const RunResult r =
      run({"grade", "--queries", kSampleFile.string(), "--answers", answers_file.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  std::string expected = "false negatives: " + std::to_string(colliding.size()) + "  (queries";
  for (std::size_t i = 0; i < 20; ++i) expected += " " + std::to_string(colliding[i]);
  expected += " ... and " + std::to_string(colliding.size() - 20) + " more)";
  EXPECT_NE(r.out.find(expected + "\n"), std::string::npos) << "want: " << expected << "\n"
                                                            << r.out;
}

TEST_F(CliTest, GradeFlagsOnlyTheToiLaterThanContact) {
  // t* = 1/2 exactly: a toi of 0.5 or 0.25 is conservative, 1 or the next double after 0.5 not.
  for (const char* ok : {"1,0.5", "1,0.25", "1,0", "1,-0"}) {
    SCOPED_TRACE(ok);
    const RunResult r = grade(std::string(ok) + "\n1\n0\n");
    EXPECT_EQ(r.status, 0) << r.err << r.out;
    EXPECT_EQ(parse_json(r).value("non_conservative_tois", 9u), 0u);
  }
  char just_after_half[64];
  std::snprintf(just_after_half, sizeof just_after_half, "1,%.17g", std::nextafter(0.5, 1.0));
  for (const std::string late :
       {std::string("1,1"), std::string("1,0.75"), std::string(just_after_half)}) {
    SCOPED_TRACE(late);
    const RunResult r = grade(late + "\n1\n0\n");
    EXPECT_EQ(r.status, 1) << r.err;
    const nlohmann::json j = parse_json(r);
    EXPECT_EQ(indices(j, "non_conservative_toi_indices"), std::vector<std::size_t>{0});
    EXPECT_EQ(j.value("false_positives", 9u), 0u);
    EXPECT_EQ(j.value("false_negatives", 9u), 0u);
  }
}

TEST_F(CliTest, GradeJudgesToiAroundNonDyadicContactExactly) {
  // t* = 1/3 is no double: the largest double below it is conservative, the next one is not.
  const mpq_class third(1, 3);
  double below = 1.0 / 3.0;
  if (mpq_class(below) > third) below = std::nextafter(below, 0.0);
  const double above = std::nextafter(below, 1.0);
  ASSERT_LT(mpq_class(below), third);
  ASSERT_GT(mpq_class(above), third);
  char below_line[64], above_line[64];
  std::snprintf(below_line, sizeof below_line, "1,%.17g", below);
  std::snprintf(above_line, sizeof above_line, "1,%.17g", above);

  const RunResult ok = grade(std::string("1\n") + below_line + "\n0\n");
  EXPECT_EQ(ok.status, 0) << ok.err << ok.out;
  const RunResult late = grade(std::string("1\n") + above_line + "\n0\n");
  EXPECT_EQ(late.status, 1) << late.err;
  EXPECT_EQ(indices(parse_json(late), "non_conservative_toi_indices"), std::vector<std::size_t>{1});
}

TEST_F(CliTest, GradeUsesTMax) {
  // With t_max = 0.4 the contact at 1/2 is out of range and the one at 1/3 still in.
  const RunResult right = grade("0\n1,0.3\n0\n", {"--t-max", "0.4"});
  EXPECT_EQ(right.status, 0) << right.err << right.out;
  const RunResult wrong = grade("1\n1\n0\n", {"--t-max", "0.4"});
  EXPECT_EQ(wrong.status, 1) << wrong.err;
  EXPECT_EQ(indices(parse_json(wrong), "false_positive_indices"), std::vector<std::size_t>{0});
}

}  // namespace
