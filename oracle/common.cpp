#include <cmath>
#include "oracle/common.hpp"

#include <cstdio>
#include <iostream>

#include "exactccd/query_file.hpp"

namespace exactccd::oracle {

void warn(const std::string& message) {
  std::cerr << "exactccd: warning: " << printable(message) << '\n';  // \n escaped: one line
}

void require_some_queries(const std::vector<std::string>& empty_files, std::size_t file_count,
                          std::size_t queries) {
  constexpr const char* kEmpty = "no queries (an empty file, or only blank lines)";
  if (queries == 0 && file_count == 1 && empty_files.size() == 1)
    throw InputError(empty_files.front(), 0, kEmpty);
  if (queries == 0)
    throw UsageError("no queries in any of the " + std::to_string(file_count) +
                     " files (each empty, or only blank lines)");
  for (const std::string& file : empty_files) warn(file + ": " + kEmpty);
}

void validate_t_max(double t_max) {
  if (!(t_max > 0.0 && t_max <= 1.0))
    throw UsageError("--t-max must lie in (0, 1], got " + format_double(t_max));
}

void validate_min_separation(double delta) {
  if (!(delta >= 0.0) || !std::isfinite(delta))
    throw UsageError("--min-separation must be finite and >= 0, got " + format_double(delta));
}

std::string format_double(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace exactccd::oracle
