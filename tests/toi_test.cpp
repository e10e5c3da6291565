// The time of impact, confirmed independently of the code under test where the time is
// rational (CGAL's exact kernel at that time), and by the exact path restricted to shorter
// intervals where it is not.
//
// For a colliding query with exact first contact time t* and tight enclosure [lo, hi]:
//  (a) contact at t*: lo == hi: the primitives touch at the rational time lo (CGAL);
//      lo < hi: lo and hi are consecutive doubles, the query collides on [0, hi] (exact path)
//      and not at lo (CGAL), and the coplanarity determinant (unless zero throughout) changes
//      sign on [lo, hi] or has a rational multiple root r in (lo, hi) with contact at r (CGAL).
//  (b) none before: the query restricted to [0, lo] (lo < hi) or [0, prev double of lo]
//      (lo == hi) does not collide, and CGAL finds no contact at sampled times in [0, lo).
//  (c) coarser widths: the enclosure contains the tight one and is at most that wide, or is it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "test_support.hpp"

namespace exactccd::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

CcdOptions with_t_max(double t_max, double width = 0) {
  CcdOptions o;
  o.t_max = t_max;
  o.toi_width = width;
  return o;
}

/// Counts what the checks looked at, so that a test can insist its inputs exercised each case.
struct ToiStats {
  std::size_t colliding = 0, free = 0, double_toi = 0, between_doubles = 0, at_zero = 0;
  std::size_t multiple_root = 0;  // t* a multiple root of the determinant, between doubles
  std::string str() const {
    std::ostringstream s;
    s << colliding << " colliding (" << double_toi << " with a double t*, " << at_zero
      << " of them at t = 0; " << between_doubles << " with t* between two doubles, "
      << multiple_root << " of them a multiple rational root), " << free << " free";
    return s.str();
  }
};

