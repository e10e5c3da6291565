// The earliest time of the exact path at which an instant predicate holds, among candidate
// times (t = 0 and the real roots of given polynomials), and the helpers the exact procedures
// share. PROOF: proofs/exact_ccd.md#theorem-1
#pragma once

#include <optional>
#include <utility>

#include "core/predicates/coplanarity_cubic.hpp"
#include "exact/polynomials/root_isolation.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::exact {

inline predicates::MovingPoint<Rational> moving(const RationalPoint& x0, const RationalPoint& x1) {
  return predicates::linear_motion(predicates::Vec3<Rational>{x0.x, x0.y, x0.z},
                                   predicates::Vec3<Rational>{x1.x, x1.y, x1.z});
}

/// The sign of a polynomial at the algebraic time t, for the instant predicates.
inline auto sign_at(AlgebraicTime& t) {
  return [&t](const auto& q) { return t.sign_of(q); };
}

/// The earliest time at which contact_at holds among the candidates: t = t_from when
/// include_start, and the roots in [t_from, t_max] of each polynomial in `candidates` (zero
/// polynomials and constants have none). Each polynomial is searched in ascending order of its
/// roots up to the best time found so far, and the earliest of the per-polynomial firsts is
/// returned.
template <class Polynomials, class ContactAt>
std::optional<AlgebraicTime> earliest_contact(const Polynomials& candidates,
                                              bool include_start, const Rational& t_max,
                                              ContactAt&& contact_at,
                                              const Rational& t_from = Rational(0)) {
  if (include_start) {
    AlgebraicTime start = AlgebraicTime::rational(t_from);
    if (contact_at(start)) return start;
  }
  std::optional<AlgebraicTime> best;
  for (const Polynomial& poly : candidates) {
    if (poly.degree() < 1) continue;
    for (AlgebraicTime& t : real_roots_in(poly, t_from, t_max)) {
      if (include_start && t.is_rational() && cmp(t.lo(), t_from) == 0) continue;  // tried
      if (best && compare(t, *best) >= 0) break;  // ascending: no later root can be earlier
      if (contact_at(t)) {
        best = std::move(t);
        break;
      }
    }
  }
  return best;
}

/// The query scaled by the least common multiple l of its coordinates' denominators (a uniform
/// positive scaling of space changes no contact and no contact time, and integer data keeps
/// GMP's rational normalisation cheap); *scale = l when asked.
RationalQuery with_integer_coordinates(const RationalQuery& q, Rational* scale = nullptr);

/// The verdict and TOI enclosure of an exact earliest contact time (none: no contact).
CcdResult make_result(std::optional<AlgebraicTime> toi, const CcdOptions& options);

}  // namespace exactccd::exact
