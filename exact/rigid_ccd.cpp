// PROOF: proofs/rigid_ccd.md (Theorem R and the lemmas it cites).
#include "exact/rigid_ccd.hpp"

#include <initializer_list>

#include "core/predicates/inclusion.hpp"
#include "exact/earliest_contact.hpp"
#include "exact/vertex_edge_candidates.hpp"

namespace exactccd::exact {

namespace {

using predicates::FixedPoly;
using predicates::RigidPoint;
using predicates::Vec3;

struct SidePaths {
  std::array<Vec3<FixedPoly<Rational, 3>>, 3> numerator;
  FixedPoly<Rational, 2> denominator;
};

FixedPoly<Rational, 2> denominator_of(const RationalSide& side) {
  return side.rigid ? predicates::rigid_path_denominator(side.motion)
                    : FixedPoly<Rational, 2>{{Rational(1), Rational(0), Rational(0)}};
}

SidePaths paths_of(const RationalSide& side, const Vec3<Rational>* start, int count) {
  SidePaths paths;
  for (int i = 0; i < count; ++i)
    paths.numerator[i] = side.rigid ? predicates::rigid_path_numerator(side.motion, start[i])
                                    : predicates::linear_path_numerator(start[i], side.end[i]);
  paths.denominator = denominator_of(side);
  return paths;
}

/// f with every factor w (a denominator 1 + |q|^2 s^2 of degree 2, which has no real root)
/// divided out as often as it divides f: the same real roots, a lower degree.
/// PROOF: proofs/rigid_ccd.md#degree
Polynomial without_denominator_factors(Polynomial f,
                                       std::initializer_list<const FixedPoly<Rational, 2>*> ws) {
  for (const FixedPoly<Rational, 2>* w : ws) {
    const Polynomial divisor(*w);
    if (divisor.degree() < 1) continue;
    while (f.degree() >= divisor.degree()) {
      Polynomial quotient, remainder;
      divide(f, divisor, &quotient, &remainder);
      if (!remainder.is_zero()) break;
      f = std::move(quotient);
    }
  }
  return f;
}

}  // namespace

std::array<RigidPoint<Rational>, 4> common_denominator_points(const RationalRigidQuery& q) {
  const int first_side_count = q.type == QueryType::vertex_face ? 1 : 2;
  const SidePaths a = paths_of(q.side[0], &q.start[0], first_side_count);
  const SidePaths b = paths_of(q.side[1], &q.start[first_side_count], 4 - first_side_count);
  std::array<RigidPoint<Rational>, 4> points;
  for (int i = 0; i < 4; ++i)
    points[i] = i < first_side_count
                    ? predicates::on_common_denominator(a.numerator[i], b.denominator)
                    : predicates::on_common_denominator(b.numerator[i - first_side_count],
                                                        a.denominator);
  return points;
}

namespace {

Polynomial coplanarity_of(const RationalRigidQuery& q,
                          const std::array<RigidPoint<Rational>, 4>& y) {
  const FixedPoly<Rational, 2> w0 = denominator_of(q.side[0]), w1 = denominator_of(q.side[1]);
  const auto f = q.type == QueryType::vertex_face
                     ? predicates::coplanarity_determinant(y[0], y[1], y[2], y[3])
                     : predicates::coplanarity_determinant(y[3], y[0], y[1], y[2]);
  return without_denominator_factors(Polynomial(f), {&w0, &w1});
}

}  // namespace

Polynomial rigid_coplanarity_polynomial(const RationalRigidQuery& q) {
  return coplanarity_of(q, common_denominator_points(q));
}

CcdResult rigid_ccd_exact(const RationalRigidQuery& q, const CcdOptions& options) {
  const auto y = common_denominator_points(q);
  const Rational t_max(options.t_max);
  const Polynomial f = coplanarity_of(q, y);
  if (q.type == QueryType::vertex_face) {
    const auto &p = y[0], &a = y[1], &b = y[2], &c = y[3];
    auto contact_at = [&](AlgebraicTime& t) {
      return predicates::point_in_triangle_at(p, a, b, c, sign_at(t));
    };
    if (!f.is_zero())
      return make_result(earliest_contact(std::initializer_list<Polynomial>{f}, false, t_max,
                                          contact_at),
                         options);
    return make_result(
        earliest_contact(std::initializer_list<Polynomial>{vertex_edge_candidates(p, a, b),
                                                           vertex_edge_candidates(p, b, c),
                                                           vertex_edge_candidates(p, c, a)},
                         true, t_max, contact_at),
        options);
  }
  const auto &a0 = y[0], &a1 = y[1], &b0 = y[2], &b1 = y[3];
  auto contact_at = [&](AlgebraicTime& t) {
    return predicates::segments_intersect_at(a0, a1, b0, b1, sign_at(t));
  };
  if (!f.is_zero())
    return make_result(
        earliest_contact(std::initializer_list<Polynomial>{f}, false, t_max, contact_at),
        options);
  return make_result(
      earliest_contact(std::initializer_list<Polynomial>{vertex_edge_candidates(a0, b0, b1),
                                                         vertex_edge_candidates(a1, b0, b1),
                                                         vertex_edge_candidates(b0, a0, a1),
                                                         vertex_edge_candidates(b1, a0, a1)},
                       true, t_max, contact_at),
      options);
}

}  // namespace exactccd::exact
