// The check of CcdOptions that the library's entry points make (ccd.cpp and the scene).
#pragma once

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "exactccd/types.hpp"

namespace exactccd {

/// x as the shortest decimal that reads back as x (1e+308, -1e-300: not std::to_string's 309
/// digits or "-0.000000").
inline std::string shortest_decimal(double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  return std::string(text, end);
}

/// The message for an option outside its domain, built out of line (the checks sit on every
/// query's path).
[[noreturn, gnu::noinline, gnu::cold]] inline void throw_bad_option(const char* what,
                                                                     double value) {
  throw std::invalid_argument(std::string("exactccd: ") + what + ", got " +
                              shortest_decimal(value));
}

/// Throws std::invalid_argument unless t_max lies in [0, 1] (0: the state at t = 0 alone,
/// held_at_start.hpp) and toi_width and min_separation are finite and >= 0; the message names
/// the value given.
inline void check_ccd_options(const CcdOptions& o) {
  if (!(o.t_max >= 0.0 && o.t_max <= 1.0)) throw_bad_option("t_max must lie in [0, 1]", o.t_max);
  if (!(o.toi_width >= 0.0) || !std::isfinite(o.toi_width))
    throw_bad_option("toi_width must be finite and >= 0", o.toi_width);
  if (!(o.min_separation >= 0.0) || !std::isfinite(o.min_separation))
    throw_bad_option("min_separation must be finite and >= 0", o.min_separation);
}

}  // namespace exactccd
