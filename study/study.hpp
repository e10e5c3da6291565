// `exactccd study`: the numerical-stability study. For each data set and each method or setting
// (float_only, the tolerance method at each eps, the default path at each TOI width, the exact
// path) against the exact truth: false positives, false negatives, non-conservative (late) TOIs,
// the TOI error, and the mean time per query (single thread). A generated suite (a folder with
// a manifest.json, written by `exactccd generate`) is also broken down per family and per
// coordinate scale / translation. With a minimum separation D > 0, the same for "comes within
// distance D" (issue 12).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "corpus/simulation_queries.hpp"
#include "exactccd/types.hpp"

namespace exactccd::study {

struct StudyOptions {
  /// Each a data set: a CSV file, a folder of them, or a generated suite (folder holding a
  /// manifest.json).
  std::vector<std::string> paths;
  std::optional<QueryType> type;                  ///< --type: overrides the folder name
  std::vector<double> widths = {0.0, 1e-6, 1e-3};  ///< the default path's TOI widths
  std::vector<double> tolerances = {1e-12, 1e-9, 1e-6};  ///< the tolerance method's eps
  /// --min-separation D >= 0: every method decides "within distance D" (float_only: the common
  /// practice with eps = D; tolerance: distance <= D + eps at a cubic root; default and exact:
  /// CcdOptions::min_separation = D); with D > 0 verdicts and exact TOIs come from the exact
  /// path at D for every data set. 0: contact.
  double min_separation = 0.0;
  int repetitions = 3;  ///< timed samples per group and method; mean_ns is their median
  bool simulation = false;  ///< add the simulation-like set (reference: the exact path)
  sim::SimulationConfig simulation_config = sim::small_simulation_config();
  bool json = false;    ///< the JSON document on stdout instead of text tables
  std::string out_md;   ///< --out-md: also write the Markdown tables there
  bool force = false;   ///< --force: --out-md may replace an existing file
};

/// Runs the subcommand. Exit status 1 when a certified method (default at any width, exact)
/// shows a false positive, a false negative or a late TOI, else 0. Throws InputError /
/// UsageError for bad input.
int run_study(const StudyOptions& options);

}  // namespace exactccd::study
