// The family constructions (see families.hpp).
//
// Every builder works in a canonical frame with exact rationals (GMP) and returns one boundary
// configuration: the rows of the query, its exact first contact time t*, and the outward moves
// of its near misses. The comment above each builder is the proof of its claims: why t* is the
// first contact, and why moving the listed coordinates outward by any delta > 0 (all by the
// same delta) leaves no contact in [0, 1]. Conventions in the proofs: "the cubic" is the
// coplanarity determinant det[b - a, c - a, p - a] (vertex-face) or
// det[a1 - a0, b0 - a0, b1 - a0] (edge-edge); tc = m/n is the contact time in lowest terms and
// unit(tc) = n / 2^floor(log2 n) in [1, 2), so that tc * unit(tc) * w is dyadic for dyadic w.
#include "corpus/families.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>

#include "corpus/construction.hpp"

namespace exactccd::families {

using namespace construction;

namespace {

/// Row of a one-coordinate lateral move that shifts the position at tc: p at t = 0 shifts it
/// by (1 - tc) delta, p at t = 1 by tc delta; both work for tc in (0, 1).
int lateral_row(Rng& r, int row, const Q& tc) {
  if (tc == 1) return row + 4;
  if (tc == 0) return row;
  return r.coin() ? row : row + 4;
}

// ---- triangles in the plane z = 0 ------------------------------------------------------------

using Triangle = std::array<P3, 3>;

/// A random triangle in z = 0, coordinates k/8 in [-size, size], twice its area >= size^2/4.
Triangle random_triangle(Rng& r, const Q& size = 1) {
  for (;;) {
    Triangle t;
    for (P3& v : t) v = P3{size * r.dyadic(-8, 8, 8), size * r.dyadic(-8, 8, 8), Q(0)};
    if (abs(orient2(t[0], t[1], t[2])) >= size * size / 4) return t;
  }
}

/// A sliver: base [0, size] on the x axis, apex at height size * 2^-20.
Triangle sliver_triangle(Rng& r, const Q& size) {
  return {p3(0, 0, 0), p3(size, 0, 0), p3(size * r.dyadic(-8, 16, 8), size * pow2(-20), 0)};
}

/// Axis-aligned moves (axis, sign) in the plane z = 0 that leave the closed half-plane of the
/// line (a, b) that holds c: sign * n[axis] > 0 for the outward normal n. Moving any point of
/// the line by delta > 0 along one of them puts it at signed distance delta |n[axis]| / |n|
/// > 0 outside the half-plane, hence outside the triangle.
std::vector<std::pair<int, int>> outward_axes(const P3& a, const P3& b, const P3& c) {
  P3 n = p3(-(b[1] - a[1]), b[0] - a[0], 0);
  if (sgn(dot(n, c - a)) > 0) n = p3(-n[0], -n[1], 0);
  std::vector<std::pair<int, int>> out;
  for (int axis = 0; axis < 2; ++axis)
    if (sgn(n[axis]) != 0) out.push_back({axis, sgn(n[axis])});
  return out;
}

struct Location {
  P3 point;
  std::string kind;                          // face, edge, vertex
  std::vector<std::pair<int, int>> outward;  // lateral moves that leave the triangle
};

Location face_point(Rng& r, const Triangle& t) {
  const long i = r.uniform(1, 6), j = r.uniform(1, 7 - i), k = 8 - i - j;
  return {frac(1, 8) * (Q(i) * t[0] + Q(j) * t[1] + Q(k) * t[2]), "face", {}};
}
Location edge_point(Rng& r, const Triangle& t) {
  const long i = r.uniform(0, 2);
  const P3 &a = t[i], &b = t[(i + 1) % 3], &c = t[(i + 2) % 3];
  return {a + r.dyadic(1, 7, 8) * (b - a), "edge", outward_axes(a, b, c)};
}
/// At a vertex b the triangle is the intersection of the half-planes of its two edges there:
/// leaving either one leaves the triangle.
Location vertex_point(Rng& r, const Triangle& t) {
  const long i = r.uniform(0, 2);
  const P3 &b = t[i], &a = t[(i + 2) % 3], &c = t[(i + 1) % 3];
  std::vector<std::pair<int, int>> out = outward_axes(b, a, c);
  for (const auto& m : outward_axes(b, c, a))
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  return {b, "vertex", out};
}
Location point_of_kind(Rng& r, const Triangle& t, int kind) {
  switch (kind % 3) {
    case 0:
      return face_point(r, t);
    case 1:
      return vertex_point(r, t);
    default:
      return edge_point(r, t);
  }
}

void set_static_triangle(Construction& c, const Triangle& t) {
  for (int i = 0; i < 3; ++i) set_static(c, 1 + i, t[i]);
}

P3 velocity_with_z(Rng& r) {
  return P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), r.nonzero_dyadic(-8, 8, 8)};
}

// ---- vertex-face builders --------------------------------------------------------------------

// Static triangle T in z = 0; p moves with a velocity W of nonzero z. vf_t0: p(0) = q in T,
// so t* = 0. Near miss: p(0) lifted by delta to the side p moves to: z(t) = (1 - t) s delta +
// t W_z with s = sign(W_z) never vanishes on [0, 1], and p is coplanar with T only if z = 0.
Construction vf_t0(Rng& r, int group) {
  Construction c;
  const Triangle t = random_triangle(r);
  set_static_triangle(c, t);
  const Location loc = point_of_kind(r, t, group);
  const P3 w = velocity_with_z(r);
  c.rows[0] = loc.point;
  c.rows[4] = loc.point + w;
  c.toi = 0;
  c.moves = {{0, 2, sgn(w[2])}};
  c.kind = loc.kind;
  return c;
}

// vf_t1: p(1) = q in T, p(0) = q - W with W_z != 0: z(t) = -(1 - t) W_z vanishes only at
// t = 1, so t* = 1. Near miss: p(1) stops delta short: z(t) = -(1 - t) W_z - t s delta with
// s = sign(W_z), of one strict sign on [0, 1].
Construction vf_t1(Rng& r, int group) {
  Construction c;
  const Triangle t = random_triangle(r);
  set_static_triangle(c, t);
  const Location loc = point_of_kind(r, t, group);
  const P3 w = velocity_with_z(r);
  c.rows[4] = loc.point;
  c.rows[0] = loc.point - w;
  c.toi = 1;
  c.moves = {{4, 2, -sgn(w[2])}};
  c.kind = loc.kind;
  return c;
}

// Static T in z = 0; p(t) = q + (t - tc) V with V_z != 0 crosses z = 0 only at tc, at q, on
// the boundary of T (edge or vertex): t* = tc. Near miss: p(0) (or p(1)) moved by delta along
// an outward axis of an edge through q; the crossing time is unchanged (z untouched) and the
// crossing point moves by (1 - tc) delta (tc delta) along that axis, strictly outside the
// edge's half-plane (outward_axes), hence outside T.
Construction vf_crossing(Rng& r, const Triangle& t, const Location& loc, const Q& tc) {
  Construction c;
  set_static_triangle(c, t);
  set_motion(c, 0, loc.point, unit(tc) * velocity_with_z(r), tc);
  c.toi = tc;
  const auto [axis, sign] = r.pick(loc.outward);
  c.moves = {{lateral_row(r, 0, tc), axis, sign}};
  c.kind = loc.kind;
  return c;
}

Construction vf_interior(Rng& r, int /*group*/) {
  const Triangle t = random_triangle(r);
  const Location loc = edge_point(r, t);
  return vf_crossing(r, t, loc, interior_time(r));
}

Construction vf_vertex(Rng& r, int /*group*/) {
  const Triangle t = random_triangle(r);
  const Location loc = vertex_point(r, t);
  return vf_crossing(r, t, loc, interior_time(r));
}

// Rapid motion through a small or thin triangle T in z = 0: p(0) = (q - H W, H), p(1) =
// (q + F W, -F) with F = 2^10..2^40 (the vertex ends far beyond the face, far to the side
// too). z(t) = H - t (H + F) vanishes only at tc = H / (H + F), where p = q on an edge or at a
// vertex: t* = tc. Near miss: p(0) moved laterally outward, as in vf_crossing.
Construction vf_tunneling(Rng& r, int group) {
  Construction c;
  const Q size = pow2(-static_cast<int>(4 * r.uniform(0, 2)));
  const bool sliver = group % 2 == 1;
  const Triangle t = sliver ? sliver_triangle(r, size) : random_triangle(r, size);
  set_static_triangle(c, t);
  const Location loc = r.coin() ? edge_point(r, t) : vertex_point(r, t);
  const Q h = size * r.dyadic(1, 8, 8);
  const Q f = pow2(static_cast<int>(10 * r.uniform(1, 4)));
  const Q wx = r.dyadic(-8, 8, 8), wy = r.dyadic(-8, 8, 8);
  c.rows[0] = p3(loc.point[0] - h * wx, loc.point[1] - h * wy, h);
  c.rows[4] = p3(loc.point[0] + f * wx, loc.point[1] + f * wy, -f);
  c.toi = canon(h / (h + f));
  const auto [axis, sign] = r.pick(loc.outward);
  c.moves = {{0, axis, sign}};
  c.kind = std::string(sliver ? "sliver-" : "") + loc.kind;
  return c;
}

// Grazing: a = 0, b = (beta, 0, 0) static, c(t) = (cx, g, k (t - tc)) tilts about ab (g a power
// of two), p(t) = (px + nu (t - tc), v + mu (t - tc), k v (t - tc) / g). The cubic is
// b . (c x p) = beta (g p_z - c_z p_y) = -beta k mu (t - tc)^2: a double root at tc and no
// other. At tc the plane is z = 0 and p(tc) = w1 b + w2 c(tc) (v = w2 g) with barycentric
// weights chosen in the face, on an edge or at a vertex: t* = tc. Near miss: p_z(0) moved by
// h = -sign(k mu) delta adds beta g (1 - t) h to the cubic (p_z(1): beta g t h), so the cubic
// is -sign(k mu) [beta |k mu| (t - tc)^2 + beta g (1 - t) delta] (resp. t delta), never zero on
// [0, 1] for tc in (0, 1): never coplanar.
Construction vf_grazing(Rng& r, int group) {
  Construction c;
  const Q tc = interior_time(r), u = unit(tc);
  const Q beta = r.dyadic(2, 8, 4), g = pow2(static_cast<int>(r.uniform(-1, 1)));
  const Q cx = r.dyadic(-4, 4, 4);
  const Q k = u * r.nonzero_dyadic(-8, 8, 8), mu = u * r.nonzero_dyadic(-8, 8, 8),
          nu = u * r.dyadic(-8, 8, 8);
  long w1 = 0, w2 = 0;  // weights of b and c, in eighths
  switch (group % 3) {
    case 0:  // face interior
      w1 = r.uniform(1, 6), w2 = r.uniform(1, 7 - w1);
      c.kind = "face";
      break;
    case 1: {  // inside one of the edges ab, bc, ca
      const long x = r.uniform(1, 7), e = r.uniform(0, 2);
      w1 = e == 0 ? x : e == 1 ? x : 0;
      w2 = e == 0 ? 0 : e == 1 ? 8 - x : x;
      c.kind = "edge";
      break;
    }
    default: {  // at a, b or c
      const long v = r.uniform(0, 2);
      w1 = v == 1 ? 8 : 0;
      w2 = v == 2 ? 8 : 0;
      c.kind = "vertex";
      break;
    }
  }
  const Q v = canon(frac(w2, 8) * g);
  const P3 c_tc = p3(cx, g, 0);
  const P3 p_tc = p3(frac(w1, 8) * beta + frac(w2, 8) * cx, v, 0);
  set_static(c, 1, zero3());
  set_static(c, 2, p3(beta, 0, 0));
  set_motion(c, 3, c_tc, p3(0, 0, k), tc);
  set_motion(c, 0, p_tc, p3(nu, mu, k * v / g), tc);
  c.toi = tc;
  c.moves = {{lateral_row(r, 0, tc), 2, -sgn(k * mu)}};
  return c;
}

