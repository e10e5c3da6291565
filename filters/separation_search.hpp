// The certified search for the first time within delta (minimum-separation CCD) over
// [0, t_max]: adaptive subdivision, depth first and earliest half first, of pieces excluded
// by separating directions or by the region polynomials' signs, and the tightening of the one
// polynomial root that is the first contact. Needs a RoundingGuard.
// PROOF: proofs/min_separation.md#interval-search
#pragma once

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <limits>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/motion.hpp"
#include "core/predicates/separation_exact_stage.hpp"
#include "exactccd/types.hpp"
#include "filters/certified_numbers.hpp"
#include "filters/separation_filter.hpp"

namespace exactccd::filters::separation {

using predicates::FixedPoly;
using Poly6 = FixedPoly<Interval, 6>;
using CoefficientTable = predicates::SeparationCoefficientTable;
using CoefficientValues = predicates::SeparationValues;
using ExactStage = predicates::SeparationExactStage;

/// The region polynomials of a separation (its numbering) with interval coefficients, padded
/// to degree 6, each computed when first asked for: over a piece, the positions' enclosures
/// certify most signs, and a contact's tightening needs one polynomial's coefficients.
template <class Separation>
class PolynomialTable {
 public:
  explicit PolynomialTable(const Separation& s) : separation_(s) {}

  const Poly6& operator[](int k) {
    if (!computed(k)) {
      separation_.for_each_polynomial(
          [this, k](const auto& g) {
            constexpr int D = std::decay_t<decltype(g)>::degree;
            static_assert(D <= 6, "the region polynomials have degree at most 6");
            for (int i = 0; i <= 6; ++i) poly_[k].c[i] = i <= D ? g.c[i] : Interval(0);
          },
          k);
      computed_ |= std::uint32_t{1} << k;
    }
    return poly_[k];
  }
  bool computed(int k) const { return (computed_ >> k) & 1; }
  /// Every polynomial replaced in place by `fill`'s (references stay valid), all computed.
  template <class Fill>
  void replace_all(Fill&& fill) {
    fill(&poly_);
    computed_ = ~std::uint32_t{0};
  }

