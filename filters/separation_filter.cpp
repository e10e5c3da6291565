// PROOF: proofs/min_separation.md#filters
#include "filters/separation_filter.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/separation.hpp"
#include "exact/polynomial.hpp"
#include "filters/interval.hpp"

namespace exactccd::filters {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;

/// hi1 + delta < lo2 or hi2 + delta < lo1 on some axis, the sums rounded upwards: a certain
/// gap wider than delta. PROOF: proofs/min_separation.md#culling-with-delta
template <std::size_t N1, std::size_t N2>
bool boxes_apart(const std::array<const Eigen::Vector3d*, N1>& first,
                 const std::array<const Eigen::Vector3d*, N2>& second, double delta) {
  const RoundingGuard upward;
  for (int k = 0; k < 3; ++k) {
    double lo1 = first[0]->coeff(k), hi1 = lo1, lo2 = second[0]->coeff(k), hi2 = lo2;
    for (const auto* v : first) {
      lo1 = std::min(lo1, v->coeff(k));
      hi1 = std::max(hi1, v->coeff(k));
    }
    for (const auto* v : second) {
      lo2 = std::min(lo2, v->coeff(k));
      hi2 = std::max(hi2, v->coeff(k));
    }
    if (hi1 + delta < lo2 || hi2 + delta < lo1) return true;
  }
  return false;
}

/// A vertex's linear motion: x(T) = x0 + T (x1 - x0) enclosed over a time interval T.
struct MovingVertex {
  std::array<Interval, 3> x0, dx;
  MovingVertex(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    for (int k = 0; k < 3; ++k) {
      x0[k] = Interval(a[k]);
      dx[k] = Interval(b[k]) - Interval(a[k]);
    }
  }
  std::array<Interval, 3> at(const Interval& t) const {
    return {x0[0] + t * dx[0], x0[1] + t * dx[1], x0[2] + t * dx[2]};
  }
  /// Midpoint position at the double t, in plain arithmetic (a direction guess only).
  Eigen::Vector3d guess_at(double t) const {
    Eigen::Vector3d r;
    for (int k = 0; k < 3; ++k) r[k] = x0[k].inf() + t * dx[k].inf();
    return r;
  }
};

template <std::size_t N>
using Positions = std::array<std::array<Interval, 3>, N>;

/// Lower bound of min over the second set minus max over the first, along s.
template <std::size_t N1, std::size_t N2>
double support_gap(const Eigen::Vector3d& s, const Positions<N1>& first,
                   const Positions<N2>& second) {
  double max1 = -std::numeric_limits<double>::infinity();
  for (const auto& x : first) {
    const Interval proj = Interval(s[0]) * x[0] + Interval(s[1]) * x[1] + Interval(s[2]) * x[2];
    max1 = std::max(max1, proj.sup());
  }
  double min2 = std::numeric_limits<double>::infinity();
  for (const auto& x : second) {
    const Interval proj = Interval(s[0]) * x[0] + Interval(s[1]) * x[1] + Interval(s[2]) * x[2];
    min2 = std::min(min2, proj.inf());
  }
  return (Interval(min2) - Interval(max1)).inf();
}

/// Certainly more than delta apart along the direction s (either orientation): the convex
/// hulls of the two vertex sets are separated by the slab of width gap / |s| > delta.
/// PROOF: proofs/min_separation.md#separating-directions
template <std::size_t N1, std::size_t N2>
bool apart_along(const Eigen::Vector3d& s, const Positions<N1>& first,
                 const Positions<N2>& second, const Interval& delta2) {
  if (!s.allFinite() || s.isZero(0.0)) return false;
  const Interval norm2 = Interval(s[0]) * s[0] + Interval(s[1]) * s[1] + Interval(s[2]) * s[2];
  for (const double orientation : {1.0, -1.0}) {
    const double gap = support_gap<N1, N2>(orientation * s, first, second);
    if (gap > 0 && (Interval(gap) * gap).inf() > (delta2 * norm2).sup()) return true;
  }
  return false;
}

/// Axis-aligned gaps wider than delta over T.
template <std::size_t N1, std::size_t N2>
bool apart_on_an_axis(const Positions<N1>& first, const Positions<N2>& second, double delta) {
  for (int k = 0; k < 3; ++k) {
    double lo1 = first[0][k].inf(), hi1 = first[0][k].sup();
    for (const auto& x : first) {
      lo1 = std::min(lo1, x[k].inf());
      hi1 = std::max(hi1, x[k].sup());
    }
    double lo2 = second[0][k].inf(), hi2 = second[0][k].sup();
    for (const auto& x : second) {
      lo2 = std::min(lo2, x[k].inf());
      hi2 = std::max(hi2, x[k].sup());
    }
    if ((Interval(lo2) - hi1).inf() > delta || (Interval(lo1) - hi2).inf() > delta) return true;
  }
  return false;
}

/// The closest point to p on the closed triangle (a, b, c) in plain arithmetic (Ericson,
/// Real-Time Collision Detection, 5.1.5): a direction guess only, never a decision.
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// The closest points of the closed segments [p1, q1] and [p2, q2] in plain arithmetic
/// (Ericson 5.1.9): a direction guess only.
std::pair<Eigen::Vector3d, Eigen::Vector3d> closest_on_segments(
    const Eigen::Vector3d& p1, const Eigen::Vector3d& q1, const Eigen::Vector3d& p2,
    const Eigen::Vector3d& q2) {
  const Eigen::Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) return {p1, p2};
  if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p1 + d1 * s, p2 + d2 * t};
}

