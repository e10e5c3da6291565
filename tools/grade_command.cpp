#include "grade_command.hpp"

#include <filesystem>
#include <iostream>
#include <utility>
#include <vector>

#include "exact/arithmetic/rational.hpp"
#include "oracle/answers_file.hpp"
#include "oracle/common.hpp"
#include "oracle/grade.hpp"
#include "oracle/inspection.hpp"
#include "oracle/inspection_report.hpp"
#include "oracle/inspector_page.hpp"
#include "oracle/names.hpp"
#include "oracle/output_file.hpp"
#include "oracle/progress.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

namespace {

// The folder of a report's pages: REPORT.html -> REPORT_files (as browsers save a page).
std::string pages_folder(const std::string& report) {
  std::filesystem::path p(report);
  return (p.parent_path() / (p.stem().string() + "_files")).string();
}

// REPORT.html and its folder: the grading tables, and an inspector page for each of the first
// `limit` findings of each kind (wrong verdicts, late TOIs), with the count of the rest.
void write_grade_report(const GradeOptions& options, const GradeFindings& findings) {
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  const QueryType type = resolve_query_type(options.queries_path, options.type);
  const QueryFile file = read_query_file(options.queries_path, type);
  const std::vector<Answer> answers = read_answers_file(
      options.answers_path, file.queries.size(), options.queries_path, options.t_max);
  const std::string folder = pages_folder(options.html_path);
  const std::string folder_name = std::filesystem::path(folder).filename().string();

  // The pages show the exact path's answer (what the grading is against), which takes any
  // rational coordinates; every page is made before the folder is, so that an error leaves
  // nothing behind.
  InspectSettings settings;
  settings.mode = Mode::exact;
  settings.t_max = options.t_max;
  settings.min_separation = options.min_separation;
  std::vector<std::pair<std::string, std::string>> page_data;  // {name, JSON}
  std::vector<IndexSection> sections;
  sections.push_back({"Summary", "",
                      {"queries", "answers with a TOI", "false positives", "false negatives",
                       "late TOIs (later than the exact first contact)"},
                      {{{std::to_string(findings.queries), std::to_string(findings.tois_given),
                         std::to_string(findings.false_positives.size()),
                         std::to_string(findings.false_negatives.size()),
                         std::to_string(findings.non_conservative.size())},
                        {}}}});
  const struct {
    const char* finding;
    const std::vector<std::size_t>& indices;
  } kinds[] = {{"false positive", findings.false_positives},
               {"false negative", findings.false_negatives},
               {"late TOI", findings.non_conservative}};
  for (const auto& kind : kinds) {
    IndexSection section{std::string(kind.finding) + "s (" + std::to_string(kind.indices.size()) +
                             ")",
                         "",
                         {"query", "line", "graded answer", "graded TOI", "exact TOI"},
                         {}};
    if (kind.indices.empty()) section.text = "None.";
    for (std::size_t n = 0; n < kind.indices.size() && n < options.html_limit; ++n) {
      const std::size_t i = kind.indices[n];
      const Answer& a = answers[i];
      GradedAnswer graded{kind.finding, a.collides, std::nullopt, 0.0};
      if (a.toi) {
        graded.toi = a.toi->get_str();
        graded.toi_double = exact::round_nearest(*a.toi);
      }
      page_data.push_back({"query_" + std::to_string(i),
                           inspection_json(file.queries[i], type, options.queries_path, i,
                                           settings, &graded)});
      const std::string page = page_data.back().first + ".html";
      CcdOptions exact_options;
      exact_options.t_max = options.t_max;
      exact_options.min_separation = options.min_separation;
      const CcdResult exact = exact_ccd(file.queries[i].query, exact_options);
      section.rows.push_back(
          {{"query " + std::to_string(i), std::to_string(file.queries[i].first_line),
            a.collides ? "1" : "0", a.toi ? format_double(exact::round_nearest(*a.toi)) : "-",
            exact.collides ? format_double(exact.toi_lo) : "no contact"},
           {folder_name + "/" + page}});
    }
    if (kind.indices.size() > options.html_limit) {
      const std::size_t rest = kind.indices.size() - options.html_limit;
      section.text = "The first " + std::to_string(options.html_limit) + " are shown; " +
                     std::to_string(rest) + (rest == 1 ? " more is not" : " more are not") +
                     " (exactccd grade --json lists them; --html-limit shows more).";
    }
    sections.push_back(std::move(section));
  }
  const std::string intro = "Answers " + options.answers_path + " graded against the exact "
                            "decision of " + options.queries_path + " (t_max " +
                            format_double(options.t_max) + ", minimum separation " +
                            format_double(options.min_separation) +
                            "). Each linked query opens its inspector.";
  InspectionFolder pages(folder, overwrite, "--html");
  for (const auto& [name, json] : page_data) pages.add_page(name, json);
  write_file_atomically(options.html_path, index_page("exactccd grade", intro, sections),
                        overwrite, "--html");
}

}  // namespace

int run_grade(const GradeOptions& options) {
  validate_t_max(options.t_max);
  validate_min_separation(options.min_separation);
  if (!options.html_path.empty()) {
    if (options.primitive)
      throw UsageError("--html shows vertex-face and edge-edge files (not --type " +
                       std::string(to_string(*options.primitive)) + ")");
    require_inspector();
    check_output_path(options.html_path,
                      options.force ? Overwrite::replace : Overwrite::refuse, "--html");
  }
  Progress progress;
  const GradeFindings findings = grade_file(
      options.queries_path, options.answers_path, options.type, options.t_max,
      [&](std::size_t done, std::size_t count) {
        progress.update(0, 1, options.queries_path, done, count);
      },
      options.min_separation, options.primitive);
  progress.clear();
  if (!options.html_path.empty()) write_grade_report(options, findings);

  if (options.json)
    print_grade_json(std::cout, findings, options.t_max, options.min_separation);
  else
    print_grade_text(std::cout, findings);
  return findings.all_good() ? kExitAgree : kExitDisagree;
}

}  // namespace exactccd::cli
