// Hand-made degenerate queries (tests/degenerate_cases.hpp) through the public API: the
// double entry points vertex_face_ccd / edge_edge_ccd (default pipeline and Mode::exact) and
// the rational entry point exact_ccd, with the tightest enclosure (toi_width = 0) and a coarse
// one (toi_width = 1e-3), plus the symmetric variants of each query (relabelled triangle
// vertices, swapped or reversed edges, permuted axes), which have the same exact answer.
//
// Expected answers come from the table's hand derivations only. The table itself is
// sanity-checked below with an independent exact contact test at rational times (a
// parametric line solve, not the library's orientation tests).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"
#include "tests/degenerate_cases.hpp"

namespace {

using exactccd::CcdOptions;
using exactccd::CcdResult;
using exactccd::Mode;
using exactccd::QueryType;
using exactccd::RationalPoint;
using exactccd::RationalQuery;
using exactccd::testing::DegenerateCase;
using exactccd::testing::ExpectedToi;

constexpr double kCoarseWidth = 1e-3;

// ------------------------------------------------------------------------- expected times

mpq_class parse(const char* s) {
  mpq_class q(s, 10);
  q.canonicalize();
  return q;
}

/// Value of the table's polynomial at the rational t.
mpq_class poly_at(const ExpectedToi& e, const mpq_class& t) {
  mpq_class r = 0;
  for (int i = 3; i >= 0; --i) {
    r *= t;
    if (e.poly[i] != nullptr) r += parse(e.poly[i]);
  }
  return r;
}

int sign(const mpq_class& q) { return sgn(q); }

bool is_double(const mpq_class& q) { return mpq_class(q.get_d()) == q; }

/// Checks lo <= t* <= hi for the exact t* of `e`; with width == 0 also that the pair is the
/// tightest (equal to t* when t* is a double, else consecutive doubles around it), with
/// width > 0 that hi - lo <= width.
void expect_enclosure(const DegenerateCase& c, const CcdResult& r, double width,
                      const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(r.collides);
  ASSERT_TRUE(std::isfinite(r.toi_lo) && std::isfinite(r.toi_hi));
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  EXPECT_LE(r.toi_lo, r.toi_hi);
  EXPECT_GE(r.toi_lo, 0.0);
  EXPECT_LE(r.toi_hi, c.t_max);
  const bool tight = width == 0;
  if (!tight) {
    EXPECT_LE(r.toi_hi - r.toi_lo, width);
  }
  const double next_after_lo = std::nextafter(r.toi_lo, std::numeric_limits<double>::infinity());

  if (c.toi.is_rational()) {
    const mpq_class t = parse(c.toi.rational);
    EXPECT_TRUE(lo <= t && t <= hi) << "t* = " << t << " not in [" << lo << ", " << hi << "]";
    if (tight) {
      if (is_double(t)) {
        EXPECT_EQ(lo, t) << "t* = " << t << " is a double";
        EXPECT_EQ(hi, t) << "t* = " << t << " is a double";
      } else {
        EXPECT_TRUE(lo < t && t < hi) << "t* = " << t;
        EXPECT_EQ(r.toi_hi, next_after_lo) << "not consecutive doubles";
      }
    }
    return;
  }
  // t* is the only root of the polynomial in (root_lo, root_hi), and it is irrational: the
  // enclosure lies inside that interval and the polynomial changes sign strictly across it.
  const mpq_class root_lo = parse(c.toi.root_lo), root_hi = parse(c.toi.root_hi);
  EXPECT_TRUE(root_lo <= lo && hi <= root_hi)
      << "[" << lo << ", " << hi << "] not inside (" << root_lo << ", " << root_hi << ")";
  EXPECT_LT(sign(poly_at(c.toi, lo)) * sign(poly_at(c.toi, hi)), 0)
      << "no sign change of the polynomial on [" << lo << ", " << hi << "]";
  if (tight) {
    EXPECT_EQ(r.toi_hi, next_after_lo) << "not consecutive doubles";
  }
}

void expect_answer(const DegenerateCase& c, const CcdResult& r, double width,
                   const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(r.collides, c.collides);
  if (c.collides) {
    expect_enclosure(c, r, width, what);
  } else {
    // Contract: both times are +infinity when there is no collision.
    EXPECT_EQ(r.toi_lo, std::numeric_limits<double>::infinity());
    EXPECT_EQ(r.toi_hi, std::numeric_limits<double>::infinity());
  }
}

// ------------------------------------------------------------------------- query builders

Eigen::Vector3d eigen(const RationalPoint& p) {
  // The table's coordinates and their permutations are doubles; check rather than assume.
  const Eigen::Vector3d v(p.x.get_d(), p.y.get_d(), p.z.get_d());
  EXPECT_TRUE(mpq_class(v.x()) == p.x && mpq_class(v.y()) == p.y && mpq_class(v.z()) == p.z);
  return v;
}

/// The query through vertex_face_ccd / edge_edge_ccd (Eigen doubles).
CcdResult run_double_api(const RationalQuery& rq, const CcdOptions& o) {
  const auto& v = rq.points;
  if (rq.type == QueryType::vertex_face) {
    const exactccd::VertexFaceQuery q{eigen(v[0]), eigen(v[1]), eigen(v[2]), eigen(v[3]),
                                      eigen(v[4]), eigen(v[5]), eigen(v[6]), eigen(v[7])};
    return exactccd::vertex_face_ccd(q, o);
  }
  const exactccd::EdgeEdgeQuery q{eigen(v[0]), eigen(v[1]), eigen(v[2]), eigen(v[3]),
                                  eigen(v[4]), eigen(v[5]), eigen(v[6]), eigen(v[7])};
  return exactccd::edge_edge_ccd(q, o);
}

CcdResult run_double_api(const DegenerateCase& c, const CcdOptions& o) {
  return run_double_api(exactccd::testing::to_rational_query(c), o);
}

CcdOptions options(const DegenerateCase& c, double width, Mode mode = CcdOptions{}.mode) {
  CcdOptions o;
  o.t_max = c.t_max;
  o.toi_width = width;
  o.mode = mode;
  return o;
}

/// The query with its four per-instant points reordered by `order` (same order at t0, t1).
RationalQuery reordered(const RationalQuery& q, const std::array<int, 4>& order) {
  RationalQuery r;
  r.type = q.type;
  for (int i = 0; i < 4; ++i) {
    r.points[i] = q.points[order[i]];
    r.points[4 + i] = q.points[4 + order[i]];
  }
  return r;
}

/// The query with coordinates permuted: new coordinate i is old coordinate axes[i].
RationalQuery with_axes(const RationalQuery& q, const std::array<int, 3>& axes) {
  RationalQuery r = q;
  for (auto& p : r.points) {
    const std::array<mpq_class, 3> old{p.x, p.y, p.z};
    p = {old[axes[0]], old[axes[1]], old[axes[2]]};
  }
  return r;
}

/// Point orders that describe the same geometric query: the 6 labellings of the triangle
/// (p stays first), or the 8 combinations of swapping the edges and reversing each one.
std::vector<std::array<int, 4>> symmetric_orders(QueryType type) {
  if (type == QueryType::vertex_face)
    return {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1}};
  return {{0, 1, 2, 3}, {1, 0, 2, 3}, {0, 1, 3, 2}, {1, 0, 3, 2},
          {2, 3, 0, 1}, {3, 2, 0, 1}, {2, 3, 1, 0}, {3, 2, 1, 0}};
}

