// The paths of a rigid (or per-vertex linear) query's four points over any number type, written
// once for every stage: the numerators X_i(s) and the two sides' denominators w_side(s)
// (rigid_motion.hpp), positions x_i(s) = X_i(s) / w_side(s), and the points on the common
// denominator W = w_0 w_1 that the exact procedures and the region polynomials read.
// PROOF: proofs/rigid_ccd.md#homogeneous-paths, proofs/rigid_ccd.md#common-denominator
#pragma once

#include <array>

#include "core/predicates/rigid_motion.hpp"
#include "exactccd/types.hpp"

namespace exactccd::predicates {

template <class NT>
struct RigidPaths {
  std::array<Vec3<FixedPoly<NT, 3>>, 4> numerator;  ///< X_i(s), in the query's point order
  std::array<FixedPoly<NT, 2>, 2> denominator;      ///< w_side(s) (1 for a linear side)
  int first_side_count = 1;                         ///< points of side 0 (vertex-face 1, edge-edge 2)
  /// denominator[side] is the constant 1 (a linear side): positions need no division.
  std::array<bool, 2> unit_denominator{};

  /// The point on the common denominator: Y_i = X_i w_other, so x_i = Y_i / W.
  RigidPoint<NT> on_common_denominator(int point) const {
    return predicates::on_common_denominator(numerator[point],
                                             denominator[point < first_side_count ? 1 : 0]);
  }
  /// The positions x_i(s) = X_i(s) / w_side(s) at s (for an interval s: boxes enclosing them
  /// over s, w >= 1 there).
  template <class T>
  std::array<Vec3<NT>, 4> positions_at(const T& s) const {
    const NT w[2] = {evaluate(denominator[0], s), evaluate(denominator[1], s)};
    std::array<Vec3<NT>, 4> x;
    for (int i = 0; i < 4; ++i) {
      const int side = i < first_side_count ? 0 : 1;
      x[i] = {evaluate(numerator[i].x, s), evaluate(numerator[i].y, s),
              evaluate(numerator[i].z, s)};
      if (unit_denominator[side]) continue;  // x / 1 = x exactly
      const NT& d = w[side];
      x[i] = {x[i].x / d, x[i].y / d, x[i].z / d};
    }
    return x;
  }
  /// W = w_0 w_1 (> 0 for every real s).
  FixedPoly<NT, 4> common_denominator() const { return denominator[0] * denominator[1]; }
};

/// The paths of a query with start positions q.start and sides q.side (DoubleRigidQuery,
/// exact::RationalRigidQuery), each number converted to NT exactly.
template <class NT, class Query>
EXACTCCD_CERTIFIED RigidPaths<NT> rigid_paths(const Query& q) {
  auto to = [](const auto& x) { return Vec3<NT>{NT(x.x), NT(x.y), NT(x.z)}; };
  RigidPaths<NT> paths;
  paths.first_side_count = q.type == QueryType::vertex_face ? 1 : 2;
  for (int side = 0; side < 2; ++side) {
    const auto& s = q.side[side];
    const RigidMotionOver<NT> motion{to(s.motion.pivot), to(s.motion.translation),
                                     to(s.motion.cayley)};
    paths.denominator[side] = s.rigid ? rigid_path_denominator(motion)
                                      : FixedPoly<NT, 2>{{NT(1), NT(0), NT(0)}};
    paths.unit_denominator[side] = !s.rigid;
    const int begin = side == 0 ? 0 : paths.first_side_count;
    const int end = side == 0 ? paths.first_side_count : 4;
    for (int i = begin; i < end; ++i) {
      const Vec3<NT> x0 = to(q.start[i]);
      paths.numerator[i] = s.rigid ? rigid_path_numerator(motion, x0)
                                   : linear_path_numerator(x0, to(s.end[i - begin]));
    }
  }
  return paths;
}

}  // namespace exactccd::predicates
