// The retry of the cubic filter with the cubic from its exact coefficients
// (proofs/filters.md#exact-cubic-retry): the leading bits of an exact integer, the enclosures of
// the scaled exact coefficients, and queries whose interval cubic cannot isolate its roots
// (motions far smaller than the coordinates), which the retry decides as the exact path does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/predicates/coplanarity_cubic.hpp"
#include "corpus/random_queries.hpp"
#include "exact/stages/integer_query.hpp"
#include "filters/cubic_filter.hpp"
#include "core/predicates/interval.hpp"
#include "fixed_int_support.hpp"
#include "test_support.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

using exact::FixedInt;
using exact::IntegerQuery;
using exact::LeadingBits;

/// A random integer of random sign and a random bit length in [0, max_bits], often with long
/// runs of zero bits below its leading ones (exact in 53 bits), sometimes not.
mpz_class random_integer(std::mt19937_64& rng, int max_bits) {
  const int bits = std::uniform_int_distribution<int>(0, max_bits)(rng);
  mpz_class z = 0;
  for (int done = 0; done < bits; done += 64) z = (z << 64) + exact::mpz_from_u64(rng());
  if (bits > 0) z >>= static_cast<unsigned>((bits + 63) / 64 * 64 - bits);
  if (bits > 0) mpz_setbit(z.get_mpz_t(), static_cast<mp_bitcnt_t>(bits - 1));
  if (bits > 53 && rng() % 3 == 0) {  // clear everything below the leading 53 bits (or fewer)
    const auto keep = static_cast<unsigned>(std::uniform_int_distribution<int>(1, 53)(rng));
    z = (z >> (static_cast<unsigned>(bits) - keep)) << (static_cast<unsigned>(bits) - keep);
  }
  return rng() % 2 ? mpz_class(-z) : z;
}

/// |z| = m 2^e + r, 0 <= r < 2^e, m < 2^53 (and m >= 2^52 when e > 0), inexact = (r != 0).
void expect_leading_bits_of(const mpz_class& z, const LeadingBits& b) {
  const mpz_class a = abs(z);
  ASSERT_LT(b.m, std::uint64_t{1} << 53);
  ASSERT_GE(b.e, 0);
  if (b.e > 0) ASSERT_GE(b.m, std::uint64_t{1} << 52);
  const mpz_class high = exact::mpz_from_u64(b.m) << static_cast<unsigned>(b.e);
  const mpz_class r = a - high;
  ASSERT_GE(r, 0) << z.get_str();
  ASSERT_LT(r, mpz_class(1) << static_cast<unsigned>(b.e)) << z.get_str();
  ASSERT_EQ(b.inexact, r != 0) << z.get_str();
}

template <int N>
void check_leading_bits(std::mt19937_64& rng, int rounds) {
  SCOPED_TRACE("N = " + std::to_string(N));
  for (int i = 0; i < rounds; ++i) {
    const mpz_class z = random_integer(rng, 64 * N - 2);
    expect_leading_bits_of(z, exact::leading_bits(fixed_from<N>(z)));
    expect_leading_bits_of(z, exact::leading_bits(z));
    const LeadingBits f = exact::leading_bits(fixed_from<N>(z)), g = exact::leading_bits(z);
    ASSERT_EQ(f.m, g.m);
    ASSERT_EQ(f.e, g.e);
    ASSERT_EQ(f.inexact, g.inexact);
  }
}

TEST(LeadingBits, MatchTheIntegerInFixedWidthsAndGmp) {
  std::mt19937_64 rng(test_seed("leading bits"));
  const int rounds = static_cast<int>(scaled_count(2000, scale_from_environment()));
  check_leading_bits<1>(rng, rounds);
  check_leading_bits<2>(rng, rounds);
  check_leading_bits<3>(rng, rounds);
  check_leading_bits<6>(rng, rounds);
  check_leading_bits<16>(rng, rounds);
  expect_leading_bits_of(0, exact::leading_bits(FixedInt<2>(0)));
  EXPECT_EQ(exact::leading_bits(FixedInt<2>(0)).m, 0u);
  EXPECT_EQ(exact::leading_bits(mpz_class(0)).m, 0u);
}

