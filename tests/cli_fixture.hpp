// The fixture of the `exactccd` command's tests (cli_test, cli_robustness_test): runs the
// built binary (EXACTCCD_CLI) on files written into a fresh temporary directory, and the
// hand-made queries whose contact times are worked out by hand.
#pragma once

// AddressSanitizer builds (gcc defines __SANITIZE_ADDRESS__, clang has __has_feature).
#if defined(__SANITIZE_ADDRESS__)
#define EXACTCCD_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EXACTCCD_UNDER_ASAN 1
#endif
#endif

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

struct RunResult {
  int status = -1;  ///< exit status; -1 when the command did not exit normally (a crash)
  std::string out, err;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (const char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

inline const fs::path kSampleFile =
    fs::path(EXACTCCD_SAMPLE_QUERIES) / "unit-tests" / "vertex-face" / "data_0_1.csv";

// Hand-made vertex-face queries: the static triangle a=(0,0,0), b=(1,0,0), c=(0,1,0) and the
// vertex p moving from (1/4,1/4,1) to (1/4,1/4,z1), so p_z(t) = 1 + t (z1 - 1): it crosses
// the plane z=0 at t* = 1 / (1 - z1) at (1/4,1/4,0), inside the triangle. z1 = -1: t* = 1/2;
// z1 = -2: t* = 1/3; z1 = 1: p stays at height 1, no contact.
inline std::string falling_vertex_query(int z1, int truth) {
  const std::string t = "," + std::to_string(truth) + "\n";
  const std::string a = "0,1,0,1,0,1" + t, b = "1,1,0,1,0,1" + t, c = "0,1,1,1,0,1" + t;
  return "1,4,1,4,1,1" + t + a + b + c + "1,4,1,4," + std::to_string(z1) + ",1" + t + a + b + c;
}
inline const std::string kHalfThirdNever =  // t* = 1/2, t* = 1/3, no contact (truth 1, 1, 0)
    falling_vertex_query(-1, 1) + falling_vertex_query(-2, 1) + falling_vertex_query(1, 0);

// `text` with its 1-based line `line_no` replaced by `replacement`.
inline std::string replace_line(const std::string& text, std::size_t line_no,
                         const std::string& replacement) {
  std::vector<std::string> lines = lines_of(text);
  lines.at(line_no - 1) = replacement;
  std::string joined;
  for (const std::string& line : lines) joined += line + "\n";
  return joined;
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device random;
    for (int attempt = 0; dir_.empty() && attempt < 100; ++attempt) {
      const fs::path candidate =
          fs::temp_directory_path() /
          ("exactccd-cli-test-" + std::to_string(getpid()) + "-" + std::to_string(random()));
      if (fs::create_directory(candidate)) dir_ = candidate;
    }
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    std::error_code ignored;
    if (!dir_.empty()) fs::remove_all(dir_, ignored);
  }

  fs::path write_file(const std::string& relative, const std::string& text) {
    const fs::path path = dir_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  RunResult run(const std::vector<std::string>& args) { return run_with(args, {}); }

  // How to run the command besides its arguments; empty fields keep the defaults.
  struct RunSetting {
    std::string stdout_path;  ///< stdout goes there instead of a file read back (/dev/full)
    std::string cwd;          ///< working directory
    std::string prefix;       ///< shell words before the command (timeout 20, setpriv ...)
  };

  // The command stopped after `seconds` and limited to 4 GB of address space. Under
  // AddressSanitizer, which reserves terabytes of address space at start-up, ASan's own
  // resident-memory limit takes the place of the address-space limit.
  RunResult run_bounded(const std::vector<std::string>& args, int seconds) {
    const std::string timeout = " timeout " + std::to_string(seconds);
#ifdef EXACTCCD_UNDER_ASAN
    return run_with(args, {"", "", "ASAN_OPTIONS=\"$ASAN_OPTIONS:hard_rss_limit_mb=4000\"" + timeout});
#else
    return run_with(args, {"", "", "ulimit -v 4000000 &&" + timeout});
#endif
  }

  RunResult run_with(const std::vector<std::string>& args, const RunSetting& setting) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    std::string command = setting.prefix + " " + shell_quote(EXACTCCD_CLI);
    for (const std::string& arg : args) command += " " + shell_quote(arg);
    const std::string stdout_path = setting.stdout_path.empty() ? out.string() : setting.stdout_path;
    command += " >" + shell_quote(stdout_path) + " 2>" + shell_quote(err.string()) + " </dev/null";
    if (!setting.cwd.empty()) command = "cd " + shell_quote(setting.cwd) + " && " + command;
    std::error_code ignored;
    fs::remove(out, ignored);
    const int raw = std::system(("(" + command + ")").c_str());
    RunResult result;
    result.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    result.out = setting.stdout_path.empty() ? read_text(out) : std::string();
    result.err = read_text(err);
    return result;
  }

  // Bad input: exit status 2, nothing on stdout, one line on stderr naming `expected` parts.
  static void expect_bad_input(const RunResult& r, const std::vector<std::string>& expected) {
    EXPECT_EQ(r.status, 2) << "stderr: " << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("exactccd: ", 0), 0u) << r.err;
    for (const std::string& part : expected)
      EXPECT_NE(r.err.find(part), std::string::npos) << "missing '" << part << "' in: " << r.err;
  }

  // `check` on a vertex-face file holding `text`; the error must name bad.csv:line.
  void expect_check_rejects(const std::string& text, std::size_t line) {
    const fs::path file = write_file("vertex-face/bad.csv", text);
    expect_bad_input(run({"check", file.string()}),
                     {file.string() + ":" + std::to_string(line) + ":"});
  }

  // `grade` of `answers` for the three hand-made queries.
  RunResult grade(const std::string& answers, const std::vector<std::string>& extra = {}) {
    const fs::path queries = write_file("vertex-face/queries.csv", kHalfThirdNever);
    const fs::path answers_file = write_file("answers.txt", answers);
    std::vector<std::string> args = {"grade",          "--json",    "--queries",
                                     queries.string(), "--answers", answers_file.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
  }

  fs::path dir_;
};

inline nlohmann::json parse_json(const RunResult& r) {
  try {
    return nlohmann::json::parse(r.out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "stdout is not JSON (" << e.what() << "): " << r.out << r.err;
    return nlohmann::json::object();
  }
}

}  // namespace cli_test
