// PROOF: proofs/min_separation.md#rigid-separation-filter
#include "filters/rigid_separation_filter.hpp"

#include <array>
#include <cmath>
#include <cstdint>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/separation.hpp"
#include "filters/rigid_paths_in_intervals.hpp"

namespace exactccd::filters {

namespace {

using predicates::double_of;
using predicates::FixedPoly;
using predicates::order_bits;
using predicates::Vec3;
using rigid::Boxes;
using rigid::IntervalPaths;

/// A number and its derivative in s, both enclosed (forward differentiation over intervals).
struct Jet {
  Interval v{0.0}, d{0.0};
};
Jet operator+(const Jet& a, const Jet& b) { return {a.v + b.v, a.d + b.d}; }
Jet operator-(const Jet& a, const Jet& b) { return {a.v - b.v, a.d - b.d}; }
Jet operator-(const Jet& a) { return {-a.v, -a.d}; }
Jet operator*(const Jet& a, const Jet& b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }

template <class NT>
using ConstantPoint = Vec3<FixedPoly<NT, 0>>;
template <class NT>
using Positions = std::array<Vec3<NT>, 4>;

/// Positions and their derivatives over T: x = X / w, x' = (X' w - X w') / w^2 (w >= 1).
Positions<Jet> position_jets(const IntervalPaths& paths, const Interval& T) {
  Interval w[2], dw[2];
  for (int side = 0; side < 2; ++side) {
    w[side] = predicates::evaluate(paths.denominator[side], T);
    dw[side] = predicates::evaluate(predicates::derivative(paths.denominator[side]), T);
  }
  Positions<Jet> x;
  for (int i = 0; i < 4; ++i) {
    const int side = i < paths.first_side_count ? 0 : 1;
    const auto& X = paths.numerator[i];
    auto jet = [&](const FixedPoly<Interval, 3>& c) {
      const Interval v = predicates::evaluate(c, T);
      const Interval dv = predicates::evaluate(predicates::derivative(c), T);
      return Jet{v / w[side], (dv * w[side] - v * dw[side]) / (w[side] * w[side])};
    };
    x[i] = {jet(X.x), jet(X.y), jet(X.z)};
  }
  return x;
}

/// Some axis separates the two primitives' boxes by more than delta.
bool apart_by_more_than(const Boxes& x, int first, double delta) {
  for (int k = 0; k < 3; ++k) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 4; ++i) {
      const int side = i < first ? 0 : 1;
      const double l = x[i][k].inf(), h = x[i][k].sup();
      if (!(l <= h)) return false;  // NaN (overflow) never separates
      lo[side] = std::min(lo[side], l);
      hi[side] = std::max(hi[side], h);
    }
    if ((Interval(lo[1]) - Interval(hi[0])).inf() > delta ||
        (Interval(lo[0]) - Interval(hi[1])).inf() > delta)
      return true;
  }
  return false;
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
  Search(const IntervalPaths& paths, double delta, const CcdOptions& options,
         RigidExactSigns& exact)
      : paths_(paths), delta_(delta), delta2_(Interval(delta) * Interval(delta)),
        t_max_(options.t_max), toi_width_(options.toi_width), exact_(exact) {}

