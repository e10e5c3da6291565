/// \file
/// Exact rational queries for the oracle: every coordinate an exact GMP rational, as the
/// benchmark's CSV files give them (x_num / x_den). Include only where GMP is wanted.
#pragma once

#include <gmpxx.h>

#include <array>

#include "exactccd/export.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// A point with exact rational coordinates (any rationals, not only doubles).
struct RationalPoint {
  mpq_class x;  ///< x coordinate
  mpq_class y;  ///< y coordinate
  mpq_class z;  ///< z coordinate
};

/// A vertex-face or edge-edge query with exact rational coordinates.
struct RationalQuery {
  /// Which primitives the points describe.
  QueryType type = QueryType::vertex_face;
  /// Points in the benchmark's row order: vertex-face p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1,
  /// c_t1; edge-edge ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1.
  std::array<RationalPoint, 8> points;
};

/// Decides the query with the exact path (exact/): exact for every input (\ref semantics),
/// with options.min_separation as the minimum separation (0: contact).
/// \param query any rational coordinates (canonical mpq_class values).
/// \param options t_max in [0, 1] (0: the state at t = 0) and toi_width finite and >= 0; the
///        mode is ignored (always the exact path).
/// \return the verdict and the TOI enclosure (doubles around the exact t*); +infinity TOIs
///         without contact.
/// \throws std::invalid_argument for options outside their domain (see CcdOptions).
EXACTCCD_API CcdResult exact_ccd(const RationalQuery& query, const CcdOptions& options = {});

/// Minimum-separation CCD on the exact path with a rational delta (\ref min_separation): the
/// earliest t in [0, t_max] at which the closed primitives come within Euclidean distance
/// min_separation. The minimum separation is given once: here as the rational argument, so
/// options.min_separation must be left at 0 (a non-zero one is refused, never ignored).
/// \param query any rational coordinates (canonical mpq_class values).
/// \param min_separation delta >= 0; 0 is contact, as exact_ccd(query, options) decides it.
/// \param options t_max in [0, 1] (0: the state at t = 0) and toi_width finite and >= 0;
///        min_separation 0; the mode is ignored.
/// \return the verdict and the TOI enclosure; +infinity TOIs when never within delta.
/// \throws std::invalid_argument for a negative delta, a non-zero options.min_separation
///         ("exactccd: give the minimum separation once: options.min_separation or the
///         rational argument, not both") or options outside their domain.
EXACTCCD_API CcdResult exact_ccd(const RationalQuery& query, const mpq_class& min_separation,
                                 const CcdOptions& options = {});

/// The query's coordinates as exact rationals, in the benchmark's row order.
/// \param query any finite coordinates.
/// \return the same query, exactly.
/// \throws std::invalid_argument for a non-finite coordinate (the message names it).
EXACTCCD_API RationalQuery to_rational(const VertexFaceQuery& query);

/// The query's coordinates as exact rationals, in the benchmark's row order.
/// \param query any finite coordinates.
/// \return the same query, exactly.
/// \throws std::invalid_argument for a non-finite coordinate (the message names it).
EXACTCCD_API RationalQuery to_rational(const EdgeEdgeQuery& query);

}  // namespace exactccd
