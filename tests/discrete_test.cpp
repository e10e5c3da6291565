// The discrete baseline (exactccd/discrete.hpp) and its exact closed-triangle test
// (exact/reference/triangle_intersection.hpp).
//
// (a) triangles_intersect: hand-built cases whose answers follow from the geometry (crossing,
//     touching at a vertex or an edge point, coplanar overlap and separation, one-ulp gaps,
//     segment and point triangles), each under every vertex order and both argument orders;
//     then random, grid and near-degenerate inputs against an independent exact method: the
//     closed triangles meet iff the linear program "sum l_i a_i = sum m_j b_j, l, m >= 0,
//     sum l = sum m = 1" is feasible, decided here by enumerating basic solutions in GMP
//     rationals (no CGAL, no case analysis of degeneracies).
// (b) Scenes: a small tetrahedron passes through a static sheet within the step (discrete sees
//     nothing, the scene's CCD reports the contacts, each confirmed by the exact path); a
//     tetrahedron that ends inside the sheet (the bisection bracket against the first contact
//     time computed by hand); positions at t are the nearest doubles (a case where two
//     roundings would differ); intersecting_triangle_pairs against brute force over all
//     triangle pairs with the LP method on random grid scenes.
#include <gtest/gtest.h>

#include <gmpxx.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact/reference/triangle_intersection.hpp"
#include "exactccd/discrete.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/scene.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

using V = Eigen::Vector3d;
using Tri = std::array<V, 3>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// ---------------------------------------------------------------------------------------------
// The independent method: feasibility of a linear program, by basic solutions.
//
// Unknowns x = (l0, l1, l2, m0, m1, m2) >= 0 with A x = r, where the rows of A say
// l0 + l1 + l2 = 1, m0 + m1 + m2 = 1 and l0 a0 + l1 a1 + l2 a2 - m0 b0 - m1 b1 - m2 b2 = 0
// (three coordinates). The closed triangles (degenerate or not: they are the convex hulls of
// their vertices) share a point iff this system has a solution. By the fundamental theorem of
// linear programming a feasible system has a basic feasible solution, whose support is a set of
// linearly independent columns; that set extends to a basis B (rank(A) independent columns),
// and x_B is then the unique solution of A_B y = r. So the system is feasible iff for some set B
// of rank(A) independent columns, A_B y = r is consistent and its solution is >= 0. All such
// sets are tried.

/// Gauss-Jordan elimination of the first n columns of m (5 rows; column n is the right-hand
/// side); returns the rank of those n columns.
int eliminate(mpq_class (&m)[5][7], int n) {
  int rank = 0;
  for (int j = 0; j < n && rank < 5; ++j) {
    int pivot = -1;
    for (int row = rank; row < 5 && pivot < 0; ++row)
      if (sgn(m[row][j]) != 0) pivot = row;
    if (pivot < 0) continue;
    for (int c = 0; c <= n; ++c) std::swap(m[rank][c], m[pivot][c]);
    for (int row = 0; row < 5; ++row) {
      if (row == rank || sgn(m[row][j]) == 0) continue;
      const mpq_class f = m[row][j] / m[rank][j];
      for (int c = j; c <= n; ++c) m[row][c] -= f * m[rank][c];
    }
    ++rank;
  }
  return rank;
}

bool lp_triangles_intersect(const Tri& a, const Tri& b) {
  mpq_class A[5][6];
  const int r[5] = {1, 1, 0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    A[0][i] = 1;
    A[1][i] = 0;
    A[0][3 + i] = 0;
    A[1][3 + i] = 1;
    for (int k = 0; k < 3; ++k) {
      A[2 + k][i] = a[i][k];
      A[2 + k][3 + i] = -b[i][k];
    }
  }
  mpq_class m[5][7];
  for (int row = 0; row < 5; ++row)
    for (int c = 0; c < 6; ++c) m[row][c] = A[row][c];
  const int rank = eliminate(m, 6);
  for (int mask = 1; mask < 64; ++mask) {
    int cols[6], n = 0;
    for (int c = 0; c < 6; ++c)
      if (mask & (1 << c)) cols[n++] = c;
    if (n != rank) continue;
    for (int row = 0; row < 5; ++row) {
      for (int j = 0; j < n; ++j) m[row][j] = A[row][cols[j]];
      m[row][n] = r[row];
    }
    if (eliminate(m, n) != n) continue;  // dependent columns: not a basis
    // Rows n..4 are zero on the left: consistent iff zero on the right too.
    bool consistent = true;
    for (int row = n; row < 5; ++row)
      if (sgn(m[row][n]) != 0) consistent = false;
    if (!consistent) continue;
    // Row j reads m[j][j] y_j = m[j][n].
    bool nonnegative = true;
    for (int j = 0; j < n; ++j)
      if (sgn(m[j][n]) * sgn(m[j][j]) < 0) nonnegative = false;
    if (nonnegative) return true;
  }
  return false;
}