// ------------------------------------------------- independent contact test for the table

struct Q3 {
  mpq_class x, y, z;
};
Q3 operator-(const Q3& a, const Q3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
mpq_class dot(const Q3& a, const Q3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
bool is_zero(const Q3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }

Q3 position(const RationalPoint& x0, const RationalPoint& x1, const mpq_class& t) {
  return {x0.x + t * (x1.x - x0.x), x0.y + t * (x1.y - x0.y), x0.z + t * (x1.z - x0.z)};
}

bool on_closed_segment(const Q3& p, const Q3& x, const Q3& y) {
  return is_zero(cross(y - x, p - x)) && sgn(dot(p - x, p - y)) <= 0;
}

bool in_closed_triangle(const Q3& p, const Q3& a, const Q3& b, const Q3& c) {
  const Q3 n = cross(b - a, c - a);
  if (is_zero(n))  // segment or point: the union of the edges
    return on_closed_segment(p, a, b) || on_closed_segment(p, b, c) ||
           on_closed_segment(p, c, a);
  return sgn(dot(n, p - a)) == 0 && sgn(dot(n, cross(b - a, p - a))) >= 0 &&
         sgn(dot(n, cross(c - b, p - b))) >= 0 && sgn(dot(n, cross(a - c, p - c))) >= 0;
}

bool closed_segments_meet(const Q3& a0, const Q3& a1, const Q3& b0, const Q3& b1) {
  const Q3 da = a1 - a0, db = b1 - b0, w = b0 - a0;
  const Q3 m = cross(da, db);
  if (is_zero(m))  // parallel or zero-length: they meet iff an endpoint is on the other
    return on_closed_segment(a0, b0, b1) || on_closed_segment(a1, b0, b1) ||
           on_closed_segment(b0, a0, a1) || on_closed_segment(b1, a0, a1);
  if (sgn(dot(m, w)) != 0) return false;  // skew lines
  // a0 + s da = b0 + u db, solved by crossing with db and with da.
  const mpq_class mm = dot(m, m);
  const mpq_class s = dot(cross(w, db), m) / mm, u = dot(cross(w, da), m) / mm;
  return 0 <= s && s <= 1 && 0 <= u && u <= 1;
}

bool contact_at(const RationalQuery& q, const mpq_class& t) {
  Q3 x[4];
  for (int i = 0; i < 4; ++i) x[i] = position(q.points[i], q.points[4 + i], t);
  return q.type == QueryType::vertex_face ? in_closed_triangle(x[0], x[1], x[2], x[3])
                                          : closed_segments_meet(x[0], x[1], x[2], x[3]);
}

// ------------------------------------------------------------------------------ the tests

}  // namespace

namespace exactccd::testing {
// Failure messages name the case instead of dumping its bytes.
void PrintTo(const DegenerateCase& c, std::ostream* os) { *os << c.name; }
}  // namespace exactccd::testing

namespace {

class DegenerateCaseTest : public ::testing::TestWithParam<DegenerateCase> {};

// Sanity of the hand-made table, independent of the library: the contact test above holds
// at a rational t*, and fails at the sampled times before t* (at every sampled time of
// [0, t_max] for a non-colliding case). Sampling is only a necessary condition; the table's
// derivations are the argument. For an irrational t* the stated polynomial must change sign
// on the stated interval.
TEST_P(DegenerateCaseTest, TableIsConsistent) {
  const DegenerateCase& c = GetParam();
  const RationalQuery q = exactccd::testing::to_rational_query(c);
  const mpq_class t_max(c.t_max);
  ASSERT_TRUE(t_max > 0 && t_max <= 1);
  constexpr int kSamples = 64;
  if (!c.collides) {
    for (int k = 0; k <= kSamples; ++k) {
      const mpq_class t = t_max * k / kSamples;
      EXPECT_FALSE(contact_at(q, t)) << "contact at t = " << t;
    }
    return;
  }
  if (c.toi.is_rational()) {
    const mpq_class t_star = parse(c.toi.rational);
    ASSERT_TRUE(0 <= t_star && t_star <= t_max);
    EXPECT_TRUE(contact_at(q, t_star)) << "no contact at t* = " << t_star;
    for (int k = 0; k < kSamples && t_star > 0; ++k) {  // k / kSamples * t* < t*
      const mpq_class t = t_star * k / kSamples;
      EXPECT_FALSE(contact_at(q, t)) << "contact at t = " << t << " < t*";
    }
    return;
  }
  const mpq_class lo = parse(c.toi.root_lo), hi = parse(c.toi.root_hi);
  ASSERT_TRUE(0 <= lo && lo < hi && hi <= t_max);
  EXPECT_LT(sign(poly_at(c.toi, lo)) * sign(poly_at(c.toi, hi)), 0);
}

// The double entry points with the default pipeline (Mode::filtered: culling, filters, exact
// path) and with the exact path only; both are certified, so both must give the exact answer.
TEST_P(DegenerateCaseTest, DoubleApiTightest) {
  const DegenerateCase& c = GetParam();
  expect_answer(c, run_double_api(c, options(c, 0)), 0, "double API, default mode, width 0");
  expect_answer(c, run_double_api(c, options(c, 0, Mode::exact)), 0,
                "double API, Mode::exact, width 0");
}

TEST_P(DegenerateCaseTest, DoubleApiCoarseWidth) {
  const DegenerateCase& c = GetParam();
  expect_answer(c, run_double_api(c, options(c, kCoarseWidth)), kCoarseWidth,
                "double API, default mode, width 1e-3");
  expect_answer(c, run_double_api(c, options(c, kCoarseWidth, Mode::exact)), kCoarseWidth,
                "double API, Mode::exact, width 1e-3");
}

TEST_P(DegenerateCaseTest, RationalApiTightest) {
  const DegenerateCase& c = GetParam();
  expect_answer(c, exactccd::exact_ccd(exactccd::testing::to_rational_query(c), options(c, 0)),
                0, "exact_ccd, width 0");
}

TEST_P(DegenerateCaseTest, RationalApiCoarseWidth) {
  const DegenerateCase& c = GetParam();
  expect_answer(c,
                exactccd::exact_ccd(exactccd::testing::to_rational_query(c),
                                    options(c, kCoarseWidth)),
                kCoarseWidth, "exact_ccd, width 1e-3");
}

// Relabelling the triangle's vertices or swapping / reversing the edges describes the same
// point sets over time, and permuting the coordinate axes (rotations for the cyclic
// permutations, reflections for the others) is an exact isometry, so the exact answer is
// unchanged. The axis permutations move the motion onto every projection plane the inclusion
// tests may choose. Each variant goes through exact_ccd and the default double pipeline.
TEST_P(DegenerateCaseTest, SymmetricVariantsAgree) {
  const DegenerateCase& c = GetParam();
  const RationalQuery q = exactccd::testing::to_rational_query(c);
  const std::array<std::array<int, 3>, 6> axis_orders{
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}}};
  for (const auto& order : symmetric_orders(c.type)) {
    for (const auto& axes : axis_orders) {
      const std::string what = "point order " + std::to_string(order[0]) +
                               std::to_string(order[1]) + std::to_string(order[2]) +
                               std::to_string(order[3]) + ", axes " + std::to_string(axes[0]) +
                               std::to_string(axes[1]) + std::to_string(axes[2]);
      const RationalQuery variant = with_axes(reordered(q, order), axes);
      expect_answer(c, exactccd::exact_ccd(variant, options(c, 0)), 0, "exact_ccd, " + what);
      expect_answer(c, run_double_api(variant, options(c, 0)), 0, "double API, " + what);
    }
  }
}