// Motion coplanar throughout: everything in z = 0, T static.
// - touch (no in-plane crossing): p(t) = B + (t - tc) V passes through the vertex B of T along
//   a line that has the other two vertices strictly on one side, so it meets T only at B:
//   t* = tc (tc in [0, 1)). Near miss: p(0) moved by delta along an axis pointing away from
//   that side (normal N): p(t) is then at signed distance (1 - t) delta |N_axis| > 0 from the
//   line for t < 1, and at t = 1 on the line but not at B (p(1) - B = (1 - tc) V != 0).
// - crossing: p(t) = q + (t - tc) V enters T through the edge point q, V pointing inward
//   (V . n < 0 for the outward normal n): before tc p is strictly outside the edge's line, so
//   t* = tc. Near miss: p lifted by delta at both times (z(t) = delta): never coplanar.
// - arrival: p(1) = q on an edge, p(0) = q + E with E . n > 0: the signed distance (1 - t)
//   E . n is positive before t = 1, so t* = 1. Near miss: p(1) moved by delta outward: the
//   signed distance (1 - t) E . n + t delta |n_axis| stays positive.
Construction vf_coplanar(Rng& r, int group) {
  Construction c;
  const Triangle t = random_triangle(r);
  set_static_triangle(c, t);
  const long kind = group % 3;
  if (kind == 0) {
    const long i = r.uniform(0, 2);
    const P3 &b = t[i], &a = t[(i + 2) % 3], &cc = t[(i + 1) % 3];
    P3 d;
    Q sa, sc;
    do {
      d = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
      sa = orient2(b, b + d, a), sc = orient2(b, b + d, cc);
    } while (sgn(sa) == 0 || sgn(sa) != sgn(sc));
    // N: the normal of the line pointing away from a and c.
    P3 n = p3(-d[1], d[0], 0);
    if (sgn(dot(n, a - b)) > 0) n = p3(-n[0], -n[1], 0);
    Q tc;
    do tc = any_time(r);
    while (tc == 1);
    set_motion(c, 0, b, unit(tc) * d, tc);
    c.toi = tc;
    std::vector<int> axes;
    for (int axis = 0; axis < 2; ++axis)
      if (sgn(n[axis]) != 0) axes.push_back(axis);
    const int axis = r.pick(axes);
    c.moves = {{0, axis, sgn(n[axis])}};
    c.kind = "touch-vertex";
    return c;
  }
  const long e = r.uniform(0, 2);
  const P3 &a = t[e], &b = t[(e + 1) % 3], &cc = t[(e + 2) % 3];
  P3 n = p3(-(b[1] - a[1]), b[0] - a[0], 0);
  if (sgn(dot(n, cc - a)) > 0) n = p3(-n[0], -n[1], 0);  // outward
  const P3 q = a + r.dyadic(1, 7, 8) * (b - a);
  P3 v;
  do v = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
  while (sgn(dot(v, n)) >= 0);
  if (kind == 1) {
    const Q tc = interior_time(r);
    set_motion(c, 0, q, unit(tc) * v, tc);
    c.toi = tc;
    const int s = r.sign();
    c.moves = {{0, 2, s}, {4, 2, s}};
    c.kind = "crossing";
    return c;
  }
  c.rows[4] = q;
  c.rows[0] = q - v;  // E = -v, E . n > 0
  c.toi = 1;
  const auto [axis, sign] = r.pick(outward_axes(a, b, cc));
  c.moves = {{4, axis, sign}};
  c.kind = "arrival";
  return c;
}

// A vertex sliding in the face's plane (z = 0, T static):
// - inside: p(0) and p(1) in the interior of T; T convex: in T throughout, t* = 0;
// - leaving: p(0) in T, p(1) anywhere: t* = 0;
// - entering: p(t) = q + (t - tc) V enters through the edge point q (V . n < 0): t* = tc.
// Near miss: p lifted by delta at both times (z(t) = delta): never coplanar with T.
Construction vf_sliding_face(Rng& r, int group) {
  Construction c;
  const Triangle t = random_triangle(r);
  set_static_triangle(c, t);
  const long kind = std::array<long, 3>{0, 2, 1}[group % 3];  // inside, entering, leaving
  if (kind == 0) {
    c.rows[0] = face_point(r, t).point;
    c.rows[4] = face_point(r, t).point;
    c.toi = 0;
    c.kind = "inside";
  } else if (kind == 1) {
    c.rows[0] = face_point(r, t).point;
    c.rows[4] = c.rows[0] + P3{r.dyadic(-16, 16, 8), r.dyadic(-16, 16, 8), Q(0)};
    c.toi = 0;
    c.kind = "leaving";
  } else {
    const long e = r.uniform(0, 2);
    const P3 &a = t[e], &b = t[(e + 1) % 3], &cc = t[(e + 2) % 3];
    P3 n = p3(-(b[1] - a[1]), b[0] - a[0], 0);
    if (sgn(dot(n, cc - a)) > 0) n = p3(-n[0], -n[1], 0);
    P3 v;
    do v = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
    while (sgn(dot(v, n)) >= 0);
    const Q tc = interior_time(r);
    set_motion(c, 0, a + r.dyadic(1, 7, 8) * (b - a), unit(tc) * v, tc);
    c.toi = tc;
    c.kind = "entering";
  }
  const int s = r.sign();
  c.moves = {{0, 2, s}, {4, 2, s}};
  return c;
}

// A vertex sliding along the line of the edge AB of T (z = 0, T static); T meets that line
// exactly in the edge [A, B]. p(t) = A + lambda(t) (B - A):
// - entering: lambda(t) = 1 - (t - tc) unit(tc) l with l > 0: beyond B before tc, t* = tc;
// - on the edge at t = 0 (lambda(0) in [0, 1]): t* = 0.
// Near miss: p moved by delta at both times, either along an outward axis of AB (the path is
// then a parallel line strictly outside AB's half-plane) or along z (never coplanar).
Construction vf_sliding_edge(Rng& r, int group) {
  Construction c;
  const Triangle t = random_triangle(r);
  set_static_triangle(c, t);
  const long e = r.uniform(0, 2);
  const P3 &a = t[e], &b = t[(e + 1) % 3], &cc = t[(e + 2) % 3];
  if (group % 2 == 0) {
    const Q tc = any_time(r);
    const Q l = r.dyadic(1, 16, 8);
    set_motion(c, 0, b, unit(tc) * (-l) * (b - a), tc);
    c.toi = tc;
    c.kind = "entering";
  } else {
    c.rows[0] = a + r.dyadic(0, 8, 8) * (b - a);
    c.rows[4] = a + r.dyadic(-16, 24, 8) * (b - a);
    c.toi = 0;
    c.kind = "on-edge";
  }
  if (r.coin()) {
    const auto [axis, sign] = r.pick(outward_axes(a, b, cc));
    c.moves = {{0, axis, sign}, {4, axis, sign}};
  } else {
    const int s = r.sign();
    c.moves = {{0, 2, s}, {4, 2, s}};
  }
  return c;
}

// A triangle collinear throughout: a(t), b(t), c(t) = alpha(t) d, beta(t) d, gamma(t) d on the
// line through 0 along d (two of them equal in kind "two-equal"); the closed triangle is the
// segment [min, max] d of their parameters. p(t) = theta d + (t - tc) V with V not parallel to
// d meets the line only at tc, at theta d, with theta in [min, max](tc) (an end of the segment
// or inside it): t* = tc. Near miss: p(0) (p(1)) moved by delta along an axis e with
// det[V, e, d] != 0: p(t) - (point of the line) = (t - tc) V + (1 - t) delta e (+ multiples of
// d) vanishes only if both coefficients do, t = tc and t = 1 (resp. t = 0): impossible.
Construction vf_collinear_triangle(Rng& r, int group) {
  Construction c;
  P3 d;
  do d = random_vector(r, 4);
  while (sgn(dot(d, d)) == 0);
  const Q tc = any_time(r), u = unit(tc);
  std::array<Q, 3> at_tc = {r.dyadic(-4, 4, 4), r.dyadic(-4, 4, 4), r.dyadic(-4, 4, 4)};
  c.kind = "collinear";
  if (group % 2 == 1) {
    at_tc[1] = at_tc[0];
    c.kind = "two-equal";
  }
  for (int i = 0; i < 3; ++i) {
    const Q speed = u * r.dyadic(-4, 4, 4);
    if (c.kind == "two-equal" && i == 1) {
      c.rows[2] = c.rows[1], c.rows[6] = c.rows[5];
      continue;
    }
    set_motion(c, 1 + i, at_tc[i] * d, speed * d, tc);
  }
  const Q lo = std::min({at_tc[0], at_tc[1], at_tc[2]}),
          hi = std::max({at_tc[0], at_tc[1], at_tc[2]});
  const Q theta = r.coin() ? (r.coin() ? lo : hi) : canon(lo + r.dyadic(0, 8, 8) * (hi - lo));
  P3 v;
  do v = random_vector(r);
  while (sgn(dot(cross(v, d), cross(v, d))) == 0);
  set_motion(c, 0, theta * d, u * v, tc);
  c.toi = tc;
  std::vector<int> axes;
  for (int axis = 0; axis < 3; ++axis) {
    P3 e = zero3();
    e[axis] = 1;
    if (sgn(det3(v, e, d)) != 0) axes.push_back(axis);
  }
  c.moves = {{lateral_row(r, 0, tc), r.pick(axes), r.sign()}};
  return c;
}

