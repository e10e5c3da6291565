// Exact rational queries for the oracle: every coordinate an exact GMP rational, as the
// benchmark's CSV files give them (x_num / x_den). Include only where GMP is wanted.
#pragma once

#include <gmpxx.h>

#include <array>

#include "exactccd/types.hpp"

namespace exactccd {

struct RationalPoint {
  mpq_class x, y, z;
};

/// Points in the benchmark's row order: vertex-face p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1,
/// c_t1; edge-edge ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1.
struct RationalQuery {
  QueryType type = QueryType::vertex_face;
  std::array<RationalPoint, 8> points;
};

/// Decides the query with the exact path (exact/): exact for every input. Throws
/// std::invalid_argument for options outside their domain (see CcdOptions).
CcdResult exact_ccd(const RationalQuery& query, const CcdOptions& options = {});

RationalQuery to_rational(const VertexFaceQuery& query);
RationalQuery to_rational(const EdgeEdgeQuery& query);

}  // namespace exactccd
