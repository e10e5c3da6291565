// Hand-made degenerate CCD queries with their exact expected verdict and first contact time.
//
// Every expectation is derived by hand from the motion (the one-line derivation is the comment
// above each case); none was obtained by running the library. Coordinates are small dyadic
// numbers, hence exact doubles, so the double and the rational form of a query are the same
// query. Semantics: every vertex moves x(t) = (1 - t) x_t0 + t x_t1; a query collides iff the
// closed primitives share a point at some t in the closed interval [0, t_max].
//
// Notation in the comments: T is the static unit triangle a = (0,0,0), b = (1,0,0),
// c = (0,1,0) in the plane z = 0; "cubic" is the coplanarity polynomial
// det[b - a, c - a, p - a](t) (vertex-face) or det[a1 - a0, b0 - a0, b1 - a0](t) (edge-edge).
#pragma once

#include <array>
#include <vector>

#include "exactccd/rational_query.hpp"

namespace exactccd::testing {

struct CasePoint {
  double x, y, z;
};

/// The four points of a query at one instant, in the benchmark's row order
/// (vertex-face: p, a, b, c; edge-edge: ea0, ea1, eb0, eb1).
struct CaseFrame {
  CasePoint v0, v1, v2, v3;
};

/// The exact earliest contact time t*, in one of two forms:
/// - `rational`: t* = p/q (a string mpq_class parses);
/// - `poly`: t* is the only root of poly[0] + poly[1] t + poly[2] t^2 + poly[3] t^3 in the
///   open interval (root_lo, root_hi), and t* is irrational (all strings parse as mpq_class;
///   a null coefficient is 0).
/// Both null: the query does not collide.
struct ExpectedToi {
  const char* rational = nullptr;
  std::array<const char*, 4> poly{};
  const char* root_lo = nullptr;
  const char* root_hi = nullptr;

