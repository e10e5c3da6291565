// Interval arithmetic with directed rounding (CGAL::Interval_nt) and certified signs.
//
// Interval_nt<false> assumes the rounding mode is "towards +infinity"; every filter entry
// point holds a RoundingGuard, which sets it and restores the caller's mode on every return
// (thread-safe: the mode is per thread). PROOF: proofs/filters.md#interval-enclosure
#pragma once

#include <CGAL/Interval_nt.h>

#include <cstdint>

namespace exactccd::filters {

using Interval = CGAL::Interval_nt<false>;
using RoundingGuard = CGAL::Protect_FPU_rounding<true>;

/// A sign decided with certainty, or `uncertain`, which is never the same as `zero`.
enum class CertifiedSign : std::int8_t { negative = -1, zero = 0, positive = 1, uncertain = 2 };

inline CertifiedSign certified_sign(const Interval& x) {
  if (x.inf() > 0) return CertifiedSign::positive;
  if (x.sup() < 0) return CertifiedSign::negative;
  if (x.inf() == 0 && x.sup() == 0) return CertifiedSign::zero;
  return CertifiedSign::uncertain;
}

/// True when x is certainly non-zero with the sign s (s = +1 or -1).
inline bool certainly_has_sign(const Interval& x, int s) {
  return s > 0 ? x.inf() > 0 : x.sup() < 0;
}

/// +1 / -1 when x is certainly positive / negative, 0 when not certainly non-zero.
inline int certain_strict_sign(const Interval& x) {
  return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0);
}

}  // namespace exactccd::filters
