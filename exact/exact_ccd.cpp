// PROOF: proofs/exact_ccd.md (theorems 1 and 2 and the lemmas they cite).
#include "exact/exact_ccd.hpp"

#include <optional>

#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/inclusion.hpp"
#include "exact/root_isolation.hpp"

namespace exactccd::exact {

namespace {

using predicates::MovingPoint;
using predicates::Vec3;

MovingPoint<Rational> moving(const RationalPoint& x0, const RationalPoint& x1) {
  return predicates::linear_motion(Vec3<Rational>{x0.x, x0.y, x0.z},
                                   Vec3<Rational>{x1.x, x1.y, x1.z});
}

/// A non-zero polynomial whose roots contain every contact time of the vertex-edge motion
/// (p against the closed segment [x, y]) other than t = 0; the zero polynomial when contact at
/// t = 0 is the only possibility left. PROOF: proofs/exact_ccd.md#lemma-vertex-edge-candidates
Polynomial vertex_edge_candidates(const MovingPoint<Rational>& p, const MovingPoint<Rational>& x,
                                  const MovingPoint<Rational>& y) {
  const auto n = cross(y - x, p - x);
  for (int k = 0; k < 3; ++k) {
    Polynomial q(n[k]);
    if (!q.is_zero()) return q;
  }
  return Polynomial(dot(p - x, p - y));
}

/// Multiplies the non-zero candidates into one polynomial (the constant 1 when none).
Polynomial product_of_nonzero(std::initializer_list<Polynomial> factors) {
  Polynomial product(std::vector<Rational>{Rational(1)});
  for (const auto& f : factors)
    if (!f.is_zero()) product = product * f;
  return product;
}

/// The earliest time among the candidates (t = 0 when include_zero, and the roots of
/// `candidates` in [0, t_max]) at which contact_at holds.
template <class ContactAt>
std::optional<AlgebraicTime> earliest_contact(const Polynomial& candidates, bool include_zero,
                                              const Rational& t_max, ContactAt&& contact_at) {
  if (include_zero) {
    AlgebraicTime zero = AlgebraicTime::rational(0);
    if (contact_at(zero)) return zero;
  }
  if (candidates.is_zero() || candidates.degree() == 0) return std::nullopt;
  for (AlgebraicTime& t : real_roots_in(candidates, Rational(0), t_max)) {
    if (include_zero && t.is_rational() && sgn(t.lo()) == 0) continue;  // already tried
    if (contact_at(t)) return std::move(t);
  }
  return std::nullopt;
}

CcdResult make_result(std::optional<AlgebraicTime> toi, const CcdOptions& options) {
  CcdResult r;
  r.decided_by = Stage::exact;
  if (!toi) return r;
  r.collides = true;
  std::tie(r.toi_lo, r.toi_hi) = toi->enclosure(options.toi_width);
  return r;
}

auto sign_at(AlgebraicTime& t) {
  return [&t](const auto& q) { return t.sign_of(q); };
}

}  // namespace

CcdResult vertex_face_ccd_exact(const RationalQuery& q, const CcdOptions& options) {
  const auto& v = q.points;
  const auto p = moving(v[0], v[4]), a = moving(v[1], v[5]), b = moving(v[2], v[6]),
             c = moving(v[3], v[7]);
  const Rational t_max(options.t_max);
  auto contact_at = [&](AlgebraicTime& t) {
    return predicates::point_in_triangle_at(p, a, b, c, sign_at(t));
  };
  const Polynomial cubic(predicates::vertex_face_coplanarity_cubic(p, a, b, c));
  if (!cubic.is_zero())  // contact implies coplanarity: only the cubic's roots are candidates
    return make_result(earliest_contact(cubic, false, t_max, contact_at), options);
  // Coplanar throughout: the first contact after t = 0 lies on an edge of the triangle.
  const Polynomial candidates = product_of_nonzero({vertex_edge_candidates(p, a, b),
                                                    vertex_edge_candidates(p, b, c),
                                                    vertex_edge_candidates(p, c, a)});
  return make_result(earliest_contact(candidates, true, t_max, contact_at), options);
}

CcdResult edge_edge_ccd_exact(const RationalQuery& q, const CcdOptions& options) {
  const auto& v = q.points;
  const auto a0 = moving(v[0], v[4]), a1 = moving(v[1], v[5]), b0 = moving(v[2], v[6]),
             b1 = moving(v[3], v[7]);
  const Rational t_max(options.t_max);
  auto contact_at = [&](AlgebraicTime& t) {
    return predicates::segments_intersect_at(a0, a1, b0, b1, sign_at(t));
  };
  const Polynomial cubic(predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1));
  if (!cubic.is_zero())
    return make_result(earliest_contact(cubic, false, t_max, contact_at), options);
  // Coplanar throughout: the first contact after t = 0 puts an endpoint on the other segment.
  const Polynomial candidates = product_of_nonzero(
      {vertex_edge_candidates(a0, b0, b1), vertex_edge_candidates(a1, b0, b1),
       vertex_edge_candidates(b0, a0, a1), vertex_edge_candidates(b1, a0, a1)});
  return make_result(earliest_contact(candidates, true, t_max, contact_at), options);
}

}  // namespace exactccd::exact
