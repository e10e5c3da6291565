// What `exactccd inspect` computes for one query: everything the inspector page shows (the
// points, the certified answer of a mode, the exact and float_only answers, the polynomial that
// decides the query with its roots as exact brackets and the inclusion test at each, the
// contact geometry, the distance over the step with a minimum separation), as one JSON document,
// and the self-contained page (inspector_page.hpp) that draws it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::oracle {

struct InspectSettings {
  Mode mode = Mode::filtered;   ///< the path whose answer the page shows as "the answer"
  double t_max = 1.0;           ///< in [0, 1]
  double min_separation = 0.0;  ///< delta >= 0 (0: contact)
};

/// Another code's answer to the query, shown beside the exact one (`exactccd grade --html`).
struct GradedAnswer {
  std::string finding;             ///< e.g. "false positive", "late TOI"
  bool collides = false;
  std::optional<std::string> toi;  ///< the TOI as the answers file gave it, exactly
  double toi_double = 0.0;         ///< its nearest double, for drawing
};

/// The inspection of `record` (a query of type `type`, from `source` at 0-based `index`) as the
/// JSON text the page reads (format "exactccd-inspection", version 1; schema in
/// oracle/inspector/README.md). The mode's answer needs coordinates that are doubles, except
/// with Mode::exact; throws InputError naming the row otherwise. Throws std::invalid_argument for
/// settings the library refuses.
std::string inspection_json(const QueryRecord& record, QueryType type, const std::string& source,
                            std::size_t index, const InspectSettings& settings,
                            const GradedAnswer* graded = nullptr);

/// The inspection of a rigid query (a contact of a rigid scene's step, say) over s in
/// [0, t_max]: the vertices' exact positions at sample parameters rounded ("motion":
/// "samples"), the answers of the mode, the exact path and float_only in s, the reduced rigid
/// coplanarity polynomial g(s) with its roots as exact brackets and the inclusion test at each,
/// and the contact geometry. `title`, `source`, `labels` (4 names) and the scene's `step`
/// (1-based) describe the pair.
std::string rigid_inspection_json(const RigidVertexFaceQuery& query, const InspectSettings& settings,
                                  const std::string& title, const std::string& source,
                                  const std::vector<std::string>& labels,
                                  std::optional<std::size_t> step = std::nullopt);
std::string rigid_inspection_json(const RigidEdgeEdgeQuery& query, const InspectSettings& settings,
                                  const std::string& title, const std::string& source,
                                  const std::vector<std::string>& labels,
                                  std::optional<std::size_t> step = std::nullopt);

/// The inspection of a point against a plane: linear motion (a query of a `pl` file: `source`,
/// `index`, `first_line` and `truth` from it) or a rigid body's point against a static plane
/// (a contact of a rigid scene's `step`). The plane offset polynomial f = (p - o) . n (rigid: its
/// numerator F(s) on the path's common denominator) with its roots as exact brackets.
struct PointPlaneSource {
  std::string file;
  std::optional<std::size_t> index, first_line, step;
  std::optional<bool> truth;
  std::string title;
};
std::string point_plane_inspection_json(const PointPlaneQuery& query,
                                        const InspectSettings& settings,
                                        const PointPlaneSource& source);
std::string rigid_point_plane_inspection_json(const RigidPointPlaneQuery& query,
                                              const InspectSettings& settings,
                                              const PointPlaneSource& source);

/// The inspection of query `index` (0-based) of the benchmark CSV file `path` (its type `type`
/// when given, else from the folder name), or of a file of a point kind or the plane
/// (`primitive`: pe, pp and their 2D forms as the edge-edge queries of their zero-length
/// segments, pl as a point-plane query). Throws InputError for a file that is not such a file
/// or an index past its end, and as inspection_json does.
std::string inspect_file_query(const std::string& path, std::optional<QueryType> type,
                               std::size_t index, const InspectSettings& settings,
                               std::optional<PrimitiveKind> primitive = std::nullopt);

/// A short text account of the same inspection (verdict, TOI, stage, float_only, the roots and
/// their inclusion test), for a terminal.
std::string inspection_text(const std::string& json);

}  // namespace exactccd::oracle
