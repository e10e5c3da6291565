// Exact comparison of algebraic times and the width contract of AlgebraicTime::enclosure.
// PROOF: proofs/exact_ccd.md#lemma-sign-at-algebraic-time, proofs/exact_ccd.md#theorem-toi
#include <gtest/gtest.h>

#include <cmath>

#include "exact/polynomials/algebraic_time.hpp"
#include "exact/polynomials/root_isolation.hpp"

namespace {

using exactccd::exact::AlgebraicTime;
using exactccd::exact::Polynomial;
using exactccd::exact::Rational;

Polynomial poly(std::vector<Rational> c) { return Polynomial(std::move(c)); }

// The root of p in (lo, hi) (unique there by construction in each test).
AlgebraicTime root_in(const Polynomial& p, Rational lo, Rational hi) {
  auto roots = exactccd::exact::real_roots_in(p, lo, hi);
  EXPECT_EQ(roots.size(), 1u);
  return roots.front();
}

TEST(AlgebraicTimeCompare, EqualIrrationalTimesFromDifferentPolynomials) {
  // sqrt(2)/2 as a root of 2t^2 - 1 and of (2t^2 - 1)(t - 1/4) = 2t^3 - t^2/2 - t + 1/4.
  AlgebraicTime a = root_in(poly({-1, 0, 2}), Rational(1, 2), 1);
  AlgebraicTime b = root_in(poly({Rational(1, 4), -1, Rational(-1, 2), 2}), Rational(1, 2), 1);
  EXPECT_EQ(compare(a, b), 0);
  EXPECT_EQ(compare(b, a), 0);
}

TEST(AlgebraicTimeCompare, DistinctRootsCloserThanOneUlp) {
  // sqrt(2)/2 against q = a rational within 2^-70 of it, as the root of t - q.
  AlgebraicTime a = root_in(poly({-1, 0, 2}), Rational(1, 2), 1);
  mpq_class q(std::sqrt(0.5));  // a double near sqrt(2)/2
  const mpq_class tiny(mpz_class(1), mpz_class(1) << 70);
  // Exactly: is q^2 < 1/2 ? Then q < sqrt(2)/2.
  const bool q_below = cmp(q * q, Rational(1, 2)) < 0;
  // Move 2^-70 towards the root; the side it ends on is decided independently by squaring.
  const Rational near = q_below ? Rational(q + tiny) : Rational(q - tiny);
  const bool near_below = cmp(near * near, Rational(1, 2)) < 0;
  AlgebraicTime b = AlgebraicTime::rational(near);
  EXPECT_EQ(compare(a, b), near_below ? 1 : -1);
  // Two irrational roots 2^-70 apart: sqrt(2)/2 and sqrt(2)/2 + 2^-70, roots of
  // 2t^2 - 1 and 2(t - 2^-70)^2 - 1.
  const Polynomial shifted = poly({2 * tiny * tiny - 1, -4 * tiny, 2});
  AlgebraicTime c = root_in(shifted, Rational(1, 2), 1);
  EXPECT_EQ(compare(a, c), -1);
  EXPECT_EQ(compare(c, a), 1);
}

TEST(AlgebraicTimeEnclosure, WidthBoundHoldsExactly) {
  // t = 1/3 isolated in (2^-54, 1/2 + 2^-53): the double difference of the rounded ends is 0.5
  // although the exact one exceeds it; the enclosure must refine further.
  AlgebraicTime t(poly({Rational(-1, 3), 1}), Rational(std::ldexp(1.0, -54)),
                  Rational(0.5) + Rational(std::ldexp(1.0, -53)));
  const auto [lo, hi] = t.enclosure(0.5);
  EXPECT_LE(cmp(Rational(hi) - Rational(lo), Rational(0.5)), 0);
  EXPECT_LT(cmp(Rational(lo), Rational(1, 3)), 0);
  EXPECT_GT(cmp(Rational(hi), Rational(1, 3)), 0);
}

}  // namespace

