// The float_only tests' root refinement, in plain doubles (uncertified, for comparison only).
#pragma once

#include "core/predicates/motion.hpp"

namespace exactccd::float_only {

/// Bisects [lo, hi] in doubles, f(lo) of sign s_lo (+1 or -1) and f(hi) of the other: the lower
/// end of the last bracket (the classic codes' conservative choice), or the double at which f
/// evaluates to exactly 0.
template <int D>
double bisect_sign_change(const predicates::FixedPoly<double, D>& f, double lo, double hi,
                          int s_lo) {
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double fm = predicates::evaluate(f, mid);
    if (fm == 0) return mid;
    (((fm > 0) - (fm < 0)) == s_lo ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace exactccd::float_only
