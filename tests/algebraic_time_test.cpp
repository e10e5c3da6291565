// Exact comparison of algebraic times and the width contract of AlgebraicTime::enclosure.
// PROOF: proofs/exact_ccd.md#lemma-sign-at-algebraic-time, proofs/exact_ccd.md#theorem-toi
#include <gtest/gtest.h>

#include <cmath>

#include "exact/algebraic_time.hpp"
#include "exact/root_isolation.hpp"

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