/// The bit length of |z| (0 for z = 0).
long bit_length(const mpz_class& z) { return exact::bit_length(z); }

/// The scaled bounds enclose c_i 2^-s (s the largest bit length), are points exactly when c_i
/// has at most 53 significant bits, else one unit of the 53rd bit apart.
void expect_enclosures(const IntegerQuery& q, const std::string& where) {
  const auto c = q.coefficients();
  double lo[4], hi[4];
  q.scaled_coefficient_bounds(lo, hi);
  long s = 0;
  bool any = false;
  for (const mpz_class& ci : c)
    if (ci != 0) s = any ? std::max(s, bit_length(ci)) : bit_length(ci), any = true;
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(where + ", coefficient " + std::to_string(i));
    ASSERT_TRUE(std::isfinite(lo[i]) && std::isfinite(hi[i]));
    ASSERT_LE(lo[i], hi[i]);
    const mpq_class exact = mpq_class(c[i]) / pow2(static_cast<int>(s));
    ASSERT_LE(mpq_class(lo[i]), exact);
    ASSERT_GE(mpq_class(hi[i]), exact);
    if (c[i] == 0) {
      EXPECT_EQ(lo[i], 0.0);
      EXPECT_EQ(hi[i], 0.0);
      continue;
    }
    EXPECT_LT(abs(exact), 1);
    const long significant =
        bit_length(c[i]) - static_cast<long>(mpz_scan1(c[i].get_mpz_t(), 0));
    if (significant <= 53 && s - bit_length(c[i]) < 1000) {
      EXPECT_EQ(lo[i], hi[i]);
    } else if (s - bit_length(c[i]) < 1000) {
      EXPECT_EQ(std::nextafter(lo[i], hi[i]), hi[i]);  // adjacent doubles
    }
  }
  if (any) {
    double largest = 0;
    for (int i = 0; i < 4; ++i) largest = std::max({largest, std::fabs(lo[i]), std::fabs(hi[i])});
    EXPECT_GE(largest, 0.5);
    EXPECT_LE(largest, 1.0);
  }
}

TEST(ScaledCoefficientBounds, EncloseTheExactCoefficients) {
  const std::uint64_t seed = test_seed("coefficient bounds");
  const std::uint64_t n = scaled_count(300, scale_from_environment());
  std::size_t inexact_seen = 0, checked = 0;
  for (const Generator& g : all_generators()) {
    for (std::uint64_t i = 0; i < n; ++i) {
      const DoubleQuery q = generate(g, seed, i);
      for (auto a : {IntegerQuery::Arithmetic::fixed_first, IntegerQuery::Arithmetic::gmp}) {
        const IntegerQuery iq = q.type == QueryType::vertex_face ? IntegerQuery(q.vertex_face(), a)
                                                                 : IntegerQuery(q.edge_edge(), a);
        expect_enclosures(iq, std::string(to_string(g.family)) + " #" + std::to_string(i));
        if (HasFatalFailure()) return;
        double lo[4], hi[4];
        iq.scaled_coefficient_bounds(lo, hi);
        for (int k = 0; k < 4; ++k) inexact_seen += lo[k] != hi[k];
        ++checked;
      }
    }
  }
  EXPECT_GT(inexact_seen, 0u) << "no coefficient needed more than 53 bits";
  std::printf("%zu queries, %zu inexact enclosures\n", checked, inexact_seen);
}

// ---- the retry on queries whose interval cubic cannot isolate its roots ---------------------

/// Inclusion tests that never decide: the filter then relies on isolating the cubic's roots.
struct NeverDecides {
  bool excluded(const predicates::Interval&) const { return false; }
  bool excluded_in_leading_projection(const predicates::Interval&) const { return false; }
  bool certainly_included(const predicates::Interval&) const { return false; }
};

struct IntegerOracle final : filters::ContactExactStage {
  explicit IntegerOracle(const IntegerQuery& q) : q_(q) {}
  int cubic_sign_at(double t) override { return q_.cubic_sign_at(t); }
  bool contact_at(double t) override { return q_.contact_at(t); }
  std::pair<double, double> bisect_root(double lo, double hi) override {
    return q_.bisect_root(lo, hi, 0.0);
  }
  void cubic_coefficient_bounds(double (&lo)[4], double (&hi)[4]) override {
    q_.scaled_coefficient_bounds(lo, hi);
  }