std::string case_name(const ::testing::TestParamInfo<DegenerateCase>& info) {
  return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(HandMade, DegenerateCaseTest,
                         ::testing::ValuesIn(exactccd::testing::degenerate_cases()), case_name);

// The table's own promises: enough cases, unique names (GoogleTest needs them), both types,
// both verdicts, both t_max values, and each form of expected time.
TEST(DegenerateCaseTable, CoversTheRequiredKinds) {
  const auto cases = exactccd::testing::degenerate_cases();
  EXPECT_GE(cases.size(), 45u);
  std::vector<std::string> names;
  int vf = 0, ee = 0, hits = 0, misses = 0, short_interval = 0, irrational = 0, non_double = 0;
  for (const auto& c : cases) {
    names.emplace_back(c.name);
    (c.type == QueryType::vertex_face ? vf : ee) += 1;
    (c.collides ? hits : misses) += 1;
    if (c.t_max < 1) ++short_interval;
    if (c.collides && !c.toi.is_rational()) ++irrational;
    if (c.collides && c.toi.is_rational() && !is_double(parse(c.toi.rational))) ++non_double;
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "duplicate name";
  EXPECT_GT(vf, 0);
  EXPECT_GT(ee, 0);
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
  EXPECT_GT(short_interval, 0);
  EXPECT_GT(irrational, 0);
  EXPECT_GT(non_double, 0);
}

}  // namespace
