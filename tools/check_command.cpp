#include "check_command.hpp"

#include <iostream>
#include <utility>

#include "exactccd/query_file.hpp"
#include "oracle/check.hpp"
#include "oracle/common.hpp"
#include "oracle/names.hpp"
#include "oracle/output_file.hpp"
#include "oracle/progress.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

namespace {

// Every file to read with its type, all resolved before any work so that a bad path or an
// untyped file fails at once.
std::vector<std::pair<std::string, QueryType>> list_files(const CheckOptions& options) {
  std::vector<std::pair<std::string, QueryType>> files;
  for (const std::string& path : options.paths) {
    if (options.primitive) {  // a point kind: the files themselves
      require_regular_file(path, std::string("a query file of --type ") +
                                     to_string(*options.primitive));
      files.emplace_back(path, QueryType::edge_edge);  // the type is unused for these
      continue;
    }
    for (const std::string& file : find_query_files(path))
      files.emplace_back(file, resolve_query_type(file, options.type));
  }
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

}  // namespace

int run_check(const CheckOptions& options) {
  validate_t_max(options.t_max);
  validate_min_separation(options.min_separation);
  const auto files = list_files(options);

  // Opened before the work, so that an unwritable --out fails at once; renamed into place
  // only when every query is decided.
  std::optional<OutputFile> out_file;
  if (!options.out_path.empty())
    out_file.emplace(options.out_path, options.force ? Overwrite::replace : Overwrite::refuse,
                     "--out");

  CheckSettings settings;
  settings.t_max = options.t_max;
  settings.mode = options.mode;
  settings.min_separation = options.min_separation;
  Progress progress;
  std::vector<CheckTally> tallies;
  CheckTally total;
  total.file = "TOTAL";
  std::vector<std::string> empty_files;
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string& file = files[k].first;
    const auto visit = [&](std::size_t index, std::size_t count, const CcdResult& result) {
      if (out_file) write_result_line(*out_file, file, index, result);
      progress.update(k, files.size(), file, index + 1, count);
    };
    CheckTally tally = options.primitive
                           ? check_primitive_file(file, *options.primitive, settings, visit)
                           : check_file(file, files[k].second, settings, visit);
    if (tally.queries == 0) empty_files.push_back(tally.file);
    total.add(tally);
    tallies.push_back(std::move(tally));
  }
  progress.clear();
  require_some_queries(empty_files, files.size(), total.queries);

  if (out_file) out_file->commit();
  if (options.format == "json")
    print_check_json(std::cout, options.mode, tallies, total, options.t_max,
                     options.min_separation);
  else if (options.format == "csv")
    print_check_csv(std::cout, options.mode, tallies, total);
  else
    print_check_table(std::cout, options.mode, tallies, total,
                      options.format == "wide" ? 0 : kCheckTableWidth);
  return total.disagreements() == 0 ? kExitAgree : kExitDisagree;
}

}  // namespace exactccd::cli
