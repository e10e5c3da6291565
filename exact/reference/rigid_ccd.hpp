// The exact decision procedure for rigid (and per-vertex linear) motion: the coplanarity
// polynomial of the common-denominator paths, exact root isolation, exact inclusion at each
// root, the coplanar-throughout reduction. PROOF: proofs/rigid_ccd.md
#pragma once

#include <array>

#include "core/predicates/rigid_motion.hpp"
#include "exact/polynomials/polynomial.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

/// One side of a rigid query over the rationals: a rigid motion, or straight lines to `end`.
struct RationalSide {
  bool rigid = true;
  predicates::RigidMotionOver<Rational> motion;
  std::array<predicates::Vec3<Rational>, 3> end;  ///< linear: the side's vertices at s = 1
};

/// Positions at s = 0 in the order of the public queries (vertex-face p, a, b, c: p on side 0,
/// the triangle on side 1; edge-edge ea0, ea1 on side 0, eb0, eb1 on side 1).
struct RationalRigidQuery {
  QueryType type = QueryType::vertex_face;
  std::array<predicates::Vec3<Rational>, 4> start;
  std::array<RationalSide, 2> side;
};

/// The four points on the common denominator (rigid_motion.hpp), in the query's order.
std::array<predicates::RigidPoint<Rational>, 4> common_denominator_points(
    const RationalRigidQuery& query);

/// The reduced coplanarity polynomial g (core/predicates/rigid_coplanarity.hpp): the coplanarity
/// determinant of the four points on the common denominator divided by w_0^2 (side 0 rigid) and
/// w_1^2 (side 1 rigid), in closed form: the same real roots and signs, degree <= 5 whatever the
/// motions. PROOF: proofs/rigid_ccd.md#degree, proofs/rigid_ccd.md#reduced-polynomial
Polynomial rigid_coplanarity_polynomial(const RationalRigidQuery& query);

/// Options must already be validated; min_separation is ignored (contact). The TOI is in s.
CcdResult rigid_ccd_exact(const RationalRigidQuery& query, const CcdOptions& options);

}  // namespace exactccd::exact
