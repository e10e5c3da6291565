#include "exact/polynomials/guided_bisection.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/fp_environment.hpp"
#include "exact/arithmetic/rational.hpp"

namespace exactccd::exact {

// Root bracketing with guided probes. PROOF: proofs/filters.md#guided-bisection
//
// The result is defined by the reference loop (bit-order bisection of [lo, hi] with the exact
// sign at every middle double; see reference_bisection below). Under the contract (f(lo) and
// f(hi) non-zero of opposite signs, exactly one root r in [lo, hi]) the sign of f at any
// t in [lo, hi] is sign_lo for t < r, 0 at r and -sign_lo for t > r, so the loop's path is a
// function of where r lies. guided_bisection replays that path (for width 0 it returns the unique
// tightest pair as soon as the signs pin it) and asks for a sign only where the exact signs
// gathered so far do not already tell on which side of r the middle double lies; it gathers
// them first at points chosen by Newton's method (on exact values of f), which usually pin r
// between two consecutive doubles in two exact evaluations instead of the loop's 30 to 60.

namespace {

/// The doubles next to a finite x, by its bit pattern (std::nextafter without the library
/// call): for x > 0 the neighbours have patterns one apart, for x < 0 likewise with the order
/// reversed, and both zeros step to the smallest subnormals.
double next_up(double x) {
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  const std::uint64_t b = predicates::bits_of(x);
  return predicates::double_of(x > 0 ? b + 1 : b - 1);
}
double next_down(double x) {
  if (x == 0) return -std::numeric_limits<double>::denorm_min();
  const std::uint64_t b = predicates::bits_of(x);
  return predicates::double_of(x > 0 ? b - 1 : b + 1);
}

/// hi - lo <= width exactly (0 <= lo <= hi finite, width > 0 finite): difference_at_most
/// without its rationals unless the rounded difference equals width. Rounding, in any IEEE
/// mode, is monotone and leaves a double unchanged, so hi - lo <= width gives
/// fl(hi - lo) <= width and hi - lo >= width gives fl(hi - lo) >= width; the difference
/// cannot overflow (0 <= hi - lo <= hi).
bool width_at_most(double hi, double lo, double width) {
  const double rounded = hi - lo;
  if (rounded != width) return rounded < width;
  return difference_at_most(hi, lo, width);
}

/// next_up(x) has pattern order_bits(x) + 1 and, for x > 0, next_down(x) order_bits(x) - 1.
using predicates::order_bits;

double from_order_bits(std::uint64_t bits) { return predicates::double_of(bits); }

/// One step of the reference loop on [lo, hi] (lo, hi >= 0 finite): false when it stops
/// there (no double strictly inside, or width > 0 met), else true with *mid the middle
/// double of those strictly inside, in bit order (the loop's probe). The doubles strictly
/// inside have the patterns order_bits(lo) + 1 ... order_bits(hi) - 1.
bool middle_double(double lo, double hi, double width, double* mid) {
  return predicates::middle_double(lo, hi, mid) && !(width > 0 && width_at_most(hi, lo, width));
}

using Real = GuideReal;

/// The reference loop: bit-order bisection with an exact sign at every middle double.
std::pair<double, double> reference_bisection(const CubicAtDoubles& f, double lo, double hi,
                                              double width, int sign_lo) {
  double mid;
  while (middle_double(lo, hi, width, &mid)) {
    const int s = f.sign_at(mid, nullptr);
    if (s == 0) return {mid, mid};
    (s == sign_lo ? lo : hi) = mid;
  }
  return {lo, hi};
}

enum class Side { below, at, above, unknown };

/// What the exact signs gathered so far prove about the root r of the bracket [lo0, hi0],
/// under the contract. Once sign_lo (the sign of f on [lo0, r)) is known, a probe t with
/// f(t) != 0 is below r when its sign is sign_lo and above r otherwise. Before that, probes
/// that all have one sign are "pending": they are on one side of r, which one is unknown, and
/// a probe of the other sign settles it (r lies between the two kinds).
class RootKnowledge {
 public:
  RootKnowledge(double lo, double hi) : below_(lo), above_(hi) {}

  Side side_of(double t) const {
    if (root_known_) return t < root_ ? Side::below : t > root_ ? Side::above : Side::at;
    if (t <= below_) return Side::below;
    if (t >= above_) return Side::above;
    return Side::unknown;
  }
  bool sign_lo_known() const { return sign_lo_ != 0; }
  bool root_known() const { return root_known_; }
  double root() const { return root_; }
  double below() const { return below_; }
  double above() const { return above_; }

  /// Whether a probe at t can add anything: inside (below, above), and outside the pending
  /// range (a probe there would have the pending sign, or break the contract).
  bool informative(double t) const {
    if (!(t > below_ && t < above_)) return false;
    return sign_lo_ != 0 || !pending_ || t < pending_min_ || t > pending_max_;
  }