bool tested(const Tri& a, const Tri& b) {
  return exact::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
}

std::string describe(const Tri& a, const Tri& b) {
  std::string s;
  char buf[200];
  for (const Tri* t : {&a, &b}) {
    s += "\n ";
    for (const V& v : *t) {
      std::snprintf(buf, sizeof buf, " (%a, %a, %a)", v.x(), v.y(), v.z());
      s += buf;
    }
  }
  return s;
}

/// The hand-derived answer, checked against the LP method and then against triangles_intersect
/// under all 6 x 6 vertex orders and both argument orders.
void expect_meet(const Tri& a, const Tri& b, bool expected, const std::string& what) {
  SCOPED_TRACE(what + describe(a, b));
  EXPECT_EQ(lp_triangles_intersect(a, b), expected) << "the LP method disagrees with the hand answer";
  static constexpr int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int wrong = 0;
  for (const auto& p : perms)
    for (const auto& q : perms) {
      const Tri pa{a[p[0]], a[p[1]], a[p[2]]};
      const Tri qb{b[q[0]], b[q[1]], b[q[2]]};
      if (tested(pa, qb) != expected) ++wrong;
      if (tested(qb, pa) != expected) ++wrong;
    }
  EXPECT_EQ(wrong, 0) << "of 72 vertex and argument orders";
}

V v3(double x, double y, double z) { return V(x, y, z); }

/// The triangle scaled by 2^e (exact for the small dyadic coordinates used with it).
Tri scaled(const Tri& t, int e) {
  return {std::ldexp(1.0, e) * t[0], std::ldexp(1.0, e) * t[1], std::ldexp(1.0, e) * t[2]};
}

// The reference triangle of most hand cases: x, y >= 0, x + y <= 4 in the plane z = 0.
const Tri kA{v3(0, 0, 0), v3(4, 0, 0), v3(0, 4, 0)};

TEST(TrianglesIntersect, CrossingAndSeparated) {
  // B's edge from (1,1,-1) to (1,1,1) crosses z = 0 at (1,1,0), inside A.
  expect_meet(kA, {v3(1, 1, -1), v3(1, 1, 1), v3(5, 5, 0)}, true, "edge pierces the interior");
  // Both triangles cross each other's planes along segments that interleave: B is vertical
  // (plane y = 1), spanning x in [-1, 5]; it meets A along y = 1, x in [0, 3].
  expect_meet(kA, {v3(-1, 1, -1), v3(5, 1, -1), v3(2, 1, 3)}, true, "vertical triangle cuts A");
  // The same vertical triangle moved to y = 5: A has y <= 4.
  expect_meet(kA, {v3(-1, 5, -1), v3(5, 5, -1), v3(2, 5, 3)}, false, "beyond A's extent");
  // B entirely above z = 0 except one vertex at height 2^-1074 (the smallest double).
  expect_meet(kA, {v3(1, 1, kTiny), v3(1, 1, 1), v3(2, 1, 1)}, false, "one denormal above");
  // ... and with that vertex 2^-1074 below: B's edges cross z = 0 next to (1, 1), inside A.
  expect_meet(kA, {v3(1, 1, -kTiny), v3(1, 1, 1), v3(2, 1, 1)}, true, "one denormal below");
}

TEST(TrianglesIntersect, TouchingAtAVertexOrAnEdgePoint) {
  // B's vertex (2,2,0) is the midpoint of A's edge x + y = 4; B's other vertices are at z = 1.
  expect_meet(kA, {v3(2, 2, 0), v3(2, 2, 1), v3(3, 2, 1)}, true, "vertex on an edge of A");
  // One ulp outside (x + y > 4) and one ulp inside.
  expect_meet(kA, {v3(std::nextafter(2.0, kInf), 2, 0), v3(2, 2, 1), v3(3, 2, 1)}, false,
              "vertex one ulp outside the edge");
  expect_meet(kA, {v3(std::nextafter(2.0, 0.0), 2, 0), v3(2, 2, 1), v3(3, 2, 1)}, true,
              "vertex one ulp inside the edge");
  // Vertex on vertex: B's vertex is A's vertex (4,0,0); B otherwise at x > 4.
  expect_meet(kA, {v3(4, 0, 0), v3(5, 1, 1), v3(5, -1, 1)}, true, "vertex on vertex");
  // Edge through edge: B's edge from (3,3,-1) to (1,1,1) has z = 0 only at (2,2,0), A's edge
  // point; B meets z = 0 along the segment (2,2,0)-(4,4,0), where x + y >= 4.
  const Tri b{v3(3, 3, -1), v3(1, 1, 1), v3(5, 5, 1)};
  expect_meet(kA, b, true, "edge crosses edge at one point");
  // B shifted by 2^-50 along x: its trace on z = 0 now has x + y >= 4 + 2^-50 (all shifted
  // coordinates are doubles: 1, 3 and 5 have ulps <= 2^-50).
  const double s = 0x1p-50;
  expect_meet(kA, {v3(3 + s, 3, -1), v3(1 + s, 1, 1), v3(5 + s, 5, 1)}, false,
              "edge misses edge by 2^-50");
  // Scaling every coordinate by a power of two keeps each answer (exact for these inputs);
  // the extreme scales push the kernel's floating-point filters into overflow and underflow.
  for (int e : {-1070, -1000, -600, 600, 1000, 1019}) {
    expect_meet(scaled(kA, e), scaled(b, e), true, "edge crosses edge, scaled by 2^" + std::to_string(e));
    expect_meet(scaled(kA, e), scaled({v3(3, 3, -1), v3(1, 1, 1), v3(5, 5, 2)}, e), true,
                "edge crosses edge (other apex), scaled by 2^" + std::to_string(e));
    expect_meet(scaled(kA, e), scaled({v3(1, 1, -1), v3(1, 1, 1), v3(5, 5, 0)}, e), true,
                "pierce, scaled by 2^" + std::to_string(e));
    expect_meet(scaled(kA, e), scaled({v3(-1, 5, -1), v3(5, 5, -1), v3(2, 5, 3)}, e), false,
                "beyond, scaled by 2^" + std::to_string(e));
  }
}

