// PROOF: proofs/rigid_ccd.md#filters
#include "filters/rigid_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/rigid_coplanarity.hpp"
#include "core/predicates/rigid_paths.hpp"
#include "core/predicates/x87_interval.hpp"
#include "filters/certified_numbers.hpp"
#include "filters/earliest_root_search.hpp"
#include "filters/polynomial_bernstein.hpp"
#include "filters/rigid_paths_in_intervals.hpp"

namespace exactccd::filters {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;
using rigid::Boxes;
using rigid::IntervalPaths;
using rigid::boxes_apart;
using rigid::positions_over;
using Quintic = FixedPoly<Interval, 5>;

// ---------------------------------------------------------------------------------------------
// Paths and positions in intervals

/// g with coefficients over NT (an interval type: enclosures of the exact coefficients).
template <class NT>
FixedPoly<NT, 5> coplanarity_over(const DoubleRigidQuery& q) {
  using predicates::edge_edge_rigid_coplanarity;
  using predicates::vertex_face_rigid_coplanarity;
  const auto& x = q.start;
  return q.type == QueryType::vertex_face
             ? vertex_face_rigid_coplanarity<NT>(x[0], x[1], x[2], x[3], q.side[0], q.side[1])
             : edge_edge_rigid_coplanarity<NT>(x[0], x[1], x[2], x[3], q.side[0], q.side[1]);
}

#if EXACTCCD_X87_INTERVAL
/// Signs of g at doubles from its coefficients in extended-precision intervals, formed on
/// first use (about 2^11 times tighter than the double ones).
class ExtendedSigns {
 public:
  explicit ExtendedSigns(const DoubleRigidQuery& q) : query_(q) {}
  /// +1 / -1, 2 for a certain zero, 0 when uncertain.
  int sign_at(double t) {
    const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
    prepare();
    return predicates::certain_sign_or_zero(predicates::evaluate(g_, predicates::X87Interval(t)));
  }
  /// A double strictly inside (lo, hi) (some double must lie there) near the root (g(hi) of
  /// sign sign_hi): Newton's method on the midpoints of the extended coefficients, safeguarded
  /// by bisection; only a choice of probe.
  double root_guess(double lo, double hi, int sign_hi) {
    const predicates::X87EnvironmentGuard nearest;
    prepare();
    long double c[6];
    for (int i = 0; i < 6; ++i) c[i] = g_.c[i].lo / 2 + g_.c[i].hi / 2;
    long double a = lo, b = hi, t = a + (b - a) / 2;
    for (int n = 0; n < 40; ++n) {
      long double v = c[5], d = 0;
      for (int i = 4; i >= 0; --i) d = d * t + v, v = v * t + c[i];
      if (!(v != 0)) break;  // a root of the guide, or NaN
      ((v > 0) == (sign_hi > 0) ? b : a) = t;
      long double next = t - v / d;
      if (!(next > a && next < b)) next = a + (b - a) / 2;
      if (next == t) break;
      t = next;
    }
    const double guess = static_cast<double>(t);
    if (guess > lo && guess < hi) return guess;
    double mid = lo;
    predicates::middle_double(lo, hi, &mid);  // lo < mid < hi: the caller has a double inside
    return mid;
  }

 private:
  void prepare() {
    if (ready_) return;
    const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
    g_ = coplanarity_over<predicates::X87Interval>(query_);
    ready_ = true;
  }

