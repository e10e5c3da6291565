#include "study/labels.hpp"

#include <cstdio>
#include <cstdlib>

namespace exactccd::study {

std::string short_number(double x) {
  char buffer[32];
  for (int n = -30; n <= 30; ++n) {
    if (n == 0) continue;
    std::snprintf(buffer, sizeof buffer, "1e%d", n);
    if (std::strtod(buffer, nullptr) == x) return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

}  // namespace exactccd::study