TEST(TrianglesIntersect, Coplanar) {
  expect_meet(kA, {v3(1, 1, 0), v3(5, 1, 0), v3(1, 5, 0)}, true, "coplanar, overlapping");
  // B: x >= 2, y >= 2, x + y <= 8 in z = 0; A: x + y <= 4. They share only (2, 2, 0).
  expect_meet(kA, {v3(2, 2, 0), v3(6, 2, 0), v3(2, 6, 0)}, true, "coplanar, touching at a point");
  const double s = 0x1p-50;  // 2, 6 have ulps <= 2^-50
  expect_meet(kA, {v3(2 + s, 2, 0), v3(6 + s, 2, 0), v3(2 + s, 6, 0)}, false,
              "coplanar, 2^-50 apart");
  // Hexagram: neither holds a vertex of the other, the edges cross.
  expect_meet({v3(0, 0, 0), v3(6, 0, 0), v3(3, 6, 0)}, {v3(0, 4, 0), v3(6, 4, 0), v3(3, -2, 0)},
              true, "coplanar hexagram");
  // Sharing an edge segment: B's edge lies on A's edge x = 0, y in [1, 3]; B at x <= 0.
  expect_meet(kA, {v3(0, 1, 0), v3(0, 3, 0), v3(-2, 2, 0)}, true, "coplanar, sharing an edge part");
  // In the tilted plane x + y + z = 4: A' its part with x, y, z >= 0; the medial triangle (its
  // vertices are the midpoints of A's edges) lies in A'; a triangle of the plane at z < 0 misses
  // A', and touches it when one of its vertices is moved to an edge midpoint (the others stay
  // at z = -2).
  const Tri tilted{v3(4, 0, 0), v3(0, 4, 0), v3(0, 0, 4)};
  expect_meet(tilted, {v3(2, 2, 0), v3(2, 0, 2), v3(0, 2, 2)}, true, "tilted plane, medial triangle");
  expect_meet(tilted, {v3(3, 3, -2), v3(4, 2, -2), v3(3, 2, -1)}, false, "tilted plane, outside");
  expect_meet(tilted, {v3(3, 3, -2), v3(4, 2, -2), v3(2, 2, 0)}, true, "tilted plane, vertex on edge");
}

