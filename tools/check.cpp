#include "check.hpp"

#include <chrono>
#include <cstring>
#include <iostream>
#include <utility>

#include "check_report.hpp"
#include "cli_common.hpp"
#include "exact/rational.hpp"
#include "exactccd/ccd.hpp"
#include "output_file.hpp"
#include "progress.hpp"

namespace exactccd::cli {

// ---- Shared pieces ----------------------------------------------------------------------------

std::optional<Mode> parse_mode_name(const std::string& name) {
  for (const Mode m : {Mode::float_only, Mode::filtered, Mode::exact})
    if (name == to_string(m)) return m;
  return std::nullopt;
}

const std::vector<std::string>& mode_names() {
  static const std::vector<std::string> names = {
      to_string(Mode::float_only), to_string(Mode::filtered), to_string(Mode::exact)};
  return names;
}

const std::vector<Stage>& all_stages() {
  static const std::vector<Stage> stages = [] {
    std::vector<Stage> found;
    for (int k = 0; k < 256; ++k) {
      const Stage s = static_cast<Stage>(k);
      if (std::strcmp(to_string(s), "unknown") == 0) break;
      found.push_back(s);
    }
    return found;
  }();
  return stages;
}

std::vector<Stage> stages_of(Mode mode) {
  switch (mode) {
    case Mode::float_only: return {Stage::float_only};
    case Mode::exact: return {Stage::exact};
    case Mode::filtered: break;
  }
  std::vector<Stage> stages;
  for (const Stage s : all_stages())
    if (s != Stage::float_only) stages.push_back(s);
  return stages;
}

std::optional<QueryPoints> exact_doubles(const RationalQuery& query, std::size_t* bad_row) {
  QueryPoints points;
  for (std::size_t row = 0; row < 8; ++row) {
    const RationalPoint& p = query.points[row];
    double x, y, z;
    if (!exact::to_double_exactly(p.x, &x) || !exact::to_double_exactly(p.y, &y) ||
        !exact::to_double_exactly(p.z, &z)) {
      *bad_row = row;
      return std::nullopt;
    }
    points[row] = {x, y, z};
  }
  return points;
}

VertexFaceQuery vertex_face_query(const QueryPoints& p) {
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

EdgeEdgeQuery edge_edge_query(const QueryPoints& p) {
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

// ---- The subcommand ---------------------------------------------------------------------------

namespace {

// Every file to read with its type, all resolved before any work so that a bad path or an
// untyped file fails at once.
std::vector<std::pair<std::string, QueryType>> list_files(const CheckOptions& options) {
  std::vector<std::pair<std::string, QueryType>> files;
  for (const std::string& path : options.paths)
    for (const std::string& file : find_query_files(path))
      files.emplace_back(file, resolve_query_type(file, options.type));
  return files;
}

// One line per query: file,index,collides,toi_lo,toi_hi (TOI fields "inf" without contact: the
// library's +infinity, which %.17g writes so and strtod and Python's float read back).
void write_result_line(OutputFile& out, const std::string& file, std::size_t index,
                       const CcdResult& r) {
  std::string line = file + ',' + std::to_string(index) + (r.collides ? ",1," : ",0,");
  line += format_double(r.toi_lo) + ',' + format_double(r.toi_hi);
  line += '\n';
  out.write(line);
}

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

int run_check(const CheckOptions& options) {
  validate_t_max(options.t_max);
  const auto files = list_files(options);

  // Opened before the work, so that an unwritable --out fails at once; renamed into place
  // only when every query is decided.
  std::optional<OutputFile> out_file;
  if (!options.out_path.empty())
    out_file.emplace(options.out_path, options.force ? Overwrite::replace : Overwrite::refuse,
                     "--out");

  CcdOptions ccd_options;
  ccd_options.t_max = options.t_max;
  ccd_options.mode = options.mode;
  Progress progress;
  std::vector<CheckTally> tallies;
  CheckTally total;
  total.file = "TOTAL";
  std::vector<std::string> empty_files;
  for (std::size_t k = 0; k < files.size(); ++k) {
    const QueryFile input = read_query_file(files[k].first, files[k].second);
    if (input.queries.empty()) empty_files.push_back(input.path);
    CheckTally tally;
    tally.file = input.path;
    for (std::size_t i = 0; i < input.queries.size(); ++i) {
      const QueryRecord& record = input.queries[i];
      const CcdResult result = decide(input, record, ccd_options, &tally.seconds);
      ++tally.queries;
      tally.collisions += result.collides;
      tally.false_positives += result.collides && !record.truth;
      tally.false_negatives += !result.collides && record.truth;
      tally.count_stage(result.decided_by);
      if (out_file) write_result_line(*out_file, input.path, i, result);
      progress.update(k, files.size(), input.path, i + 1, input.queries.size());
    }
    total.add(tally);
    tallies.push_back(std::move(tally));
  }
  progress.clear();
  require_some_queries(empty_files, files.size(), total.queries);

  if (out_file) out_file->commit();
  if (options.json)
    print_check_json(std::cout, options.mode, tallies, total, options.t_max);
  else
    print_check_table(std::cout, options.mode, tallies, total);
  return total.disagreements() == 0 ? kExitAgree : kExitDisagree;
}

}  // namespace exactccd::cli
