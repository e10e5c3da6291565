// The minimum-separation constructions (see min_separation_families.hpp).
//
// Each builder works in a canonical frame with exact rationals, for a canonical delta d (the
// family's delta divided by the group's geometry scale), and returns one boundary
// configuration: rows, t*, and the near misses' outward moves. Notation: s = t - tc; a point
// "moving with V through x at tc" is x + s V (set_motion with the velocity unit(tc) W, so that
// both rows are dyadic); n is an integer vector of integer length h, n^ = n / h its unit
// vector, and "the offset" is d n^, exact by the choice of n (random_direction).
//
// SLAB LEMMA (the proofs below use it). Let H0 = {x : n^.x = sigma} and Hd = {x : n^.x =
// sigma + d}. If at time t the closed primitive P lies in {n^.x >= sigma + d} and Q in
// {n^.x <= sigma}, then dist(P, Q) >= d, with equality iff some x in P and y in Q have
// x - y = d n^ (then x in Hd, y in H0). Proof: |x - y| >= n^.(x - y) >= d (Cauchy-Schwarz),
// with equality iff x - y is d n^. So the query is within d at t iff (P cap Hd) - d n^ meets
// Q cap H0. And if P lies in {n^.x >= sigma + d + e} with e > 0 at every time, the distance
// exceeds d at every time: that is every slab family's near miss, which moves the coordinates
// of P's points in Hd by the same distance outward along an axis where n^ is non-zero, with
// that component's sign (their n^.x grows by distance * |n_axis| / h > 0; P is the convex hull
// of its vertices, whose others lie strictly beyond Hd).
#include "corpus/min_separation_families.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "corpus/construction.hpp"