 private:
  static_assert(kMaxSeparationPolynomials <= 32, "one bit per polynomial");
  const Separation& separation_;
  CoefficientTable poly_;
  std::uint32_t computed_ = 0;
};

/// An enclosure of g over [lo, hi] in centred form: g(m + s) = sum_i c_i s^i (an interval
/// Taylor shift to a double m), |s| <= h with [lo, hi] inside [m - h, m + h]; much tighter
/// than Horner over [lo, hi] where g is small and flat.
EXACTCCD_CERTIFIED Interval enclosure_over(const Poly6& g, double lo, double hi) {
  const double m = lo + 0.5 * (hi - lo);      // rounded upwards
  const double h = std::max(m - lo, hi - m);  // rounded upwards: >= every |t - m|
  std::array<Interval, 7> c = g.c;  // Taylor shift by m: repeated synthetic division
  const Interval mi(m);
  for (int k = 0; k < 6; ++k)
    for (int i = 5; i >= k; --i) c[i] = c[i] + mi * c[i + 1];
  Interval r = c[0];
  double hk = 1.0;
  for (int i = 1; i <= 6; ++i) {
    hk *= h;  // rounded upwards
    r = r + c[i] * (i % 2 ? Interval(-hk, hk) : Interval(0.0, hk));
  }
  return r;
}

/// The certified sign of g over [lo, hi] (constant there), or uncertain: interval Horner over
/// the piece first (cheap, and enough where g is far from zero), the centred form where that
/// cannot tell.
EXACTCCD_CERTIFIED CertifiedSign sign_over(const Poly6& g, double lo, double hi) {
  const CertifiedSign s = certified_sign(predicates::evaluate(g, Interval(lo, hi)));
  if (s != CertifiedSign::uncertain) return s;
  return certified_sign(enclosure_over(g, lo, hi));
}

EXACTCCD_CERTIFIED Poly6 derivative_of(const Poly6& g) {
  Poly6 d;
  for (int i = 1; i <= 6; ++i) d.c[i - 1] = g.c[i] * Interval(i);
  d.c[6] = Interval(0);  // Interval_nt default-constructs no value
  return d;
}

/// Depth to which separating directions are tried, and depth of the whole subdivision.
constexpr int kDirectionDepth = 6;
constexpr int kMaxDepth = 40;
/// Pieces one search examines at most.
constexpr int kMaxPieces = 400;
/// Depth to which pieces are first enclosed from the positions: the pieces advancement hands
/// over (depth 7) and the bisection's first analysed ones. Deeper, the coefficients alone:
/// the positions' enclosures there cost more than they decide, and on nearly parallel edges
/// they exclude pieces only deep down, so that the search walks the step at a fine resolution
/// instead of giving up at kMaxDepth at once (sample queries at 1e-8 of the size: 2.4 us with
/// them to depth 16, 2.1 us to depth 8).
constexpr int kFactoredDepth = 8;
/// Conservative advancement: rounds (advancement, then one analysed piece), steps per round,
/// and the distance to the estimate at which a round stops advancing.
constexpr int kAdvanceRounds = 2;
constexpr int kAdvanceSteps = 6;
constexpr double kAdvancedPiece = 0x1p-8;

/// Every piece before the current one is certainly never within delta (`cleared_` is its
/// end). A piece is excluded by separating directions (depth <= kDirectionDepth), or when the
/// instant predicate is false over it with every sign the table cannot certify read
/// optimistically (within is monotone); a piece over which every sign is certain but one
/// polynomial's, monotone with opposite certain signs at the ends, holds the first contact at
/// that root when the predicate certainly holds at its end.
///
/// Where the enclosures of its table cannot tell, the search asks `Factored` (an enclosure of
/// region polynomial k at the double t, `factored(k, t)`, and of every one over [lo, hi],
/// `factored.all_over(Interval(lo, hi), &values)`, from interval positions of the vertices: the
/// polynomials' factored forms, far tighter near a root than their expanded coefficients), then
/// the exact stage (exact signs at doubles, guesses that never decide, the exact coefficients).
template <class Motion, class Separation, class Factored>
class FirstWithinSearch {
 public:
  enum class Step : std::uint8_t { excluded, found, give_up };

  FirstWithinSearch(const Motion& m, const Separation& s, const Factored& factored,
                    const ExactStage& exact, const CcdOptions& options)
      : m_(m), separation_(s), factored_(factored), exact_(exact), options_(options),
        delta2_(Interval(options.min_separation) * options.min_separation) {}

  FilterOutcome run() {
    FilterOutcome out;
    Step s = advance_then_search();
    if (s == Step::give_up && sharpen()) {
      // The enclosures computed from the coordinates could not tell: the rest of the step
      // again with the exact coefficients' (the same polynomials up to positive scales, so
      // every sign already read holds). PROOF: proofs/min_separation.md#exact-coefficients
      bracket_ = false;
      pieces_ = 0;
      s = search(cleared_, options_.t_max, 0);
    }
    out.cleared_until = cleared_;
    out.exact_used = exact_used_;
    if (s == Step::excluded) {
      out.verdict = FilterOutcome::Verdict::no_contact;
    } else if (s == Step::found) {
      out.verdict = FilterOutcome::Verdict::contact;
      out.toi_lo = toi_lo_;
      out.toi_hi = toi_hi_;
      out.toi_final = true;
    } else if (bracket_ && cleared_ == bracket_lo_) {
      out.bracketed = true;
      out.cleared_until = bracket_lo_;
      out.within_at = bracket_hi_;
      out.known_signs = known_;
    }
    return out;
  }

 private:
  static constexpr int kUnknown = 2;
  static constexpr signed char kNotYet = 3;
  /// Signs of the region polynomials over a piece: -1, 0, +1 certain, kUnknown (uncertain
  /// there), kNotYet (not computed).
  using Signs = std::array<signed char, Separation::kCount>;

