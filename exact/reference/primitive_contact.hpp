// The earliest contact of a vertex-face or edge-edge query on the exact path, over any
// moving-point type (linear motion, or rigid motion on a common denominator): Theorems 1 and 2
// of the exact path, written once.
// PROOF: proofs/exact_ccd.md#theorem-1
// PROOF: proofs/exact_ccd.md#lemma-vertex-edge-candidates
// PROOF: proofs/rigid_ccd.md#theorem-rigid
#pragma once

#include <initializer_list>
#include <optional>

#include "core/predicates/inclusion.hpp"
#include "exact/reference/earliest_contact.hpp"
#include "exact/polynomials/polynomial.hpp"

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

/// The earliest t in [0, t_max] at which p lies in the closed triangle (a, b, c), given a
/// polynomial with the real roots of the coplanarity determinant det[b - a, c - a, p - a]
/// (zero when it vanishes identically): its roots are the candidates, or, coplanar throughout,
/// t = 0 and the times p crosses an edge.
template <class Point>
std::optional<AlgebraicTime> earliest_vertex_face_contact(const Point& p, const Point& a,
                                                          const Point& b, const Point& c,
                                                          const Polynomial& coplanarity,
                                                          const Rational& t_max) {
  auto contact_at = [&](AlgebraicTime& t) {
    return predicates::point_in_triangle_at(p, a, b, c, sign_at(t));
  };
  if (!coplanarity.is_zero())  // contact implies coplanarity: only its roots are candidates
    return earliest_contact(std::initializer_list<Polynomial>{coplanarity}, false, t_max,
                            contact_at);
  // Coplanar throughout: the first contact after t = 0 lies on an edge of the triangle.
  return earliest_contact(
      std::initializer_list<Polynomial>{vertex_edge_candidates(p, a, b),
                                        vertex_edge_candidates(p, b, c),
                                        vertex_edge_candidates(p, c, a)},
      true, t_max, contact_at);
}

/// The earliest t in [0, t_max] at which the closed segments [a0, a1] and [b0, b1] meet, given
/// a polynomial with the real roots of det[a1 - a0, b0 - a0, b1 - a0] (zero when it vanishes
/// identically).
template <class Point>
std::optional<AlgebraicTime> earliest_edge_edge_contact(const Point& a0, const Point& a1,
                                                        const Point& b0, const Point& b1,
                                                        const Polynomial& coplanarity,
                                                        const Rational& t_max) {
  auto contact_at = [&](AlgebraicTime& t) {
    return predicates::segments_intersect_at(a0, a1, b0, b1, sign_at(t));
  };
  if (!coplanarity.is_zero())
    return earliest_contact(std::initializer_list<Polynomial>{coplanarity}, false, t_max,
                            contact_at);
  // Coplanar throughout: the first contact after t = 0 puts an endpoint on the other segment.
  return earliest_contact(
      std::initializer_list<Polynomial>{vertex_edge_candidates(a0, b0, b1),
                                        vertex_edge_candidates(a1, b0, b1),
                                        vertex_edge_candidates(b0, a0, a1),
                                        vertex_edge_candidates(b1, a0, a1)},
      true, t_max, contact_at);
}

}  // namespace exactccd::exact
