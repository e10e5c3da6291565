// PROOF: proofs/min_separation.md#rigid-separation-filter
#include "filters/rigid_separation_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/rigid_separation.hpp"
#include "core/predicates/separation.hpp"
#include "core/predicates/x87_interval.hpp"
#include "filters/rigid_paths_in_intervals.hpp"

namespace exactccd::filters {

namespace {

using predicates::double_of;
using predicates::FixedPoly;
using predicates::order_bits;
using predicates::Vec3;
using rigid::Boxes;
using rigid::IntervalPaths;
#if EXACTCCD_X87_INTERVAL
using predicates::X87Interval;
#endif

/// A number and its first two derivatives in s, each enclosed (forward differentiation over
/// intervals).
struct Jet {
  Interval v{0.0}, d{0.0}, dd{0.0};
};
Jet operator+(const Jet& a, const Jet& b) { return {a.v + b.v, a.d + b.d, a.dd + b.dd}; }
Jet operator-(const Jet& a, const Jet& b) { return {a.v - b.v, a.d - b.d, a.dd - b.dd}; }
Jet operator-(const Jet& a) { return {-a.v, -a.d, -a.dd}; }
Jet operator*(const Jet& a, const Jet& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d, a.dd * b.v + Interval(2) * (a.d * b.d) + a.v * b.dd};
}

/// A number and its first derivative: the jets at an instant, where the second derivative is
/// never used (half the products of Jet).
struct SlopeJet {
  Interval v{0.0}, d{0.0};
};
SlopeJet operator+(const SlopeJet& a, const SlopeJet& b) { return {a.v + b.v, a.d + b.d}; }
SlopeJet operator-(const SlopeJet& a, const SlopeJet& b) { return {a.v - b.v, a.d - b.d}; }
SlopeJet operator-(const SlopeJet& a) { return {-a.v, -a.d}; }
SlopeJet operator*(const SlopeJet& a, const SlopeJet& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d};
}

template <class NT>
using ConstantPoint = Vec3<FixedPoly<NT, 0>>;
template <class NT>
using Positions = std::array<Vec3<NT>, 4>;

/// Positions and their derivatives over T (or at an instant): x = X / w,
/// x' = (X' - w' x) / w, x'' = (X'' - 2 w' x' - w'' x) / w (w >= 1); J = Jet or SlopeJet (no
/// second derivative).
template <class J>
Positions<J> position_jets(const IntervalPaths& paths, const Interval& T) {
  constexpr bool second = std::is_same_v<J, Jet>;
  Interval w[2], dw[2], ddw[2];
  for (int side = 0; side < 2; ++side) {
    const auto& p = paths.denominator[side];
    w[side] = predicates::evaluate(p, T);
    dw[side] = predicates::evaluate(predicates::derivative(p), T);
    if constexpr (second)
      ddw[side] = predicates::evaluate(predicates::derivative(predicates::derivative(p)), T);
  }
  Positions<J> x;
  for (int i = 0; i < 4; ++i) {
    const int side = i < paths.first_side_count ? 0 : 1;
    const auto& X = paths.numerator[i];
    const bool unit = paths.unit_denominator[side];
    auto jet = [&](const FixedPoly<Interval, 3>& c) {
      const auto dc = predicates::derivative(c);
      if (unit) {  // w = 1, w' = w'' = 0: the numerator's own derivatives
        if constexpr (second)
          return Jet{predicates::evaluate(c, T), predicates::evaluate(dc, T),
                     predicates::evaluate(predicates::derivative(dc), T)};
        else
          return SlopeJet{predicates::evaluate(c, T), predicates::evaluate(dc, T)};
      }
      const Interval v = predicates::evaluate(c, T) / w[side];
      const Interval d = (predicates::evaluate(dc, T) - dw[side] * v) / w[side];
      if constexpr (second) {
        const Interval dd = (predicates::evaluate(predicates::derivative(dc), T) -
                             Interval(2) * (dw[side] * d) - ddw[side] * v) /
                            w[side];
        return Jet{v, d, dd};
      } else {
        return SlopeJet{v, d};
      }
    };
    x[i] = {jet(X.x), jet(X.y), jet(X.z)};
  }
  return x;
}