/// All checks (a), (b), (c) of one query at one t_max; failures name `where` and the query.
void check_toi(const RationalQuery& q, double t_max, const std::string& where, ToiStats* stats) {
  SCOPED_TRACE(where + " (t_max " + std::to_string(t_max) + ")" + describe(q));
  const CcdResult r = exact_ccd(q, with_t_max(t_max));
  if (!r.collides) {
    ++stats->free;
    EXPECT_EQ(r.toi_lo, kInf);  // the no-contact convention
    EXPECT_EQ(r.toi_hi, kInf);
    // Independent necessary condition: no contact at sampled rational times of [0, t_max].
    const mpq_class end(t_max);
    for (int k = 0; k <= 8; ++k)
      EXPECT_FALSE(cgal_contact_at(q, end * k / 8)) << "contact at t = " << k << "/8 t_max";
    return;
  }
  ++stats->colliding;
  ASSERT_LE(0.0, r.toi_lo);
  ASSERT_LE(r.toi_lo, r.toi_hi);
  ASSERT_LE(r.toi_hi, t_max);
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);  // finite, as just checked

  // (a) contact at t*.
  if (r.toi_lo == r.toi_hi) {
    ++stats->double_toi;
    stats->at_zero += r.toi_lo == 0;
    EXPECT_TRUE(cgal_contact_at(q, lo)) << "no contact at the reported t* = " << r.toi_lo;
  } else {
    ++stats->between_doubles;
    EXPECT_EQ(std::nextafter(r.toi_lo, kInf), r.toi_hi) << "not the tightest pair of doubles";
    EXPECT_TRUE(exact_ccd(q, with_t_max(r.toi_hi)).collides) << "no contact in [0, toi_hi]";
    EXPECT_FALSE(cgal_contact_at(q, lo)) << "contact at toi_lo, yet t* > toi_lo is reported";
    // t* lies strictly inside (lo, hi), and the four points are coplanar there. When they are
    // not coplanar throughout, the determinant is a non-zero cubic D. If D keeps one non-zero
    // sign at lo and hi, its roots in (lo, hi) have even total multiplicity: with at most three
    // roots, either a multiple root r (rational, found exactly) is the only one, so t* = r and
    // CGAL must see contact there; or two distinct roots lie within this one ulp (not expected
    // from these inputs, so reported).
    if (!cgal_coplanar_throughout(q)) {
      const int s_lo = cgal_coplanarity_sign_at(q, lo), s_hi = cgal_coplanarity_sign_at(q, hi);
      if (s_lo * s_hi > 0) {
        const auto multiple = multiple_roots_in(coplanarity_polynomial(q), lo, hi);
        if (multiple.empty()) {
          ADD_FAILURE() << "coplanarity determinant keeps its sign on [toi_lo, toi_hi] and has "
                           "no multiple root there";
        } else {
          ++stats->multiple_root;
          EXPECT_TRUE(cgal_contact_at(q, multiple.front()))
              << "no contact at the multiple root t* = " << multiple.front().get_str();
        }
      }
    }
  }

  // (b) no contact before t*.
  if (r.toi_lo > 0) {
    if (r.toi_lo < r.toi_hi) {
      EXPECT_FALSE(exact_ccd(q, with_t_max(r.toi_lo)).collides) << "contact in [0, toi_lo]";
    } else {
      const double before = std::nextafter(r.toi_lo, 0.0);
      if (before > 0) {  // else toi_lo is the smallest positive double: t_max must be > 0
        EXPECT_FALSE(exact_ccd(q, with_t_max(before)).collides)
            << "contact in [0, " << before << "], before t* = " << r.toi_lo;
      }
    }
    const mpq_class before_lo = lo - lo / (1 << 20);
    EXPECT_FALSE(cgal_contact_at(q, 0)) << "contact at t = 0";
    EXPECT_FALSE(cgal_contact_at(q, lo / 4)) << "contact at t = toi_lo / 4";
    EXPECT_FALSE(cgal_contact_at(q, lo / 2)) << "contact at t = toi_lo / 2";
    EXPECT_FALSE(cgal_contact_at(q, 3 * lo / 4)) << "contact at t = 3 toi_lo / 4";
    EXPECT_FALSE(cgal_contact_at(q, before_lo)) << "contact at t = toi_lo (1 - 2^-20)";
  }

  // (c) coarser enclosures.
  for (const double width : {1e-6, 0.25}) {
    const CcdResult w = exact_ccd(q, with_t_max(t_max, width));
    EXPECT_TRUE(w.collides) << "width " << width;
    EXPECT_LE(0.0, w.toi_lo) << "width " << width;
    EXPECT_LE(w.toi_lo, r.toi_lo) << "width " << width;
    EXPECT_GE(w.toi_hi, r.toi_hi) << "width " << width;
    EXPECT_LE(w.toi_hi, t_max) << "width " << width;
    const bool tight = w.toi_lo == r.toi_lo && w.toi_hi == r.toi_hi;
    // The width is compared exactly: a double subtraction could round below the width.
    EXPECT_TRUE(tight || mpq_class(w.toi_hi) - mpq_class(w.toi_lo) <= mpq_class(width))
        << "width " << width << ": [" << w.toi_lo << ", " << w.toi_hi << "]";
  }
}

TEST(Toi, SampleQueries) {
  ToiStats stats;
  for (const auto& s : sample_queries()) {
    const CcdResult r = exact_ccd(s.query);
    if (!r.collides) continue;
    check_toi(s.query, 1.0, s.where(), &stats);
  }
  std::cout << "[ stats    ] " << stats.str() << "\n";
  EXPECT_EQ(stats.colliding, 329u);
  EXPECT_GT(stats.double_toi, 0u);
  EXPECT_GT(stats.at_zero, 0u);
}

