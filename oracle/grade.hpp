// What `exactccd grade` computes: another CCD code's answers to one benchmark CSV file judged
// against the exact decision. The findings and their text / JSON forms are in grade_report.hpp,
// the answers file's format and reader in answers_file.hpp (both included).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"
#include "oracle/answers_file.hpp"
#include "oracle/grade_report.hpp"

namespace exactccd::oracle {

/// Called after each graded query: the number done so far and the file's query count.
using GradeProgress = std::function<void(std::size_t done, std::size_t count)>;

/// Grades the answers file `answers_path` against the queries of `queries_path` (their type
/// `type` when given, else from the folder name) over [0, t_max]: false positives, false
/// negatives, and TOIs later than the exact first contact time. Throws InputError for a
/// queries path that is not a regular file, an unreadable or malformed file, a file without
/// queries, an unknown type, or an answers file that does not match (answers_file.hpp).
/// `primitive`: a file of a point kind (pe, pe2d, pp, pp2d), graded as the edge-edge queries
/// its queries are (check.hpp, as_edge_edge_file).
GradeFindings grade_file(const std::string& queries_path, const std::string& answers_path,
                         std::optional<QueryType> type, double t_max,
                         const GradeProgress& progress = {}, double min_separation = 0.0,
                         std::optional<PrimitiveKind> primitive = std::nullopt);

/// The same on answers [begin, end) of files already read (`end` clipped to the query count;
/// indices are the file's): one shard of it, e.g. a task of a distributed grade. `answers` as
/// read_answers_file gives them for `input` over [0, t_max].
GradeFindings grade_answers(const QueryFile& input, const std::vector<Answer>& answers,
                            double t_max, std::size_t begin, std::size_t end,
                            const GradeProgress& progress = {}, double min_separation = 0.0);

/// Whether a reported `toi` (an exact rational in [0, t_max]) is later than the exact first
/// contact time t* of `query`, exactly; `exact` is exact_ccd(query) with toi_width 0, a contact.
/// With min_separation delta > 0, t* is the first time within delta.
bool later_than_first_contact(const mpq_class& toi, const RationalQuery& query,
                              const CcdResult& exact, double min_separation = 0.0);

}  // namespace exactccd::oracle