// All three vertices equal: the triangle is the point o(t) = (t - tc) U; p(t) = (t - tc) V
// with V != U meets it only at tc: t* = tc. Near miss: p(0) (p(1)) moved by delta along an
// axis e not parallel to V - U: p - o = (t - tc)(V - U) + (1 - t) delta e (resp. t delta e)
// vanishes only if t = tc and t = 1 (resp. 0).
Construction vf_point_triangle(Rng& r, int /*group*/) {
  Construction c;
  const Q tc = any_time(r), u = unit(tc);
  const P3 uo = random_vector(r);
  P3 v;
  do v = random_vector(r);
  while (v == uo);
  for (int i = 1; i <= 3; ++i) set_motion(c, i, zero3(), u * uo, tc);
  set_motion(c, 0, zero3(), u * v, tc);
  c.toi = tc;
  const P3 rel = v - uo;
  std::vector<int> axes;
  for (int axis = 0; axis < 3; ++axis) {
    P3 e = zero3();
    e[axis] = 1;
    if (sgn(dot(cross(rel, e), cross(rel, e))) != 0) axes.push_back(axis);
  }
  c.moves = {{lateral_row(r, 0, tc), r.pick(axes), r.sign()}};
  c.kind = "point";
  return c;
}

// A triangle that degenerates and flips: a = 0, b = (beta, 0, 0), c(t) = (chi + w (t - tf),
// k (tf - t), 0) with 0 < beta < chi, k != 0: c crosses the x axis at tf, where the triangle
// is the segment [0, chi] of the x axis; at any other time it meets the x axis only in [0,
// beta]. p(t) = (chi, y, zeta (tf - t)) + (t - tf)(nu, ny, 0) ends at the far end of that
// segment at tf. Kind "in-plane" (zeta = nu = ny = 0): p = (chi, 0, 0) static, in the plane,
// outside T except at tf. Kind "crossing" (zeta != 0): the cubic is beta k zeta (tf - t)^2,
// zero only at tf. Either way t* = tf. Near miss: p_x(0) (p_x(1)) moved by +delta: p_x >= chi
// > beta throughout and p_x(tf) > chi.
Construction vf_flipping(Rng& r, int group) {
  Construction c;
  const Q tf = interior_time(r), u = unit(tf);
  const Q beta = r.dyadic(1, 4, 4), chi = beta + r.dyadic(1, 4, 4);
  const Q w = u * r.dyadic(-8, 8, 8), k = u * r.nonzero_dyadic(-8, 8, 8);
  set_static(c, 1, zero3());
  set_static(c, 2, p3(beta, 0, 0));
  set_motion(c, 3, p3(chi, 0, 0), p3(w, -k, 0), tf);
  if (group % 2 == 0) {
    set_static(c, 0, p3(chi, 0, 0));
    c.kind = "in-plane";
  } else {
    const Q zeta = u * r.nonzero_dyadic(-8, 8, 8);
    set_motion(c, 0, p3(chi, 0, 0), P3{u * r.dyadic(-8, 8, 8), u * r.dyadic(-8, 8, 8), -zeta}, tf);
    c.kind = "crossing";
  }
  c.toi = tf;
  c.moves = {{lateral_row(r, 0, tf), 0, 1}};
  return c;
}

// Two roots of the cubic in (0, 1), only the later one a contact. a = 0, b = (1, 0, 0) static,
// c(t) = (0, 1, k (t - tm)); p(t) = (px(t), mu (t - s), l(t)) with
// l(t) = k mu [(t - tm)(t - s) - (t - r1)(t - r2)] (linear). The cubic is c_y p_z - c_z p_y =
// -k mu (t - r1)(t - r2). At a root r, p = u b + w c(r) with u = px(r), w = mu (r - s); p is in
// T iff u >= 0, w >= 0, u + w <= 1. px(t) = u2 + rho (r2 - t) with u2 = 1 - w2 puts p on the
// edge bc at r2 (u2, w2 > 0): t* = r2. At r1: kind "sum" (s < r1, rho > mu > 0): u1 + w1 =
// 1 + (r2 - r1)(rho - mu) > 1; kind "side" (r1 < s < r2, mu > 0): w1 < 0. Near miss: px(0)
// (px(1)) moved by +delta: u grows at both roots, w and the roots do not change.
Construction vf_later_root(Rng& r, int group) {
  Construction c;
  const long i1 = r.uniform(1, 13), i2 = r.uniform(i1 + 2, 15);
  const Q r1 = frac(i1, 16), r2 = frac(i2, 16), u = 16;
  const bool sum = group % 2 == 0;
  const long is = sum ? r.uniform(-8, i1 - 1) : r.uniform(i1 + 1, i2 - 1);
  const Q s = frac(is, 16);
  // w2 = mu (r2 - s) in (0, 1): mu = m / 32 with m (i2 - is) < 512.
  const long mmax = std::min<long>(16, (511) / (i2 - is));
  const Q mu = frac(r.uniform(1, mmax), 32);
  const Q w2 = canon(mu * (r2 - s)), u2 = canon(1 - w2);
  const Q rho = sum ? canon(mu + frac(r.uniform(1, 16), 16)) : frac(r.uniform(-16, 16), 16);
  const Q k = u * r.nonzero_dyadic(-8, 8, 64), tm = frac(r.uniform(-16, 32), 16);
  set_static(c, 1, zero3());
  set_static(c, 2, p3(1, 0, 0));
  c.rows[3] = p3(0, 1, -k * tm);
  c.rows[7] = p3(0, 1, k * (1 - tm));
  const auto px = [&](const Q& t) { return canon(u2 + rho * (r2 - t)); };
  const auto l = [&](const Q& t) {
    return canon(k * mu * ((t - tm) * (t - s) - (t - r1) * (t - r2)));
  };
  c.rows[0] = p3(px(0), -mu * s, l(0));
  c.rows[4] = p3(px(1), mu * (1 - s), l(1));
  c.toi = r2;
  c.moves = {{lateral_row(r, 0, r2), 0, 1}};
  c.kind = sum ? "first-root-beyond-edge" : "first-root-beside-edge";
  return c;
}

// ---- edge-edge builders ----------------------------------------------------------------------

// ea = [(-alpha, 0, 0), (L, 0, 0)] static on the x axis; eb(t) = [(xi, -eta0, 0), (xi, eta1,
// 0)] + (t - tc) V, parallel to the y axis, V_z != 0. Both ends of eb have z = (t - tc) V_z
// and ea lies in z = 0, so they can meet only at tc, where eb crosses the x axis at (xi, 0, 0)
// (eta0, eta1 >= 0): contact iff xi in [-alpha, L]. Near misses (all for any delta > 0):
// - "time": eb at tc in {0, 1} pushed off z = 0 by delta to the side it moves to (tc = 0) or
//   comes from (tc = 1): z(t) keeps one strict sign on [0, 1];
// - "ea-end" (xi = L): ea1_x moved by -delta at t = 0 (t = 1): ea stays on the x axis, it ends
//   at L - (1 - tc) delta (L - tc delta) < xi at tc;
// - "eb-end" (eta0 = 0): eb0_y moved by +delta at t = 0 (t = 1): eb's y range at tc is
//   [(1 - tc) delta, eta1] (resp. [tc delta, eta1]), which misses 0.
struct CrossingSetup {
  Q alpha, length, xi, eta0, eta1;
};

Construction ee_cross(const CrossingSetup& s, const P3& v, const Q& tc) {
  Construction c;
  set_static(c, 0, p3(-s.alpha, 0, 0));
  set_static(c, 1, p3(s.length, 0, 0));
  set_motion(c, 2, p3(s.xi, -s.eta0, 0), v, tc);
  set_motion(c, 3, p3(s.xi, s.eta1, 0), v, tc);
  c.toi = tc;
  return c;
}

CrossingSetup random_crossing(Rng& r, bool xi_at_end, bool eta0_zero) {
  CrossingSetup s;
  s.alpha = r.dyadic(0, 8, 8);
  s.length = r.dyadic(1, 8, 8);
  s.xi = xi_at_end ? s.length : canon(-s.alpha + r.dyadic(1, 7, 8) * (s.length + s.alpha));
  s.eta0 = eta0_zero ? Q(0) : r.dyadic(1, 8, 8);
  s.eta1 = r.dyadic(1, 8, 8);
  return s;
}

std::string crossing_kind(bool xi_at_end, bool eta0_zero) {
  if (xi_at_end && eta0_zero) return "endpoint-endpoint";
  if (xi_at_end) return "ea-endpoint";
  if (eta0_zero) return "eb-endpoint";
  return "interiors";
}

Construction ee_time(Rng& r, int group, const Q& tc) {
  const bool at_end = group % 2 == 1, eta0_zero = group % 4 >= 2;
  const P3 v = velocity_with_z(r);
  Construction c = ee_cross(random_crossing(r, at_end, eta0_zero), v, tc);
  const int s = tc == 0 ? sgn(v[2]) : -sgn(v[2]);
  const int row = tc == 0 ? 2 : 6;
  c.moves = {{row, 2, s}, {row + 1, 2, s}};
  c.kind = crossing_kind(at_end, eta0_zero);
  return c;
}

Construction ee_t0(Rng& r, int group) { return ee_time(r, group, Q(0)); }
Construction ee_t1(Rng& r, int group) { return ee_time(r, group, Q(1)); }

Construction ee_end(Rng& r, bool xi_at_end, bool eta0_zero, const Q& tc) {
  const P3 v = unit(tc) * velocity_with_z(r);
  Construction c = ee_cross(random_crossing(r, xi_at_end, eta0_zero), v, tc);
  const bool move_ea = xi_at_end && (!eta0_zero || r.coin());
  if (move_ea)
    c.moves = {{lateral_row(r, 1, tc), 0, -1}};
  else
    c.moves = {{lateral_row(r, 2, tc), 1, 1}};
  c.kind = crossing_kind(xi_at_end, eta0_zero);
  return c;
}

Construction ee_crossing(Rng& r, int group) {
  const bool at_end = group % 2 == 0;
  return ee_end(r, at_end, !at_end, interior_time(r));
}

Construction ee_endpoints(Rng& r, int /*group*/) { return ee_end(r, true, true, interior_time(r)); }

// Rapid motion through a short edge: as ee_cross with xi = L (eb crosses ea's end), eb moving
// from z = H to z = -F (F = 2^10..2^40) and far sideways: eb(t) = eb(tc) + (t - tc)(H + F) W
// with W_z = -1, tc = H / (H + F). Near miss: ea1_x(0) moved by -delta ("ea-end").
Construction ee_tunneling(Rng& r, int /*group*/) {
  const Q size = pow2(-static_cast<int>(4 * r.uniform(0, 2)));
  CrossingSetup s = random_crossing(r, true, false);
  s.alpha *= size, s.length *= size, s.xi *= size;
  const Q h = r.dyadic(1, 8, 8), f = pow2(static_cast<int>(10 * r.uniform(1, 4)));
  const Q tc = canon(h / (h + f));
  const P3 v = (h + f) * P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(-1)};
  Construction c = ee_cross(s, v, tc);
  c.moves = {{1, 0, -1}};
  c.kind = "ea-endpoint";
  return c;
}

