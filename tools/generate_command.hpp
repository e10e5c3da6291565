// `exactccd generate`: writes the families of hard and degenerate queries (corpus/families.hpp),
// or with --min-separation the minimum-separation families for that delta
// (corpus/min_separation_families.hpp), as a corpus: benchmark CSV files with the exact path's
// truth, TOI sidecars and a manifest.
#pragma once

#include "exactccd/query_file.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "corpus/families.hpp"
#include "corpus/min_separation_families.hpp"

namespace exactccd::cli {

struct GenerateOptions {
  std::string out_dir;
  std::uint64_t seed = 1;
  int per_family = families::kDefaultPerFamily;
  std::vector<std::string> families;  ///< empty: all
  bool force = false;                 ///< --force: replace the files of an earlier run
  /// --min-separation: the minimum-separation families (min_separation_families.hpp) for this
  /// delta instead of the degenerate families.
  std::optional<double> min_separation;
  /// --type: the degenerate families of this point kind (point_families.hpp) instead, one file
  /// of the kind per family, DIR/<family>.csv.
  std::optional<PrimitiveKind> primitive;
  /// --html: also DIR/index.html and DIR/inspect/<family>.html (oracle/inspection_report.hpp).
  bool html = false;
};

/// Runs the subcommand: 0 when every base-family member's exact verdict and TOI match its
/// construction, 1 otherwise (the mismatches are listed on stderr; the files are written
/// anyway). Throws UsageError for an unknown family, a bad --per-family or --min-separation
/// (min_separation_delta_problem), OutputError for an
/// output folder that cannot be written or, without `force`, that holds one of the files to
/// write. Each file is written whole or not at all (output_file.hpp); none is deleted.
int run_generate(const GenerateOptions& options);

}  // namespace exactccd::cli
