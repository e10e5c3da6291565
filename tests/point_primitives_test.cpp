// Point-edge and point-point CCD (pipeline/point_ccd.cpp), thin reductions to edge_edge_ccd with
// zero-length segments: the same results as the explicit reduction in every mode, and, as
// independent checks, the same verdict and tightest TOI as a different reduction on the rational
// exact path (a degenerate triangle), as the closed form of point-point contact (per-axis linear
// equations solved in exact rationals), and as hand-made cases with known answers.
// PROOF: proofs/api_reductions.md#point-primitives
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"
#include "test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string describe(const CcdResult& r) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "collides %d [%a, %a] by %s", r.collides ? 1 : 0, r.toi_lo,
                r.toi_hi, to_string(r.decided_by));
  return buffer;
}

std::string describe(const Vector3d& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%a, %a, %a)", v.x(), v.y(), v.z());
  return buffer;
}

std::string describe(const PointEdgeQuery& q) {
  return "\n p " + describe(q.p_t0) + " -> " + describe(q.p_t1) + "\n e0 " + describe(q.e0_t0) +
         " -> " + describe(q.e0_t1) + "\n e1 " + describe(q.e1_t0) + " -> " + describe(q.e1_t1);
}

std::string describe(const PointPointQuery& q) {
  return "\n p " + describe(q.p_t0) + " -> " + describe(q.p_t1) + "\n q " + describe(q.q_t0) +
         " -> " + describe(q.q_t1);
}

Vector3d z0(const Vector2d& v) { return {v.x(), v.y(), 0.0}; }

PointEdgeQuery embedded(const PointEdgeQuery2d& q) {
  return {z0(q.p_t0), z0(q.e0_t0), z0(q.e1_t0), z0(q.p_t1), z0(q.e0_t1), z0(q.e1_t1)};
}

/// Identical results, bit for bit (the stage too: the same query takes the same path).
bool same(const CcdResult& a, const CcdResult& b) {
  return a.collides == b.collides && std::signbit(a.toi_lo) == std::signbit(b.toi_lo) &&
         a.toi_lo == b.toi_lo && a.toi_hi == b.toi_hi && a.decided_by == b.decided_by;
}

/// The options the reductions are compared under: every mode, a shorter interval, a coarse TOI.
std::vector<CcdOptions> option_grid() {
  std::vector<CcdOptions> all;
  for (const Mode mode : {Mode::filtered, Mode::exact, Mode::float_only})
    for (const double t_max : {1.0, 0.5})
      for (const double width : {0.0, 0x1p-10}) {
        CcdOptions o;
        o.mode = mode;
        o.t_max = t_max;
        o.toi_width = width;
        all.push_back(o);
      }
  return all;
}

// ---- Independent references --------------------------------------------------------------------

RationalPoint rational(const Vector3d& v) {
  return {mpq_class(v.x()), mpq_class(v.y()), mpq_class(v.z())};
}

/// The second reduction: p against the degenerate triangle (e0, e1, e1), whose closed hull is the
/// segment [e0, e1], on the rational exact path (another predicate: point in triangle).
CcdResult as_degenerate_triangle(const PointEdgeQuery& q, const CcdOptions& options) {
  RationalQuery r;
  r.type = QueryType::vertex_face;
  r.points = {rational(q.p_t0), rational(q.e0_t0), rational(q.e1_t0), rational(q.e1_t0),
              rational(q.p_t1), rational(q.e0_t1), rational(q.e1_t1), rational(q.e1_t1)};
  return exact_ccd(r, options);
}