TEST(TrianglesIntersect, DegenerateTriangles) {
  // A segment from (0,0,0) to (4,4,4) (middle vertex listed first) meets z = 2 only at (2,2,2),
  // on the edge x + y = 4 of the first triangle, outside the second (x + y <= 3).
  const Tri segment{v3(2, 2, 2), v3(0, 0, 0), v3(4, 4, 4)};
  expect_meet(segment, {v3(0, 0, 2), v3(4, 0, 2), v3(0, 4, 2)}, true, "segment touches an edge");
  expect_meet(segment, {v3(0, 0, 2), v3(3, 0, 2), v3(0, 3, 2)}, false, "segment misses");
  // A segment lying in A's plane: y = 1, x in [-1, 5] crosses A; y = 5 misses it.
  expect_meet({v3(-1, 1, 0), v3(5, 1, 0), v3(2, 1, 0)}, kA, true, "coplanar segment crosses");
  expect_meet({v3(-1, 5, 0), v3(5, 5, 0), v3(2, 5, 0)}, kA, false, "coplanar segment misses");
  // A segment with a repeated vertex, ending on A's interior.
  expect_meet({v3(1, 1, 0), v3(1, 1, 3), v3(1, 1, 3)}, kA, true, "segment ends inside");
  expect_meet({v3(1, 1, kTiny), v3(1, 1, 3), v3(1, 1, 3)}, kA, false, "segment ends a denormal above");
  // Points.
  const V p(1, 1, 0);
  expect_meet({p, p, p}, kA, true, "point inside");
  expect_meet({v3(2, 2, 0), v3(2, 2, 0), v3(2, 2, 0)}, kA, true, "point on an edge");
  expect_meet({v3(1, 1, kTiny), v3(1, 1, kTiny), v3(1, 1, kTiny)}, kA, false, "point above");
  expect_meet({p, p, p}, {p, p, p}, true, "equal points");
  const V q(1, std::nextafter(1.0, kInf), 0);
  expect_meet({p, p, p}, {q, q, q}, false, "points one ulp apart");
  expect_meet({p, p, p}, {v3(0, 0, 0), v3(2, 2, 0), v3(2, 2, 0)}, true, "point on a segment");
  expect_meet({q, q, q}, {v3(0, 0, 0), v3(2, 2, 0), v3(2, 2, 0)}, false, "point one ulp off a segment");
  // Segments: crossing, lifted apart, collinear touching and one ulp apart.
  const Tri diagonal{v3(0, 0, 0), v3(2, 2, 0), v3(1, 1, 0)};
  expect_meet(diagonal, {v3(0, 2, 0), v3(2, 0, 0), v3(2, 0, 0)}, true, "segments cross");
  expect_meet(diagonal, {v3(0, 2, kTiny), v3(2, 0, kTiny), v3(2, 0, kTiny)}, false,
              "segments pass a denormal apart");
  const Tri on_x{v3(0, 0, 0), v3(2, 0, 0), v3(2, 0, 0)};
  expect_meet(on_x, {v3(2, 0, 0), v3(3, 0, 0), v3(5, 0, 0)}, true, "collinear, touching");
  expect_meet(on_x, {v3(1, 0, 0), v3(3, 0, 0), v3(5, 0, 0)}, true, "collinear, overlapping");
  expect_meet(on_x, {v3(std::nextafter(2.0, kInf), 0, 0), v3(3, 0, 0), v3(5, 0, 0)}, false,
              "collinear, one ulp apart");
  // Non-finite input is rejected.
  EXPECT_THROW(tested({v3(NAN, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, kA), std::invalid_argument);
  EXPECT_THROW(tested(kA, {v3(kInf, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Random comparison with the LP method.

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int integer(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

V grid_point(Rng& rng, int range) {
  return v3(integer(rng, -range, range), integer(rng, -range, range), integer(rng, -range, range));
}
V random_point(Rng& rng) { return v3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)); }

/// The rounded point sum w_i t_i (affine weights): on t's plane up to rounding.
V combination(const Tri& t, double w0, double w1) {
  return w0 * t[0] + w1 * t[1] + (1.0 - w0 - w1) * t[2];
}

/// Moves some coordinates to a neighbouring double.
void nudge(Rng& rng, Tri& t) {
  for (V& v : t)
    for (int k = 0; k < 3; ++k)
      if (integer(rng, 0, 3) == 0) v[k] = std::nextafter(v[k], integer(rng, 0, 1) ? kInf : -kInf);
}

struct Family {
  const char* name;
  int count;
  void (*make)(Rng&, Tri&, Tri&);
};

const Family kFamilies[] = {
    // Small integer coordinates: many collinear, coplanar and touching configurations.
    {"grid", 6000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (V& v : a) v = grid_point(rng, 2);
       for (V& v : b) v = grid_point(rng, 2);
     }},
    // The same, then coordinates moved by one ulp (zero becomes a denormal).
    {"grid + ulp", 6000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (V& v : a) v = grid_point(rng, 2);
       for (V& v : b) v = grid_point(rng, 2);
       nudge(rng, a);
       nudge(rng, b);
     }},
    {"uniform", 2000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (V& v : a) v = random_point(rng);
       for (V& v : b) v = random_point(rng);
     }},
    // B's vertices rounded onto A's plane (some inside A, some outside): nearly coplanar.
    {"near-coplanar", 3000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (V& v : a) v = random_point(rng);
       for (V& v : b) v = combination(a, uniform(rng, -0.5, 1.5), uniform(rng, -0.5, 1.5));
       if (integer(rng, 0, 1)) nudge(rng, b);
     }},
    // One vertex of B rounded onto A (inside, on an edge or at a vertex), the others anywhere.
    {"near-touching", 3000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (V& v : a) v = random_point(rng);
       const double choices[] = {0.0, 0.5, 1.0, 0.25, uniform(rng, 0, 1)};
       const double w0 = choices[integer(rng, 0, 4)];
       const double w1 = (1 - w0) * choices[integer(rng, 0, 4)];
       b[0] = combination(a, w0, w1);
       b[1] = random_point(rng);
       b[2] = integer(rng, 0, 1) ? random_point(rng) : V(2.0 * b[0] - b[1]);
       if (integer(rng, 0, 1)) nudge(rng, b);
     }},
    // A nearly degenerate: its third vertex rounded onto the line of the first two.
    {"near-collinear", 3000,
     [](Rng& rng, Tri& a, Tri& b) {
       a[0] = random_point(rng);
       a[1] = random_point(rng);
       const double s = integer(rng, 0, 1) ? uniform(rng, -0.5, 1.5) : 0.5;
       a[2] = a[0] + s * (a[1] - a[0]);
       if (integer(rng, 0, 1)) nudge(rng, a);
       for (V& v : b) v = integer(rng, 0, 1) ? random_point(rng) : V(combination(a, uniform(rng, 0, 1), 0.0));
     }},
    // Segments and points on the grid: a repeated vertex, three collinear grid points in any
    // order, or one point three times; sometimes against a proper grid triangle.
    {"degenerate grid", 4000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (Tri* t : {&a, &b}) {
         const V p = grid_point(rng, 1), d = grid_point(rng, 1);
         switch (integer(rng, 0, 3)) {
           case 0: *t = {p, p, p}; break;
           case 1: *t = {p, V(p + 2 * d), V(p + 2 * d)}; break;
           case 2: *t = {p, V(p + d), V(p - d)}; break;
           default: *t = {grid_point(rng, 1), grid_point(rng, 1), grid_point(rng, 1)}; break;
         }
         std::shuffle(t->begin(), t->end(), rng);
       }
     }},
    // Grid configurations scaled by powers of two far from 1 (exact), with ulp nudges.
    {"scaled grid + ulp", 3000,
     [](Rng& rng, Tri& a, Tri& b) {
       for (V& v : a) v = grid_point(rng, 3);
       for (V& v : b) v = grid_point(rng, 3);
       const int e = integer(rng, 0, 1) ? integer(rng, 900, 1020) : integer(rng, -1072, -900);
       a = scaled(a, e);
       b = scaled(b, e);
       if (integer(rng, 0, 1)) nudge(rng, a);
     }},
};

