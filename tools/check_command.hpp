// `exactccd check`: decide benchmark queries with a chosen path and compare with their truth
// column (oracle/check.hpp), over files and folders, with the per-query --out file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"

namespace exactccd::cli {

struct CheckOptions {
  std::vector<std::string> paths;  ///< CSV files or directories searched for them
  std::optional<QueryType> type;   ///< --type: overrides the type from the folder name
  /// --type pe|pe2d|pp|pp2d|pl: files of a point kind or the plane (paths must be files).
  std::optional<PrimitiveKind> primitive;
  double t_max = 1.0;
  double min_separation = 0.0;  ///< --min-separation: delta >= 0 (0: contact)
  Mode mode = Mode::filtered;  ///< --mode: the path that decides every query
  /// --format: table (fits 100 columns), wide (every column), csv, json (one object).
  std::string format = "table";
  std::string out_path;        ///< --out: per-query results, empty for none
  bool force = false;          ///< --force: --out may replace an existing file
};

/// Runs the subcommand; returns the exit status (0 all agree, 1 some disagree). Throws
/// InputError / UsageError for bad input.
int run_check(const CheckOptions& options);

}  // namespace exactccd::cli