// Grazing: ea = [(-alpha, 0, 0), (L, 0, 0)] static; eb in the plane x = xi (both ends moving
// with the same x velocity): eb0 = (., 1, k (t - tm)), eb1 = (., mu (t - s), om(t)) with
// om(t) = k mu [(t - tm)(t - s) - (t - tc)^2] (linear). The cubic is (L + alpha) g(t) with g =
// eb0_y eb1_z - eb0_z eb1_y = om - k (t - tm) mu (t - s) = -k mu (t - tc)^2: one double root.
// At tc, (eb1_y, eb1_z) = mu (tc - s) (eb0_y, eb0_z) with mu (tc - s) < 0: eb crosses the x
// axis at (xi, 0, 0), inside ea (kind "interior") or at its end (kind "ea-endpoint"):
// t* = tc. Near miss: eb1_z(0) (eb1_z(1)) moved by h = -sign(k mu) delta: g becomes
// -sign(k mu) [|k mu| (t - tc)^2 + (1 - t) delta] (resp. t delta): never zero on [0, 1].
Construction ee_grazing(Rng& r, int group) {
  Construction c;
  const Q tc = interior_time(r), u = unit(tc);
  const Q alpha = r.dyadic(0, 8, 8), length = r.dyadic(1, 8, 8);
  const bool at_end = group % 2 == 1;
  const Q xi = at_end ? length : canon(-alpha + r.dyadic(1, 7, 8) * (length + alpha));
  const Q k = u * r.nonzero_dyadic(-8, 8, 8), tm = frac(r.uniform(-8, 16), 8);
  Q mu, s;
  do {
    mu = u * r.nonzero_dyadic(-8, 8, 8);
    s = frac(r.uniform(-8, 16), 8);
  } while (sgn(canon(mu * (tc - s))) >= 0);
  const Q vx = u * r.dyadic(-8, 8, 8);
  set_static(c, 0, p3(-alpha, 0, 0));
  set_static(c, 1, p3(length, 0, 0));
  const auto om = [&](const Q& t) {
    return canon(k * mu * ((t - tm) * (t - s) - (t - tc) * (t - tc)));
  };
  c.rows[2] = p3(xi - tc * vx, 1, -k * tm);
  c.rows[6] = p3(xi + (1 - tc) * vx, 1, k * (1 - tm));
  c.rows[3] = p3(xi - tc * vx, -mu * s, om(0));
  c.rows[7] = p3(xi + (1 - tc) * vx, mu * (1 - s), om(1));
  c.toi = tc;
  c.moves = {{lateral_row(r, 3, tc), 2, -sgn(k * mu)}};
  c.kind = at_end ? "ea-endpoint" : "interior";
  return c;
}

// Two roots of the cubic in (0, 1), only the later a contact. ea = [(-alpha,0,0), (L,0,0)],
// eb in the plane x = L: eb0 = (L, 1, k (t - tm)), eb1 = (L, mu (t - s), om(t)) with
// om(t) = k mu [(t - tm)(t - s) - (t - r1)(t - r2)], mu < 0, r1 < s < r2. As in ee_grazing
// the cubic is -(L + alpha) k mu (t - r1)(t - r2), and at a root r, eb1 = mu (r - s) eb0 in
// (y, z): at r1 the factor is > 0 (both ends on one side of the x axis: no contact), at r2 it
// is < 0 (eb crosses the x axis at (L, 0, 0), ea's end): t* = r2. Near miss: ea1_x(0)
// (ea1_x(1)) moved by -delta: ea stays on the x axis (the roots do not move) and ends short
// of L at r2.
Construction ee_later_root(Rng& r, int /*group*/) {
  Construction c;
  const long i1 = r.uniform(1, 12), i2 = r.uniform(i1 + 2, 15);
  const Q r1 = frac(i1, 16), r2 = frac(i2, 16), u = 16;
  const Q s = frac(r.uniform(i1 + 1, i2 - 1), 16);
  const Q mu = u * r.nonzero_dyadic(-8, -1, 8), k = u * r.nonzero_dyadic(-8, 8, 8);
  const Q tm = frac(r.uniform(-16, 32), 16);
  const Q alpha = r.dyadic(0, 8, 8), length = r.dyadic(1, 8, 8);
  set_static(c, 0, p3(-alpha, 0, 0));
  set_static(c, 1, p3(length, 0, 0));
  const auto om = [&](const Q& t) {
    return canon(k * mu * ((t - tm) * (t - s) - (t - r1) * (t - r2)));
  };
  c.rows[2] = p3(length, 1, -k * tm);
  c.rows[6] = p3(length, 1, k * (1 - tm));
  c.rows[3] = p3(length, -mu * s, om(0));
  c.rows[7] = p3(length, mu * (1 - s), om(1));
  c.toi = r2;
  c.moves = {{lateral_row(r, 1, r2), 0, -1}};
  c.kind = "first-root-one-side";
  return c;
}

// Motion coplanar throughout (z = 0): ea = [(0,0,0), (L,0,0)] static, eb translating in the
// plane.
// - slide (no in-plane crossing): eb0(t) = (L - (t - tc) v, 0) slides along ea's line into
//   ea's end (v > 0), eb1 = eb0 + (dx, dy) with dy > 0; eb meets the line y = 0 only at eb0,
//   beyond L before tc: t* = tc. Near miss: eb0_y lifted by delta at both times: every point
//   of eb has y > 0.
// - crossing: eb descends (V_y < 0) onto ea: eb0(tc) = (x0, 0) with x0 in [0, L], eb1 = eb0 +
//   (dx, dy), dy > 0; before tc every point of eb has y > 0: t* = tc. Near miss: eb lifted
//   out of the plane by delta (z = delta at all four eb rows).
// - arrival: the same with tc = 1; near miss: eb0_y(1) moved by +delta: eb0_y(t) = (1 - t)
//   eb0_y(0) + t delta > 0 and eb1_y > 0 at both ends, so every point of eb has y > 0.
Construction ee_coplanar(Rng& r, int group) {
  Construction c;
  const Q length = r.dyadic(1, 8, 8);
  set_static(c, 0, zero3());
  set_static(c, 1, p3(length, 0, 0));
  const P3 d = P3{r.dyadic(-8, 8, 8), r.dyadic(1, 8, 8), Q(0)};
  const long kind = group % 3;
  if (kind == 0) {
    const Q tc = any_time(r), u = unit(tc);
    const P3 v = p3(-u * r.dyadic(1, 8, 8), 0, 0);
    set_motion(c, 2, p3(length, 0, 0), v, tc);
    set_motion(c, 3, p3(length, 0, 0) + d, v, tc);
    c.toi = tc;
    c.moves = {{2, 1, 1}, {6, 1, 1}};
    c.kind = "slide-touch";
    return c;
  }
  const Q tc = kind == 1 ? interior_time(r) : Q(1), u = unit(tc);
  const P3 v = u * P3{r.dyadic(-8, 8, 8), -r.dyadic(1, 8, 8), Q(0)};
  const P3 at = p3(r.dyadic(0, 8, 8) * length, 0, 0);
  set_motion(c, 2, at, v, tc);
  set_motion(c, 3, at + d, v, tc);
  c.toi = tc;
  if (kind == 1) {
    c.moves = {{2, 2, 1}, {3, 2, 1}, {6, 2, 1}, {7, 2, 1}};
    c.kind = "crossing";
  } else {
    c.moves = {{6, 1, 1}};
    c.kind = "arrival";
  }
  return c;
}

// An endpoint sliding along the other edge's line: eb = [(0,0,0), (L,0,0)] static; ea0 moves on
// the x axis, ea1 stays off it (ea1_y > 0 at both times), so ea meets the x axis only at ea0
// (the cubic vanishes identically). Kind "entering": ea0_x(t) = L - (t - tc) v, v > 0: t* = tc;
// kind "on-edge": ea0_x(0) in [0, L]: t* = 0. Near miss: ea0 lifted by delta at both times,
// along +y (every point of ea has y > 0) or along z (the only point of ea with y = 0 is ea0,
// now off the axis).
Construction ee_sliding(Rng& r, int group) {
  Construction c;
  const Q length = r.dyadic(1, 8, 8);
  set_static(c, 2, zero3());
  set_static(c, 3, p3(length, 0, 0));
  if (group % 2 == 0) {
    const Q tc = any_time(r), u = unit(tc);
    set_motion(c, 0, p3(length, 0, 0), p3(-u * r.dyadic(1, 8, 8), 0, 0), tc);
    c.toi = tc;
    c.kind = "entering";
  } else {
    c.rows[0] = p3(r.dyadic(0, 8, 8) * length, 0, 0);
    c.rows[4] = p3(r.dyadic(-16, 24, 8), 0, 0);
    c.toi = 0;
    c.kind = "on-edge";
  }
  c.rows[1] = P3{r.dyadic(-8, 8, 8), r.dyadic(1, 8, 8), r.dyadic(-8, 8, 8)};
  c.rows[5] = P3{r.dyadic(-8, 8, 8), r.dyadic(1, 8, 8), r.dyadic(-8, 8, 8)};
  if (r.coin())
    c.moves = {{0, 1, 1}, {4, 1, 1}};
  else {
    const int s = r.sign();
    c.moves = {{0, 2, s}, {4, 2, s}};
  }
  return c;
}

// Parallel edges: ea = [(0,0,0), (L,0,0)] static; eb = [b0, b1] x {(0, (t - tc) unit W)},
// parallel to the x axis in the plane y = 0, sliding along x rigidly; the lines coincide only
// at tc. Kind "overlap": eb's x range overlaps ea's at tc; near miss: eb lifted by delta in y
// (all four eb rows): eb stays in y = delta. Kind "endpoint": eb starts at x = L at tc
// (touching ea's end); near miss: eb0_x moved by +delta at both times, so at tc eb lies in
// x > L (at other times the lines do not meet). Disjoint parallel edges are those near misses.
Construction ee_parallel(Rng& r, int group) {
  Construction c;
  const Q tc = any_time(r), u = unit(tc);
  const Q length = r.dyadic(1, 8, 8);
  set_static(c, 0, zero3());
  set_static(c, 1, p3(length, 0, 0));
  const P3 v = u * P3{r.dyadic(-8, 8, 8), Q(0), r.nonzero_dyadic(-8, 8, 8)};
  const bool overlap = group % 2 == 0;
  Q b0, b1;
  if (overlap) {
    b0 = r.dyadic(-8, 7, 8) * length;
    b1 = canon(std::max(b0, Q(0)) + r.dyadic(1, 8, 8));
  } else {
    b0 = length;
    b1 = canon(length + r.dyadic(1, 8, 8));
  }
  set_motion(c, 2, p3(b0, 0, 0), v, tc);
  set_motion(c, 3, p3(b1, 0, 0), v, tc);
  c.toi = tc;
  if (overlap)
    c.moves = {{2, 1, 1}, {3, 1, 1}, {6, 1, 1}, {7, 1, 1}};
  else
    c.moves = {{2, 0, 1}, {6, 0, 1}};
  c.kind = overlap ? "overlap" : "endpoint";
  return c;
}

