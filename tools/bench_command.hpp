// `exactccd bench`: time per query and errors of each mode (float_only, filtered, exact) on
// benchmark CSV data sets and on the simulation-like set (corpus/simulation_queries.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "corpus/simulation_queries.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"

namespace exactccd::cli {

struct BenchOptions {
  std::vector<std::string> paths;  ///< each a data set: a CSV file or a folder of them
  std::optional<QueryType> type;   ///< --type: overrides the type from the folder name
  /// --type pe|pe2d|pp|pp2d: files of a point kind, timed as the edge-edge queries they are
  /// (point_edge_ccd and point_point_ccd are that call on copied rows).
  std::optional<PrimitiveKind> primitive;
  std::vector<Mode> modes = {Mode::float_only, Mode::filtered, Mode::exact};
  int repetitions = 5;             ///< batch passes; mean_ns is their median
  bool simulation = false;         ///< add the simulation-like set (truth: the exact path)
  sim::SimulationConfig simulation_config;
  bool json = false;
  /// --min-separation: each delta (or factor, with relative_separation) is one run per mode.
  std::vector<double> min_separations = {0.0};
  /// --relative-separation: the deltas are factors of each data set's size (box diagonal).
  bool relative_separation = false;
  /// Used when `paths` is empty and `simulation` false.
  std::string default_path;
};

/// Runs the subcommand. Exit status 1 when a certified mode (filtered, exact) disagrees with
/// the truth (a wrong truth column, or a bug), else 0; float_only's errors are only reported.
/// Throws InputError / UsageError for bad input.
int run_bench(const BenchOptions& options);

}  // namespace exactccd::cli