/// Point-point contact in closed form: p(t) = q(t) iff each axis' difference
/// d(t) = (1 - t) d0 + t d1 vanishes; per axis that is every t (d0 = d1 = 0), no t (d0 = d1 != 0)
/// or the single time d0 / (d0 - d1). The first contact time in [0, t_max], or nullopt.
std::optional<mpq_class> point_point_first_contact(const PointPointQuery& q, double t_max) {
  std::optional<mpq_class> only;  // the one admissible time, once an axis pins it
  for (int k = 0; k < 3; ++k) {
    const mpq_class d0 = mpq_class(q.p_t0[k]) - mpq_class(q.q_t0[k]);
    const mpq_class d1 = mpq_class(q.p_t1[k]) - mpq_class(q.q_t1[k]);
    if (d0 == d1) {
      if (d0 != 0) return std::nullopt;  // a constant non-zero gap
      continue;                          // equal on this axis throughout
    }
    const mpq_class t = d0 / (d0 - d1);
    if (only && *only != t) return std::nullopt;
    only = t;
  }
  const mpq_class t = only.value_or(mpq_class(0));  // equal throughout: contact from t = 0
  if (t < 0 || t > mpq_class(t_max)) return std::nullopt;
  return t;
}

/// Failure text unless [r.toi_lo, r.toi_hi] is the tightest pair of doubles around t: [t, t]
/// when t is a double, else consecutive doubles strictly around it.
std::string tightest_pair_failure(const CcdResult& r, const mpq_class& t) {
  if (!r.collides) return "no contact reported; expected t* = " + t.get_str();
  if (!(std::isfinite(r.toi_lo) && std::isfinite(r.toi_hi))) return "non-finite TOI";
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  const bool exact_double = mpq_class(t.get_d()) == t;
  const bool ok = exact_double ? (lo == t && hi == t)
                               : (lo < t && t < hi && std::nextafter(r.toi_lo, kInf) == r.toi_hi);
  return ok ? std::string() : "not the tightest pair around t* = " + t.get_str();
}

/// Failure text unless r encloses t with a width of at most `width` (or is the tightest pair).
std::string enclosure_failure(const CcdResult& r, const mpq_class& t, double width) {
  if (tightest_pair_failure(r, t).empty()) return {};
  if (!r.collides || !(std::isfinite(r.toi_lo) && std::isfinite(r.toi_hi)))
    return "no finite enclosure";
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  if (!(lo <= t && t <= hi)) return "enclosure misses t* = " + t.get_str();
  if (hi - lo > mpq_class(width)) return "enclosure wider than toi_width";
  return {};
}

// ---- Random and degenerate queries -------------------------------------------------------------

class PointQueries {
 public:
  explicit PointQueries(std::uint64_t seed) : rng_(seed) {}

  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  /// k / 2^bits, k uniform in [-2^bits, 2^bits]: a coarse dyadic grid, so that contacts,
  /// touching, collinear and coincident configurations are frequent.
  double grid(int bits) {
    const long m = 1L << bits;
    return std::ldexp(static_cast<double>(std::uniform_int_distribution<long>(-m, m)(rng_)),
                      -bits);
  }
  Vector3d grid_point(int bits) { return {grid(bits), grid(bits), grid(bits)}; }
  Vector3d wide_point() {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    return {u(rng_), u(rng_), u(rng_)};
  }

  /// A point on the segment [a, b] at parameter k/4 (exact for grid points of few bits).
  Vector3d on_segment(const Vector3d& a, const Vector3d& b) {
    const double s = 0.25 * pick(5);
    return a + s * (b - a);
  }

