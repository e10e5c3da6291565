#include "grade.hpp"

#include <iostream>

#include "answers_file.hpp"
#include "cli_common.hpp"
#include "exactccd/query_file.hpp"
#include "grade_report.hpp"
#include "progress.hpp"

namespace exactccd::cli {

int run_grade(const GradeOptions& options) {
  validate_t_max(options.t_max);
  const QueryFile input =
      read_query_file(options.queries_path, resolve_query_type(options.queries_path, options.type));
  const std::vector<Answer> answers =
      read_answers_file(options.answers_path, input.queries.size(), options.queries_path);

  CcdOptions ccd_options;
  ccd_options.t_max = options.t_max;
  ccd_options.toi_width = 0.0;  // the tightest doubles around t*, which the toi test needs
  GradeFindings findings;
  findings.queries = input.queries.size();
  Progress progress;
  for (std::size_t i = 0; i < input.queries.size(); ++i) {
    const Answer& answer = answers[i];
    const CcdResult exact = exact_ccd(input.queries[i].query, ccd_options);
    findings.tois_given += answer.toi.has_value();
    if (answer.collides && !exact.collides) findings.false_positives.push_back(i);
    if (!answer.collides && exact.collides) findings.false_negatives.push_back(i);
    // A double toi exceeds t* iff toi > toi_lo: either toi_lo == toi_hi == t*, or t* lies
    // strictly between the consecutive doubles toi_lo < toi_hi, so no double is in between.
    if (answer.collides && exact.collides && answer.toi && *answer.toi > exact.toi_lo)
      findings.non_conservative.push_back(i);
    progress.update(0, 1, input.path, i + 1, input.queries.size());
  }
  progress.clear();

  if (options.json)
    print_grade_json(std::cout, findings, options.t_max);
  else
    print_grade_text(std::cout, findings);
  return findings.all_good() ? kExitAgree : kExitDisagree;
}

}  // namespace exactccd::cli