namespace sign_in_quadratic_field {

/// P + Q sqrt(m) with rational P, Q and m > 0: its exact sign.
int sign_plus_sqrt(const Rational& P, const Rational& Q, const Rational& m) {
  const int sp = sgn(P), sq = sgn(Q);
  if (sq == 0) return sp;
  if (sp == 0 || sp == sq) return sq;
  return sgn(P * P - Q * Q * m) * sp;  // opposite signs: the larger square wins
}

/// g(sqrt(m) / k) as P + Q sqrt(m), exactly, independently of the exact path.
int sign_at_root(const Polynomial& g, const Rational& m, long k) {
  Rational P = 0, Q = 0, even = 1;  // even = (m / k^2)^j
  const Rational m_over_k2 = m / (k * k);
  const auto& c = g.coefficients();
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i % 2 == 0) {
      P += c[i] * even;
    } else {
      Q += c[i] * even / k;
      even *= m_over_k2;
    }
  }
  return sign_plus_sqrt(P, Q, m);
}

}  // namespace sign_in_quadratic_field

// PROOF: proofs/exact_ccd.md#lemma-sign-at-algebraic-time
// AlgebraicTime::sign_of (integer pseudo-remainders and Descartes' rule on dyadic intervals)
// at irrational roots sqrt(m) / k of f = (k^2 t^2 - m) h, against arithmetic in Q(sqrt(m)):
// random g of degree 0-7, g sharing the root (zero), g with a rational root 2^-60 or 2^-200
// away (tiny values), rational and integer coefficients.
TEST(AlgebraicTimeSign, SignOfEqualsArithmeticInTheQuadraticField) {
  gmp_randclass rng(gmp_randinit_default);
  rng.seed(424242);
  int zeros = 0, checks = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const long k = 2 + trial % 7;
    long m = 1 + static_cast<long>(mpz_class(rng.get_z_range(k * k - 1)).get_si());
    const long root = static_cast<long>(std::sqrt(static_cast<double>(m)));
    if (root * root == m) ++m;  // not a square (m + 1 below k^2 is not one either: m < k^2)
    if (m >= k * k) continue;
    const Polynomial quadratic = poly({Rational(-m), 0, Rational(k * k)});
    // h: a rational root and a quadratic without real roots, so the roots in [0, 1] are known.
    const Rational other(1 + trial % 5, 7);
    const Polynomial f = quadratic * poly({-other, 1}) * poly({1, 0, 1});
    auto roots = exactccd::exact::real_roots_in(f, 0, 1);
    ASSERT_EQ(roots.size(), 2u);
    // The one at sqrt(m) / k: lo^2 < m / k^2 < hi^2 (the other is `other`).
    const Rational r2(m, k * k);
    auto holds_root = [&](const AlgebraicTime& x) {
      return !x.is_rational() && cmp(x.lo() * x.lo(), r2) < 0 && cmp(r2, x.hi() * x.hi()) < 0;
    };
    ASSERT_NE(holds_root(roots[0]), holds_root(roots[1]));
    AlgebraicTime& t = holds_root(roots[0]) ? roots[0] : roots[1];
    for (int j = 0; j < 6; ++j) {
      std::vector<Rational> c;
      const int degree = static_cast<int>(mpz_class(rng.get_z_range(8)).get_si());
      for (int i = 0; i <= degree; ++i) {
        c.emplace_back(rng.get_z_bits(80) - rng.get_z_bits(80),
                       j % 2 ? mpz_class(1) : mpz_class(rng.get_z_bits(30) + 1));
        c.back().canonicalize();
      }
      Polynomial g(c);
      if (j == 2) g = g * quadratic;  // vanishes at the root
      if (j == 3 || j == 4) {  // a rational root s within 2^-60 (2^-200) of sqrt(m) / k
        const int bits = j == 3 ? 60 : 200;
        mpz_class s_num;
        mpz_class m_scaled = mpz_class(m) << (2 * bits);
        mpz_sqrt(s_num.get_mpz_t(), m_scaled.get_mpz_t());
        Rational s(s_num, mpz_class(k) << bits);
        s.canonicalize();
        g = g * poly({-s, 1});
      }
      const int expected = g.is_zero() ? 0 : sign_in_quadratic_field::sign_at_root(g, m, k);
      EXPECT_EQ(t.sign_of(g), expected) << "trial " << trial << " j " << j;
      // The same time defined by -f (a negative leading coefficient: pseudo-remainders by it
      // carry the sign of lc^e).
      AlgebraicTime negated(-t.defining_polynomial(), t.lo(), t.hi());
      EXPECT_EQ(negated.sign_of(g), expected) << "trial " << trial << " j " << j << " (-f)";
      zeros += expected == 0;
      ++checks;
    }
  }
  EXPECT_GT(checks, 1500);
  EXPECT_GT(zeros, checks / 8);
}