  PointEdgeQuery point_edge() {
    const int bits = 1 + pick(3);
    PointEdgeQuery q{grid_point(bits), grid_point(bits), grid_point(bits),
                     grid_point(bits), grid_point(bits), grid_point(bits)};
    switch (pick(9)) {
      case 0: break;  // a coarse grid
      case 1:         // full-precision doubles: contact is rare, near misses common
        q = {wide_point(), wide_point(), wide_point(), wide_point(), wide_point(), wide_point()};
        break;
      case 2:  // a zero-length edge
        q.e1_t0 = q.e0_t0;
        q.e1_t1 = q.e0_t1;
        break;
      case 3:  // on the segment at t = 0
        q.p_t0 = on_segment(q.e0_t0, q.e1_t0);
        break;
      case 4:  // on the segment at t = 1
        q.p_t1 = on_segment(q.e0_t1, q.e1_t1);
        break;
      case 5:  // collinear throughout: everything on the x axis
        for (Vector3d* v : {&q.p_t0, &q.e0_t0, &q.e1_t0, &q.p_t1, &q.e0_t1, &q.e1_t1})
          v->tail<2>().setZero();
        break;
      case 6:  // coplanar throughout (z = 0)
        for (Vector3d* v : {&q.p_t0, &q.e0_t0, &q.e1_t0, &q.p_t1, &q.e0_t1, &q.e1_t1})
          v->z() = 0.0;
        break;
      case 7:  // the point rides on the edge's endpoint
        q.p_t0 = q.e0_t0;
        q.p_t1 = q.e0_t1;
        break;
      default:  // nothing moves
        q.p_t1 = q.p_t0;
        q.e0_t1 = q.e0_t0;
        q.e1_t1 = q.e1_t0;
        break;
    }
    return q;
  }

  PointPointQuery point_point() {
    const int bits = 1 + pick(3);
    PointPointQuery q{grid_point(bits), grid_point(bits), grid_point(bits), grid_point(bits)};
    switch (pick(8)) {
      case 0: break;  // a coarse grid: equal coordinates on some axes are common
      case 1:
        q = {wide_point(), wide_point(), wide_point(), wide_point()};
        break;
      case 2: {  // meet at t = 1/4, 1/2 or 1: q_t1 = (p(t) - (1 - t) q_t0) / t, exact here
        const double t = std::ldexp(1.0, -pick(3));
        const Vector3d meet = (1 - t) * q.p_t0 + t * q.p_t1;
        q.q_t1 = (meet - (1 - t) * q.q_t0) / t;
        break;
      }
      case 3:  // equal at t = 0
        q.q_t0 = q.p_t0;
        break;
      case 4:  // equal at t = 1
        q.q_t1 = q.p_t1;
        break;
      case 5:  // the same motion, shifted on one axis: never
        q.q_t0 = q.p_t0;
        q.q_t1 = q.p_t1;
        q.q_t0[pick(3)] += 0.5;
        q.q_t1 = q.p_t1 + (q.q_t0 - q.p_t0);
        break;
      case 6: {  // meet at t = 1/3, no double: q - p = k (1 - 3t) with a grid vector k != 0
        Vector3d k = grid_point(bits);
        if (k.isZero()) k.x() = 1.0;
        q.q_t0 = q.p_t0 + k;
        q.q_t1 = q.p_t1 - 2.0 * k;
        break;
      }
      default:  // identical throughout
        q.q_t0 = q.p_t0;
        q.q_t1 = q.p_t1;
        break;
    }
    return q;
  }

  PointEdgeQuery2d point_edge_2d() {
    const PointEdgeQuery q = point_edge();
    const auto xy = [](const Vector3d& v) { return Vector2d(v.x(), v.y()); };
    return {xy(q.p_t0), xy(q.e0_t0), xy(q.e1_t0), xy(q.p_t1), xy(q.e0_t1), xy(q.e1_t1)};
  }

 private:
  std::mt19937_64 rng_;
};

std::size_t query_count() { return scaled_count(1500); }

// ---- The reductions, as stated -----------------------------------------------------------------

