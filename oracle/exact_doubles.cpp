#include "oracle/exact_doubles.hpp"

#include "exact/arithmetic/rational.hpp"

namespace exactccd::oracle {

std::optional<QueryPoints> exact_doubles(const RationalQuery& query, std::size_t* bad_row) {
  QueryPoints points;
  for (std::size_t row = 0; row < 8; ++row) {
    const RationalPoint& p = query.points[row];
    double x, y, z;
    if (!exact::to_double_exactly(p.x, &x) || !exact::to_double_exactly(p.y, &y) ||
        !exact::to_double_exactly(p.z, &z)) {
      *bad_row = row;
      return std::nullopt;
    }
    points[row] = {x, y, z};
  }
  return points;
}

VertexFaceQuery vertex_face_query(const QueryPoints& p) {
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

EdgeEdgeQuery edge_edge_query(const QueryPoints& p) {
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

}  // namespace exactccd::oracle
