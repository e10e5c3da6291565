// Minimum-separation CCD (CcdOptions::min_separation, exact_ccd with a rational delta):
// hand-made cases with known exact answers, delta = 0 against the contact procedure, the
// default path against the exact path on random queries, CGAL's exact squared distances at
// sampled rational times (a check that shares no reduction with exactccd), monotonicity in
// delta, power-of-two invariance and bad input.
// PROOF: proofs/min_separation.md
#include <CGAL/Simple_cartesian.h>
#include <CGAL/mpq_class.h>
#include <CGAL/squared_distance_3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "exact/reference/exact_ccd.hpp"
#include "core/predicates/separation.hpp"
#include "exact/reference/earliest_contact.hpp"
#include "exact/reference/min_separation.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "filters/separation_filter.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"
#include "sample_double_queries.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using Kernel = CGAL::Simple_cartesian<mpq_class>;
using V = Eigen::Vector3d;

CcdOptions with_delta(double delta, Mode mode = Mode::filtered) {
  CcdOptions o;
  o.min_separation = delta;
  o.mode = mode;
  return o;
}

/// t* enclosed by the tightest pair of doubles (or equal to a double).
void expect_tight_enclosure(const CcdResult& r, const mpq_class& t_star) {
  ASSERT_TRUE(r.collides);
  EXPECT_LE(cmp(mpq_class(r.toi_lo), t_star), 0);
  EXPECT_GE(cmp(mpq_class(r.toi_hi), t_star), 0);
  EXPECT_TRUE(r.toi_lo == r.toi_hi || std::nextafter(r.toi_lo, 2.0) == r.toi_hi);
}

// A static triangle (0,0,0), (4,0,0), (0,4,0) and delta = 1/4.
VertexFaceQuery vertex_face(const V& p0, const V& p1) {
  const V a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  return {p0, a, b, c, p1, a, b, c};
}

TEST(MinSeparationTest, VertexFaceHandMadeCasesInEveryCertifiedMode) {
  for (const Mode mode : {Mode::filtered, Mode::exact}) {
    SCOPED_TRACE(to_string(mode));
    const CcdOptions o = with_delta(0.25, mode);
    // Falling through the face: height 1 - 2t reaches 1/4 at t = 3/8.
    expect_tight_enclosure(vertex_face_ccd(vertex_face({1, 1, 1}, {1, 1, -1}), o),
                           mpq_class(3, 8));
    // Sliding at height exactly delta from outside: within only once over the triangle,
    // x = -1 + 4t = 0 at t = 1/4.
    expect_tight_enclosure(vertex_face_ccd(vertex_face({-1, 1, 0.25}, {3, 1, 0.25}), o),
                           mpq_class(1, 4));
    // The same 2^-40 higher: never within.
    const double above = 0.25 + std::ldexp(1.0, -40);
    EXPECT_FALSE(vertex_face_ccd(vertex_face({-1, 1, above}, {3, 1, above}), o).collides);
    // Passing the vertex sphere of a with delta = 5/16: distance^2 = (3/16)^2 + (4/16)^2 + z^2,
    // tangent at z = 0, t = 1/2.
    const CcdOptions sphere = with_delta(0.3125, mode);
    const VertexFaceQuery past_a = vertex_face({-0.1875, -0.25, 1}, {-0.1875, -0.25, -1});
    expect_tight_enclosure(vertex_face_ccd(past_a, sphere), mpq_class(1, 2));
    EXPECT_FALSE(vertex_face_ccd(past_a, with_delta(std::nextafter(0.3125, 0.0), mode)).collides);
    // Passing the edge capsule of ab: distance^2 = 1/16 + z^2, tangent at t = 1/2.
    expect_tight_enclosure(vertex_face_ccd(vertex_face({1, -0.25, 1}, {1, -0.25, -1}), o),
                           mpq_class(1, 2));
    // One ulp short of the tangency: delta just below 1/4 misses both.
    const CcdOptions below = with_delta(std::nextafter(0.25, 0.0), mode);
    EXPECT_FALSE(vertex_face_ccd(vertex_face({1, -0.25, 1}, {1, -0.25, -1}), below).collides);
    // Within delta at t = 0 already.
    const CcdResult r = vertex_face_ccd(vertex_face({1, 1, 0.125}, {1, 1, 3}), o);
    EXPECT_TRUE(r.collides);
    EXPECT_EQ(r.toi_lo, 0.0);
    EXPECT_EQ(r.toi_hi, 0.0);
  }
}

