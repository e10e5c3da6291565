// The one trim of the file readers (benchmark CSV files, answers files).
#pragma once

#include <string_view>

namespace exactccd {

/// `s` without leading spaces and tabs, and without trailing spaces, tabs and carriage returns
/// (a CRLF line end's '\r').
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

}  // namespace exactccd
