// The answers file that `exactccd grade` judges: one line per query, in order, `0`, `1` or
// `1,toi` (toi a decimal double, the graded code's reported time of impact).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace exactccd::cli {

struct Answer {
  bool collides = false;
  std::optional<double> toi;  ///< only on a `1` line, when given
  std::size_t line = 0;       ///< 1-based
};

/// Reads `path`, expecting exactly `query_count` answers (the number of queries in
/// `queries_path`, named in the message when the counts differ). Throws InputError
/// ("path:line: what") for a malformed line, a toi that is not a finite decimal number, a toi
/// on a `0` line, or too few / too many lines.
std::vector<Answer> read_answers_file(const std::string& path, std::size_t query_count,
                                      const std::string& queries_path);

}  // namespace exactccd::cli
