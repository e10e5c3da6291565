// Tests of the `exactccd` command against hostile input and output: full devices, FIFOs,
// devices and link loops given as files, lines without end, control characters, empty files,
// existing outputs, failed and interrupted runs, manifests pointing outside their suite,
// decimal TOIs next to an exact contact time. Each runs the built binary (cli_fixture.hpp).
#include <fcntl.h>
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "cli_fixture.hpp"

extern char** environ;

namespace {

using namespace cli_test;

class CliRobustness : public CliTest {
 protected:
  // A command that could block or grow without bound before the fixes: bounded (see
  // CliTest::run_bounded), then it fails instead of hanging the suite.
  RunResult run_bounded(const std::vector<std::string>& args) {
    return CliTest::run_bounded(args, 30);
  }

  // Leftover temporaries of the atomic writer (".NAME.tmp-...") anywhere below dir_.
  std::vector<std::string> temporaries() {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir_))
      if (entry.path().filename().string().find(".tmp-") != std::string::npos)
        found.push_back(entry.path().string());
    return found;
  }

  // The three hand-made queries (t* = 1/2, 1/3, none) and answers for them.
  std::pair<fs::path, fs::path> grade_files(const std::string& answers) {
    return {write_file("vertex-face/queries.csv", kHalfThirdNever),
            write_file("answers.txt", answers)};
  }
};

std::size_t lines_in(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::vector<std::size_t> indices_of(const nlohmann::json& j, const char* key) {
  return j.contains(key) ? j.at(key).get<std::vector<std::size_t>>() : std::vector<std::size_t>{};
}

// ---- 1. Output lost to a full device is an error -------------------------------------------

TEST_F(CliRobustness, StdoutOnAFullDeviceExitsTwo) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const auto [queries, answers] = grade_files("1\n1\n0\n");
  const std::string small = queries.string();
  const std::vector<std::vector<std::string>> commands = {
      {"check", small},
      {"check", "--json", small},
      {"grade", "--queries", small, "--answers", answers.string()},
      {"bench", "--modes", "float_only", "--repetitions", "1", small},
      {"study", "--repetitions", "1", "--widths", "0", "--eps", "1e-9", small},
      {"simulate", "--out", (dir_ / "sim").string(), "--resolution", "2", "--steps", "1",
       "--truth", "none"},
      {"generate", "--out", (dir_ / "gen").string(), "--per-family", "7", "--families",
       "vf_interior"},
      {"inspect", small, "--index", "2"},
      {"--help"},
      {"check", "--help"}};
  for (const std::vector<std::string>& args : commands) {
    SCOPED_TRACE(args.front() + " " + args.back());
    const RunResult r = run_with(args, {"/dev/full", "", ""});
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(lines_in(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("exactccd: stdout: write failed: No space left on device", 0), 0u)
        << r.err;
  }
}

TEST_F(CliRobustness, OutputFileOnAFullDeviceExitsTwo) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"check", "--out", "/dev/full", file.string()},
        {"study", "--repetitions", "1", "--out-md", "/dev/full", file.string()}}) {
    SCOPED_TRACE(args.front());
    const RunResult r = run_with(args, {"/dev/null", "", ""});
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err, "exactccd: /dev/full: write failed: No space left on device\n");
  }
}

// ---- 2. Output files: no empty folder name, no overwrite without --force, never a deletion,
//         never a half-written file --------------------------------------------------------

TEST_F(CliRobustness, SimulateRejectsAnEmptyOutFolder) {
  const fs::path cwd = dir_ / "cwd";
  fs::create_directories(cwd);
  const RunResult r = run_with(
      {"simulate", "--out", "", "--resolution", "2", "--steps", "1", "--truth", "none"},
      {"", cwd.string(), ""});
  expect_bad_input(r, {"--out", "empty"});
  EXPECT_TRUE(fs::is_empty(cwd)) << "simulate wrote into the working directory";
}

