// Shared helpers of the property tests: the sample queries, seeded random query generators,
// and an independent contact test at a rational time built on CGAL's exact kernel.
#pragma once

#include <gmpxx.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/gmpxx.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "exact/arithmetic/rational.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"
#include "result_text.hpp"
#include "test_scale.hpp"

namespace exactccd::test {

// ---------------------------------------------------------------------------------------------
// Sample queries

struct SampleQuery {
  std::string file;
  std::size_t line = 0;  // 1-based line of the query's first row
  RationalQuery query;
  bool truth = false;
  std::string where() const { return file + ":" + std::to_string(line); }
};

/// Every query of every file under EXACTCCD_SAMPLE_QUERIES (read once per program).
inline const std::vector<SampleQuery>& sample_queries() {
  static const std::vector<SampleQuery> all = [] {
    std::vector<SampleQuery> out;
    for (const std::string& path : find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
      const auto type = query_type_from_path(path);
      if (!type) throw std::runtime_error(path + ": neither vertex-face nor edge-edge");
      for (const QueryRecord& r : read_query_file(path, *type).queries)
        out.push_back({path, r.first_line, r.query, r.truth});
    }
    return out;
  }();
  return all;
}

/// Every subset_stride()-th sample query (all of them at EXACTCCD_TEST_SCALE >= 1), for the
/// loops whose per-query work is heavy.
inline const std::vector<SampleQuery>& scaled_sample_queries() {
  static const std::vector<SampleQuery> some = [] {
    std::vector<SampleQuery> out;
    const std::vector<SampleQuery>& all = sample_queries();
    for (std::size_t i = 0; i < all.size(); i += subset_stride()) out.push_back(all[i]);
    return out;
  }();
  return some;
}

// ---------------------------------------------------------------------------------------------
// Seeds

/// EXACTCCD_TEST_SEED when set, else a fixed default; printed so that a failure can be replayed.
inline std::uint64_t test_seed(const char* what) {
  std::uint64_t seed = 20240617;
  if (const char* env = std::getenv("EXACTCCD_TEST_SEED")) seed = std::strtoull(env, nullptr, 0);
  std::cout << "[ seed     ] " << what << ": EXACTCCD_TEST_SEED=" << seed << "\n";
  return seed;
}

// ---------------------------------------------------------------------------------------------
// Rational helpers

inline mpq_class pow2(int e) {
  mpq_class r(1);
  if (e >= 0) mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(e));
  else mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(-e));
  return r;
}

/// x(t) = (1 - t) x0 + t x1, exactly.
inline RationalPoint position_at(const RationalQuery& q, int vertex, const mpq_class& t) {
  const RationalPoint& a = q.points[vertex];
  const RationalPoint& b = q.points[vertex + 4];
  const mpq_class s = 1 - t;
  return {mpq_class(s * a.x + t * b.x), mpq_class(s * a.y + t * b.y),
          mpq_class(s * a.z + t * b.z)};
}

inline bool all_coordinates_are_doubles(const RationalQuery& q) {
  double d;
  for (const auto& p : q.points)
    if (!exact::to_double_exactly(p.x, &d) || !exact::to_double_exactly(p.y, &d) ||
        !exact::to_double_exactly(p.z, &d))
      return false;
  return true;
}

inline Eigen::Vector3d to_vector(const RationalPoint& p) {
  double x = 0, y = 0, z = 0;
  if (!exact::to_double_exactly(p.x, &x) || !exact::to_double_exactly(p.y, &y) ||
      !exact::to_double_exactly(p.z, &z))
    throw std::logic_error("coordinate is not exactly a double");
  return {x, y, z};
}

/// The double API on a query whose coordinates are all exactly doubles.
inline CcdResult double_api_ccd(const RationalQuery& q, const CcdOptions& options = {}) {
  std::array<Eigen::Vector3d, 8> v;
  for (int i = 0; i < 8; ++i) v[i] = to_vector(q.points[i]);
  if (q.type == QueryType::vertex_face)
    return vertex_face_ccd(VertexFaceQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]},
                           options);
  return edge_edge_ccd(EdgeEdgeQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, options);
}

/// The same verdict and TOI enclosure, bit for bit (the stage may differ).
inline bool same_answer(const CcdResult& a, const CcdResult& b) {
  return a.collides == b.collides && a.toi_lo == b.toi_lo && a.toi_hi == b.toi_hi;
}

inline std::string describe(const RationalQuery& q) {
  std::string s = q.type == QueryType::vertex_face ? "vertex-face" : "edge-edge";
  for (const auto& p : q.points)
    s += "\n  " + p.x.get_str() + ", " + p.y.get_str() + ", " + p.z.get_str();
  return s;
}