  const DoubleRigidQuery& query_;
  FixedPoly<predicates::X87Interval, 5> g_;
  bool ready_ = false;
};
#endif

// ---------------------------------------------------------------------------------------------
// Inclusion on boxes (PROOF: proofs/rigid_ccd.md#inclusion-over-brackets)

enum class Inclusion : std::uint8_t { excluded, included, unknown };

/// Over a time interval whose position boxes are x: `excluded` when no s of it is a contact;
/// `included` when every coplanar s of it is a contact.
Inclusion vertex_face_inclusion(const Boxes& x) {
  const auto &p = x[0], &a = x[1], &b = x[2], &c = x[3];
  for (int k = 0; k < 3; ++k) {
    const int s = certain_strict_sign(predicates::orient2d_along_axis(k, a, b, c));
    if (s == 0) continue;
    const int e[3] = {certain_strict_sign(predicates::orient2d_along_axis(k, a, b, p)),
                      certain_strict_sign(predicates::orient2d_along_axis(k, b, c, p)),
                      certain_strict_sign(predicates::orient2d_along_axis(k, c, a, p))};
    if (e[0] == -s || e[1] == -s || e[2] == -s) return Inclusion::excluded;
    if (e[0] == s && e[1] == s && e[2] == s) return Inclusion::included;
  }
  return Inclusion::unknown;
}

Inclusion edge_edge_inclusion(const Boxes& x) {
  const auto &a0 = x[0], &a1 = x[1], &b0 = x[2], &b1 = x[3];
  for (int k = 0; k < 3; ++k) {
    const int o[4] = {certain_strict_sign(predicates::orient2d_along_axis(k, a0, a1, b0)),
                      certain_strict_sign(predicates::orient2d_along_axis(k, a0, a1, b1)),
                      certain_strict_sign(predicates::orient2d_along_axis(k, b0, b1, a0)),
                      certain_strict_sign(predicates::orient2d_along_axis(k, b0, b1, a1))};
    if ((o[0] != 0 && o[0] == o[1]) || (o[2] != 0 && o[2] == o[3])) return Inclusion::excluded;
    if (o[0] != 0 && o[1] == -o[0] && o[2] != 0 && o[3] == -o[2]) return Inclusion::included;
  }
  return Inclusion::unknown;
}

// ---------------------------------------------------------------------------------------------
// Brackets of a single root (PROOF: proofs/rigid_ccd.md#toi-tightening)

/// lo < r < hi with g(lo), g(hi) certainly non-zero of signs -sign_hi, sign_hi, r the only
/// root of g in [lo, hi] (simple); or lo == hi == r.
struct Bracket {
  double lo, hi;
  int sign_hi;
};

/// g with the midpoints of its interval coefficients: only a guide for where to probe.
/// Nothing is decided from it, whatever its rounding or accuracy.
struct Guide {
  double c[6], w[6];
  explicit Guide(const Quintic& g) {
    for (int i = 0; i < 6; ++i) {
      c[i] = g.c[i].inf() / 2 + g.c[i].sup() / 2;
      w[i] = g.c[i].sup() - g.c[i].inf();
    }
  }
  double value(double t) const {
    double r = c[5];
    for (int i = 4; i >= 0; --i) r = r * t + c[i];
    return r;
  }
  double slope(double t) const {
    double r = 5 * c[5];
    for (int i = 4; i >= 1; --i) r = r * t + i * c[i];
    return r;
  }
  double width(double t) const {
    double r = w[5];
    for (int i = 4; i >= 0; --i) r = r * t + w[i];
    return r;
  }
  /// A guess at the root in (lo, hi): Newton's method safeguarded by bisection of the guide's
  /// own bracket.
  double root(double lo, double hi, int sign_hi) const {
    double a = lo, b = hi;
    const double g_lo = value(lo), g_hi = value(hi);
    double t = lo + (hi - lo) * (g_lo / (g_lo - g_hi));
    if (!(t > lo && t < hi)) t = lo + (hi - lo) / 2;  // NaN included
    for (int i = 0; i < 60; ++i) {
      const double v = value(t);
      if (!(v != 0)) break;  // a root of the guide, or NaN
      ((v > 0) == (sign_hi > 0) ? b : a) = t;
      double next = t - v / slope(t);
      if (!(next > a && next < b)) next = a + (b - a) / 2;
      if (next == a || next == b) break;
      const double moved = std::fabs(next - t);
      const bool close = moved <= std::fabs(t) * 0x1p-50;
      t = next;
      if (close) break;
    }
    return t;
  }
};

using predicates::double_of;
using predicates::order_bits;

/// No double lies strictly inside the bracket: it is the tightest pair (or the exact root).
bool tightest(const Bracket& b) { return order_bits(b.hi) - order_bits(b.lo) < 2; }

class RootSearch {
 public:
  RootSearch(const Quintic& g, const DoubleRigidQuery& query, const IntervalPaths& paths,
             const CcdOptions& options, RigidExactStage& exact)
      : g_(g), guide_(g), paths_(paths), type_(query.type), t_max_(options.t_max),
        toi_width_(options.toi_width), exact_(exact)
#if EXACTCCD_X87_INTERVAL
        , extended_(query)
#endif
  {
  }

  FilterOutcome run();

  // The policy of the earliest-root search (filters/earliest_root_search.hpp).
  bool excluded_first(const Interval&, bool) const { return false; }
  bool hopeless(const Bernstein<Interval, 5>&, int, int, int) const { return false; }
  int end_sign(const Interval&, double t, FilterOutcome& out) {
    const int s = resolved_sign_at(t);
    out.exact_used = verdict_exact_;
    return s;
  }
  RootDecision at_double(double t, FilterOutcome& out) const {
    const Inclusion i = inclusion_over(Interval(t));
    if (i == Inclusion::excluded) return RootDecision::no_contact;
    if (i == Inclusion::included) out = contact(Bracket{t, t, 1});
    return i == Inclusion::included ? RootDecision::contact : RootDecision::undecided;
  }
  RootDecision single_root(double lo, double hi, int sign_hi, const Interval&, FilterOutcome& out) {
    Bracket b{lo, hi, sign_hi};
    const RootDecision d = decide_root(b);
    out.exact_used = verdict_exact_;
    if (d == RootDecision::contact) out = contact(b);
    return d;
  }
  /// Disjoint boxes, or no contact at any s of the node.
  bool excluded_last(const Interval& T, bool) const { return discarded(T); }