  /// Records sign(f(t)) = s for t in (below, above). False when the signs seen contradict
  /// the contract (two sign changes).
  bool learn(double t, int s) {
    if (s == 0) {  // the only root of [lo0, hi0]
      root_known_ = true;
      root_ = t;
      return true;
    }
    if (sign_lo_ != 0) {
      (s == sign_lo_ ? below_ : above_) = t;
      return true;
    }
    if (!pending_) {
      pending_ = true;
      pending_min_ = pending_max_ = t;
      pending_sign_ = s;
      return true;
    }
    if (s == pending_sign_) {
      pending_min_ = std::min(pending_min_, t);
      pending_max_ = std::max(pending_max_, t);
      return true;
    }
    if (t > pending_max_) {  // pending probes below r, t above it
      sign_lo_ = pending_sign_;
      below_ = pending_max_;
      above_ = t;
    } else if (t < pending_min_) {  // t below r, pending probes above it
      sign_lo_ = s;
      below_ = t;
      above_ = pending_min_;
    } else {
      return false;
    }
    pending_ = false;
    return true;
  }

  /// Records sign(f(lo0)) = s. False when s == 0 (the contract excludes it).
  bool learn_sign_lo(int s) {
    if (s == 0) return false;
    sign_lo_ = s;
    if (pending_ && pending_sign_ == s) below_ = pending_max_;
    if (pending_ && pending_sign_ != s) above_ = pending_min_;
    pending_ = false;
    return true;
  }

 private:
  double below_, above_;  // lo0 <= below < r < above <= hi0
  bool root_known_ = false;
  double root_ = 0;
  int sign_lo_ = 0;
  bool pending_ = false;
  double pending_min_ = 0, pending_max_ = 0;
  int pending_sign_ = 0;
};

/// Chooses probe points near the root: floating-point Newton on the cubic with rounded
/// coefficients for the first one, then Newton steps driven by the EXACT value of f at the
/// latest probe (rounded), aimed slightly past the predicted root so that consecutive probes
/// tend to straddle it. Nothing it computes decides anything: a poor guess only costs an
/// exact evaluation, whatever the precision of Real and the rounding mode.
class Guide {
 public:
  explicit Guide(const CubicAtDoubles& f) {
    Approximation c[4];
    f.approximate_coefficients(c);
    scale_ = LONG_MIN;
    for (const Approximation& ci : c)
      if (ci.mantissa != 0) scale_ = std::max(scale_, ci.exponent);
    if (scale_ == LONG_MIN) scale_ = 0;
    for (int i = 0; i < 4; ++i)  // f(t) ~ 2^scale (a0 + a1 t + a2 t^2 + a3 t^3)
      a_[i] = c[i].mantissa * power_of_two(c[i].exponent - scale_);
  }

  /// The next probe: a point where RootKnowledge::informative holds, or NaN when guidance
  /// has nothing useful to offer.
  double next_probe(const RootKnowledge& known, double lo, double hi) const {
    double x;
    if (!has_probe_) {
      x = initial_estimate(lo, hi);
    } else {
      x = newton_probe();
    }
    // r lies in (below, above): a target at or beyond an end means that r is next to it.
    if (x <= known.below()) x = next_up(known.below());
    if (x >= known.above()) x = next_down(known.above());
    return known.informative(x) ? x : std::numeric_limits<double>::quiet_NaN();
  }

  /// The probe t gave f(t) ~ value (rounded from the exact value), of sign s != 0.
  void record(double t, int s, const Approximation& value) {
    if (has_probe_ && s == sign_) ++misses_;
    else misses_ = 0;
    has_probe_ = true;
    t_ = t;
    sign_ = s;
    m_ = value.mantissa;
    e_ = value.exponent;  // f(t) ~ m 2^e
  }

 private:
  static int clamp(long e) { return static_cast<int>(std::min(4000L, std::max(-4000L, e))); }

  /// 2^k for -1022 <= k <= 1023, 0 below (a cheap ldexp where tiny values may be dropped).
  static double power_of_two(long k) {
    if (k < -1022) return 0.0;
    return from_order_bits(static_cast<std::uint64_t>(std::min(k, 1023L) + 1023) << 52);
  }

  Real g(Real t) const { return ((a_[3] * t + a_[2]) * t + a_[1]) * t + a_[0]; }
  Real dg(Real t) const { return (3 * a_[3] * t + 2 * a_[2]) * t + a_[1]; }

  /// Newton's method on the rounded cubic from the middle of [lo, hi], kept inside it.
  double initial_estimate(double lo, double hi) const {
    Real t = lo + (static_cast<Real>(hi) - lo) / 2;
    for (int i = 0; i < 8; ++i) {
      const Real next = t - g(t) / dg(t);
      if (!(next >= lo && next <= hi)) break;  // NaN included
      const bool converged =
          std::fabs(next - t) <= std::fabs(t) * std::numeric_limits<Real>::epsilon();
      t = next;
      if (converged) break;
    }
    return static_cast<double>(t);
  }