namespace exactccd::families {

using namespace construction;

namespace {

// ---------------------------------------------------------------------------------------------
// Exact directions and offsets

struct Direction {
  P3 n;  ///< integer components
  long h = 1;  ///< |n|, an integer
};

/// Integer vectors of integer length, up to signed permutations (applied at random).
const std::vector<Direction>& base_directions() {
  static const std::vector<Direction> table = {
      {p3(1, 0, 0), 1},  {p3(1, 2, 2), 3},  {p3(3, 4, 0), 5},   {p3(2, 3, 6), 7},
      {p3(4, 4, 7), 9},  {p3(5, 12, 0), 13}, {p3(3, 4, 12), 13},
  };
  return table;
}

bool is_dyadic(const Q& q) { return mpz_popcount(q.get_den().get_mpz_t()) == 1; }

/// A random direction whose offset d n / h is dyadic: a coordinate axis always, a Pythagorean
/// direction where h divides d's odd numerator. With zero_x, n's x component is 0 (the
/// direction is perpendicular to the x axis).
Direction random_direction(Rng& r, const Q& d, bool zero_x = false) {
  std::vector<Direction> usable;
  for (const Direction& dir : base_directions()) {
    const bool has_zero = sgn(dir.n[0]) == 0 || sgn(dir.n[1]) == 0 || sgn(dir.n[2]) == 0;
    if (is_dyadic(canon(d / dir.h)) && (!zero_x || has_zero)) usable.push_back(dir);
  }
  Direction dir = r.pick(usable);
  std::array<int, 3> order = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(order[i], order[r.uniform(0, i)]);
  if (zero_x)  // the permutation that puts a zero component first
    while (sgn(dir.n[order[0]]) != 0) std::rotate(order.begin(), order.begin() + 1, order.end());
  P3 n;
  for (int i = 0; i < 3; ++i) {
    const int sign = r.sign();
    n[i] = canon(sign * dir.n[order[i]]);
  }
  dir.n = n;
  return dir;
}

/// d n^, exact.
P3 offset(const Direction& dir, const Q& d) { return frac(1, dir.h) * d * dir.n; }

/// A random non-zero vector perpendicular to n: n x v.
P3 perpendicular(Rng& r, const P3& n) {
  for (;;) {
    const P3 w = cross(n, random_vector(r));
    if (w != zero3()) return w;
  }
}
/// ... and not parallel to e (also perpendicular to n).
P3 perpendicular_not_along(Rng& r, const P3& n, const P3& e) {
  for (;;) {
    const P3 w = perpendicular(r, n);
    if (cross(w, e) != zero3()) return w;
  }
}

/// A random vector v with sign(n . v) == side (+1 or -1).
P3 vector_on_side(Rng& r, const P3& n, int side) {
  for (;;) {
    const P3 v = random_vector(r);
    if (sgn(dot(n, v)) == side) return v;
  }
}

/// The near misses' moves: `rows` moved along a random axis where n is non-zero, outward
/// (the sign of n there).
std::vector<Move> outward_moves(Rng& r, const P3& n, std::initializer_list<int> rows) {
  std::vector<int> axes;
  for (int axis = 0; axis < 3; ++axis)
    if (sgn(n[axis]) != 0) axes.push_back(axis);
  const int axis = r.pick(axes);
  std::vector<Move> moves;
  for (const int row : rows) moves.push_back({row, axis, sgn(n[axis])});
  return moves;
}

/// Contact times: mostly interior, sometimes 0 or 1.
Q contact_time(Rng& r, int group) { return group % 4 == 3 ? any_time(r) : interior_time(r); }

/// A point of P's side beyond Hd for the moving primitives that arrive at t = 1: 2d above the
/// plane when d > 0 (still exact: 2 d n^), else n / 8.
P3 lift(const Direction& dir, const Q& d) {
  return sgn(d) > 0 ? Q(2) * offset(dir, d) : pow2(-3) * dir.n;
}

/// Static vertex `row` of a primitive at `at`.
void place_static(Construction& c, int row, const P3& at) { set_static(c, row, at); }

/// P's vertex `row`, through `at` at tc with velocity W (unit(tc) W, so both rows are dyadic).
void move_through(Construction& c, int row, const P3& at, const P3& w, const Q& tc) {
  set_motion(c, row, at, unit(tc) * w, tc);
}

// ---- vertex-face -------------------------------------------------------------------------------

// ms_vf_vertex: the triangle {q, q + u1, q + u2} with n.u1 < 0 and n.u2 < 0 (static) lies in
// {n^.x <= n^.q} and meets H0 only at q; p moves with W perpendicular to n (W != 0) through
// q + d n^ at tc, so p stays in Hd. By the slab lemma the query is within d at t iff p(t) - d n^
// = q + s W = q, iff s = 0: t* = tc, the vertex sphere's tangency.
Construction ms_vf_vertex(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 q = random_vector(r);
  P3 u1, u2;
  do {
    u1 = vector_on_side(r, dir.n, -1);
    u2 = vector_on_side(r, dir.n, -1);
  } while (cross(u1, u2) == zero3());
  place_static(c, 1, q);
  place_static(c, 2, q + u1);
  place_static(c, 3, q + u2);
  const Q tc = contact_time(r, group);
  const P3 w = perpendicular(r, dir.n);
  move_through(c, 0, q + offset(dir, d), w, tc);
  c.toi = tc;
  c.moves = outward_moves(r, dir.n, {0, 4});
  c.kind = "vertex-sphere";
  return c;
}

// ms_vf_edge: the edge [q - alpha e, q + beta e] (alpha, beta > 0, e perpendicular to n) lies in
// H0 with q inside it, and the third vertex q + u has n.u < 0, so the static triangle lies in
// {n^.x <= n^.q} and meets H0 exactly in that edge. p moves with W perpendicular to n, not
// parallel to e, through q + d n^ at tc: p(t) - d n^ = q + s W lies on the edge's line only at
// s = 0 (W and e independent), where it is q, inside the edge: t* = tc, tangent to the edge's
// capsule. "edge-in-plane": u = -gamma n + lambda e, so n lies in the triangle's plane.
Construction ms_vf_edge(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 q = random_vector(r);
  const P3 e = perpendicular(r, dir.n);
  const Q alpha = r.dyadic(1, 8, 8);
  const Q beta = r.dyadic(1, 8, 8);
  P3 u;
  if (group % 2 == 0) {
    const Q gamma = r.dyadic(1, 8, 8);
    const Q lambda = r.dyadic(-8, 8, 8);
    u = Q(-gamma) * dir.n + lambda * e;
    c.kind = "edge-capsule-in-plane";
  } else {
    u = vector_on_side(r, dir.n, -1);
    c.kind = "edge-capsule-oblique";
  }
  place_static(c, 1, q - alpha * e);
  place_static(c, 2, q + beta * e);
  place_static(c, 3, q + u);
  const Q tc = contact_time(r, group);
  const P3 w = perpendicular_not_along(r, dir.n, e);
  move_through(c, 0, q + offset(dir, d), w, tc);
  c.toi = tc;
  c.moves = outward_moves(r, dir.n, {0, 4});
  return c;
}

/// A point of the closed triangle with barycentric weights in eighths: interior (all > 0).
P3 face_point(Rng& r, const std::array<P3, 3>& t) {
  const long i = r.uniform(1, 6);
  const long j = r.uniform(1, 7 - i);
  const long k = 8 - i - j;
  return frac(1, 8) * (Q(i) * t[0] + Q(j) * t[1] + Q(k) * t[2]);
}

// ms_vf_face: a static triangle T in the plane H0 = {n^.x = n^.o} (its edges perpendicular to
// n); the slab lemma's contact set is all of T, so the query is within d at t iff p(t) is in
// Hd and p(t) - d n^ lies in T.
// - sliding-entering: p slides in Hd (W perpendicular to n) through q + d n^ at tc, q inside
//   the edge [a, b], W pointing into T (W.m < 0 for the edge's outward normal m in the plane).
//   For s < 0, (q + s W - a).m = s W.m > 0: outside the edge's half-plane, outside T. t* = tc.
// - sliding-over: p(0) - d n^ is inside T, p slides in Hd: t* = 0.
// - arriving: p(1) = q + d n^ with q inside T, p(0) = q + lift + V (lift above Hd: n^.lift > d,
//   V in the plane): n^.p(t) > sigma + d for t < 1, so t* = 1; the near miss moves p(1) only,
//   and P stays in {n^.x >= sigma + d + e} with e = min(lift's excess, the move) > 0.
Construction ms_vf_face(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 o = random_vector(r);
  P3 e1, e2;
  do {
    e1 = perpendicular(r, dir.n);
    e2 = perpendicular(r, dir.n);
  } while (cross(e1, e2) == zero3());
  const std::array<P3, 3> t = {o, o + e1, o + e2};
  for (int i = 0; i < 3; ++i) place_static(c, 1 + i, t[i]);
  const P3 up = offset(dir, d);
  switch (group % 3) {
    case 0: {
      const long i = r.uniform(0, 2);
      const P3 &a = t[i], &b = t[(i + 1) % 3], &other = t[(i + 2) % 3];
      P3 m = cross(dir.n, b - a);
      if (sgn(dot(m, other - a)) > 0) m = zero3() - m;  // outward
      const P3 q = a + r.dyadic(1, 7, 8) * (b - a);
      P3 w;
      do w = perpendicular(r, dir.n);
      while (sgn(dot(w, m)) >= 0);
      const Q tc = contact_time(r, group);
      move_through(c, 0, q + up, w, tc);
      c.toi = tc;
      c.moves = outward_moves(r, dir.n, {0, 4});
      c.kind = "face-sliding-entering";
      break;
    }
    case 1: {
      c.rows[0] = face_point(r, t) + up;
      c.rows[4] = c.rows[0] + perpendicular(r, dir.n);
      c.toi = 0;
      c.moves = outward_moves(r, dir.n, {0, 4});
      c.kind = "face-sliding-over";
      break;
    }
    default: {
      const P3 q = face_point(r, t);
      c.rows[4] = q + up;
      c.rows[0] = q + lift(dir, d) + perpendicular(r, dir.n);
      c.toi = 1;
      c.moves = outward_moves(r, dir.n, {4});
      c.kind = "face-arriving";
      break;
    }
  }
  return c;
}

// ms_vf_face_tilt: tangent to the face's plane at an interior time, the triangle tilting. At tc
// the triangle lies in z = 0 with the point o = 0 in it (inside, on an edge or at a vertex);
// each vertex (x, y, 0) moves to (x, y, k s y): the triangle lies in the plane z = k s y, of
// normal (0, -k s, 1), and stays non-degenerate (a shear of a non-degenerate triangle). p(t) =
// (nu s, mu s, d). The plane distance of p is |N| / sqrt(1 + k^2 s^2) with N = d - k mu s^2 =
// d + c s^2, c = -k mu > 0 by construction, and N^2 - d^2 (1 + k^2 s^2) = s^2 (2 d c - d^2 k^2)
// + c^2 s^4 > 0 for s != 0 because 2 c >= d k^2 (drawn so; "-quartic": 2 c = d k^2, mu = -d k
// / 2, and the difference is c^2 s^4, a tangency of order four). The distance to the triangle is at
// least the plane distance: > d for t != tc; at tc, p = (0, 0, d) projects to o, in the
// triangle, at distance d: t* = tc. Near miss: p's z moved up by e at both times: N = d + e +
// c s^2 and N^2 - d^2 (1 + k^2 s^2) >= (d + e)^2 - d^2 > 0 at every s.
Construction ms_vf_face_tilt(Rng& r, int group, const Q& d) {
  Construction c;
  std::array<P3, 3> t;
  do
    for (P3& v : t) v = P3{r.dyadic(-8, 8, 8), r.dyadic(-8, 8, 8), Q(0)};
  while (abs(orient2(t[0], t[1], t[2])) < frac(1, 4));
  P3 o;
  switch (group % 3) {
    case 0:
      o = face_point(r, t);
      c.kind = "face-tilting-interior";
      break;
    case 1: {
      const long i = r.uniform(0, 2);
      o = t[i] + r.dyadic(1, 7, 8) * (t[(i + 1) % 3] - t[i]);
      c.kind = "face-tilting-edge";
      break;
    }
    default:
      o = t[r.uniform(0, 2)];
      c.kind = "face-tilting-vertex";
      break;
  }
  const Q tc = interior_time(r);
  Q k, mu;
  if (sgn(d) > 0 && r.coin()) {  // 2 c = d k^2: a fourth-order tangency
    k = r.nonzero_dyadic(-8, 8, 8);
    mu = canon(-d * k / 2);
    c.kind += "-quartic";
  } else {
    do {
      k = r.nonzero_dyadic(-8, 8, 8);
      mu = canon(-sgn(k) * r.dyadic(1, 8, 8));
    } while (2 * (-k * mu) < d * k * k);
  }
  const Q nu = r.dyadic(-8, 8, 8);
  for (int i = 0; i < 3; ++i) {
    const P3 v = t[i] - o;
    move_through(c, 1 + i, v, p3(0, 0, k * v[1]), tc);
  }
  move_through(c, 0, p3(0, 0, d), p3(nu, mu, 0), tc);
  c.toi = tc;
  c.moves = {{0, 2, 1}, {4, 2, 1}};
  return c;
}

// ms_vf_degenerate: a degenerate triangle (its vertices on a line, or one point) in
// {n^.x <= n^.q}, and p moving with W perpendicular to n through q + d n^ at tc (slab lemma).
// - collinear-side: vertices q + lambda_i e (e perpendicular to n, some lambda < 0 < some
//   lambda): the triangle is a segment in H0 with q inside; W not parallel to e: t* = tc as for
//   ms_vf_edge.
// - collinear-end: vertices q + lambda_i e with n.e < 0 and lambda_i >= 0, one of them 0: the
//   segment meets H0 only at q: t* = tc as for ms_vf_vertex.
// - point: all three vertices at q: t* = tc.
Construction ms_vf_degenerate(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 q = random_vector(r);
  P3 e, w;
  std::array<Q, 3> lambda;
  switch (group % 3) {
    case 0:
      e = perpendicular(r, dir.n);
      lambda = {Q(-r.dyadic(1, 8, 8)), r.dyadic(1, 8, 8), r.dyadic(-8, 8, 8)};
      w = perpendicular_not_along(r, dir.n, e);
      c.kind = "collinear-triangle-side";
      break;
    case 1:
      e = vector_on_side(r, dir.n, -1);
      lambda = {Q(0), r.dyadic(1, 8, 8), r.dyadic(0, 8, 8)};
      w = perpendicular(r, dir.n);
      c.kind = "collinear-triangle-end";
      break;
    default:
      e = zero3();
      lambda = {Q(0), Q(0), Q(0)};
      w = perpendicular(r, dir.n);
      c.kind = "point-triangle";
      break;
  }
  for (int i = 0; i < 3; ++i) place_static(c, 1 + i, q + canon(lambda[i]) * e);
  const Q tc = contact_time(r, group);
  move_through(c, 0, q + offset(dir, d), w, tc);
  c.toi = tc;
  c.moves = outward_moves(r, dir.n, {0, 4});
  return c;
}

// ---- edge-edge (rows: ea0, ea1, eb0, eb1 at t = 0, then at t = 1; A = [ea0, ea1] is P) ----

// ms_ee_endpoints: B = [q, q + u] static with n.u < 0 meets H0 only at q; A's endpoint a0 moves
// with W perpendicular to n through q + d n^ at tc and a1 = a0 + f with n.f > 0, so A lies in
// {n^.x >= n^.q + d} and meets Hd only at a0. Within d iff a0(t) - d n^ = q + s W = q: t* = tc,
// the endpoints' sphere.
Construction ms_ee_endpoints(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 q = random_vector(r);
  place_static(c, 2, q);
  place_static(c, 3, q + vector_on_side(r, dir.n, -1));
  const P3 f = vector_on_side(r, dir.n, 1);
  const Q tc = contact_time(r, group);
  const P3 w = perpendicular(r, dir.n);
  move_through(c, 0, q + offset(dir, d), w, tc);
  move_through(c, 1, q + offset(dir, d) + f, w, tc);
  c.toi = tc;
  c.moves = outward_moves(r, dir.n, {0, 4});
  c.kind = "endpoint-sphere";
  return c;
}

// ms_ee_capsule: B = [q - alpha e, q + beta e] static in H0 (e perpendicular to n, alpha, beta >
// 0); a0 moves with W (perpendicular to n, not parallel to e) through q + d n^ at tc; a1 =
// a0 + f.
// - oblique: n.f > 0, A meets Hd only at a0: within d iff q + s W lies in B, iff s = 0 (W, e
//   independent): t* = tc, a0 tangent to B's capsule.
// - in-plane (sliding at distance d): f perpendicular to n, A lies in Hd; the slab lemma's
//   sets are A - d n^ and B, in the plane H0. With m = n x e (B's line's normal in the plane),
//   (a0(t) - d n^ - q).m = s W.m and (a1(t) - d n^ - q).m = s W.m + f.m, where W.m != 0 and
//   f.m has the sign of -W.m: for s < 0 both are non-zero of one sign, A - d n^ lies strictly
//   on one side of B's line and misses B. At s = 0, a0 - d n^ = q is in B: t* = tc.
Construction ms_ee_capsule(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 q = random_vector(r);
  const P3 e = perpendicular(r, dir.n);
  const Q alpha = r.dyadic(1, 8, 8);
  const Q beta = r.dyadic(1, 8, 8);
  place_static(c, 2, q - alpha * e);
  place_static(c, 3, q + beta * e);
  const P3 w = perpendicular_not_along(r, dir.n, e);
  P3 f;
  if (group % 2 == 0) {
    f = vector_on_side(r, dir.n, 1);
    c.kind = "endpoint-edge-capsule";
  } else {
    const P3 m = cross(dir.n, e);
    const Q along = r.dyadic(-8, 8, 8);
    const Q across = canon(-sgn(dot(w, m)) * r.dyadic(1, 8, 8));
    f = along * e + across * m;
    c.kind = "edges-sliding-in-plane";
  }
  const Q tc = contact_time(r, group);
  move_through(c, 0, q + offset(dir, d), w, tc);
  move_through(c, 1, q + offset(dir, d) + f, w, tc);
  c.toi = tc;
  // Oblique: a0 alone lies in Hd; in-plane: all of A.
  c.moves = group % 2 == 0 ? outward_moves(r, dir.n, {0, 4})
                           : outward_moves(r, dir.n, {0, 1, 4, 5});
  return c;
}

// ms_ee_interior:
// - tilting: the lines' distance tangent to d at tc, with the closest points inside both
//   edges. B: b_i(t) = (x_i, 0, k s x_i), x_0 < 0 < x_1, direction v = (1, 0, k s). A: a_j(t)
//   = (l_j ux, mu s + l_j, -d), l_0 < 0 < l_1, direction u = (ux, 1, 0), through P = (0, mu s,
//   -d). m = u x v = (k s, -ux k s, -1), |m|^2 = 1 + k^2 s^2 (1 + ux^2) >= 1 (never parallel),
//   and P.m = d + c s^2 with c = -ux k mu > 0 by construction; the lines' squared distance
//   is (P.m)^2 / |m|^2 and (P.m)^2 - d^2 |m|^2 = s^2 (2 d c - d^2 k^2 (1 + ux^2)) + c^2 s^4 >
//   0 for s != 0, since 2 c >= d k^2 (1 + ux^2) (drawn so; "-quartic": equal, with ux a power
//   of two so that mu = -d k (1 + ux^2) / (2 ux) is dyadic). The edges' distance is at least
//   the lines': > d for t != tc. At tc the closest points of the lines are (0, 0, -d) (l = 0)
//   and the origin (x = 0), inside both edges, at distance d: t* = tc. Near miss: A's z moved
//   down by e (all four of A's rows): P.m = d + e + c s^2 and the difference is >= (d + e)^2 -
//   d^2 > 0 at every s.
// - arriving: B = [(x_0, 0, 0), (x_1, 0, 0)] static and A = {(l ux, l, z(t))} with z(0) =
//   lift > d, z(1) = d: A's projection on z = 0 crosses B at the origin, inside both; A lies
//   in z >= d, and in z = d only at t = 1 (slab lemma, n = z): t* = 1. The near miss moves A's
//   rows at t = 1 up.
Construction ms_ee_interior(Rng& r, int group, const Q& d) {
  Construction c;
  const std::array<Q, 2> x = {Q(-r.dyadic(1, 8, 8)), r.dyadic(1, 8, 8)};
  const std::array<Q, 2> l = {Q(-r.dyadic(1, 8, 8)), r.dyadic(1, 8, 8)};
  Q ux = r.nonzero_dyadic(-8, 8, 8);
  if (group % 2 == 0) {
    const Q tc = interior_time(r);
    Q k, mu;
    if (sgn(d) > 0 && r.coin()) {  // 2 c = d k^2 (1 + ux^2): a fourth-order tangency
      ux = canon(r.sign() * pow2(-static_cast<int>(r.uniform(0, 3))));
      k = r.nonzero_dyadic(-8, 8, 8);
      mu = canon(-d * k * (1 + ux * ux) / (2 * ux));  // dyadic: ux is a power of two
      c.kind = "interior-tilting-quartic";
    } else {
      do {
        k = r.nonzero_dyadic(-8, 8, 8);
        mu = canon(-sgn(ux * k) * r.dyadic(1, 8, 8));
      } while (2 * (-ux * k * mu) < d * k * k * (1 + ux * ux));
      c.kind = "interior-tilting";
    }
    for (int i = 0; i < 2; ++i) move_through(c, 2 + i, p3(x[i], 0, 0), p3(0, 0, k * x[i]), tc);
    for (int j = 0; j < 2; ++j) move_through(c, j, p3(l[j] * ux, l[j], -d), p3(0, mu, 0), tc);
    c.toi = tc;
    c.moves = {{0, 2, -1}, {1, 2, -1}, {4, 2, -1}, {5, 2, -1}};
  } else {
    const Direction z{p3(0, 0, 1), 1};
    const Q high = lift(z, d)[2];
    for (int i = 0; i < 2; ++i) place_static(c, 2 + i, p3(x[i], 0, 0));
    for (int j = 0; j < 2; ++j) {
      c.rows[j] = p3(l[j] * ux, l[j], high);
      c.rows[j + 4] = p3(l[j] * ux, l[j], d);
    }
    c.toi = 1;
    c.moves = {{4, 2, 1}, {5, 2, 1}};
    c.kind = "interior-arriving";
  }
  return c;
}

// ms_ee_parallel: parallel edges, B = [q, q + L x^] static in H0 (n perpendicular to x^), A =
// [a0, a0 + L' x^] in Hd with a0(t) = q + d n^ + X(t) x^ + Y(t) m, m = n x x^ (in H0's plane,
// perpendicular to the edges). By the slab lemma A within d of B iff Y(t) = 0 and [X, X + L']
// meets [0, L].
// - side: Y = s Y' (Y' != 0), the x-intervals overlap at tc: t* = tc.
// - axial (sliding along each other): Y = 0, X(t) = L - s V with V > 0: X > L for s < 0, and
//   X = L at tc (a0 over b1): t* = tc.
// - overlapping: Y = 0 and the intervals overlap at t = 0: t* = 0 (then sliding along).
Construction ms_ee_parallel(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d, true);
  const P3 ex = p3(1, 0, 0);
  const P3 m = cross(dir.n, ex);
  const P3 q = random_vector(r);
  const Q length_b = r.dyadic(1, 16, 8);
  const Q length_a = r.dyadic(1, 16, 8);
  place_static(c, 2, q);
  place_static(c, 3, q + length_b * ex);
  const P3 base = q + offset(dir, d);
  const P3 along_a = length_a * ex;
  Q x_tc;  // X at tc, in [-length_a, length_b]: the intervals overlap
  do x_tc = r.dyadic(-16, 16, 8);
  while (x_tc < -length_a || x_tc > length_b);
  switch (group % 3) {
    case 0: {
      const Q tc = contact_time(r, group);
      const Q vx = r.dyadic(-8, 8, 8);
      const Q vy = r.nonzero_dyadic(-8, 8, 8);
      const P3 w = vx * ex + vy * m;
      move_through(c, 0, base + x_tc * ex, w, tc);
      move_through(c, 1, base + x_tc * ex + along_a, w, tc);
      c.toi = tc;
      c.kind = "parallel-side";
      break;
    }
    case 1: {
      const Q tc = contact_time(r, group);
      const P3 w = Q(-r.dyadic(1, 8, 8)) * ex;
      move_through(c, 0, base + length_b * ex, w, tc);
      move_through(c, 1, base + length_b * ex + along_a, w, tc);
      c.toi = tc;
      c.kind = "parallel-axial";
      break;
    }
    default: {
      const P3 slide = r.dyadic(-16, 16, 8) * ex;
      c.rows[0] = base + x_tc * ex;
      c.rows[1] = c.rows[0] + along_a;
      c.rows[4] = c.rows[0] + slide;
      c.rows[5] = c.rows[1] + slide;
      c.toi = 0;
      c.kind = "parallel-overlapping";
      break;
    }
  }
  c.moves = outward_moves(r, dir.n, {0, 1, 4, 5});
  return c;
}

// ms_ee_degenerate: A is a point (a0 = a1) moving with W perpendicular to n through q + d n^ at
// tc (in Hd, slab lemma).
// - point-edge-side: B = [q - alpha e, q + beta e] in H0, W not parallel to e: as
//   ms_ee_capsule (oblique), t* = tc.
// - point-edge-end: B = [q, q + u], n.u < 0: meets H0 only at q: t* = tc.
// - point-point: B = [q, q]: t* = tc.
Construction ms_ee_degenerate(Rng& r, int group, const Q& d) {
  Construction c;
  const Direction dir = random_direction(r, d);
  const P3 q = random_vector(r);
  P3 w;
  switch (group % 3) {
    case 0: {
      const P3 e = perpendicular(r, dir.n);
      const Q alpha = r.dyadic(1, 8, 8);
      const Q beta = r.dyadic(1, 8, 8);
      place_static(c, 2, q - alpha * e);
      place_static(c, 3, q + beta * e);
      w = perpendicular_not_along(r, dir.n, e);
      c.kind = "point-edge-side";
      break;
    }
    case 1:
      place_static(c, 2, q);
      place_static(c, 3, q + vector_on_side(r, dir.n, -1));
      w = perpendicular(r, dir.n);
      c.kind = "point-edge-end";
      break;
    default:
      place_static(c, 2, q);
      place_static(c, 3, q);
      w = perpendicular(r, dir.n);
      c.kind = "point-point";
      break;
  }
  const Q tc = contact_time(r, group);
  move_through(c, 0, q + offset(dir, d), w, tc);
  move_through(c, 1, q + offset(dir, d), w, tc);
  c.toi = tc;
  c.moves = outward_moves(r, dir.n, {0, 1, 4, 5});
  return c;
}

// ---------------------------------------------------------------------------------------------
// The table

using Builder = Construction (*)(Rng&, int group, const Q& d);

struct MinSeparationFamily {
  const char* name;
  QueryType type;
  Builder build;
  const char* description;
};

const std::vector<MinSeparationFamily>& ms_families() {
  static const std::vector<MinSeparationFamily> table = {
      {"ms_vf_vertex", QueryType::vertex_face, ms_vf_vertex,
       "The vertex passes a triangle vertex at distance exactly delta at t* (tangent to the "
       "vertex sphere; the triangle on the far side); near misses: the vertex moved 1 ulp / "
       "~2^-k delta farther along the direction of closest approach."},
      {"ms_vf_edge", QueryType::vertex_face, ms_vf_edge,
       "The vertex passes the interior of a triangle edge at distance exactly delta at t* "
       "(tangent to the edge capsule), the direction of closest approach in the triangle's "
       "plane or oblique to it; near misses: moved 1 ulp / ~2^-k delta farther."},
      {"ms_vf_face", QueryType::vertex_face, ms_vf_face,
       "The vertex at distance exactly delta from the face's plane: sliding at that height "
       "into the triangle through an edge at t*, sliding over the face from t = 0, or "
       "arriving at that height over the face at t = 1; near misses: 1 ulp / ~2^-k delta "
       "higher."},
      {"ms_vf_face_tilt", QueryType::vertex_face, ms_vf_face_tilt,
       "The triangle tilts so that the vertex is tangent to the face's plane at distance "
       "exactly delta at an interior time t*, over the face interior, an edge or a vertex; "
       "near misses: the vertex 1 ulp / ~2^-k delta higher, never within delta."},
      {"ms_vf_degenerate", QueryType::vertex_face, ms_vf_degenerate,
       "Degenerate triangles (three collinear vertices, or one point) passed by the vertex at "
       "distance exactly delta at t*, beside the segment or beyond its end; near misses: "
       "moved 1 ulp / ~2^-k delta farther."},
      {"ms_ee_endpoints", QueryType::edge_edge, ms_ee_endpoints,
       "Two endpoints pass each other at distance exactly delta at t* (the endpoints' "
       "sphere); near misses: moved 1 ulp / ~2^-k delta apart."},
      {"ms_ee_capsule", QueryType::edge_edge, ms_ee_capsule,
       "An endpoint of one edge passes the interior of the other at distance exactly delta at "
       "t* (the capsule's side), or the edges slide at distance exactly delta in parallel "
       "planes until they first overlap at t*; near misses: moved 1 ulp / ~2^-k delta apart."},
      {"ms_ee_interior", QueryType::edge_edge, ms_ee_interior,
       "The edges' lines tilt so that their distance is tangent to delta at an interior time "
       "t* with the closest points inside both edges, or crossing edges arrive at distance "
       "exactly delta at t = 1; near misses: moved 1 ulp / ~2^-k delta apart."},
      {"ms_ee_parallel", QueryType::edge_edge, ms_ee_parallel,
       "Parallel edges at distance exactly delta: approaching sideways until they overlap at "
       "t*, sliding along each other until their ends meet at t*, or overlapping from t = 0; "
       "near misses: 1 ulp / ~2^-k delta apart."},
      {"ms_ee_degenerate", QueryType::edge_edge, ms_ee_degenerate,
       "A zero-length edge (a point) passes the other edge's interior, its end, or another "
       "point at distance exactly delta at t*; near misses: moved 1 ulp / ~2^-k delta farther."},
  };
  return table;
}

const MinSeparationFamily& ms_family(const std::string& name) {
  for (const MinSeparationFamily& f : ms_families())
    if (name == f.name) return f;
  throw std::invalid_argument("unknown minimum-separation family: " + name);
}

/// delta / (geometry scale) = 2^-r with r in [kRatio - 1, kRatio): the geometry's size is
/// about 2^r times delta.
constexpr std::array<int, 5> kGeometryRatios = {2, 5, 10, 20, 30};
constexpr int kMaxAttempts = 10000;

Frame without_translation(Frame f) {
  f.translation = zero3();
  f.velocity = zero3();
  return f;
}

}  // namespace