  /// `inherited`: the certain signs over an enclosing piece, which hold over this one too
  /// (none at the top).
  Step search(double lo, double hi, int depth, const Signs* inherited = nullptr) {
    // A bound on the work: past kMaxPieces pieces the search gives up (the exact coefficients'
    // table, then the exact procedure from the cleared time, decide), so that pieces that are
    // each excluded only deep down cannot make it walk the step at a fine resolution.
    if (++pieces_ > kMaxPieces) return Step::give_up;
    // All of [0, 1] has just failed the whole-step test (the same guesses from the input
    // doubles) and culling (the axes): not tried again.
    if (depth <= kDirectionDepth && !(lo == 0.0 && hi == 1.0) &&
        m_.apart_over(Interval(lo, hi), delta2_, options_.min_separation, true)) {
      cleared_ = hi;
      return Step::excluded;
    }
    Signs signs;
    signs.fill(kNotYet);
    if (inherited)
      for (int k = 0; k < Separation::kCount; ++k)
        if ((*inherited)[k] != kUnknown) signs[k] = (*inherited)[k];
    if (depth >= kDirectionDepth) {
      bool split = false;
      const Step s = analyse(lo, hi, depth, &split, &signs);
      if (!split) return s;
    }
    const double mid = lo + 0.5 * (hi - lo);  // rounded upwards: in (lo, hi] or hi
    if (depth == kMaxDepth || !(mid > lo && mid < hi)) {
      if (depth >= kDirectionDepth) bracket(lo, hi);
      return Step::give_up;
    }
    const Step left = search(lo, mid, depth + 1, &signs);
    if (left != Step::excluded) return left;
    return search(mid, hi, depth + 1, &signs);
  }

  /// Conservative advancement, then the search over what is left. Advancement clears pieces
  /// [lo, end] along the closest-points direction at lo until the way to its estimate of the
  /// first time within delta is short; the piece from there to twice that way is analysed at
  /// once (depth past kDirectionDepth: no separating-direction tests on a piece that most
  /// likely holds the contact); if it is excluded, again from its end. The bisection of
  /// `search` takes over where advancement makes no progress.
  /// PROOF: proofs/min_separation.md#conservative-advancement
  Step advance_then_search() {
    const double t_max = options_.t_max;
    double lo = 0.0;
    for (int round = 0; round < kAdvanceRounds; ++round) {
      double estimate = lo;
      for (int step = 0; step < kAdvanceSteps; ++step) {
        const double next = m_.advance(lo, t_max, delta2_, options_.min_separation, &estimate);
        if (!(next > lo)) break;
        cleared_ = lo = next;
        if (lo >= t_max) return Step::excluded;
        if (estimate - lo <= kAdvancedPiece) break;
      }
      const double hi = lo + 2 * (estimate - lo);  // rounded upwards
      if (lo == 0.0 || !(hi > lo && hi < t_max)) break;
      const Step s = search(lo, hi, kDirectionDepth + 1);
      if (s != Step::excluded) return s;
      lo = hi;
    }
    return search(cleared_, t_max, 0);
  }

  /// Replaces the table by the exact coefficients' enclosures; false when it already is.
  bool sharpen() {
    if (sharp_) return false;
    table_.replace_all([this](CoefficientTable* t) { exact_.exact_coefficients(t); });
    exact_used_ = sharp_ = true;
    return true;
  }

  /// Region polynomial k's interval coefficients.
  const Poly6& poly(int k) { return table_[k]; }

