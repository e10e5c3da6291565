// The findings of `exactccd grade` and their text / JSON forms.
#pragma once

#include <cstddef>
#include <ostream>
#include <vector>

namespace exactccd::oracle {

/// Offending 0-based query indices, per category, in query order.
struct GradeFindings {
  std::size_t queries = 0;
  std::size_t tois_given = 0;                 ///< `1,toi` lines
  std::vector<std::size_t> false_positives;   ///< answer 1, exact 0
  std::vector<std::size_t> false_negatives;   ///< answer 0, exact 1
  std::vector<std::size_t> non_conservative;  ///< answer 1 with toi > t*, exact 1

  bool all_good() const {
    return false_positives.empty() && false_negatives.empty() && non_conservative.empty();
  }
};

/// At most this many indices are printed per category (the counts are always complete).
inline constexpr std::size_t kMaxListedIndices = 20;

void print_grade_text(std::ostream& out, const GradeFindings& findings);
void print_grade_json(std::ostream& out, const GradeFindings& findings, double t_max,
                      double min_separation = 0.0);

}  // namespace exactccd::oracle