 private:
  static constexpr int kMaxDepth = 14;

  Side side_of(double t, int sign_hi) const {
    const CertifiedSign s = certified_sign(predicates::evaluate(g_, Interval(t)));
    if (s == CertifiedSign::uncertain) return Side::unknown;
    if (s == CertifiedSign::zero) return Side::at;
    return static_cast<int>(s) == sign_hi ? Side::above : Side::below;
  }
  /// The sign of g at the double t: from the double intervals, else the extended ones, else
  /// exact (then exact_used_).
  int fine_sign_at(double t) {
    const CertifiedSign s = certified_sign(predicates::evaluate(g_, Interval(t)));
    if (s != CertifiedSign::uncertain) return static_cast<int>(s);
#if EXACTCCD_X87_INTERVAL
    const int x = extended_.sign_at(t);
    if (x != 0) return x == 2 ? 0 : x;
#endif
    exact_used_ = true;
    return exact_.coplanarity_sign_at(t);
  }
  Side fine_side_of(double t, int sign_hi) {
    const int s = fine_sign_at(t);
    return s == 0 ? Side::at : (s == sign_hi ? Side::above : Side::below);
  }
  /// The sign of g at the double t (0 or t_max).
  int resolved_sign_at(double t) {
    exact_used_ = false;
    const int s = fine_sign_at(t);
    verdict_exact_ = verdict_exact_ || exact_used_;
    return s;
  }
  Inclusion inclusion_over(const Interval& T) const {
    const Boxes x = positions_over(paths_, T);
    return type_ == QueryType::vertex_face ? vertex_face_inclusion(x) : edge_edge_inclusion(x);
  }
  bool discarded(const Interval& T) const {
    const Boxes x = positions_over(paths_, T);
    if (boxes_apart(x, paths_.first_side_count)) return true;
    const Inclusion i =
        type_ == QueryType::vertex_face ? vertex_face_inclusion(x) : edge_edge_inclusion(x);
    return i == Inclusion::excluded;
  }
  bool toi_final(const Bracket& b) const {
    return tightest(b) || (toi_width_ > 0 && certainly_within_width(b.lo, b.hi, toi_width_));
  }
  static void classify(Bracket& b, double t, Side s) {
    if (s == Side::below) b.lo = t;
    if (s == Side::above) b.hi = t;
    if (s == Side::at) b.lo = b.hi = t;
  }
  bool narrow_by_intervals(Bracket& b) const;
  void narrow_finely(Bracket& b, bool to_tightest);
  RootDecision decide_root(Bracket& b);
  FilterOutcome contact(const Bracket& b) const {
    FilterOutcome r;
    r.verdict = FilterOutcome::Verdict::contact;
    r.toi_lo = b.lo;
    r.toi_hi = b.hi;
    r.toi_final = true;
    r.exact_used = verdict_exact_;
    r.toi_exact = toi_exact_;
    return r;
  }

