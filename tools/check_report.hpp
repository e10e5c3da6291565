// Tallies of `exactccd check` and their table / JSON forms.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace exactccd::cli {

/// Counts for one file, or for all of them (the TOTAL row).
struct CheckTally {
  std::string file;
  std::size_t queries = 0;
  std::size_t collisions = 0;       ///< queries the exact decision finds colliding
  std::size_t false_positives = 0;  ///< exact says 1, truth column says 0
  std::size_t false_negatives = 0;  ///< exact says 0, truth column says 1
  double seconds = 0.0;             ///< time spent in the decisions only

  std::size_t disagreements() const { return false_positives + false_negatives; }
  void add(const CheckTally& other);
};

void print_check_table(std::ostream& out, const std::vector<CheckTally>& files,
                       const CheckTally& total);

void print_check_json(std::ostream& out, const std::vector<CheckTally>& files,
                      const CheckTally& total, double t_max);

}  // namespace exactccd::cli