/// The search for one separation kind (predicates::VertexFaceSeparation or EdgeEdgeSeparation).
template <template <class, class> class Separation>
class Search {
  using Kind = Separation<ConstantPoint<Interval>, Interval>;
  static constexpr int kCount = Kind::kCount;
  static constexpr int kNonStrict = Kind::kNonStrictCount;
  static constexpr int kMaxDepth = 14;
  static constexpr int kMaxPieces = 256;  // then the exact path, from what is cleared
  using Values = std::array<Interval, kCount>;

 public:
  Search(const DoubleRigidQuery& query, const IntervalPaths& paths, double delta,
         const CcdOptions& options, RigidExactStage& exact)
      : query_(query), paths_(paths), delta_(delta), delta2_(Interval(delta) * Interval(delta)),
        t_max_(options.t_max), toi_width_(options.toi_width), exact_(exact),
        extended_in_range_(in_extended_range(query, delta)) {}

  FilterOutcome run();

 private:
  /// Region polynomial values (all, or k alone into out[k]) on positions of any number type.
  template <class NT>
  static void region_values(const Positions<NT>& x, const NT& delta2, NT* out, int only = -1) {
    auto point = [&x](int i) {
      return ConstantPoint<NT>{{{x[i].x}}, {{x[i].y}}, {{x[i].z}}};
    };
    const Separation<ConstantPoint<NT>, NT> s{point(0), point(1), point(2), point(3), delta2};
    int n = 0;
    s.for_each_polynomial([&](const auto& g) { out[only < 0 ? n++ : only] = g.c[0]; }, only);
  }
  /// Enclosures over a piece T of the region polynomials, each formed when first asked for
  /// (`within` short-circuits: an excluded piece needs few of them): the box evaluation,
  /// intersected, when its sign is uncertain, with the mean-value form f(m) + f'(T) (T - m),
  /// which narrows quadratically with T.
  class PieceValues {
   public:
    /// narrow: worth the Taylor form (a piece of at most 1/128 of [0, t_max], not an instant).
    PieceValues(const Search& search, const Interval& T, const Boxes& x, bool narrow)
        : search_(search), T_(T), x_(x), narrow_(narrow) {}
    const Interval& operator[](int k) {
      if (!((formed_ >> k) & 1)) form(k);
      return v_[k];
    }
    const Interval& piece() const { return T_; }
    /// Position jets over T, and at the double m in its middle; T - m.
    const Positions<Jet>& positions_over() {
      prepare();
      return over_;
    }
    const Interval& offset() {
      prepare();
      return offset_;
    }
    /// Polynomial k's jets over T and at m.
    const Jet& jet_over(int k) {
      jets_of(k);
      return jet_over_[k];
    }
    const SlopeJet& jet_at_m(int k) {
      jets_of(k);
      return jet_at_m_[k];
    }

   private:
    void form(int k) {
      formed_ |= std::uint32_t{1} << k;
      region_values<Interval>(x_, search_.delta2_, v_.data(), k);
      if (certified_sign(v_[k]) != CertifiedSign::uncertain || !narrow_) return;
      // Taylor at m: f(m) + f'(m) o + f''(T) o^2 / 2, o = T - m.
      const SlopeJet& m = jet_at_m(k);
      const Interval taylor =
          m.v + m.d * offset_ + jet_over(k).dd * CGAL::square(offset_) * Interval(0.5);
      const double lo = std::max(v_[k].inf(), taylor.inf());
      const double hi = std::min(v_[k].sup(), taylor.sup());
      if (lo <= hi) v_[k] = Interval(lo, hi);  // both enclose f(T): they meet (NaN: keep the box)
    }
    void prepare() {
      if (ready_) return;
      const double m = T_.inf() + (T_.sup() - T_.inf()) / 2;  // rounded upwards: inside T
      over_ = position_jets<Jet>(search_.paths_, T_);
      at_m_ = position_jets<SlopeJet>(search_.paths_, Interval(m));
      offset_ = T_ - Interval(m);
      ready_ = true;
    }
    void jets_of(int k) {
      if ((jets_formed_ >> k) & 1) return;
      prepare();
      jets_formed_ |= std::uint32_t{1} << k;
      jet_over_[k] = search_.jet_of(k, over_);
      jet_at_m_[k] = search_.jet_of(k, at_m_);
    }