TEST(MinSeparationTest, EdgeEdgeHandMadeCasesInEveryCertifiedMode) {
  for (const Mode mode : {Mode::filtered, Mode::exact}) {
    SCOPED_TRACE(to_string(mode));
    const CcdOptions o = with_delta(0.25, mode);
    // Parallel edges at distance exactly delta, sliding into overlap: b0.x = 2 - 5t = 1 at 1/5.
    const EdgeEdgeQuery sliding{V(0, 0, 0),    V(1, 0, 0),     V(2, 0.25, 0),  V(3, 0.25, 0),
                                V(0, 0, 0),    V(1, 0, 0),     V(-3, 0.25, 0), V(-2, 0.25, 0)};
    expect_tight_enclosure(edge_edge_ccd(sliding, o), mpq_class(1, 5));
    // Crossing edges, b falling: z = 1 - 2t = 1/4 at t = 3/8 (interior-interior region).
    const EdgeEdgeQuery crossing{V(-1, 0, 0), V(1, 0, 0), V(0, -1, 1),  V(0, 1, 1),
                                 V(-1, 0, 0), V(1, 0, 0), V(0, -1, -1), V(0, 1, -1)};
    expect_tight_enclosure(edge_edge_ccd(crossing, o), mpq_class(3, 8));
    // Parallel at distance delta + 2^-45: never within.
    const double gap = 0.25 + std::ldexp(1.0, -45);
    const EdgeEdgeQuery apart{V(0, 0, 0), V(1, 0, 0), V(2, gap, 0),  V(3, gap, 0),
                              V(0, 0, 0), V(1, 0, 0), V(-3, gap, 0), V(-2, gap, 0)};
    EXPECT_FALSE(edge_edge_ccd(apart, o).collides);
    // Point primitives reduce to edge-edge: a point passing a segment at distance exactly delta.
    const PointEdgeQuery point{V(0.5, 0.25, 1), V(0, 0, 0), V(1, 0, 0),
                               V(0.5, 0.25, -1), V(0, 0, 0), V(1, 0, 0)};
    expect_tight_enclosure(point_edge_ccd(point, o), mpq_class(1, 2));
  }
}

TEST(MinSeparationTest, ZeroSeparationIsContactOnTheSampleQueries) {
  const auto& all = test::sample_double_queries();
  const std::size_t stride = test::subset_stride() * 4;
  int compared = 0, contacts = 0;
  for (std::size_t i = 0; i < all.size(); i += stride) {
    const auto& q = all[i];
    const RationalQuery r = q.type == QueryType::vertex_face ? to_rational(q.vertex_face())
                                                             : to_rational(q.edge_edge());
    const CcdOptions o;
    const CcdResult contact = q.type == QueryType::vertex_face
                                  ? exact::vertex_face_ccd_exact(r, o)
                                  : exact::edge_edge_ccd_exact(r, o);
    const CcdResult zero = q.type == QueryType::vertex_face
                               ? exact::vertex_face_min_separation_exact(r, 0, o)
                               : exact::edge_edge_min_separation_exact(r, 0, o);
    ASSERT_EQ(zero.collides, contact.collides) << "sample query " << i;
    ASSERT_EQ(zero.toi_lo, contact.toi_lo) << "sample query " << i;
    ASSERT_EQ(zero.toi_hi, contact.toi_hi) << "sample query " << i;
    ++compared;
    contacts += contact.collides;
  }
  EXPECT_GE(compared, static_cast<int>(all.size() / stride));
  EXPECT_GT(contacts, 0);
}

