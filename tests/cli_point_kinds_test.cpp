// `exactccd check --type pe|pe2d|pp|pp2d|pl`: query files of the point kinds and the plane
// (query_file.hpp, PrimitiveKind; rows documented in README.md), decided by their own functions
// and compared with the truth column. Hand-made queries whose contact times are worked out by
// hand (the --out file's TOIs are checked), a wrong truth (exit status 1), malformed files and
// the errors particular to these kinds.
#include "cli_fixture.hpp"

namespace cli_test {
namespace {

// Point-edge: p from (1/2, 1, 0) to (1/2, -1, 0) across the segment [(0,0,0), (1,0,0)] (t* =
// 1/2), and beside its end from x = 3/2 (never).
const std::string kPointEdge =
    "1,2,1,1,0,1,1\n0,1,0,1,0,1,1\n1,1,0,1,0,1,1\n1,2,-1,1,0,1,1\n0,1,0,1,0,1,1\n1,1,0,1,0,1,1\n"
    "\n"
    "3,2,1,1,0,1,0\n0,1,0,1,0,1,0\n1,1,0,1,0,1,0\n3,2,-1,1,0,1,0\n0,1,0,1,0,1,0\n1,1,0,1,0,1,0\n";
// The same in the plane (5 columns).
const std::string kPointEdge2d =
    "1,2,1,1,1\n0,1,0,1,1\n1,1,0,1,1\n1,2,-1,1,1\n0,1,0,1,1\n1,1,0,1,1\n"
    "3,2,1,1,0\n0,1,0,1,0\n1,1,0,1,0\n3,2,-1,1,0\n0,1,0,1,0\n1,1,0,1,0\n";
// Point-point: p from (0,0) to (4,0), q at (1,0): t* = 1/4; then p 2^-60 above: never.
const std::string kPointPoint2d =
    "0,1,0,1,1\n1,1,0,1,1\n4,1,0,1,1\n1,1,0,1,1\n"
    "0,1,1,1152921504606846976,0\n1,1,0,1,0\n4,1,1,1152921504606846976,0\n1,1,0,1,0\n";
const std::string kPointPoint =
    "0,1,0,1,5,1,1\n1,1,0,1,5,1,1\n4,1,0,1,5,1,1\n1,1,0,1,5,1,1\n";
// Point-plane: (5,7,1) to (-3,2,-1) onto the floor z = 0 (t* = 1/2); a plane rising from
// z = -1 to 1 under a point at rest at z = 1/2 (t* = 3/4); a point that stays above (never).
const std::string kPointPlane =
    "5,1,7,1,1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n-3,1,2,1,-1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n"
    "0,1,0,1,1,2,1\n0,1,0,1,-1,1,1\n0,1,0,1,1,1,1\n0,1,0,1,1,2,1\n0,1,0,1,1,1,1\n0,1,0,1,1,1,1\n"
    "0,1,0,1,1,1,0\n0,1,0,1,0,1,0\n0,1,0,1,1,1,0\n1,1,0,1,1,2,0\n0,1,0,1,0,1,0\n0,1,0,1,1,1,0\n";

TEST_F(CliTest, CheckDecidesEveryPointKindWithItsOwnFunction) {
  struct Case {
    const char* type;
    const std::string* text;
    std::vector<std::string> tois;  // toi_lo of each query ("inf": none)
  };
  const Case cases[] = {{"pe", &kPointEdge, {"0.5", "inf"}},
                        {"pe2d", &kPointEdge2d, {"0.5", "inf"}},
                        {"pp", &kPointPoint, {"0.25"}},
                        {"pp2d", &kPointPoint2d, {"0.25", "inf"}},
                        {"pl", &kPointPlane, {"0.5", "0.75", "inf"}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.type);
    const fs::path file = write_file(std::string(c.type) + ".csv", *c.text);
    const fs::path out = dir_ / (std::string(c.type) + ".out");
    for (const char* mode : {"filtered", "exact"}) {
      if (std::string(c.type) == "pl" && std::string(mode) == "exact") continue;
      const RunResult r = run({"check", "--type", c.type, "--mode", mode, "--json", "--force",
                               "--out", out.string(), file.string()});
      ASSERT_EQ(r.status, 0) << r.err;
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["queries"].get<int>(), static_cast<int>(c.tois.size()));
      const std::vector<std::string> lines = lines_of(read_text(out));
      ASSERT_EQ(lines.size(), c.tois.size());
      for (std::size_t i = 0; i < lines.size(); ++i)
        EXPECT_EQ(split(lines[i], ',').at(3), c.tois[i]) << lines[i];
    }
  }
}

TEST_F(CliTest, CheckOfAPointKindCountsAWrongTruth) {
  // The crossing query's truth set to 0: a false positive, exit status 1.
  std::string text = kPointEdge;
  for (std::size_t line = 1; line <= 6; ++line) {
    const std::string row = lines_of(text)[line - 1];
    text = replace_line(text, line, row.substr(0, row.size() - 1) + "0");
  }
  const fs::path file = write_file("pe.csv", text);
  const RunResult r = run({"check", "--type", "pe", "--json", file.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["false_positives"].get<int>(), 1);
}

TEST_F(CliTest, CheckOfAPointKindRejectsBadFiles) {
  // A 2D file read as 3D, a 3D file as 2D, a query cut short, a folder, a zero plane normal,
  // a rational coordinate outside --mode exact and in a plane query.
  expect_bad_input(run({"check", "--type", "pe", write_file("a.csv", kPointEdge2d).string()}),
                   {"a.csv:1:", "expected 7 comma-separated columns"});
  expect_bad_input(run({"check", "--type", "pe2d", write_file("b.csv", kPointEdge).string()}),
                   {"b.csv:1:",
                    "expected 5 comma-separated columns (x_num,x_den,y_num,y_den,truth)"});
  const fs::path cut = write_file("c.csv", kPointPoint + "0,1,0,1,0,1,1\n");
  expect_bad_input(run({"check", "--type", "pp", cut.string()}),
                   {"c.csv:5:", "query cut short: 1 rows in the last query (4 per query)"});
  expect_bad_input(run({"check", "--type", "pl", dir_.string()}),
                   {"is a directory, not a query file of --type pl"});
  const std::string zero_normal = replace_line(kPointPlane, 3, "0,1,0,1,0,1,1");
  expect_bad_input(run({"check", "--type", "pl", write_file("d.csv", zero_normal).string()}),
                   {"d.csv:1:", "normal_t0 is zero"});
  const std::string third = replace_line(kPointEdge, 1, "1,3,1,1,0,1,1");
  const fs::path rational = write_file("e.csv", third);
  expect_bad_input(run({"check", "--type", "pe", rational.string()}),
                   {"e.csv:1:", "only --mode exact decides such queries"});
  EXPECT_EQ(run({"check", "--type", "pe", "--mode", "exact", rational.string()}).status, 0);
  const fs::path plane = write_file("f.csv", replace_line(kPointPlane, 1, "5,3,7,1,1,1,1"));
  expect_bad_input(run({"check", "--type", "pl", "--mode", "exact", plane.string()}),
                   {"f.csv:1:", "point-plane queries are decided on doubles only"});
}

TEST_F(CliTest, GradeTakesThePointKindsAsTheirEdgeEdgeQueries) {
  // The crossing point-edge query answered at 1/2 (exact, conservative) or 3/4 (late), the
  // other one answered 0; the 2D point-point file's first query answered with no contact.
  const fs::path pe = write_file("pe.csv", kPointEdge);
  const RunResult good = run({"grade", "--type", "pe", "--queries", pe.string(), "--answers",
                              write_file("good.txt", "1,0.5\n0\n").string()});
  EXPECT_EQ(good.status, 0) << good.err;
  const RunResult late = run({"grade", "--type", "pe", "--json", "--queries", pe.string(),
                              "--answers", write_file("late.txt", "1,0.75\n0\n").string()});
  EXPECT_EQ(late.status, 1) << late.err;
  EXPECT_EQ(nlohmann::json::parse(late.out)["non_conservative_tois"].get<int>(), 1) << late.out;
  const fs::path pp = write_file("pp.csv", kPointPoint2d);
  const RunResult missed = run({"grade", "--type", "pp2d", "--json", "--queries", pp.string(),
                                "--answers", write_file("missed.txt", "0\n0\n").string()});
  EXPECT_EQ(missed.status, 1) << missed.err;
  EXPECT_EQ(nlohmann::json::parse(missed.out)["false_negatives"].get<int>(), 1) << missed.out;
}

TEST_F(CliTest, GradeJudgesPointPlaneAnswersAgainstTheExactPath) {
  // kPointPlane (t* = 1/2, 3/4, none) and a fall from z = 1 to z = -2 onto the floor: t* = 1/3,
  // not a double, so a TOI between its enclosing doubles is judged exactly.
  const fs::path pl = write_file(
      "pl.csv", kPointPlane +
                    "0,1,0,1,1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n0,1,0,1,-2,1,1\n0,1,0,1,0,1,1\n"
                    "0,1,0,1,1,1,1\n");
  const RunResult good = run({"grade", "--type", "pl", "--queries", pl.string(), "--answers",
                              write_file("good.txt", "1,0.5\n1,0.75\n0\n1,0.33333333333333333\n")
                                  .string()});
  EXPECT_EQ(good.status, 0) << good.out << good.err;
  const RunResult bad = run(
      {"grade", "--type", "pl", "--json", "--queries", pl.string(), "--answers",
       write_file("bad.txt", "1,0.5000000001\n1,0.7\n1\n1,0.333333333333333334\n").string()});
  EXPECT_EQ(bad.status, 1) << bad.err;
  const auto j = nlohmann::json::parse(bad.out);
  EXPECT_EQ(j["non_conservative_tois"].get<int>(), 2) << bad.out;  // queries 0 and 3
  EXPECT_EQ(j["false_positives"].get<int>(), 1) << bad.out;        // query 2
  EXPECT_EQ(j["false_negatives"].get<int>(), 0) << bad.out;
}

TEST_F(CliTest, BenchTimesThePointKinds) {
  const fs::path pe = write_file("pe.csv", kPointEdge);
  const RunResult r = run({"bench", "--type", "pe", "--json", "--repetitions", "1", "--modes",
                           "filtered,exact", pe.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // one object per data set and mode
  ASSERT_EQ(j.size(), 2u) << r.out;
  for (const auto& result : j) {
    EXPECT_EQ(result["queries"].get<int>(), 2);
    EXPECT_EQ(result["false_positives"].get<int>(), 0);
    EXPECT_EQ(result["false_negatives"].get<int>(), 0);
  }
  // Point-plane files are timed as point_plane_ccd calls, every mode against the truth column.
  const RunResult pl = run({"bench", "--type", "pl", "--json", "--repetitions", "1", "--modes",
                            "filtered,exact,float_only",
                            write_file("pl.csv", kPointPlane).string()});
  ASSERT_EQ(pl.status, 0) << pl.err;
  const auto planes = nlohmann::json::parse(pl.out);
  ASSERT_EQ(planes.size(), 3u) << pl.out;
  for (const auto& result : planes) {
    EXPECT_EQ(result["queries"].get<int>(), 3);
    if (result["mode"] != "float_only") {
      EXPECT_EQ(result["false_positives"].get<int>(), 0);
      EXPECT_EQ(result["false_negatives"].get<int>(), 0);
    }
  }
  const RunResult wrong = run({"bench", "--type", "pl", "--repetitions", "1",
                               write_file("wrong.csv", "0,1,0,1,1,1,0\n0,1,0,1,0,1,0\n"
                                                       "0,1,0,1,1,1,0\n0,1,0,1,-1,1,0\n"
                                                       "0,1,0,1,0,1,0\n0,1,0,1,1,1,0\n")
                                   .string()});
  EXPECT_EQ(wrong.status, 1) << wrong.out << wrong.err;  // a truth column that is wrong
  expect_bad_input(run({"bench", "--type", "pl",
                        write_file("zero.csv", "0,1,0,1,1,1,0\n0,1,0,1,0,1,0\n"
                                               "0,1,0,1,0,1,0\n0,1,0,1,-1,1,0\n"
                                               "0,1,0,1,0,1,0\n0,1,0,1,0,1,0\n")
                            .string()}),
                   {"zero.csv:1", "zero normal"});
}

TEST_F(CliTest, GenerateWritesThePointKindsFamiliesThatCheckAgrees) {
  for (const char* type : {"pe", "pe2d", "pp", "pp2d", "pl"}) {
    SCOPED_TRACE(type);
    const fs::path out = dir_ / (std::string("families_") + type);
    const RunResult r =
        run({"generate", "--type", type, "--per-family", "8", "--out", out.string()});
    ASSERT_EQ(r.status, 0) << r.err;
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
      ++files;
      // The truth column (the exact verdicts) agrees with the filtered path: exit status 0.
      const RunResult c = run({"check", "--type", type, entry.path().string()});
      EXPECT_EQ(c.status, 0) << entry.path() << c.out << c.err;
    }
    EXPECT_GE(files, 4u);
    // Nothing is overwritten without --force; then it is.
    const RunResult again =
        run({"generate", "--type", type, "--per-family", "8", "--out", out.string()});
    EXPECT_EQ(again.status, 2) << again.err;
    EXPECT_EQ(run({"generate", "--type", type, "--per-family", "8", "--out", out.string(),
                   "--force"}).status, 0);
  }
  const RunResult unknown = run({"generate", "--type", "pe", "--families", "vf_interior",
                                 "--out", (dir_ / "x").string()});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("pe_through_endpoint"), std::string::npos) << unknown.err;
  const RunResult separation = run({"generate", "--type", "pl", "--min-separation", "0.5",
                                    "--out", (dir_ / "y").string()});
  EXPECT_EQ(separation.status, 2);
  EXPECT_NE(separation.err.find("not with --type"), std::string::npos) << separation.err;
}

}  // namespace
}  // namespace cli_test