    const Search& search_;
    const Interval T_;
    const Boxes& x_;
    const bool narrow_;
    Values v_;
    std::uint32_t formed_ = 0, jets_formed_ = 0;
    bool ready_ = false;
    Positions<Jet> over_;
    Positions<SlopeJet> at_m_;
    Interval offset_;
    Jet jet_over_[kCount];
    SlopeJet jet_at_m_[kCount];
  };


  /// Polynomial k's jet from position jets.
  template <class J>
  J jet_of(int k, const Positions<J>& x) const {
    J out[kCount];
    J delta2;
    delta2.v = delta2_;  // a constant: its derivatives are 0
    region_values<J>(x, delta2, out, k);
    return out[k];
  }
  /// f_k changes sign at most once on T: f_k' of certain sign; or, for f_k = P - delta^2 Q with
  /// P, Q > 0 on T (the spheres, capsules, the face and the lines' region: squared distances
  /// times Q), h = sqrt(P) - delta sqrt(Q) of certain slope, h having f_k's sign (f_k = h times
  /// sqrt(P) + delta sqrt(Q) > 0). h is what the distance does; f_k's slope near its root is
  /// delta times smaller and its curvature is not, so f_k' is seldom certain on a wide piece.
  template <class V>
  bool certainly_monotone(int k, V& v) const {
    if (certain_strict_sign(derivative_over(k, v)) != 0) return true;
    const Positions<Jet>& over = v.positions_over();
    Jet p[kCount], p_minus_q[kCount];
    region_values<Jet>(over, Jet{Interval(0.0), Interval(0.0), Interval(0.0)}, p, k);
    region_values<Jet>(over, Jet{Interval(1.0), Interval(0.0), Interval(0.0)}, p_minus_q, k);
    const Jet& P = p[k];
    const Jet Q = p[k] - p_minus_q[k];
    if (!(P.v.inf() > 0 && Q.v.inf() > 0)) return false;
    const Interval slope = P.d / (Interval(2) * CGAL::sqrt(P.v)) -
                           Interval(delta_) * Q.d / (Interval(2) * CGAL::sqrt(Q.v));
    return certain_strict_sign(slope) != 0;
  }
  /// f_k' over T: f'(m) + f''(T) o, within the direct enclosure f'(T).
  template <class V>
  static Interval derivative_over(int k, V& v) {
    const SlopeJet& m = v.jet_at_m(k);
    const Jet& t = v.jet_over(k);
    const Interval taylor = m.d + t.dd * v.offset();
    const double lo = std::max(t.d.inf(), taylor.inf()), hi = std::min(t.d.sup(), taylor.sup());
    return lo <= hi ? Interval(lo, hi) : t.d;
  }
  Interval value_at(int k, double t) const {
    Interval v[kCount];
    region_values<Interval>(rigid::positions_over(paths_, Interval(t)), delta2_, v, k);
    return v[k];
  }
  /// Within delta somewhere the signs allow: uncertain conditions taken as met.
  template <class V>
  static bool possibly_within(V& v) {
    return Kind::within([&v](int k) {
      const CertifiedSign s = certified_sign(v[k]);
      if (s == CertifiedSign::uncertain) return k < kNonStrict ? 0 : 1;
      return static_cast<int>(s);
    });
  }
  /// Within delta with every condition it uses met strictly: then also at nearby instants.
  template <class V>
  static bool surely_within(V& v) {
    return Kind::within([&v](int k) {
      const int s = certain_strict_sign(v[k]);
      if (k >= kNonStrict) return s > 0 ? 1 : 0;
      const int c = Kind::condition(k);
      return s == c ? c : -c;
    });
  }
  /// The non-strict polynomials whose conditions decide `within` over the piece as their
  /// disjunction, for every sign the other uncertain polynomials may take (a bit mask; 0 when
  /// there are none): one polynomial, or all the uncertain ones (a contact close to the border
  /// of two regions, where both cross).
  template <class V>
  static std::uint32_t deciding_set(V& v) {
    constexpr int kMaxUncertain = 4;
    int uncertain[kMaxUncertain], count = 0;
    for (int i = 0; i < kCount; ++i) {
      if (certified_sign(v[i]) != CertifiedSign::uncertain) continue;
      if (count == kMaxUncertain) return 0;
      uncertain[count++] = i;
    }
    int combinations = 1;
    for (int i = 0; i < count; ++i) combinations *= 3;
    auto decides = [&](std::uint32_t set) {
      for (int code = 0; code < combinations; ++code) {
        int assigned[kCount];  // the uncertain ones' signs: code's base-3 digits - 1
        bool any_met = false;
        for (int i = 0, rest = code; i < count; ++i, rest /= 3) {
          const int k = uncertain[i];
          assigned[k] = rest % 3 - 1;
          if ((set >> k) & 1)
            any_met = any_met || assigned[k] == 0 || assigned[k] == Kind::condition(k);
        }
        const bool within = Kind::within([&](int i) {
          const CertifiedSign s = certified_sign(v[i]);
          return s == CertifiedSign::uncertain ? assigned[i] : static_cast<int>(s);
        });
        if (within != any_met) return false;
      }
      return true;
    };
    std::uint32_t all = 0;
    for (int j = 0; j < count; ++j) {
      const int k = uncertain[j];
      if (k >= kNonStrict) return 0;
      all |= std::uint32_t{1} << k;
      if (decides(std::uint32_t{1} << k)) return std::uint32_t{1} << k;
    }
    return count > 1 && decides(all) ? all : 0;
  }
  /// The exact sign of polynomial k at the double t: double intervals first, then extended
  /// ones on the common denominator, then exact.
  int fine_sign(int k, double t) {
    const CertifiedSign s = certified_sign(value_at(k, t));
    if (s != CertifiedSign::uncertain) return static_cast<int>(s);
#if EXACTCCD_X87_INTERVAL
    if (extended_in_range_) {
      // Positions, delta and Cayley vectors at most 2^66 in magnitude, the value of degree at
      // most 30 in them: far inside the extended exponent range (2^16383).
      const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
      if (!extended_paths_) extended_paths_ = predicates::rigid_paths<X87Interval>(query_);
      const int x = predicates::certain_sign_or_zero(predicates::rigid_region_value(
          *extended_paths_, query_.type, X87Interval(delta_), k, X87Interval(t)));
      if (x != 0) return x == 2 ? 0 : x;
    }
#endif
    exact_used_ = true;
    return exact_.region_sign_at(k, t);
  }
  bool toi_final(double lo, double hi) const {
    return order_bits(hi) - order_bits(lo) < 2 ||
           (toi_width_ > 0 && (Interval(hi) - Interval(lo)).sup() <= toi_width_);
  }
  enum class PieceVerdict : std::uint8_t { excluded, contact, undecided };
  PieceVerdict decide_piece(std::uint32_t set, PieceValues& v, FilterOutcome* out);
  bool advance(double* start, double* last_step) const;
  static constexpr int kMaxAdvances = 32;
  static constexpr double kSlowAdvance = 0x1p-8;  // of t_max: then the pieces take over
  static constexpr double kFirstWindow = 0x1p-6;  // of t_max: the least first window
  static constexpr double kNarrow = 0x1p-7;       // of t_max: pieces worth the Taylor form

