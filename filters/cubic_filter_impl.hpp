// Implementation of filters/cubic_filter.hpp (a template over the inclusion policy).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "core/predicates/double_bits.hpp"
#include "filters/earliest_root_search.hpp"
#include "filters/polynomial_bernstein.hpp"

namespace exactccd::filters {

namespace detail {

constexpr int kMaxSubdivisionDepth = 10;

using predicates::double_of;
using predicates::order_bits;

/// Where a double lies relative to the only root r of a bracket, by the certified sign of the
/// cubic's enclosure there (the sign at the bracket's upper end is `sign_hi`).
EXACTCCD_CERTIFIED Side side_of_root(const Interval& value, int sign_hi) {
  const CertifiedSign s = certified_sign(value);
  if (s == CertifiedSign::uncertain) return Side::unknown;
  if (s == CertifiedSign::zero) return Side::at;
  return static_cast<int>(s) == sign_hi ? Side::above : Side::below;
}

EXACTCCD_CERTIFIED Side side_of_root(const predicates::FixedPoly<Interval, 3>& cubic, double t,
                                     int sign_hi) {
  return side_of_root(predicates::evaluate(cubic, Interval(t)), sign_hi);
}

/// A bracket [lo, hi] of the only root r of the cubic being narrowed: lo < r < hi (or
/// lo == hi == r) with certain signs at both ends, as Theorem 2 requires.
struct RootBracket {
  double lo, hi;
  FilterOutcome outcome(bool final) const {
    FilterOutcome out;
    out.verdict = FilterOutcome::Verdict::contact;
    out.toi_lo = lo;
    out.toi_hi = hi;
    out.toi_final = final;
    return out;
  }
};

/// Certified bisection of a bracket [lo, hi] (0 <= lo < hi) of the only root of the cubic,
/// whose signs at lo and hi are certainly -s_hi and s_hi. Splits at the middle double in bit
/// order, so that at most 64 steps reach the tightest pair; with toi_width > 0 it stops once
/// hi - lo <= toi_width. An uncertain sign stops it with toi_final = false at a state of that
/// loop, which the exact bisection then continues.
EXACTCCD_CERTIFIED
FilterOutcome bisect_bracket(const predicates::FixedPoly<Interval, 3>& cubic, double lo,
                             double hi, int sign_hi, double toi_width) {
  RootBracket b{lo, hi};
  for (;;) {
    double mid;
    if (!predicates::middle_double(b.lo, b.hi, &mid) ||
        (toi_width > 0 && certainly_within_width(b.lo, b.hi, toi_width)))
      return b.outcome(true);
    switch (side_of_root(cubic, mid, sign_hi)) {
      case Side::unknown: return b.outcome(false);
      case Side::at: return RootBracket{mid, mid}.outcome(true);
      case Side::below: b.lo = mid; break;
      case Side::above: b.hi = mid; break;
    }
  }
}

/// The cubic with the midpoints of its interval coefficients: a guide for choosing where to
/// evaluate. Nothing is decided from it, whatever its rounding (it runs under upward
/// rounding) or accuracy.
struct CubicGuide {
  double c[4], w[4];  // midpoints and widths of the interval coefficients
  explicit CubicGuide(const predicates::FixedPoly<Interval, 3>& cubic) {
    for (int i = 0; i < 4; ++i) {
      c[i] = cubic.c[i].inf() / 2 + cubic.c[i].sup() / 2;
      w[i] = cubic.c[i].sup() - cubic.c[i].inf();
    }
  }
  double value(double t) const { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
  double slope(double t) const { return (3 * c[3] * t + 2 * c[2]) * t + c[1]; }
  /// About the width of the cubic's enclosure at t (t >= 0).
  double width(double t) const { return ((w[3] * t + w[2]) * t + w[1]) * t + w[0]; }

  /// A guess at the root in [lo, hi] (f(lo), f(hi) of signs -sign_hi, sign_hi): Halley's
  /// method from the secant's root (the cubic is close to linear over most brackets),
  /// safeguarded by bisection of the guide's own bracket.
  double root(double lo, double hi, int sign_hi) const {
    const double g_lo = value(lo), g_hi = value(hi);
    double a = lo, b = hi, t = lo + (hi - lo) * (g_lo / (g_lo - g_hi));
    if (!(t > lo && t < hi)) t = lo + (hi - lo) / 2;  // NaN included
    for (int i = 0; i < 48; ++i) {
      const double g = value(t);
      if (!(g != 0)) break;  // a root of the guide (or NaN)
      ((g > 0) == (sign_hi > 0) ? b : a) = t;
      // Halley's step (cubic convergence: one or two steps fewer than Newton's).
      const double d = slope(t), dd = 6 * c[3] * t + 2 * c[2];
      double next = t - (2 * g * d) / (2 * d * d - g * dd);
      if (!(next > a && next < b)) next = a + (b - a) / 2;  // outside the guide's bracket, NaN
      if (next == a || next == b) break;                    // no double left between
      // Within a few doubles, or well inside the band where enclosures contain zero: the
      // probes take it from there (rounding can make Newton alternate between neighbours).
      const double moved = std::fabs(next - t);
      const bool close = moved <= std::fabs(t) * 0x1p-50 || 8 * moved <= width(t) / std::fabs(d);
      t = next;
      if (close) break;
    }
    return t;
  }

  /// How many doubles above (up) or below the double t (of bit pattern x) the cubic's
  /// enclosure `value` at t suggests probing to find certain signs beyond the root: the Newton
  /// step to the root, if in that direction, plus the radius of the band around the root where
  /// enclosures as wide as this one contain zero; at least 1.
  std::uint64_t steps(double t, std::uint64_t x, const Interval& value, bool up) const {
    const double d = slope(t), spacing = double_of(up ? x + 1 : x - 1) - t;
    const double newton = -(value.inf() / 2 + value.sup() / 2) / d;
    const double reach = ((newton > 0) == up ? std::fabs(newton) : 0.0) +
                         (value.sup() - value.inf()) / std::fabs(d);
    const double n = reach / std::fabs(spacing);
    if (!(n >= 1)) return 1;  // NaN included
    return n < 0x1p60 ? static_cast<std::uint64_t>(n) + 1 : std::uint64_t{1} << 60;
  }
};

/// The tightest pair of doubles around the only root r of [lo, hi] (0 <= lo < hi; certain
/// signs -sign_hi at lo and sign_hi at hi), or [r, r] when r is a double, with certified
/// interval signs at probes chosen near r: a Newton guess, then, in each direction where r
/// may lie, probes at growing distances (first the guide's estimate of where signs become
/// certain beyond r, then doubling) until a certain sign on the far side of r; then bisection
/// in bit order. Where interval signs near r are uncertain, the certified bracket reached is
/// returned with toi_final = false: the tightest pair is unique, the exact bisection finds it
/// from any bracket. PROOF: proofs/filters.md#cubic-filter
EXACTCCD_CERTIFIED
FilterOutcome tighten_bracket(const predicates::FixedPoly<Interval, 3>& cubic, double lo,
                              double hi, int sign_hi) {
  RootBracket b{lo, hi};
  std::uint64_t below = order_bits(lo), above = order_bits(hi);  // below < r < above
  if (above - below < 2) return b.outcome(true);
  bool uncertain_seen = false;
  // Classifies the double of pattern x, below < x < above, and narrows the bracket.
  auto probe = [&](std::uint64_t x, Interval* value) {
    const double t = double_of(x);
    *value = predicates::evaluate(cubic, Interval(t));
    const Side side = side_of_root(*value, sign_hi);
    switch (side) {
      case Side::below: below = x, b.lo = t; break;
      case Side::above: above = x, b.hi = t; break;
      case Side::at: b.lo = b.hi = t; break;
      case Side::unknown: uncertain_seen = true; break;
    }
    return side;
  };
  // Doubling steps, capped below any span of patterns (< 2^63): never wraps to 0.
  auto grown = [](std::uint64_t step) { return step < (std::uint64_t{1} << 62) ? 2 * step : step; };
  const CubicGuide guide(cubic);
  const std::uint64_t guessed = order_bits(guide.root(lo, hi, sign_hi));
  const std::uint64_t guess = std::min(std::max(guessed, below + 1), above - 1);
  Interval at_guess;
  const Side first = probe(guess, &at_guess);
  if (first == Side::at) return b.outcome(true);
  const double t_guess = double_of(guess);
  Interval value;
  // Each walk stops after a few probes: past them the signs near r are too uncertain for the
  // intervals (e.g. all of [0, r] when f(0) is tiny), and the exact bisection takes over.
  constexpr int kWalkProbes = 6;
  if (first != Side::above) {  // r may lie above the guess: walk up
    std::uint64_t from = guess, step = guide.steps(t_guess, guess, at_guess, true);
    for (int n = 0; n < kWalkProbes && from + 1 < above; ++n, step = grown(step)) {
      const std::uint64_t x = step < above - from ? from + step : from + (above - from) / 2;
      const Side s = probe(x, &value);
      if (s == Side::at) return b.outcome(true);
      if (s == Side::above) break;
      from = x;
    }
  }
  if (first != Side::below) {  // r may lie below the guess: walk down
    std::uint64_t from = guess, step = guide.steps(t_guess, guess, at_guess, false);
    for (int n = 0; n < kWalkProbes && below + 1 < from; ++n, step = grown(step)) {
      const std::uint64_t x = step < from - below ? from - step : from - (from - below) / 2;
      const Side s = probe(x, &value);
      if (s == Side::at) return b.outcome(true);
      if (s == Side::below) break;
      from = x;
    }
  }
  // A bracket left wider than a pair: the steps overshot or stopped, or signs near r are
  // uncertain.
  for (int n = 0; above - below >= 2; ++n) {
    if (uncertain_seen || n == 64) return b.outcome(false);
    if (probe(below + (above - below) / 2, &value) == Side::at) return b.outcome(true);
  }
  return b.outcome(true);
}

/// Narrows a bracket [lo, hi] of the only root of the cubic (0 <= lo < hi, certain signs
/// -sign_hi and sign_hi at the ends) to the requested width: for toi_width = 0 the tightest
/// pair (unique), found near a Newton guess; for toi_width > 0 the bisection's result. When
/// interval signs cannot finish, toi_final = false with a bracket that the exact bisection
/// finishes to the same result: for toi_width > 0 a state of the bisection.
EXACTCCD_CERTIFIED
FilterOutcome refine_bracket(const predicates::FixedPoly<Interval, 3>& cubic, double lo,
                             double hi, int sign_hi, double toi_width) {
  if (toi_width > 0) return bisect_bracket(cubic, lo, hi, sign_hi, toi_width);
  return tighten_bracket(cubic, lo, hi, sign_hi);
}

}  // namespace detail

EXACTCCD_CERTIFIED bool coplanarity_cubic_root_free_interval(
    const predicates::FixedPoly<Interval, 3>& cubic, double t_max) {
  return strict_sign_of_all(bernstein_of(cubic, Interval(t_max))) != 0;
}

namespace detail {

/// Contact at a double t where the cubic is exactly zero (a coplanar instant): the interval
/// inclusion tests at the point t when they decide, else the exact test.
/// PROOF: proofs/filters.md#inclusion-over-an-interval
template <class Inclusion>
EXACTCCD_CERTIFIED bool contact_at_coplanar_double(const Inclusion& inclusion, double t,
                                                   ContactExactStage& exact) {
  const Interval at(t);
  if (inclusion.excluded(at)) return false;
  if (inclusion.certainly_included(at)) return true;
  return exact.contact_at(t);
}

}  // namespace detail

/// The coplanarity cubic's policy of the earliest-root search: inclusion over time intervals,
/// exact answers at doubles where the intervals cannot tell, the bracket refined by certified
/// bisection. PROOF: proofs/filters.md#cubic-filter
template <class Inclusion>
struct CubicRootPolicy {
  const predicates::FixedPoly<Interval, 3>& cubic;
  double toi_width;
  const Inclusion& inclusion;
  ContactExactStage& exact;
  bool tighter_cubic_available;

