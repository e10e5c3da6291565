// `exactccd inspect`: one query of a benchmark CSV file shown as a self-contained HTML page
// (oracle/inspection.hpp, oracle/inspector_page.hpp), or summarised as text or JSON.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"
#include "oracle/inspection.hpp"

namespace exactccd::cli {

struct InspectOptions {
  std::string path;            ///< a benchmark CSV file
  std::optional<QueryType> type;
  /// --type pe|pe2d|pp|pp2d|pl: a file of a point kind (shown as the edge-edge query of its
  /// zero-length segments) or of the plane (a point-plane page).
  std::optional<PrimitiveKind> primitive;
  std::size_t index = 0;       ///< 0-based query index in the file
  oracle::InspectSettings settings;
  std::string html_path;       ///< --html OUT.html (empty: no page)
  bool json = false;           ///< print the inspection JSON instead of text
  bool force = false;          ///< replace an existing OUT.html
  /// A rigid scene file (FILE ending in .json): the step (1-based) whose first contact is
  /// shown; none: the first step with a contact.
  std::optional<std::size_t> step;
  /// Given on the command line (a scene file's own settings apply otherwise).
  bool mode_given = false, t_max_given = false, min_separation_given = false;
  bool index_given = false, html_given = false;
};

/// Writes the page (when asked) and prints the summary; 0. A FILE ending in .json is a rigid
/// scene file (docs/rigid_scene_format.md): the first contact of a step is shown. Throws InputError for a file that is
/// not a benchmark file or an index past its end, OutputError for an output it may not write.
int run_inspect(const InspectOptions& options);

}  // namespace exactccd::cli
