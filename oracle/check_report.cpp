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

double CheckTally::stage_share(Stage stage) const {
  return queries == 0 ? 0.0 : static_cast<double>(stage_count(stage)) / queries;
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
    std::snprintf(line, sizeof line, " %*.2f%%", stage_column_width(s) - 1,
                  100.0 * t.stage_share(s));
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
    shares[to_string(s)] = t.stage_share(s);
  }
  j["stage_counts"] = std::move(counts);
  j["stage_share"] = std::move(shares);
  return j;
}

}  // namespace

namespace {

/// A short header for a stage's share column in the compact table.
const char* short_name(Stage s) {
  switch (s) {
    case Stage::culling: return "cull";
    case Stage::filter: return "filter";
    case Stage::filter_exact_toi: return "f+xtoi";
    case Stage::exact_at_double: return "ex@dbl";
    case Stage::exact: return "exact";
    case Stage::float_only: return "float";
  }
  return "?";
}

/// The names shown in the compact table: below the files' common folder (when there are
/// several), the type folders as vf/ and ee/, and at most `width` characters (cut in the
/// middle, marked by "...").
std::vector<std::string> short_file_names(const std::vector<CheckTally>& files,
                                          const CheckTally& total, std::size_t width) {
  std::size_t common = 0;
  if (files.size() >= 2) {
    const std::string& first = files.front().file;
    std::size_t n = first.size();
    for (const CheckTally& f : files) {
      std::size_t k = 0;
      while (k < n && k < f.file.size() && first[k] == f.file[k]) ++k;
      n = k;
    }
    const std::size_t slash = first.rfind('/', n == 0 ? 0 : n - 1);
    common = (n == 0 || slash == std::string::npos) ? 0 : slash + 1;
  }
  std::vector<std::string> names;
  for (const CheckTally& f : files) {
    std::string name = f.file.substr(common);
    for (const auto& [folder, code] : {std::pair<std::string, std::string>{"vertex-face/", "vf/"},
                                       {"edge-edge/", "ee/"}})
      for (std::size_t at; (at = name.find(folder)) != std::string::npos;)
        name.replace(at, folder.size(), code);
    if (name.size() > width && width > 3) {  // keep both ends: the family and the file
      const std::size_t head = (width - 3) / 2, tail = width - 3 - head;
      name = name.substr(0, head) + "..." + name.substr(name.size() - tail);
    }
    names.push_back(std::move(name));
  }
  names.push_back(total.file);
  return names;
}

void print_full_table(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
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

}  // namespace

void print_check_table(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                       const CheckTally& total, int max_width) {
  if (max_width <= 0) {
    print_full_table(out, mode, files, total);
    return;
  }
  const std::vector<Stage> stages = reported_stages(mode, total);
  // Columns after the name: queries 8, collisions 7, false_pos 5, false_neg 5, us/query 9, each
  // stage 7 (" 100.0%"); the name takes what is left (at least 12).
  const int fixed = 8 + 7 + 5 + 5 + 9 + 7 * static_cast<int>(stages.size());
  const int name_width = std::max(12, max_width - fixed);
  const std::vector<std::string> names =
      short_file_names(files, total, static_cast<std::size_t>(name_width));
  int width = 4;  // "file"
  for (const std::string& n : names) width = std::max(width, static_cast<int>(n.size()));
  out << "mode: " << to_string(mode) << "  (stage shares; --format wide: every column)\n";
  char cell[512];
  std::snprintf(cell, sizeof cell, "%-*s %7s %6s %4s %4s %8s", width, "file", "queries",
                "coll", "FP", "FN", "us/query");
  out << cell;
  for (const Stage s : stages) {
    std::snprintf(cell, sizeof cell, " %6s", short_name(s));
    out << cell;
  }
  out << '\n';
  for (std::size_t i = 0; i <= files.size(); ++i) {
    const CheckTally& t = i < files.size() ? files[i] : total;
    char mean[32] = "-";
    if (t.queries > 0) std::snprintf(mean, sizeof mean, "%.1f", 1e6 * t.seconds / t.queries);
    std::snprintf(cell, sizeof cell, "%-*s %7zu %6zu %4zu %4zu %8s", width, names[i].c_str(),
                  t.queries, t.collisions, t.false_positives, t.false_negatives, mean);
    out << cell;
    for (const Stage s : stages) {
      std::snprintf(cell, sizeof cell, " %5.1f%%", 100.0 * t.stage_share(s));
      out << cell;
    }
    out << '\n';
  }
}

void print_check_csv(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                     const CheckTally& total) {
  const std::vector<Stage> stages = reported_stages(mode, total);
  out << "file,queries,collisions,agree,disagree,false_positives,false_negatives,us_per_query";
  for (const Stage s : stages) out << ",share_" << to_string(s);
  out << '\n';
  auto quoted = [](const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string q = "\"";
    for (const char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + '"';
  };
  for (std::size_t i = 0; i <= files.size(); ++i) {
    const CheckTally& t = i < files.size() ? files[i] : total;
    char numbers[256];
    std::snprintf(numbers, sizeof numbers, ",%zu,%zu,%zu,%zu,%zu,%zu,", t.queries, t.collisions,
                  t.queries - t.disagreements(), t.disagreements(), t.false_positives,
                  t.false_negatives);
    out << quoted(t.file) << numbers;
    if (t.queries > 0) {
      char mean[32];
      std::snprintf(mean, sizeof mean, "%.3f", 1e6 * t.seconds / t.queries);
      out << mean;
    }
    for (const Stage s : stages) {
      char v[32];
      std::snprintf(v, sizeof v, ",%.6f", t.stage_share(s));
      out << v;
    }
    out << '\n';
  }
}

void print_check_json(std::ostream& out, Mode mode, const std::vector<CheckTally>& files,
                      const CheckTally& total, double t_max, double min_separation) {
  const std::vector<Stage> stages = reported_stages(mode, total);
  nlohmann::ordered_json j;
  j["mode"] = to_string(mode);
  j.update(counts_json(total, stages));
  j["t_max"] = t_max;
  j["min_separation"] = min_separation;
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