  /// The signs of every region polynomial over one piece, each from the positions'
  /// enclosures over the piece (all of them computed at the first sign asked for) when that
  /// is certain and the table is not the exact coefficients', else from polynomial k's
  /// coefficients (Horner, then the centred form). PROOF: proofs/min_separation.md#factored-form
  class PieceSigns {
   public:
    PieceSigns(FirstWithinSearch* search, double lo, double hi, bool factored = true)
        : search_(search), lo_(lo), hi_(hi), factored_(factored) {}
    CertifiedSign operator()(int k) {
      if (factored_ && !search_->sharp_) {
        if (!have_values_) {
          search_->factored_.all_over(Interval(lo_, hi_), &values_);
          have_values_ = true;
        }
        const CertifiedSign s = certified_sign(values_[k]);
        if (s != CertifiedSign::uncertain) return s;
      }
      return sign_over(search_->poly(k), lo_, hi_);
    }

   private:
    FirstWithinSearch* search_;
    double lo_, hi_;
    bool factored_;
    bool have_values_ = false;
    CoefficientValues values_;
  };

  /// The predicate at the double t with certified signs: +1 within, -1 not, 0 uncertain.
  int within_at(double t) {
    bool uncertain = false;
    const bool within = Separation::within([&](int k) {
      const CertifiedSign s = interval_sign_at(k, t);
      if (s != CertifiedSign::uncertain) return static_cast<int>(s);
      uncertain = true;
      return 0;
    });
    return uncertain ? 0 : (within ? 1 : -1);
  }

  /// The piece [lo, hi] where the search stops (lo is cleared): when the predicate certainly
  /// holds at hi, t* lies in (lo, hi], a root of one of the polynomials whose sign is
  /// uncertain over the piece; the others' signs there are constant and handed to the exact
  /// stage. PROOF: proofs/min_separation.md#interval-search
  void bracket(double lo, double hi) {
    if (within_at(hi) <= 0) return;
    bracket_ = true;
    bracket_lo_ = lo;
    bracket_hi_ = hi;
    known_.fill(kUnknown);
    PieceSigns piece(this, lo, hi);
    for (int k = 0; k < Separation::kCount; ++k) {
      const CertifiedSign s = piece(k);
      if (s != CertifiedSign::uncertain) known_[k] = static_cast<signed char>(s);
    }
  }

  /// The signs of every region polynomial over [lo, hi]; *split when a finer piece may
  /// decide what this one cannot. The signs are computed when first read: the optimistic test
  /// often excludes a piece after a few of them.
  /// `sign`: the signs known over the piece (inherited from enclosing pieces), completed here.
  Step analyse(double lo, double hi, int depth, bool* split, Signs* signs) {
    Signs& sign = *signs;
    PieceSigns piece(this, lo, hi, depth <= kFactoredDepth);
    auto sign_of = [&](int k) {
      if (sign[k] == kNotYet) {
        const CertifiedSign s = piece(k);
        sign[k] = static_cast<signed char>(s == CertifiedSign::uncertain ? kUnknown : int(s));
      }
      return static_cast<int>(sign[k]);
    };
    if (lo == 0.0 && cleared_ == 0.0) {  // not within at lo: lo is cleared, or t = 0 is tested
      const int at_zero = within_at(0.0);
      if (at_zero == 0) return Step::give_up;
      if (at_zero > 0) {
        toi_lo_ = toi_hi_ = 0.0;
        return Step::found;
      }
    }
    // Optimistic: an uncertain non-strict condition reads as satisfied (sign 0), an uncertain
    // strict one as positive. Not within even so: not within anywhere in the piece.
    const bool possible = Separation::within([&](int k) {
      const int s = sign_of(k);
      if (s != kUnknown) return s;
      return k < Separation::kNonStrictCount ? 0 : 1;
    });
    if (!possible) {
      cleared_ = hi;
      return Step::excluded;
    }
    int uncertain = 0, which = -1;
    for (int k = 0; k < Separation::kCount; ++k) {
      if (sign_of(k) == kUnknown) {
        ++uncertain;
        which = k;
      }
    }
    if (uncertain > 1) {
      const Step s = conditions_turning_on(lo, hi, sign);
      if (s != Step::give_up) return s;
    }
    if (uncertain != 1 || which >= Separation::kNonStrictCount) {
      *split = true;
      return Step::give_up;
    }
    // One polynomial g's sign is uncertain over the piece; every other sign is constant.
    const Poly6& g = poly(which);
    const CertifiedSign slope = sign_over(derivative_of(g), lo, hi);
    if (slope == CertifiedSign::uncertain || slope == CertifiedSign::zero) {
      *split = true;
      return Step::give_up;
    }
    // g is strictly monotone: its signs at the ends (exact ones where intervals cannot
    // tell) place its only possible root.
    const int s_lo = sign_at(which, lo), s_hi = sign_at(which, hi);
    auto within_with = [&](int g_sign) {  // the predicate with g's sign set, the others known
      return Separation::within([&](int k) { return k == which ? g_sign : int(sign[k]); });
    };
    if (s_lo == 0) return Step::give_up;  // lo is not within: never reached, left to exact
    if (s_lo == s_hi) {  // no root: every sign constant over the piece, as at lo
      cleared_ = hi;
      return Step::excluded;
    }
    // g's only root r lies in (lo, hi]; on [lo, r) every sign is as at lo (not within). At r
    // g's non-strict condition holds, as it does on whichever side it holds: within at r iff
    // within on (r, hi] (or at r = hi, with g = 0).
    if (!within_with(s_hi)) {
      cleared_ = hi;
      return Step::excluded;
    }
    if (s_hi == 0) {
      toi_lo_ = toi_hi_ = hi;
      return Step::found;
    }
    return tighten(which, lo, hi, s_lo);
  }