/// Vertex-face: the positions over T and the direction guesses at T's middle.
struct VertexFaceMotion {
  std::array<MovingVertex, 4> v;  // p, a, b, c
  bool apart_over(const Interval& T, const Interval& delta2, double delta) const {
    const Positions<1> first{v[0].at(T)};
    const Positions<3> second{v[1].at(T), v[2].at(T), v[3].at(T)};
    if (apart_on_an_axis<1, 3>(first, second, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    const Eigen::Vector3d p = v[0].guess_at(mid), a = v[1].guess_at(mid), b = v[2].guess_at(mid),
                          c = v[3].guess_at(mid);
    if (apart_along<1, 3>(p - closest_on_triangle(p, a, b, c), first, second, delta2))
      return true;
    return apart_along<1, 3>((b - a).cross(c - a), first, second, delta2);
  }
};

/// Edge-edge: the positions over T and the direction guesses at T's middle.
struct EdgeEdgeMotion {
  std::array<MovingVertex, 4> v;  // a0, a1, b0, b1
  bool apart_over(const Interval& T, const Interval& delta2, double delta) const {
    const Positions<2> first{v[0].at(T), v[1].at(T)};
    const Positions<2> second{v[2].at(T), v[3].at(T)};
    if (apart_on_an_axis<2, 2>(first, second, delta)) return true;
    const double mid = 0.5 * (T.inf() + T.sup());
    const Eigen::Vector3d a0 = v[0].guess_at(mid), a1 = v[1].guess_at(mid),
                          b0 = v[2].guess_at(mid), b1 = v[3].guess_at(mid);
    const auto [ca, cb] = closest_on_segments(a0, a1, b0, b1);
    if (apart_along<2, 2>(ca - cb, second, first, delta2)) return true;
    return apart_along<2, 2>((a1 - a0).cross(b1 - b0), second, first, delta2);
  }
};

/// The sign of a polynomial at one instant (its constant coefficient, for positions at that
/// instant), certified or not: an uncertain sign sets the flag and reads as 0.
struct SignAtZero {
  bool* uncertain;
  template <int D>
  int operator()(const FixedPoly<Interval, D>& g) const {
    const CertifiedSign s = certified_sign(g.c[0]);
    if (s == CertifiedSign::uncertain) {
      *uncertain = true;
      return 0;
    }
    return static_cast<int>(s);
  }
};

predicates::MovingPoint<Interval> moving(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  return predicates::linear_motion(Vec3<Interval>{x0.x(), x0.y(), x0.z()},
                                   Vec3<Interval>{x1.x(), x1.y(), x1.z()});
}

using Position = Vec3<FixedPoly<Interval, 0>>;

/// The enclosure of a vertex's position at the double t.
Position position_at(const MovingVertex& v, double t) {
  const auto x = v.at(Interval(t));
  return {FixedPoly<Interval, 0>{{x[0]}}, FixedPoly<Interval, 0>{{x[1]}},
          FixedPoly<Interval, 0>{{x[2]}}};
}

/// Every polynomial the instant predicate reads (the non-strict ones first, in
/// for_each_polynomial's order, then the strict ones), with interval coefficients, padded to
/// degree 6.
struct PolynomialTable {
  static constexpr int kMax = 32;
  std::array<FixedPoly<Interval, 6>, kMax> poly;
  std::array<bool, kMax> strict{};
  int count = 0;

  template <int D>
  void add(const FixedPoly<Interval, D>& g, bool is_strict) {
    static_assert(D <= 6, "the region polynomials have degree at most 6");
    FixedPoly<Interval, 6>& p = poly[count];
    for (int i = 0; i <= 6; ++i) p.c[i] = i <= D ? g.c[i] : Interval(0);
    strict[count++] = is_strict;
  }
  template <class Separation>
  explicit PolynomialTable(const Separation& s) {
    s.for_each_polynomial([this](const auto& g) { add(g, false); });
    s.for_each_strict_polynomial([this](const auto& g) { add(g, true); });
  }
};

/// An enclosure of g over [lo, hi] in centred form: g(m + s) = sum_i c_i s^i (an interval
/// Taylor shift to a double m inside), |s| <= h; much tighter than Horner over [lo, hi]
/// where g is small and flat. PROOF: proofs/min_separation.md#interval-search
Interval enclosure_over(const FixedPoly<Interval, 6>& g, double lo, double hi) {
  const double m = lo + 0.5 * (hi - lo);  // inside [lo, hi] (rounded upwards, at most hi)
  const double h = std::max(m - lo, hi - m);  // rounded upwards: >= every |t - m|
  // Taylor shift by m: repeated synthetic division, exact in interval arithmetic's sense.
  std::array<Interval, 7> c = g.c;
  const Interval mi(m);
  for (int k = 0; k < 6; ++k)
    for (int i = 5; i >= k; --i) c[i] = c[i] + mi * c[i + 1];
  Interval r = c[0];
  double hk = 1.0;
  for (int i = 1; i <= 6; ++i) {
    hk *= h;  // rounded upwards
    const Interval power = i % 2 ? Interval(-hk, hk) : Interval(0.0, hk);
    r = r + c[i] * power;
  }
  return r;
}

/// Optimistic signs over [lo, hi]: a polynomial's certain sign when its enclosure excludes 0
/// (or is exactly 0), else 0 for the non-strict conditions (which 0 satisfies) and "positive"
/// for the strict ones. Every condition that holds somewhere in [lo, hi] reads as true.
struct OptimisticSignOver {
  double lo, hi;
  template <int D>
  static FixedPoly<Interval, 6> padded(const FixedPoly<Interval, D>& g) {
    FixedPoly<Interval, 6> p;
    for (int i = 0; i <= 6; ++i) p.c[i] = i <= D ? g.c[i] : Interval(0);
    return p;
  }
  template <int D>
  int operator()(const FixedPoly<Interval, D>& g) const {
    const CertifiedSign s = certified_sign(enclosure_over(padded(g), lo, hi));
    return s == CertifiedSign::uncertain ? 0 : static_cast<int>(s);
  }
  template <int D>
  bool positive(const FixedPoly<Interval, D>& g) const {
    return enclosure_over(padded(g), lo, hi).sup() > 0;
  }
};

/// Depth to which separating directions are tried, and depth of the whole subdivision.
constexpr int kDirectionDepth = 6;
constexpr int kMaxDepth = 40;

/// The search for the first time within delta over [0, t_max]: depth first, earliest half
/// first. Every piece before the current one is certainly never within delta (`cleared` is
/// its end). A piece is excluded by separating directions (depth <= kDirectionDepth) or by the
/// signs of the region polynomials over it (deeper); a piece over which all signs are certain
/// but one simple, monotone polynomial's is the first contact's, if the instant predicate
/// certainly holds at its end. PROOF: proofs/min_separation.md#interval-search
/// The k-th polynomial of PolynomialTable's order over the exact rationals (built on demand,
/// only where interval signs cannot tighten a TOI).
using ExactPolynomial = std::function<exact::Polynomial(int)>;

template <class Motion, class Separation, class PointSeparation>
class FirstWithinSearch {
 public:
  enum class Step : std::uint8_t { excluded, found, give_up };

  FirstWithinSearch(const Motion& m, const Separation& moving_separation,
                    const PointSeparation& at, const ExactPolynomial& exact_polynomial,
                    const CcdOptions& options)
      : m_(m), moving_(moving_separation), at_(at), options_(options),
        delta2_(Interval(options.min_separation) * options.min_separation),
        exact_polynomial_(exact_polynomial) {}

  SeparationOutcome run() {
    SeparationOutcome out;
    const Step s = search(0.0, options_.t_max, 0);
    out.cleared_until = cleared_;
    if (s == Step::excluded) {
      out.verdict = SeparationVerdict::never_within;
    } else if (s == Step::found) {
      out.verdict = SeparationVerdict::contact;
      out.exact_used = exact_used_;
      out.toi_lo = toi_lo_;
      out.toi_hi = toi_hi_;
    }
    return out;
  }

 private:
  Step search(double lo, double hi, int depth) {
    if (depth <= kDirectionDepth &&
        m_.apart_over(Interval(lo, hi), delta2_, options_.min_separation)) {
      cleared_ = hi;
      return Step::excluded;
    }
    if (depth >= kDirectionDepth) {
      const Step s = analyse(lo, hi);
      if (s != Step::give_up || undecided_ == false) return s;
    }
    const double mid = lo + 0.5 * (hi - lo);  // rounded upwards: inside (lo, hi] or hi
    if (depth == kMaxDepth || !(mid > lo && mid < hi)) return Step::give_up;
    const Step left = search(lo, mid, depth + 1);
    if (left != Step::excluded) return left;
    return search(mid, hi, depth + 1);
  }

  /// Certain within delta at the double t (every sign read certain): +1; certainly not: -1;
  /// 0 when some sign was uncertain.
  int within_at(double t) const {
    bool uncertain = false;
    const bool within = at_(t).within_at(SignAtZero{&uncertain});
    return uncertain ? 0 : (within ? 1 : -1);
  }

  /// The signs of every region polynomial over [lo, hi]; sets undecided_ when splitting the
  /// piece may decide it.
  Step analyse(double lo, double hi) {
    undecided_ = false;
    if (!table_) table_.emplace(moving_);
    int uncertain = 0, which = -1;
    for (int k = 0; k < table_->count; ++k) {
      if (certified_sign(enclosure_over(table_->poly[k], lo, hi)) == CertifiedSign::uncertain) {
        ++uncertain;
        which = k;
      }
    }
    // Not within at lo: lo is cleared, or lo = 0 is tested.
    if (lo == 0.0 && cleared_ == 0.0) {
      const int at_zero = within_at(0.0);
      if (at_zero == 0) return Step::give_up;
      if (at_zero > 0) {
        toi_lo_ = toi_hi_ = 0.0;
        return Step::found;
      }
    }
    if (uncertain == 0) {  // every sign constant over the piece: not within anywhere in it
      cleared_ = hi;
      return Step::excluded;
    }
    if (uncertain > 1 || table_->strict[which]) {
      // Within at no t of the piece even with every uncertain condition read as true
      // (within_at is monotone in the conditions): excluded.
      const OptimisticSignOver optimistic{lo, hi};
      if (!moving_.within_at(optimistic,
                             [&optimistic](const auto& q) { return optimistic.positive(q); })) {
        cleared_ = hi;
        return Step::excluded;
      }
      undecided_ = true;
      return Step::give_up;
    }
    const FixedPoly<Interval, 6>& g = table_->poly[which];
    FixedPoly<Interval, 6> slope_poly{};
    for (int i = 1; i <= 6; ++i) slope_poly.c[i - 1] = g.c[i] * Interval(i);
    slope_poly.c[6] = Interval(0);  // Interval_nt default-constructs no value
    const CertifiedSign slope = certified_sign(enclosure_over(slope_poly, lo, hi));
    const int s_lo = certain_strict_sign(predicates::evaluate(g, Interval(lo)));
    const int s_hi = certain_strict_sign(predicates::evaluate(g, Interval(hi)));
    if (slope == CertifiedSign::uncertain || slope == CertifiedSign::zero || s_lo == 0 ||
        s_hi == 0) {
      undecided_ = true;
      return Step::give_up;
    }
    if (s_lo == s_hi) {  // monotone, one sign at both ends: no root, as uncertain == 0
      cleared_ = hi;
      return Step::excluded;
    }
    // g has one simple root r in (lo, hi) and is the only sign that changes over the piece.
    // At r every condition reads as at the end where g's (non-strict) condition holds, so
    // the piece is within delta from r on when within at hi, and nowhere when not.
    const int at_hi = within_at(hi);
    if (at_hi == 0) return Step::give_up;
    if (at_hi < 0) {
      cleared_ = hi;
      return Step::excluded;
    }
    which_ = which;
    return tighten(g, lo, hi, s_lo);
  }

  /// The first contact is g's root r in (lo, hi), g(lo) of sign s_lo: bisection with
  /// certified signs of g to the tightest pair of doubles (or toi_width).
  Step tighten(const FixedPoly<Interval, 6>& g, double lo, double hi, int s_lo) {
    for (;;) {
      if (options_.toi_width > 0 && hi - lo <= options_.toi_width) break;  // rounded up
      double mid = 0;
      if (!predicates::middle_double(lo, hi, &mid)) break;
      CertifiedSign s = certified_sign(predicates::evaluate(g, Interval(mid)));
      if (s == CertifiedSign::uncertain) {  // near r: g's exact sign at the double mid
        if (!exact_g_) exact_g_.emplace(exact_polynomial_(which_));
        s = static_cast<CertifiedSign>(exact_g_->sign_at(exact::Rational(mid)));
        exact_used_ = true;
      }
      if (s == CertifiedSign::zero) {
        lo = hi = mid;
        break;
      }
      (static_cast<int>(s) == s_lo ? lo : hi) = mid;
    }
    toi_lo_ = lo;
    toi_hi_ = hi;
    return Step::found;
  }

  const Motion& m_;
  const Separation& moving_;
  const PointSeparation& at_;
  const CcdOptions& options_;
  const Interval delta2_;
  std::optional<PolynomialTable> table_;
  const ExactPolynomial& exact_polynomial_;
  std::optional<exact::Polynomial> exact_g_;
  int which_ = -1;
  bool exact_used_ = false;
  double cleared_ = 0.0;
  double toi_lo_ = 0.0, toi_hi_ = 0.0;
  bool undecided_ = false;
};

template <class Motion, class Separation, class PointSeparation>
SeparationOutcome first_within(const Motion& m, const Separation& s, const PointSeparation& at,
                               const ExactPolynomial& exact_polynomial,
                               const CcdOptions& options) {
  return FirstWithinSearch<Motion, Separation, PointSeparation>(m, s, at, exact_polynomial,
                                                               options)
      .run();
}

/// Polynomial k (PolynomialTable's order: non-strict, then strict) of a separation over the
/// exact rationals.
template <class Separation>
exact::Polynomial polynomial_number(const Separation& s, int k) {
  exact::Polynomial found;
  int index = 0;
  auto pick = [&](const auto& g) {
    if (index++ == k) found = exact::Polynomial(g);
  };
  s.for_each_polynomial(pick);
  s.for_each_strict_polynomial(pick);
  return found;
}

predicates::MovingPoint<exact::Rational> exact_moving(const Eigen::Vector3d& x0,
                                                      const Eigen::Vector3d& x1) {
  return predicates::linear_motion(
      Vec3<exact::Rational>{exact::Rational(x0.x()), exact::Rational(x0.y()),
                            exact::Rational(x0.z())},
      Vec3<exact::Rational>{exact::Rational(x1.x()), exact::Rational(x1.y()),
                            exact::Rational(x1.z())});
}

}  // namespace

bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta) {
  return boxes_apart<2, 6>({&q.p_t0, &q.p_t1},
                           {&q.a_t0, &q.b_t0, &q.c_t0, &q.a_t1, &q.b_t1, &q.c_t1}, delta);
}

bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta) {
  return boxes_apart<4, 4>({&q.ea0_t0, &q.ea1_t0, &q.ea0_t1, &q.ea1_t1},
                           {&q.eb0_t0, &q.eb1_t0, &q.eb0_t1, &q.eb1_t1}, delta);
}

SeparationOutcome vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options) {
  const RoundingGuard upward;
  const VertexFaceMotion m{{MovingVertex(q.p_t0, q.p_t1), MovingVertex(q.a_t0, q.a_t1),
                            MovingVertex(q.b_t0, q.b_t1), MovingVertex(q.c_t0, q.c_t1)}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto separation = predicates::vertex_face_separation(
      moving(q.p_t0, q.p_t1), moving(q.a_t0, q.a_t1), moving(q.b_t0, q.b_t1),
      moving(q.c_t0, q.c_t1), delta2);
  const auto at = [&m, &delta2](double t) {
    return predicates::vertex_face_separation(position_at(m.v[0], t), position_at(m.v[1], t),
                                              position_at(m.v[2], t), position_at(m.v[3], t),
                                              delta2);
  };
  const ExactPolynomial exact_polynomial = [&q, &options](int k) {
    const exact::Rational d(options.min_separation);
    return polynomial_number(
        predicates::vertex_face_separation(exact_moving(q.p_t0, q.p_t1),
                                           exact_moving(q.a_t0, q.a_t1),
                                           exact_moving(q.b_t0, q.b_t1),
                                           exact_moving(q.c_t0, q.c_t1), exact::Rational(d * d)),
        k);
  };
  return first_within(m, separation, at, exact_polynomial, options);
}

SeparationOutcome edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options) {
  const RoundingGuard upward;
  const EdgeEdgeMotion m{{MovingVertex(q.ea0_t0, q.ea0_t1), MovingVertex(q.ea1_t0, q.ea1_t1),
                          MovingVertex(q.eb0_t0, q.eb0_t1), MovingVertex(q.eb1_t0, q.eb1_t1)}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto separation = predicates::edge_edge_separation(
      moving(q.ea0_t0, q.ea0_t1), moving(q.ea1_t0, q.ea1_t1), moving(q.eb0_t0, q.eb0_t1),
      moving(q.eb1_t0, q.eb1_t1), delta2);
  const auto at = [&m, &delta2](double t) {
    return predicates::edge_edge_separation(position_at(m.v[0], t), position_at(m.v[1], t),
                                            position_at(m.v[2], t), position_at(m.v[3], t),
                                            delta2);
  };
  const ExactPolynomial exact_polynomial = [&q, &options](int k) {
    const exact::Rational d(options.min_separation);
    return polynomial_number(
        predicates::edge_edge_separation(exact_moving(q.ea0_t0, q.ea0_t1),
                                         exact_moving(q.ea1_t0, q.ea1_t1),
                                         exact_moving(q.eb0_t0, q.eb0_t1),
                                         exact_moving(q.eb1_t0, q.eb1_t1), exact::Rational(d * d)),
        k);
  };
  return first_within(m, separation, at, exact_polynomial, options);
}

}  // namespace exactccd::filters
