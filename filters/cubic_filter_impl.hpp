// Implementation of filters/cubic_filter.hpp (a template over the inclusion policy).
#pragma once

#include <cmath>
#include <cstring>
#include <limits>

#include "filters/cubic_bernstein.hpp"

namespace exactccd::filters {

namespace detail {

constexpr int kMaxSubdivisionDepth = 10;

inline int strict_sign_of_all(const Bernstein3<Interval>& b) {
  const int s = certain_strict_sign(b[0]);
  if (s == 0) return 0;
  for (int i = 1; i < 4; ++i)
    if (!certainly_has_sign(b[i], s)) return 0;
  return s;
}

/// Exactly one simple root in the parameter interval: certain opposite signs at its ends and
/// a derivative (Bernstein coefficients b[i+1] - b[i]) of one certain strict sign.
inline bool certainly_one_root(const Bernstein3<Interval>& b) {
  const int s0 = certain_strict_sign(b[0]);
  if (s0 == 0 || !certainly_has_sign(b[3], -s0)) return false;
  const int d = certain_strict_sign(b[1] - b[0]);
  return d != 0 && certainly_has_sign(b[2] - b[1], d) && certainly_has_sign(b[3] - b[2], d);
}

/// [down(t_max * s0), up(t_max * s1)] under upward rounding.
inline Interval time_enclosure(double t_max, double s0, double s1) {
  const double lo = -((-t_max) * s0);
  const double hi = t_max * s1;
  return Interval(lo, hi);
}

inline std::uint64_t bits_of(double d) {
  std::uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  return u;
}
inline double double_of(std::uint64_t u) {
  double d;
  std::memcpy(&d, &u, sizeof d);
  return d;
}

/// Certified bisection of a bracket [lo, hi] (0 <= lo < hi) of the only root of the cubic,
/// whose signs at lo and hi are certainly -s_hi and s_hi. Splits at the middle double in bit
/// order, so that at most 64 steps reach the tightest pair.
inline FilterOutcome refine_bracket(const predicates::FixedPoly<Interval, 3>& cubic, double lo,
                                    double hi, int sign_hi, double toi_width) {
  FilterOutcome out;
  out.verdict = FilterOutcome::Verdict::contact;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (;;) {
    out.toi_lo = lo;
    out.toi_hi = hi;
    const double first = std::nextafter(lo, kInf), last = std::nextafter(hi, -kInf);
    if (first > last || (toi_width > 0 && hi - lo <= toi_width)) {  // hi - lo rounded up
      out.toi_final = true;
      return out;
    }
    const std::uint64_t a = bits_of(first), b = bits_of(last);
    const double mid = double_of(a + (b - a) / 2);
    const CertifiedSign s = certified_sign(predicates::evaluate(cubic, Interval(mid)));
    if (s == CertifiedSign::uncertain) return out;  // toi_final stays false
    if (s == CertifiedSign::zero) {
      out.toi_lo = out.toi_hi = mid;
      out.toi_final = true;
      return out;
    }
    (static_cast<int>(s) == sign_hi ? hi : lo) = mid;
  }
}

}  // namespace detail

inline bool cubic_certainly_root_free(const predicates::FixedPoly<Interval, 3>& cubic,
                                      double t_max) {
  return detail::strict_sign_of_all(cubic_bernstein(cubic, Interval(t_max))) != 0;
}

template <class Inclusion>
FilterOutcome cubic_filter(const predicates::FixedPoly<Interval, 3>& cubic, double t_max,
                           double toi_width, const Inclusion& inclusion) {
  using detail::kMaxSubdivisionDepth;
  struct Node {
    Bernstein3<Interval> b;
    double s0, s1;
    int depth;
  };
  // Depth-first, left child first: nodes leave the stack in increasing time order, so the
  // first confirmed contact is the earliest one. At most one pending right child per level.
  Node stack[kMaxSubdivisionDepth + 2];
  int top = 0;
  stack[top++] = Node{cubic_bernstein(cubic, Interval(t_max)), 0.0, 1.0, 0};
  FilterOutcome uncertain;
  while (top > 0) {
    const Node node = stack[--top];
    if (detail::strict_sign_of_all(node.b) != 0) continue;  // no coplanar instant here
    const Interval T = detail::time_enclosure(t_max, node.s0, node.s1);
    if (inclusion.excluded(T)) continue;
    if (detail::certainly_one_root(node.b) && inclusion.certainly_included(T)) {
      // Contact at the node's only root; earlier nodes were all excluded. Re-certify the
      // bracket on the rounded-out time interval T in the power basis.
      const double lo = T.inf(), hi = T.sup();
      const int s_lo = certain_strict_sign(predicates::evaluate(cubic, Interval(lo)));
      const int s_hi = certain_strict_sign(predicates::evaluate(cubic, Interval(hi)));
      const int d = certain_strict_sign(predicates::evaluate(predicates::derivative(cubic), T));
      if (s_lo == 0 || s_hi != -s_lo || d == 0) return uncertain;
      return detail::refine_bracket(cubic, lo, hi, s_hi, toi_width);
    }
    if (node.depth == kMaxSubdivisionDepth) return uncertain;
    Node left, right;
    de_casteljau_halves(node.b, left.b, right.b);
    const double mid = (node.s0 + node.s1) / 2;  // dyadic: exact
    left.s0 = node.s0, left.s1 = mid, left.depth = node.depth + 1;
    right.s0 = mid, right.s1 = node.s1, right.depth = node.depth + 1;
    stack[top++] = right;
    stack[top++] = left;
  }
  FilterOutcome none;
  none.verdict = FilterOutcome::Verdict::no_contact;
  return none;
}

}  // namespace exactccd::filters