TEST(PointPrimitives, PointEdgeIsTheExplicitReduction) {
  PointQueries gen(test_seed("point-edge reduction"));
  const std::vector<CcdOptions> grid = option_grid();
  std::size_t contacts = 0, free = 0;
  for (std::size_t i = 0; i < query_count(); ++i) {
    const PointEdgeQuery q = gen.point_edge();
    const EdgeEdgeQuery ee{q.p_t0, q.p_t0, q.e0_t0, q.e1_t0, q.p_t1, q.p_t1, q.e0_t1, q.e1_t1};
    for (const CcdOptions& o : grid) {
      const CcdResult got = point_edge_ccd(q, o), want = edge_edge_ccd(ee, o);
      ASSERT_TRUE(same(got, want)) << "point_edge_ccd " << describe(got) << " != edge_edge_ccd "
                                   << describe(want) << " (" << to_string(o.mode) << ", t_max "
                                   << o.t_max << ")" << describe(q);
      if (o.mode == Mode::filtered && o.t_max == 1.0 && o.toi_width == 0.0)
        (got.collides ? contacts : free) += 1;
    }
  }
  EXPECT_GT(contacts, query_count() / 4);  // both outcomes are well represented
  EXPECT_GT(free, query_count() / 4);
}

TEST(PointPrimitives, PointPointIsTheExplicitReduction) {
  PointQueries gen(test_seed("point-point reduction"));
  const std::vector<CcdOptions> grid = option_grid();
  std::size_t contacts = 0, free = 0;
  for (std::size_t i = 0; i < query_count(); ++i) {
    const PointPointQuery q = gen.point_point();
    const EdgeEdgeQuery ee{q.p_t0, q.p_t0, q.q_t0, q.q_t0, q.p_t1, q.p_t1, q.q_t1, q.q_t1};
    for (const CcdOptions& o : grid) {
      const CcdResult got = point_point_ccd(q, o), want = edge_edge_ccd(ee, o);
      ASSERT_TRUE(same(got, want)) << "point_point_ccd " << describe(got) << " != edge_edge_ccd "
                                   << describe(want) << " (" << to_string(o.mode) << ")"
                                   << describe(q);
      if (o.mode == Mode::filtered && o.t_max == 1.0 && o.toi_width == 0.0)
        (got.collides ? contacts : free) += 1;
    }
  }
  EXPECT_GT(contacts, query_count() / 4);
  EXPECT_GT(free, query_count() / 4);
}

TEST(PointPrimitives, PointEdge2dIsTheEmbeddedQuery) {
  PointQueries gen(test_seed("2d point-edge embedding"));
  const std::vector<CcdOptions> grid = option_grid();
  for (std::size_t i = 0; i < query_count(); ++i) {
    const PointEdgeQuery2d q = gen.point_edge_2d();
    for (const CcdOptions& o : grid) {
      const CcdResult got = point_edge_ccd_2d(q, o), want = point_edge_ccd(embedded(q), o);
      ASSERT_TRUE(same(got, want)) << "point_edge_ccd_2d " << describe(got)
                                   << " != point_edge_ccd in z = 0 " << describe(want)
                                   << describe(embedded(q));
    }
  }
}

TEST(PointPrimitives, PointPoint2dIsTheEmbeddedQuery) {
  PointQueries gen(test_seed("2d point-point embedding"));
  const std::vector<CcdOptions> grid = option_grid();
  const auto xy = [](const Vector3d& v) { return Vector2d(v.x(), v.y()); };
  std::size_t contacts = 0;
  for (std::size_t i = 0; i < query_count(); ++i) {
    const PointPointQuery q3 = gen.point_point();
    const PointPointQuery2d q{xy(q3.p_t0), xy(q3.q_t0), xy(q3.p_t1), xy(q3.q_t1)};
    const PointPointQuery in_z0{z0(q.p_t0), z0(q.q_t0), z0(q.p_t1), z0(q.q_t1)};
    for (const CcdOptions& o : grid) {
      const CcdResult got = point_point_ccd_2d(q, o), want = point_point_ccd(in_z0, o);
      ASSERT_TRUE(same(got, want)) << "point_point_ccd_2d " << describe(got)
                                   << " != point_point_ccd in z = 0 " << describe(want)
                                   << describe(in_z0);
      if (o.mode == Mode::filtered && got.collides) ++contacts;
    }
    // The per-axis closed form, independently of the library.
    const std::optional<mpq_class> t = point_point_first_contact(in_z0, 1.0);
    const CcdResult r = point_point_ccd_2d(q);
    ASSERT_EQ(r.collides, t.has_value()) << describe(in_z0);
    if (t) ASSERT_TRUE(tightest_pair_failure(r, *t).empty()) << describe(in_z0);
  }
  EXPECT_GT(contacts, query_count() / 8);
}