TEST_F(CliRobustness, SimulateNeverDeletesAndReplacesOnlyWithForce) {
  const fs::path out = dir_ / "out";
  const fs::path earlier_vf = write_file("out/simulation/vertex-face/data_0.csv", "earlier\n");
  const fs::path earlier_ee = write_file("out/simulation/edge-edge/data_7.csv", "earlier\n");
  const std::vector<std::string> args = {"simulate",   "--out", out.string(), "--resolution",
                                         "2",          "--steps", "1",          "--truth",
                                         "none"};
  expect_bad_input(run(args), {earlier_vf.string(), "--force"});
  EXPECT_EQ(read_text(earlier_vf), "earlier\n");
  EXPECT_EQ(read_text(earlier_ee), "earlier\n");
  EXPECT_FALSE(fs::exists(out / "simulation" / "edge-edge" / "data_0.csv"));

  std::vector<std::string> forced = args;
  forced.push_back("--force");
  const RunResult r = run(forced);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_text(earlier_vf), "earlier\n");  // replaced by this run's queries
  EXPECT_EQ(read_text(earlier_ee), "earlier\n");  // not this run's: kept, and named
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(earlier_ee.string()), std::string::npos) << r.err;
  EXPECT_EQ(temporaries(), std::vector<std::string>{});
}

TEST_F(CliRobustness, GenerateReplacesOnlyWithForceAndNeverDeletes) {
  const fs::path out = dir_ / "suite";
  std::vector<std::string> args = {"generate", "--out",      out.string(), "--per-family",
                                   "7",        "--families", "vf_interior"};
  ASSERT_EQ(run(args).status, 0);
  const std::string manifest = read_text(out / "manifest.json");
  const fs::path extra = write_file("suite/vf_interior/vertex-face/data_3.csv", "earlier\n");

  args.insert(args.end(), {"--seed", "5"});
  expect_bad_input(run(args), {(out / "manifest.json").string(), "--force"});
  EXPECT_EQ(read_text(out / "manifest.json"), manifest);

  args.push_back("--force");
  const RunResult r = run(args);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_text(out / "manifest.json"), manifest);  // seed 5 now
  EXPECT_EQ(read_text(extra), "earlier\n");
  EXPECT_NE(r.err.find(extra.string()), std::string::npos) << r.err;
  EXPECT_EQ(temporaries(), std::vector<std::string>{});
}

