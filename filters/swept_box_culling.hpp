// Culling by swept bounding boxes, with exact comparisons of the input doubles.
//
// A linearly moving point stays in the box of its two positions (convexity), and a moving
// triangle or segment at time t is the convex hull of its moving vertices, so it stays in the
// box of all its vertex positions. Disjoint boxes on one axis exclude contact at every t.
// Only comparisons of input doubles are made: no rounding. PROOF: proofs/filters.md#culling
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <initializer_list>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

namespace exactccd::filters {

/// True when the boxes of the two point sets are disjoint on some axis.
EXACTCCD_CERTIFIED bool swept_boxes_disjoint(std::initializer_list<const Eigen::Vector3d*> first,
                                 std::initializer_list<const Eigen::Vector3d*> second) {
  for (int k = 0; k < 3; ++k) {
    double lo1 = (*first.begin())->coeff(k), hi1 = lo1;
    for (const auto* v : first) {
      lo1 = std::min(lo1, v->coeff(k));
      hi1 = std::max(hi1, v->coeff(k));
    }
    double lo2 = (*second.begin())->coeff(k), hi2 = lo2;
    for (const auto* v : second) {
      lo2 = std::min(lo2, v->coeff(k));
      hi2 = std::max(hi2, v->coeff(k));
    }
    if (hi1 < lo2 || hi2 < lo1) return true;
  }
  return false;
}

}  // namespace exactccd::filters