  /// A node with a single root certified by its interval signs alone is tested in the leading
  /// projection only: the root's own narrow bracket is tested in all of them (a subset of T).
  bool excluded_first(const Interval& T, bool single_root) const {
    return single_root ? inclusion.excluded_in_leading_projection(T) : inclusion.excluded(T);
  }
  bool excluded_last(const Interval& T, bool single_root) const {
    return single_root && inclusion.excluded(T);  // tested in one projection first
  }
  /// No coefficient of certain sign below the top levels: hopeless at any depth, so the
  /// caller's tighter cubic next.
  bool hopeless(const Bernstein<Interval, 3>& b, int depth, int sign_start, int sign_end) const {
    return tighter_cubic_available && depth >= 2 && sign_start == 0 && sign_end == 0 &&
           certain_strict_sign(b[1]) == 0 && certain_strict_sign(b[2]) == 0;
  }
  int end_sign(const Interval& enclosure, double t, FilterOutcome& out) {
    const int s = certain_strict_sign(enclosure);
    if (s != 0) return s;
    out.exact_used = true;
    return exact.cubic_sign_at(t);
  }
  RootDecision at_double(double t, FilterOutcome& out) {
    if (!detail::contact_at_coplanar_double(inclusion, t, exact)) return RootDecision::no_contact;
    out.verdict = FilterOutcome::Verdict::contact;
    out.toi_lo = out.toi_hi = t;
    out.toi_final = true;
    return RootDecision::contact;
  }
  RootDecision single_root(double lo, double hi, int s_hi, const Interval& T, FilterOutcome& out) {
    const bool used = out.exact_used;
    // With toi_width > 0 the answer is the bisection of T's bracket when inclusion holds on
    // T. With width 0 it is the tightest pair, which narrowing finds anyway: the test on T is
    // skipped, as inclusion on T implies it on any R inside T (isotone enclosures).
    if (toi_width > 0 && inclusion.certainly_included(T)) {
      out = detail::refine_bracket(cubic, lo, hi, s_hi, toi_width);
      out.exact_used = used;
      return RootDecision::contact;
    }
    // Narrow the bracket around r, decide inclusion there (inclusion first: it is usually
    // decided in the leading projection; both cannot hold, r being a coplanar instant of R),
    // else decide exactly.
    const FilterOutcome narrow = detail::refine_bracket(cubic, lo, hi, s_hi, 0.0);
    const Interval R(narrow.toi_lo, narrow.toi_hi);
    const bool included = inclusion.certainly_included(R);
    if (!included && inclusion.excluded(R)) return RootDecision::no_contact;
    if (included) {
      out = toi_width > 0
                ? detail::refine_bracket(cubic, narrow.toi_lo, narrow.toi_hi, s_hi, toi_width)
                : narrow;  // the tightest pair, or a bracket the exact path tightens
      out.exact_used = used;
      return RootDecision::contact;
    }
    out.exact_used = true;
    double r_lo = narrow.toi_lo, r_hi = narrow.toi_hi;
    if (r_lo != r_hi) std::tie(r_lo, r_hi) = exact.bisect_root(r_lo, r_hi);
    if (r_lo != r_hi) return RootDecision::undecided;  // r is not a double
    return at_double(r_lo, out);  // the node's only coplanar instant
  }
};

template <class Inclusion>
EXACTCCD_CERTIFIED
FilterOutcome cubic_filter(const predicates::FixedPoly<Interval, 3>& cubic, double t_max,
                           double toi_width, const Inclusion& inclusion, ContactExactStage& exact,
                           bool tighter_cubic_available) {
  CubicRootPolicy<Inclusion> policy{cubic, toi_width, inclusion, exact, tighter_cubic_available};
  return earliest_root_search<3, detail::kMaxSubdivisionDepth>(cubic, t_max, policy);
}

}  // namespace exactccd::filters