// Restricting t_max: a query collides on [0, T] iff t* <= T, with the same first contact. The
// sample queries at T = 1/2 and at T = 3/4, from their TOI at T = 1.
TEST(Toi, SampleQueriesShorterInterval) {
  ToiStats stats;
  for (const auto& s : scaled_sample_queries()) {
    const CcdResult full = exact_ccd(s.query);
    for (const double t_max : {0.5, 0.75}) {
      const CcdResult r = exact_ccd(s.query, with_t_max(t_max));
      // With t_max a double, t* <= t_max reads toi_lo <= t_max when t* is the double toi_lo and
      // toi_hi <= t_max when t* lies strictly between two consecutive doubles.
      const bool expect = full.collides && (full.toi_lo == full.toi_hi ? full.toi_lo <= t_max
                                                                       : full.toi_hi <= t_max);
      EXPECT_EQ(r.collides, expect) << s.where() << " at t_max " << t_max;
      if (r.collides && expect) {
        EXPECT_EQ(r.toi_lo, full.toi_lo) << s.where();
        EXPECT_EQ(r.toi_hi, full.toi_hi) << s.where();
      }
      if (r.collides) check_toi(s.query, t_max, s.where(), &stats);
    }
  }
  std::cout << "[ stats    ] " << stats.str() << "\n";
}

