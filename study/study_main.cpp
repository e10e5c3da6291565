// `exactccd_study` (also run as `exactccd study`): the numerical-stability study of the
// uncertified methods against the exact truth (study.hpp), from the command line.
#include <CLI/CLI.hpp>
#include <string>
#include <tuple>

#include "study/study.hpp"
#include "oracle/command_line.hpp"
#include "oracle/common.hpp"
#include "oracle/names.hpp"

using namespace exactccd::oracle;
using exactccd::study::run_study;
using exactccd::study::StudyOptions;

int main(int argc, char** argv) {
  StudyOptions study_options;
  std::string study_type;
  CLI::App app(
      "Numerical-stability study: each method or setting (float_only; the tolerance method, "
      "distance <= eps at a cubic root, at each eps; the filtered path at each TOI width; exact) "
      "against the exact truth on each data set: false positives, false negatives, late "
      "(non-conservative) TOIs, TOI error, mean time per query (single thread). A folder with "
      "a manifest.json (exactccd generate) is also broken down per family and per coordinate "
      "scale. With --min-separation D > 0 every method decides \"comes within distance D\" "
      "instead of contact.",
      "exactccd study");
  CLI::App* study = &app;
  study->footer(
      "Verdicts: the truth column (the exact path for --simulation). Exact TOIs: a data_K.csv "
      "file's toi_K.csv sidecar when present, else the exact path. With --min-separation D > 0, "
      "verdicts and exact TOIs of every data set come from the exact path at D (truth columns "
      "and sidecars are not read). TOI error: the reported toi "
      "(toi_lo of an enclosure) minus t*, as the signed distance to the exact tightest pair "
      "[lo, hi]; late: toi > lo.\n\nExit status: 0 the certified methods (filtered, exact) show "
      "no false positive, false negative or late TOI; 1 one of them does; 2 bad command line, "
      "input or output (an existing --out-md file without --force); 3 internal error.");
  study->add_flag("--json", study_options.json,
                  "Print one JSON document (datasets[...] with methods[...], and for a suite "
                  "families[...] and scales[...]) instead of Markdown tables");
  study->add_option("--out-md", study_options.out_md, "Also write the Markdown tables to FILE");
  add_force_flag(study, study_options.force);
  // One comma-separated argument each, so that a PATH after them stays a PATH.
  study->add_option("--widths", study_options.widths, "The filtered path's TOI widths")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(numeric_text(false))
      ->capture_default_str();
  study->add_option("--eps", study_options.tolerances,
                    "The tolerance method's absolute distance tolerances")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(numeric_text(false))
      ->capture_default_str();
  study
      ->add_option("--repetitions", study_options.repetitions,
                   "Timed samples per group and method; mean_ns is their median")
      ->check(numeric_text(true))
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  study->add_flag("--simulation", study_options.simulation,
                  "Add the simulation-like set, generated in memory (verdicts and TOIs: the "
                  "exact path); default size: about 50,000 queries");
  CLI::Option* study_resolution = nullptr;
  CLI::Option* study_steps = nullptr;
  CLI::Option* study_seed = nullptr;
  std::tie(study_resolution, study_steps, study_seed) =
      add_simulation_options(study, study_options.simulation_config);
  add_type_option(study, study_type);
  add_min_separation_option(study, study_options.min_separation);
  // The shared help says the truth column is read for delta; the study recomputes it instead.
  study->get_option("--min-separation")
      ->description(
          "Minimum separation D >= 0: every method decides whether the primitives come within "
          "Euclidean distance D (float_only: the common practice with eps = D; tolerance: "
          "distance <= D + eps at a cubic root; filtered and exact: min_separation = D); "
          "verdicts and exact TOIs from the exact path at D (0: contact, the truth column)");
  study->add_option("PATH", study_options.paths,
                    "CSV files, folders of them, or generated suites; one data set each");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return finish(app.exit(e));  // --help
    report_error(std::string(e.what()) + " (see exactccd study --help)");
    return kExitBadInput;
  }
  // Every failure ends as one line on stderr, 'exactccd: <what>', with its exit status.
  return run_reporting_errors([&] {
    for (CLI::Option* option : {study_resolution, study_steps, study_seed})
      if (option->count() > 0 && !study_options.simulation)
        throw UsageError(option->get_name() + " needs --simulation");
    study_options.type = parse_type_name(study_type);
    return run_study(study_options);
  });
}