// ---------------------------------------------------------------------------------------------
// Independent contact test at a rational time (CGAL, exact rational kernel)
//
// Positions at time t are exact rationals; CGAL's predicates on them are exact. CGAL's
// Triangle_3 and Segment_3 predicates want non-degenerate objects, so a collinear triangle is
// tested as the union of its three edges and a zero-length segment as a point.

using CgalKernel = CGAL::Simple_cartesian<mpq_class>;
using CgalPoint = CgalKernel::Point_3;
using CgalSegment = CgalKernel::Segment_3;
using CgalTriangle = CgalKernel::Triangle_3;

inline CgalPoint cgal_point(const RationalPoint& p) { return CgalPoint(p.x, p.y, p.z); }

/// The closed segment [a, b] (a == b allowed) contains p.
inline bool cgal_point_on_segment(const CgalPoint& p, const CgalPoint& a, const CgalPoint& b) {
  if (a == b) return p == a;
  return CGAL::do_intersect(p, CgalSegment(a, b));
}

/// The closed segments [a0, a1] and [b0, b1] (either may have zero length) meet.
inline bool cgal_segments_meet(const CgalPoint& a0, const CgalPoint& a1, const CgalPoint& b0,
                               const CgalPoint& b1) {
  if (a0 == a1) return cgal_point_on_segment(a0, b0, b1);
  if (b0 == b1) return cgal_point_on_segment(b0, a0, a1);
  return CGAL::do_intersect(CgalSegment(a0, a1), CgalSegment(b0, b1));
}

/// The closed triangle (a, b, c) (possibly a segment or a point) contains p.
inline bool cgal_point_in_triangle(const CgalPoint& p, const CgalPoint& a, const CgalPoint& b,
                                   const CgalPoint& c) {
  const CgalTriangle tri(a, b, c);
  if (!tri.is_degenerate()) return CGAL::do_intersect(p, tri);
  return cgal_point_on_segment(p, a, b) || cgal_point_on_segment(p, b, c) ||
         cgal_point_on_segment(p, c, a);
}

/// The query's primitives share a point at the rational time t.
inline bool cgal_contact_at(const RationalQuery& q, const mpq_class& t) {
  std::array<CgalPoint, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = cgal_point(position_at(q, i, t));
  if (q.type == QueryType::vertex_face) return cgal_point_in_triangle(x[0], x[1], x[2], x[3]);
  return cgal_segments_meet(x[0], x[1], x[2], x[3]);
}

/// The squared Euclidean distance between the query's closed primitives at the rational time t
/// (degenerate primitives as the point sets they are: a collinear triangle as its edges, a
/// zero-length segment as its point).
inline mpq_class cgal_squared_distance_at(const RationalQuery& q, const mpq_class& t) {
  std::array<CgalPoint, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = cgal_point(position_at(q, i, t));
  const auto point_segment = [](const CgalPoint& p, const CgalPoint& a, const CgalPoint& b) {
    return a == b ? CGAL::squared_distance(p, a) : CGAL::squared_distance(p, CgalSegment(a, b));
  };
  if (q.type == QueryType::vertex_face) {
    if (!CGAL::collinear(x[1], x[2], x[3]))
      return CGAL::squared_distance(x[0], CgalTriangle(x[1], x[2], x[3]));
    return std::min({point_segment(x[0], x[1], x[2]), point_segment(x[0], x[2], x[3]),
                     point_segment(x[0], x[3], x[1])});
  }
  if (x[0] == x[1]) return point_segment(x[0], x[2], x[3]);
  if (x[2] == x[3]) return point_segment(x[2], x[0], x[1]);
  return CGAL::squared_distance(CgalSegment(x[0], x[1]), CgalSegment(x[2], x[3]));
}

/// Sign of the coplanarity determinant of the query's four points at time t (CGAL orientation
/// of (a, b, c, p) for vertex-face, (a0, a1, b0, b1) for edge-edge).
inline int cgal_coplanarity_sign_at(const RationalQuery& q, const mpq_class& t) {
  std::array<CgalPoint, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = cgal_point(position_at(q, i, t));
  if (q.type == QueryType::vertex_face)
    return static_cast<int>(CGAL::orientation(x[1], x[2], x[3], x[0]));
  return static_cast<int>(CGAL::orientation(x[0], x[1], x[2], x[3]));
}

/// The coplanarity determinant, a polynomial of degree <= 3 in t, vanishes identically: it
/// vanishes at four distinct times.
inline bool cgal_coplanar_throughout(const RationalQuery& q) {
  for (const mpq_class& t : {mpq_class(0), mpq_class(1, 3), mpq_class(2, 3), mpq_class(1)})
    if (cgal_coplanarity_sign_at(q, t) != 0) return false;
  return true;
}