  /// A lower bound of the distance between the primitives at an instant whose positions' boxes
  /// are x: the larger of the gap between the two sides' boxes and the distance to the
  /// triangle's plane (vertex-face) or between the segments' lines (edge-edge), each at most
  /// the distance between the primitives. 0 when nothing is certain.
  double distance_lower_bound(const Boxes& x) const {
    double gap[3];
    if (!rigid::axis_gaps(x, paths_.first_side_count, gap)) return 0.0;
    Interval gap2(0.0);
    for (const double g : gap)
      if (g > 0 && g < INFINITY) gap2 = gap2 + Interval(g) * Interval(g);
    double bound = CGAL::sqrt(Interval(gap2.inf())).inf();
    const Vec3<Interval> n = paths_.first_side_count == 1
                                 ? predicates::cross(x[2] - x[1], x[3] - x[1])
                                 : predicates::cross(x[1] - x[0], x[3] - x[2]);
    const Interval along = paths_.first_side_count == 1 ? predicates::dot(n, x[0] - x[1])
                                                        : predicates::dot(n, x[0] - x[2]);
    const Interval n2 = predicates::dot(n, n);
    if (n2.inf() > 0) {
      const double a = std::max(along.inf(), (-along).inf());  // |along| from below
      if (a > 0 && a < INFINITY) bound = std::max(bound, (Interval(a) / CGAL::sqrt(n2)).inf());
    }
    return bound;
  }
  /// An upper bound over S of the fastest vertex of side 0 plus the fastest of side 1.
  double speed_bound(const Interval& S) const {
    const Positions<SlopeJet> x = position_jets<SlopeJet>(paths_, S);
    double fastest[2] = {0.0, 0.0};
    for (int i = 0; i < 4; ++i) {
      Interval v2(0.0);
      for (int k = 0; k < 3; ++k) {
        const double m = std::max(std::fabs(x[i][k].d.inf()), std::fabs(x[i][k].d.sup()));
        if (!(m < INFINITY)) return INFINITY;  // overflow or NaN: no bound
        v2 = v2 + Interval(m) * Interval(m);
      }
      const double speed = CGAL::sqrt(v2).sup();
      double& f = fastest[i < paths_.first_side_count ? 0 : 1];
      f = std::max(f, speed);
    }
    return (Interval(fastest[0]) + Interval(fastest[1])).sup();
  }
  void tighten(int k, double* lo, double* hi);