// Collinear throughout on the x axis: ea = [0, L] static; eb = [b0(t), b1(t)] with b0 < b1 at
// both times (hence throughout).
// - "touch": b0(t) = L - (t - tc) v, v > 0 (b1 moving independently): eb lies beyond L before
//   tc: t* = tc. Near miss: eb lifted by delta in y (all four rows): parallel, never touching.
// - "arrival": b0(1) = L, b0(0) > L: t* = 1. Near miss: b0(1) moved by +delta: b0(t) > L on
//   [0, 1].
Construction ee_collinear(Rng& r, int group) {
  Construction c;
  const Q length = r.dyadic(1, 8, 8);
  set_static(c, 0, zero3());
  set_static(c, 1, p3(length, 0, 0));
  if (group % 2 == 0) {
    const Q tc = any_time(r), u = unit(tc);
    const Q v = u * r.dyadic(1, 8, 8);
    set_motion(c, 2, p3(length, 0, 0), p3(-v, 0, 0), tc);
    const Q b1_0 = canon(c.rows[2][0] + r.dyadic(1, 8, 8)),
            b1_1 = canon(c.rows[6][0] + r.dyadic(1, 8, 8));
    c.rows[3] = p3(b1_0, 0, 0);
    c.rows[7] = p3(b1_1, 0, 0);
    c.toi = tc;
    c.moves = {{2, 1, 1}, {3, 1, 1}, {6, 1, 1}, {7, 1, 1}};
    c.kind = "touch";
  } else {
    c.rows[2] = p3(length + r.dyadic(1, 8, 8), 0, 0);
    c.rows[6] = p3(length, 0, 0);
    c.rows[3] = p3(c.rows[2][0] + r.dyadic(1, 8, 8), 0, 0);
    c.rows[7] = p3(length + r.dyadic(1, 8, 8), 0, 0);
    c.toi = 1;
    c.moves = {{6, 0, 1}};
    c.kind = "arrival";
  }
  return c;
}

// Zero-length edges: ea0 = ea1 = P(t) = q + (t - tc) V with V_z != 0; eb = [0, L] on the x
// axis (or eb0 = eb1 = 0, kind "point-point"), q = (x, 0, 0) in eb. P meets the x axis only
// when P_z = (t - tc) V_z = 0: t* = tc. Near miss: ea0_y and ea1_y moved by delta at t = 0
// (t = 1): then P_y(tc) = (1 - tc) delta (tc delta) != 0.
Construction ee_zero_length(Rng& r, int group) {
  Construction c;
  const Q tc = any_time(r), u = unit(tc);
  // Kinds 0 point-edge-interior, 1 point-edge-endpoint, 2 point-point, in the order 0, 2, 1.
  const long kind = std::array<long, 3>{0, 2, 1}[group % 3];
  const Q length = kind == 2 ? Q(0) : r.dyadic(1, 8, 8);
  set_static(c, 2, zero3());
  set_static(c, 3, p3(length, 0, 0));
  const Q x = kind == 0 ? canon(r.dyadic(1, 7, 8) * length) : (r.coin() ? length : Q(0));
  const P3 v = u * velocity_with_z(r);
  set_motion(c, 0, p3(x, 0, 0), v, tc);
  c.rows[1] = c.rows[0], c.rows[5] = c.rows[4];
  c.toi = tc;
  const int row = lateral_row(r, 0, tc), s = r.sign();
  c.moves = {{row, 1, s}, {row + 1, 1, s}};
  c.kind = kind == 0 ? "point-edge-interior" : kind == 1 ? "point-edge-endpoint" : "point-point";
  return c;
}

// ---- resting contact and stacked faces ---------------------------------------------------------

// A plane that is not vertical, P: z = s1 x + s2 y + c (slopes k/4 in [-1, 1], c = k/8 in
// [-1, 1]), and h(x) = x_z - s1 x_x - s2 x_y - c, the vertical offset of a point from it. h is
// affine, so h(x(t)) = (1 - t) h(x(0)) + t h(x(1)) for a linearly moving point: a point in P at
// t = 0 and t = 1 is in P throughout, and a triangle or edge whose vertices are is contained in
// P throughout. lift maps the xy plane affinely onto P (it preserves convex combinations), so a
// point of a closed triangle or segment of the xy plane lifts to a point of the lifted one.
struct TiltedPlane {
  Q s1, s2, c;
};

TiltedPlane random_tilted_plane(Rng& r) {
  TiltedPlane p;
  p.s1 = r.dyadic(-4, 4, 4);
  p.s2 = r.dyadic(-4, 4, 4);
  p.c = r.dyadic(-8, 8, 8);
  return p;
}

/// The point of P above (x, y) of a point of the xy plane.
P3 lift(const TiltedPlane& p, const P3& xy) {
  return p3(xy[0], xy[1], p.s1 * xy[0] + p.s2 * xy[1] + p.c);
}

/// A velocity parallel to P: (vx, vy, s1 vx + s2 vy), vx, vy = k/8 in [-1, 1].
P3 in_plane_velocity(Rng& r, const TiltedPlane& p) {
  const Q vx = r.dyadic(-8, 8, 8), vy = r.dyadic(-8, 8, 8);
  return p3(vx, vy, p.s1 * vx + p.s2 * vy);
}

// A vertex resting on a face that moves within its (tilted) plane P; T(0) is the lift of a
// random triangle of the xy plane, p(0) the lift of a point q of that triangle (inside, on an
// edge or at a vertex), so p(0) is in T(0): t* = 0. Every vertex is in P at t = 0 and t = 1,
// hence T(t) and p(t) lie in P throughout (coplanar motion).
// - riding: T translates by an in-plane V and p moves with it (p on the face throughout);
// - sliding: T translates by V, p by its own in-plane velocity W (it may leave the face);
// - deforming: every vertex of T and p moves to its own point of P.
// Near misses (any delta > 0): (a) p lifted by delta along z at both times: h(p(t)) = +-delta
// for every t while T(t) lies in P, never coplanar; (b) riding, q on an edge or at a vertex:
// p(0), p(1) moved by delta along an outward axis of an edge through q (outward_axes, x or y).
// Project along z: T(t) projects onto the xy triangle translated by t V_xy and p(t) onto q +
// delta e + t V_xy, so p(t) in T(t) would put q + delta e in the xy triangle; but q + delta e is
// strictly outside that edge's half-plane.
Construction vf_resting(Rng& r, int group) {
  Construction c;
  const TiltedPlane plane = random_tilted_plane(r);
  const Triangle t = random_triangle(r);
  const long kind = group % 3;
  const Location loc = point_of_kind(r, t, static_cast<int>(r.uniform(0, 2)));
  const P3 v = in_plane_velocity(r, plane);
  for (int i = 0; i < 3; ++i) {
    c.rows[1 + i] = lift(plane, t[i]);
    c.rows[5 + i] = kind == 2 ? lift(plane, P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)})
                              : c.rows[1 + i] + v;
  }
  c.rows[0] = lift(plane, loc.point);
  if (kind == 0)
    c.rows[4] = c.rows[0] + v;
  else if (kind == 1)
    c.rows[4] = c.rows[0] + in_plane_velocity(r, plane);
  else
    c.rows[4] = lift(plane, P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)});
  c.toi = 0;
  if (kind == 0 && !loc.outward.empty() && r.coin()) {
    const auto [axis, sign] = r.pick(loc.outward);
    c.moves = {{0, axis, sign}, {4, axis, sign}};
  } else {
    const int s = r.sign();
    c.moves = {{0, 2, s}, {4, 2, s}};
  }
  c.kind = std::string(kind == 0 ? "riding-" : kind == 1 ? "sliding-" : "deforming-") + loc.kind;
  return c;
}

// Edges sliding along each other, in contact at t = 0 (t* = 0).
// - collinear: all four ends on the line L = {o + s d} at t = 0 and t = 1 (each end moving along
//   L with its own speed), so both edges lie in L throughout; at t = 0, eb0 = ea0 + lambda
//   (ea1 - ea0), lambda = k/8 in [0, 1], is a point of ea. Near miss: eb (its four rows) moved by
//   delta along an axis e not parallel to d: eb then lies in the line L + delta e, parallel to
//   L and distinct from it, throughout; parallel distinct lines do not meet.
// - crossing / endpoint: both edges in a tilted plane P (ends lifted from the xy plane at both
//   times), crossing at t = 0 at X = lift(ea0 + lambda (ea1 - ea0)) with eb = [X - mu w, X +
//   (1 - mu) w] (lambda = k/8 in [0, 1], mu = k/8 in (0, 1) for a crossing, mu = 0 for an
//   endpoint of eb on ea); each edge translates by its own in-plane velocity, or each end moves
//   to its own point of P. Near miss: eb (four rows) lifted by delta along z: h = +-delta on eb
//   throughout while ea lies in P.
Construction ee_resting(Rng& r, int group) {
  Construction c;
  const long kind = group % 3;
  if (kind == 0) {
    const P3 o = random_vector(r);
    P3 d;
    do d = random_vector(r, 4);
    while (sgn(dot(d, d)) == 0);
    const Q a0 = r.dyadic(-8, 8, 8), a1 = r.dyadic(-8, 8, 8);
    const Q b0 = canon(a0 + r.dyadic(0, 8, 8) * (a1 - a0)), b1 = r.dyadic(-8, 8, 8);
    const std::array<Q, 4> s0 = {a0, a1, b0, b1};
    for (int i = 0; i < 4; ++i) {
      c.rows[i] = o + s0[i] * d;
      c.rows[i + 4] = o + canon(s0[i] + r.dyadic(-8, 8, 8)) * d;
    }
    std::vector<int> axes;
    for (int axis = 0; axis < 3; ++axis) {
      P3 e = zero3();
      e[axis] = 1;
      if (sgn(dot(cross(d, e), cross(d, e))) != 0) axes.push_back(axis);
    }
    const int axis = r.pick(axes), s = r.sign();
    c.moves = {{2, axis, s}, {3, axis, s}, {6, axis, s}, {7, axis, s}};
    c.toi = 0;
    c.kind = "collinear";
    return c;
  }
  const TiltedPlane plane = random_tilted_plane(r);
  P3 a0, a1, w;
  do {
    a0 = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
    a1 = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
    w = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
  } while (sgn(orient2(zero3(), a1 - a0, w)) == 0);  // not parallel (nor zero)
  const P3 x = a0 + r.dyadic(0, 8, 8) * (a1 - a0);
  const Q mu = kind == 1 ? r.dyadic(1, 7, 8) : Q(0);
  const std::array<P3, 4> at0 = {a0, a1, x - mu * w, x + canon(1 - mu) * w};
  const bool rigid = r.coin();
  const P3 va = in_plane_velocity(r, plane), vb = in_plane_velocity(r, plane);
  for (int i = 0; i < 4; ++i) {
    c.rows[i] = lift(plane, at0[i]);
    c.rows[i + 4] = rigid ? c.rows[i] + (i < 2 ? va : vb)
                          : lift(plane, P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)});
  }
  const int s = r.sign();
  c.moves = {{2, 2, s}, {3, 2, s}, {6, 2, s}, {7, 2, s}};
  c.toi = 0;
  c.kind = std::string(kind == 1 ? "crossing" : "endpoint") + (rigid ? "-translating" : "-free");
  return c;
}