TEST_F(CliRobustness, CheckOutReplacesAnExistingFileOnlyWithForce) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path out = write_file("results.csv", "precious\n");
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  expect_bad_input(run({"check", "--out", out.string(), file.string()}),
                   {out.string(), "--force"});
  EXPECT_EQ(read_text(out), "precious\n");

  const RunResult r = run({"check", "--force", "--out", out.string(), file.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(lines_of(read_text(out)).size(), 3u);
  EXPECT_EQ(fs::status(out).permissions(),  // the replacement keeps the file's permissions
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  // A device is written in place: no --force needed, nothing replaced.
  EXPECT_EQ(run({"check", "--out", "/dev/null", file.string()}).status, 0);
  EXPECT_EQ(temporaries(), std::vector<std::string>{});
}

TEST_F(CliRobustness, FailedCheckLeavesNoPartialOutFile) {
  // The first file is decided and its lines written before the second is found malformed.
  const fs::path good = write_file("vertex-face/a-good.csv", kHalfThirdNever);
  const fs::path bad =
      write_file("vertex-face/b-bad.csv", replace_line(kHalfThirdNever, 9, "1,4,1,4,x,1,1"));
  const fs::path out = dir_ / "results.csv";
  expect_bad_input(run({"check", "--out", out.string(), good.string(), bad.string()}),
                   {bad.string() + ":9:"});
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(temporaries(), std::vector<std::string>{});
}

TEST_F(CliRobustness, InterruptedCheckLeavesNoOutFile) {
  // The exact mode over the sample set, several times: seconds of work with the output's
  // temporary open, then SIGINT.
  const fs::path out = dir_ / "results.csv";
  std::vector<std::string> args = {EXACTCCD_CLI, "check", "--mode", "exact", "--out",
                                   out.string()};
  for (int k = 0; k < 8; ++k) args.push_back(EXACTCCD_SAMPLE_QUERIES);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, EXACTCCD_CLI, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  bool started = false;  // the temporary exists: the signal handlers are installed
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!started && std::chrono::steady_clock::now() < deadline) {
    started = !temporaries().empty();
    if (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(started) << "no temporary output file seen";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(temporaries(), std::vector<std::string>{});
}

// ---- 3. Files that are not regular files, lines without end, link loops -------------------

TEST_F(CliRobustness, FifoIsRefusedWithoutBlocking) {
  fs::create_directories(dir_ / "vertex-face");
  const fs::path fifo = dir_ / "vertex-face" / "pipe.csv";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_bad_input(run_bounded({"check", fifo.string()}), {fifo.string(), "FIFO"});
  const fs::path queries = write_file("vertex-face/q.csv", kHalfThirdNever);
  expect_bad_input(
      run_bounded({"grade", "--queries", queries.string(), "--answers", fifo.string()}),
      {fifo.string(), "FIFO"});
}

TEST_F(CliRobustness, DeviceIsRefused) {
  if (!fs::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
  expect_bad_input(run_bounded({"check", "--type", "vf", "/dev/zero"}),
                   {"/dev/zero", "character device"});
}

TEST_F(CliRobustness, LinesAreCappedAt64KiB) {
  const fs::path csv = write_file("vertex-face/long.csv", std::string(100000, '7'));
  expect_bad_input(run_bounded({"check", csv.string()}), {csv.string() + ":1:", "65536"});
  const auto [queries, answers] = grade_files("1\n1,0." + std::string(70000, '1') + "\n0\n");
  expect_bad_input(
      run_bounded({"grade", "--queries", queries.string(), "--answers", answers.string()}),
      {answers.string() + ":2:", "65536"});
}

TEST_F(CliRobustness, SymbolicLinkLoopIsReportedAsSuch) {
  fs::create_directory_symlink(dir_ / "loop-b", dir_ / "loop-a");
  fs::create_directory_symlink(dir_ / "loop-a", dir_ / "loop-b");
  const fs::path loop = dir_ / "loop-a";
  expect_bad_input(run({"check", "--type", "vf", loop.string()}),
                   {loop.string(), "Too many levels of symbolic links"});
  const fs::path queries = write_file("vertex-face/q.csv", kHalfThirdNever);
  expect_bad_input(run({"grade", "--queries", queries.string(), "--answers", loop.string()}),
                   {loop.string(), "Too many levels of symbolic links"});
}

TEST_F(CliRobustness, DirectoryWhereAFileIsExpected) {
  // A folder with no type in its name: the message must not be about the query type.
  const auto [queries, answers] = grade_files("1\n1\n0\n");
  const fs::path folder = dir_;
  expect_bad_input(run({"grade", "--queries", folder.string(), "--answers", answers.string()}),
                   {folder.string(), "is a directory"});
  expect_bad_input(run({"grade", "--queries", queries.string(), "--answers", folder.string()}),
                   {folder.string(), "is a directory"});
}

// ---- 4. Control characters and a byte-order mark in messages ------------------------------

TEST_F(CliRobustness, ControlCharactersInAFieldAreEscaped) {
  const std::string nul_tab_escape = std::string("0\t1\x1b", 4) + '\0';
  const fs::path file =
      write_file("vertex-face/ctl.csv",
                 replace_line(kHalfThirdNever, 3, "1,1," + nul_tab_escape + ",1,0,1,1"));
  const RunResult r = run({"check", file.string()});
  expect_bad_input(r, {file.string() + ":3:", "'0\\t1\\x1B\\x00'"});
  for (const char raw : {'\0', '\t', '\x1b'})
    EXPECT_EQ(r.err.find(raw), std::string::npos) << "raw byte " << static_cast<int>(raw);

  const auto [queries, answers] = grade_files("1\n1,0.3\x1b[31m\n0\n");
  expect_bad_input(run({"grade", "--queries", queries.string(), "--answers", answers.string()}),
                   {answers.string() + ":2:", "0.3\\x1B[31m"});
}

TEST_F(CliRobustness, ByteOrderMarkIsNamed) {
  const fs::path file = write_file("vertex-face/bom.csv", "\xEF\xBB\xBF" + kHalfThirdNever);
  const RunResult r = run({"check", file.string()});
  expect_bad_input(r, {file.string() + ":1:", "\\xEF\\xBB\\xBF", "UTF-8 byte-order mark"});
  EXPECT_EQ(r.err.find("\xEF\xBB\xBF"), std::string::npos);
}

// ---- 5. Numeric options and subcommands ---------------------------------------------------

TEST_F(CliRobustness, EmptyNumericArgumentIsNotANumber) {
  const fs::path file = write_file("vertex-face/q.csv", kHalfThirdNever);
  const fs::path answers = write_file("answers.txt", "1\n1\n0\n");
  const std::string out = (dir_ / "out").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"check", "--t-max", "", file.string()}, "--t-max"},
      {{"grade", "--t-max", "", "--queries", file.string(), "--answers", answers.string()},
       "--t-max"},
      {{"bench", "--repetitions", "", file.string()}, "--repetitions"},
      {{"study", "--repetitions", "", file.string()}, "--repetitions"},
      {{"study", "--widths", "", file.string()}, "--widths"},
      {{"study", "--eps", "", file.string()}, "--eps"},
      {{"simulate", "--out", out, "--resolution", ""}, "--resolution"},
      {{"simulate", "--out", out, "--steps", ""}, "--steps"},
      {{"simulate", "--out", out, "--seed", "", "--truth", "none"}, "--seed"},
      {{"generate", "--out", out, "--per-family", ""}, "--per-family"},
      {{"generate", "--out", out, "--seed", ""}, "--seed"},
      {{"check", "--t-max", "0.5x", file.string()}, "--t-max"},
  };
  for (const auto& [args, option] : cases) {
    SCOPED_TRACE(args.front() + " " + option);
    const RunResult r = run(args);
    expect_bad_input(r, {option, " is not "});
    EXPECT_EQ(r.err.find("got 0"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliRobustness, UnknownSubcommandIsNamed) {
  expect_bad_input(run({"foo", "--json"}), {"unknown subcommand 'foo'", "check", "grade"});
}

// ---- 6. grade: toi in [0, t_max], a folder as --queries -----------------------------------

TEST_F(CliRobustness, GradeRejectsToiOutsideZeroToTMax) {
  const fs::path answers = dir_ / "answers.txt";
  expect_bad_input(grade("1,-0.5\n1\n0\n"), {answers.string() + ":1:", "[0, t_max]"});
  expect_bad_input(grade("1\n1,1.5\n0\n"), {answers.string() + ":2:", "[0, t_max]"});
  expect_bad_input(grade("0\n1,0.45\n0\n", {"--t-max", "0.4"}),
                   {answers.string() + ":2:", "[0, t_max]"});
  const RunResult edge = grade("0\n1,0.4\n0\n", {"--t-max", "0.4"});  // t_max itself: in range
  EXPECT_EQ(edge.status, 1) << edge.err;  // but later than t* = 1/3
}

// ---- 7. grade: decimal tois compared exactly ----------------------------------------------

TEST_F(CliRobustness, GradeComparesDecimalToisExactly) {
  // t* = 1/2 (a double), 1/3 (between two doubles), 1/10 (between two doubles).
  const fs::path queries =
      write_file("vertex-face/exact.csv", falling_vertex_query(-1, 1) +
                                              falling_vertex_query(-2, 1) +
                                              falling_vertex_query(-9, 1));
  const std::string half_plus = "0.5000000000000000000000001";  // 1/2 + 1e-25
  const std::string third_minus = "0.3333333333333333333", third_plus = "0.3333333333333333334";
  const std::string tenth = "0.1", tenth_plus = "0.1000000000000000000000001";
  // What made rounding to the nearest double wrong: 1/2 + 1e-25 rounds to 1/2, the decimal
  // above 1/3 to a double below 1/3, and 0.1 (exactly t*) to a double above 1/10.
  auto exact = [](const std::string& decimal) {  // "0.ddd" as an exact fraction
    const std::string digits = decimal.substr(2);
    return mpq_class(mpz_class(digits), mpz_class("1" + std::string(digits.size(), '0')));
  };
  ASSERT_EQ(std::strtod(half_plus.c_str(), nullptr), 0.5);
  ASSERT_GT(exact(half_plus), mpq_class(1, 2));
  ASSERT_GT(exact(third_plus), mpq_class(1, 3));
  ASSERT_LT(mpq_class(std::strtod(third_plus.c_str(), nullptr)), mpq_class(1, 3));
  ASSERT_LT(exact(third_minus), mpq_class(1, 3));
  ASSERT_EQ(exact(tenth), mpq_class(1, 10));
  ASSERT_GT(mpq_class(std::strtod(tenth.c_str(), nullptr)), mpq_class(1, 10));

  auto late_indices = [&](const std::string& answers) {
    const fs::path file = write_file("answers.txt", answers);
    const RunResult r =
        run({"grade", "--json", "--queries", queries.string(), "--answers", file.string()});
    EXPECT_EQ(r.status == 0, parse_json(r).value("non_conservative_tois", 9u) == 0u) << r.err;
    return indices_of(parse_json(r), "non_conservative_toi_indices");
  };
  EXPECT_EQ(late_indices("1," + half_plus + "\n1," + third_plus + "\n1," + tenth + "\n"),
            (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(late_indices("1,0.5\n1," + third_minus + "\n1," + tenth_plus + "\n"),
            (std::vector<std::size_t>{2}));
  EXPECT_EQ(late_indices("1,5e-1\n1,0.333e0\n1,1E-1\n"), std::vector<std::size_t>{});
}

// ---- 8. study: the manifest is checked, not trusted ---------------------------------------

class StudyManifest : public CliRobustness {
 protected:
  // suite/hit/vertex-face/data_0.csv: two queries, one contact (t* = 1/2).
  void SetUp() override {
    CliRobustness::SetUp();
    write_file("suite/hit/vertex-face/data_0.csv",
               falling_vertex_query(-1, 1) + falling_vertex_query(1, 0));
  }
  RunResult study_with(const std::string& families) {
    write_file("suite/manifest.json",
               R"({"generator": "hand-written", "seed": 0, "families": [)" + families + "]}");
    return run({"study", "--json", "--repetitions", "1", "--widths", "0", "--eps", "1e-9",
                (dir_ / "suite").string()});
  }
  static std::string family(const std::string& name, const std::string& counts) {
    return R"({"name": ")" + name + R"(", "type": "vertex-face")" + counts + "}";
  }
  std::string manifest_path() const { return (dir_ / "suite" / "manifest.json").string(); }
};

TEST_F(StudyManifest, AValidManifestIsAccepted) {
  const RunResult r = study_with(family("hit", R"(, "queries": 2, "collisions": 1)"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r)["datasets"][0]["families"][0]["queries"], 2);
}

TEST_F(StudyManifest, FamilyNamesStayInsideTheSuite) {
  // A folder outside the suite with the same data: reachable through ../ or an absolute path.
  write_file("outside/vertex-face/data_0.csv",
             falling_vertex_query(-1, 1) + falling_vertex_query(1, 0));
  for (const std::string& name : {std::string("../outside"), (dir_ / "outside").string(),
                                  std::string("."), std::string("..")}) {
    SCOPED_TRACE(name);
    expect_bad_input(study_with(family(name, R"(, "queries": 2, "collisions": 1)")),
                     {manifest_path(), "plain folder name"});
  }
}

TEST_F(StudyManifest, CountsMustMatchTheFiles) {
  expect_bad_input(study_with(family("hit", R"(, "collisions": 1)")),
                   {manifest_path(), "hit", "\"queries\""});
  expect_bad_input(study_with(family("hit", R"(, "queries": 3, "collisions": 1)")),
                   {manifest_path(), "hit", "3 queries"});
  expect_bad_input(study_with(family("hit", R"(, "queries": 2, "collisions": 2)")),
                   {manifest_path(), "hit", "2 collisions"});
  expect_bad_input(study_with(family("hit", R"(, "queries": -2)")),
                   {manifest_path(), "hit", "non-negative integer"});
  const std::string hit = family("hit", R"(, "queries": 2, "collisions": 1)");
  expect_bad_input(study_with(hit + "," + hit), {manifest_path(), "listed twice"});
}

TEST_F(StudyManifest, AnEmptyFamilyListIsRefused) {
  expect_bad_input(study_with(""), {manifest_path(), "empty"});
}

// ---- 9. Empty files and blank lines -------------------------------------------------------

TEST_F(CliRobustness, NoQueryAtAllExitsTwoAndAnEmptyFileIsWarnedAbout) {
  const fs::path empty = write_file("vertex-face/empty.csv", "");
  const fs::path blank = write_file("vertex-face/blank.csv", "\n  \n\r\n");
  const fs::path good = write_file("vertex-face/good.csv", kHalfThirdNever);
  expect_bad_input(run({"check", empty.string()}), {empty.string(), "no queries"});
  expect_bad_input(run({"check", blank.string()}), {blank.string(), "no queries"});
  expect_bad_input(run({"check", empty.string(), blank.string()}), {"no queries", "2 files"});
  const fs::path answers = write_file("answers.txt", "");
  expect_bad_input(run({"grade", "--queries", empty.string(), "--answers", answers.string()}),
                   {empty.string(), "no queries"});

  const RunResult r = run({"check", "--json", empty.string(), good.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r).value("queries", 0u), 3u);
  EXPECT_EQ(lines_in(r.err), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("exactccd: warning: " + empty.string() + ": no queries", 0), 0u) << r.err;
}

TEST_F(CliRobustness, BlankLinesOnlyBetweenQueries) {
  const std::string one = falling_vertex_query(-1, 1), two = falling_vertex_query(1, 0);
  const fs::path ok = write_file("vertex-face/ok.csv", "\n" + one + "\n \n" + two + "\n\n");
  const RunResult r = run({"check", "--json", ok.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r).value("queries", 0u), 2u);

  // A blank line after the third row of the second query: line 12.
  std::string text = one;
  const std::vector<std::string> rows = lines_of(two);
  for (std::size_t i = 0; i < rows.size(); ++i) text += rows[i] + (i == 2 ? "\n\n" : "\n");
  const fs::path bad = write_file("vertex-face/bad.csv", text);
  expect_bad_input(run({"check", bad.string()}),
                   {bad.string() + ":12:", "blank line inside a query"});
}

// ---- 10. Filesystem errors are one-line messages ------------------------------------------

TEST_F(CliRobustness, PermissionDeniedIsAOneLineMessage) {
  // Root passes permission checks: run as nobody when root.
  std::string prefix;
  if (geteuid() == 0) {
    if (std::system("command -v setpriv >/dev/null 2>&1") != 0) GTEST_SKIP() << "no setpriv";
    prefix = "setpriv --reuid=65534 --regid=65534 --clear-groups";
  }
  const fs::path out = dir_ / "out";
  const fs::perms read_only = fs::perms::owner_read | fs::perms::owner_exec |
                              fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec;
  for (const char* type : {"vertex-face", "edge-edge"}) {
    write_file("out/simulation/" + std::string(type) + "/data_0.csv", "earlier\n");
    fs::permissions(out / "simulation" / type, read_only);
  }
  const std::vector<std::string> args = {"simulate", "--out",   out.string(), "--resolution",
                                         "2",        "--steps", "1",          "--truth",
                                         "none"};
  for (const bool force : {false, true}) {
    SCOPED_TRACE(force);
    std::vector<std::string> a = args;
    if (force) a.push_back("--force");
    const RunResult r = run_with(a, {"", "", prefix});
    expect_bad_input(r, {"exactccd: " + (out / "simulation").string(),
                         force ? "Permission denied" : "--force"});
    EXPECT_EQ(r.err.find("filesystem error"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(out / "simulation" / "vertex-face" / "data_0.csv"), "earlier\n");
  }
  for (const char* type : {"vertex-face", "edge-edge"})  // so that TearDown can remove them
    fs::permissions(out / "simulation" / type, fs::perms::owner_write, fs::perm_options::add);
}

}  // namespace
