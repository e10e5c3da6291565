// `exactccd check`: decide benchmark queries with a chosen path and compare with their truth
// column. Also the pieces `exactccd bench` shares: mode names, stages, double queries.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/types.hpp"

namespace exactccd::cli {

struct CheckOptions {
  std::vector<std::string> paths;  ///< CSV files or directories searched for them
  std::optional<QueryType> type;   ///< --type: overrides the type from the folder name
  double t_max = 1.0;
  Mode mode = Mode::filtered;  ///< --mode: the path that decides every query
  bool json = false;           ///< one JSON object on stdout instead of a table
  std::string out_path;        ///< --out: per-query results, empty for none
  bool force = false;          ///< --force: --out may replace an existing file
};

/// Runs the subcommand; returns the exit status (0 all agree, 1 some disagree). Throws
/// InputError / UsageError for bad input.
int run_check(const CheckOptions& options);

// ---- Shared with `exactccd bench` -------------------------------------------------------------

/// The names of --mode: "float_only", "default", "exact" (to_string(Mode)).
std::optional<Mode> parse_mode_name(const std::string& name);
const std::vector<std::string>& mode_names();

/// Every Stage in enum order. Found through to_string(Stage), which names each stage and
/// answers "unknown" past the last, so that a stage added to the library is listed too.
const std::vector<Stage>& all_stages();

/// The stages that can decide a query in `mode` (the table's share columns).
std::vector<Stage> stages_of(Mode mode);

using QueryPoints = std::array<Eigen::Vector3d, 8>;  ///< benchmark row order

/// The query's coordinates as doubles when each is exactly a double; otherwise nullopt and
/// *bad_row (0-7) is the first row holding one that is not.
std::optional<QueryPoints> exact_doubles(const RationalQuery& query, std::size_t* bad_row);

VertexFaceQuery vertex_face_query(const QueryPoints& p);
EdgeEdgeQuery edge_edge_query(const QueryPoints& p);

}  // namespace exactccd::cli
