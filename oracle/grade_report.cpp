#include "oracle/grade_report.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

namespace exactccd::oracle {

namespace {

std::vector<std::size_t> first_indices(const std::vector<std::size_t>& indices) {
  return {indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(
                                                 std::min(indices.size(), kMaxListedIndices))};
}

void print_category(std::ostream& out, const char* name, const std::vector<std::size_t>& indices) {
  out << name << ": " << indices.size();
  if (!indices.empty()) {
    out << "  (queries";
    for (const std::size_t i : first_indices(indices)) out << ' ' << i;
    if (indices.size() > kMaxListedIndices)
      out << " ... and " << indices.size() - kMaxListedIndices << " more";
    out << ')';
  }
  out << '\n';
}

}  // namespace

void print_grade_text(std::ostream& out, const GradeFindings& f) {
  out << "queries: " << f.queries << " (" << f.tois_given << " with a toi)\n";
  print_category(out, "false positives", f.false_positives);
  print_category(out, "false negatives", f.false_negatives);
  print_category(out, "non-conservative tois", f.non_conservative);
  out << (f.all_good() ? "all answers correct and conservative\n"
                       : "some answers are wrong or not conservative\n");
}

void print_grade_json(std::ostream& out, const GradeFindings& f, double t_max,
                      double min_separation) {
  nlohmann::ordered_json j;
  j["queries"] = f.queries;
  j["tois_given"] = f.tois_given;
  j["t_max"] = t_max;
  j["min_separation"] = min_separation;
  j["false_positives"] = f.false_positives.size();
  j["false_negatives"] = f.false_negatives.size();
  j["non_conservative_tois"] = f.non_conservative.size();
  // The first kMaxListedIndices offending indices of each category.
  j["false_positive_indices"] = first_indices(f.false_positives);
  j["false_negative_indices"] = first_indices(f.false_negatives);
  j["non_conservative_toi_indices"] = first_indices(f.non_conservative);
  out << j.dump(2) << '\n';
}

}  // namespace exactccd::oracle
