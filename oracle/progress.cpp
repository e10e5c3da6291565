#include "oracle/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace exactccd::oracle {

Progress::Progress() : enabled_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { clear(); }

void Progress::update(std::size_t file_index, std::size_t file_count, const std::string& name,
                      std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && done != total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  shown_ = true;
  // \x1b[K erases the rest of a longer previous line.
  std::fprintf(stderr, "\r[file %zu/%zu] %s: %zu/%zu queries\x1b[K", file_index + 1, file_count,
               name.c_str(), done, total);
  std::fflush(stderr);
}

void Progress::clear() {
  if (!enabled_ || !shown_) return;
  std::fputs("\r\x1b[K", stderr);
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace exactccd::oracle