  SeparationOutcome run();

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
  /// Enclosures over T of every region polynomial: the box evaluation intersected with the
  /// mean-value form f(m) + f'(T) (T - m), which narrows quadratically with T.
  Values values_over(const Interval& T, const Boxes& x) const {
    Values v;
    region_values<Interval>(x, delta2_, v.data());
    if (T.inf() == T.sup()) return v;
    const double m = T.inf() + (T.sup() - T.inf()) / 2;  // rounded upwards: inside T
    Jet jets[kCount];
    region_values<Jet>(position_jets(paths_, T), Jet{delta2_, Interval(0.0)}, jets);
    Interval at_m[kCount];
    region_values<Interval>(rigid::positions_over(paths_, Interval(m)), delta2_, at_m);
    const Interval offset = T - Interval(m);
    for (int k = 0; k < kCount; ++k) {
      const Interval mean_value = at_m[k] + jets[k].d * offset;
      const double lo = std::max(v[k].inf(), mean_value.inf());
      const double hi = std::min(v[k].sup(), mean_value.sup());
      if (lo <= hi) v[k] = Interval(lo, hi);  // both enclose f(T): they meet (NaN: keep the box)
    }
    return v;
  }
  Interval value_at(int k, double t) const {
    Interval v[kCount];
    region_values<Interval>(rigid::positions_over(paths_, Interval(t)), delta2_, v, k);
    return v[k];
  }
  /// Within delta somewhere the signs allow: uncertain conditions taken as met.
  static bool possibly_within(const Values& v) {
    return Kind::within([&v](int k) {
      const CertifiedSign s = certified_sign(v[k]);
      if (s == CertifiedSign::uncertain) return k < kNonStrict ? 0 : 1;
      return static_cast<int>(s);
    });
  }
  /// Within delta with every condition it uses met strictly: then also at nearby instants.
  static bool surely_within(const Values& v) {
    return Kind::within([&v](int k) {
      const int s = certain_strict_sign(v[k]);
      if (k >= kNonStrict) return s > 0 ? 1 : 0;
      const int c = Kind::condition(k);
      return s == c ? c : -c;
    });
  }
  /// The one non-strict polynomial whose condition alone decides `within` over the piece (for
  /// every sign the other uncertain ones may take, within when it is met and not otherwise),
  /// or -1.
  static int deciding_polynomial(const Values& v) {
    constexpr int kMaxUncertain = 4;
    int uncertain[kMaxUncertain], count = 0;
    for (int i = 0; i < kCount; ++i) {
      if (certified_sign(v[i]) != CertifiedSign::uncertain) continue;
      if (count == kMaxUncertain) return -1;
      uncertain[count++] = i;
    }
    for (int j = 0; j < count; ++j) {
      const int k = uncertain[j];
      if (k >= kNonStrict) continue;
      const int c = Kind::condition(k);
      bool decides = true;
      int combinations = 1;
      for (int i = 1; i < count; ++i) combinations *= 3;
      for (int code = 0; code < combinations && decides; ++code) {
        int assigned[kCount];  // the others' signs: code's base-3 digits - 1
        for (int i = 0, rest = code; i < count; ++i) {
          if (i == j) continue;
          assigned[uncertain[i]] = rest % 3 - 1;
          rest /= 3;
        }
        auto within_when = [&](int sign_k) {
          return Kind::within([&](int i) {
            if (i == k) return sign_k;
            const CertifiedSign s = certified_sign(v[i]);
            return s == CertifiedSign::uncertain ? assigned[i] : static_cast<int>(s);
          });
        };
        decides = within_when(c) && !within_when(-c);
      }
      if (decides) return k;
    }
    return -1;
  }
  /// The exact sign of polynomial k at the double t: intervals first, then exact.
  int fine_sign(int k, double t) {
    const CertifiedSign s = certified_sign(value_at(k, t));
    if (s != CertifiedSign::uncertain) return static_cast<int>(s);
    exact_used_ = true;
    return exact_.region_sign_at(k, t);
  }
  bool toi_final(double lo, double hi) const {
    return order_bits(hi) - order_bits(lo) < 2 ||
           (toi_width_ > 0 && (Interval(hi) - Interval(lo)).sup() <= toi_width_);
  }
  enum class PieceVerdict : std::uint8_t { excluded, contact, undecided };
  PieceVerdict decide_piece(int k, const Interval& T, SeparationOutcome* out);
  void tighten(int k, double* lo, double* hi);

  static SeparationOutcome contact(double lo, double hi, bool exact_used) {
    SeparationOutcome r;
    r.verdict = SeparationVerdict::contact;
    r.toi_lo = lo;
    r.toi_hi = hi;
    r.exact_used = exact_used;
    return r;
  }

  const IntervalPaths& paths_;
  const double delta_;
  const Interval delta2_;
  const double t_max_, toi_width_;
  RigidExactSigns& exact_;
  bool exact_used_ = false;
};

