#include "oracle/check.hpp"

#include <algorithm>
#include <chrono>

#include "exactccd/ccd.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/names.hpp"

namespace exactccd::oracle {

namespace {

// Decides one query of `file` with the chosen mode, through the public double API when every
// coordinate is a double. Otherwise only the exact mode can decide it (on the rationals).
CcdResult decide(const QueryFile& file, const QueryRecord& record, const CcdOptions& options,
                 double* seconds) {
  std::size_t bad_row = 0;
  const std::optional<QueryPoints> points = exact_doubles(record.query, &bad_row);
  if (!points && options.mode != Mode::exact)
    throw InputError(file.path, record.line_of_row(bad_row),
                     std::string("a coordinate is not exactly a double: only --mode exact "
                                 "decides such queries (--mode ") +
                         to_string(options.mode) + ")");
  const auto start = std::chrono::steady_clock::now();
  CcdResult result;
  if (!points)
    result = exact_ccd(record.query, options);
  else if (file.type == QueryType::vertex_face)
    result = vertex_face_ccd(vertex_face_query(*points), options);
  else
    result = edge_edge_ccd(edge_edge_query(*points), options);
  *seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

CheckTally check_file(const std::string& path, std::optional<QueryType> type,
                      const CheckSettings& settings, const CheckVisitor& on_query) {
  const QueryFile input = read_query_file(path, resolve_query_type(path, type));
  return check_queries(input, 0, input.queries.size(), settings, on_query);
}

CheckTally check_queries(const QueryFile& input, std::size_t begin, std::size_t end,
                         const CheckSettings& settings, const CheckVisitor& on_query) {
  CcdOptions ccd_options;
  ccd_options.t_max = settings.t_max;
  ccd_options.mode = settings.mode;
  ccd_options.min_separation = settings.min_separation;
  CheckTally tally;
  tally.file = input.path;
  const std::size_t stop = std::min(end, input.queries.size());
  for (std::size_t i = begin; i < stop; ++i) {
    const QueryRecord& record = input.queries[i];
    const CcdResult result = decide(input, record, ccd_options, &tally.seconds);
    count_query(tally, result, record.truth);
    if (on_query) on_query(i, input.queries.size(), result);
  }
  return tally;
}

void count_query(CheckTally& tally, const CcdResult& result, bool truth) {
  ++tally.queries;
  tally.collisions += result.collides;
  tally.false_positives += result.collides && !truth;
  tally.false_negatives += !result.collides && truth;
  tally.count_stage(result.decided_by);
}

}  // namespace exactccd::oracle
