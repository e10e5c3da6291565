// A CcdResult in one line for test and fuzz failure messages, TOIs in hexadecimal (exact).
// Light on purpose: the fuzz harnesses include it without the tests' CGAL support.
#pragma once

#include <cstdio>
#include <string>

#include "exactccd/ccd.hpp"

namespace exactccd::test {

inline std::string describe_result(const CcdResult& r) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "collides %d [%a, %a] by %s", r.collides ? 1 : 0, r.toi_lo,
                r.toi_hi, to_string(r.decided_by));
  return buffer;
}

}  // namespace exactccd::test