/// On a piece where polynomial k alone decides: k monotone over it (its derivative of certain
/// sign) makes `within` false up to k's only root and true after it.
template <template <class, class> class Separation>
typename Search<Separation>::PieceVerdict Search<Separation>::decide_piece(
    int k, const Interval& T, SeparationOutcome* out) {
  Jet jets[kCount];
  region_values<Jet>(position_jets(paths_, T), Jet{delta2_, Interval(0.0)}, jets, k);
  if (certain_strict_sign(jets[k].d) == 0) return PieceVerdict::undecided;
  const int c = Kind::condition(k);
  double lo = T.inf(), hi = T.sup();
  const int at_lo = fine_sign(k, lo);
  if (at_lo == 0 || at_lo == c) {  // within at lo: the first instant only at s = 0
    if (lo != 0.0) return PieceVerdict::undecided;
    *out = contact(0.0, 0.0, exact_used_);
    return PieceVerdict::contact;
  }
  const int at_hi = fine_sign(k, hi);
  if (at_hi == -c) return PieceVerdict::excluded;  // unmet at both ends: unmet throughout
  if (at_hi != 0) tighten(k, &lo, &hi);
  else lo = hi;  // the root is hi itself
  *out = contact(lo, hi, exact_used_);
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
    Jet jets[kCount];
    Positions<Jet> x = position_jets(paths_, Interval(t));
    region_values<Jet>(x, Jet{delta2_, Interval(0.0)}, jets, k);
    const CertifiedSign s = certified_sign(jets[k].v);
    if (s == CertifiedSign::uncertain) {
      unknown = true;
      break;
    }
    classify(t, static_cast<int>(s));
    const double v = jets[k].v.inf() / 2 + jets[k].v.sup() / 2;
    const double d = jets[k].d.inf() / 2 + jets[k].d.sup() / 2;
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
SeparationOutcome Search<Separation>::run() {
  if (surely_within(values_over(Interval(0.0), rigid::positions_over(paths_, Interval(0.0)))))
    return contact(0.0, 0.0, false);
  struct Piece {
    double u0, u1;
    int depth;
  };
  Piece stack[kMaxDepth + 2];
  int top = 0, pieces = 0;
  stack[top++] = Piece{0.0, 1.0, 0};
  while (top > 0) {
    const Piece piece = stack[--top];
    const Interval T = Interval(t_max_) * Interval(piece.u0, piece.u1);
    const Boxes x = rigid::positions_over(paths_, T);
    if (apart_by_more_than(x, paths_.first_side_count, delta_)) continue;
    const Values v = values_over(T, x);
    if (!possibly_within(v)) continue;
    const int k = deciding_polynomial(v);
    if (k >= 0) {
      SeparationOutcome out;
      switch (decide_piece(k, T, &out)) {
        case PieceVerdict::excluded: continue;
        case PieceVerdict::contact: return out;
        case PieceVerdict::undecided: break;
      }
    }
    if (piece.depth == kMaxDepth || ++pieces > kMaxPieces) {
      SeparationOutcome r;  // uncertain: the exact path searches from the piece on
      r.cleared_until = T.inf();
      r.exact_used = exact_used_;
      return r;
    }
    const double mid = (piece.u0 + piece.u1) / 2;  // dyadic: exact
    stack[top++] = Piece{mid, piece.u1, piece.depth + 1};
    stack[top++] = Piece{piece.u0, mid, piece.depth + 1};
  }
  SeparationOutcome r;
  r.verdict = SeparationVerdict::never_within;
  r.exact_used = exact_used_;
  return r;
}

/// delta scaled with the query by 2^k, when that loses no bit (else the query stays unscaled).
bool scaled_exactly(double delta, int k, double* out) {
  *out = std::ldexp(delta, k);
  return std::isfinite(*out) && *out > 0 && std::ldexp(*out, -k) == delta;
}

}  // namespace

SeparationOutcome rigid_separation_filter(const DoubleRigidQuery& query, const CcdOptions& options,
                                          RigidExactSigns& exact) {
  const RoundingGuard upward;
  int k = rigid::normalising_exponent(query);
  double delta = options.min_separation;
  if (k != 0 && !scaled_exactly(options.min_separation, k, &delta)) {
    k = 0;
    delta = options.min_separation;
  }
  const DoubleRigidQuery q = k == 0 ? query : rigid::scaled(query, k);
  const IntervalPaths paths = rigid::interval_paths(q);
  if (apart_by_more_than(rigid::positions_over(paths, Interval(0.0, options.t_max)),
                         paths.first_side_count, delta)) {
    SeparationOutcome r;
    r.verdict = SeparationVerdict::never_within;
    r.culled = true;
    return r;
  }
  if (q.type == QueryType::vertex_face)
    return Search<predicates::VertexFaceSeparation>(paths, delta, options, exact).run();
  return Search<predicates::EdgeEdgeSeparation>(paths, delta, options, exact).run();
}

}  // namespace exactccd::filters