  /// A Newton step from the latest probe with its exact value, f' from the rounded cubic,
  /// carried past the predicted root by a margin: 2^-10 of the step (the step's relative
  /// error is far smaller near a simple root), 16 times more, plus 16^(n-1) ulps, after n
  /// probes in a row that stayed on the same side. The probe is the first double beyond
  /// the target in the step's direction, and never the latest probe itself.
  double newton_probe() const {
    const Real q = -m_ / dg(t_);  // step = q 2^(e - scale)
    if (!std::isfinite(q) || q == 0) return std::numeric_limits<double>::quiet_NaN();
    const Real step = std::ldexp(q, clamp(e_ - scale_));
    if (!std::isfinite(step)) return std::numeric_limits<double>::quiet_NaN();
    const bool up = q > 0;
    const int growth = 4 * std::min(misses_, 12);
    Real margin = std::fabs(step) * power_of_two(-10 + growth);
    if (misses_ > 0) margin += static_cast<Real>(next_up(t_) - t_) * power_of_two(growth - 4);
    const Real target_step = up ? step + margin : step - margin;
    const double c = static_cast<double>(t_ + target_step);
    if (!std::isfinite(c)) return std::numeric_limits<double>::quiet_NaN();
    const Real residual = target_step - (static_cast<Real>(c) - t_);  // which side of c
    double x = c;
    if (up && residual > 0) x = next_up(c);
    if (!up && residual < 0) x = next_down(c);
    if (x == t_) x = up ? next_up(t_) : next_down(t_);
    return x;
  }

  Real a_[4];
  long scale_;
  bool has_probe_ = false;
  double t_ = 0;
  Real m_ = 0;
  long e_ = 0;
  int sign_ = 0, misses_ = 0;
};

/// Exact evaluations spent on guided probes at most (then plain bisection of what is left).
constexpr int kMaxGuidedProbes = 8;

}  // namespace

// Each pass of the loop makes exactly one exact evaluation (PROOF:
// proofs/filters.md#guided-bisection, with the proof that the result is the reference loop's):
//  (a) a guided probe: at most kMaxGuidedProbes = 8 in all;
//  (b) the sign at lo0: at most once (sign_lo is then known);
//  (c) with sign_lo known, the sign at `mid`. For width 0, mid is the middle double (bit
//      order) strictly inside (below, above): the count of doubles there, at most 2^63, at
//      least halves, so (c) happens at most 64 times before no double is left (tight). For
//      width > 0, mid is the reference loop's next middle, whose side is then known: the
//      replay takes at least one step of that loop, which stops within 64 steps.
// So at most 8 + 1 + 64 = 73 evaluations (the reference loop: at most 65), and, where the
// signs seen contradict the contract, at most 65 more in the reference loop.
std::pair<double, double> guided_bisection(const CubicAtDoubles& f, double lo, double hi,
                                           double width) {
  double mid;
  if (!middle_double(lo, hi, width, &mid)) return {lo, hi};  // the reference loop's first stop
  const double lo0 = lo, hi0 = hi;
  RootKnowledge known(lo0, hi0);
  std::optional<Guide> guide;
  int guided_left = kMaxGuidedProbes;
  for (;;) {
    if (width == 0) {
      // The answer is the tightest pair around r: unique, so whatever pins r gives the
      // reference loop's answer.
      if (known.root_known()) return {known.root(), known.root()};
      if (!middle_double(known.below(), known.above(), 0.0, &mid))  // consecutive doubles
        return {known.below(), known.above()};
    } else {
      // Replay the reference loop as far as the signs gathered so far determine it.
      for (Side side; (side = known.side_of(mid)) != Side::unknown;) {
        if (side == Side::at) return {mid, mid};
        (side == Side::below ? lo : hi) = mid;
        if (!middle_double(lo, hi, width, &mid)) return {lo, hi};
      }
    }
    // One exact evaluation. A guided probe, unless guidance is spent (or, with a coarse
    // width, the replay ends within two or three middles anyway); else the middle, once the
    // sign at lo0 is known.
    double probe = std::numeric_limits<double>::quiet_NaN();
    if (guided_left > 0 && !(width > 0 && hi - lo <= 4 * width)) {
      if (!guide) guide.emplace(f);
      probe = guide->next_probe(known, lo0, hi0);
      guided_left = std::isnan(probe) ? 0 : guided_left - 1;
    }
    if (std::isnan(probe)) {
      if (!known.sign_lo_known()) {
        const int s = f.sign_at(lo0, nullptr);
        if (!known.learn_sign_lo(s)) return reference_bisection(f, lo0, hi0, width, s);
        continue;
      }
      probe = mid;
    }
    Approximation value;
    const int s = f.sign_at(probe, guide ? &value : nullptr);
    if (!known.learn(probe, s))
      return reference_bisection(f, lo0, hi0, width, f.sign_at(lo0, nullptr));
    if (guide && s != 0) guide->record(probe, s, value);
  }
}

}  // namespace exactccd::exact
