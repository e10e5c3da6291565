// Point-edge and point-point CCD, in 3D and in the plane: thin reductions to edge_edge_ccd,
// whose degenerate (zero-length) segments are the points they are. Every coordinate is copied, never computed, so the reduced
// query has exactly the original motion and hence the same contact set, verdict and TOI.
// PROOF: proofs/api_reductions.md#point-primitives
#include "exactccd/ccd.hpp"

#include <stdexcept>
#include <string>

namespace exactccd {

namespace {

/// The point query's own coordinate names in the message (edge_edge_ccd would name the reduced
/// query's, ea0_t0 and so on).
template <class Vector>
void require_finite(const Vector& x, const char* name) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + name);
}

template <class Query>
void require_finite_point_edge(const Query& q) {
  require_finite(q.p_t0, "p_t0");
  require_finite(q.e0_t0, "e0_t0");
  require_finite(q.e1_t0, "e1_t0");
  require_finite(q.p_t1, "p_t1");
  require_finite(q.e0_t1, "e0_t1");
  require_finite(q.e1_t1, "e1_t1");
}

/// (x, y) -> (x, y, 0): exact, and linear motion stays linear (z(t) = 0 throughout).
Eigen::Vector3d in_plane_z0(const Eigen::Vector2d& v) { return {v.x(), v.y(), 0.0}; }

}  // namespace

CcdResult point_edge_ccd(const PointEdgeQuery& q, const CcdOptions& options) {
  require_finite_point_edge(q);
  // Edge a is the zero-length segment [p, p] = {p}.
  return edge_edge_ccd({q.p_t0, q.p_t0, q.e0_t0, q.e1_t0, q.p_t1, q.p_t1, q.e0_t1, q.e1_t1},
                       options);
}

CcdResult point_point_ccd(const PointPointQuery& q, const CcdOptions& options) {
  require_finite(q.p_t0, "p_t0");
  require_finite(q.q_t0, "q_t0");
  require_finite(q.p_t1, "p_t1");
  require_finite(q.q_t1, "q_t1");
  // Both edges zero-length: [p, p] = {p} against [q, q] = {q}.
  return edge_edge_ccd({q.p_t0, q.p_t0, q.q_t0, q.q_t0, q.p_t1, q.p_t1, q.q_t1, q.q_t1},
                       options);
}

CcdResult point_edge_ccd_2d(const PointEdgeQuery2d& q, const CcdOptions& options) {
  require_finite_point_edge(q);
  return point_edge_ccd({in_plane_z0(q.p_t0), in_plane_z0(q.e0_t0), in_plane_z0(q.e1_t0),
                         in_plane_z0(q.p_t1), in_plane_z0(q.e0_t1), in_plane_z0(q.e1_t1)},
                        options);
}

CcdResult point_point_ccd_2d(const PointPointQuery2d& q, const CcdOptions& options) {
  require_finite(q.p_t0, "p_t0");
  require_finite(q.q_t0, "q_t0");
  require_finite(q.p_t1, "p_t1");
  require_finite(q.q_t1, "q_t1");
  return point_point_ccd(
      {in_plane_z0(q.p_t0), in_plane_z0(q.q_t0), in_plane_z0(q.p_t1), in_plane_z0(q.q_t1)},
      options);
}

}  // namespace exactccd
