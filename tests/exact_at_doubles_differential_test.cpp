// Differential tests of the exact stage at double times (exact/stages/integer_query.hpp): the
// fixed-size instantiation of the integer kernels against the same templates instantiated with
// mpz_class (IntegerQuery::Arithmetic::gmp, the reference), against the exact rational
// evaluation of the predicate templates, and the whole default path against Mode::exact.
//
// Queries: the random families of corpus/random_queries.hpp (planted and near-degenerate
// contacts included), and adversarial ones built here exactly in doubles: resting contact (a
// vertex on a face, everything moving within the face's plane; or lifting off it at t = 0),
// edges sliding along each other on a common line or in a common plane, and random doubles
// whose exponents spread over +-10 to +-1000 (the fixed widths and beyond). Times: 0, 1, the
// planted time, random doubles, dyadic times of few bits, 1 - 2^-k, and tiny times down to
// the subnormal 2^-1074 (the largest exponents k).
//
// At least 1,000,000 compared evaluations per run (EXACTCCD_TEST_SCALE scales the counts;
// EXACTCCD_TEST_SEED replays a run).
// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/inclusion.hpp"
#include "corpus/random_queries.hpp"
#include "exact/stages/integer_query.hpp"
#include "tests/test_scale.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

using exact::IntegerQuery;
using Rng = std::mt19937_64;

std::uint64_t test_seed() {
  static const std::uint64_t seed = [] {
    const std::uint64_t s = seed_from_environment(0xd1ff);
    std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n", static_cast<unsigned long long>(s));
    return s;
  }();
  return seed;
}

// ---- adversarial queries, exact in doubles -----------------------------------------------------

/// A dyadic number n 2^-d with |n| < 2^bits.
double dyadic(Rng& rng, int bits, int d) {
  const std::int64_t range = std::int64_t{1} << bits;
  const auto n = static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(2 * range)) - range;
  return std::ldexp(static_cast<double>(n), -d);
}

Eigen::Vector3d dyadic_vector(Rng& rng, int bits, int d) {
  return {dyadic(rng, bits, d), dyadic(rng, bits, d), dyadic(rng, bits, d)};
}

/// Scales every coordinate by 2^s (exact: the values have few bits and moderate exponents).
void scale(DoubleQuery* q, int s) {
  for (auto& p : q->v) p = {std::ldexp(p.x(), s), std::ldexp(p.y(), s), std::ldexp(p.z(), s)};
}

/// A point O + a U + b V of the plane spanned by U and V through O, with dyadic a and b.
/// Every value has few bits, so each coordinate is exact in doubles.
struct Plane {
  Eigen::Vector3d origin, u, v;
  Eigen::Vector3d at(double a, double b) const { return origin + a * u + b * v; }
};

Plane random_plane(Rng& rng) {
  Plane p{dyadic_vector(rng, 12, 6), dyadic_vector(rng, 3, 0), dyadic_vector(rng, 3, 0)};
  if (p.u.cross(p.v).squaredNorm() == 0) p.v = p.v + Eigen::Vector3d(1, 2, 3);
  return p;
}

/// Resting contact: a triangle in a plane and a vertex on the plane (inside, on an edge, at a
/// vertex or outside), all moving within the plane (the cubic vanishes identically); or the
/// vertex lifting off the plane from t = 0 (a root at t = 0).
DoubleQuery resting_vertex_face(Rng& rng) {
  const Plane plane = random_plane(rng);
  auto coord = [&] { return dyadic(rng, 8, 6); };
  DoubleQuery q;
  q.type = QueryType::vertex_face;
  double a[4][2], da[4][2];
  for (int i = 1; i < 4; ++i)
    for (int k = 0; k < 2; ++k) a[i][k] = coord(), da[i][k] = coord() / 8;
  // The vertex: a dyadic affine combination of the triangle's corners (weights k/8, some
  // outside [0, 1]), at t = 0 and moving as the same combination (resting on the face).
  const int w1 = static_cast<int>(rng() % 12) - 2, w2 = static_cast<int>(rng() % 12) - 2;
  const double b1 = w1 / 8.0, b2 = w2 / 8.0, b0 = 1 - b1 - b2;
  for (int k = 0; k < 2; ++k) {
    a[0][k] = b0 * a[1][k] + b1 * a[2][k] + b2 * a[3][k];
    da[0][k] = b0 * da[1][k] + b1 * da[2][k] + b2 * da[3][k];
  }
  for (int i = 0; i < 4; ++i) {
    q.v[i] = plane.at(a[i][0], a[i][1]);
    q.v[i + 4] = plane.at(a[i][0] + da[i][0], a[i][1] + da[i][1]);
  }
  if (rng() % 2) q.v[4] += plane.u.cross(plane.v) / 64;  // lifts off the plane from t = 0
  q.planted_time = 0.0;
  return q;
}

