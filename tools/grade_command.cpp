#include "grade_command.hpp"

#include <iostream>

#include "oracle/common.hpp"
#include "oracle/grade.hpp"
#include "oracle/progress.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

int run_grade(const GradeOptions& options) {
  validate_t_max(options.t_max);
  validate_min_separation(options.min_separation);
  Progress progress;
  const GradeFindings findings = grade_file(
      options.queries_path, options.answers_path, options.type, options.t_max,
      [&](std::size_t done, std::size_t count) {
        progress.update(0, 1, options.queries_path, done, count);
      },
      options.min_separation, options.primitive);
  progress.clear();

  if (options.json)
    print_grade_json(std::cout, findings, options.t_max, options.min_separation);
  else
    print_grade_text(std::cout, findings);
  return findings.all_good() ? kExitAgree : kExitDisagree;
}

}  // namespace exactccd::cli
