// What `exactccd check` computes: every query of one benchmark CSV file decided by a chosen
// path and compared with the file's truth column. The tallies and their table / JSON forms are
// in check_report.hpp (included).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"
#include "oracle/check_report.hpp"

namespace exactccd::oracle {

struct CheckSettings {
  double t_max = 1.0;          ///< in (0, 1]
  Mode mode = Mode::filtered;  ///< the path that decides every query
  double min_separation = 0.0;  ///< delta >= 0 (0: contact)
};

/// Called after each query of the file: its 0-based index, the file's query count, the result.
using CheckVisitor =
    std::function<void(std::size_t index, std::size_t count, const CcdResult& result)>;

/// Decides every query of the benchmark CSV file `path` (its type `type` when given, else from
/// the folder name) and counts the collisions, the disagreements with the truth column and the
/// deciding stages; the tally's `file` is `path`, its `seconds` the time in the decisions only.
/// Coordinates must be doubles, except with Mode::exact, which decides rational queries.
/// Throws InputError for an unreadable or malformed file, an unknown type, or a coordinate that
/// is not a double outside Mode::exact; the library's std::invalid_argument for settings it
/// refuses (a t_max outside (0, 1]).
CheckTally check_file(const std::string& path, std::optional<QueryType> type,
                      const CheckSettings& settings, const CheckVisitor& on_query = {});

/// The same on queries [begin, end) of a file already read (`end` clipped to its query count;
/// indices are the file's): one shard of it, e.g. a task of a distributed check. Tallies of
/// shards add up (CheckTally::add) to the file's.
CheckTally check_queries(const QueryFile& input, std::size_t begin, std::size_t end,
                         const CheckSettings& settings, const CheckVisitor& on_query = {});

/// Decides every query of the file `path` of a point kind or the plane (PrimitiveKind: its own
/// rows per query and columns), as check_file does for the benchmark's kinds: the tally of its
/// collisions, disagreements with the truth column and stages. Coordinates must be doubles,
/// except with Mode::exact for the point kinds (decided as the edge-edge query they are).
/// Throws InputError for a malformed file, a coordinate that is not a double where one is
/// needed, or a zero plane normal (at its query's line).
CheckTally check_primitive_file(const std::string& path, PrimitiveKind kind,
                                const CheckSettings& settings, const CheckVisitor& on_query = {});

/// The file of a point kind (pe, pe2d, pp, pp2d) as the edge-edge queries its queries are, each
/// point the zero-length segment [p, p] (rows copied; proofs/api_reductions.md,
/// point-primitives), with their truth and first lines. Throws InputError for the plane (pl),
/// which is no edge-edge query.
QueryFile as_edge_edge_file(const PrimitiveQueryFile& file);

/// Counts one decided query into `tally`: a collision, a disagreement with `truth`, its stage.
void count_query(CheckTally& tally, const CcdResult& result, bool truth);

}  // namespace exactccd::oracle