  const Quintic& g_;
  const Guide guide_;
  const IntervalPaths& paths_;
  const QueryType type_;
  const double t_max_, toi_width_;
  RigidExactStage& exact_;
#if EXACTCCD_X87_INTERVAL
  ExtendedSigns extended_;
#endif
  bool exact_used_ = false;     // exact signs consulted by the current narrowing
  bool verdict_exact_ = false;  // exact signs decided part of the verdict
  bool toi_exact_ = false;      // exact signs tightened the reported TOI
};

/// Narrows b towards the tightest pair with interval signs only: a guess by the guide, probes
/// at growing distances from it on each side where r may lie, then bisection in bit order; stops
/// at the first uncertain sign of the bisection. True when the tightest pair (or r) is reached.
bool RootSearch::narrow_by_intervals(Bracket& b) const {
  if (tightest(b)) return true;
  std::uint64_t below = order_bits(b.lo), above = order_bits(b.hi);
  auto probe = [&](std::uint64_t x) {
    const double t = double_of(x);
    const Side s = side_of(t, b.sign_hi);
    classify(b, t, s);
    if (s == Side::below) below = x;
    if (s == Side::above) above = x;
    return s;
  };
  const std::uint64_t guessed = order_bits(guide_.root(b.lo, b.hi, b.sign_hi));
  const std::uint64_t guess = std::min(std::max(guessed, below + 1), above - 1);
  const Side first = probe(guess);
  if (first == Side::at) return true;
  // The first distance: the band around r where enclosures as wide as the guide's contain 0.
  const double t = double_of(guess);
  const double spacing = std::fabs(double_of(guess + 1) - t);
  const double band = guide_.width(t) / std::fabs(guide_.slope(t)) / spacing;
  const std::uint64_t step0 =
      band >= 1 && band < 0x1p60 ? static_cast<std::uint64_t>(band) + 1 : std::uint64_t{1};
  auto grown = [](std::uint64_t step) { return step < (std::uint64_t{1} << 62) ? 2 * step : step; };
  constexpr int kWalkProbes = 6;
  if (first != Side::above) {  // r may lie above the guess
    std::uint64_t from = guess, step = step0;
    for (int n = 0; n < kWalkProbes && from + 1 < above; ++n, step = grown(step)) {
      const std::uint64_t x = step < above - from ? from + step : from + (above - from) / 2;
      const Side s = probe(x);
      if (s == Side::at) return true;
      if (s == Side::above) break;
      from = x;
    }
  }
  if (first != Side::below) {  // r may lie below the guess
    std::uint64_t from = guess, step = step0;
    for (int n = 0; n < kWalkProbes && below + 1 < from; ++n, step = grown(step)) {
      const std::uint64_t x = step < from - below ? from - step : from - (from - below) / 2;
      const Side s = probe(x);
      if (s == Side::at) return true;
      if (s == Side::below) break;
      from = x;
    }
  }
  while (above - below >= 2) {
    const Side s = probe(below + (above - below) / 2);
    if (s == Side::at) return true;
    if (s == Side::unknown) return false;
  }
  return true;
}

/// Bisection in bit order to the tightest pair (or, unless to_tightest, to the reported TOI's
/// width when toi_width > 0), each sign from the double or extended intervals when certain,
/// else exact.
void RootSearch::narrow_finely(Bracket& b, bool to_tightest) {
  auto done = [&] { return to_tightest ? tightest(b) : toi_final(b); };
#if EXACTCCD_X87_INTERVAL
  // First the double nearest the extended guide's root and its neighbour towards r: with the
  // guide as accurate as the extended enclosures, usually the tightest pair at once.
  if (!done()) {
    const double guess = extended_.root_guess(b.lo, b.hi, b.sign_hi);
    const Side s = fine_side_of(guess, b.sign_hi);
    classify(b, guess, s);
    if (!done() && s != Side::at) {
      const std::uint64_t x = order_bits(guess);
      const double next = double_of(s == Side::below ? x + 1 : x - 1);
      if (next > b.lo && next < b.hi) classify(b, next, fine_side_of(next, b.sign_hi));
    }
  }
#endif
  double mid;
  while (!done() && predicates::middle_double(b.lo, b.hi, &mid))
    classify(b, mid, fine_side_of(mid, b.sign_hi));
}

/// Decides whether the only root r of the bracket is a contact, and narrows the bracket to the
/// reported TOI when it is.
RootDecision RootSearch::decide_root(Bracket& b) {
  const bool at_tightest = narrow_by_intervals(b);
  Inclusion inclusion = inclusion_over(Interval(b.lo, b.hi));
  if (inclusion == Inclusion::unknown && !at_tightest) {
    exact_used_ = false;
    narrow_finely(b, true);
    verdict_exact_ = verdict_exact_ || exact_used_;
    inclusion = inclusion_over(Interval(b.lo, b.hi));
  }
  if (inclusion == Inclusion::excluded) return RootDecision::no_contact;
  if (inclusion == Inclusion::unknown) return RootDecision::undecided;
  if (!toi_final(b)) {
    exact_used_ = false;
    narrow_finely(b, false);
    toi_exact_ = exact_used_;
  }
  return RootDecision::contact;
}

FilterOutcome RootSearch::run() {
  // g may vanish identically (coplanar throughout): every root then, for the exact path.
  bool nonzero = false;
  for (const Interval& c : g_.c) nonzero = nonzero || certain_strict_sign(c) != 0;
  if (!nonzero) return FilterOutcome{};
  return earliest_root_search<5, kMaxDepth>(g_, t_max_, *this);
}

}  // namespace

FilterOutcome rigid_ccd_filter(const DoubleRigidQuery& query, const CcdOptions& options,
                               RigidExactStage& exact) {
  const RoundingGuard upward;
  const int k = rigid::normalising_exponent(query);
  const DoubleRigidQuery q = k == 0 ? query : rigid::scaled(query, k);
  const IntervalPaths paths = rigid::interval_paths(q);
  if (boxes_apart(positions_over(paths, Interval(0.0, options.t_max)), paths.first_side_count)) {
    FilterOutcome r;
    r.verdict = FilterOutcome::Verdict::no_contact;
    r.culled = true;
    return r;
  }
  const Quintic g = coplanarity_over<Interval>(q);
  return RootSearch(g, q, paths, options, exact).run();
}

}  // namespace exactccd::filters
