#include "check_report.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace exactccd::cli {

void CheckTally::add(const CheckTally& other) {
  queries += other.queries;
  collisions += other.collisions;
  false_positives += other.false_positives;
  false_negatives += other.false_negatives;
  seconds += other.seconds;
}

namespace {

void print_row(std::ostream& out, int name_width, const CheckTally& t) {
  char mean[32] = "-";
  if (t.queries > 0) std::snprintf(mean, sizeof mean, "%.1f", 1e6 * t.seconds / t.queries);
  char line[512];
  std::snprintf(line, sizeof line, "%-*s %9zu %10zu %9zu %9zu %9zu %9zu %9s\n", name_width,
                t.file.c_str(), t.queries, t.collisions, t.queries - t.disagreements(),
                t.disagreements(), t.false_positives, t.false_negatives, mean);
  out << line;
}

nlohmann::ordered_json counts_json(const CheckTally& t) {
  nlohmann::ordered_json j;
  j["queries"] = t.queries;
  j["collisions"] = t.collisions;
  j["false_positives"] = t.false_positives;
  j["false_negatives"] = t.false_negatives;
  j["seconds"] = t.seconds;
  return j;
}

}  // namespace

void print_check_table(std::ostream& out, const std::vector<CheckTally>& files,
                       const CheckTally& total) {
  int width = static_cast<int>(total.file.size());
  for (const CheckTally& f : files) width = std::max(width, static_cast<int>(f.file.size()));
  char header[512];
  std::snprintf(header, sizeof header, "%-*s %9s %10s %9s %9s %9s %9s %9s\n", width, "file",
                "queries", "collisions", "agree", "disagree", "false_pos", "false_neg", "us/query");
  out << header;
  for (const CheckTally& f : files) print_row(out, width, f);
  print_row(out, width, total);
}

void print_check_json(std::ostream& out, const std::vector<CheckTally>& files,
                      const CheckTally& total, double t_max) {
  nlohmann::ordered_json j = counts_json(total);
  j["t_max"] = t_max;
  j["files"] = nlohmann::ordered_json::array();
  for (const CheckTally& f : files) {
    nlohmann::ordered_json entry;
    entry["file"] = f.file;
    entry.update(counts_json(f));
    j["files"].push_back(std::move(entry));
  }
  out << j.dump(2) << '\n';
}

}  // namespace exactccd::cli
