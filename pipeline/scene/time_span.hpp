// Culling by time, not only by space: a linearly moving primitive's box at time t lies in the
// blend (1 - t) B0 + t B1 of its boxes at t = 0 and t = 1, so two primitives can meet only at
// times where their blended boxes overlap. Per axis each of the two overlap conditions is linear
// in t; the times where all six hold form one interval, of which overlap_span returns a superset.
// The same holds for hierarchy nodes whose boxes at 0 and at 1 are the unions of their
// primitives'. PROOF: proofs/scene.md#time-span
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/predicates/double_bits.hpp"
#include "pipeline/scene/bvh.hpp"

namespace exactccd::scene {

/// A primitive's (or a node's) boxes at t = 0 and t = 1 (upper corners raised by the minimum
/// separation, as the swept boxes).
struct MotionBox {
  Box at0, at1;
};

inline MotionBox merge(const MotionBox& a, const MotionBox& b) {
  return {merge(a.at0, b.at0), merge(a.at1, b.at1)};
}

/// A set of times [lo, hi] within [0, 1]; empty when lo > hi.
struct TimeSpan {
  double lo = 0.0, hi = 1.0;
  bool empty() const { return lo > hi; }
};

namespace detail {

/// How far the computed root of a condition is moved outwards, in units in the last place: its
/// relative error is below 2^-49 in any rounding mode (four correctly rounded operations), and
/// 64 ulps of r are at least 2^-47 r. PROOF: proofs/scene.md#time-span
constexpr std::uint64_t kSpanSlackUlps = 64;

/// A double at most r (r in [0, 1], -0 read as 0) by kSpanSlackUlps of r, or 0.
inline double below(double r) {
  const std::uint64_t b = predicates::order_bits(r);
  return b > kSpanSlackUlps ? predicates::double_of(b - kSpanSlackUlps) : 0.0;
}
/// A double at least r (r in [0, 1], -0 read as 0) by kSpanSlackUlps of r.
inline double above(double r) {
  return predicates::double_of(predicates::order_bits(r) + kSpanSlackUlps);
}

/// Narrows `s` to (a superset of) the times where g(t) = (1 - t) g0 + t g1 <= 0, given the
/// computed g0 = fl(x0 - y0) and g1 = fl(x1 - y1): differences of doubles, whose signs are exact
/// in any rounding mode (no flush to zero).
inline void keep_nonpositive(double g0, double g1, TimeSpan& s) {
  if (g0 <= 0 && g1 <= 0) return;  // everywhere
  if (g0 > 0 && g1 > 0) {          // nowhere
    s.lo = 1.0;
    s.hi = 0.0;
    return;
  }
  // An infinite difference (overflow) bounds nothing: g0 = -1e308 with g1 = +inf (truly 2e308)
  // would give r = 0 for a root at 1/3. Finite ones give the root within 2^-50 relative. Here
  // g0 and g1 have opposite signs (or one is 0), so d is infinite whenever one of them is.
  const double d = g0 - g1;
  if (!std::isfinite(d)) return;
  const double r = g0 / d;  // the root of the line, one sign change in [0, 1]
  if (!(r >= 0.0 && r <= 1.0)) return;
  if (g0 > 0)
    s.lo = std::max(s.lo, below(r));  // g <= 0 on [r, 1]
  else
    s.hi = std::min(s.hi, above(r));  // g <= 0 on [0, r]
}

}  // namespace detail

/// A superset of the times t in [0, 1] at which the blended boxes of a and b overlap (touching
/// counts). Any rounding mode; no flush to zero (the traversal's guard).
inline TimeSpan overlap_span(const MotionBox& a, const MotionBox& b) {
  TimeSpan s;
  for (int k = 0; k < 3 && !s.empty(); ++k) {
    detail::keep_nonpositive(a.at0.lo[k] - b.at0.hi[k], a.at1.lo[k] - b.at1.hi[k], s);
    detail::keep_nonpositive(b.at0.lo[k] - a.at0.hi[k], b.at1.lo[k] - a.at1.hi[k], s);
  }
  return s;
}

/// Whether a and b may meet at some t in [0, t_end] (t_end in [0, 1]).
inline bool may_meet_by(const MotionBox& a, const MotionBox& b, double t_end) {
  const TimeSpan s = overlap_span(a, b);
  return !s.empty() && s.lo <= t_end;
}

}  // namespace exactccd::scene