TEST(TrianglesIntersect, AgreesWithLinearProgramOnRandomAndNearDegenerateInputs) {
  const std::uint64_t seed = test_seed("triangles_intersect vs LP");
  for (const Family& family : kFamilies) {
    Rng rng(seed ^ std::hash<std::string>{}(family.name));
    int meet = 0, mismatches = 0;
    const int count = static_cast<int>(scaled_count(family.count));
    for (int i = 0; i < count; ++i) {
      Tri a, b;
      family.make(rng, a, b);
      const bool expected = lp_triangles_intersect(a, b);
      meet += expected;
      if (tested(a, b) != expected || tested(b, a) != expected) {
        if (++mismatches <= 5)
          ADD_FAILURE() << family.name << " #" << i << ": LP says " << expected << describe(a, b);
      }
    }
    EXPECT_EQ(mismatches, 0) << family.name;
    // Both answers must be well represented, or the family tests little.
    EXPECT_GT(meet, count / 20) << family.name;
    EXPECT_LT(meet, count - count / 20) << family.name;
    std::cout << "[ family   ] " << family.name << ": " << count << " pairs, " << meet
              << " meet\n";
  }
}

// ---------------------------------------------------------------------------------------------
// Scenes

Positions positions(std::initializer_list<std::array<double, 3>> rows) {
  Positions x(static_cast<Eigen::Index>(rows.size()), 3);
  Eigen::Index i = 0;
  for (const auto& r : rows) x.row(i++) << r[0], r[1], r[2];
  return x;
}

Triangles triangles(std::initializer_list<std::array<std::int32_t, 3>> rows) {
  Triangles t(static_cast<Eigen::Index>(rows.size()), 3);
  Eigen::Index i = 0;
  for (const auto& r : rows) t.row(i++) << r[0], r[1], r[2];
  return t;
}

/// The square [-1, 1]^2 at height z: triangle 0 is the half y <= x, triangle 1 the half y >= x.
MeshId add_sheet(Scene& scene, double z) {
  return scene.add_static_mesh(
      positions({{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}}), triangles({{0, 1, 2}, {0, 2, 3}}));
}

/// A tetrahedron with a horizontal base (vertices 0, 1, 2) at height z over (1/2, 1/8),
/// (3/4, 1/8), (1/2, 3/8) -- inside the sheet's half y < x -- and apex 3 at height z + 1/4 over
/// (1/2, 1/8). Triangle 0 is the base, 1..3 the sides (each holds the apex).
Positions tetrahedron_at(double z) {
  return positions({{0.5, 0.125, z}, {0.75, 0.125, z}, {0.5, 0.375, z}, {0.5, 0.125, z + 0.25}});
}
const Triangles kTetrahedron = triangles({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});

MeshId add_moving_tetrahedron(Scene& scene, double z_start, double z_end) {
  const MeshId id = scene.add_mesh(tetrahedron_at(z_start), kTetrahedron);
  scene.set_motion(id, tetrahedron_at(z_start), tetrahedron_at(z_end));
  return id;
}