TEST(MinSeparationTest, ZeroSeparationOptionIsTheContactPath) {
  const auto& all = test::sample_double_queries();
  for (std::size_t i = 0; i < all.size(); i += test::subset_stride()) {
    CcdOptions zero;
    zero.min_separation = 0.0;
    const CcdResult a = random_queries::ccd(all[i], zero), b = random_queries::ccd(all[i], {});
    ASSERT_EQ(a.collides, b.collides);
    ASSERT_EQ(a.toi_lo, b.toi_lo);
    ASSERT_EQ(a.decided_by, b.decided_by);
  }
}

TEST(MinSeparationTest, DefaultPathEqualsExactPathOnTheSampleQueries) {
  // The benchmark's degenerate scenes: contacts at vertices and edges where several region
  // polynomials vanish together, exactly the hard case of the filters' search.
  const auto& all = test::sample_double_queries();
  const std::size_t stride = test::subset_stride() * 2;
  int contacts = 0, by_filters = 0;
  for (const double delta : {1.5e-7, 1.5e-5, 1.5e-3}) {
    for (std::size_t i = 0; i < all.size(); i += stride) {
      const CcdOptions o = with_delta(delta);
      const CcdResult fast = random_queries::ccd(all[i], o);
      const CcdResult exact =
          random_queries::ccd(all[i], random_queries::with_mode(o, Mode::exact));
      ASSERT_EQ(fast.collides, exact.collides) << "sample query " << i << " delta " << delta;
      ASSERT_EQ(fast.toi_lo, exact.toi_lo) << "sample query " << i << " delta " << delta;
      ASSERT_EQ(fast.toi_hi, exact.toi_hi) << "sample query " << i << " delta " << delta;
      contacts += exact.collides;
      by_filters += exact.collides && (fast.decided_by == Stage::filter ||
                                       fast.decided_by == Stage::exact_at_double);
    }
  }
  EXPECT_GT(contacts, static_cast<int>(all.size() / stride / 20));  // ~1,000 at full scale
  EXPECT_GT(by_filters, contacts / 2);  // the search decides most contacts without GMP's roots
}

/// Every non-strict polynomial's condition (Separation::condition) is the one `within` reads:
/// moving its sign from the off side onto the condition never turns `within` off, and turns it
/// on for some signs of the others (the conditions-turning-on case of the search relies on it).
template <class Separation>
void expect_conditions_match_within() {
  std::mt19937_64 rng(7);
  std::array<int, Separation::kCount> sign{};
  for (int k = 0; k < Separation::kNonStrictCount; ++k) {
    const int on = Separation::condition(k);
    bool turns_on = false;
    for (int trial = 0; trial < 4000; ++trial) {
      for (int j = 0; j < Separation::kCount; ++j)
        sign[j] = j < Separation::kNonStrictCount ? static_cast<int>(rng() % 3) - 1
                                                  : static_cast<int>(rng() % 2);
      auto within_with = [&](int s) {
        return Separation::within([&](int j) { return j == k ? s : sign[j]; });
      };
      const bool off = within_with(-on);
      for (const int s : {0, on}) {
        EXPECT_TRUE(!off || within_with(s)) << "polynomial " << k << " turned within off";
        turns_on = turns_on || (!off && within_with(s));
      }
    }
    EXPECT_TRUE(turns_on) << "polynomial " << k << " never mattered";
  }
}

TEST(MinSeparationTest, ConditionsAreTheOnesWithinReads) {
  using P = predicates::Vec3<predicates::FixedPoly<mpq_class, 1>>;
  expect_conditions_match_within<predicates::VertexFaceSeparation<P, mpq_class>>();
  expect_conditions_match_within<predicates::EdgeEdgeSeparation<P, mpq_class>>();
}