/// The coplanarity determinant at time t, computed here from exact positions:
/// det[b - a, c - a, p - a] (vertex-face) or det[a1 - a0, b0 - a0, b1 - a0] (edge-edge).
inline mpq_class coplanarity_determinant_at(const RationalQuery& q, const mpq_class& t) {
  std::array<RationalPoint, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = position_at(q, i, t);
  const bool vf = q.type == QueryType::vertex_face;
  const RationalPoint& o = x[vf ? 1 : 0];
  const RationalPoint& u = x[vf ? 2 : 1];
  const RationalPoint& v = x[vf ? 3 : 2];
  const RationalPoint& w = x[vf ? 0 : 3];
  const mpq_class ux = u.x - o.x, uy = u.y - o.y, uz = u.z - o.z;
  const mpq_class vx = v.x - o.x, vy = v.y - o.y, vz = v.z - o.z;
  const mpq_class wx = w.x - o.x, wy = w.y - o.y, wz = w.z - o.z;
  return mpq_class(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx));
}

/// The coplanarity determinant as a polynomial c[0] + c[1] t + c[2] t^2 + c[3] t^3: it has
/// degree <= 3, so Newton's forward differences at t = 0, 1, 2, 3 give it exactly.
inline std::array<mpq_class, 4> coplanarity_polynomial(const RationalQuery& q) {
  std::array<mpq_class, 4> v;
  for (int i = 0; i < 4; ++i) v[i] = coplanarity_determinant_at(q, i);
  const mpq_class d1 = v[1] - v[0];
  const mpq_class d2 = v[2] - 2 * v[1] + v[0];
  const mpq_class d3 = v[3] - 3 * v[2] + 3 * v[1] - v[0];
  // v0 + d1 t + d2 t (t - 1)/2 + d3 t (t - 1)(t - 2)/6, expanded.
  return {v[0], mpq_class(d1 - d2 / 2 + d3 / 3), mpq_class(d2 / 2 - d3 / 2), mpq_class(d3 / 6)};
}

/// A rational square root of q >= 0, if q is the square of a rational.
inline bool rational_sqrt(const mpq_class& q, mpq_class* root) {
  if (sgn(q) < 0) return false;
  const mpz_class& n = q.get_num();
  const mpz_class& d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return false;
  *root = mpq_class(mpz_class(sqrt(n)), mpz_class(sqrt(d)));
  return true;
}

