// Implementation of filters/cubic_filter.hpp (a template over the inclusion policy).
#pragma once

#include <cmath>
#include <tuple>
#include <limits>

#include "core/predicates/double_bits.hpp"
#include "filters/cubic_bernstein.hpp"

namespace exactccd::filters {

namespace detail {

constexpr int kMaxSubdivisionDepth = 10;

EXACTCCD_CERTIFIED int strict_sign_of_all(const Bernstein3<Interval>& b) {
  const int s = certain_strict_sign(b[0]);
  if (s == 0) return 0;
  for (int i = 1; i < 4; ++i)
    if (!certainly_has_sign(b[i], s)) return 0;
  return s;
}

/// The derivative's Bernstein coefficients (3 (b[i+1] - b[i])) all of one certain strict sign.
EXACTCCD_CERTIFIED bool certainly_monotone(const Bernstein3<Interval>& b) {
  const int d = certain_strict_sign(b[1] - b[0]);
  return d != 0 && certainly_has_sign(b[2] - b[1], d) && certainly_has_sign(b[3] - b[2], d);
}

/// Exactly one simple root in the parameter interval: certain opposite signs at its ends and
/// a derivative (Bernstein coefficients b[i+1] - b[i]) of one certain strict sign.
EXACTCCD_CERTIFIED bool certainly_one_root(const Bernstein3<Interval>& b) {
  const int s0 = certain_strict_sign(b[0]);
  return s0 != 0 && certainly_has_sign(b[3], -s0) && certainly_monotone(b);
}

/// An enclosure of t_max * [s0, s1] (0 <= s0 <= s1): [down(t_max s0), up(t_max s1)]. Through
/// the interval type, whose operations the compiler cannot move across the rounding-mode
/// switch (a raw double product could be).
EXACTCCD_CERTIFIED Interval time_enclosure(double t_max, double s0, double s1) {
  return Interval(t_max) * Interval(s0, s1);
}

/// hi - lo <= width, with the difference rounded up (through the interval type, as above).
EXACTCCD_CERTIFIED bool certainly_within_width(double lo, double hi, double width) {
  return (Interval(hi) - Interval(lo)).sup() <= width;
}

using predicates::bits_of;
using predicates::double_of;

/// Certified bisection of a bracket [lo, hi] (0 <= lo < hi) of the only root of the cubic,
/// whose signs at lo and hi are certainly -s_hi and s_hi. Splits at the middle double in bit
/// order, so that at most 64 steps reach the tightest pair.
EXACTCCD_CERTIFIED
FilterOutcome refine_bracket(const predicates::FixedPoly<Interval, 3>& cubic, double lo,
                                    double hi, int sign_hi, double toi_width) {
  FilterOutcome out;
  out.verdict = FilterOutcome::Verdict::contact;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (;;) {
    out.toi_lo = lo;
    out.toi_hi = hi;
    const double first = std::nextafter(lo, kInf), last = std::nextafter(hi, -kInf);
    if (first > last || (toi_width > 0 && certainly_within_width(lo, hi, toi_width))) {
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

EXACTCCD_CERTIFIED bool cubic_certainly_root_free(const predicates::FixedPoly<Interval, 3>& cubic,
                                      double t_max) {
  return detail::strict_sign_of_all(cubic_bernstein(cubic, Interval(t_max))) != 0;
}

template <class Inclusion>
EXACTCCD_CERTIFIED
FilterOutcome cubic_filter(const predicates::FixedPoly<Interval, 3>& cubic, double t_max,
                           double toi_width, const Inclusion& inclusion, ExactAtDoubles& exact) {
  using detail::kMaxSubdivisionDepth;
  FilterOutcome out;  // uncertain until decided
  auto contact_at_double = [&](double t) {
    out.verdict = FilterOutcome::Verdict::contact;
    out.toi_lo = out.toi_hi = t;
    out.toi_final = true;
    return out;
  };

  // The ends of [0, t_max] as exact roots: a contact at t = 0 is the first one; a root at an
  // end is excluded from the nodes' single-root test below, so it is decided here exactly.
  bool zero_at_start = false, zero_at_end = false;
  if (certain_strict_sign(cubic.c[0]) == 0) {
    out.exact_used = true;
    if (exact.cubic_sign_at(0.0) == 0) {
      if (exact.contact_at(0.0)) return contact_at_double(0.0);
      zero_at_start = true;
    }
  }
  if (certain_strict_sign(predicates::evaluate(cubic, Interval(t_max))) == 0) {
    out.exact_used = true;
    zero_at_end = exact.cubic_sign_at(t_max) == 0;
  }

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
  while (top > 0) {
    const Node node = stack[--top];
    if (detail::strict_sign_of_all(node.b) != 0) continue;  // no coplanar instant here
    const Interval T = detail::time_enclosure(t_max, node.s0, node.s1);
    if (inclusion.excluded(T)) continue;
    const bool root_at_start = zero_at_start && node.s0 == 0.0;
    const bool root_at_end = zero_at_end && node.s1 == 1.0;
    if (root_at_start || root_at_end) {
      if (detail::certainly_monotone(node.b)) {
        // The node's only root is its end point, whose contact is decided exactly.
        if (root_at_start) continue;  // no contact at t = 0 (checked above)
        if (exact.contact_at(t_max)) return contact_at_double(t_max);
        continue;
      }
    } else if (detail::certainly_one_root(node.b)) {
      // The node's only root r is its only coplanar instant; earlier nodes were all excluded.
      // Re-certify the bracket on the rounded-out time interval T in the power basis.
      const double lo = T.inf(), hi = T.sup();
      const int s_lo = certain_strict_sign(predicates::evaluate(cubic, Interval(lo)));
      const int s_hi = certain_strict_sign(predicates::evaluate(cubic, Interval(hi)));
      const int d = certain_strict_sign(predicates::evaluate(predicates::derivative(cubic), T));
      if (s_lo != 0 && s_hi == -s_lo && d != 0) {
        if (inclusion.certainly_included(T)) {
          const bool used = out.exact_used;
          out = detail::refine_bracket(cubic, lo, hi, s_hi, toi_width);
          out.exact_used = used;
          return out;
        }
        // Undecided at r: narrow the bracket around r and try again, then decide exactly.
        const FilterOutcome narrow = detail::refine_bracket(cubic, lo, hi, s_hi, 0.0);
        const Interval R(narrow.toi_lo, narrow.toi_hi);
        if (inclusion.excluded(R)) continue;
        if (inclusion.certainly_included(R)) {
          const bool used = out.exact_used;
          out = detail::refine_bracket(cubic, narrow.toi_lo, narrow.toi_hi, s_hi, toi_width);
          out.exact_used = used;
          return out;
        }
        out.exact_used = true;
        double r_lo = narrow.toi_lo, r_hi = narrow.toi_hi;
        if (r_lo != r_hi) std::tie(r_lo, r_hi) = exact.bisect_root(r_lo, r_hi);
        if (r_lo != r_hi) return out;  // r is not a double: uncertain
        if (exact.contact_at(r_lo)) return contact_at_double(r_lo);
        continue;  // the node's only coplanar instant is no contact
      }
    }
    if (node.depth == kMaxSubdivisionDepth) return out;  // uncertain
    Node left, right;
    de_casteljau_halves(node.b, left.b, right.b);
    const double mid = (node.s0 + node.s1) / 2;  // dyadic: exact
    left.s0 = node.s0, left.s1 = mid, left.depth = node.depth + 1;
    right.s0 = mid, right.s1 = node.s1, right.depth = node.depth + 1;
    stack[top++] = right;
    stack[top++] = left;
  }
  out.verdict = FilterOutcome::Verdict::no_contact;
  return out;
}

}  // namespace exactccd::filters
