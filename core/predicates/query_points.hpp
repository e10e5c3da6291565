// A linear query as its eight points, in the benchmark's row order (the four points at t = 0,
// then the same four at t = 1): the one place that spells the fields of both pair kinds.
#pragma once

#include <array>

#include "exactccd/types.hpp"

namespace exactccd::predicates {

using QueryPoints = std::array<const Eigen::Vector3d*, 8>;

inline QueryPoints points_of(const VertexFaceQuery& q) {
  return {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1};
}

inline QueryPoints points_of(const EdgeEdgeQuery& q) {
  return {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
}

/// The four points at t = 0 (`at_end` false) or at t = 1.
template <class Query>
std::array<const Eigen::Vector3d*, 4> points_at(const Query& q, bool at_end) {
  const QueryPoints p = points_of(q);
  const int o = at_end ? 4 : 0;
  return {p[o], p[o + 1], p[o + 2], p[o + 3]};
}

/// Whether every coordinate is finite.
template <class Query>
bool all_finite(const Query& q) {
  for (const Eigen::Vector3d* x : points_of(q))
    if (!x->allFinite()) return false;
  return true;
}

}  // namespace exactccd::predicates