/// The multiple roots of the cubic c (not identically zero) strictly inside (lo, hi). A multiple
/// root r is a root of c' as well; c' has degree <= 2, and r is rational (a root of gcd(c, c'),
/// of degree 1 for a cubic), so it is among the rational roots of c' found by the quadratic
/// formula.
inline std::vector<mpq_class> multiple_roots_in(const std::array<mpq_class, 4>& c,
                                                const mpq_class& lo, const mpq_class& hi) {
  const mpq_class d0 = c[1], d1 = 2 * c[2], d2 = 3 * c[3];  // c'
  std::vector<mpq_class> candidates;
  if (sgn(d2) != 0) {
    mpq_class s;
    if (rational_sqrt(d1 * d1 - 4 * d2 * d0, &s)) {
      candidates.push_back((-d1 - s) / (2 * d2));
      candidates.push_back((-d1 + s) / (2 * d2));
    }
  } else if (sgn(d1) != 0) {
    candidates.push_back(-d0 / d1);
  }
  std::vector<mpq_class> out;
  for (const mpq_class& r : candidates) {
    const mpq_class value = c[0] + r * (c[1] + r * (c[2] + r * c[3]));
    if (sgn(value) == 0 && lo < r && r < hi) out.push_back(r);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Random queries

/// Seeded random queries. The coordinates of uniform, tiny-grid and degenerate queries are
/// k / 2^bits with |k| <= 2^bits: exact doubles with few mantissa bits, so that sums of a few,
/// power-of-two scalings and mirrors stay exact doubles. Colliding queries may have one vertex
/// with non-dyadic coordinates at t1 (for the rational API).
class QueryGenerator {
 public:
  explicit QueryGenerator(std::uint64_t seed) : rng_(seed) {}

  int uniform_int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  /// k / 2^bits, k uniform in [-2^bits, 2^bits].
  mpq_class coordinate(int bits) {
    const long m = 1L << bits;
    mpq_class r(std::uniform_int_distribution<long>(-m, m)(rng_), m);
    r.canonicalize();
    return r;
  }

  RationalPoint point(int bits) { return {coordinate(bits), coordinate(bits), coordinate(bits)}; }

  /// All eight points uniform, `bits` bits of resolution in [-1, 1].
  RationalQuery uniform(QueryType type, int bits) {
    RationalQuery q;
    q.type = type;
    for (auto& p : q.points) p = point(bits);
    return q;
  }

  /// A query on a tiny grid (coordinates in {-2..2}/2): coplanar, collinear, coincident and
  /// touching configurations, contact at t = 0 or t = 1, are frequent.
  RationalQuery tiny_grid(QueryType type) { return uniform(type, 1); }

  /// A query with a degeneracy planted on purpose (kind chosen at random).
  RationalQuery degenerate(QueryType type) {
    const bool vf = type == QueryType::vertex_face;
    RationalQuery q = uniform(type, uniform_int(1, 4));
    auto& v = q.points;
    const auto same_at_both_times = [&v](int i, int j) {
      v[i] = v[j];
      v[i + 4] = v[j + 4];
    };
    switch (uniform_int(0, 7)) {
      case 0:  // everything in the plane z = 0 throughout (coplanar motion)
        for (auto& p : v) p.z = 0;
        break;
      case 1:  // everything on the x-axis throughout (collinear motion)
        for (auto& p : v) p.y = p.z = 0;
        break;
      case 2:  // contact at t = 0: the first point sits on a vertex of the other primitive
        v[0] = v[vf ? uniform_int(1, 3) : uniform_int(2, 3)];
        break;
      case 3:  // contact at t = 1
        v[4] = v[vf ? uniform_int(5, 7) : uniform_int(6, 7)];
        break;
      case 4:  // a shared vertex at both times (vertex-face: p = b; edge-edge: ea0 = eb0)
        same_at_both_times(0, 2);
        break;
      case 5:  // vertex-face: the triangle is a segment (a = b); edge-edge: ea0 = ea1
        if (vf) same_at_both_times(1, 2);
        else same_at_both_times(0, 1);
        break;
      case 6:  // vertex-face: the triangle is a point; edge-edge: both edges of zero length
        if (vf) {
          same_at_both_times(2, 1);
          same_at_both_times(3, 1);
        } else {
          same_at_both_times(1, 0);
          same_at_both_times(3, 2);
        }
        break;
      default:  // the four points coplanar at t = 0 only
        for (int i = 0; i < 4; ++i) v[i].z = 0;
        break;
    }
    return q;
  }

  /// A query that certainly has contact at the dyadic time tc in (0, 1] (returned): the
  /// primitives are built to meet at tc at a point of given barycentric coordinates.
  RationalQuery colliding(QueryType type, mpq_class* tc) {
    const int bits = uniform_int(2, 10);
    RationalQuery q = uniform(type, bits);
    *tc = mpq_class(uniform_int(1, 16), 16);
    tc->canonicalize();
    // Dyadic weights (w0 + w1 = 1 for a segment, w0 + w1 + w2 = 1 for a triangle).
    const int n = uniform_int(0, 8);
    const mpq_class w0(n, 8);
    if (type == QueryType::vertex_face) {
      const int m = uniform_int(0, 8 - n);
      const mpq_class w1(m, 8), w2 = 1 - w0 - w1;
      const RationalPoint a = position_at(q, 1, *tc), b = position_at(q, 2, *tc),
                          c = position_at(q, 3, *tc);
      const RationalPoint x{w0 * a.x + w1 * b.x + w2 * c.x, w0 * a.y + w1 * b.y + w2 * c.y,
                            w0 * a.z + w1 * b.z + w2 * c.z};
      steer(&q, 0, x, *tc);
    } else {
      const mpq_class w1 = 1 - w0;
      const RationalPoint b0 = position_at(q, 2, *tc), b1 = position_at(q, 3, *tc);
      const RationalPoint x{w0 * b0.x + w1 * b1.x, w0 * b0.y + w1 * b1.y, w0 * b0.z + w1 * b1.z};
      // ea0 at tc is x - s (ea1(tc) - x) for some s >= 0, so x lies on [ea0(tc), ea1(tc)].
      const RationalPoint a1 = position_at(q, 1, *tc);
      const mpq_class s(uniform_int(0, 4), 2);
      steer(&q, 0, {x.x - s * (a1.x - x.x), x.y - s * (a1.y - x.y), x.z - s * (a1.z - x.z)},
            *tc);
    }
    return q;
  }

 private:
  /// Changes vertex i's position at t1 so that it is at x at time tc.
  static void steer(RationalQuery* q, int i, const RationalPoint& x, const mpq_class& tc) {
    RationalPoint& p0 = q->points[i];
    RationalPoint& p1 = q->points[i + 4];
    const mpq_class s = 1 - tc;
    p1 = {(x.x - s * p0.x) / tc, (x.y - s * p0.y) / tc, (x.z - s * p0.z) / tc};
  }

  std::mt19937_64 rng_;
};

}  // namespace exactccd::test
