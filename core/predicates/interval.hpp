// Interval arithmetic with directed rounding (CGAL::Interval_nt) and certified signs.
//
// Interval_nt<false> assumes the rounding mode is "towards +infinity" and gradual underflow;
// every filter entry point holds a RoundingGuard, which sets that environment and restores the
// caller's on every return (thread-safe: the state is per thread).
// PROOF: proofs/filters.md#interval-enclosure, proofs/filters.md#fp-environment
#pragma once

#include <CGAL/Interval_nt.h>

#include <cstdint>

#include "core/predicates/fp_environment.hpp"

namespace exactccd::predicates {

using Interval = CGAL::Interval_nt<false>;

/// Upward rounding, no flush-to-zero, no denormals-are-zero, exceptions masked.
class RoundingGuard : predicates::FpEnvironmentGuard {
 public:
  RoundingGuard() noexcept : FpEnvironmentGuard(predicates::Rounding::upward) {}
};

/// A sign decided with certainty, or `uncertain`, which is never the same as `zero`.
enum class CertifiedSign : std::int8_t { negative = -1, zero = 0, positive = 1, uncertain = 2 };

EXACTCCD_CERTIFIED CertifiedSign certified_sign(const Interval& x) {
  if (x.inf() > 0) return CertifiedSign::positive;
  if (x.sup() < 0) return CertifiedSign::negative;
  if (x.inf() == 0 && x.sup() == 0) return CertifiedSign::zero;
  return CertifiedSign::uncertain;
}

/// True when x is certainly non-zero with the sign s (s = +1 or -1).
EXACTCCD_CERTIFIED bool certainly_has_sign(const Interval& x, int s) {
  return s > 0 ? x.inf() > 0 : x.sup() < 0;
}

/// +1 / -1 when x is certainly positive / negative, 0 when not certainly non-zero.
EXACTCCD_CERTIFIED int certain_strict_sign(const Interval& x) {
  return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0);
}

}  // namespace exactccd::predicates
