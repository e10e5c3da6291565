// Benchmark queries as the double API takes them, when every coordinate is exactly a double.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>

#include "exactccd/rational_query.hpp"
#include "exactccd/types.hpp"

namespace exactccd::oracle {

using QueryPoints = std::array<Eigen::Vector3d, 8>;  ///< benchmark row order

/// The query's coordinates as doubles when each is exactly a double; otherwise nullopt and
/// *bad_row (0-7) is the first row holding one that is not.
std::optional<QueryPoints> exact_doubles(const RationalQuery& query, std::size_t* bad_row);

VertexFaceQuery vertex_face_query(const QueryPoints& p);
EdgeEdgeQuery edge_edge_query(const QueryPoints& p);

}  // namespace exactccd::oracle
