// Progress on stderr, only when stderr is a terminal (never in pipes, files or CI logs).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace exactccd::oracle {

class Progress {
 public:
  Progress();   ///< enabled iff isatty(2)
  ~Progress();  ///< clears the progress line

  /// Shows "[file k/n] name: done/total queries", at most a few times a second.
  void update(std::size_t file_index, std::size_t file_count, const std::string& name,
              std::size_t done, std::size_t total);
  void clear();

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace exactccd::oracle
