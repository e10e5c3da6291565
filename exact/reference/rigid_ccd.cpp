// PROOF: proofs/rigid_ccd.md (Theorem R and the lemmas it cites).
#include "exact/reference/rigid_ccd.hpp"

#include <initializer_list>

#include "core/predicates/inclusion.hpp"
#include "core/predicates/rigid_coplanarity.hpp"
#include "core/predicates/rigid_paths.hpp"
#include "exact/reference/earliest_contact.hpp"
#include "exact/reference/primitive_contact.hpp"

namespace exactccd::exact {

using predicates::RigidPoint;

std::array<RigidPoint<Rational>, 4> common_denominator_points(const RationalRigidQuery& q) {
  const predicates::RigidPaths<Rational> paths = predicates::rigid_paths<Rational>(q);
  std::array<RigidPoint<Rational>, 4> points;
  for (int i = 0; i < 4; ++i) points[i] = paths.on_common_denominator(i);
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
