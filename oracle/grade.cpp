#include "oracle/grade.hpp"

#include <algorithm>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/query_file.hpp"
#include "oracle/answers_file.hpp"
#include "oracle/check.hpp"
#include "oracle/common.hpp"
#include "oracle/names.hpp"

namespace exactccd::oracle {

// `exact` is exact_ccd(query) with toi_width 0 and a contact, so lo = toi_lo <= t* <= hi =
// toi_hi with lo == hi == t* when t* is a double, and otherwise consecutive doubles lo < t* < hi.
bool later_than_first_contact(const mpq_class& toi, const RationalQuery& query,
                              const CcdResult& exact, double min_separation) {
  if (toi <= mpq_class(exact.toi_lo)) return false;  // toi <= lo <= t*
  if (exact.toi_lo == exact.toi_hi || toi >= mpq_class(exact.toi_hi)) return true;
  // lo < toi < hi, and t* also lies in (lo, hi): decide exactly on the motion over [0, toi],
  // rescaled to [0, 1]. Each end position x1 becomes x0 + toi (x1 - x0), so the new query is at
  // time s where the original is at t = toi s: it has a contact iff t* <= toi, and its first
  // contact is s* = t* / toi. Its tightest enclosure has lower end 1 (a double) iff s* = 1, that
  // is iff t* = toi; else lower end < 1 and t* < toi.
  RationalQuery over_toi = query;
  for (int k = 0; k < 4; ++k) {
    const RationalPoint& x0 = query.points[k];
    const RationalPoint& x1 = query.points[k + 4];
    RationalPoint& end = over_toi.points[k + 4];
    end.x = x0.x + toi * (x1.x - x0.x);
    end.y = x0.y + toi * (x1.y - x0.y);
    end.z = x0.z + toi * (x1.z - x0.z);
  }
  // Reparametrising time changes no distance: the same holds for the first time within delta.
  const CcdResult restricted = exact_ccd(over_toi, mpq_class(min_separation));  // t_max 1
  return restricted.collides && restricted.toi_lo < 1.0;
}

GradeFindings grade_file(const std::string& queries_path, const std::string& answers_path,
                         std::optional<QueryType> type, double t_max,
                         const GradeProgress& progress, double min_separation,
                         std::optional<PrimitiveKind> primitive) {
  // Before the type: a folder given as the queries is named as such, not as an untyped file.
  require_regular_file(queries_path, "a CSV file (--queries takes one file)");
  const QueryFile input =
      primitive ? as_edge_edge_file(read_primitive_query_file(queries_path, *primitive))
                : read_query_file(queries_path, resolve_query_type(queries_path, type));
  require_some_queries(input.queries.empty() ? std::vector<std::string>{input.path}
                                             : std::vector<std::string>{},
                       1, input.queries.size());
  const std::vector<Answer> answers =
      read_answers_file(answers_path, input.queries.size(), queries_path, t_max);

  return grade_answers(input, answers, t_max, 0, input.queries.size(), progress, min_separation);
}

GradeFindings grade_answers(const QueryFile& input, const std::vector<Answer>& answers,
                            double t_max, std::size_t begin, std::size_t end,
                            const GradeProgress& progress, double min_separation) {
  CcdOptions ccd_options;
  ccd_options.t_max = t_max;
  ccd_options.min_separation = min_separation;
  ccd_options.toi_width = 0.0;  // the tightest doubles around t*, which the toi test needs
  GradeFindings findings;
  const std::size_t stop = std::min({end, input.queries.size(), answers.size()});
  for (std::size_t i = begin; i < stop; ++i) {
    const Answer& answer = answers[i];
    const RationalQuery& query = input.queries[i].query;
    const CcdResult exact = exact_ccd(query, ccd_options);
    ++findings.queries;
    findings.tois_given += answer.toi.has_value();
    if (answer.collides && !exact.collides) findings.false_positives.push_back(i);
    if (!answer.collides && exact.collides) findings.false_negatives.push_back(i);
    if (answer.collides && exact.collides && answer.toi &&
        later_than_first_contact(*answer.toi, query, exact, min_separation))
      findings.non_conservative.push_back(i);
    if (progress) progress(i + 1, input.queries.size());
  }
  return findings;
}

}  // namespace exactccd::oracle