// ---- Independent checks ------------------------------------------------------------------------

TEST(PointPrimitives, PointEdgeAgreesWithDegenerateTriangle) {
  PointQueries gen(test_seed("point-edge vs degenerate triangle"));
  std::size_t contacts = 0, free = 0;
  for (std::size_t i = 0; i < query_count(); ++i) {
    const PointEdgeQuery q = gen.point_edge();
    for (const double t_max : {1.0, 0.5}) {
      CcdOptions o;
      o.t_max = t_max;
      const CcdResult want = as_degenerate_triangle(q, o);  // tightest pair: unique
      for (const Mode mode : {Mode::filtered, Mode::exact}) {
        o.mode = mode;
        const CcdResult got = point_edge_ccd(q, o);
        ASSERT_EQ(got.collides, want.collides)
            << to_string(mode) << ": " << describe(got) << " vs triangle (e0, e1, e1) "
            << describe(want) << describe(q);
        ASSERT_EQ(got.toi_lo, want.toi_lo) << to_string(mode) << describe(q);
        ASSERT_EQ(got.toi_hi, want.toi_hi) << to_string(mode) << describe(q);
      }
      (want.collides ? contacts : free) += 1;
    }
  }
  EXPECT_GT(contacts, query_count() / 4);
  EXPECT_GT(free, query_count() / 4);
}

TEST(PointPrimitives, PointEdge2dAgreesWithAnotherPlane) {
  // The plane x = 0 instead of z = 0, decided as a degenerate triangle: another embedding and
  // another predicate, the same contact set.
  PointQueries gen(test_seed("2d point-edge vs plane x = 0"));
  const auto yz = [](const Vector2d& v) { return Vector3d(0.0, v.x(), v.y()); };
  for (std::size_t i = 0; i < query_count(); ++i) {
    const PointEdgeQuery2d q = gen.point_edge_2d();
    const PointEdgeQuery other{yz(q.p_t0), yz(q.e0_t0), yz(q.e1_t0),
                               yz(q.p_t1), yz(q.e0_t1), yz(q.e1_t1)};
    const CcdResult got = point_edge_ccd_2d(q), want = as_degenerate_triangle(other, {});
    ASSERT_EQ(got.collides, want.collides) << describe(got) << " vs " << describe(want)
                                           << describe(other);
    ASSERT_EQ(got.toi_lo, want.toi_lo) << describe(other);
    ASSERT_EQ(got.toi_hi, want.toi_hi) << describe(other);
  }
}

TEST(PointPrimitives, PointPointAgreesWithPerAxisSolve) {
  PointQueries gen(test_seed("point-point vs per-axis solve"));
  std::size_t contacts = 0, free = 0, not_double = 0;
  // At least 300 queries: the counts below are shares, which a reduced scale must still see.
  const std::size_t count = at_least(query_count(), 300);
  for (std::size_t i = 0; i < count; ++i) {
    const PointPointQuery q = gen.point_point();
    for (const double t_max : {1.0, 0.5}) {
      const std::optional<mpq_class> t = point_point_first_contact(q, t_max);
      (t ? contacts : free) += 1;
      if (t && mpq_class(t->get_d()) != *t) ++not_double;
      for (const Mode mode : {Mode::filtered, Mode::exact})
        for (const double width : {0.0, 0x1p-10}) {
          CcdOptions o;
          o.t_max = t_max;
          o.mode = mode;
          o.toi_width = width;
          const CcdResult r = point_point_ccd(q, o);
          const std::string where = std::string(to_string(mode)) + ", t_max " +
                                    std::to_string(t_max) + ", width " + std::to_string(width) +
                                    ": " + describe(r) + describe(q);
          if (!t) {
            ASSERT_FALSE(r.collides) << where;
            ASSERT_EQ(r.toi_lo, kInf) << where;
            ASSERT_EQ(r.toi_hi, kInf) << where;
            continue;
          }
          const std::string failure =
              width == 0 ? tightest_pair_failure(r, *t) : enclosure_failure(r, *t, width);
          ASSERT_TRUE(failure.empty()) << failure << "; " << where;
        }
    }
  }
  EXPECT_GT(contacts, count / 4);
  EXPECT_GT(free, count / 4);
  EXPECT_GT(not_double, 0u);  // some contact times fall between doubles (a two-double pair)
}