// Queries built to touch at a known dyadic time tc: they collide, t* <= tc, and they collide on
// [0, tc] already.
void random_colliding(QueryType type) {
  QueryGenerator gen(test_seed(to_string(type)) + static_cast<int>(type));
  ToiStats stats;
  const int n = static_cast<int>(scaled_count(1500));
  for (int i = 0; i < n; ++i) {
    mpq_class tc;
    const RationalQuery q = gen.colliding(type, &tc);
    const std::string where = "random colliding #" + std::to_string(i);
    ASSERT_TRUE(cgal_contact_at(q, tc)) << where << ": generator failed" << describe(q);
    const CcdResult r = exact_ccd(q);
    EXPECT_TRUE(r.collides) << where << describe(q);
    EXPECT_LE(mpq_class(r.toi_lo), tc) << where << describe(q);
    EXPECT_TRUE(exact_ccd(q, with_t_max(tc.get_d())).collides) << where << describe(q);
    check_toi(q, 1.0, where, &stats);
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[ stats    ] " << stats.str() << "\n";
  EXPECT_EQ(stats.colliding, static_cast<std::size_t>(n));
  EXPECT_GT(stats.between_doubles, 0u);
  EXPECT_GT(stats.double_toi, 0u);
}

TEST(Toi, RandomCollidingVertexFace) { random_colliding(QueryType::vertex_face); }
TEST(Toi, RandomCollidingEdgeEdge) { random_colliding(QueryType::edge_edge); }

// Degenerate and tiny-grid queries (many contacts at t = 0 or t = 1, coplanar motion, collapsed
// primitives), colliding or not, at t_max = 1 and t_max = 1/2.
void random_degenerate(QueryType type) {
  QueryGenerator gen(test_seed(to_string(type)) + 100 + static_cast<int>(type));
  ToiStats stats;
  const int n = static_cast<int>(scaled_count(1500));
  for (int i = 0; i < n; ++i) {
    const RationalQuery q = i % 2 ? gen.degenerate(type) : gen.tiny_grid(type);
    for (const double t_max : {1.0, 0.5})
      check_toi(q, t_max, "random degenerate #" + std::to_string(i), &stats);
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[ stats    ] " << stats.str() << "\n";
  EXPECT_GT(stats.colliding, 0u);
  EXPECT_GT(stats.free, 0u);
  EXPECT_GT(stats.at_zero, 0u);
  EXPECT_GT(stats.double_toi, stats.at_zero);
}

TEST(Toi, RandomDegenerateVertexFace) { random_degenerate(QueryType::vertex_face); }
TEST(Toi, RandomDegenerateEdgeEdge) { random_degenerate(QueryType::edge_edge); }

// Hand-made queries whose first contact time is known in closed form.
TEST(Toi, KnownFirstContactTimes) {
  ToiStats stats;
  // A vertex falling straight onto the triangle z = 0 from z = 1 to z = -2: it reaches the plane
  // at t = 1/3 (not a double), inside the triangle.
  RationalQuery vf;
  vf.type = QueryType::vertex_face;
  vf.points = {RationalPoint{mpq_class(1, 4), mpq_class(1, 4), 1}, {0, 0, 0}, {1, 0, 0},
               {0, 1, 0}, {mpq_class(1, 4), mpq_class(1, 4), -2}, {0, 0, 0}, {1, 0, 0},
               {0, 1, 0}};
  CcdResult r = exact_ccd(vf);
  ASSERT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, exact::round_down(mpq_class(1, 3)));
  EXPECT_EQ(r.toi_hi, exact::round_up(mpq_class(1, 3)));
  check_toi(vf, 1.0, "vertex falling to t* = 1/3", &stats);

  // Edge A fixed on the x-axis; edge B parallel to the y-axis at x = 0 descends from z = 1 to
  // z = -1 and crosses A at the origin at t = 1/2 (a double).
  RationalQuery ee;
  ee.type = QueryType::edge_edge;
  ee.points = {RationalPoint{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1},
               {-1, 0, 0}, {1, 0, 0}, {0, -1, -1}, {0, 1, -1}};
  r = exact_ccd(ee);
  ASSERT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.5);
  EXPECT_EQ(r.toi_hi, 0.5);
  check_toi(ee, 1.0, "edges crossing at t* = 1/2", &stats);

  // A vertex moving in the triangle's plane along x = y towards the edge x + y = 1 of the unit
  // right triangle from outside: p(t) = (1 - t)(2, 2) + t (0, 0) reaches x + y = 1 when
  // 4(1 - t) = 1, t = 3/4. Coplanar throughout, so this exercises the coplanar reduction.
  RationalQuery coplanar;
  coplanar.type = QueryType::vertex_face;
  coplanar.points = {RationalPoint{2, 2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                     {0, 0, 0},             {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  r = exact_ccd(coplanar);
  ASSERT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.75);
  EXPECT_EQ(r.toi_hi, 0.75);
  check_toi(coplanar, 1.0, "coplanar vertex reaching an edge at t* = 3/4", &stats);

  // An irrational first contact. p = (1/4, 1/4, 1/4) fixed; a = 0 fixed; b(t) = (1 - t, 0, t);
  // c(t) = (0, 1, t). The normal b x c = (-t, -t (1 - t), 1 - t), and p is in the plane when
  // (t^2 - 3t + 1)/4 = 0: t* = (3 - sqrt 5)/2 ~ 0.382 (the other root exceeds 1; before t* the
  // points are not coplanar, so no earlier contact). At t*, p = alpha b + beta c with
  // beta = 1/4 (y) and alpha = 1/(4 (1 - t*)) ~ 0.405 (x): both >= 0, sum <= 1, so p is inside.
  RationalQuery irrational;
  irrational.type = QueryType::vertex_face;
  const mpq_class q4(1, 4);
  irrational.points = {RationalPoint{q4, q4, q4}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                       RationalPoint{q4, q4, q4}, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}};
  r = exact_ccd(irrational);
  ASSERT_TRUE(r.collides);
  // lo < (3 - sqrt 5)/2 < hi iff (3 - 2 lo)^2 > 5 > (3 - 2 hi)^2 (as 3 - 2 lo, 3 - 2 hi > 0).
  const mpq_class lo(r.toi_lo), hi(r.toi_hi);
  EXPECT_GT((3 - 2 * lo) * (3 - 2 * lo), 5);
  EXPECT_LT((3 - 2 * hi) * (3 - 2 * hi), 5);
  EXPECT_EQ(std::nextafter(r.toi_lo, kInf), r.toi_hi);
  check_toi(irrational, 1.0, "vertex on a tilting triangle at t* = (3 - sqrt 5)/2", &stats);
}

}  // namespace
}  // namespace exactccd::test
