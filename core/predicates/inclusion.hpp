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

/// The projection the exact phase of the two functions below decides in: the first k whose
/// normal sign is already known (normal[k] != 0), else the first whose exact sign s.normal(k) is
/// non-zero (stored in normal[k]); -1 when every normal vanishes.
template <class Signs>
EXACTCCD_CERTIFIED int projection_with_nonzero_normal(int (&normal)[3], Signs& s) {
  for (int k = 0; k < 3; ++k)
    if (normal[k] != 0) return k;
  for (int k = 0; k < 3; ++k)
    if ((normal[k] = s.normal(k)) != 0) return k;
  return -1;
}

/// Lemma 3 (a) with the orientations' signs asked for by index, known signs first. `s` gives,
/// at the instant under test, for the normal n_k = O_k(a, b, c) (`normal`) and the edge
/// orientations O_k(a, b, p), O_k(b, c, p), O_k(c, a, p) (`edge`, i = 0, 1, 2):
///   s.certain_normal(k), s.certain_edge(k, i): the sign when known cheaply (+1 or -1, never
///     wrong), else 0 ("unknown", never "zero");
///   s.normal(k), s.edge(k, i): the exact sign (-1, 0, +1).
/// Every projection whose normal has a known sign is tried with known signs alone (an edge of
/// sign -s: outside; all three of sign s: inside); then one projection with n_k != 0 (a known
/// one first, else the first exact non-zero) decides with exact signs where none is known.
/// Returns 1 (p in the triangle), 0 (not), or -1 when n = 0 (a degenerate triangle: the caller
/// decides by Lemma 3 (b), as point_in_triangle_at does). Any projection with n_k != 0 gives
/// the exact answer, so the first that decides is right.
/// PROOF: proofs/exact_ccd.md#certain-signs-first
template <class Signs>
EXACTCCD_CERTIFIED int point_in_triangle_by_projections(Signs& s) {
  int normal[3], edge[3][3] = {};
  for (int k = 0; k < 3; ++k) {
    normal[k] = s.certain_normal(k);
    if (normal[k] == 0) continue;
    bool inside = true;
    for (int i = 0; i < 3; ++i) {
      edge[k][i] = s.certain_edge(k, i);
      if (edge[k][i] == -normal[k]) return 0;
      inside = inside && edge[k][i] == normal[k];
    }
    if (inside) return 1;
  }
  const int k = projection_with_nonzero_normal(normal, s);
  if (k < 0) return -1;
  for (int i = 0; i < 3; ++i) {
    const int e = edge[k][i] != 0 ? edge[k][i] : s.edge(k, i);
    if (e == -normal[k]) return 0;
  }
  return 1;
}

/// Lemma 4 (a) in the same way: `normal` is m_k = (d_a x d_b)_k, `edge` (i = 0 ... 3) the
/// orientations O_k(a0, a1, b0), O_k(a0, a1, b1), O_k(b0, b1, a0), O_k(b0, b1, a1). A
/// projection with m_k of known sign decides with known signs alone when o1 = o2 or o3 = o4
/// (both known: no contact), or all four known with o1 = -o2 and o3 = -o4 (contact). Returns
/// 1, 0, or -1 when m = 0 (parallel or degenerate: the caller decides by Lemma 4 (b)).
/// PROOF: proofs/exact_ccd.md#certain-signs-first
template <class Signs>
EXACTCCD_CERTIFIED int segments_intersect_by_projections(Signs& s) {
  int normal[3], edge[3][4] = {};
  for (int k = 0; k < 3; ++k) {
    normal[k] = s.certain_normal(k);
    if (normal[k] == 0) continue;
    int* o = edge[k];
    o[0] = s.certain_edge(k, 0), o[1] = s.certain_edge(k, 1);
    if (o[0] != 0 && o[0] == o[1]) return 0;
    o[2] = s.certain_edge(k, 2), o[3] = s.certain_edge(k, 3);
    if (o[2] != 0 && o[2] == o[3]) return 0;
    if (o[0] != 0 && o[1] == -o[0] && o[2] != 0 && o[3] == -o[2]) return 1;
  }
  const int k = projection_with_nonzero_normal(normal, s);
  if (k < 0) return -1;
  auto sign = [&](int i) { return edge[k][i] != 0 ? edge[k][i] : s.edge(k, i); };
  if (sign(0) * sign(1) > 0) return 0;
  return sign(2) * sign(3) <= 0 ? 1 : 0;
}

}  // namespace exactccd::predicates