  /// Several signs uncertain over [lo, hi], every one a non-strict polynomial whose
  /// derivative's enclosure has the certain strict sign that turns its condition on (negative
  /// for "<= 0", positive for ">= 0"): each condition, once on, stays on over the piece, so by
  /// monotonicity the instants within delta form [t*, hi] or nothing (lo is not within). The
  /// predicate at hi and a bisection in double order on the predicate at doubles (certified
  /// signs, exact ones where intervals cannot tell) then give t*. The case of several region
  /// polynomials vanishing together: a vertex reaching delta at a triangle's corner.
  /// PROOF: proofs/min_separation.md#conditions-turning-on
  Step conditions_turning_on(double lo, double hi,
                             const std::array<signed char, Separation::kCount>& sign) {
    for (int k = 0; k < Separation::kCount; ++k) {
      if (sign[k] != kUnknown) continue;
      if (k >= Separation::kNonStrictCount) return Step::give_up;
      const CertifiedSign slope = sign_over(derivative_of(poly(k)), lo, hi);
      if (slope == CertifiedSign::uncertain || slope == CertifiedSign::zero ||
          static_cast<int>(slope) != Separation::condition(k))
        return Step::give_up;
    }
    auto within_exactly_at = [&](double t) {
      return Separation::within(
          [&](int k) { return sign[k] != kUnknown ? int(sign[k]) : sign_at(k, t); });
    };
    if (!within_exactly_at(hi)) {
      cleared_ = hi;
      return Step::excluded;
    }
    double l = lo, h = hi;  // not within at l, within at h
    for (;;) {
      if (options_.toi_width > 0 && h - l <= options_.toi_width) break;  // rounded up
      double mid = 0;
      if (!predicates::middle_double(l, h, &mid)) break;
      (within_exactly_at(mid) ? h : l) = mid;
    }
    // t* = h exactly iff not within just before h: there a condition whose polynomial vanishes
    // at h is still off, one strictly on at h was already on.
    const bool before_h = Separation::within([&](int k) {
      if (sign[k] != kUnknown) return int(sign[k]);
      const int s = sign_at(k, h);
      return s != 0 ? s : -Separation::condition(k);
    });
    toi_lo_ = before_h ? l : h;
    toi_hi_ = h;
    return Step::found;
  }