/// Edges sliding along each other: on one line (overlapping or apart), or in one plane with
/// parallel directions (touching or apart), all motion along the line or within the plane.
DoubleQuery sliding_edge_edge(Rng& rng) {
  const Plane plane = random_plane(rng);
  auto coord = [&] { return dyadic(rng, 8, 6); };
  DoubleQuery q;
  q.type = QueryType::edge_edge;
  const bool collinear = rng() % 2;
  const double offset = collinear ? 0.0 : (rng() % 3) / 4.0;  // the second edge's line
  const double shift = coord() / 4;
  const double s[4] = {coord(), coord(), coord(), coord()};
  for (int i = 0; i < 4; ++i) {
    const double across = i < 2 ? 0.0 : offset;
    q.v[i] = plane.at(s[i], across);
    q.v[i + 4] = plane.at(s[i] + (i < 2 ? shift : -shift), across);
  }
  q.planted_time = 0.5;
  return q;
}

/// Random doubles whose binary exponents are uniform in [-spread, spread].
DoubleQuery wide_spread(Rng& rng, QueryType type, int spread) {
  DoubleQuery q;
  q.type = type;
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-spread, spread);
  for (auto& p : q.v)
    for (int k = 0; k < 3; ++k)
      p[k] = std::ldexp(rng() % 2 ? -mantissa(rng) : mantissa(rng), exponent(rng));
  return q;
}

// ---- references ----------------------------------------------------------------------------

RationalQuery rational_of(const DoubleQuery& q) {
  return q.type == QueryType::vertex_face ? to_rational(q.vertex_face())
                                          : to_rational(q.edge_edge());
}

/// The sign of the coplanarity cubic (the predicate template over rationals) at t.
int rational_cubic_sign(const RationalQuery& rq, double t) {
  using predicates::linear_motion;
  using predicates::Vec3;
  auto moving = [&](int k) {
    const auto& a = rq.points[k];
    const auto& b = rq.points[k + 4];
    return linear_motion(Vec3<mpq_class>{a.x, a.y, a.z}, Vec3<mpq_class>{b.x, b.y, b.z});
  };
  const auto f =
      rq.type == QueryType::vertex_face
          ? predicates::vertex_face_coplanarity_cubic(moving(0), moving(1), moving(2), moving(3))
          : predicates::edge_edge_coplanarity_cubic(moving(0), moving(1), moving(2), moving(3));
  return sgn(predicates::evaluate(f, mpq_class(t)));
}

