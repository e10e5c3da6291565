// The exact stage's steps for widely spread exponents, against exact integer arithmetic written
// here or GMP: the sign of an integer polynomial at a quadratic irrational from enclosures
// (exact/polynomials/interval_sign_at_irrational.hpp), the square-free test by a residue of the
// discriminant (exact/polynomials/small_polynomial.hpp), integers without their trailing zero bits
// (exact/arithmetic/trimmed_integer.hpp), and the stage on such queries against the rational path.
// PROOF: proofs/exact_ccd.md#interval-sign-at-an-irrational
// PROOF: proofs/exact_ccd.md#square-free-by-a-residue
// PROOF: proofs/exact_ccd.md#trimmed-integers
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/predicates/fp_environment.hpp"
#include "corpus/random_queries.hpp"
#include "exact/stages/algebraic_at_doubles.hpp"
#include "exact/reference/exact_ccd.hpp"
#include "exact/stages/integer_query.hpp"
#include "exact/polynomials/interval_sign_at_irrational.hpp"
#include "exact/polynomials/small_polynomial.hpp"
#include "exact/arithmetic/trimmed_integer.hpp"
#include "integer_polynomial_support.hpp"
#include "test_scale.hpp"

namespace exactccd::exact {
namespace {

using test::random_integer;
using test::with_roots;

/// A random integer of at most `bits` bits whose set bits lie in a few islands far apart (the
/// shape of values computed from doubles of widely spread exponents).
mpz_class sparse_integer(std::mt19937_64& rng, int bits) {
  mpz_class z = 0;
  const int islands = 1 + static_cast<int>(rng() % 3);
  for (int i = 0; i < islands; ++i) {
    const int width = 1 + static_cast<int>(rng() % 60);
    const int shift = static_cast<int>(rng() % static_cast<unsigned>(std::max(1, bits - width)));
    z += random_integer(rng, width) << shift;
  }
  return z;
}

/// The exact sign of X + Y sqrt(D), D >= 0, written independently of the library.
int sign_of_sum_with_root(const mpz_class& X, const mpz_class& Y, const mpz_class& D) {
  if (sgn(Y) == 0 || sgn(D) == 0) return sgn(X);
  const mpz_class y2d = Y * Y * D, x2 = X * X;
  if (sgn(X) == sgn(Y) || sgn(X) == 0) return sgn(Y);
  return x2 > y2d ? sgn(X) : x2 < y2d ? sgn(Y) : 0;
}

/// The exact sign of p((P + tau sqrt(D)) / Q): Q^d p(s) = X + Y sqrt(D) with integers X, Y
/// from the powers of P + tau sqrt(D).
int exact_sign(const MpzPolynomial& p, const mpz_class& P, int tau, const mpz_class& D,
               const mpz_class& Q) {
  if (p.degree < 0) return 0;
  mpz_class X = 0, Y = 0, ux = 1, uy = 0;  // u^i = ux + uy sqrt(D)
  for (int i = 0; i <= p.degree; ++i) {
    mpz_class q_power = 1;
    for (int k = i; k < p.degree; ++k) q_power *= Q;
    X += p.c[static_cast<std::size_t>(i)] * ux * q_power;
    Y += p.c[static_cast<std::size_t>(i)] * uy * q_power;
    const mpz_class nx = ux * P + tau * uy * D, ny = tau * ux + uy * P;
    ux = nx;
    uy = ny;
  }
  const int q_sign = (sgn(Q) < 0 && p.degree % 2 == 1) ? -1 : 1;
  return q_sign * sign_of_sum_with_root(X, Y, D);
}

MpzPolynomial polynomial(std::vector<mpz_class> c) {
  MpzPolynomial p;
  for (std::size_t i = 0; i < c.size() && i < 4; ++i) p.c[i] = c[i];
  p.degree = -1;
  for (int i = 3; i >= 0; --i)
    if (sgn(p.c[static_cast<std::size_t>(i)]) != 0) {
      p.degree = i;
      break;
    }
  return p;
}

class IntervalSignAtIrrational : public ::testing::Test {
 protected:
  predicates::FpEnvironmentGuard nearest{predicates::Rounding::to_nearest};
};

// Random and sparse integers of 8 to 6000 bits; p of degree 0 to 3 of three kinds: random, a
// multiple of h = Q^2 t^2 - 2PQ t + (P^2 - D) (whose roots are the two irrationals) plus a
// small constant e (|p(s)| = |e|, far below p's terms), and such a multiple with e = 0 (p(s) =
// 0 exactly, which must be left undecided). Every decided sign equals the exact one.
TEST_F(IntervalSignAtIrrational, EqualsTheExactSignOrDeclines) {
  std::mt19937_64 rng(20261125);
  const int n = static_cast<int>(test::at_least(test::scaled_count(3000), 600));
  int decided = 0, near_zero_decided = 0, zeros = 0;
  for (int i = 0; i < n; ++i) {
    const int bits = 8 + static_cast<int>(rng() % 6000);
    auto integer = [&](int b) {
      return (rng() & 1) ? random_integer(rng, b) : sparse_integer(rng, b);
    };
    mpz_class P = integer(bits), Q = integer(bits), D = abs(integer(2 * bits));
    if (sgn(Q) == 0) Q = 1;
    const int tau = (rng() & 1) ? 1 : -1;
    const int kind = static_cast<int>(rng() % 3);
    MpzPolynomial p;
    if (kind == 0) {
      const int degree = static_cast<int>(rng() % 4);
      std::vector<mpz_class> c;
      for (int k = 0; k <= degree; ++k)
        c.push_back(integer(1 + static_cast<int>(rng() % (3 * bits))));
      p = polynomial(c);
    } else {
      const mpz_class h2 = Q * Q, h1 = -2 * P * Q, h0 = P * P - D;
      const mpz_class a = integer(1 + static_cast<int>(rng() % 64)),
                      b = integer(1 + static_cast<int>(rng() % 64));
      const mpz_class e = kind == 1
                              ? mpz_class(random_integer(rng, 1 + static_cast<int>(rng() % 8)))
                              : mpz_class(0);
      p = polynomial({h0 * b + e, h0 * a + h1 * b, h1 * a + h2 * b, h2 * a});
    }
    const int truth = exact_sign(p, P, tau, D, Q);
    const long max_bits = 128L << (2 * (rng() % 6));  // 128 .. 131072
    const std::optional<int> s = interval_sign_at_irrational(p, P, tau, D, Q, max_bits);
    if (truth == 0) {
      ++zeros;
      EXPECT_FALSE(s.has_value()) << "an exact zero decided as " << *s;
      continue;
    }
    if (!s) continue;
    ++decided;
    near_zero_decided += kind == 1;
    ASSERT_EQ(*s, truth) << "kind " << kind << " bits " << bits << " degree " << p.degree;
  }
  EXPECT_GT(decided, n / 3);
  EXPECT_GT(near_zero_decided, n / 20);
  EXPECT_GT(zeros, n / 10);
}

// A polynomial with a repeated root (rational, or the double root of an irreducible quadratic
// factor squared is beyond degree 3) is never called square-free; one with distinct roots is,
// except with probability about 2^-61 per polynomial; and each one called square-free has a
// constant gcd with its derivative (polynomial_gcd, independent of the residue).
TEST(SquareFreeByResidue, NeverClaimsARepeatedRootAndRecognisesDistinctOnes) {
  std::mt19937_64 rng(112025);
  const int n = static_cast<int>(test::at_least(test::scaled_count(2000), 400));
  int distinct = 0, claimed = 0;
  for (int i = 0; i < n; ++i) {
    const int bits = 1 + static_cast<int>(rng() % 2000);
    auto rational = [&]() {
      mpz_class den = abs(random_integer(rng, 1 + static_cast<int>(rng() % bits)));
      if (sgn(den) == 0) den = 1;
      return mpq_class(random_integer(rng, 1 + static_cast<int>(rng() % bits)), den);
    };
    mpz_class scale = random_integer(rng, 1 + static_cast<int>(rng() % 64));
    if (sgn(scale) == 0) scale = 1;
    std::vector<mpq_class> roots;
    const int degree = 2 + static_cast<int>(rng() % 2);
    const bool repeated = (rng() % 2) == 0;
    for (int k = 0; k < degree; ++k) roots.push_back(repeated && k > 0 ? roots[0] : rational());
    for (mpq_class& r : roots) r.canonicalize();
    SmallPolynomial p = with_roots(roots, scale);
    bool has_repeated = false;
    for (std::size_t a = 0; a < roots.size(); ++a)
      for (std::size_t b = a + 1; b < roots.size(); ++b)
        has_repeated = has_repeated || roots[a] == roots[b];
    if (!has_repeated && (rng() % 4) == 0) {  // an irreducible-looking cubic: random coefficients
      std::vector<mpz_class> c;
      for (int k = 0; k <= 3; ++k)
        c.push_back(random_integer(rng, 1 + static_cast<int>(rng() % bits)));
      if (sgn(c[3]) == 0) c[3] = 1;
      p = SmallPolynomial::from_mpz(c.data(), 4);
    }
    const bool said = square_free_by_residue(p);
    if (has_repeated) {
      EXPECT_FALSE(said) << "a repeated root called square-free";
      continue;
    }
    const MpzPolynomial m = to_mpz_polynomial(p);
    MpzPolynomial derivative;
    for (int k = 1; k <= m.degree; ++k)
      derivative.c[static_cast<std::size_t>(k - 1)] = m.c[static_cast<std::size_t>(k)] * k;
    derivative.degree = m.degree - 1;
    const bool gcd_constant = polynomial_gcd(m, derivative).degree == 0;
    if (!gcd_constant) {
      EXPECT_FALSE(said);
      continue;
    }
    ++distinct;
    claimed += said;
  }
  EXPECT_GT(distinct, n / 3);
  EXPECT_EQ(claimed, distinct) << "distinct roots left to the gcd (a 2^-61 event each)";
}

// The stage at double brackets on widely spread exponents, where both new steps run: with and
// without the filter's IntegerQuery (whose GMP cubic it then reuses), against the rational
// path; the enclosures must have been tried and must have decided some signs.
TEST(WideExponentStage, AgreesWithTheRationalPathAndUsesTheEnclosures) {
  predicates::FpEnvironmentGuard nearest{predicates::Rounding::to_nearest};
  using random_queries::Family;
  const IntervalIrrationalCounts before = interval_irrational_counts_in_this_thread();
  const std::uint64_t n = test::at_least(test::scaled_count(40), 12);
  int reused = 0;
  for (const Family family : {Family::wide_exponent_300, Family::wide_exponent_1000})
    for (const QueryType type : {QueryType::vertex_face, QueryType::edge_edge})
      for (std::uint64_t i = 0; i < n; ++i) {
        const random_queries::DoubleQuery q =
            random_queries::generate_unscaled(random_queries::Generator{family, type}, 7, i);
        CcdOptions o;
        o.toi_width = 0;
        const bool vf = type == QueryType::vertex_face;
        const IntegerQuery known = vf ? IntegerQuery(q.vertex_face()) : IntegerQuery(q.edge_edge());
        reused += known.coefficient_limbs() == 0;
        const auto fresh = vf ? vertex_face_ccd_at_doubles(q.vertex_face(), o)
                              : edge_edge_ccd_at_doubles(q.edge_edge(), o);
        const auto with_known = vf ? vertex_face_ccd_at_doubles(q.vertex_face(), o, &known)
                                   : edge_edge_ccd_at_doubles(q.edge_edge(), o, &known);
        const CcdResult ref = vf ? vertex_face_ccd_exact(to_rational(q.vertex_face()), o)
                                 : edge_edge_ccd_exact(to_rational(q.edge_edge()), o);
        ASSERT_TRUE(fresh && with_known);
        for (const CcdResult& r : {*fresh, *with_known}) {
          ASSERT_EQ(r.collides, ref.collides) << "query " << i;
          if (ref.collides) {
            EXPECT_EQ(r.toi_lo, ref.toi_lo);
            EXPECT_EQ(r.toi_hi, ref.toi_hi);
          }
        }
      }
  const IntervalIrrationalCounts after = interval_irrational_counts_in_this_thread();
  EXPECT_GT(reused, 0);
  EXPECT_GT(after.attempts, before.attempts);
  EXPECT_GT(after.decided, before.decided);
}

// Every operation of TrimmedInteger against mpz_class: random 1- to 64-bit odd parts shifted by
// 0 to 3,000 bits (and zeros), sums, differences, products and fused products, chained so that
// cancellations to 0 and to short values occur.
TEST(TrimmedIntegers, ArithmeticEqualsMpz) {
  std::mt19937_64 rng(77);
  const int n = static_cast<int>(test::at_least(test::scaled_count(20000), 4000));
  int zeros = 0;
  auto random_value = [&](TrimmedInteger* t, mpz_class* z) {
    if (rng() % 8 == 0) {
      *t = TrimmedInteger();
      *z = 0;
      return;
    }
    const auto m = static_cast<std::int64_t>(rng() >> (rng() % 63 + 1)) * ((rng() & 1) ? 1 : -1);
    const unsigned shift = static_cast<unsigned>(rng() % 3000);
    *t = TrimmedInteger::scaled(m, shift);
    *z = mpz_class(static_cast<long>(m)) << shift;
  };
  TrimmedInteger acc;
  mpz_class acc_z = 0;
  for (int i = 0; i < n; ++i) {
    TrimmedInteger a, b;
    mpz_class az, bz;
    random_value(&a, &az);
    random_value(&b, &bz);
    switch (rng() % 6) {
      case 0:
        acc += a;
        acc_z += az;
        break;
      case 1:
        acc -= a;
        acc_z -= az;
        break;
      case 2:
        acc = acc * a;
        acc_z *= az;
        break;
      case 3:
        add_product(acc, a, b);
        acc_z += az * bz;
        break;
      case 4:
        sub_product(acc, a, b);
        acc_z -= az * bz;
        break;
      default: {  // cancel exactly, or nearly
        const TrimmedInteger copy = acc;
        acc -= copy;
        acc_z = 0;
        if (rng() & 1) {
          acc += a;
          acc_z += az;
        }
      }
    }
    ASSERT_EQ(acc.to_mpz(), acc_z) << "step " << i;
    ASSERT_EQ(acc.sign(), sgn(acc_z));
    if (acc.sign() != 0) ASSERT_TRUE(mpz_odd_p(acc.odd_part().get_mpz_t()));  // trimmed
    zeros += acc.sign() == 0;
    if (mpz_sizeinbase(acc_z.get_mpz_t(), 2) > 20000) {  // keep the values short
      acc = TrimmedInteger();
      acc_z = 0;
    }
  }
  EXPECT_GT(zeros, n / 50);
}

// The cubic formed in TrimmedInteger equals the one formed in mpz_class, on every generator's
// queries (wide spreads, subnormals, coincident points, zeros).
TEST(TrimmedIntegers, CubicEqualsTheMpzCubic) {
  const std::uint64_t n = test::at_least(test::scaled_count(200), 40);
  int checked = 0;
  for (const random_queries::Generator& g : random_queries::all_generators())
    for (std::uint64_t i = 0; i < n; ++i) {
      const random_queries::DoubleQuery q = random_queries::generate(g, 11, i);
      const IntegerCoordinates c = q.type == QueryType::vertex_face
                                       ? integer_coordinates(q.vertex_face())
                                       : integer_coordinates(q.edge_edge());
      mpz_class plain[4];
      TrimmedInteger trimmed[4];
      coplanarity_coefficients(c, plain);
      coplanarity_coefficients(c, trimmed);
      for (int k = 0; k < 4; ++k)
        ASSERT_EQ(trimmed[k].to_mpz(), plain[k]) << g.name() << " #" << i << " coefficient " << k;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace exactccd::exact