/// Several region polynomials reaching zero together (a vertex coming within delta of a
/// triangle's corner, an edge's end coming within delta of another's end): the filters' search
/// decides them (conditions turning on) with the exact path's TOI, the point one when t* is a
/// double, the tightest pair when 2^-40 off the corner moves the roots apart.
TEST(MinSeparationTest, SeveralPolynomialsVanishingTogetherAreDecidedByTheSearch) {
  const double delta = std::ldexp(1.0, -10), off = std::ldexp(1.0, -40);
  const V a(0, 0, 0), b(1, 0, 1), c(1, 0, 0);
  std::vector<random_queries::DoubleQuery> queries;
  for (const double dz : {0.0, off, -off}) {
    random_queries::DoubleQuery q;  // p falls through the plane y = 0 above (near) corner b
    q.type = QueryType::vertex_face;
    q.v = {V(1, 1, 1 + dz), a, b, c, V(1, -1, 1 - dz), a, b, c};
    queries.push_back(q);
    q.type = QueryType::edge_edge;  // a1 = (0, 1 - 2t, dz) passes b0 = (0, 0, 0)
    q.v = {V(-1, 1, dz), V(0, 1, dz), V(0, 0, 0), V(0, 0, 1),
           V(-1, -1, -dz), V(0, -1, -dz), V(0, 0, 0), V(0, 0, 1)};
    queries.push_back(q);
  }
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const CcdOptions o = with_delta(delta);
    const CcdResult fast = random_queries::ccd(queries[i], o);
    const CcdResult exact =
        random_queries::ccd(queries[i], random_queries::with_mode(o, Mode::exact));
    ASSERT_TRUE(exact.collides) << "query " << i;
    EXPECT_EQ(fast.collides, exact.collides) << "query " << i;
    EXPECT_EQ(fast.toi_lo, exact.toi_lo) << "query " << i;
    EXPECT_EQ(fast.toi_hi, exact.toi_hi) << "query " << i;
    EXPECT_NE(fast.decided_by, Stage::exact) << "query " << i;
  }
  // On the corner itself t* = (1 - delta) / 2, a double.
  const CcdResult corner = random_queries::ccd(queries[0], with_delta(delta));
  EXPECT_EQ(corner.toi_lo, (1 - delta) / 2);
  EXPECT_EQ(corner.toi_hi, (1 - delta) / 2);
}

/// A random query of coordinates in [-1, 1] with the given spread of motion.
random_queries::DoubleQuery random_query(std::mt19937_64& rng, QueryType type, double motion) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  random_queries::DoubleQuery q;
  q.type = type;
  for (int i = 0; i < 4; ++i) {
    q.v[i] = V(u(rng), u(rng), u(rng)) * 0.5;
    q.v[i + 4] = q.v[i] + motion * V(u(rng), u(rng), u(rng));
  }
  return q;
}

TEST(MinSeparationTest, DefaultPathEqualsExactPathOnRandomQueries) {
  std::mt19937_64 rng(20261124);
  const int n = static_cast<int>(test::scaled_count(3000));
  int contacts = 0, misses = 0;
  for (int i = 0; i < n; ++i) {
    const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const auto q = random_query(rng, type, i % 3 == 0 ? 0.01 : 1.0);
    const double delta = std::ldexp(1.0, -(static_cast<int>(rng() % 12) + 1));
    CcdOptions o = with_delta(delta);
    o.t_max = i % 5 == 0 ? 0.5 : 1.0;
    const CcdResult fast = random_queries::ccd(q, o);
    const CcdResult exact = random_queries::ccd(q, random_queries::with_mode(o, Mode::exact));
    ASSERT_EQ(fast.collides, exact.collides) << "query " << i << " delta " << delta;
    ASSERT_EQ(fast.toi_lo, exact.toi_lo) << "query " << i;
    ASSERT_EQ(fast.toi_hi, exact.toi_hi) << "query " << i;
    contacts += exact.collides;
    misses += !exact.collides;
  }
  EXPECT_GT(contacts, n / 20);
  EXPECT_GT(misses, n / 20);
}

