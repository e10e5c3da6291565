// `exactccd inspect`, `grade --html` and `generate --html`: what they write and what they
// refuse (an index past the end, a file of the wrong kind, an output that exists). What the
// pages do in a browser is tests/browser's job.
#include "cli_fixture.hpp"

namespace cli_test {
namespace {

class CliInspectTest : public CliTest {};

TEST_F(CliInspectTest, WritesThePageAndPrintsTheSummary) {
  const fs::path queries = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path page = dir_ / "q1.html";
  const RunResult r = run({"inspect", queries.string(), "--index", "1", "--html", page.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("collides, toi [0.33333333333333331, 0.33333333333333337]"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("inside (earliest contact)"), std::string::npos) << r.out;
  const std::string html = read_text(page);
  EXPECT_NE(html.find("exactccd-inspection"), std::string::npos);
  EXPECT_EQ(html.find("<script src="), std::string::npos);  // self-contained

  // --json: the page's data.
  const nlohmann::json doc =
      parse_json(run({"inspect", queries.string(), "--index", "0", "--json"}));
  EXPECT_EQ(doc["result"]["toi_lo"].get<double>(), 0.5);
  EXPECT_EQ(doc["source"]["first_line"].get<int>(), 1);
  const nlohmann::json never =
      parse_json(run({"inspect", queries.string(), "--index", "2", "--json", "--mode", "exact"}));
  EXPECT_FALSE(never["result"]["collides"].get<bool>());
  EXPECT_TRUE(never["result"]["toi_lo"].is_null());
  EXPECT_EQ(never["result"]["mode"], "exact");
}

TEST_F(CliInspectTest, RefusesToOverwriteWithoutForce) {
  const fs::path queries = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path page = write_file("page.html", "a user's file\n");
  expect_bad_input(run({"inspect", queries.string(), "--html", page.string()}),
                   {page.string(), "--force"});
  EXPECT_EQ(read_text(page), "a user's file\n");
  ASSERT_EQ(run({"inspect", queries.string(), "--html", page.string(), "--force"}).status, 0);
  EXPECT_NE(read_text(page).find("exactccd-inspection"), std::string::npos);
  // A folder in the page's place is refused too.
  fs::create_directory(dir_ / "folder.html");
  expect_bad_input(run({"inspect", queries.string(), "--html", (dir_ / "folder.html").string(),
                        "--force"}),
                   {"folder.html"});
}

TEST_F(CliInspectTest, BadInput) {
  const fs::path queries = write_file("vertex-face/q.csv", kHalfThirdNever);
  expect_bad_input(run({"inspect", queries.string(), "--index", "3"}),
                   {queries.string(), "past the end", "3 queries"});
  expect_bad_input(run({"inspect", queries.string(), "--index", "-1"}), {"--index"});
  expect_bad_input(run({"inspect", queries.string(), "--index", "x"}), {"--index"});
  // A file of the wrong kind: JSON, a scene file, a folder, a missing file.
  const fs::path scene = write_file("vertex-face/scene.json", "{\"bodies\": []}\n");
  expect_bad_input(run({"inspect", scene.string()}), {scene.string()});
  expect_bad_input(run({"inspect", (dir_ / "vertex-face").string()}), {"vertex-face"});
  expect_bad_input(run({"inspect", (dir_ / "missing.csv").string(), "--type", "vf"}),
                   {"missing.csv"});
  // No type from the folder name.
  const fs::path untyped = write_file("q.csv", kHalfThirdNever);
  expect_bad_input(run({"inspect", untyped.string()}), {"q.csv"});
  // A coordinate that is not a double needs --mode exact.
  const fs::path third =
      write_file("vertex-face/third.csv", replace_line(kHalfThirdNever, 1, "1,3,1,4,1,1,1"));
  expect_bad_input(run({"inspect", third.string()}), {"not a double", "--mode exact"});
  EXPECT_EQ(run({"inspect", third.string(), "--mode", "exact"}).status, 0);
  expect_bad_input(run({"inspect", queries.string(), "--min-separation", "-1", "--html",
                        (dir_ / "out.html").string()}),
                   {"--min-separation"});
  expect_bad_input(run({"inspect", queries.string(), "--index", "7", "--html",
                        (dir_ / "out.html").string()}),
                   {"past the end"});
  EXPECT_FALSE(fs::exists(dir_ / "out.html"));  // refused before anything is written
  expect_bad_input(run({"inspect", queries.string(), "--html", ""}), {"--html", "empty"});
  const fs::path empty = write_file("vertex-face/empty.csv", "");
  expect_bad_input(run({"inspect", empty.string()}), {"no query"});
  // A coordinate beyond the doubles: decided exactly, float_only not run (no double query).
  const fs::path huge = write_file(
      "vertex-face/huge.csv",
      replace_line(kHalfThirdNever, 1, "1,4,1,4,1" + std::string(400, '0') + ",1,1"));
  const RunResult beyond = run({"inspect", huge.string(), "--mode", "exact", "--json"});
  ASSERT_EQ(beyond.status, 0) << beyond.err;
  EXPECT_TRUE(parse_json(beyond)["float_only"].is_null());
  // A file name that is not UTF-8 is carried, not fatal.
  const fs::path odd = write_file("vertex-face/odd\xff.csv", kHalfThirdNever);
  EXPECT_EQ(run({"inspect", odd.string(), "--json"}).status, 0);
}

TEST_F(CliInspectTest, GradeReportLinksAPagePerFinding) {
  // Query 0 right, query 1 a false negative, query 2 a false positive.
  const fs::path queries = write_file("vertex-face/queries.csv", kHalfThirdNever);
  const fs::path answers = write_file("answers.txt", "1,0.5\n0\n1,0.25\n");
  const fs::path report = dir_ / "report.html";
  const std::vector<std::string> args = {"grade",          "--queries", queries.string(),
                                         "--answers",      answers.string(), "--html",
                                         report.string()};
  const RunResult r = run(args);
  ASSERT_EQ(r.status, 1) << r.err;  // findings
  const std::string html = read_text(report);
  EXPECT_NE(html.find("report_files/query_1.html"), std::string::npos);
  EXPECT_NE(html.find("report_files/query_2.html"), std::string::npos);
  EXPECT_EQ(html.find("report_files/query_0.html"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "report_files" / "query_1.html"));
  EXPECT_TRUE(fs::exists(dir_ / "report_files" / "scripts" / "three.min.js"));
  const std::string page = read_text(dir_ / "report_files" / "query_2.html");
  EXPECT_NE(page.find("\"finding\":\"false positive\""), std::string::npos);
  EXPECT_NE(page.find("\"toi_exact\":\"1/4\""), std::string::npos);

  // Again: the report and its folder exist; refused without --force, nothing touched.
  fs::remove(report);
  expect_bad_input(run(args), {"report_files", "--force"});
  EXPECT_FALSE(fs::exists(report));
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  EXPECT_EQ(run(forced).status, 1);
  EXPECT_TRUE(fs::exists(report));
  expect_bad_input(run(args), {"report.html", "--force"});

  // Coordinates that are not doubles: graded, and their pages show the exact path.
  const fs::path thirds = write_file(
      "vertex-face/thirds.csv", replace_line(kHalfThirdNever, 17, "1,3,1,4,1,1,0"));
  const fs::path thirds_report = dir_ / "thirds.html";
  EXPECT_EQ(run({"grade", "--queries", thirds.string(), "--answers", answers.string(), "--html",
                 thirds_report.string()})
                .status,
            1);
  EXPECT_TRUE(fs::exists(dir_ / "thirds_files" / "query_2.html"));
  EXPECT_TRUE(fs::exists(thirds_report));

  // --html-limit 0: the tables and the count of what is not shown, no page.
  const fs::path limited = dir_ / "limited.html";
  std::vector<std::string> limit = {"grade",        "--queries",       queries.string(),
                                    "--answers",    answers.string(),  "--html",
                                    limited.string(), "--html-limit", "0"};
  EXPECT_EQ(run(limit).status, 1);
  EXPECT_NE(read_text(limited).find("1 more is not"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "limited_files" / "query_1.html"));
}

TEST_F(CliInspectTest, GenerateIndexesTheSuite) {
  const fs::path out = dir_ / "suite";
  const RunResult r = run({"generate", "--out", out.string(), "--families",
                           "vf_t0,ee_parallel@s1e-12", "--per-family", "8", "--html"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string index = read_text(out / "index.html");
  EXPECT_NE(index.find("inspect/vf_t0.html"), std::string::npos);
  EXPECT_NE(index.find("inspect/ee_parallel@s1e-12.html"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "inspect" / "vf_t0.html"));
  EXPECT_TRUE(fs::exists(out / "inspect" / "scripts" / "orbit_controls.js"));
  // Again with --html: the index exists, refused without --force.
  expect_bad_input(run({"generate", "--out", out.string(), "--families", "vf_t0", "--html"}),
                   {"--force"});
  EXPECT_EQ(run({"generate", "--out", out.string(), "--families", "vf_t0", "--html", "--force"})
                .status,
            0);
  expect_bad_input(run({"generate", "--out", (dir_ / "p").string(), "--type", "pe", "--html"}),
                   {"--html"});
}

TEST_F(CliInspectTest, RigidSceneStep) {
  const fs::path rigid = fs::path(EXACTCCD_TEST_DATA) / "rigid";
  const fs::path page = dir_ / "wall.html";
  const RunResult r = run({"inspect", (rigid / "cube_turns_into_wall.json").string(), "--html",
                           page.string(), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json doc = parse_json(r);
  EXPECT_EQ(doc["motion"], "samples");
  EXPECT_NE(doc["title"].get<std::string>().find("step 1"), std::string::npos);
  // s* = 2/3, as the scene file's comment works out.
  EXPECT_LE(doc["result"]["toi_lo"].get<double>(), 2.0 / 3.0);
  EXPECT_GE(doc["result"]["toi_hi"].get<double>(), 2.0 / 3.0);
  EXPECT_NE(read_text(page).find("exactccd-inspection"), std::string::npos);
  // The same as `exactccd rigid` reports.
  const nlohmann::json run_json =
      parse_json(run({"rigid", (rigid / "cube_turns_into_wall.json").string(), "--json"}));
  EXPECT_EQ(run_json["steps"][0]["contact"]["s_lo"], doc["result"]["toi_lo"]);
  EXPECT_EQ(run_json["steps"][0]["contact"]["s_hi"], doc["result"]["toi_hi"]);

  // A step out of range, a collision-free step or scene, --step on a CSV file.
  const std::string steps = (rigid / "cube_turns_in_steps.json").string();
  expect_bad_input(run({"inspect", steps, "--step", "99"}), {"--step 99", "not a step"});
  expect_bad_input(run({"inspect", steps, "--step", "1"}), {"step 1 is collision-free"});
  EXPECT_EQ(run({"inspect", steps, "--step", "2"}).status, 0);
  expect_bad_input(run({"inspect", (rigid / "cube_turns_clear_of_wall.json").string()}),
                   {"collision-free in every step"});
  const fs::path queries = write_file("vertex-face/q.csv", kHalfThirdNever);
  expect_bad_input(run({"inspect", queries.string(), "--step", "1"}), {"--step"});
  const fs::path broken = write_file("broken.json", "{\"bodies\": [");
  expect_bad_input(run({"inspect", broken.string()}), {"broken.json"});
  expect_bad_input(run({"inspect", steps, "--index", "1"}), {"--index"});
}

TEST_F(CliInspectTest, PointKindsAndPlanes) {
  // A point falling through the floor z = 0 from height 1 to -1: contact at t = 1/2.
  const fs::path floor = write_file("floor.csv",
                                    "1,4,1,4,1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n"
                                    "1,4,1,4,-1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n");
  const nlohmann::json plane =
      parse_json(run({"inspect", floor.string(), "--type", "pl", "--json"}));
  EXPECT_EQ(plane["kind"], "point_plane");
  EXPECT_EQ(plane["result"]["toi_lo"].get<double>(), 0.5);
  EXPECT_EQ(plane["polynomials"][0]["roots"][0]["exact"], "1/2");
  EXPECT_EQ(plane["plane_normal"]["exact"][0], nlohmann::json({"0", "0", "1"}));
  EXPECT_EQ(run({"inspect", floor.string(), "--type", "pl", "--html",
                 (dir_ / "floor.html").string()})
                .status,
            0);
  // A zero normal: bad input at its query's line.
  const fs::path zero = write_file("zero.csv",
                                   "1,4,1,4,1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,0,1,1\n"
                                   "1,4,1,4,-1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,0,1,1\n");
  expect_bad_input(run({"inspect", zero.string(), "--type", "pl"}), {"zero.csv:1"});
  // A point against a segment (pe): the edge-edge query of its zero-length segment.
  const fs::path pe = write_file("pe.csv",
                                 "1,2,1,1,0,1,1\n0,1,0,1,0,1,1\n1,1,0,1,0,1,1\n"
                                 "1,2,-1,1,0,1,1\n0,1,0,1,0,1,1\n1,1,0,1,0,1,1\n");
  const nlohmann::json point = parse_json(run({"inspect", pe.string(), "--type", "pe", "--json"}));
  EXPECT_EQ(point["kind"], "edge_edge");
  EXPECT_EQ(point["result"]["toi_lo"].get<double>(), 0.5);
  // A rigid cube tipping onto a floor plane: a point-plane contact of a rigid body.
  const nlohmann::json tips = parse_json(run(
      {"inspect", (fs::path(EXACTCCD_TEST_DATA) / "rigid" / "cube_tips_onto_floor.json").string(),
       "--json"}));
  EXPECT_EQ(tips["kind"], "point_plane");
  EXPECT_EQ(tips["motion"], "samples");
  EXPECT_TRUE(tips["result"]["collides"].get<bool>());
}

}  // namespace
}  // namespace cli_test
