#include "oracle/grade.hpp"

#include <algorithm>

#include "exact/arithmetic/rational.hpp"
#include "exact/reference/point_plane.hpp"
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

namespace {

/// A point-plane file graded against point_plane_ccd's exact path (its coordinates must be
/// doubles, as check requires); a reported TOI is late when the exact first contact is strictly
/// before it (point_plane_contact_before).
GradeFindings grade_point_plane_file(const std::string& queries_path,
                                     const std::string& answers_path, double t_max,
                                     const GradeProgress& progress, double min_separation) {
  const PrimitiveQueryFile file =
      read_primitive_query_file(queries_path, PrimitiveKind::point_plane);
  require_some_queries(file.queries.empty() ? std::vector<std::string>{file.path}
                                            : std::vector<std::string>{},
                       1, file.queries.size());
  const std::vector<Answer> answers =
      read_answers_file(answers_path, file.queries.size(), queries_path, t_max);
  CcdOptions exact;
  exact.mode = Mode::exact;
  exact.t_max = t_max;
  exact.min_separation = min_separation;
  GradeFindings findings;
  for (std::size_t i = 0; i < file.queries.size() && i < answers.size(); ++i) {
    const PrimitiveQueryRecord& r = file.queries[i];
    exact::PointPlanePoints x;
    for (std::size_t k = 0; k < 6; ++k) {
      const RationalPoint& p = r.points[k];
      if (!exact::to_double_exactly(p.x, &x[k].x()) || !exact::to_double_exactly(p.y, &x[k].y()) ||
          !exact::to_double_exactly(p.z, &x[k].z()))
        throw InputError(file.path, r.first_line + k,
                         "a coordinate is not exactly a double: point-plane queries are "
                         "decided on doubles only");
    }
    CcdResult truth;
    try {
      truth = point_plane_ccd({x[0], x[1], x[2], x[3], x[4], x[5]}, exact);
    } catch (const std::invalid_argument& e) {  // a zero normal: the file's fault, at its line
      throw InputError(file.path, r.first_line, e.what());
    }
    const Answer& answer = answers[i];
    ++findings.queries;
    findings.tois_given += answer.toi.has_value();
    if (answer.collides && !truth.collides) findings.false_positives.push_back(i);
    if (!answer.collides && truth.collides) findings.false_negatives.push_back(i);
    if (answer.collides && truth.collides && answer.toi) {
      const mpq_class& toi = *answer.toi;
      const bool late = toi > mpq_class(truth.toi_lo) &&
                        (truth.toi_lo == truth.toi_hi || toi >= mpq_class(truth.toi_hi) ||
                         exact::point_plane_contact_before(x, toi, min_separation));
      if (late) findings.non_conservative.push_back(i);
    }
    if (progress) progress(i + 1, file.queries.size());
  }
  return findings;
}

}  // namespace

GradeFindings grade_file(const std::string& queries_path, const std::string& answers_path,
                         std::optional<QueryType> type, double t_max,
                         const GradeProgress& progress, double min_separation,
                         std::optional<PrimitiveKind> primitive) {
  // Before the type: a folder given as the queries is named as such, not as an untyped file.
  require_regular_file(queries_path, "a CSV file (--queries takes one file)");
  if (primitive == PrimitiveKind::point_plane)
    return grade_point_plane_file(queries_path, answers_path, t_max, progress, min_separation);
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
