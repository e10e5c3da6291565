// `exactccd simulate`: writes the simulation-like queries (corpus/simulation_queries.hpp) as benchmark CSV
// files, every coordinate as its exact fraction, with the exact path's truth column.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "corpus/simulation_queries.hpp"

namespace exactccd::cli {

struct SimulateOptions {
  std::string out_dir;           ///< files go to out_dir/simulation/{vertex-face,edge-edge}/
  sim::SimulationConfig config;
  bool exact_truth = true;       ///< --truth exact; false (--truth none): truth column all 0
  bool force = false;            ///< --force: replace data_K.csv files of an earlier run
  /// --barrier-step NAME: instead, the candidates of that barrier-method trial step
  /// (corpus/barrier_steps.hpp) at --barrier-scale, to out_dir/barrier/NAME/<type>/.
  std::string barrier_step;
  double barrier_scale = 0.1;
};

/// Runs the subcommand (exit status 0). Throws UsageError for a bad configuration, OutputError
/// for an output folder that cannot be written or, without `force`, that already holds
/// data_K.csv files (checked before any work). Never deletes a file: data_K.csv files of an
/// earlier run that this one does not replace are left in place, with a warning.
int run_simulate(const SimulateOptions& options);

/// Most queries per written file.
constexpr std::size_t kQueriesPerFile = 100000;

/// The exact path's verdict (exact_ccd on the query's exact rationals) for every query,
/// computed in parallel (TBB); the result does not depend on the number of threads.
std::vector<std::uint8_t> exact_truth(const std::vector<sim::SimulationQuery>& queries);

}  // namespace exactccd::cli