  static FilterOutcome contact(double lo, double hi, bool exact_used) {
    FilterOutcome r;
    r.verdict = FilterOutcome::Verdict::contact;
    r.toi_lo = lo;
    r.toi_hi = hi;
    r.toi_final = true;
    r.exact_used = exact_used;
    return r;
  }

  /// Every number of the query at most 2^66 in magnitude (after its normalisation, unless that
  /// was not exact): the x87 tier cannot overflow.
  static bool in_extended_range(const DoubleRigidQuery& q, double delta) {
    double largest = delta;
    auto grow = [&largest](const Vec3<double>& x) {
      largest = std::max({largest, std::fabs(x.x), std::fabs(x.y), std::fabs(x.z)});
    };
    rigid::for_each_position(q, grow);
    for (const auto& side : q.side) grow(side.motion.cayley);
    return largest <= 0x1p66;
  }

  const DoubleRigidQuery& query_;
  const IntervalPaths& paths_;
  const double delta_;
  const Interval delta2_;
  const double t_max_, toi_width_;
  RigidExactStage& exact_;
  const bool extended_in_range_;
  bool exact_used_ = false;
#if EXACTCCD_X87_INTERVAL
  std::optional<predicates::RigidPaths<X87Interval>> extended_paths_;
#endif
};

/// On a piece where polynomial k alone decides: k monotone over it (its derivative of certain
/// sign) makes `within` false up to k's only root and true after it.
template <template <class, class> class Separation>
typename Search<Separation>::PieceVerdict Search<Separation>::decide_piece(
    std::uint32_t set, PieceValues& v, FilterOutcome* out) {
  const double lo = v.piece().inf(), hi = v.piece().sup();
  double first_lo = INFINITY, first_hi = INFINITY;  // the earliest root's bracket so far
  for (int k = 0; k < kCount; ++k) {
    if (!((set >> k) & 1)) continue;
    if (!certainly_monotone(k, v)) return PieceVerdict::undecided;
    const int c = Kind::condition(k);
    const int at_lo = fine_sign(k, lo);
    if (at_lo == 0 || at_lo == c) {  // within at lo: the first instant only at s = 0
      if (lo != 0.0) return PieceVerdict::undecided;
      *out = contact(0.0, 0.0, exact_used_);
      return PieceVerdict::contact;
    }
    const int at_hi = fine_sign(k, hi);
    if (at_hi == -c) continue;  // unmet at both ends: unmet throughout
    double root_lo = lo, root_hi = hi;
    if (at_hi != 0) tighten(k, &root_lo, &root_hi);
    else root_lo = hi;  // the root is hi itself
    // The earliest of the roots: [min lo, min hi] encloses it and, on tightest pairs and exact
    // roots of one grid of doubles, is again the tightest.
    first_lo = std::min(first_lo, root_lo);
    first_hi = std::min(first_hi, root_hi);
  }
  if (first_hi == INFINITY) return PieceVerdict::excluded;  // no condition met on T
  *out = contact(first_lo, first_hi, exact_used_);
  return PieceVerdict::contact;
}