/// CcdOptions::toi_width with delta > 0: the default path's enclosure holds the exact first time
/// within delta (the exact path's tightest pair of doubles, or that double) and is at most
/// toi_width wide (or two adjacent doubles), on random queries and the sample queries, at
/// every stage that tightens (the Newton probes, the interval secant steps, conditions turning
/// on, the exact procedure). PROOF: proofs/min_separation.md#newton-tightening
TEST(MinSeparationTest, ToiWidthIsHonouredAndEnclosesTheExactTime) {
  std::mt19937_64 rng(20261125);
  const auto& samples = test::sample_double_queries();
  const std::size_t stride = test::subset_stride() * 4;
  const int n = static_cast<int>(test::scaled_count(800));
  int contacts = 0, coarse = 0;
  auto check = [&](const auto& q, CcdOptions o, const std::string& what) {
    for (const double width : {0x1p-20, 1e-3}) {
      o.toi_width = width;
      const CcdResult fast = random_queries::ccd(q, o);
      CcdOptions tight = random_queries::with_mode(o, Mode::exact);
      tight.toi_width = 0;
      const CcdResult exact = random_queries::ccd(q, tight);
      ASSERT_EQ(fast.collides, exact.collides) << what << " width " << width;
      if (!exact.collides) continue;
      ++contacts;
      // t* in [exact.toi_lo, exact.toi_hi] (that double, or strictly between two adjacent
      // ones): a double enclosure holds it iff it holds those.
      EXPECT_LE(fast.toi_lo, exact.toi_lo) << what;
      EXPECT_GE(fast.toi_hi, exact.toi_hi) << what;
      const mpq_class wide = mpq_class(fast.toi_hi) - mpq_class(fast.toi_lo);
      EXPECT_TRUE(cmp(wide, mpq_class(width)) <= 0 ||
                  std::nextafter(fast.toi_lo, 2.0) == fast.toi_hi)
          << what << ": [" << fast.toi_lo << ", " << fast.toi_hi << "] for width " << width;
      coarse += fast.toi_hi - fast.toi_lo > 0x1p-30;
    }
  };
  for (int i = 0; i < n; ++i) {
    const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const auto q = random_query(rng, type, i % 3 == 0 ? 0.01 : 1.0);
    check(q, with_delta(std::ldexp(1.0, -(static_cast<int>(rng() % 12) + 1))),
          "random query " + std::to_string(i));
  }
  for (std::size_t i = 0; i < samples.size(); i += stride)
    check(samples[i], with_delta(1.5e-5), "sample query " + std::to_string(i));
  EXPECT_GT(contacts, n / 10);
  // Not vacuous: the width was used, not only the tightest pair (a probe that lands on the
  // root's adjacent doubles at once closes the bracket anyway).
  EXPECT_GT(coarse, contacts / 4);
}

/// Culling with delta reads the boxes at both ends of the step: pairs that pass over each
/// other's boxes during the step while staying apart along an axis at both ends (both rising,
/// the first above; the swept boxes overlap), with the gap at the ends within 2^-40 of delta
/// on either side, or ending on the other side (another axis may still separate them). Every
/// culled pair is never within delta on the exact path; culling claims many. PROOF: proofs/min_separation.md#culling-with-delta
TEST(MinSeparationTest, CullingAtBothEndsAgreesWithTheExactPath) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = static_cast<int>(test::scaled_count(600));
  int culled = 0;
  for (int i = 0; i < n; ++i) {
    const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const int first = type == QueryType::vertex_face ? 1 : 2;
    const int axis = static_cast<int>(rng() % 3);
    const double delta = std::ldexp(1.0, -(static_cast<int>(rng() % 20) + 2));
    const double factor = (i % 3 == 0) ? 1 - 0x1p-40 : (i % 3 == 1 ? 1 + 0x1p-40 : 2.0);
    const double gap = delta * factor;
    const bool opposite = i % 7 == 0;  // the first ends on the other side
    random_queries::DoubleQuery q;
    q.type = type;
    const double rise = 0.75;  // both rise by more than their boxes' height
    for (int v = 0; v < 4; ++v) {
      q.v[v] = V(u(rng), u(rng), u(rng)) * 0.25;
      q.v[v][axis] = v < first ? gap : -0.25 * std::fabs(u(rng));
      q.v[v + 4] = q.v[v] + V(u(rng), u(rng), u(rng)) * 0.25;
      q.v[v + 4][axis] = q.v[v][axis] + rise;
    }
    if (opposite)
      for (int v = 0; v < first; ++v) q.v[v + 4][axis] = -gap - 1.0 + rise;
    // The first's lowest vertex exactly at the gap above the second's highest, at both ends.
    double top0 = -1e300, top1 = -1e300;
    for (int v = first; v < 4; ++v) {
      top0 = std::max(top0, q.v[v][axis]);
      top1 = std::max(top1, q.v[v + 4][axis]);
    }
    for (int v = 0; v < first && !opposite; ++v) {
      q.v[v][axis] = top0 + gap + (v == 0 ? 0.0 : 0.125);
      q.v[v + 4][axis] = top1 + gap + (v == 0 ? 0.0 : 0.125);
    }
    const bool culls = type == QueryType::vertex_face
                           ? filters::vertex_face_separation_culling(q.vertex_face(), delta)
                           : filters::edge_edge_separation_culling(q.edge_edge(), delta);
    if (!culls) continue;
    ++culled;
    const CcdResult exact =
        random_queries::ccd(q, random_queries::with_mode(with_delta(delta), Mode::exact));
    EXPECT_FALSE(exact.collides) << "query " << i << " culled but within " << delta << " at "
                                 << exact.toi_lo;
  }
  EXPECT_GT(culled, n / 4);
}

