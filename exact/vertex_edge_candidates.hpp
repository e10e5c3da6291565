// The candidate polynomial of a vertex moving against a segment while the four points of a
// query stay coplanar, over any moving-point type (linear, or rigid on a common denominator).
// PROOF: proofs/exact_ccd.md#lemma-vertex-edge-candidates
// PROOF: proofs/rigid_ccd.md#theorem-rigid
#pragma once

#include "core/predicates/motion.hpp"
#include "exact/polynomial.hpp"

namespace exactccd::exact {

/// A non-zero polynomial whose roots contain every contact time of p against the closed
/// segment [x, y] other than t = 0; the zero polynomial when contact at t = 0 is the only
/// possibility left.
template <class Point>
Polynomial vertex_edge_candidates(const Point& p, const Point& x, const Point& y) {
  const auto n = predicates::cross(y - x, p - x);
  for (int k = 0; k < 3; ++k) {
    Polynomial q(n[k]);
    if (!q.is_zero()) return q;
  }
  return Polynomial(predicates::dot(p - x, p - y));
}

}  // namespace exactccd::exact
