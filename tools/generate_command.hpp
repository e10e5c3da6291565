// `exactccd generate`: writes the families of hard and degenerate queries (bench/degenerate)
// as a corpus: benchmark CSV files with the exact path's truth, TOI sidecars and a manifest.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "families.hpp"

namespace exactccd::cli {

struct GenerateOptions {
  std::string out_dir;
  std::uint64_t seed = 1;
  int per_family = families::kDefaultPerFamily;
  std::vector<std::string> families;  ///< empty: all
};

/// Runs the subcommand: 0 when every base-family member's exact verdict and TOI match its
/// construction, 1 otherwise (the mismatches are listed on stderr; the files are written
/// anyway). Throws UsageError for an unknown family, a bad --per-family or an output folder
/// that cannot be written.
int run_generate(const GenerateOptions& options);

}  // namespace exactccd::cli