  bool is_rational() const { return rational != nullptr; }
};

inline ExpectedToi no_contact() { return {}; }
inline ExpectedToi at(const char* rational) { return {rational, {}, nullptr, nullptr}; }
inline ExpectedToi irrational_root_of(std::array<const char*, 4> poly, const char* lo,
                                      const char* hi) {
  return {nullptr, poly, lo, hi};
}

struct DegenerateCase {
  const char* name;
  QueryType type;
  std::array<CasePoint, 8> points;  // benchmark row order: frame at t=0, then frame at t=1
  double t_max;
  bool collides;
  ExpectedToi toi;
};

inline DegenerateCase make_case(const char* name, QueryType type, const CaseFrame& t0,
                                const CaseFrame& t1, const ExpectedToi& toi,
                                double t_max = 1.0) {
  return {name,  type, {t0.v0, t0.v1, t0.v2, t0.v3, t1.v0, t1.v1, t1.v2, t1.v3},
          t_max, toi.rational != nullptr || toi.poly[0] != nullptr || toi.poly[1] != nullptr ||
                     toi.poly[2] != nullptr || toi.poly[3] != nullptr,
          toi};
}

/// Vertex-face: frames list p, a, b, c.
inline DegenerateCase vf(const char* name, const CaseFrame& t0, const CaseFrame& t1,
                         const ExpectedToi& toi, double t_max = 1.0) {
  return make_case(name, QueryType::vertex_face, t0, t1, toi, t_max);
}

/// Edge-edge: frames list ea0, ea1, eb0, eb1.
inline DegenerateCase ee(const char* name, const CaseFrame& t0, const CaseFrame& t1,
                         const ExpectedToi& toi, double t_max = 1.0) {
  return make_case(name, QueryType::edge_edge, t0, t1, toi, t_max);
}

inline RationalQuery to_rational_query(const DegenerateCase& c) {
  RationalQuery q;
  q.type = c.type;
  for (int i = 0; i < 8; ++i)
    q.points[i] = {mpq_class(c.points[i].x), mpq_class(c.points[i].y),
                   mpq_class(c.points[i].z)};
  return q;
}

// clang-format off
inline std::vector<DegenerateCase> degenerate_cases() {
  return {
    // ---------------------------------------------------------------- vertex-face, cubic != 0
    // p falls straight through T at (1/4,1/4): z = 1 - 2t = 0 at t = 1/2, inside T.
    vf("vf_face_interior_at_half",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2")),
    // z = 1 - 3t = 0 at t = 1/3 (not a double), p = (1/4,1/4,0) inside T.
    vf("vf_face_interior_at_one_third",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/3")),
    // Same motion with t_max = 1/2: contact at 1/3 < t_max still reported.
    vf("vf_face_interior_at_one_third_tmax_half",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/3"), 0.5),
    // T moves down through the static p = (1/4,1/4,0): plane z = 1 - 3t = 0 at t = 1/3.
    vf("vf_triangle_moves_through_static_vertex",
       {{0.25, 0.25, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
       {{0.25, 0.25, 0}, {0, 0, -2}, {1, 0, -2}, {0, 1, -2}}, at("1/3")),
    // p already in T at t = 0 (z = -t), leaves the plane afterwards: t* = 0.
    vf("vf_inside_at_t0",
       {{0.25, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("0")),
    // z = 1 - t reaches 0 exactly at t = 1 = t_max, inside T.
    vf("vf_contact_at_t1",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1")),
    // z = 1 - 2t reaches 0 exactly at t = 1/2 = t_max.
    vf("vf_contact_at_tmax_half",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2"), 0.5),
    // z = 1 - (2 - 2^-50) t = 0 at t = 2^50/(2^51 - 1) > 1/2 = t_max: not reported.
    vf("vf_contact_just_after_tmax_half",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -1 + 0x1p-50}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, no_contact(), 0.5),
    // Same motion with t_max = 1: t* = 1/(2 - 2^-50) = 2^50/(2^51 - 1), odd denominator so
    // not a double; it lies just above the double 1/2 + 2^-52.
    vf("vf_contact_just_after_half_tmax_one",
       {{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.25, 0.25, -1 + 0x1p-50}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       at("1125899906842624/2251799813685247")),
    // p crosses z = 0 at t = 1/2 at (1/2,0,0): the midpoint of edge ab.
    vf("vf_hits_edge_ab",
       {{0.5, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.5, 0, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2")),
    // p crosses z = 0 at t = 1/2 at (1/2,1/2,0): on edge bc (x + y = 1).
    vf("vf_hits_edge_bc",
       {{0.5, 0.5, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.5, 0.5, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2")),
    // p crosses z = 0 at t = 1/2 exactly at the vertex b = (1,0,0).
    vf("vf_hits_vertex_b",
       {{1, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{1, 0, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2")),
    // p crosses z = 0 only at (1/2,-2^-40,0): y < 0, just outside edge ab.
    vf("vf_near_miss_outside_edge_ab",
       {{0.5, -0x1p-40, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.5, -0x1p-40, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, no_contact()),
    // p crosses z = 0 only at (1/2, 1/2 + 2^-53, 0): x + y = 1 + 2^-53 > 1, just outside bc.
    vf("vf_near_miss_outside_edge_bc",
       {{0.5, 0.5 + 0x1p-53, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.5, 0.5 + 0x1p-53, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, no_contact()),

    // ---------------------------------------------------------------- grazing / several roots
    // Below, a = (0,0,0), b = (1,0,0) static and c = (0,1,-1+2t) tilts about edge ab, so the
    // plane is {u b + v c} and the cubic is -c_z p_y + p_z; p is in the closed triangle iff it
    // is coplanar with u = p_x >= 0, v = p_y >= 0, u + v <= 1.
    // p = (1/4, 1/2 - t/2, -1/4 + t/2): cubic = (1-2t)(1/2-t/2) - 1/4 + t/2 = (t - 1/2)^2,
    // a double root; at t = 1/2 p = (1/4,1/4,0) is inside: grazing contact.
    vf("vf_double_root_grazing_inside",
       {{0.25, 0.5, -0.25}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}},
       {{0.25, 0, 0.25}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}}, at("1/2")),
    // Same with p_x = 2: cubic (t - 1/2)^2 again, but u + v = 2 + 1/4 > 1 at t = 1/2.
    vf("vf_double_root_grazing_outside",
       {{2, 0.5, -0.25}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}},
       {{2, 0, 0.25}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}}, no_contact()),
    // p = (3/4, 1/2 - t/2, -5/16 + t/2): cubic = t^2 - t + 3/16 = (t - 1/4)(t - 3/4);
    // u + v = 3/4 + 3/8 > 1 at t = 1/4 (miss), 3/4 + 1/8 <= 1 at t = 3/4 (contact).
    vf("vf_two_roots_first_misses",
       {{0.75, 0.5, -0.3125}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}},
       {{0.75, 0, 0.1875}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}}, at("3/4")),
    // Same with p_x = 5/4: u > 1 at both roots 1/4 and 3/4, no contact.
    vf("vf_two_roots_none_contact",
       {{1.25, 0.5, -0.3125}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}},
       {{1.25, 0, 0.1875}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}}, no_contact()),
    // p = (1/4, 1 - t, -2 + 3t): cubic = (1-2t)(1-t) - 2 + 3t = 2t^2 - 1, only root in [0,1]
    // is sqrt(2)/2; there v = 1 - sqrt(2)/2 ~ 0.29, u + v ~ 0.54: inside.
    vf("vf_irrational_sqrt2_over_2",
       {{0.25, 1, -2}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}},
       {{0.25, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}},
       irrational_root_of({"-1", "0", "2", nullptr}, "0", "1")),
    // a = 0, b = (1,0,4t-1), c = (2t-1,1,0), p = (0,6-8t,0): cubic = b_z c_x p_y
    // = (4t-1)(2t-1)(6-8t), roots 1/4, 1/2, 3/4. t = 1/4: T' in z = 0 has y <= 1 < p_y = 4;
    // t = 1/2: p = 2c outside; t = 3/4: p = a. First contact at the third root.
    vf("vf_three_roots_third_contact",
       {{0, 6, 0}, {0, 0, 0}, {1, 0, -1}, {-1, 1, 0}},
       {{0, -2, 0}, {0, 0, 0}, {1, 0, 3}, {1, 1, 0}}, at("3/4")),

    // ---------------------------------------------------------------- vertex-face, coplanar
    // Everything in z = 0 (cubic == 0). p_x = -1 + 3t enters T through edge ca at t = 1/3.
    vf("vf_coplanar_enters_through_edge_at_one_third",
       {{-1, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{2, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/3")),
    // p_x = -1 + 3t/2 reaches edge ca at t = 2/3.
    vf("vf_coplanar_enters_at_two_thirds",
       {{-1, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.5, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("2/3")),
    // Same motion, t_max = 1/2: entry at 2/3 is after t_max.
    vf("vf_coplanar_enters_after_tmax_half",
       {{-1, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0.5, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, no_contact(), 0.5),
    // p starts inside T and slides within the plane: t* = 0.
    vf("vf_coplanar_inside_at_t0",
       {{0.25, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{3, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("0")),
    // p slides along y = 2 > 1, never in T.
    vf("vf_coplanar_passes_by",
       {{-1, 2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{2, 2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, no_contact()),
    // p = (2t, -1+2t, 0) on the line x - y = 1, which meets T only at b: reached at t = 1/2.
    vf("vf_coplanar_grazes_vertex_b",
       {{0, -1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{2, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2")),
    // Line x - y = 1 + 2^-30 misses T (y >= 0 forces x >= 1 + 2^-30 > 1 - y).
    vf("vf_coplanar_near_miss_vertex_b",
       {{0x1p-30, -1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{2 + 0x1p-30, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, no_contact()),
    // p = (-1+2t, 2-2t, 0) slides along the line of edge bc (x + y = 1), reaching c at t = 1/2.
    vf("vf_coplanar_along_edge_line_reaches_c",
       {{-1, 2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at("1/2")),
    // Triangle (1,0,0),(0,1,0),(0,0,1) in x+y+z = 1 (barycentrics = coordinates);
    // p = (1-2t, 1-2t, -1+4t) stays in the plane, all coordinates >= 0 first at t = 1/4.
    vf("vf_coplanar_tilted_plane_enters_at_quarter",
       {{1, 1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
       {{-1, -1, 3}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, at("1/4")),
    // T translates by (2t,0,0) toward static p = (3/2,1/4,0): in T's frame p = (3/2-2t, 1/4),
    // x + y <= 1 from t = 3/8 (through edge bc).
    vf("vf_triangle_translates_in_plane",
       {{1.5, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{1.5, 0.25, 0}, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}}, at("3/8")),
    // a = 0, b = (1-t, t), c = (-t, 1-t) turns (and shrinks) in z = 0; static p = (-1/2,1/4):
    // det(c, p) = 1/2 - 3t/4 vanishes at t = 2/3 where p = (3/4) c is on edge ca; before, p
    // is on the far side of line ac.
    vf("vf_triangle_rotates_in_plane",
       {{-0.5, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{-0.5, 0.25, 0}, {0, 0, 0}, {0, 1, 0}, {-1, 0, 0}}, at("2/3")),
    // c = (0,1,-1+2t) tilts the plane; p = (3/2-3t, 1/2, (1/2)(-1+2t)) = u b + v c with
    // u = 3/2 - 3t, v = 1/2: coplanar throughout; u + v <= 1 from t = 1/3 (u >= 0 until 1/2).
    vf("vf_triangle_tilts_with_vertex_coplanar",
       {{1.5, 0.5, -0.5}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}},
       {{-1.5, 0.5, 0.5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}}, at("1/3")),
    // Static p = 0, a = (2,-2,0), b = (-t,-1,0), c = (1,2t,0): orient(b,c,p) = 1 - 2t^2 > 0
    // and orient(b,c,a) = -2t^2 - 6t - 3 < 0 until sqrt(2)/2, where p = 0 lies on segment bc
    // (c = -sqrt(2) b).
    vf("vf_coplanar_irrational_sqrt2_over_2",
       {{0, 0, 0}, {2, -2, 0}, {0, -1, 0}, {1, 0, 0}},
       {{0, 0, 0}, {2, -2, 0}, {-1, -1, 0}, {1, 2, 0}},
       irrational_root_of({"-1", "0", "2", nullptr}, "0", "1")),

    // ---------------------------------------------------------------- degenerate triangles
    // Triangle = segment [0,2] on the x axis; p = (3/2, 1-2t, 1-2t) meets the axis at t = 1/2.
    vf("vf_segment_triangle_hit",
       {{1.5, 1, 1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}},
       {{1.5, -1, -1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, at("1/2")),
    // p meets the x axis only at (3,0,0), outside the segment [0,2].
    vf("vf_segment_triangle_miss",
       {{3, 1, 1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}},
       {{3, -1, -1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, no_contact()),
    // Triangle = the point (1,1,1); p = (2t,2t,2t) passes through it at t = 1/2.
    vf("vf_point_triangle_hit",
       {{0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}},
       {{2, 2, 2}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, at("1/2")),
    // p = (2t, 2t, (2+2^-30) t): x = 1 only at t = 1/2, where z = 1 + 2^-31 != 1.
    vf("vf_point_triangle_miss",
       {{0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}},
       {{2, 2, 2 + 0x1p-30}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, no_contact()),
    // Point triangle (3t,0,0) runs into the static p = (1,0,0) at t = 1/3.
    vf("vf_moving_point_triangle_hits_vertex",
       {{1, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
       {{1, 0, 0}, {3, 0, 0}, {3, 0, 0}, {3, 0, 0}}, at("1/3")),
    // a = 0, b = (1,0,0), c = (1+2t, 1-2t, 0): in z = 0 the triangle meets the x axis only in
    // [0,1], except at t = 1/2 where it flips through the segment [0,2]; static p = (3/2,0,0)
    // is touched exactly then.
    vf("vf_flipping_triangle_vertex_in_plane_hit",
       {{1.5, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
       {{1.5, 0, 0}, {0, 0, 0}, {1, 0, 0}, {3, -1, 0}}, at("1/2")),
    // Same flip, p = (5/2,0,0) lies beyond the flip segment [0,2].
    vf("vf_flipping_triangle_vertex_in_plane_miss",
       {{2.5, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
       {{2.5, 0, 0}, {0, 0, 0}, {1, 0, 0}, {3, -1, 0}}, no_contact()),
    // Same flip, p = (3/2, 0, 1-2t) crosses z = 0 at t = 1/2: normal (0,0,1-2t), so the cubic
    // is (1-2t)^2 (double root) and the triangle is the segment [0,2] there, containing p.
    vf("vf_flipping_triangle_double_root_hit",
       {{1.5, 0, 1}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
       {{1.5, 0, -1}, {0, 0, 0}, {1, 0, 0}, {3, -1, 0}}, at("1/2")),

    // ---------------------------------------------------------------- edge-edge, cubic != 0
    // ea = [-1,1] on the x axis; eb = x = 0, y in [-1,1], z = 1 - 2t: they cross at the origin
    // at t = 1/2.
    ee("ee_cross_interior_at_half",
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}},
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, -1}, {0, 1, -1}}, at("1/2")),
    // z = 1 - 3t: crossing at t = 1/3 (not a double).
    ee("ee_cross_interior_at_one_third",
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}},
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, -2}, {0, 1, -2}}, at("1/3")),
    // z = t: the edges cross at t = 0 and separate.
    ee("ee_cross_at_t0",
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}},
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}}, at("0")),
    // z = 1 - t: crossing exactly at t = 1.
    ee("ee_cross_at_t1",
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}},
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}}, at("1")),
    // z = 1 - 2t, t_max = 1/2: crossing exactly at t_max.
    ee("ee_cross_at_tmax_half",
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}},
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, -1}, {0, 1, -1}}, at("1/2"), 0.5),
    // z = 1 - (2 - 2^-50) t: crossing at 2^50/(2^51 - 1) > 1/2 = t_max, not reported.
    ee("ee_cross_just_after_tmax_half",
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}},
       {{-1, 0, 0}, {1, 0, 0}, {0, -1, -1 + 0x1p-50}, {0, 1, -1 + 0x1p-50}}, no_contact(),
       0.5),
    // ea = [0,1] on the x axis; eb = {x = 1, y in [0,1], z = 1-2t}: eb0 meets ea1 at t = 1/2
    // (cubic = -z), endpoint against endpoint.
    ee("ee_endpoints_touch",
       {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}},
       {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {1, 1, -1}}, at("1/2")),
    // Same with eb at x = 1 + 2^-40: at the only coplanar instant eb0 is 2^-40 beyond ea1.
    ee("ee_endpoints_near_miss",
       {{0, 0, 0}, {1, 0, 0}, {1 + 0x1p-40, 0, 1}, {1 + 0x1p-40, 1, 1}},
       {{0, 0, 0}, {1, 0, 0}, {1 + 0x1p-40, 0, -1}, {1 + 0x1p-40, 1, -1}}, no_contact()),
    // ea = [0,1] on the x axis, fixed; eb = [-1,1] at x = 1/2 with eb0 = (1/2,1,2t-1) and
    // eb1 = (1/2,-2t,1-2t): cubic = eb0_y eb1_z - eb0_z eb1_y = (2t-1)^2 (double root); at
    // t = 1/2 eb = (1/2,1,0)-(1/2,-1,0) crosses ea at (1/2,0,0).
    ee("ee_double_root_grazing_cross",
       {{0, 0, 0}, {1, 0, 0}, {0.5, 1, -1}, {0.5, 0, 1}},
       {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 1}, {0.5, -2, -1}}, at("1/2")),
    // Same at x = 3/2: at t = 1/2 eb crosses the x axis at (3/2,0,0), outside ea.
    ee("ee_double_root_grazing_miss",
       {{0, 0, 0}, {1, 0, 0}, {1.5, 1, -1}, {1.5, 0, 1}},
       {{0, 0, 0}, {1, 0, 0}, {1.5, 1, 1}, {1.5, -2, -1}}, no_contact()),
    // ea = [0,1] on the x axis; eb0 = (1/2, 1, -2+8t), eb1 = (1/2, 1-2t, 1-4t): cubic =
    // (1-4t) - (-2+8t)(1-2t) = 16t^2 - 16t + 3, roots 1/4, 3/4. At 1/4 eb = (1,0)-(1/2,0) in
    // (y,z), not through the axis; at 3/4 eb = (1,4)-(-1/2,-2) crosses it at (1/2,0,0).
    ee("ee_two_roots_first_misses",
       {{0, 0, 0}, {1, 0, 0}, {0.5, 1, -2}, {0.5, 1, 1}},
       {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 6}, {0.5, -1, -3}}, at("3/4")),
    // Same at x = 5/4: the crossing at 3/4 is at (5/4,0,0), outside ea; no contact.
    ee("ee_two_roots_none_contact",
       {{0, 0, 0}, {1, 0, 0}, {1.25, 1, -2}, {1.25, 1, 1}},
       {{0, 0, 0}, {1, 0, 0}, {1.25, 1, 6}, {1.25, -1, -3}}, no_contact()),
    // ea = [0,1] on the x axis; eb0 = (1/2, t, 1), eb1 = (1/2, -1, -1-t): cubic = t(-1-t) + 1
    // = 1 - t - t^2, only root in [0,1] is (sqrt(5)-1)/2, where eb1 = -(1+t) eb0 in (y,z), so
    // eb crosses the axis at x = 1/2.
    ee("ee_irrational_golden_ratio",
       {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 1}, {0.5, -1, -1}},
       {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 1}, {0.5, -1, -2}},
       irrational_root_of({"-1", "1", "1", nullptr}, "0", "1")),

    // ---------------------------------------------------------------- edge-edge, coplanar
    // Parallel (cubic == 0): eb stays in the plane y = 1, ea in y = 0; never touch.
    ee("ee_parallel_never_touch",
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
       {{0, 0, 0}, {1, 0, 0}, {2, 1, 1}, {3, 1, 1}}, no_contact()),
    // ea = [0,2] on the x axis; eb = [1,3] x {(1-2t, 1-2t)} becomes collinear at t = 1/2,
    // overlapping in [1,2].
    ee("ee_parallel_become_collinear_overlap",
       {{0, 0, 0}, {2, 0, 0}, {1, 1, 1}, {3, 1, 1}},
       {{0, 0, 0}, {2, 0, 0}, {1, -1, -1}, {3, -1, -1}}, at("1/2")),
    // Collinear, overlapping in [1,2] at t = 0, then eb leaves sideways.
    ee("ee_collinear_overlap_at_t0",
       {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {3, 0, 0}},
       {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0}}, at("0")),
    // Collinear throughout on the x axis: ea = [0,1], eb = [2+t, 3+t] moves away.
    ee("ee_collinear_disjoint_throughout",
       {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}},
       {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0}}, no_contact()),
    // Collinear: eb = [3 - 3t/2, 4 - 3t/2] approaches ea = [0,1] but stops at [3/2,5/2].
    ee("ee_collinear_approach_never_touch",
       {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0}},
       {{0, 0, 0}, {1, 0, 0}, {1.5, 0, 0}, {2.5, 0, 0}}, no_contact()),
    // Collinear: eb0 = 2 - 3t reaches ea1 = 1 at t = 1/3 (endpoint touch), then overlaps.
    ee("ee_collinear_slide_into_overlap",
       {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}},
       {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 0}}, at("1/3")),
    // In z = 0: eb = {x = 1/2, y in [1-2t, 2-2t]} descends onto ea = [0,1]; eb1 touches ea's
    // interior at t = 1/2.
    ee("ee_coplanar_endpoint_hits_interior",
       {{0, 0, 0}, {1, 0, 0}, {0.5, 2, 0}, {0.5, 1, 0}},
       {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0.5, -1, 0}}, at("1/2")),
    // In z = 0: eb = {x = 2 - 3t, y in [-1,1]} sweeps left; meets ea = [0,1] first at its
    // endpoint ea1 = (1,0,0) at t = 1/3.
    ee("ee_coplanar_sweep_hits_endpoint",
       {{0, 0, 0}, {1, 0, 0}, {2, -1, 0}, {2, 1, 0}},
       {{0, 0, 0}, {1, 0, 0}, {-1, -1, 0}, {-1, 1, 0}}, at("1/3")),
    // In z = 0: the edges cross at (1/2,0,0) at t = 0, then eb moves away to x = 3.
    ee("ee_coplanar_crossing_at_t0",
       {{0, 0, 0}, {1, 0, 0}, {0.5, -1, 0}, {0.5, 1, 0}},
       {{0, 0, 0}, {1, 0, 0}, {3, -1, 0}, {3, 1, 0}}, at("0")),
    // In z = 0: ea = [0, (-2,2)] fixed, eb = (-t,-1)-(1,2t): orient(eb0,eb1,ea0) = 1 - 2t^2 and
    // orient(eb0,eb1,ea1) = -2t^2 + 6t + 5 > 0, so ea is on one side of eb's line until
    // sqrt(2)/2, where ea0 = 0 lies on eb (eb1 = -sqrt(2) eb0).
    ee("ee_coplanar_irrational_sqrt2_over_2",
       {{0, 0, 0}, {-2, 2, 0}, {0, -1, 0}, {1, 0, 0}},
       {{0, 0, 0}, {-2, 2, 0}, {-1, -1, 0}, {1, 2, 0}},
       irrational_root_of({"-1", "0", "2", nullptr}, "0", "1")),

    // ---------------------------------------------------------------- zero-length edges
    // ea is the point (1/2, 1-2t, 1-2t), eb = [0,1] on the x axis: it lands on eb at t = 1/2.
    ee("ee_point_hits_edge",
       {{0.5, 1, 1}, {0.5, 1, 1}, {0, 0, 0}, {1, 0, 0}},
       {{0.5, -1, -1}, {0.5, -1, -1}, {0, 0, 0}, {1, 0, 0}}, at("1/2")),
    // The point crosses the x axis at (3/2,0,0), beyond eb = [0,1].
    ee("ee_point_misses_edge",
       {{1.5, 1, 1}, {1.5, 1, 1}, {0, 0, 0}, {1, 0, 0}},
       {{1.5, -1, -1}, {1.5, -1, -1}, {0, 0, 0}, {1, 0, 0}}, no_contact()),
    // Both edges are points: (3t,3t,3t) and (1,3t,3t) coincide at t = 1/3.
    ee("ee_points_meet",
       {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}},
       {{3, 3, 3}, {3, 3, 3}, {1, 3, 3}, {1, 3, 3}}, at("1/3")),
    // (3t,3t,3t) and (1, 3t, 3t + 2^-20): the z coordinates never agree.
    ee("ee_points_miss",
       {{0, 0, 0}, {0, 0, 0}, {1, 0, 0x1p-20}, {1, 0, 0x1p-20}},
       {{3, 3, 3}, {3, 3, 3}, {1, 3, 3 + 0x1p-20}, {1, 3, 3 + 0x1p-20}}, no_contact()),
  };
}
// clang-format on

}  // namespace exactccd::testing