const std::vector<std::string>& min_separation_family_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const MinSeparationFamily& f : ms_families()) out.push_back(f.name);
    return out;
  }();
  return names;
}

bool is_min_separation_family(const std::string& name) {
  const auto& names = min_separation_family_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string min_separation_delta_problem(double delta) {
  if (!std::isfinite(delta)) return "must be finite";
  if (delta < 0) return "must be >= 0";
  if (delta > 0 && (delta < std::ldexp(1.0, kMinSeparationMinExponent) ||
                    delta > std::ldexp(1.0, kMinSeparationMaxExponent)))
    return "must be 0 or lie in [2^" + std::to_string(kMinSeparationMinExponent) + ", 2^" +
           std::to_string(kMinSeparationMaxExponent) +
           "] (the families' geometry spans 2^2 to 2^36 times delta, in normal doubles)";
  return {};
}

Family generate_min_separation_family(const std::string& name, double delta, std::uint64_t seed,
                                      int per_family) {
  const MinSeparationFamily& spec = ms_family(name);
  check_per_family(per_family);
  const std::string problem = min_separation_delta_problem(delta);
  if (!problem.empty())
    throw std::invalid_argument("min_separation " + problem + ", got " + std::to_string(delta));
  Rng rng(splitmix64(seed ^ fnv1a(name)));
  const Q delta_q(delta);
  // Near misses 2^-k * 2^floor(log2 delta) beyond (a power of two, so that the move lands on
  // a double next to delta for every k <= 52, also when delta has 53 significant bits; 2^-k
  // alone when delta = 0, the geometry's scale being 1).
  const double offset_unit = delta > 0 ? std::ldexp(1.0, std::ilogb(delta)) : 1.0;
  Family family;
  family.name = family.base = name;
  family.type = spec.type;
  family.description = spec.description;
  std::map<std::string, int> kinds, ratios;
  std::set<std::string> times;
  int groups = 0, raised = 0;
  while (static_cast<int>(family.members.size()) < per_family) {
    Construction c;
    std::optional<Placed> placed;
    int ratio = 0;
    for (int attempt = 0; !placed; ++attempt) {
      if (attempt == kMaxAttempts)
        throw std::logic_error(name + ": no construction lands on doubles");
      ratio = kGeometryRatios[static_cast<std::size_t>(
          rng.uniform(0, static_cast<long>(kGeometryRatios.size()) - 1))];
      const Q scale = delta > 0 ? pow2(std::ilogb(delta) + ratio) : Q(1);
      c = spec.build(rng, groups, canon(delta_q / scale));
      for (P3& row : c.rows) row = scale * row;
      // The frame's translation and velocity at the geometry's scale.
      Frame frame = random_frame(rng, spec.type);
      frame.translation = scale * frame.translation;
      frame.velocity = scale * frame.velocity;
      placed = place(c, frame);
      if (!placed) placed = place(c, without_translation(frame));
    }
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
      Member m = near_miss(contact, partner, *placed, k < 0 ? 0 : kNearMissExponents[k],
                           offset_unit);
      const bool duplicate = std::any_of(group.begin(), group.end(),
                                         [&](const Member& g) { return g.points == m.points; });
      if (duplicate) continue;
      if (m.distance_log2 > 0 && m.distance != std::ldexp(offset_unit, -m.distance_log2))
        ++raised;
      group.push_back(std::move(m));
    }
    for (Member& m : group) {
      if (static_cast<int>(family.members.size()) == per_family) break;
      if (m.label == "contact") {
        times.insert(m.toi.get_str());
        ++ratios["2^-" + std::to_string(ratio)];
      }
      ++kinds[m.kind];
      family.members.push_back(std::move(m));
    }
  }
  nlohmann::json kind_counts = nlohmann::json::object();
  for (const auto& [k, v] : kinds) kind_counts[k] = v;
  nlohmann::json ratio_counts = nlohmann::json::object();
  for (const auto& [k, v] : ratios) ratio_counts[k] = v;
  std::vector<std::string> offsets = {"1ulp"};
  for (const int k : kNearMissExponents)
    offsets.push_back("2^-" + std::to_string(k) + (delta > 0 ? " * 2^floor(log2 delta)" : ""));
  family.parameters = {
      {"per_family", per_family},
      {"min_separation", delta},
      {"min_separation_exact", delta_q.get_str()},
      {"groups", groups},
      {"near_miss_offsets", offsets},
      {"near_misses_beyond_requested_offset", raised},
      {"kinds", kind_counts},
      {"contact_times", std::vector<std::string>(times.begin(), times.end())},
      // Contacts per ratio delta / geometry scale (the geometry's size is about 2^r delta).
      {"delta_over_geometry", ratio_counts},
      {"frame",
       "random signed axis permutation, vertex relabelling (edge swap and reversal), dyadic "
       "translation k/16 and common velocity k/8 per axis times the geometry's scale where "
       "exact (else the permutation alone), applied before the near-miss moves"},
  };
  return family;
}

std::vector<Family> generate_min_separation_families(double delta, std::uint64_t seed,
                                                     int per_family,
                                                     const std::vector<std::string>& names) {
  for (const std::string& name : names) ms_family(name);  // unknown names first
  std::vector<Family> out;
  for (const std::string& name : min_separation_family_names())
    if (names.empty() || std::find(names.begin(), names.end(), name) != names.end())
      out.push_back(generate_min_separation_family(name, delta, seed, per_family));
  return out;
}

}  // namespace exactccd::families