/// The inclusion predicates on the rational positions at t.
bool rational_contact(const RationalQuery& rq, double t) {
  using Position = predicates::Vec3<predicates::FixedPoly<mpq_class, 0>>;
  const mpq_class T(t);
  Position x[4];
  for (int i = 0; i < 4; ++i) {
    const auto& a = rq.points[i];
    const auto& b = rq.points[i + 4];
    x[i].x.c[0] = a.x + T * (b.x - a.x);
    x[i].y.c[0] = a.y + T * (b.y - a.y);
    x[i].z.c[0] = a.z + T * (b.z - a.z);
  }
  auto sign_at = [](const predicates::FixedPoly<mpq_class, 0>& p) { return sgn(p.c[0]); };
  return rq.type == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

// ---- the comparison of one query -------------------------------------------------------------

struct Tally {
  std::uint64_t queries = 0, evaluations = 0, rational_checks = 0, pipeline_checks = 0;
  std::uint64_t fixed_coefficients = 0, gmp_values = 0, zero_signs = 0, contacts = 0;
  std::uint64_t brackets = 0;
};

/// Times at which the query is evaluated: the ends, the planted time, random ones, dyadic ones
/// of few bits, 1 - 2^-k, tiny ones (large k, down to the subnormal range).
std::vector<double> times_for(const DoubleQuery& q, Rng& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> t = {0.0, 1.0, unit(rng), unit(rng), unit(rng)};
  if (std::isfinite(q.planted_time)) t.push_back(q.planted_time);
  t.push_back(std::ldexp(static_cast<double>(rng() % 64), -6));
  t.push_back(std::ldexp(static_cast<double>(rng() % 4096), -12));
  t.push_back(1.0 - std::ldexp(1.0, -static_cast<int>(1 + rng() % 53)));
  t.push_back(std::ldexp(unit(rng), -static_cast<int>(rng() % 200)));
  t.push_back(std::ldexp(unit(rng) + 0.5, -static_cast<int>(200 + rng() % 874)));
  t.push_back(std::ldexp(static_cast<double>(1 + rng() % 7), -1074));  // subnormal
  return t;
}

void compare(const DoubleQuery& q, Rng& rng, bool rational, bool pipeline, Tally* tally) {
  const IntegerQuery fixed = q.type == QueryType::vertex_face ? IntegerQuery(q.vertex_face())
                                                              : IntegerQuery(q.edge_edge());
  const IntegerQuery gmp = q.type == QueryType::vertex_face
                               ? IntegerQuery(q.vertex_face(), IntegerQuery::Arithmetic::gmp)
                               : IntegerQuery(q.edge_edge(), IntegerQuery::Arithmetic::gmp);
  ++tally->queries;
  tally->fixed_coefficients += fixed.coefficient_limbs() != 0;
  ASSERT_EQ(fixed.coefficients(), gmp.coefficients()) << describe(q);
  ++tally->evaluations;
  const RationalQuery rq = rational_of(q);
  const std::vector<double> times = times_for(q, rng);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    ASSERT_EQ(fixed.scaled_value_at(t), gmp.scaled_value_at(t)) << "t = " << t << describe(q);
    const int s = fixed.cubic_sign_at(t);
    ASSERT_EQ(s, gmp.cubic_sign_at(t)) << "t = " << t << describe(q);
    tally->evaluations += 2;
    tally->gmp_values += fixed.value_limbs(t) == 0;
    tally->zero_signs += s == 0;
    // Contact tests at a few of the times (all of them where the cubic vanishes).
    if (s == 0 || i < 3 || i + 1 == times.size()) {
      const bool c = fixed.contact_at(t);
      ASSERT_EQ(c, gmp.contact_at(t)) << "t = " << t << describe(q);
      ++tally->evaluations;
      tally->contacts += c;
      if (rational && (s == 0 || i < 2)) {
        ASSERT_EQ(c, rational_contact(rq, t)) << "t = " << t << describe(q);
        ++tally->rational_checks;
      }
    }
    if (rational && i % 4 == 0) {
      ASSERT_EQ(s, rational_cubic_sign(rq, t)) << "t = " << t << describe(q);
      ++tally->rational_checks;
    }
  }
  // Guided bisection on the first sign change of a grid of [0, 1]: both arithmetics.
  int previous = fixed.cubic_sign_at(0.0);
  for (int k = 1; k <= 16 && previous != 0; ++k) {
    const double lo = (k - 1) / 16.0, hi = k / 16.0;
    const int s = fixed.cubic_sign_at(hi);
    if (s == 0) break;
    if (s == previous) continue;
    for (double width : {0.0, 1e-9}) {
      ASSERT_EQ(fixed.bisect_root(lo, hi, width), gmp.bisect_root(lo, hi, width)) << describe(q);
      ++tally->evaluations;
    }
    ++tally->brackets;
    break;
  }
  if (pipeline) {
    for (const CcdOptions& o : {CcdOptions{}, CcdOptions{0.5, 0.0, Mode::filtered}}) {
      const CcdResult d = ccd(q, o), e = ccd(q, with_mode(o, Mode::exact));
      ASSERT_EQ(d.collides, e.collides) << describe(o) << describe(q);
      if (e.collides) {
        ASSERT_EQ(d.toi_lo, e.toi_lo) << describe(o) << describe(q);
        ASSERT_EQ(d.toi_hi, e.toi_hi) << describe(o) << describe(q);
      }
      ++tally->pipeline_checks;
    }
  }
}

