/// \file
/// The CCD functions: one query (two moving primitives) at a time.
///
/// Every function here is exact for every finite input, degenerate ones included, under the
/// collision semantics of the \ref semantics "main page": `collides` is the true answer for the
/// closed primitives over the closed interval [0, t_max], [toi_lo, toi_hi] encloses the exact
/// earliest contact time, and both TOI fields are +infinity without contact. They are
/// thread-safe (no shared state) and leave the caller's floating-point environment as they
/// found it.
#pragma once

#include "exactccd/export.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// Vertex p against the closed triangle (a, b, c), over [0, options.t_max] (\ref semantics).
/// \param query any finite coordinates (degenerate triangles included).
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate (the message names it) or options
///         outside their domain.
EXACTCCD_API CcdResult vertex_face_ccd(const VertexFaceQuery& query,
                                       const CcdOptions& options = {});

/// Closed segment [ea0, ea1] against the closed segment [eb0, eb1], over [0, options.t_max]
/// (\ref semantics).
/// \param query any finite coordinates (zero-length segments included).
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate (the message names it) or options
///         outside their domain.
EXACTCCD_API CcdResult edge_edge_ccd(const EdgeEdgeQuery& query, const CcdOptions& options = {});

/// Point p against the closed segment [e0, e1] in 3D, over [0, options.t_max]: contact when p
/// lies on the segment (an endpoint included). Exactly edge_edge_ccd of the zero-length
/// segment [p, p] against [e0, e1], which has the same contact set and hence the same verdict
/// and TOI (\ref point_primitives). Throws and returns as edge_edge_ccd.
/// \param query any finite coordinates (a zero-length segment included).
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate or options outside their domain.
EXACTCCD_API CcdResult point_edge_ccd(const PointEdgeQuery& query, const CcdOptions& options = {});

/// Point p against point q in 3D, over [0, options.t_max]: contact when p(t) == q(t). Exactly
/// edge_edge_ccd of the zero-length segments [p, p] and [q, q] (\ref point_primitives).
/// \param query any finite coordinates.
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate or options outside their domain.
EXACTCCD_API CcdResult point_point_ccd(const PointPointQuery& query,
                                       const CcdOptions& options = {});

/// Point p against the closed segment [e0, e1] in the plane, over [0, options.t_max]: the 3D
/// point_edge_ccd of the query embedded in the plane z = 0 (exactly: the embedding adds a zero
/// coordinate and rounds nothing), which has the same contact set (\ref point_primitives).
/// \param query any finite coordinates (a zero-length segment included).
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate or options outside their domain.
EXACTCCD_API CcdResult point_edge_ccd_2d(const PointEdgeQuery2d& query,
                                         const CcdOptions& options = {});

/// Points p and q in the plane, over [0, options.t_max]: the 3D point_point_ccd of the query
/// embedded in the plane z = 0 (exactly, as point_edge_ccd_2d), the same contact set
/// (\ref point_primitives).
/// \param query any finite coordinates.
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate or options outside their domain.
EXACTCCD_API CcdResult point_point_ccd_2d(const PointPointQuery2d& query,
                                          const CcdOptions& options = {});

/// Point p against a plane (\ref point_plane "point-plane CCD"), over [0, options.t_max]:
/// contact when p(t) lies on the plane {x : (x - origin(t)) . normal(t) = 0}, each of p, origin
/// and normal moving linearly (a static plane repeats them); with min_separation delta > 0,
/// when the distance |(p - origin) . normal| / |normal| is at most delta. Exact (the polynomial
/// (p - origin) . normal has degree <= 2, <= 1 for a static plane).
/// \param query finite coordinates, normal_t0 and normal_t1 non-zero.
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0, any mode.
/// \return the verdict and the TOI enclosure; +infinity TOIs without contact.
/// \throws std::invalid_argument for a non-finite coordinate, a zero normal (the message names
///         it) or options outside their domain.
EXACTCCD_API CcdResult point_plane_ccd(const PointPlaneQuery& query,
                                       const CcdOptions& options = {});

}  // namespace exactccd
