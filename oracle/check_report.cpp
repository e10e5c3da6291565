#include "oracle/check_report.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "oracle/names.hpp"

namespace exactccd::oracle {

void CheckTally::count_stage(Stage stage) {
  const auto k = static_cast<std::size_t>(stage);
  if (stage_counts.size() <= k) stage_counts.resize(k + 1, 0);
  ++stage_counts[k];
}

std::size_t CheckTally::stage_count(Stage stage) const {
  const auto k = static_cast<std::size_t>(stage);
  return k < stage_counts.size() ? stage_counts[k] : 0;
}

void CheckTally::add(const CheckTally& other) {
  queries += other.queries;
  collisions += other.collisions;
  false_positives += other.false_positives;
  false_negatives += other.false_negatives;
  seconds += other.seconds;
  if (stage_counts.size() < other.stage_counts.size())
    stage_counts.resize(other.stage_counts.size(), 0);
  for (std::size_t k = 0; k < other.stage_counts.size(); ++k)
    stage_counts[k] += other.stage_counts[k];
}

std::vector<Stage> reported_stages(Mode mode, const CheckTally& total) {
  const std::vector<Stage> possible = stages_of(mode);
  std::vector<Stage> shown;
  for (const Stage s : all_stages())
    if (std::find(possible.begin(), possible.end(), s) != possible.end() ||
        total.stage_count(s) > 0)
      shown.push_back(s);
  return shown;
}

namespace {

int stage_column_width(Stage s) {
  return std::max(8, static_cast<int>(std::char_traits<char>::length(to_string(s))));
}

double share(const CheckTally& t, Stage s) {
  return t.queries == 0 ? 0.0 : static_cast<double>(t.stage_count(s)) / t.queries;
}

void print_row(std::ostream& out, int name_width, const CheckTally& t,
               const std::vector<Stage>& stages) {
  char mean[32] = "-";
  if (t.queries > 0) std::snprintf(mean, sizeof mean, "%.1f", 1e6 * t.seconds / t.queries);
  char line[512];
  std::snprintf(line, sizeof line, "%-*s %9zu %10zu %9zu %9zu %9zu %9zu %9s", name_width,
                t.file.c_str(), t.queries, t.collisions, t.queries - t.disagreements(),
                t.disagreements(), t.false_positives, t.false_negatives, mean);
  out << line;
  for (const Stage s : stages) {
    std::snprintf(line, sizeof line, " %*.2f%%", stage_column_width(s) - 1, 100.0 * share(t, s));
    out << line;
  }
  out << '\n';
}

nlohmann::ordered_json counts_json(const CheckTally& t, const std::vector<Stage>& stages) {
  nlohmann::ordered_json j;
  j["queries"] = t.queries;
  j["collisions"] = t.collisions;
  j["false_positives"] = t.false_positives;
  j["false_negatives"] = t.false_negatives;
  j["seconds"] = t.seconds;
  nlohmann::ordered_json counts = nlohmann::ordered_json::object();
  nlohmann::ordered_json shares = nlohmann::ordered_json::object();
  for (const Stage s : stages) {
    counts[to_string(s)] = t.stage_count(s);
    shares[to_string(s)] = share(t, s);
  }
  j["stage_counts"] = std::move(counts);
  j["stage_share"] = std::move(shares);
  return j;
}

}  // namespace

void print_check_table(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                       const CheckTally& total) {
  const std::vector<Stage> stages = reported_stages(mode, total);
  out << "mode: " << to_string(mode)
      << "  (last columns: share of queries decided by each stage)\n";
  int width = static_cast<int>(total.file.size());
  for (const CheckTally& f : files) width = std::max(width, static_cast<int>(f.file.size()));
  char header[512];
  std::snprintf(header, sizeof header, "%-*s %9s %10s %9s %9s %9s %9s %9s", width, "file",
                "queries", "collisions", "agree", "disagree", "false_pos", "false_neg", "us/query");
  out << header;
  for (const Stage s : stages) {
    std::snprintf(header, sizeof header, " %*s", stage_column_width(s), to_string(s));
    out << header;
  }
  out << '\n';
  for (const CheckTally& f : files) print_row(out, width, f, stages);
  print_row(out, width, total, stages);
}

void print_check_json(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                      const CheckTally& total, double t_max) {
  const std::vector<Stage> stages = reported_stages(mode, total);
  nlohmann::ordered_json j;
  j["mode"] = to_string(mode);
  j.update(counts_json(total, stages));
  j["t_max"] = t_max;
  j["files"] = nlohmann::ordered_json::array();
  for (const CheckTally& f : files) {
    nlohmann::ordered_json entry;
    entry["file"] = f.file;
    entry.update(counts_json(f, stages));
    j["files"].push_back(std::move(entry));
  }
  out << j.dump(2) << '\n';
}

}  // namespace exactccd::oracle