  /// The certified sign of polynomial k at the double t: the table's enclosure, else the
  /// factored form's.
  CertifiedSign interval_sign_at(int k, double t) {
    // Without coefficients at hand, the positions' enclosure first (it needs none); each
    // enclosure at most once.
    const bool factored_first = !table_.computed(k);
    if (factored_first) {
      const CertifiedSign s = certified_sign(factored_(k, t));
      if (s != CertifiedSign::uncertain) return s;
    }
    const CertifiedSign s = certified_sign(predicates::evaluate(poly(k), Interval(t)));
    if (s != CertifiedSign::uncertain || factored_first) return s;
    return certified_sign(factored_(k, t));
  }

  /// The sign of polynomial k at the double t: certified by intervals, else by the exact stage
  /// (double-double with an error bound, else exact integers; the caller learns from it
  /// whether exact arithmetic was needed).
  int sign_at(int k, double t) {
    const CertifiedSign s = interval_sign_at(k, t);
    if (s != CertifiedSign::uncertain) return static_cast<int>(s);
    return exact_.sign_at(k, t);
  }

  /// The first contact is the root r in (lo, hi) of polynomial k, of sign s_lo at lo, g
  /// strictly monotone on [lo, hi]: every probe t in (lo, hi) whose sign is certified moves lo
  /// or hi to t. The probes: secant steps through the middles of g's interval values (at most
  /// kGuidedSteps, the first slope from g''s enclosure), else bisection in the order of
  /// doubles; where the interval cannot tell, two probes about its uncertainty away on either
  /// side, then exact signs at doubles (at a point guessed from exact values, and its
  /// neighbour on r's side), to the tightest pair of doubles (or toi_width).
  /// PROOF: proofs/min_separation.md#interval-search
  Step tighten(int k, double lo, double hi, int s_lo) {
    const double start = exact_.newton_guess(k, lo, hi);
    if (!std::isnan(start)) return tighten_by_newton(k, lo, hi, s_lo, start);
    constexpr int kGuidedSteps = 16;
    const Poly6& g = poly(k);
    bool exact_phase = false;  // the interval signs have failed once: exact signs from here
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double slope = kNone;                   // a guess of g' near r
    double guess = kNone;                   // the next probe the guesses suggest
    double t_prev = kNone, v_prev = kNone;  // the previous probe and its value's middle
    int guided = 0;
    // A certified sign at t in (lo, hi) moves an end; true when t is the root itself.
    auto classify = [&](CertifiedSign s, double t) {
      if (s == CertifiedSign::zero) {
        lo = hi = t;
        return true;
      }
      (static_cast<int>(s) == s_lo ? lo : hi) = t;
      return false;
    };
    for (;;) {
      if (options_.toi_width > 0 && hi - lo <= options_.toi_width) break;  // rounded up
      double mid = 0;
      if (!predicates::middle_double(lo, hi, &mid)) break;
      if (!exact_phase) {
        const bool use_guess = guided < kGuidedSteps && guess > lo && guess < hi;
        guided += use_guess;
        const double t = use_guess ? guess : mid;
        Interval v = predicates::evaluate(g, Interval(t));
        CertifiedSign s = certified_sign(v);
        if (s == CertifiedSign::uncertain) {
          // The positions' enclosure: its sign, and (unless the table holds the exact
          // coefficients' scaled polynomials) its far narrower value for the guesses.
          const Interval f = factored_(k, t);
          s = certified_sign(f);
          if (!sharp_ && f.sup() - f.inf() < v.sup() - v.inf()) v = f;
        }
        const double v_mid = 0.5 * (v.inf() + v.sup());
        const double secant = (v_mid - v_prev) / (t - t_prev);  // NaN without a previous probe
        if (std::isfinite(secant) && secant != 0) {
          slope = secant;
        } else if (std::isnan(slope)) {
          slope = predicates::evaluate(derivative_of(g), Interval(t)).sup();
        }
        if (s != CertifiedSign::uncertain) {
          if (classify(s, t)) break;
          t_prev = t;
          v_prev = v_mid;
          guess = t - v_mid / slope;
          continue;
        }
        // Within the interval's uncertainty of r: probes at twice its estimated radius on
        // either side bracket r tightly when their signs are certified.
        const double radius = 2 * (v.sup() - v.inf()) / std::fabs(slope);
        bool root = false;
        for (const double probe : {t - radius, t + radius}) {
          if (root || !(probe > lo && probe < hi)) continue;
          const CertifiedSign sp = interval_sign_at(k, probe);
          if (sp != CertifiedSign::uncertain) root = classify(sp, probe);
        }
        if (root) break;
        exact_phase = true;
        continue;
      }
      // Near r the interval cannot tell: a point guessed from g's exact values (secant_guess;
      // its exact sign decides) and its neighbour on r's side, so that a good guess closes the
      // bracket to adjacent doubles at once.
      if (lo > 0) {
        const double exact_guess = exact_.secant_guess(k, lo, hi);
        if (exact_guess > lo && exact_guess < hi) mid = exact_guess;
      }
      const int s = sign_at(k, mid);
      if (s == 0) {
        lo = hi = mid;
        break;
      }
      (s == s_lo ? lo : hi) = mid;
      const double next = s == s_lo ? std::nextafter(mid, hi) : std::nextafter(mid, lo);
      if (next > lo && next < hi) {
        const int s_next = sign_at(k, next);
        if (s_next == 0) {
          lo = hi = next;
          break;
        }
        (s_next == s_lo ? lo : hi) = next;
      }
    }
    toi_lo_ = lo;
    toi_hi_ = hi;
    return Step::found;
  }

