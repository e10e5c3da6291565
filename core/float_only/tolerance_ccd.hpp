// The tolerance-based floating-point CCD test: the common practice that the numerical-stability
// study measures. UNCERTIFIED: it misses contacts and reports false ones.
//
// In plain double arithmetic: the coplanarity cubic's roots in [0, t_max] (the float_only mode's
// root finder, core/float_only/float_only_ccd.hpp), then, earliest first, the distance between the
// primitives at each root (point-triangle for vertex-face, segment-segment for edge-edge); the
// first root where that distance is <= eps is the time of impact. A cubic that vanishes identically
// in doubles (motion coplanar throughout, a zero-length edge, a triangle degenerate throughout)
// yields only the two ends 0 and t_max as candidate roots, as in the classic codes.
//
// eps is an ABSOLUTE distance, as such codes use it, so the method depends on the coordinates'
// scale: eps = 1e-9 is a tight tolerance for a mesh of unit size and a coarse one for a mesh of
// size 1e-9 (a gap as wide as the whole mesh counts as contact), and below the coordinates'
// rounding (about 2^-52 |x|) it is effectively zero for large coordinates.
#pragma once

#include <Eigen/Core>

#include "exactccd/types.hpp"

namespace exactccd::methods {

/// Vertex p against the triangle (a, b, c) over [0, t_max]. The result's toi_lo == toi_hi is
/// the root, decided_by is Stage::float_only.
CcdResult tolerance_vertex_face_ccd(const VertexFaceQuery& query, double eps, double t_max = 1.0);

/// Edge (ea0, ea1) against edge (eb0, eb1) over [0, t_max]; as tolerance_vertex_face_ccd.
CcdResult tolerance_edge_edge_ccd(const EdgeEdgeQuery& query, double eps, double t_max = 1.0);

// ---- The distances, in double arithmetic (exposed for the tests) ------------------------------

/// Distance from p to the closed segment [x, y]; a zero-length segment is the point x.
double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& x,
                              const Eigen::Vector3d& y);

/// Distance from p to the closed triangle (a, b, c). A triangle whose normal cross(b - a, c - a)
/// is zero in doubles (collinear or coincident vertices) is the union of its three sides.
double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Distance between the closed segments [a0, a1] and [b0, b1] (zero-length ones included).
double segment_segment_distance(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                const Eigen::Vector3d& b0, const Eigen::Vector3d& b1);

}  // namespace exactccd::methods
