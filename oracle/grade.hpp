// What `exactccd grade` computes: another CCD code's answers to one benchmark CSV file judged
// against the exact decision. The findings and their text / JSON forms are in grade_report.hpp
// (included); the answers file's format in answers_file.hpp.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "exactccd/types.hpp"
#include "oracle/grade_report.hpp"

namespace exactccd::oracle {

/// Called after each graded query: the number done so far and the file's query count.
using GradeProgress = std::function<void(std::size_t done, std::size_t count)>;

/// Grades the answers file `answers_path` against the queries of `queries_path` (their type
/// `type` when given, else from the folder name) over [0, t_max]: false positives, false
/// negatives, and TOIs later than the exact first contact time. Throws InputError for a
/// queries path that is not a regular file, an unreadable or malformed file, a file without
/// queries, an unknown type, or an answers file that does not match (answers_file.hpp).
/// `first` and `last` restrict the grading to the queries [first, last) (clipped to the file's
/// count; findings keep whole-file indices): a shard for a distributed run (exactccd.dask).
GradeFindings grade_file(const std::string& queries_path, const std::string& answers_path,
                         std::optional<QueryType> type, double t_max,
                         const GradeProgress& progress = {}, std::size_t first = 0,
                         std::size_t last = static_cast<std::size_t>(-1));

}  // namespace exactccd::oracle