  /// tighten for a polynomial with a kernel: Newton's method in plain arithmetic has guessed
  /// the root r (`start`); from there every probe is an exact sign at a double (double-double
  /// with an error bound, exact integers where it cannot tell), which moves lo or hi, and its
  /// value's Newton step is the next probe; a step that rounds back to the probe goes to the
  /// probe's neighbour on r's side instead, so that two probes usually close the bracket to
  /// adjacent doubles. The intervals are not asked: at a guess this close to r they cannot
  /// tell. Past kNewtonProbes probes, bisection in the order of doubles.
  /// PROOF: proofs/min_separation.md#newton-tightening
  Step tighten_by_newton(int k, double lo, double hi, int s_lo, double start) {
    constexpr int kNewtonProbes = 8;
    double t = start;
    for (int probes = 0;; ++probes) {
      if (options_.toi_width > 0 && hi - lo <= options_.toi_width) break;  // rounded up
      double mid = 0;
      if (!predicates::middle_double(lo, hi, &mid)) break;
      if (!(t > lo && t < hi) || probes >= kNewtonProbes) t = mid;
      const ExactStage::Probe p = exact_.probe_at(k, t);
      if (p.sign == 0) {
        lo = hi = t;
        break;
      }
      const bool below = p.sign == s_lo;  // t < r
      (below ? lo : hi) = t;
      const double neighbour = below ? std::nextafter(t, hi) : std::nextafter(t, lo);
      // The Newton step, unless it does not leave t or goes the wrong way.
      t = (below ? p.newton > t : p.newton < t) ? p.newton : neighbour;
    }
    toi_lo_ = lo;
    toi_hi_ = hi;
    return Step::found;
  }

  const Motion& m_;
  const Separation& separation_;
  const Factored& factored_;
  const ExactStage& exact_;
  const CcdOptions& options_;
  const Interval delta2_;
  PolynomialTable<Separation> table_{separation_};
  bool sharp_ = false;  // the table holds the exact coefficients' enclosures
  bool bracket_ = false;
  double bracket_lo_ = 0.0, bracket_hi_ = 0.0;
  std::array<signed char, kMaxSeparationPolynomials> known_{};
  double cleared_ = 0.0;
  int pieces_ = 0;  // pieces examined by the current search
  double toi_lo_ = 0.0, toi_hi_ = 0.0;
  bool exact_used_ = false;
};

}  // namespace exactccd::filters::separation
