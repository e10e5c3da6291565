// `exactccd grade`: judge another CCD code's answers against the exact decision
// (oracle/grade.hpp) and print the findings.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"

namespace exactccd::cli {

struct GradeOptions {
  std::string queries_path;  ///< one benchmark CSV file
  std::string answers_path;  ///< see oracle/answers_file.hpp
  std::optional<QueryType> type;
  /// --type pe|pe2d|pp|pp2d: a file of a point kind (graded as its edge-edge queries).
  std::optional<PrimitiveKind> primitive;
  double t_max = 1.0;
  double min_separation = 0.0;  ///< --min-separation: delta >= 0 (0: contact)
  bool json = false;
  std::string html_path;       ///< --html REPORT.html (empty: none)
  std::size_t html_limit = 10; ///< inspector pages per kind of finding
  bool force = false;          ///< replace REPORT.html and the pages of its folder
};

/// Returns 0 when every answer is right and every toi conservative, 1 otherwise. Throws
/// InputError / UsageError for bad input.
int run_grade(const GradeOptions& options);

}  // namespace exactccd::cli