TEST(DiscreteScene, ThinSheetPassedWithinTheStepIsMissed) {
  // The base descends from z = 1/2 to z = -1: it meets the sheet at t = 1/3 (1/2 - 3t/2 = 0),
  // the apex at t = 1/2; at t = 0 and t = 1 the tetrahedron is clear of the sheet.
  Scene scene;
  const MeshId sheet = add_sheet(scene, 0.0);
  const MeshId tet = add_moving_tetrahedron(scene, 0.5, -1.0);

  const DiscreteResult discrete = discrete_collision(scene);
  EXPECT_FALSE(discrete.collides);
  EXPECT_TRUE(discrete.pairs_at_end.empty());
  // No contact: +infinity, as CcdResult's.
  EXPECT_EQ(discrete.toi_lo, std::numeric_limits<double>::infinity());
  EXPECT_EQ(discrete.toi_hi, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(intersecting_triangle_pairs(scene, 0.0).empty());
  EXPECT_TRUE(intersecting_triangle_pairs(scene, 1.0).empty());
  // Mid-step the discrete test does see it (t = 1/2: the apex is on the sheet).
  EXPECT_FALSE(intersecting_triangle_pairs(scene, 0.5).empty());

  // CCD: each vertex of the tetrahedron passes through the sheet's triangle 0 (its x, y stay in
  // the half y < x, away from the diagonal and the border, so no edge-edge contact); the
  // rigid tetrahedron never touches itself.
  const SceneResult ccd = scene.find_contacts();
  std::vector<ScenePair> expected;
  for (std::uint32_t v = 0; v < 4; ++v) expected.push_back({QueryType::vertex_face, tet, v, sheet, 0});
  std::vector<ScenePair> got;
  for (const SceneContact& c : ccd.contacts) got.push_back(c.pair);
  EXPECT_EQ(got, expected);
  // The misses are real misses: the exact path confirms every contact, at the time expected.
  const mpq_class one_third(1, 3), one_half(1, 2);
  for (const SceneContact& c : ccd.contacts) {
    const RationalQuery q = c.pair.type == QueryType::vertex_face
                                ? to_rational(scene.vertex_face_query(c.pair))
                                : to_rational(scene.edge_edge_query(c.pair));
    const CcdResult r = exact_ccd(q);
    EXPECT_TRUE(r.collides);
    const mpq_class& t_star = c.pair.first_index == 3 ? one_half : one_third;
    EXPECT_LE(mpq_class(c.toi_lo), t_star);
    EXPECT_GE(mpq_class(c.toi_hi), t_star);
    EXPECT_EQ(r.toi_lo, c.toi_lo);
    EXPECT_EQ(r.toi_hi, c.toi_hi);
  }
}

TEST(DiscreteScene, BisectionBracketsTheFirstContact) {
  // Base from z = 1/2 to z = -1/8: first contact at 1/2 - 5t/8 = 0, t* = 4/5, not a double.
  // At t = 1 the sides cross the sheet (base at -1/8, apex at +1/8). At a probe t the rounded
  // base height has the sign of 4/5 - t (never zero: it is a nonzero multiple of 2^-64), so
  // the positions intersect iff t > 4/5, and bisection on [0, 1] keeps
  // lo = floor(4/5 2^k) / 2^k, hi = lo + 2^-k after k steps.
  Scene scene;
  add_sheet(scene, 0.0);
  add_moving_tetrahedron(scene, 0.5, -0.125);

  const std::vector<TrianglePair> at_end{{0, 0, 1, 1}, {0, 0, 1, 2}, {0, 0, 1, 3}};
  for (int steps : {0, 1, 2, 20, 40}) {
    DiscreteOptions options;
    options.bisection_steps = steps;
    const DiscreteResult r = discrete_collision(scene, options);
    ASSERT_TRUE(r.collides);
    EXPECT_EQ(r.pairs_at_end, at_end);
    const std::uint64_t floor_scaled = (std::uint64_t{4} << steps) / 5;  // floor(4/5 2^steps)
    EXPECT_EQ(r.toi_lo, std::ldexp(static_cast<double>(floor_scaled), -steps)) << steps;
    EXPECT_EQ(r.toi_hi, std::ldexp(static_cast<double>(floor_scaled + 1), -steps)) << steps;
  }
  // Beyond 53 steps no double lies strictly between the bracket's ends (spacing 2^-53 below 1):
  // bisection stops at the two consecutive doubles around 4/5.
  DiscreteOptions options;
  options.bisection_steps = 60;
  const DiscreteResult r = discrete_collision(scene, options);
  ASSERT_TRUE(r.collides);
  EXPECT_LT(mpq_class(r.toi_lo), mpq_class(4, 5));
  EXPECT_GT(mpq_class(r.toi_hi), mpq_class(4, 5));
  EXPECT_EQ(r.toi_hi, std::nextafter(r.toi_lo, 1.0));

  for (int bad : {-1, 61}) {
    options.bisection_steps = bad;
    EXPECT_THROW(discrete_collision(scene, options), std::invalid_argument);
  }
}

TEST(DiscreteScene, TouchingAtADyadicTimeCounts) {
  // Base from z = 3/4 to z = -1/4: it lies on the sheet at t* = 3/4, which bisection probes at
  // its second step (positions exactly 0 there: closed triangles touching intersect). At t = 1
  // the apex touches the sheet at (1/2, 1/8, 0), inside triangle 0: the three sides meet it.
  Scene scene;
  add_sheet(scene, 0.0);
  add_moving_tetrahedron(scene, 0.75, -0.25);
  const DiscreteResult r = discrete_collision(scene);  // 20 steps
  ASSERT_TRUE(r.collides);
  EXPECT_EQ(r.pairs_at_end, (std::vector<TrianglePair>{{0, 0, 1, 1}, {0, 0, 1, 2}, {0, 0, 1, 3}}));
  EXPECT_EQ(r.toi_hi, 0.75);
  EXPECT_EQ(r.toi_lo, 0.75 - 0x1p-20);
  // At 3/4 the base lies on the sheet: it overlaps triangle 0; the sides touch it along the
  // base's edges.
  EXPECT_EQ(intersecting_triangle_pairs(scene, 0.75),
            (std::vector<TrianglePair>{{0, 0, 1, 0}, {0, 0, 1, 1}, {0, 0, 1, 2}, {0, 0, 1, 3}}));
}

TEST(DiscreteScene, PositionsAreTheNearestDoubles) {
  // A horizontal triangle rises from z = z0 to z = 3 under a static sheet at z = 1; probed at
  // t = T, the double nearest 1/3: T = (2^54 - 1) / (3 2^54), so 3T = 1 - 2^-54, halfway between
  // the doubles 1 - 2^-53 and 1.
  //   z0 = 0:      z(T) = 1 - 2^-54, a tie, rounded to the even 1: on the sheet.
  //   z0 = 2^-60:  z(T) = 1 - 2^-54 + (2/3) 2^-60 - ..., above the tie: 1, on the sheet.
  //   z0 = -2^-60: z(T) = 1 - 2^-54 - (2/3) 2^-60 - ..., below the tie: 1 - 2^-53, under it.
  // (Two roundings, fl(fl(T (3 - z0)) + z0), would give 1 in the last case.)
  const double T = 1.0 / 3.0;
  for (const auto& [z0, on_sheet] :
       {std::pair{0.0, true}, std::pair{0x1p-60, true}, std::pair{-0x1p-60, false}}) {
    Scene scene;
    add_sheet(scene, 1.0);
    const auto at = [](double z) { return positions({{0, 0, z}, {0.5, 0, z}, {0, 0.5, z}}); };
    const MeshId m = scene.add_mesh(at(z0), triangles({{0, 1, 2}}));
    scene.set_motion(m, at(z0), at(3.0));
    const auto pairs = intersecting_triangle_pairs(scene, T);
    EXPECT_EQ(!pairs.empty(), on_sheet) << "z0 = " << z0;
  }
  // Near the top of the range: from z = 2^1001 down to 0, under a sheet at z = 2^1000, where the
  // doubles are 2^948 apart. z(t) = 2^1001 (1 - t):
  //   t = 1/2:           2^1000, on the sheet;
  //   t = 1/2 - 2^-54:   2^1000 + 2^947, a tie, rounded to the even 2^1000: on the sheet;
  //   t = 1/2 - 2^-53:   2^1000 + 2^948, a double above the sheet.
  for (const auto& [t, on_sheet] : {std::pair{0.5, true}, std::pair{0.5 - 0x1p-54, true},
                                    std::pair{0.5 - 0x1p-53, false}}) {
    Scene scene;
    add_sheet(scene, 0x1p1000);
    const auto at = [](double z) { return positions({{0, 0, z}, {0.5, 0, z}, {0, 0.5, z}}); };
    const MeshId m = scene.add_mesh(at(0x1p1001), triangles({{0, 1, 2}}));
    scene.set_motion(m, at(0x1p1001), at(0.0));
    EXPECT_EQ(!intersecting_triangle_pairs(scene, t).empty(), on_sheet) << "t = " << t;
  }
}

TEST(DiscreteScene, RejectsTimesOutsideTheStep) {
  Scene scene;
  add_sheet(scene, 0.0);
  for (double t : {-0x1p-1074, std::nextafter(1.0, 2.0), double(NAN), -kInf, kInf})
    EXPECT_THROW(intersecting_triangle_pairs(scene, t), std::invalid_argument) << t;
  EXPECT_TRUE(intersecting_triangle_pairs(scene, -0.0).empty());  // -0 == 0 is in the step
}

// Random grid scenes against brute force.

struct RandomMesh {
  bool is_static;
  Positions start, end;
  Triangles tri;
};

/// Small meshes on a grid of even integers, so that positions at t = 1/2 are exact integers.
std::vector<RandomMesh> random_scene(Rng& rng) {
  std::vector<RandomMesh> meshes(static_cast<std::size_t>(integer(rng, 1, 3)));
  for (RandomMesh& m : meshes) {
    m.is_static = integer(rng, 0, 2) == 0;
    const int n = integer(rng, 3, 7);
    m.start.resize(n, 3);
    m.end.resize(n, 3);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        m.start(i, k) = 2 * integer(rng, -2, 2);
        m.end(i, k) = m.is_static ? m.start(i, k) : 2 * integer(rng, -2, 2);
      }
    const int f = integer(rng, 1, 6);
    m.tri.resize(f, 3);
    for (int j = 0; j < f; ++j) {
      std::array<int, 3> ids;
      do {
        for (int& id : ids) id = integer(rng, 0, n - 1);
      } while (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2]);
      m.tri.row(j) << ids[0], ids[1], ids[2];
    }
  }
  return meshes;
}