TEST(MinSeparationTest, IntegerSignsAtDoublesEqualRationalPolynomialSigns) {
  // The filters' exact signs at double times (integers, positions scaled by powers of two),
  // and the tightening's probes, against the region polynomials over the rationals evaluated at the same time, on random
  // queries of wide scales and tiny motions; then exact zeros on hand-made tangencies.
  std::mt19937_64 rng(3);
  const int n = static_cast<int>(test::scaled_count(200));
  int compared = 0;
  for (int i = 0; i < n; ++i) {
    const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    auto q = random_query(rng, type, i % 4 == 0 ? 0x1p-30 : 1.0);
    const int k2 = static_cast<int>(rng() % 60) - 30;
    random_queries::scale_if_exact(&q, k2);
    const double delta = std::ldexp(1.0, k2 - 3 - static_cast<int>(rng() % 8));
    const exact::separation::ExactSignsAtDoubles signs(
        {&q.v[0], &q.v[1], &q.v[2], &q.v[3]}, {&q.v[4], &q.v[5], &q.v[6], &q.v[7]}, delta);
    const RationalQuery r =
        type == QueryType::vertex_face ? to_rational(q.vertex_face()) : to_rational(q.edge_edge());
    const auto& p = r.points;
    const mpq_class d2 = mpq_class(delta) * delta;
    std::vector<exact::Polynomial> polys;
    auto collect = [&polys](const auto& g) { polys.emplace_back(g); };
    if (type == QueryType::vertex_face)
      predicates::vertex_face_separation(exact::moving(p[0], p[4]), exact::moving(p[1], p[5]),
                                         exact::moving(p[2], p[6]), exact::moving(p[3], p[7]), d2)
          .for_each_polynomial(collect);
    else
      predicates::edge_edge_separation(exact::moving(p[0], p[4]), exact::moving(p[1], p[5]),
                                       exact::moving(p[2], p[6]), exact::moving(p[3], p[7]), d2)
          .for_each_polynomial(collect);
    for (const double t : {0.0, 1.0, 0.5, std::ldexp(1.0, -40), std::nextafter(1.0, 0.0),
                           std::uniform_real_distribution<double>(0, 1)(rng)}) {
      for (int k = 0; k < static_cast<int>(polys.size()); ++k) {
        const int expected = polys[k].sign_at(mpq_class(t));
        const int got = type == QueryType::vertex_face ? signs.vertex_face_sign(k, t)
                                                       : signs.edge_edge_sign(k, t);
        ASSERT_EQ(got, expected) << "query " << i << " polynomial " << k << " t " << t;
        // The tightening's probe: the same exact sign for every polynomial, those without a
        // double-double kernel included (never a default 0, which would read as a root).
        const auto probe = type == QueryType::vertex_face ? signs.vertex_face_probe(k, t)
                                                          : signs.edge_edge_probe(k, t);
        ASSERT_EQ(probe.sign, expected) << "probe, query " << i << " polynomial " << k;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, n * 100);
  // Exact zeros: the vertex tangent to a's sphere (polynomial 4) at t = 1/2, delta = 5/16,
  // and to the face plane's offset (polynomial 0) while sliding at height delta.
  const VertexFaceQuery past_a = vertex_face({-0.1875, -0.25, 1}, {-0.1875, -0.25, -1});
  const exact::separation::ExactSignsAtDoubles tangent(
      {&past_a.p_t0, &past_a.a_t0, &past_a.b_t0, &past_a.c_t0},
      {&past_a.p_t1, &past_a.a_t1, &past_a.b_t1, &past_a.c_t1}, 0.3125);
  EXPECT_EQ(tangent.vertex_face_sign(4, 0.5), 0);
  EXPECT_EQ(tangent.vertex_face_sign(4, std::nextafter(0.5, 0.0)), 1);
  EXPECT_EQ(tangent.vertex_face_sign(4, std::nextafter(0.5, 1.0)), 1);
  const VertexFaceQuery sliding = vertex_face({-1, 1, 0.25}, {3, 1, 0.25});
  const exact::separation::ExactSignsAtDoubles slide(
      {&sliding.p_t0, &sliding.a_t0, &sliding.b_t0, &sliding.c_t0},
      {&sliding.p_t1, &sliding.a_t1, &sliding.b_t1, &sliding.c_t1}, 0.25);
  for (const double t : {0.0, 0.3, 1.0}) EXPECT_EQ(slide.vertex_face_sign(0, t), 0);
}

Kernel::Point_3 at(const V& x0, const V& x1, const mpq_class& t) {
  const mpq_class x = mpq_class(x0.x()) + t * (mpq_class(x1.x()) - mpq_class(x0.x()));
  const mpq_class y = mpq_class(x0.y()) + t * (mpq_class(x1.y()) - mpq_class(x0.y()));
  const mpq_class z = mpq_class(x0.z()) + t * (mpq_class(x1.z()) - mpq_class(x0.z()));
  return {x, y, z};
}

/// CGAL's exact squared distance between the primitives at the rational time t.
mpq_class squared_distance_at(const random_queries::DoubleQuery& q, const mpq_class& t) {
  const auto& v = q.v;
  if (q.type == QueryType::vertex_face)
    return CGAL::squared_distance(at(v[0], v[4], t),
                                  Kernel::Triangle_3(at(v[1], v[5], t), at(v[2], v[6], t),
                                                     at(v[3], v[7], t)));
  return CGAL::squared_distance(Kernel::Segment_3(at(v[0], v[4], t), at(v[1], v[5], t)),
                                Kernel::Segment_3(at(v[2], v[6], t), at(v[3], v[7], t)));
}

TEST(MinSeparationTest, AgreesWithCgalSquaredDistancesAtSampledTimes) {
  std::mt19937_64 rng(7);
  const int n = static_cast<int>(test::at_least(test::scaled_count(400), 100));
  const int samples = 24;
  int within_samples = 0, before_toi_samples = 0, exact_tois = 0;
  for (int i = 0; i < n; ++i) {
    const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    const auto q = random_query(rng, type, 1.0);
    const double delta = 0.125;
    const mpq_class delta2 = mpq_class(delta) * delta;
    const CcdResult r = random_queries::ccd(q, with_delta(delta));
    for (int k = 0; k <= samples; ++k) {
      const mpq_class t(k, samples);
      const mpq_class d2 = squared_distance_at(q, t);
      if (cmp(d2, delta2) <= 0) {  // within delta at t: a contact no later than t
        ++within_samples;
        ASSERT_TRUE(r.collides) << "query " << i << " within delta at " << t;
        ASSERT_LE(cmp(mpq_class(r.toi_lo), t), 0) << "query " << i;
      }
      if (r.collides && cmp(t, mpq_class(r.toi_lo)) < 0) {  // before t*: never within
        ++before_toi_samples;
        ASSERT_GT(cmp(d2, delta2), 0) << "query " << i << " within delta before its TOI at " << t;
      }
    }
    if (r.collides && r.toi_lo == r.toi_hi) {  // t* is this double: within delta there
      ++exact_tois;
      ASSERT_LE(cmp(squared_distance_at(q, mpq_class(r.toi_lo)), delta2), 0) << "query " << i;
    }
  }
  EXPECT_GT(within_samples, n);
  EXPECT_GT(before_toi_samples, n);
  EXPECT_GT(exact_tois, 0);
}

TEST(MinSeparationTest, LargerSeparationNeverLaterAndScalingByPowersOfTwoChangesNothing) {
  std::mt19937_64 rng(11);
  const int n = static_cast<int>(test::scaled_count(600));
  for (int i = 0; i < n; ++i) {
    const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
    auto q = random_query(rng, type, 0.5);
    const CcdResult small = random_queries::ccd(q, with_delta(0.0625));
    const CcdResult large = random_queries::ccd(q, with_delta(0.125));
    if (small.collides) {
      ASSERT_TRUE(large.collides) << "query " << i;
      ASSERT_LE(large.toi_lo, small.toi_lo) << "query " << i;
    }
    const int k = static_cast<int>(rng() % 400) - 200;
    if (!random_queries::scale_if_exact(&q, k)) continue;
    const CcdResult scaled = random_queries::ccd(q, with_delta(std::ldexp(0.125, k)));
    ASSERT_EQ(scaled.collides, large.collides) << "query " << i << " k " << k;
    ASSERT_EQ(scaled.toi_lo, large.toi_lo) << "query " << i << " k " << k;
    ASSERT_EQ(scaled.toi_hi, large.toi_hi) << "query " << i << " k " << k;
  }
}

TEST(MinSeparationTest, RationalSeparationOnTheOracleApi) {
  // delta = 1/3 (not a double): crossing edges reach z = 1 - 2t = 1/3 at t = 1/3.
  const EdgeEdgeQuery crossing{V(-1, 0, 0), V(1, 0, 0), V(0, -1, 1),  V(0, 1, 1),
                               V(-1, 0, 0), V(1, 0, 0), V(0, -1, -1), V(0, 1, -1)};
  expect_tight_enclosure(exact_ccd(to_rational(crossing), mpq_class(1, 3)), mpq_class(1, 3));
  // delta = 0 is contact: at t = 1/2.
  expect_tight_enclosure(exact_ccd(to_rational(crossing), mpq_class(0)), mpq_class(1, 2));
  EXPECT_THROW(exact_ccd(to_rational(crossing), mpq_class(-1, 3)), std::invalid_argument);
  // The minimum separation is given once: options.min_separation or the rational argument, not
  // both (refused, never one of them silently ignored), whatever the rational delta.
  CcdOptions with_double_delta;
  with_double_delta.min_separation = 0.25;
  for (const mpq_class& delta : {mpq_class(1, 3), mpq_class(1, 4), mpq_class(0)}) {
    try {
      exact_ccd(to_rational(crossing), delta, with_double_delta);
      ADD_FAILURE() << "both minimum separations accepted, rational " << delta;
    } catch (const std::invalid_argument& e) {
      EXPECT_STREQ(e.what(),
                   "exactccd: give the minimum separation once: options.min_separation or the "
                   "rational argument, not both");
    }
  }
  // Either one alone is honoured: the double delta 1/4 reaches z = 1/4 at t = 3/8.
  expect_tight_enclosure(exact_ccd(to_rational(crossing), with_double_delta), mpq_class(3, 8));
  expect_tight_enclosure(exact_ccd(to_rational(crossing), mpq_class(1, 4), CcdOptions{}),
                         mpq_class(3, 8));
}

TEST(MinSeparationTest, NegativeOrNonFiniteSeparationThrows) {
  const VertexFaceQuery q = vertex_face({1, 1, 1}, {1, 1, -1});
  for (const double bad : {-1.0, -0.0 - std::ldexp(1.0, -1074),
                           std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    for (const Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
      EXPECT_THROW(vertex_face_ccd(q, with_delta(bad, mode)), std::invalid_argument) << bad;
      EXPECT_THROW(edge_edge_ccd(EdgeEdgeQuery{}, with_delta(bad, mode)), std::invalid_argument);
    }
  }
}

}  // namespace
}  // namespace exactccd
