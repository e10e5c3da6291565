// Region polynomial k of a rigid query's minimum separation (separation.hpp) at one instant s,
// on the common denominator: the paths' numerators and denominators at s, then the polynomial
// at those numbers with delta^2 W(s)^2 for delta^2. Ring operations only (no division), so it
// serves exact ring types and interval types alike; its sign is the sign at the positions.
// PROOF: proofs/min_separation.md#rigid-separation
#pragma once

#include "core/predicates/rigid_paths.hpp"
#include "core/predicates/separation.hpp"

namespace exactccd::predicates {

template <class NT>
EXACTCCD_CERTIFIED NT rigid_region_value(const RigidPaths<NT>& paths, QueryType type,
                                         const NT& delta, int k, const NT& s) {
  using Point = Vec3<FixedPoly<NT, 0>>;
  const NT w[2] = {evaluate(paths.denominator[0], s), evaluate(paths.denominator[1], s)};
  Point y[4];
  for (int i = 0; i < 4; ++i) {
    const NT& other = w[i < paths.first_side_count ? 1 : 0];
    const auto& X = paths.numerator[i];
    y[i] = {{{NT(evaluate(X.x, s) * other)}},
            {{NT(evaluate(X.y, s) * other)}},
            {{NT(evaluate(X.z, s) * other)}}};
  }
  const NT W = w[0] * w[1];
  const NT delta2 = delta * delta * W * W;
  NT value(0);
  auto read = [&value](const auto& g) { value = g.c[0]; };
  if (type == QueryType::vertex_face)
    vertex_face_separation(y[0], y[1], y[2], y[3], delta2).for_each_polynomial(read, k);
  else
    edge_edge_separation(y[0], y[1], y[2], y[3], delta2).for_each_polynomial(read, k);
  return value;
}

}  // namespace exactccd::predicates
