// The check of CcdOptions that the library's entry points make (ccd.cpp and the scene).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "exactccd/types.hpp"

namespace exactccd {

/// Throws std::invalid_argument unless t_max lies in (0, 1] and toi_width and min_separation
/// are finite and >= 0.
inline void check_ccd_options(const CcdOptions& o) {
  if (!(o.t_max > 0.0 && o.t_max <= 1.0))
    throw std::invalid_argument("exactccd: t_max must lie in (0, 1], got " +
                                std::to_string(o.t_max));
  if (!(o.toi_width >= 0.0) || !std::isfinite(o.toi_width))
    throw std::invalid_argument("exactccd: toi_width must be finite and >= 0");
  if (!(o.min_separation >= 0.0) || !std::isfinite(o.min_separation))
    throw std::invalid_argument("exactccd: min_separation must be finite and >= 0");
}

}  // namespace exactccd