// ---- Hand-made cases ---------------------------------------------------------------------------

struct HandMade {
  const char* name;
  double t_max;
  std::optional<mpq_class> t_star;  // nullopt: no contact in [0, t_max]
};

void expect_answer(const HandMade& c, const CcdResult& r) {
  SCOPED_TRACE(c.name);
  if (!c.t_star) {
    EXPECT_FALSE(r.collides) << describe(r);
    EXPECT_EQ(r.toi_lo, kInf);
    EXPECT_EQ(r.toi_hi, kInf);
    return;
  }
  const std::string failure = tightest_pair_failure(r, *c.t_star);
  EXPECT_TRUE(failure.empty()) << failure << ": " << describe(r);
}

CcdOptions up_to(double t_max, Mode mode) {
  CcdOptions o;
  o.t_max = t_max;
  o.mode = mode;
  return o;
}

TEST(PointPrimitives, HandMadeCases) {
  const Vector3d o(0, 0, 0), x(1, 0, 0);
  const mpq_class third(1, 3), half(1, 2), quarter(1, 4);
  struct PointEdgeCase {
    HandMade answer;
    PointEdgeQuery q;
  };
  const std::vector<PointEdgeCase> point_edge_cases = {
      // On the segment's interior at t = 0, then leaving upwards.
      {{"touching at t = 0", 1.0, mpq_class(0)},
       {Vector3d(0.5, 0, 0), o, x, Vector3d(0.5, 0, 1), o, x}},
      // On an endpoint at t = 0 only.
      {{"touching an endpoint at t = 0", 1.0, mpq_class(0)},
       {x, o, x, Vector3d(2, 0, 0), o, x}},
      // Falling onto the interior, arriving exactly at t = 1 = t_max.
      {{"arriving at t_max = 1", 1.0, mpq_class(1)},
       {Vector3d(0.5, 0, 1), o, x, Vector3d(0.5, 0, 0), o, x}},
      // Arriving at t = 1/2 = t_max (closed interval), and just after a shorter t_max.
      {{"arriving at t_max = 1/2", 0.5, half},
       {Vector3d(0.5, 0, 1), o, x, Vector3d(0.5, 0, -1), o, x}},
      {{"arriving just after t_max", std::nextafter(0.5, 0.0), std::nullopt},
       {Vector3d(0.5, 0, 1), o, x, Vector3d(0.5, 0, -1), o, x}},
      // Crossing the interior at t = 1/3, not a double: the two doubles around it.
      {{"crossing at t = 1/3", 1.0, third},
       {Vector3d(0.5, 1, 0), o, x, Vector3d(0.5, -2, 0), o, x}},
      // Passing the segment's line beyond its end: never.
      {{"passing beyond the end", 1.0, std::nullopt},
       {Vector3d(1.5, 1, 0), o, x, Vector3d(1.5, -1, 0), o, x}},
      // Passing one ulp beyond the endpoint x: never.
      {{"near miss beside the endpoint", 1.0, std::nullopt},
       {Vector3d(1 + 0x1p-52, 1, 0), o, x, Vector3d(1 + 0x1p-52, -1, 0), o, x}},
      // Passing one unit above the segment: never.
      {{"passing above", 1.0, std::nullopt},
       {Vector3d(-1, 0, 1), o, x, Vector3d(2, 0, 1), o, x}},
      // Collinear sliding: the point comes along the line from x = 3 to x = -1 and enters the
      // segment [0, 1] through its end x = 1 at t = 1/2.
      {{"collinear sliding in", 1.0, half},
       {Vector3d(3, 0, 0), o, x, Vector3d(-1, 0, 0), o, x}},
      // Collinear, moving away from the segment: never.
      {{"collinear sliding away", 1.0, std::nullopt},
       {Vector3d(2, 0, 0), o, x, Vector3d(3, 0, 0), o, x}},
      // Collinear, the segment slides along its line onto the resting point at t = 1/4.
      {{"segment sliding onto the point", 1.0, quarter},
       {Vector3d(-1, 0, 0), Vector3d(0, 0, 0), x, Vector3d(-1, 0, 0), Vector3d(-4, 0, 0),
        Vector3d(-3, 0, 0)}},
      // A zero-length edge at the origin; the point passes through it at t = 1/2, or beside it.
      {{"zero-length edge hit", 1.0, half},
       {Vector3d(-1, 0, 0), o, o, Vector3d(1, 0, 0), o, o}},
      {{"zero-length edge missed", 1.0, std::nullopt},
       {Vector3d(-1, 0x1p-1000, 0), o, o, Vector3d(1, 0x1p-1000, 0), o, o}},
      // A segment sweeping across a resting point at t = 1/4.
      {{"segment sweeping over the point", 1.0, quarter},
       {Vector3d(0.5, 0, 0), Vector3d(0, -1, 0), Vector3d(1, -1, 0), Vector3d(0.5, 0, 0),
        Vector3d(0, 3, 0), Vector3d(1, 3, 0)}},
  };
  for (const PointEdgeCase& c : point_edge_cases)
    for (const Mode mode : {Mode::filtered, Mode::exact}) {
      expect_answer(c.answer, point_edge_ccd(c.q, up_to(c.answer.t_max, mode)));
      // The 2D function on the same motion when it lies in z = 0.
      const auto flat = [](const Vector3d& v) { return v.z() == 0; };
      if (flat(c.q.p_t0) && flat(c.q.p_t1) && flat(c.q.e0_t0) && flat(c.q.e0_t1) &&
          flat(c.q.e1_t0) && flat(c.q.e1_t1)) {
        const auto xy = [](const Vector3d& v) { return Vector2d(v.x(), v.y()); };
        const PointEdgeQuery2d q2{xy(c.q.p_t0), xy(c.q.e0_t0), xy(c.q.e1_t0),
                                  xy(c.q.p_t1), xy(c.q.e0_t1), xy(c.q.e1_t1)};
        expect_answer(c.answer, point_edge_ccd_2d(q2, up_to(c.answer.t_max, mode)));
      }
    }

  struct PointPointCase {
    HandMade answer;
    PointPointQuery q;
  };
  const std::vector<PointPointCase> point_point_cases = {
      {{"identical throughout", 1.0, mpq_class(0)}, {x, x, x, x}},
      {{"equal at t = 0 only", 1.0, mpq_class(0)}, {x, x, o, Vector3d(2, 0, 0)}},
      {{"meeting at t = 1/3", 1.0, third}, {o, x, Vector3d(3, 0, 0), x}},
      {{"meeting at t_max = 1", 1.0, mpq_class(1)}, {o, x, x, x}},
      {{"meeting at t = 1 after t_max", 0.5, std::nullopt}, {o, x, x, x}},
      {{"parallel, one unit apart", 1.0, std::nullopt},
       {o, Vector3d(0, 1, 0), x, Vector3d(1, 1, 0)}},
      // x and y agree at t = 1/4, z at t = 1/8: never all three at once.
      {{"axes meeting at different times", 1.0, std::nullopt},
       {Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 4), Vector3d(-1, -1, -3)}},
  };
  for (const PointPointCase& c : point_point_cases)
    for (const Mode mode : {Mode::filtered, Mode::exact})
      expect_answer(c.answer, point_point_ccd(c.q, up_to(c.answer.t_max, mode)));
}

