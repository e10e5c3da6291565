// The exact stage of the rigid filters (predicates::RigidExactStage): a query's values over the
// rationals, and the exact signs at doubles of its reduced coplanarity polynomial and of its
// minimum separation's region polynomials, which the filters consult where their intervals
// cannot tell. PROOF: proofs/rigid_ccd.md#toi-tightening
#pragma once

#include <optional>

#include "core/predicates/rigid_coplanarity.hpp"
#include "core/predicates/rigid_paths.hpp"
#include "core/predicates/rigid_separation.hpp"
#include "exact/reference/rigid_ccd.hpp"
#include "exact/arithmetic/dyadic.hpp"
#include "exact/arithmetic/stack_dyadic.hpp"
#include "core/predicates/rigid_exact_stage.hpp"
#include "core/predicates/rigid_query.hpp"

namespace exactccd::exact {

/// The same query over the rationals (the same values), for the exact path.
inline exact::RationalRigidQuery rational_query(const predicates::DoubleRigidQuery& d) {
  auto rational = [](const predicates::Vec3<double>& x) {
    return predicates::Vec3<exact::Rational>{exact::Rational(x.x), exact::Rational(x.y),
                                             exact::Rational(x.z)};
  };
  exact::RationalRigidQuery q;
  q.type = d.type;
  for (int i = 0; i < 4; ++i) q.start[i] = rational(d.start[i]);
  const int first = d.type == QueryType::vertex_face ? 1 : 2;
  for (int k = 0; k < 2; ++k) {
    const predicates::DoubleSide& s = d.side[k];
    exact::RationalSide& r = q.side[k];
    r.rigid = s.rigid;
    if (s.rigid) {
      r.motion = {rational(s.motion.pivot), rational(s.motion.translation),
                  rational(s.motion.cayley)};
    } else {
      for (int i = 0; i < (k == 0 ? first : 4 - first); ++i) r.end[i] = rational(s.end[i]);
    }
  }
  return q;
}

/// Exact signs of g at doubles: its coefficients as exact dyadic numbers on the stack
/// (exact::StackDyadic: no allocation, no gcd), formed on the first call, and Horner's rule at
/// the double, exactly; over the rationals when a number would need more than the stack
/// holds (extreme magnitudes).
class RigidExactStageAtDoubles final : public predicates::RigidExactStage {
 public:
  /// delta: the query's minimum separation (0 for contact).
  explicit RigidExactStageAtDoubles(const predicates::DoubleRigidQuery& q, double delta = 0.0)
      : query_(q), delta_(delta) {}

  int coplanarity_sign_at(double s) override {
    if (!dyadic_ready_) {
      const auto& x = query_.start;
      dyadic_ = query_.type == QueryType::vertex_face
                    ? predicates::vertex_face_rigid_coplanarity<exact::StackDyadic>(
                          x[0], x[1], x[2], x[3], query_.side[0], query_.side[1])
                    : predicates::edge_edge_rigid_coplanarity<exact::StackDyadic>(
                          x[0], x[1], x[2], x[3], query_.side[0], query_.side[1]);
      dyadic_ready_ = true;
    }
    const exact::StackDyadic value = predicates::evaluate(dyadic_, exact::StackDyadic(s));
    if (!value.overflow()) return value.sign();
    if (!rational_) rational_ = exact::rigid_coplanarity_polynomial(rational_query(query_));
    return rational_->sign_at(exact::Rational(s));
  }

  /// Region polynomial k on the common denominator (delta^2 W^2 for delta^2), its value at s
  /// over the rationals: the positions' numerators and denominators at s, then the polynomial
  /// at those numbers. PROOF: proofs/min_separation.md#rigid-separation
  int region_sign_at(int k, double s) override {
    if (!paths_) paths_ = predicates::rigid_paths<exact::Dyadic>(query_);
    return predicates::rigid_region_value(*paths_, query_.type, exact::Dyadic(delta_), k,
                                          exact::Dyadic(s))
        .sign();
  }

 private:
  const predicates::DoubleRigidQuery& query_;
  const double delta_;
  std::optional<predicates::RigidPaths<exact::Dyadic>> paths_;
  predicates::FixedPoly<exact::StackDyadic, 5> dyadic_;
  bool dyadic_ready_ = false;
  std::optional<exact::Polynomial> rational_;
};

}  // namespace exactccd::exact