void print(const char* what, const Tally& t) {
  std::printf(
      "%-22s %7llu queries (%llu with fixed coefficients), %9llu evaluations compared, "
      "%7llu against rationals, %6llu pipeline checks; %llu values in GMP, %llu zero signs, "
      "%llu contacts, %llu brackets\n",
      what, static_cast<unsigned long long>(t.queries),
      static_cast<unsigned long long>(t.fixed_coefficients),
      static_cast<unsigned long long>(t.evaluations),
      static_cast<unsigned long long>(t.rational_checks),
      static_cast<unsigned long long>(t.pipeline_checks),
      static_cast<unsigned long long>(t.gmp_values), static_cast<unsigned long long>(t.zero_signs),
      static_cast<unsigned long long>(t.contacts), static_cast<unsigned long long>(t.brackets));
}

std::uint64_t count(std::uint64_t n) { return scaled_count(n, scale_from_environment()); }

TEST(ExactAtDoublesDifferential, RandomFamilies) {
  Tally tally;
  for (const Generator& g : all_generators()) {
    const std::uint64_t n = affordable_count(g, count(1500));
    for (std::uint64_t i = 0; i < n; ++i) {
      Rng rng;
      const DoubleQuery q = generate(g, test_seed(), i, rng);
      compare(q, rng, i % 8 == 0, false, &tally);
      if (HasFatalFailure()) return;
    }
  }
  print("random families", tally);
  // The three tests' shares add up to at least 1,000,000 evaluations (each runs alone under
  // ctest, so each checks its own).
  EXPECT_GE(tally.evaluations, count(600000));
  // Minimums shrink with the scale (sanitizer runs use a small one).
  EXPECT_GT(tally.zero_signs, count(1000));
  EXPECT_GT(tally.contacts, count(1000));
  EXPECT_GT(tally.brackets, count(1000));
}

TEST(ExactAtDoublesDifferential, RestingAndSlidingContact) {
  Rng rng(test_seed() + 1);
  Tally tally;
  const std::uint64_t n = count(10000);
  for (std::uint64_t i = 0; i < n; ++i) {
    DoubleQuery q = i % 2 ? resting_vertex_face(rng) : sliding_edge_edge(rng);
    if (i % 3 == 0) scale(&q, static_cast<int>(rng() % 120) - 60);
    compare(q, rng, i % 4 == 0, i % 16 == 0, &tally);
    if (HasFatalFailure()) return;
  }
  print("resting and sliding", tally);
  EXPECT_GE(tally.evaluations, count(300000));
  EXPECT_GT(tally.zero_signs, n);  // identically zero cubics, roots at t = 0
  EXPECT_GT(tally.contacts, n / 4);
  EXPECT_GT(tally.pipeline_checks, n / 16);
}

TEST(ExactAtDoublesDifferential, WideExponentSpreads) {
  Rng rng(test_seed() + 2);
  Tally tally;
  for (int spread : {10, 60, 120, 300, 1000}) {
    const std::uint64_t n = count(spread <= 120 ? 3000 : 800);
    for (std::uint64_t i = 0; i < n; ++i) {
      const QueryType type = i % 2 ? QueryType::edge_edge : QueryType::vertex_face;
      const DoubleQuery q = wide_spread(rng, type, spread);
      // The rational path on 1,000-bit integers is slow: a few pipeline checks per spread.
      compare(q, rng, i % 16 == 0, i % (spread <= 60 ? 32 : 200) == 0, &tally);
      if (HasFatalFailure()) return;
    }
  }
  print("wide exponent spreads", tally);
  EXPECT_GE(tally.evaluations, count(250000));
  // Both regimes are covered: coefficients in fixed width and in GMP.
  EXPECT_GT(tally.fixed_coefficients, 0u);
  EXPECT_LT(tally.fixed_coefficients, tally.queries);
  EXPECT_GT(tally.gmp_values, 0u);
}

}  // namespace
}  // namespace exactccd::test