 private:
  const IntegerQuery& q_;
};

using IntervalCubic = predicates::FixedPoly<predicates::Interval, 3>;

IntervalCubic interval_cubic(const DoubleQuery& q) {
  using predicates::Interval;
  predicates::MovingPoint<Interval> m[4];
  for (int i = 0; i < 4; ++i)
    m[i] = predicates::linear_motion(
        predicates::Vec3<Interval>{q.v[i].x(), q.v[i].y(), q.v[i].z()},
        predicates::Vec3<Interval>{q.v[i + 4].x(), q.v[i + 4].y(), q.v[i + 4].z()});
  return q.type == QueryType::vertex_face
             ? predicates::vertex_face_coplanarity_cubic(m[0], m[1], m[2], m[3])
             : predicates::edge_edge_coplanarity_cubic(m[0], m[1], m[2], m[3]);
}

IntervalCubic exact_cubic(const IntegerQuery& q) {
  double lo[4], hi[4];
  q.scaled_coefficient_bounds(lo, hi);
  IntervalCubic c;
  for (int i = 0; i < 4; ++i) c.c[i] = predicates::Interval(lo[i], hi[i]);
  return c;
}

/// The scene and sample queries, as double queries.
std::vector<DoubleQuery> data_set_queries() {
  std::vector<DoubleQuery> out;
  for (const char* set : {"/scene-queries", "/sample-queries"})
    for (const std::string& path : find_query_files(std::string(EXACTCCD_TEST_DATA) + set)) {
      const auto type = query_type_from_path(path);
      if (!type) continue;
      for (const QueryRecord& r : read_query_file(path, *type).queries) {
        DoubleQuery q;
        q.type = *type;
        for (int i = 0; i < 8; ++i) q.v[i] = to_vector(r.query.points[i]);
        out.push_back(q);
      }
    }
  return out;
}

TEST(ExactCubicRetry, IsolatesRootsWhereTheIntervalCubicCannot) {
  std::size_t unresolved = 0, resolved_by_exact_cubic = 0, decided_without_rationals = 0;
  const CcdOptions options;
  for (const DoubleQuery& q : data_set_queries()) {
    const IntegerQuery iq =
        q.type == QueryType::vertex_face ? IntegerQuery(q.vertex_face()) : IntegerQuery(q.edge_edge());
    IntegerOracle oracle(iq);
    bool interval_unresolved = false, exact_unresolved = false;
    {
      const predicates::RoundingGuard guard;
      const IntervalCubic wide = interval_cubic(q);
      if (filters::coplanarity_cubic_root_free_interval(wide, 1.0)) continue;
      interval_unresolved =
          filters::cubic_filter(wide, 1.0, 0.0, NeverDecides{}, oracle).roots_unresolved;
      if (!interval_unresolved) continue;
      exact_unresolved =
          filters::cubic_filter(exact_cubic(iq), 1.0, 0.0, NeverDecides{}, oracle).roots_unresolved;
    }
    ++unresolved;
    if (!exact_unresolved) ++resolved_by_exact_cubic;
    // The pipeline (which retries) against the exact path: verdict and TOI bits.
    const CcdResult d = ccd(q, options), e = ccd(q, with_mode(options, Mode::exact));
    EXPECT_EQ(d.collides, e.collides);
    if (d.collides && e.collides) {
      EXPECT_EQ(d.toi_lo, e.toi_lo);
      EXPECT_EQ(d.toi_hi, e.toi_hi);
    }
    if (d.decided_by != Stage::exact) ++decided_without_rationals;
  }
  std::printf("%zu queries whose interval cubic leaves roots unresolved: %zu isolated by the "
              "exact cubic, %zu decided before the exact path\n",
              unresolved, resolved_by_exact_cubic, decided_without_rationals);
  EXPECT_GT(unresolved, 0u) << "the data sets no longer exercise the retry";
  EXPECT_GT(resolved_by_exact_cubic, 0u);
  EXPECT_GT(decided_without_rationals, 0u);
}

}  // namespace
}  // namespace exactccd::test
