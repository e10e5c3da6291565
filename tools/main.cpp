// `exactccd`: the command-line oracle. `check` decides benchmark CSV files exactly and compares
// with their truth column; `grade` judges another code's answers (and TOIs) exactly.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>

#include "check.hpp"
#include "cli_common.hpp"
#include "exactccd/query_file.hpp"
#include "grade.hpp"

namespace {

using namespace exactccd::cli;

constexpr const char* kExitStatusHelp =
    "Exit status:\n"
    "  0  all ran and everything agrees (check: every exact decision equals the truth\n"
    "     column; grade: every answer is correct and every toi conservative)\n"
    "  1  some disagreement (check: an exact decision differs from the truth column;\n"
    "     grade: a false positive, a false negative or a toi later than the exact one)\n"
    "  2  bad command line or malformed input; one line on stderr:\n"
    "     'exactccd: FILE:LINE: what'\n"
    "  3  internal error (a bug in exactccd, or out of memory)\n";

constexpr const char* kTypeHelp =
    "Query type: vf (vertex-face) or ee (edge-edge); default: from the nearest folder named "
    "vertex-face or edge-edge in each file's path";

// Reports an error on one line of stderr.
void report_error(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::cerr << "exactccd: " << message << '\n';
}

void add_type_option(CLI::App* command, std::string& type_name) {
  command->add_option("--type", type_name, kTypeHelp)
      ->check(CLI::IsMember({"vf", "ee", "vertex-face", "edge-edge"}));
}

void add_t_max_option(CLI::App* command, double& t_max) {
  command->add_option("--t-max", t_max, "End of the time interval [0, T]; T in (0, 1]")
      ->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Exact continuous collision detection oracle for the CCD benchmark "
      "(Wang et al. 2021): vertex-face and edge-edge queries, decided exactly.",
      "exactccd");
  app.footer(kExitStatusHelp);
  app.require_subcommand(1);

  CheckOptions check_options;
  std::string check_type;
  CLI::App* check = app.add_subcommand(
      "check",
      "Decide every query of benchmark CSV files exactly and compare with their truth "
      "column (table per file and TOTAL on stdout).");
  check->footer(kExitStatusHelp);
  check->add_flag("--json", check_options.json,
                  "Print one JSON object (queries, collisions, false_positives, "
                  "false_negatives, seconds, files[...]) instead of the table");
  check->add_option("--out", check_options.out_path,
                    "Write one line per query: file,index,collides,toi_lo,toi_hi (index 0-based "
                    "in its file, TOI with 17 significant digits, empty when no contact)");
  add_type_option(check, check_type);
  add_t_max_option(check, check_options.t_max);
  check
      ->add_option("PATH", check_options.paths,
                   "CSV files, or directories searched for vertex-face/*.csv and "
                   "edge-edge/*.csv")
      ->required();

  GradeOptions grade_options;
  std::string grade_type;
  CLI::App* grade =
      app.add_subcommand("grade",
                         "Judge another code's answers to one benchmark CSV file against the exact "
                         "decision: false positives, false negatives, non-conservative TOIs.");
  grade->footer(std::string("Answers file: one line per query, in order: 0, 1, or 1,toi (toi a "
                            "decimal double, the\ncode's time of impact; it is conservative iff "
                            "toi <= the exact first contact time).\n\n") +
                kExitStatusHelp);
  grade->add_option("--queries", grade_options.queries_path, "The benchmark CSV file")->required();
  grade->add_option("--answers", grade_options.answers_path, "The answers file")->required();
  grade->add_flag("--json", grade_options.json, "Print one JSON object instead of text");
  add_type_option(grade, grade_type);
  add_t_max_option(grade, grade_options.t_max);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    report_error(std::string(e.what()) + " (see exactccd --help)");
    return kExitBadInput;
  }

  try {
    if (check->parsed()) {
      check_options.type = parse_type_name(check_type);
      return run_check(check_options);
    }
    grade_options.type = parse_type_name(grade_type);
    return run_grade(grade_options);
  } catch (const exactccd::InputError& e) {
    report_error(e.what());
    return kExitBadInput;
  } catch (const UsageError& e) {
    report_error(e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    report_error(std::string("internal error: ") + e.what());
    return kExitInternal;
  }
}