// ---- Conventions and errors --------------------------------------------------------------------

TEST(PointPrimitives, NoContactIsInfinity) {
  // +infinity in every mode, so that the earliest contact over many pairs is a plain minimum.
  const Vector3d o(0, 0, 0), x(1, 0, 0), up(0, 0, 1);
  const PointEdgeQuery miss{up, o, x, up + x, o, x};
  const PointEdgeQuery hit{Vector3d(0.5, 0, 1), o, x, Vector3d(0.5, 0, -1), o, x};  // t* = 1/2
  for (const Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
    CcdOptions options;
    options.mode = mode;
    const CcdResult none = point_edge_ccd(miss, options);
    EXPECT_FALSE(none.collides) << to_string(mode);
    EXPECT_EQ(none.toi_lo, kInf) << to_string(mode);
    EXPECT_EQ(none.toi_hi, kInf) << to_string(mode);
    const CcdResult pp = point_point_ccd({o, up, x, up}, options);  // parallel, never equal
    EXPECT_EQ(pp.toi_lo, kInf) << to_string(mode);
    EXPECT_EQ(pp.toi_hi, kInf) << to_string(mode);
    if (mode == Mode::float_only) continue;  // uncertified: it need not find the contact
    const double earliest = std::min({none.toi_lo, point_edge_ccd(hit, options).toi_lo,
                                      pp.toi_lo});
    EXPECT_EQ(earliest, 0.5) << to_string(mode);
  }
  EXPECT_EQ(CcdResult{}.toi_lo, kInf);  // the default-constructed result is "no contact"
  EXPECT_EQ(CcdResult{}.toi_hi, kInf);
}

