// PROOF: proofs/rigid_ccd.md (Theorem R and the lemmas it cites).
#include "exact/reference/rigid_ccd.hpp"

#include <initializer_list>

#include "core/predicates/inclusion.hpp"
#include "core/predicates/rigid_coplanarity.hpp"
#include "exact/reference/earliest_contact.hpp"
#include "exact/reference/primitive_contact.hpp"

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

Polynomial rigid_coplanarity_polynomial(const RationalRigidQuery& q) {
  const auto& x = q.start;
  return Polynomial(q.type == QueryType::vertex_face
                        ? predicates::vertex_face_rigid_coplanarity<Rational>(
                              x[0], x[1], x[2], x[3], q.side[0], q.side[1])
                        : predicates::edge_edge_rigid_coplanarity<Rational>(
                              x[0], x[1], x[2], x[3], q.side[0], q.side[1]));
}

CcdResult rigid_ccd_exact(const RationalRigidQuery& q, const CcdOptions& options) {
  const auto y = common_denominator_points(q);
  const Rational t_max(options.t_max);
  const Polynomial f = rigid_coplanarity_polynomial(q);
  return make_result(
      q.type == QueryType::vertex_face
          ? earliest_vertex_face_contact(y[0], y[1], y[2], y[3], f, t_max)
          : earliest_edge_edge_contact(y[0], y[1], y[2], y[3], f, t_max),
      options);
}

}  // namespace exactccd::exact
