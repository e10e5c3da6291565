#include "check.hpp"

#include <chrono>
#include <fstream>
#include <iostream>
#include <utility>

#include "check_report.hpp"
#include "cli_common.hpp"
#include "exactccd/query_file.hpp"
#include "progress.hpp"

namespace exactccd::cli {

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

// One line per query: file,index,collides,toi_lo,toi_hi (TOI fields empty without contact).
void write_result_line(std::ostream& out, const std::string& file, std::size_t index,
                       const CcdResult& r) {
  out << file << ',' << index << ',' << (r.collides ? 1 : 0) << ',';
  if (r.collides)
    out << format_double(r.toi_lo) << ',' << format_double(r.toi_hi);
  else
    out << ',';
  out << '\n';
}

}  // namespace

int run_check(const CheckOptions& options) {
  validate_t_max(options.t_max);
  const auto files = list_files(options);

  std::ofstream out_file;
  if (!options.out_path.empty()) {
    out_file.open(options.out_path);
    if (!out_file) throw UsageError(options.out_path + ": cannot open for writing (--out)");
  }

  CcdOptions ccd_options;
  ccd_options.t_max = options.t_max;
  Progress progress;
  std::vector<CheckTally> tallies;
  CheckTally total;
  total.file = "TOTAL";
  for (std::size_t k = 0; k < files.size(); ++k) {
    const QueryFile input = read_query_file(files[k].first, files[k].second);
    CheckTally tally;
    tally.file = input.path;
    for (std::size_t i = 0; i < input.queries.size(); ++i) {
      const QueryRecord& record = input.queries[i];
      const auto start = std::chrono::steady_clock::now();
      const CcdResult result = exact_ccd(record.query, ccd_options);
      tally.seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++tally.queries;
      tally.collisions += result.collides;
      tally.false_positives += result.collides && !record.truth;
      tally.false_negatives += !result.collides && record.truth;
      if (out_file.is_open()) write_result_line(out_file, input.path, i, result);
      progress.update(k, files.size(), input.path, i + 1, input.queries.size());
    }
    total.add(tally);
    tallies.push_back(std::move(tally));
  }
  progress.clear();

  if (out_file.is_open()) {
    out_file.close();
    if (!out_file) throw UsageError(options.out_path + ": write failed (--out)");
  }
  if (options.json)
    print_check_json(std::cout, tallies, total, options.t_max);
  else
    print_check_table(std::cout, tallies, total);
  return total.disagreements() == 0 ? kExitAgree : kExitDisagree;
}

}  // namespace exactccd::cli
