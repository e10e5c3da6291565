// Tallies of `exactccd check` and their table / JSON forms.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::oracle {

/// Counts for one file, or for all of them (the TOTAL row).
struct CheckTally {
  std::string file;
  std::size_t queries = 0;
  std::size_t collisions = 0;       ///< queries the chosen path finds colliding
  std::size_t false_positives = 0;  ///< the path says 1, truth column says 0
  std::size_t false_negatives = 0;  ///< the path says 0, truth column says 1
  double seconds = 0.0;             ///< time spent in the decisions only
  /// Queries decided by each stage, indexed by the Stage's value.
  std::vector<std::size_t> stage_counts;

  std::size_t disagreements() const { return false_positives + false_negatives; }
  void count_stage(Stage stage);
  std::size_t stage_count(Stage stage) const;
  /// The share of the queries decided by `stage` (0 without queries).
  double stage_share(Stage stage) const;
  void add(const CheckTally& other);
};

/// The stages shown: those `mode` can use, and any other that decided some query.
std::vector<Stage> reported_stages(Mode mode, const CheckTally& total);

/// The width of `exactccd check`'s default table: it fits a 100-column terminal.
inline constexpr int kCheckTableWidth = 100;

/// The table: one row per file and TOTAL. Within `max_width` columns (file names shortened to
/// their part below the files' common folder, vertex-face/ and edge-edge/ as vf/ and ee/, then
/// cut in the middle; the counts and the stage shares kept, stage names abbreviated), or every
/// column in full when max_width is 0.
void print_check_table(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                       const CheckTally& total, int max_width = kCheckTableWidth);

/// The same rows as CSV (RFC 4180 quoting of file names): file, queries, collisions, agree,
/// disagree, false_positives, false_negatives, us_per_query, then one share per stage shown.
void print_check_csv(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                     const CheckTally& total);

void print_check_json(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                      const CheckTally& total, double t_max,
                      double min_separation = 0.0);

}  // namespace exactccd::oracle