TEST(PointPrimitives, BadInputThrows) {
  const Vector3d o(0, 0, 0), x(1, 0, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto message_of = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(nothing thrown)";
  };
  // Non-finite coordinates: the message names the point query's own field.
  EXPECT_NE(message_of([&] { point_edge_ccd({o, o, x, Vector3d(nan, 0, 0), o, x}); })
                .find("p_t1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { point_edge_ccd({o, o, Vector3d(0, kInf, 0), o, o, x}); })
                .find("e1_t0"),
            std::string::npos);
  EXPECT_NE(message_of([&] { point_point_ccd({o, o, x, Vector3d(0, 0, -kInf)}); }).find("q_t1"),
            std::string::npos);
  const Vector2d o2(0, 0), x2(1, 0);
  EXPECT_NE(message_of([&] { point_edge_ccd_2d({o2, Vector2d(nan, 0), x2, o2, o2, x2}); })
                .find("e0_t0"),
            std::string::npos);
  EXPECT_NE(message_of([&] { point_point_ccd_2d({o2, Vector2d(0, nan), o2, x2}); }).find("q_t0"),
            std::string::npos);
  // Options outside their domain (t_max = 0, the state at the start, is inside it).
  for (const double t_max : {-0x1p-1074, -1.0, 1.5, nan}) {
    CcdOptions bad;
    bad.t_max = t_max;
    EXPECT_THROW(point_edge_ccd({o, o, x, o, o, x}, bad), std::invalid_argument) << t_max;
    EXPECT_THROW(point_point_ccd({o, x, o, x}, bad), std::invalid_argument) << t_max;
    EXPECT_THROW(point_edge_ccd_2d({o2, o2, x2, o2, o2, x2}, bad), std::invalid_argument);
    EXPECT_THROW(point_point_ccd_2d({o2, x2, o2, x2}, bad), std::invalid_argument);
  }
  for (const double width : {-1.0, kInf, nan}) {
    CcdOptions bad;
    bad.toi_width = width;
    EXPECT_THROW(point_edge_ccd({o, o, x, o, o, x}, bad), std::invalid_argument) << width;
  }
}

}  // namespace
}  // namespace exactccd::test
