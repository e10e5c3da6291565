// Inclusion tests at one instant t of coplanar moving primitives, written once over the
// number type. A Point is a Vec3 of FixedPoly<NT, D> (a moving point, D = 1, or a position at
// a fixed time, D = 0). `sign_at(q)` returns the sign (-1, 0, +1) of the polynomial q at the
// instant under test; the exact path evaluates it at an algebraic time exactly.
// PROOF: proofs/exact_ccd.md#inclusion-at-an-instant
#pragma once

#include "core/predicates/coplanarity_cubic.hpp"

namespace exactccd::predicates {

/// p on the closed segment [x, y] (x == y allowed): cross(y - x, p - x) = 0 and
/// (p - x).(p - y) <= 0. PROOF: proofs/exact_ccd.md#lemma-point-on-segment
template <class Point, class SignAt>
EXACTCCD_CERTIFIED bool point_on_segment_at(const Point& p, const Point& x,
                         const Point& y, SignAt&& sign_at) {
  const auto n = cross(y - x, p - x);
  if (sign_at(n.x) != 0 || sign_at(n.y) != 0 || sign_at(n.z) != 0) return false;
  return sign_at(dot(p - x, p - y)) <= 0;
}

/// p in the closed triangle (a, b, c), given that the four points are coplanar at the instant.
/// Non-degenerate triangle: exact orientation signs in a projection along an axis where the
/// normal does not vanish. Degenerate triangle (a segment or a point): the union of its edges.
/// PROOF: proofs/exact_ccd.md#lemma-point-in-triangle
template <class Point, class SignAt>
EXACTCCD_CERTIFIED bool point_in_triangle_at(const Point& p, const Point& a,
                          const Point& b, const Point& c, SignAt&& sign_at) {
  for (int k = 0; k < 3; ++k) {
    const int s = sign_at(orient2d_along_axis(k, a, b, c));
    if (s == 0) continue;
    const int s1 = sign_at(orient2d_along_axis(k, a, b, p));
    if (s1 == -s) return false;
    const int s2 = sign_at(orient2d_along_axis(k, b, c, p));
    if (s2 == -s) return false;
    const int s3 = sign_at(orient2d_along_axis(k, c, a, p));
    return s3 != -s;
  }
  return point_on_segment_at(p, a, b, sign_at) || point_on_segment_at(p, b, c, sign_at) ||
         point_on_segment_at(p, c, a, sign_at);
}

/// Closed segments [a0, a1] and [b0, b1] meet, given that the four endpoints are coplanar.
/// Non-parallel: each segment meets the other's line, in a projection where the directions'
/// cross product does not vanish. Parallel or zero-length: an endpoint lies on the other.
/// PROOF: proofs/exact_ccd.md#lemma-segments-intersect
template <class Point, class SignAt>
EXACTCCD_CERTIFIED bool segments_intersect_at(const Point& a0, const Point& a1,
                           const Point& b0, const Point& b1,
                           SignAt&& sign_at) {
  const auto da = a1 - a0;
  const auto db = b1 - b0;
  const auto m = cross(da, db);
  for (int k = 0; k < 3; ++k) {
    if (sign_at(m[k]) == 0) continue;
    const int o1 = sign_at(orient2d_along_axis(k, a0, a1, b0));
    const int o2 = sign_at(orient2d_along_axis(k, a0, a1, b1));
    if (o1 * o2 > 0) return false;
    const int o3 = sign_at(orient2d_along_axis(k, b0, b1, a0));
    const int o4 = sign_at(orient2d_along_axis(k, b0, b1, a1));
    return o3 * o4 <= 0;
  }
  return point_on_segment_at(a0, b0, b1, sign_at) || point_on_segment_at(a1, b0, b1, sign_at) ||
         point_on_segment_at(b0, a0, a1, sign_at) || point_on_segment_at(b1, a0, a1, sign_at);
}

}  // namespace exactccd::predicates
