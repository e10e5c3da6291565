// The coplanarity cubic in the Bernstein basis on [0, t_max], and de Casteljau halving,
// written over the number type (instantiated with Interval for certified enclosures).
// Convex-hull property: on a parameter interval the cubic lies between the smallest and the
// largest Bernstein coefficient. PROOF: proofs/filters.md#bernstein-no-root
#pragma once

#include <array>

#include "core/predicates/motion.hpp"

namespace exactccd::filters {

template <class NT>
using Bernstein3 = std::array<NT, 4>;

/// Bernstein coefficients of f(t_max * s), s in [0, 1], from the power basis in t.
template <class NT>
EXACTCCD_CERTIFIED
Bernstein3<NT> cubic_bernstein(const predicates::FixedPoly<NT, 3>& f, const NT& t_max) {
  const NT a1 = f.c[1] * t_max;
  const NT a2 = f.c[2] * t_max * t_max;
  const NT a3 = f.c[3] * t_max * t_max * t_max;
  return {f.c[0], f.c[0] + a1 / 3, f.c[0] + (a1 * 2 + a2) / 3, f.c[0] + a1 + a2 + a3};
}

/// Bernstein coefficients of the two halves of the parameter interval.
template <class NT>
EXACTCCD_CERTIFIED
void de_casteljau_halves(const Bernstein3<NT>& b, Bernstein3<NT>& left, Bernstein3<NT>& right) {
  const NT b01 = (b[0] + b[1]) / 2, b12 = (b[1] + b[2]) / 2, b23 = (b[2] + b[3]) / 2;
  const NT b012 = (b01 + b12) / 2, b123 = (b12 + b23) / 2;
  const NT mid = (b012 + b123) / 2;
  left = {b[0], b01, b012, mid};
  right = {mid, b123, b23, b[3]};
}

}  // namespace exactccd::filters