/// Narrows lo < r < hi (k unmet at lo, met strictly at hi, one simple root r) to the reported
/// TOI: Newton's method on the interval midpoints chooses probes, each probe's certified sign
/// moves an end; where the intervals cannot tell (close to r), a walk outwards in growing steps
/// and a bisection in bit order with exact signs.
template <template <class, class> class Separation>
void Search<Separation>::tighten(int k, double* lo, double* hi) {
  const int c = Kind::condition(k);
  auto classify = [&](double t, int s) {
    if (s == 0) *lo = *hi = t;
    else (s == c ? *hi : *lo) = t;
  };
  double t = *lo + (*hi - *lo) / 2;
  bool unknown = false;
  for (int n = 0; n < 12 && !toi_final(*lo, *hi); ++n) {
    if (!(t > *lo && t < *hi) && !predicates::middle_double(*lo, *hi, &t)) break;
    const SlopeJet jet = jet_of(k, position_jets<SlopeJet>(paths_, Interval(t)));
    const CertifiedSign s = certified_sign(jet.v);
    if (s == CertifiedSign::uncertain) {
      unknown = true;
      break;
    }
    classify(t, static_cast<int>(s));
    const double v = jet.v.inf() / 2 + jet.v.sup() / 2;
    const double d = jet.d.inf() / 2 + jet.d.sup() / 2;
    t = t - v / d;  // a guess only: NaN or outside the bracket falls back to the middle
  }
  if (unknown && !toi_final(*lo, *hi)) {  // walk out of the band where intervals cannot tell
    for (int direction : {+1, -1}) {
      std::uint64_t step = 1;
      for (int n = 0; n < 24 && !toi_final(*lo, *hi); ++n, step *= 2) {
        const std::uint64_t from = order_bits(t), lo_bits = order_bits(*lo),
                            hi_bits = order_bits(*hi);
        const std::uint64_t x = direction > 0 ? std::min(from + step, hi_bits - 1)
                                              : std::max(from - std::min(step, from), lo_bits + 1);
        if (x <= lo_bits || x >= hi_bits) break;
        const CertifiedSign s = certified_sign(value_at(k, double_of(x)));
        if (s == CertifiedSign::uncertain) continue;
        classify(double_of(x), static_cast<int>(s));
        break;
      }
    }
  }
  double mid;
  while (!toi_final(*lo, *hi) && predicates::middle_double(*lo, *hi, &mid))
    classify(mid, fine_sign(k, mid));
}

template <template <class, class> class Separation>
FilterOutcome Search<Separation>::run() {
  const Boxes at_zero = rigid::positions_over(paths_, Interval(0.0));
  PieceValues at_start(*this, Interval(0.0), at_zero, false);
  if (surely_within(at_start))
    return contact(0.0, 0.0, false);
  // Conservative advancement clears [0, start]; the pieces then search [start, t_max] window by
  // window, each twice as long as the one before, from a few times the last advance: the
  // contact is usually close to start, and a window its size needs no deep descent to it.
  double start = 0.0, last_step = 0.0;
  if (advance(&start, &last_step)) {
    FilterOutcome r;
    r.verdict = FilterOutcome::Verdict::no_contact;
    return r;
  }
  struct Piece {
    double u0, u1;
    int depth;
  };
  int pieces = 0;
  double width = std::max(8 * last_step, kFirstWindow * t_max_);
  for (double from = start; from < t_max_; width *= 2) {
    const double to = std::min((Interval(from) + Interval(width)).sup(), t_max_);
    const Interval span = Interval(to) - Interval(from);
    Piece stack[kMaxDepth + 2];
    int top = 0;
    stack[top++] = Piece{0.0, 1.0, 0};
    while (top > 0) {
      const Piece piece = stack[--top];
      // Rounded outwards, then cut to [0, t_max]: nothing beyond t_max may be reported.
      const Interval wide = Interval(from) + span * Interval(piece.u0, piece.u1);
      const Interval T(std::max(wide.inf(), 0.0), std::min(wide.sup(), t_max_));
      const Boxes x = rigid::positions_over(paths_, T);
      if (rigid::boxes_apart(x, paths_.first_side_count, delta_)) continue;
      const bool narrow = (T.sup() - T.inf()) <= kNarrow * t_max_;
      PieceValues v(*this, T, x, narrow);
      // Within delta implies polynomial 0 <= 0 (the distance to the plane, or between the
      // lines, is at most the distance to the triangle, or between the segments).
      if (certain_strict_sign(v[0]) > 0 || !possibly_within(v)) continue;
      const std::uint32_t set = narrow ? deciding_set(v) : 0;
      if (set != 0) {
        FilterOutcome out;
        switch (decide_piece(set, v, &out)) {
          case PieceVerdict::excluded: continue;
          case PieceVerdict::contact: return out;
          case PieceVerdict::undecided: break;
        }
      }
      if (piece.depth == kMaxDepth || ++pieces > kMaxPieces) {
        FilterOutcome r;  // uncertain: the exact path searches from the piece on
        r.cleared_until = T.inf();
        r.exact_used = exact_used_;
        return r;
      }
      const double mid = (piece.u0 + piece.u1) / 2;  // dyadic: exact
      stack[top++] = Piece{mid, piece.u1, piece.depth + 1};
      stack[top++] = Piece{piece.u0, mid, piece.depth + 1};
    }
    from = to;  // the window is cleared, its end included (closed pieces)
  }
  FilterOutcome r;
  r.verdict = FilterOutcome::Verdict::no_contact;
  r.exact_used = exact_used_;
  return r;
}