/// A gap 2^-20, 2^-30, 2^-40 or 2^-48 of random sign. The other coordinates of these builders
/// are multiples of 2^-8 below 2^5 in magnitude (also after the frame), so a coordinate plus
/// such a gap has at most 53 significant bits: a double (place() checks every coordinate and
/// the builder is retried otherwise).
Q random_gap(Rng& r) {
  static const std::vector<int> kGaps = {20, 30, 40, 48};
  return r.sign() * pow2(-r.pick(kGaps));
}

// Stacked faces: the triangle (edge ea) in a tilted plane P, moving within it (T(t), ea(t) in P
// throughout, as in vf_resting), and the vertex (edge eb) in the parallel layer h = g(t).
// - coplanar: g = 0 throughout: p (eb) rides on the face (crosses ea) with the same in-plane
//   velocity, in contact from t = 0: t* = 0. Near misses: p (eb, four rows) lifted by delta
//   along z at both times: g = +-delta throughout, never coplanar (a stack at gap delta).
// - landing: g(t) = (1 - t) G with G = +-2^-20 .. 2^-48 (random_gap): the layer closes at t = 1,
//   where p is on the face (eb crosses ea; both translated in-plane): g(t) != 0 for t < 1, so
//   t* = 1. p (eb) also slides tangentially (its own in-plane velocity). Near misses: p(1)
//   (eb0(1), eb1(1)) moved by delta along z in G's direction: g(t) = (1 - t) G + t sign(G)
//   delta has one strict sign on [0, 1]: no contact.
Construction vf_stacked(Rng& r, int group) {
  Construction c;
  const TiltedPlane plane = random_tilted_plane(r);
  const Triangle t = random_triangle(r);
  const bool landing = group % 2 == 1;
  const Location loc = point_of_kind(r, t, static_cast<int>(r.uniform(0, 2)));
  const P3 v = in_plane_velocity(r, plane);
  for (int i = 0; i < 3; ++i) {
    c.rows[1 + i] = lift(plane, t[i]);
    c.rows[5 + i] = c.rows[1 + i] + v;
  }
  if (!landing) {
    c.rows[0] = lift(plane, loc.point);
    c.rows[4] = c.rows[0] + v;
    c.toi = 0;
    const int s = r.sign();
    c.moves = {{0, 2, s}, {4, 2, s}};
    c.kind = "coplanar-" + loc.kind;
    return c;
  }
  const Q gap = random_gap(r);
  c.rows[4] = lift(plane, loc.point) + v;
  c.rows[0] = c.rows[4] - in_plane_velocity(r, plane) + p3(0, 0, gap);
  c.toi = 1;
  c.moves = {{4, 2, sgn(gap)}};
  c.kind = "landing-" + loc.kind;
  return c;
}

Construction ee_stacked(Rng& r, int group) {
  Construction c;
  const TiltedPlane plane = random_tilted_plane(r);
  const bool landing = group % 2 == 1;
  P3 a0, a1, w;
  do {
    a0 = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
    a1 = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
    w = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
  } while (sgn(orient2(zero3(), a1 - a0, w)) == 0);
  const P3 x = a0 + r.dyadic(0, 8, 8) * (a1 - a0);
  const Q mu = r.dyadic(0, 8, 8);
  const std::array<P3, 4> crossing = {a0, a1, x - mu * w, x + canon(1 - mu) * w};
  const P3 v = in_plane_velocity(r, plane);
  if (!landing) {
    for (int i = 0; i < 4; ++i) {
      c.rows[i] = lift(plane, crossing[i]);
      c.rows[i + 4] = c.rows[i] + v;
    }
    c.toi = 0;
    const int s = r.sign();
    c.moves = {{2, 2, s}, {3, 2, s}, {6, 2, s}, {7, 2, s}};
    c.kind = "coplanar";
    return c;
  }
  const Q gap = random_gap(r);
  const P3 vb = in_plane_velocity(r, plane);
  for (int i = 0; i < 4; ++i) {
    c.rows[i + 4] = lift(plane, crossing[i]) + v;
    c.rows[i] = i < 2 ? lift(plane, crossing[i]) : c.rows[i + 4] - vb + p3(0, 0, gap);
  }
  c.toi = 1;
  c.moves = {{6, 2, sgn(gap)}, {7, 2, sgn(gap)}};
  c.kind = "landing";
  return c;
}

// ---------------------------------------------------------------------------------------------
// The family table

/// Builds the boundary configuration of group `group` (0, 1, ...): sub-kinds alternate with
/// the group, so that a few groups cover them all.
using Builder = Construction (*)(Rng&, int group);

struct BaseFamily {
  const char* name;
  QueryType type;
  Builder build;
  const char* description;
};

const std::vector<BaseFamily>& base_families() {
  static const std::vector<BaseFamily> table = {
      {"vf_t0", QueryType::vertex_face, vf_t0,
       "Contact exactly at t = 0 (the vertex on the face, an edge or a vertex of a static "
       "triangle, then moving off its plane); near misses: the vertex starts 1 ulp / 2^-k off "
       "the plane on the side it moves to."},
      {"vf_t1", QueryType::vertex_face, vf_t1,
       "Contact exactly at t = 1 (the vertex reaches the face, an edge or a vertex); near "
       "misses: it stops 1 ulp / 2^-k short of the plane."},
      {"vf_interior", QueryType::vertex_face, vf_interior,
       "Contact at an interior time t* (1/2, 1/3, 3/7, 2^-10, 2^-30, 1 - 2^-20, ...): the "
       "vertex crosses the plane of a static triangle exactly on an edge; near misses: the "
       "vertex moved laterally outward by 1 ulp / 2^-k (same crossing time, crossing point "
       "outside)."},
      {"vf_vertex", QueryType::vertex_face, vf_vertex,
       "The vertex crosses the face's plane exactly through a vertex of the triangle at an "
       "interior time; near misses: moved laterally outward."},
      {"vf_grazing", QueryType::vertex_face, vf_grazing,
       "Grazing contact: the triangle tilts about an edge so that the coplanarity cubic has a "
       "double root at t*, where the vertex touches the face interior, an edge or a vertex "
       "without crossing; near misses: the vertex moved 1 ulp / 2^-k along the normal so the "
       "cubic has no real root in [0, 1]."},
      {"vf_coplanar", QueryType::vertex_face, vf_coplanar,
       "Motion coplanar throughout: the vertex touches a triangle vertex without an in-plane "
       "crossing (near misses: its path moved outward), crosses an edge into the face (near "
       "misses: lifted off the plane), or arrives on an edge at t = 1 (near misses: stops "
       "short)."},
      {"vf_sliding_face", QueryType::vertex_face, vf_sliding_face,
       "A vertex sliding in the face: inside throughout, leaving, or entering through an edge "
       "(coplanar motion); near misses: sliding 1 ulp / 2^-k above the face."},
      {"vf_sliding_edge", QueryType::vertex_face, vf_sliding_edge,
       "A vertex sliding along the line of an edge: on the edge from t = 0, or entering it "
       "through its end; near misses: the path moved outward in the plane or off the plane."},
      {"vf_collinear_triangle", QueryType::vertex_face, vf_collinear_triangle,
       "Degenerate triangles collinear throughout (three distinct collinear vertices, or two "
       "equal) whose vertices slide along their line; the vertex crosses the segment at an "
       "end or inside; near misses: moved 1 ulp / 2^-k off the line."},
      {"vf_point_triangle", QueryType::vertex_face, vf_point_triangle,
       "All three triangle vertices equal (a moving point); the vertex passes through it; "
       "near misses: moved 1 ulp / 2^-k aside."},
      {"vf_flipping", QueryType::vertex_face, vf_flipping,
       "A triangle that degenerates into a segment and flips during the step; the vertex "
       "touches the far end of that segment at the flip (in the plane, or crossing it: a "
       "double root of the cubic); near misses: the vertex moved 1 ulp / 2^-k beyond."},
      {"vf_later_root", QueryType::vertex_face, vf_later_root,
       "Two roots of the coplanarity cubic in (0, 1): the vertex is outside the triangle at "
       "the first and on an edge at the second (t* = the later root); near misses: moved "
       "1 ulp / 2^-k outward, so neither root is a contact."},
      {"vf_tunneling", QueryType::vertex_face, vf_tunneling,
       "Rapid motion through a small or sliver triangle: the vertex ends 2^10 to 2^40 beyond "
       "the face (t* = H / (H + F), tiny); it crosses on an edge or at a vertex; near misses: "
       "moved laterally outward by 1 ulp / 2^-k."},
      {"vf_resting", QueryType::vertex_face, vf_resting,
       "Resting contact: the vertex on a face (inside, on an edge or at a vertex) of a tilted "
       "plane from t = 0, the face moving within its plane (translating or deforming) and the "
       "vertex riding on it or sliding in the plane; near misses: the vertex 1 ulp / 2^-k off "
       "the plane, or (riding) moved 1 ulp / 2^-k outward in the plane."},
      {"vf_stacked", QueryType::vertex_face, vf_stacked,
       "Stacked faces: the vertex in the face's tilted plane riding on the face from t = 0 (near "
       "misses: stacked 1 ulp / 2^-k above it), or in a parallel layer 2^-20 .. 2^-48 away "
       "that closes exactly at t = 1 onto the face while both slide tangentially (near misses: "
       "the layer stops 1 ulp / 2^-k short)."},
      {"ee_t0", QueryType::edge_edge, ee_t0,
       "Edges crossing exactly at t = 0 (interiors, or at an endpoint), then separating; near "
       "misses: the moving edge starts 1 ulp / 2^-k off the common plane."},
      {"ee_t1", QueryType::edge_edge, ee_t1,
       "Edges meeting exactly at t = 1; near misses: the moving edge stops 1 ulp / 2^-k "
       "short."},
      {"ee_crossing", QueryType::edge_edge, ee_crossing,
       "Edges crossing at an interior time, one edge's endpoint on the other's interior; near "
       "misses: that endpoint moved 1 ulp / 2^-k so the edge falls short."},
      {"ee_endpoints", QueryType::edge_edge, ee_endpoints,
       "Edges touching endpoint to endpoint at an interior time; near misses: one endpoint "
       "moved 1 ulp / 2^-k so the edges pass each other."},
      {"ee_grazing", QueryType::edge_edge, ee_grazing,
       "Grazing: the coplanarity cubic has a double root at t*, where the edges touch (at an "
       "interior point or at an endpoint of one); near misses: one endpoint moved 1 ulp / "
       "2^-k so the cubic has no real root in [0, 1]."},
      {"ee_coplanar", QueryType::edge_edge, ee_coplanar,
       "Motion coplanar throughout: an endpoint sliding along the other edge's line into its "
       "end (no in-plane crossing), an edge descending across the other (crossing), or "
       "arriving at t = 1; near misses: moved 1 ulp / 2^-k aside, off the plane, or short."},
      {"ee_sliding", QueryType::edge_edge, ee_sliding,
       "An endpoint sliding along the other edge's line (entering the edge, or on it from "
       "t = 0; the cubic vanishes identically); near misses: that endpoint lifted off the "
       "line by 1 ulp / 2^-k."},
      {"ee_parallel", QueryType::edge_edge, ee_parallel,
       "Parallel edges whose lines coincide at t*: overlapping, or touching at an endpoint; "
       "near misses: the lines 1 ulp / 2^-k apart, or disjoint by 1 ulp / 2^-k."},
      {"ee_collinear", QueryType::edge_edge, ee_collinear,
       "Edges collinear throughout, touching endpoint to endpoint at t* and overlapping "
       "after, or arriving at t = 1; near misses: parallel 1 ulp / 2^-k apart, or disjoint by "
       "1 ulp / 2^-k."},
      {"ee_zero_length", QueryType::edge_edge, ee_zero_length,
       "Zero-length edges: a moving point hitting an edge's interior or endpoint, or another "
       "point; near misses: the point moved 1 ulp / 2^-k aside."},
      {"ee_later_root", QueryType::edge_edge, ee_later_root,
       "Two roots of the coplanarity cubic in (0, 1): at the first the edges are coplanar "
       "but apart, at the second one crosses the other's endpoint (t* = the later root); "
       "near misses: that endpoint moved 1 ulp / 2^-k inward."},
      {"ee_tunneling", QueryType::edge_edge, ee_tunneling,
       "Rapid motion across a short edge: the moving edge ends 2^10 to 2^40 away and crosses "
       "the short edge's endpoint at t* = H / (H + F); near misses: the short edge shortened "
       "by 1 ulp / 2^-k."},
      {"ee_resting", QueryType::edge_edge, ee_resting,
       "Edges sliding along each other in contact from t = 0: collinear and overlapping, or "
       "crossing (or an endpoint on the other edge) in a common tilted plane while each "
       "translates or deforms within it; near misses: one edge moved 1 ulp / 2^-k off the line "
       "or off the plane."},
      {"ee_stacked", QueryType::edge_edge, ee_stacked,
       "Stacked edges: crossing in a common tilted plane and translating together from t = 0 "
       "(near misses: one stacked 1 ulp / 2^-k above), or in a parallel layer 2^-20 .. 2^-48 "
       "away that closes exactly at t = 1 where they cross (near misses: the layer stops "
       "1 ulp / 2^-k short)."},
  };
  return table;
}

