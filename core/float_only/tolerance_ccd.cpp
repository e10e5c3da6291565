// The tolerance method (see tolerance_ccd.hpp): the float_only mode's roots, a distance test in
// doubles at each. Nothing here is certified; it exists to be measured.
#include "core/float_only/tolerance_ccd.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/float_only/float_only_ccd.hpp"
#include "core/predicates/coplanarity_cubic.hpp"

namespace exactccd::methods {

namespace {

using predicates::moving_point;
using Eigen::Vector3d;

/// The position at time t, (1 - t) x0 + t x1: exactly x0 at t = 0 and x1 at t = 1.
Vector3d at(const Vector3d& x0, const Vector3d& x1, double t) { return (1 - t) * x0 + t * x1; }

/// The earliest root of f in [0, t_max] where distance_at(root) <= eps.
template <class DistanceAt>
CcdResult first_root_within(const predicates::FixedPoly<double, 3>& f, double eps, double t_max,
                            DistanceAt&& distance_at) {
  CcdResult r;
  r.decided_by = Stage::float_only;
  double roots[3];
  const int n = float_only::cubic_roots(f, t_max, roots);
  for (int i = 0; i < n; ++i) {
    if (distance_at(roots[i]) <= eps) {
      r.collides = true;
      r.toi_lo = r.toi_hi = roots[i];
      return r;
    }
  }
  return r;
}

}  // namespace

double point_segment_distance(const Vector3d& p, const Vector3d& x, const Vector3d& y) {
  const Vector3d d = y - x;
  const double dd = d.squaredNorm();
  if (dd == 0) return (p - x).norm();
  const double s = std::clamp(d.dot(p - x) / dd, 0.0, 1.0);
  return (p - (x + s * d)).norm();
}

double point_triangle_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                               const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  // p's projection q on the plane is inside iff it is on the inner side of each side: the sign
  // of n . ((y - x) x (q - x)) equals that of n . ((y - x) x (p - x)), as p - q is parallel to n.
  if (nn > 0 && n.dot((b - a).cross(p - a)) >= 0 && n.dot((c - b).cross(p - b)) >= 0 &&
      n.dot((a - c).cross(p - c)) >= 0)
    return std::abs(n.dot(p - a)) / std::sqrt(nn);
  // Otherwise (or for a degenerate triangle) the nearest point lies on a side.
  return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                   point_segment_distance(p, c, a)});
}

double segment_segment_distance(const Vector3d& a0, const Vector3d& a1, const Vector3d& b0,
                                const Vector3d& b1) {
  // The minimum is attained at an endpoint of one segment, or at interior points of both where
  // the lines' common perpendicular meets them (non-parallel lines: unique such pair).
  double best = std::min({point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1),
                          point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)});
  const Vector3d da = a1 - a0, db = b1 - b0, r = a0 - b0;
  const double aa = da.dot(da), ab = da.dot(db), bb = db.dot(db);
  const double ar = da.dot(r), br = db.dot(r);
  const double denom = aa * bb - ab * ab;  // |da x db|^2 >= 0 (Lagrange's identity)
  if (denom > 0) {
    // Minimise |r + s da - u db|^2: s aa - u ab = -ar and s ab - u bb = -br.
    const double s = (ab * br - ar * bb) / denom;
    const double u = (aa * br - ab * ar) / denom;
    if (s >= 0 && s <= 1 && u >= 0 && u <= 1) best = std::min(best, (r + s * da - u * db).norm());
  }
  return best;
}

CcdResult tolerance_vertex_face_ccd(const VertexFaceQuery& q, double eps, double t_max) {
  const auto p = moving_point<double>(q.p_t0, q.p_t1), a = moving_point<double>(q.a_t0, q.a_t1),
             b = moving_point<double>(q.b_t0, q.b_t1), c = moving_point<double>(q.c_t0, q.c_t1);
  return first_root_within(
      predicates::vertex_face_coplanarity_cubic(p, a, b, c), eps, t_max, [&](double t) {
        return point_triangle_distance(at(q.p_t0, q.p_t1, t), at(q.a_t0, q.a_t1, t),
                                       at(q.b_t0, q.b_t1, t), at(q.c_t0, q.c_t1, t));
      });
}

CcdResult tolerance_edge_edge_ccd(const EdgeEdgeQuery& q, double eps, double t_max) {
  const auto a0 = moving_point<double>(q.ea0_t0, q.ea0_t1),
             a1 = moving_point<double>(q.ea1_t0, q.ea1_t1),
             b0 = moving_point<double>(q.eb0_t0, q.eb0_t1),
             b1 = moving_point<double>(q.eb1_t0, q.eb1_t1);
  return first_root_within(
      predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1), eps, t_max, [&](double t) {
        return segment_segment_distance(at(q.ea0_t0, q.ea0_t1, t), at(q.ea1_t0, q.ea1_t1, t),
                                        at(q.eb0_t0, q.eb0_t1, t), at(q.eb1_t0, q.eb1_t1, t));
      });
}

}  // namespace exactccd::methods