/// Conservative advancement: at an instant s not within delta by a certified distance lower
/// bound L > delta, no vertex moves faster than V over [s, t_max] (V bounds the sum of both
/// sides' fastest vertex, and the distance between the primitives changes no faster), so
/// nothing comes within delta before s + (L - delta) / V. Moves *start to the last instant
/// verified so (never within on [0, *start]); true when that clears all of [0, t_max].
template <template <class, class> class Separation>
bool Search<Separation>::advance(double* start, double* last_step) const {
  double s = 0.0;
  for (int step = 0; step < kMaxAdvances; ++step) {
    const double L = distance_lower_bound(rigid::positions_over(paths_, Interval(s)));
    if (!(L > delta_)) return false;
    *start = s;
    if (s == t_max_) return true;
    const double V = speed_bound(Interval(s, t_max_));
    if (!(V < INFINITY)) return false;
    if (V == 0) return true;  // nothing moves: the distance stays above delta
    const double length = ((Interval(L) - Interval(delta_)) / Interval(V)).inf();
    const double next = (Interval(s) + Interval(length)).inf();  // rounded down: inside the step
    if (next > t_max_) return true;
    // Slow progress: leave the rest to the pieces.
    *last_step = (Interval(next) - Interval(s)).sup();
    if (!(next > s) || *last_step < kSlowAdvance * t_max_) return false;
    s = next;
  }
  return false;
}
/// delta scaled with the query by 2^k, when that loses no bit (else the query stays unscaled).
bool scaled_exactly(double delta, int k, double* out) {
  *out = std::ldexp(delta, k);
  return std::isfinite(*out) && *out > 0 && std::ldexp(*out, -k) == delta;
}

}  // namespace

FilterOutcome rigid_separation_filter(const DoubleRigidQuery& query, const CcdOptions& options,
                                          RigidExactStage& exact) {
  const RoundingGuard upward;
  int k = rigid::normalising_exponent(query);
  double delta = options.min_separation;
  if (k != 0 && !scaled_exactly(options.min_separation, k, &delta)) {
    k = 0;
    delta = options.min_separation;
  }
  const DoubleRigidQuery q = k == 0 ? query : rigid::scaled(query, k);
  const IntervalPaths paths = rigid::interval_paths(q);
  if (rigid::boxes_apart(rigid::positions_over(paths, Interval(0.0, options.t_max)),
                         paths.first_side_count, delta)) {
    FilterOutcome r;
    r.verdict = FilterOutcome::Verdict::no_contact;
    r.culled = true;
    return r;
  }
  if (q.type == QueryType::vertex_face)
    return Search<predicates::VertexFaceSeparation>(q, paths, delta, options, exact).run();
  return Search<predicates::EdgeEdgeSeparation>(q, paths, delta, options, exact).run();
}

}  // namespace exactccd::filters
