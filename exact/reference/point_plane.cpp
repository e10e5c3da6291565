// PROOF: proofs/point_plane.md#reduction
#include "exact/reference/point_plane.hpp"

#include "core/predicates/plane_offset.hpp"
#include "exact/reference/earliest_contact.hpp"

namespace exactccd::exact {

namespace {

/// The exact first time in [0, t_max] at which the point is on the plane (delta = 0) or within
/// delta of it, or none.
std::optional<AlgebraicTime> first_time(const PointPlanePoints& x, const Rational& t_max,
                                        double min_separation) {
  const auto f_t = predicates::linear_plane_offset<Rational>(
      PointPlaneQuery{x[0], x[1], x[2], x[3], x[4], x[5]});  // degree <= 2
  const Polynomial f(f_t);
  if (min_separation == 0.0)
    // On the plane: f(t) = 0 (f identically zero: on it throughout, the start is the TOI).
    return earliest_contact(std::vector<Polynomial>{f}, true, t_max,
                            [&](AlgebraicTime& t) { return t.sign_of(f) == 0; });
  // Within delta: g(t) = f(t)^2 - delta^2 |n(t)|^2 <= 0. The first such time is t = 0 or a
  // root of g (g is continuous: it is positive just before its first non-positive time).
  const Rational delta(min_separation);
  const predicates::FixedPoly<Rational, 0> delta2{{Rational(delta * delta)}};
  const auto n = predicates::moving_point<Rational>(x[2], x[5]);
  const Polynomial g(f_t * f_t - delta2 * predicates::dot(n, n));  // degree <= 4
  return earliest_contact(std::vector<Polynomial>{g}, true, t_max,
                          [&](AlgebraicTime& t) { return t.sign_of(g) <= 0; });
}

}  // namespace

CcdResult point_plane_ccd_exact(const PointPlanePoints& x, const CcdOptions& options) {
  return make_result(first_time(x, Rational(options.t_max), options.min_separation), options);
}

bool point_plane_contact_before(const PointPlanePoints& x, const Rational& t,
                                double min_separation) {
  std::optional<AlgebraicTime> first = first_time(x, t, min_separation);
  if (!first) return false;
  AlgebraicTime at_t = AlgebraicTime::rational(t);
  return compare(*first, at_t) < 0;
}

}  // namespace exactccd::exact