const BaseFamily& base_family(const std::string& name) {
  for (const BaseFamily& f : base_families())
    if (name == f.name) return f;
  throw std::invalid_argument("unknown family: " + name);
}

// ---------------------------------------------------------------------------------------------
// Random families: seeded random queries without a construction (no claim; the truth is the
// exact path's).

/// Random sign, a full random 53-bit significand, binary exponent uniform in [lo, hi] (within
/// [-1022, 1023]: a normal double): 2^e (1 + f), f a random 52-bit fraction.
double random_full_double(Rng& r, int lo, int hi) {
  const std::uint64_t significand = (r.bits() >> 11) | (std::uint64_t{1} << 52);
  const long e = r.uniform(lo, hi);
  const double m = std::ldexp(static_cast<double>(significand), static_cast<int>(e) - 52);
  return r.coin() ? m : -m;
}

/// A random multiple of 2^-1074 below 2^(bits - 1074) (bits <= 48: a subnormal or 0), random
/// sign. Sums of two such numbers and their products by 2^m, m <= 2, stay below 2^-1022 on the
/// 2^-1074 grid, hence exact.
double random_subnormal(Rng& r, int bits) {
  const double m = std::ldexp(static_cast<double>(r.bits() >> (64 - bits)), -1074);
  return r.coin() ? m : -m;
}

struct RandomQuery {
  QueryPoints points;
  std::string kind;
};

/// Every coordinate independently random_full_double(-spread, spread).
RandomQuery wide_exponent_query(Rng& r, int spread) {
  RandomQuery q;
  for (Eigen::Vector3d& p : q.points)
    for (int k = 0; k < 3; ++k) p[k] = random_full_double(r, -spread, spread);
  q.kind = "wide-exponent";
  return q;
}

/// The subnormal offsets of a small point from the huge primitive's plane at t = 0 and t = 1.
std::array<double, 2> subnormal_offsets(Rng& r, int bits, std::string* kind) {
  const double g = random_subnormal(r, bits);
  const double h = random_subnormal(r, bits);
  switch (r.uniform(0, 5)) {
    case 0: *kind = "crossing-1/2"; return {g, -g};
    case 1: *kind = "crossing"; return {g, std::signbit(g) == std::signbit(h) ? -h : h};
    case 2: *kind = "touch-t0"; return {0.0, h};
    case 3: *kind = "touch-t1"; return {g, 0.0};
    case 4: *kind = "in-plane"; return {0.0, 0.0};
    default: *kind = "one-side"; return {g, std::signbit(g) == std::signbit(h) ? h : -h};
  }
}

/// A huge triangle (edge) in the plane w = 2^m u through the origin (coordinates 2^900 ..
/// 2^1001; m in {0, 1, 2}, or w = 0) and the other primitive near the origin with subnormal
/// coordinates and subnormal offsets from that plane; or ("moving-huge") the huge primitive's w
/// coordinates moved by subnormal amounts. Every coordinate is computed exactly. Axes (u, v,
/// w) then permuted at random.
RandomQuery huge_and_subnormal_query(Rng& r, QueryType type) {
  RandomQuery q;
  QueryPoints& x = q.points;
  const int bits = static_cast<int>(r.uniform(1, 48));
  const bool moving_huge = r.uniform(0, 2) == 0;
  const int m = moving_huge || r.uniform(0, 2) == 0 ? -1 : static_cast<int>(r.uniform(0, 2));
  const auto plane_w = [m](double u) { return m < 0 ? 0.0 : std::ldexp(u, m); };
  const auto huge = [&r] {
    const double u = random_full_double(r, 900, 1000);
    const double v = random_full_double(r, 900, 1000);
    return std::array<double, 2>{u, v};
  };
  const auto set_huge = [&](int row, const std::array<double, 2>& uv) {
    x[row] = x[row + 4] = Eigen::Vector3d(uv[0], uv[1], plane_w(uv[0]));
    if (moving_huge) {
      if (r.uniform(0, 2) != 0) x[row][2] = random_subnormal(r, bits);
      x[row + 4][2] = random_subnormal(r, bits);
    }
  };
  const auto set_small = [&](int row, const std::array<double, 2>& offsets) {
    const double u0 = random_subnormal(r, bits), v0 = random_subnormal(r, bits);
    const double u1 = random_subnormal(r, bits), v1 = random_subnormal(r, bits);
    x[row] = Eigen::Vector3d(u0, v0, plane_w(u0) + offsets[0]);
    x[row + 4] = Eigen::Vector3d(u1, v1, plane_w(u1) + offsets[1]);
  };
  std::string offsets_kind;
  if (type == QueryType::vertex_face) {
    // Quadrants (+, +), (-, +), (+-, -): the origin is often inside the triangle.
    for (int i = 0; i < 3; ++i) {
      std::array<double, 2> uv = huge();
      uv = {std::fabs(uv[0]), std::fabs(uv[1])};
      if (i == 1 || (i == 2 && r.coin())) uv[0] = -uv[0];
      if (i == 2) uv[1] = -uv[1];
      set_huge(1 + i, uv);
    }
    set_small(0, subnormal_offsets(r, bits, &offsets_kind));
  } else {
    const std::array<double, 2> a0 = huge();
    std::array<double, 2> a1;
    const bool through_origin = r.coin();
    if (through_origin) {
      const int j = static_cast<int>(r.uniform(-2, 2));
      a1 = {-std::ldexp(a0[0], j), -std::ldexp(a0[1], j)};
    } else {
      a1 = huge();
    }
    set_huge(0, a0);
    set_huge(1, a1);
    const std::array<double, 2> g = subnormal_offsets(r, bits, &offsets_kind);
    set_small(2, g);
    set_small(3, g);
    if (r.coin())  // the small edge first
      for (int k : {0, 4}) std::swap(x[k], x[k + 2]), std::swap(x[k + 1], x[k + 3]);
    offsets_kind = std::string(through_origin ? "through-origin-" : "") + offsets_kind;
  }
  q.kind = (moving_huge ? "moving-huge-" : m < 0 ? "flat-" : "tilted-") + offsets_kind;
  // A random signed permutation of the axes: exact, answer-preserving.
  std::array<int, 3> axis = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(axis[i], axis[r.uniform(0, i)]);
  std::array<int, 3> sign;
  for (int& s : sign) s = r.sign();
  for (Eigen::Vector3d& p : x) {
    const Eigen::Vector3d old = p;
    for (int k = 0; k < 3; ++k) p[k] = sign[k] * old[axis[k]];
  }
  return q;
}

using RandomBuilder = RandomQuery (*)(Rng&, QueryType);

struct RandomFamilySpec {
  const char* name;
  QueryType type;
  RandomBuilder build;
  const char* description;
  int exponent_lo, exponent_hi;  // of the random coordinates, for the manifest
};

RandomQuery wide_100(Rng& r, QueryType) { return wide_exponent_query(r, 100); }
RandomQuery wide_300(Rng& r, QueryType) { return wide_exponent_query(r, 300); }
RandomQuery wide_1000(Rng& r, QueryType) { return wide_exponent_query(r, 1000); }

const std::vector<RandomFamilySpec>& random_families() {
  static const char* kWide =
      "Every coordinate a random double: random sign, a full random 53-bit significand and a "
      "binary exponent uniform in [-E, E], independently per coordinate (the exponent spread "
      "within one query is what is hard). No claim: the truth is the exact path's.";
  static const char* kHuge =
      "A huge primitive (coordinates 2^900 .. 2^1001) in a plane through the origin and the "
      "other one near the origin with subnormal coordinates and subnormal motion across, onto "
      "or along that plane, or the huge one moved by subnormal amounts: exponent spreads of "
      "about 2000 within one query. No claim: the truth is the exact path's.";
  static const std::vector<RandomFamilySpec> table = {
      {"vf_wide_exponent_100", QueryType::vertex_face, wide_100, kWide, -100, 100},
      {"vf_wide_exponent_300", QueryType::vertex_face, wide_300, kWide, -300, 300},
      {"vf_wide_exponent_1000", QueryType::vertex_face, wide_1000, kWide, -1000, 1000},
      {"vf_huge_triangle_subnormal_motion", QueryType::vertex_face, huge_and_subnormal_query, kHuge,
       -1074, 1000},
      {"ee_wide_exponent_100", QueryType::edge_edge, wide_100, kWide, -100, 100},
      {"ee_wide_exponent_300", QueryType::edge_edge, wide_300, kWide, -300, 300},
      {"ee_wide_exponent_1000", QueryType::edge_edge, wide_1000, kWide, -1000, 1000},
      {"ee_huge_triangle_subnormal_motion", QueryType::edge_edge, huge_and_subnormal_query, kHuge,
       -1074, 1000},
  };
  return table;
}

const RandomFamilySpec& random_family(const std::string& name) {
  for (const RandomFamilySpec& f : random_families())
    if (name == f.name) return f;
  throw std::invalid_argument("unknown family: " + name);
}

}  // namespace