/// Every pair allowed by the rules, decided by the LP method on positions (1 - t) x0 + t x1
/// computed in doubles (exact for these grid inputs at the times used).
std::vector<TrianglePair> brute_force(const std::vector<RandomMesh>& meshes, double t, bool self) {
  const auto vertex = [&](const RandomMesh& m, int f, int k) {
    const auto i = m.tri(f, k);
    return V(m.start.row(i).transpose() + t * (m.end.row(i) - m.start.row(i)).transpose());
  };
  std::vector<TrianglePair> out;
  for (std::size_t a = 0; a < meshes.size(); ++a)
    for (std::size_t b = a; b < meshes.size(); ++b) {
      const RandomMesh& ma = meshes[a];
      const RandomMesh& mb = meshes[b];
      if (ma.is_static && mb.is_static) continue;
      if (a == b && !self) continue;
      for (int i = 0; i < ma.tri.rows(); ++i)
        for (int j = a == b ? i + 1 : 0; j < mb.tri.rows(); ++j) {
          if (a == b) {
            bool shared = false;
            for (int k = 0; k < 3; ++k)
              for (int l = 0; l < 3; ++l) shared |= ma.tri(i, k) == mb.tri(j, l);
            if (shared) continue;
          }
          const Tri ta{vertex(ma, i, 0), vertex(ma, i, 1), vertex(ma, i, 2)};
          const Tri tb{vertex(mb, j, 0), vertex(mb, j, 1), vertex(mb, j, 2)};
          if (lp_triangles_intersect(ta, tb))
            out.push_back({static_cast<MeshId>(a), static_cast<std::uint32_t>(i),
                           static_cast<MeshId>(b), static_cast<std::uint32_t>(j)});
        }
    }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(DiscreteScene, IntersectingPairsMatchBruteForceOnRandomGridScenes) {
  const std::uint64_t seed = test_seed("intersecting_triangle_pairs vs brute force");
  Rng rng(seed);
  int nonempty = 0, bracket_checks = 0;
  const int scenes = static_cast<int>(scaled_count(150));
  for (int s = 0; s < scenes; ++s) {
    const std::vector<RandomMesh> meshes = random_scene(rng);
    Scene scene;
    for (const RandomMesh& m : meshes) {
      if (m.is_static) {
        scene.add_static_mesh(m.start, m.tri);
      } else {
        const MeshId id = scene.add_mesh(m.start, m.tri);
        scene.set_motion(id, m.start, m.end);
      }
    }
    for (const bool self : {true, false})
      for (const double t : {0.0, 0.5, 1.0}) {
        const auto expected = brute_force(meshes, t, self);
        nonempty += !expected.empty();
        EXPECT_EQ(intersecting_triangle_pairs(scene, t, self), expected)
            << "scene " << s << ", t = " << t << ", self = " << self;
        // One thread gives the same list.
        tbb::task_arena one(1);
        EXPECT_EQ(one.execute([&] { return intersecting_triangle_pairs(scene, t, self); }), expected);
      }
    // The bisection invariant: intersecting at toi_hi, not at toi_lo unless it is 0 (positions
    // at these multiples of 2^-20 are exact for even-integer grids).
    DiscreteOptions options;
    const DiscreteResult r = discrete_collision(scene, options);
    EXPECT_EQ(r.pairs_at_end, brute_force(meshes, 1.0, true));
    EXPECT_EQ(r.collides, !r.pairs_at_end.empty());
    if (r.collides) {
      EXPECT_EQ(r.toi_hi - r.toi_lo, 0x1p-20);
      EXPECT_FALSE(brute_force(meshes, r.toi_hi, true).empty());
      if (r.toi_lo > 0) EXPECT_TRUE(brute_force(meshes, r.toi_lo, true).empty());
      ++bracket_checks;
    }
  }
  // The grid makes intersections common; both outcomes must occur.
  EXPECT_GT(nonempty, scenes);
  EXPECT_LT(nonempty, 6 * scenes - scenes / 2);
  EXPECT_GT(bracket_checks, scenes / 4);
  std::cout << "[ scenes   ] " << scenes << " scenes, " << nonempty << " of " << 6 * scenes
            << " probes non-empty, " << bracket_checks << " bisections checked\n";
}

}  // namespace
}  // namespace exactccd::test