const std::vector<std::string>& base_family_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const BaseFamily& f : base_families()) out.push_back(f.name);
    return out;
  }();
  return names;
}

const std::vector<std::string>& random_family_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const RandomFamilySpec& f : random_families()) out.push_back(f.name);
    return out;
  }();
  return names;
}

bool is_random_family(const std::string& name) {
  const auto& names = random_family_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

const std::vector<Variant>& variants() {
  static const std::vector<Variant> v = {
      {"@s1e-12", 1e-12, 0.0},
      {"@s1e-6", 1e-6, 0.0},
      {"@s1e6", 1e6, 0.0},
      {"@s1e12", 1e12, 0.0},
      {"@t1e4", 1.0, 1e4},
      {"@t1e8", 1.0, 1e8},
      {"@p2^-1000", std::ldexp(1.0, -1000), 0.0, -1000},
      {"@p2^-300", std::ldexp(1.0, -300), 0.0, -300},
      {"@p2^-100", std::ldexp(1.0, -100), 0.0, -100},
      {"@p2^100", std::ldexp(1.0, 100), 0.0, 100},
      {"@p2^300", std::ldexp(1.0, 300), 0.0, 300},
      {"@p2^1000", std::ldexp(1.0, 1000), 0.0, 1000},
  };
  return v;
}

std::vector<std::string> all_family_names() {
  std::vector<std::string> out = base_family_names();
  for (const std::string& name : random_family_names()) out.push_back(name);
  for (const Variant& v : variants())
    for (const std::string& base : base_family_names()) out.push_back(base + v.suffix);
  return out;
}

std::string base_of(const std::string& name) {
  const std::size_t at = name.find('@');
  const std::string base = name.substr(0, at);
  if (at == std::string::npos && is_random_family(name)) return name;
  const auto& bases = base_family_names();
  if (std::find(bases.begin(), bases.end(), base) == bases.end()) return {};
  if (at == std::string::npos) return base;
  const std::string suffix = name.substr(at);
  for (const Variant& v : variants())
    if (suffix == v.suffix) return base;
  return {};
}

bool is_family_name(const std::string& name) { return !base_of(name).empty(); }

Family generate_random_family(const std::string& name, std::uint64_t seed, int per_family) {
  const RandomFamilySpec& spec = random_family(name);
  check_per_family(per_family);
  Rng rng(splitmix64(seed ^ fnv1a(name)));
  Family family;
  family.name = family.base = name;
  family.type = spec.type;
  family.description = spec.description;
  std::map<std::string, int> kinds;
  for (int i = 0; i < per_family; ++i) {
    RandomQuery q = spec.build(rng, spec.type);
    Member m;
    m.points = q.points;
    m.label = "random";
    m.kind = q.kind;
    ++kinds[m.kind];
    family.members.push_back(std::move(m));
  }
  nlohmann::json kind_counts = nlohmann::json::object();
  for (const auto& [k, v] : kinds) kind_counts[k] = v;
  family.parameters = {
      {"per_family", per_family},
      {"claims", "none: the truth is the exact path's"},
      {"binary_exponents", {spec.exponent_lo, spec.exponent_hi}},
      {"kinds", kind_counts},
  };
  return family;
}

Family generate_base_family(const std::string& base, std::uint64_t seed, int per_family) {
  const BaseFamily& spec = base_family(base);
  check_per_family(per_family);
  Rng rng(splitmix64(seed ^ fnv1a(base)));
  Family family;
  family.name = family.base = base;
  family.type = spec.type;
  family.description = spec.description;
  std::map<std::string, int> kinds;
  std::set<std::string> times;
  int groups = 0, raised = 0;
  while (static_cast<int>(family.members.size()) < per_family) {
    // One group: the boundary configuration and its near misses (duplicates dropped: a 2^-k
    // move can equal the one-ulp move on a large coordinate).
    Construction c;
    std::optional<Placed> placed;
    do {
      c = spec.build(rng, groups);
      placed = place(c, random_frame(rng, spec.type));
    } while (!placed);
    ++groups;
    Member contact;
    contact.points = placed->points;
    contact.label = "contact";
    contact.kind = c.kind;
    contact.claim_known = true;
    contact.collides = true;
    contact.toi = c.toi;
    const int partner = static_cast<int>(family.members.size());
    std::vector<Member> group = {contact};
    for (int k = -1; k < static_cast<int>(kNearMissExponents.size()); ++k) {
      Member m = near_miss(contact, partner, *placed, k < 0 ? 0 : kNearMissExponents[k]);
      const bool duplicate = std::any_of(group.begin(), group.end(),
                                         [&](const Member& g) { return g.points == m.points; });
      if (duplicate) continue;
      if (m.distance_log2 > 0 && m.distance != std::ldexp(1.0, -m.distance_log2)) ++raised;
      group.push_back(std::move(m));
    }
    for (Member& m : group) {
      if (static_cast<int>(family.members.size()) == per_family) break;
      if (m.label == "contact") times.insert(m.toi.get_str());
      ++kinds[m.kind];
      family.members.push_back(std::move(m));
    }
  }
  nlohmann::json kind_counts = nlohmann::json::object();
  for (const auto& [k, v] : kinds) kind_counts[k] = v;
  std::vector<std::string> offsets = {"1ulp"};
  for (const int k : kNearMissExponents) offsets.push_back("2^-" + std::to_string(k));
  family.parameters = {
      {"per_family", per_family},
      {"groups", groups},
      {"near_miss_offsets", offsets},
      // 2^-k near misses that had to move farther than 2^-k (one ulp of a moved coordinate is
      // larger, or 2^-k would not land on a double): their distance says how far.
      {"near_misses_beyond_requested_offset", raised},
      {"kinds", kind_counts},
      {"contact_times", std::vector<std::string>(times.begin(), times.end())},
      {"frame",
       "random signed axis permutation, vertex relabelling (edge swap and reversal), dyadic "
       "translation k/16 and common velocity k/8 per axis, applied before the near-miss moves"},
  };
  return family;
}

namespace {

/// x 2^k, and whether that is exact (a double, not an overflow nor a rounded underflow). An
/// overflowing product is replaced by +-DBL_MAX, so that the member stays a finite query.
double times_power_of_two(double x, int k, bool* exact) {
  const double y = std::ldexp(x, k);
  if (!std::isfinite(y)) {
    *exact = false;
    return std::copysign(std::numeric_limits<double>::max(), x);
  }
  if (std::ldexp(y, -k) != x) *exact = false;
  return y;
}

/// Every coordinate times 2^k. Scaling space by 2^k > 0 maps the trajectories of a query onto
/// those of the scaled one at the same times: a contact at t becomes a contact at t and
/// conversely, so the verdict and t* are unchanged. A member whose products are all exact is
/// that scaled query and keeps its base member's claim (and its near-miss bookkeeping, the
/// distance scaled by 2^k); any other member carries no claim.
Family power_of_two_variant(const Family& base, const Variant& variant) {
  const int k = variant.power_of_two;
  Family f;
  f.name = base.name + variant.suffix;
  f.base = base.name;
  f.type = base.type;
  f.scale = variant.scale;
  f.description = base.description + " Every coordinate multiplied by 2^" + std::to_string(k) +
                  ": members whose products are all doubles keep their claim (a power-of-two "
                  "scaling changes neither verdict nor t*); the others (overflow, replaced by "
                  "+-DBL_MAX, or bits lost below 2^-1074) carry none.";
  std::size_t exact = 0;
  for (std::size_t i = 0; i < base.members.size(); ++i) {
    const Member& b = base.members[i];
    Member m;
    m.exact_scaling = true;
    for (int r = 0; r < 8; ++r)
      for (int a = 0; a < 3; ++a)
        m.points[r][a] = times_power_of_two(b.points[r][a], k, &m.exact_scaling);
    m.label = b.label;
    m.kind = b.kind;
    m.source = static_cast<int>(i);
    exact += m.exact_scaling;
    if (m.exact_scaling && b.claim_known) {
      m.claim_known = true;
      m.collides = b.collides;
      m.toi = b.toi;
      m.partner = b.partner;
      m.moved = b.moved;
      m.direction = b.direction;
      m.distance = std::ldexp(b.distance, k);
      m.distance_log2 = b.distance_log2;
    }
    f.members.push_back(std::move(m));
  }
  f.parameters = {{"base", base.name},
                  {"transform", "power_of_two"},
                  {"exponent", k},
                  {"scale", variant.scale},
                  {"members_scaled_exactly", exact},
                  {"members_without_claim", base.members.size() - exact}};
  return f;
}

}  // namespace

Family make_variant(const Family& base, const Variant& variant) {
  if (variant.power_of_two != 0) return power_of_two_variant(base, variant);
  Family f;
  f.name = base.name + variant.suffix;
  f.base = base.name;
  f.type = base.type;
  f.scale = variant.scale;
  f.offset = variant.offset;
  const bool scaled = variant.offset == 0.0;
  f.description = base.description +
                  (scaled ? " Every coordinate multiplied by " : " Every coordinate plus ") +
                  nlohmann::json(scaled ? variant.scale : variant.offset).dump() +
                  " in double arithmetic (rounded to nearest): the truth is the exact path's "
                  "on the rounded doubles.";
  f.parameters = {{"base", base.name},
                  {"transform", scaled ? "scale" : "translate"},
                  {scaled ? "scale" : "offset", scaled ? variant.scale : variant.offset}};
  for (std::size_t i = 0; i < base.members.size(); ++i) {
    Member m;
    for (int r = 0; r < 8; ++r)
      for (int a = 0; a < 3; ++a) {
        const double x = base.members[i].points[r][a];
        m.points[r][a] = scaled ? x * variant.scale : x + variant.offset;
      }
    m.label = base.members[i].label;
    m.kind = base.members[i].kind;
    m.source = static_cast<int>(i);
    f.members.push_back(std::move(m));
  }
  return f;
}

std::vector<Family> generate_families(std::uint64_t seed, int per_family,
                                      const std::vector<std::string>& names) {
  for (const std::string& n : names)
    if (!is_family_name(n)) throw std::invalid_argument("unknown family: " + n);
  const auto wanted = [&](const std::string& n) {
    return names.empty() || std::find(names.begin(), names.end(), n) != names.end();
  };
  std::map<std::string, Family> bases;
  const auto base = [&](const std::string& b) -> const Family& {
    auto it = bases.find(b);
    if (it == bases.end()) it = bases.emplace(b, generate_base_family(b, seed, per_family)).first;
    return it->second;
  };
  std::vector<Family> out;
  for (const std::string& n : all_family_names()) {
    if (!wanted(n)) continue;
    const std::string b = base_of(n);
    if (n == b) {
      out.push_back(is_random_family(b) ? generate_random_family(b, seed, per_family) : base(b));
      continue;
    }
    for (const Variant& v : variants())
      if (n == b + v.suffix) out.push_back(make_variant(base(b), v));
  }
  return out;
}

}  // namespace exactccd::families
