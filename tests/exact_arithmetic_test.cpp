// Unit tests of the exact arithmetic under the exact path: rational polynomials
// (exact/polynomials/polynomial.hpp), real root isolation (exact/polynomials/root_isolation.hpp),
// signs at algebraic times (exact/polynomials/algebraic_time.hpp) and the exact relation of
// rationals to doubles (exact/arithmetic/rational.hpp). Expected values are worked out by hand in
// the comments.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact/polynomials/algebraic_time.hpp"
#include "exact/polynomials/polynomial.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exact/polynomials/root_isolation.hpp"

namespace exactccd::exact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();  // 2^-1074

Rational q(long n, long d = 1) {
  Rational r(n, d);
  r.canonicalize();
  return r;
}

Rational pow2(int e) {
  Rational r(1);
  if (e >= 0) mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(e));
  else mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(-e));
  return r;
}

/// The polynomial c[0] + c[1] t + ...
Polynomial P(std::vector<Rational> c) { return Polynomial(std::move(c)); }

/// t - r
Polynomial linear(const Rational& r) { return P({-r, 1}); }

std::string str(const Polynomial& p) {
  std::string s;
  for (std::size_t i = 0; i < p.coefficients().size(); ++i)
    s += (i ? " + " : "") + p.coefficients()[i].get_str() + " t^" + std::to_string(i);
  return s.empty() ? "0" : s;
}

void expect_poly_eq(const Polynomial& got, const Polynomial& expected) {
  EXPECT_EQ(got.coefficients(), expected.coefficients())
      << "got " << str(got) << ", expected " << str(expected);
}

/// e = (lo, hi) are consecutive doubles with lo < x < hi, for a value x known only through the
/// signs of lo - x and hi - x (computed by the caller, exactly).
void expect_tightest_pair(std::pair<double, double> e, int sign_lo_minus_x,
                          int sign_hi_minus_x) {
  EXPECT_LT(sign_lo_minus_x, 0) << "lo " << e.first << " is not below the value";
  EXPECT_GT(sign_hi_minus_x, 0) << "hi " << e.second << " is not above the value";
  EXPECT_EQ(std::nextafter(e.first, kInf), e.second) << "not consecutive doubles";
}

// ---------------------------------------------------------------------------------------------
// Polynomial

TEST(Polynomial, TrimsTrailingZerosAndEvaluatesExactly) {
  const Polynomial p = P({1, 2, 0, 0});
  EXPECT_EQ(p.degree(), 1);
  EXPECT_TRUE(P({0, 0}).is_zero());
  EXPECT_EQ(P({}).degree(), -1);
  // t^2 - 2 at 3/2: 9/4 - 2 = 1/4.
  EXPECT_EQ(P({-2, 0, 1}).evaluate(q(3, 2)), q(1, 4));
  EXPECT_EQ(P({-2, 0, 1}).sign_at(q(3, 2)), 1);
  // (d/dt) (1 + t + t^3/3) = 1 + t^2.
  expect_poly_eq(P({1, 1, 0, q(1, 3)}).derivative(), P({1, 0, 1}));
  expect_poly_eq(P({4, 2}).monic(), P({2, 1}));
}

TEST(Polynomial, TaylorShift) {
  // (1/2 + s)^2 = 1/4 + s + s^2.
  expect_poly_eq(P({0, 0, 1}).taylor_shift(q(1, 2)), P({q(1, 4), 1, 1}));
  // (s - 1)^3 = -1 + 3s - 3s^2 + s^3 from t^3 shifted by -1.
  expect_poly_eq(P({0, 0, 0, 1}).taylor_shift(-1), P({-1, 3, -3, 1}));
}

TEST(Polynomial, DivisionWithoutRemainder) {
  // t^3 - 2t + 1 = (t - 1)(t^2 + t - 1).
  Polynomial quotient, remainder;
  divide(P({1, -2, 0, 1}), linear(1), &quotient, &remainder);
  expect_poly_eq(quotient, P({-1, 1, 1}));
  EXPECT_TRUE(remainder.is_zero());
}

TEST(Polynomial, DivisionWithRemainder) {
  // t^3 + 2 = (2t^2 + 1)(t/2) + (2 - t/2).
  Polynomial quotient, remainder;
  divide(P({2, 0, 0, 1}), P({1, 0, 2}), &quotient, &remainder);
  expect_poly_eq(quotient, P({0, q(1, 2)}));
  expect_poly_eq(remainder, P({2, q(-1, 2)}));
  // Dividend of lower degree: quotient 0, remainder the dividend.
  divide(P({1, 1}), P({1, 0, 1}), &quotient, &remainder);
  EXPECT_TRUE(quotient.is_zero());
  expect_poly_eq(remainder, P({1, 1}));
  // Constant divisor: exact quotient, zero remainder.
  divide(P({1, 2, 3}), P({2}), &quotient, &remainder);
  expect_poly_eq(quotient, P({q(1, 2), 1, q(3, 2)}));
  EXPECT_TRUE(remainder.is_zero());
  EXPECT_THROW(divide(P({1, 1}), Polynomial(), &quotient, &remainder), std::domain_error);
}

TEST(Polynomial, DivisionIdentity) {
  // a = q b + r with deg r < deg b, for a few dividends and divisors of mixed degrees.
  const std::vector<Polynomial> polys = {P({q(3, 7), -2, 5, q(-1, 3), 4, 1}), P({1, q(2, 9), 3}),
                                         P({-5, q(1, 11)}), P({q(7, 2), 0, 0, -1})};
  for (const auto& a : polys) {
    for (const auto& b : polys) {
      Polynomial quotient, remainder;
      divide(a, b, &quotient, &remainder);
      EXPECT_LT(remainder.degree(), b.degree());
      Polynomial sum = quotient * b;
      std::vector<Rational> c(std::max(sum.coefficients().size(), remainder.coefficients().size()));
      for (std::size_t i = 0; i < c.size(); ++i) {
        if (i < sum.coefficients().size()) c[i] += sum.coefficients()[i];
        if (i < remainder.coefficients().size()) c[i] += remainder.coefficients()[i];
      }
      expect_poly_eq(P(c), a);
    }
  }
}

TEST(Polynomial, GcdOfCoprimePolynomials) {
  expect_poly_eq(gcd(P({1, 0, 1}), linear(1)), P({1}));          // t^2 + 1, t - 1
  expect_poly_eq(gcd(linear(q(1, 3)), linear(q(1, 2))), P({1}));  // distinct roots
}

TEST(Polynomial, GcdWithCommonFactors) {
  // (t - 1/3)(t + 2) and (t - 1/3)(t^2 + 5): t - 1/3.
  expect_poly_eq(gcd(linear(q(1, 3)) * linear(-2), linear(q(1, 3)) * P({5, 0, 1})),
                 linear(q(1, 3)));
  // (2t^2 - 1)(t - 1) and 3 (2t^2 - 1)(t + 3)^2: the monic t^2 - 1/2.
  const Polynomial f = P({-1, 0, 2});
  expect_poly_eq(gcd(f * linear(1), P({3}) * f * linear(-3) * linear(-3)), P({q(-1, 2), 0, 1}));
  // With the zero polynomial: the monic other one.
  expect_poly_eq(gcd(P({2, 4}), Polynomial()), P({q(1, 2), 1}));
  expect_poly_eq(gcd(Polynomial(), P({2, 4})), P({q(1, 2), 1}));
  EXPECT_TRUE(gcd(Polynomial(), Polynomial()).is_zero());
}

TEST(Polynomial, PrimitivePartIsAPositiveIntegerMultiple) {
  // (-4/3, 2/9, 0, 8/15) -> lcm 45: (-60, 10, 0, 24) -> content 2: (-30, 5, 0, 12).
  expect_poly_eq(primitive_part(P({q(-4, 3), q(2, 9), 0, q(8, 15)})), P({-30, 5, 0, 12}));
  expect_poly_eq(primitive_part(P({q(-1, 2)})), P({1}) * P({-1}));  // the sign is kept
  EXPECT_TRUE(primitive_part(Polynomial()).is_zero());
}

/// sign_at (integer arithmetic for integer coefficients, shifts for dyadic times) against the
/// sign of the rational Horner value, on random polynomials of degree 0-7 with integer and
/// rational coefficients of up to 300 bits, at dyadic, non-dyadic, negative and huge times
/// and at roots.
TEST(Polynomial, SignAtEqualsTheSignOfTheRationalValue) {
  gmp_randclass rng(gmp_randinit_default);
  rng.seed(20261124);
  int zeros = 0, checks = 0, nonzero = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int degree = trial % 8;
    const bool integer = trial % 3 != 0;
    std::vector<Rational> c;
    for (int i = 0; i <= degree; ++i) {
      mpz_class n = rng.get_z_bits(1 + trial % 300) - rng.get_z_bits(1 + trial % 300);
      c.emplace_back(n, integer ? mpz_class(1) : mpz_class(rng.get_z_bits(40) + 1));
      c.back().canonicalize();
    }
    Polynomial p(c);
    const int shift = static_cast<int>(mpz_class(rng.get_z_range(200)).get_si());
    Rational dyadic(rng.get_z_bits(64) - rng.get_z_bits(64));
    dyadic *= pow2(-shift);
    Rational general(rng.get_z_bits(50) - rng.get_z_bits(50), rng.get_z_bits(50) + 1);
    general.canonicalize();
    for (const Rational& t : std::vector<Rational>{dyadic, general, 0, pow2(400), -pow2(-300)}) {
      EXPECT_EQ(p.sign_at(t), sgn(p.evaluate(t))) << "trial " << trial;
      ++checks;
    }
    // At a root: p (t - r) vanishes at r (p non-zero), in rational and in integer form.
    if (p.is_zero()) continue;
    ++nonzero;
    zeros += (p * P({-general, 1})).sign_at(general) == 0;
    zeros += primitive_part(p * P({-dyadic, 1})).sign_at(dyadic) == 0;
  }
  EXPECT_EQ(zeros, 2 * nonzero);
  EXPECT_GT(nonzero, 2900);
  EXPECT_EQ(checks, 15000);
}

TEST(Polynomial, SquareFreePart) {
  // (t - 1/3)^2 (t - 1/2) -> (t - 1/3)(t - 1/2) = t^2 - 5/6 t + 1/6.
  const Polynomial p = linear(q(1, 3)) * linear(q(1, 3)) * linear(q(1, 2));
  expect_poly_eq(square_free_part(p), P({q(1, 6), q(-5, 6), 1}));
  expect_poly_eq(square_free_part(P({0, 0, 0, 5})), P({0, 1}));  // 5 t^3 -> t
  expect_poly_eq(square_free_part(P({7})), P({1}));
  EXPECT_THROW(square_free_part(Polynomial()), std::domain_error);
}

// ---------------------------------------------------------------------------------------------
// Root isolation

TEST(RootIsolation, SturmCountsRootsInHalfOpenIntervals) {
  const SturmSequence s(linear(q(1, 4)) * linear(q(1, 2)) * linear(q(3, 4)));
  EXPECT_EQ(s.count_roots(0, 1), 3);
  EXPECT_EQ(s.count_roots(q(1, 4), q(1, 2)), 1);  // (1/4, 1/2] holds 1/2 only
  EXPECT_EQ(s.count_roots(0, q(1, 4)), 1);
  EXPECT_EQ(s.count_roots(q(3, 4), 10), 0);
  EXPECT_EQ(SturmSequence(P({1, 0, 1})).count_roots(-100, 100), 0);
}

TEST(RootIsolation, RationalRootsAtTheIntervalEnds) {
  // t (t - 1) on [0, 1]: exactly 0 and 1, found as rationals.
  auto roots = real_roots_in(P({0, -1, 1}), 0, 1);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_TRUE(roots[0].is_rational());
  EXPECT_EQ(roots[0].lo(), 0);
  EXPECT_TRUE(roots[1].is_rational());
  EXPECT_EQ(roots[1].lo(), 1);
  // (t - 1/4)(t - 1/2)(t - 3/4) on [1/4, 1/2]: both ends; on [3/10, 7/10]: 1/2 only.
  const Polynomial p = linear(q(1, 4)) * linear(q(1, 2)) * linear(q(3, 4));
  roots = real_roots_in(p, q(1, 4), q(1, 2));
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_EQ(roots[0].compare(q(1, 4)), 0);
  EXPECT_EQ(roots[1].compare(q(1, 2)), 0);
  roots = real_roots_in(p, q(3, 10), q(7, 10));
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_EQ(roots[0].compare(q(1, 2)), 0);
}

TEST(RootIsolation, DoubleRoot) {
  // (t - 1/2)^2 (t - 3/4): two distinct roots.
  auto roots = real_roots_in(linear(q(1, 2)) * linear(q(1, 2)) * linear(q(3, 4)), 0, 1);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_EQ(roots[0].compare(q(1, 2)), 0);
  EXPECT_EQ(roots[1].compare(q(3, 4)), 0);
  EXPECT_EQ(roots[0].enclosure(0), std::make_pair(0.5, 0.5));
  EXPECT_EQ(roots[1].enclosure(0), std::make_pair(0.75, 0.75));
}

TEST(RootIsolation, RootsCloserThanOneUlp) {
  // (t - 1/2)(t - 1/2 - 2^-60): 1/2 and a non-double just above it (ulp(1/2) = 2^-53).
  const Rational r2 = q(1, 2) + pow2(-60);
  auto roots = real_roots_in(linear(q(1, 2)) * linear(r2), 0, 1);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_EQ(roots[0].compare(q(1, 2)), 0);
  EXPECT_EQ(roots[1].compare(r2), 0);
  EXPECT_LE(cmp(roots[0].hi(), roots[1].lo()), 0) << "isolating intervals overlap";
  EXPECT_EQ(roots[0].enclosure(0), std::make_pair(0.5, 0.5));
  EXPECT_EQ(roots[1].enclosure(0), std::make_pair(0.5, std::nextafter(0.5, 1.0)));

  // Two roots inside the same gap between consecutive doubles: 1/3 and 1/3 + 2^-70.
  const Rational third = q(1, 3), r3 = third + pow2(-70);
  roots = real_roots_in(linear(third) * linear(r3), 0, 1);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_EQ(roots[0].compare(third), 0);
  EXPECT_EQ(roots[1].compare(r3), 0);
  const auto e0 = roots[0].enclosure(0), e1 = roots[1].enclosure(0);
  EXPECT_EQ(e0, e1);
  expect_tightest_pair(e0, cmp(Rational(e0.first), third), cmp(Rational(e0.second), r3));

}

TEST(RootIsolation, CloseIrrationalRoots) {
  // (t - 1/2)^2 - 2^-101 = t^2 - t + 1/4 - 2^-101: roots 1/2 -+ 2^-50.5, irrational.
  const Polynomial p = P({q(1, 4) - pow2(-101), -1, 1});
  auto roots = real_roots_in(p, 0, 1);
  ASSERT_EQ(roots.size(), 2u);
  // p > 0 below the lower root, < 0 between the roots, > 0 above the upper one; an enclosure
  // on the correct side of 1/2 where p changes sign accordingly contains that root.
  const auto e0 = roots[0].enclosure(0), e1 = roots[1].enclosure(0);
  EXPECT_FALSE(roots[0].is_rational());
  EXPECT_FALSE(roots[1].is_rational());
  EXPECT_LE(e0.second, 0.5);
  EXPECT_EQ(p.sign_at(Rational(e0.first)), 1);
  EXPECT_EQ(p.sign_at(Rational(e0.second)), -1);
  EXPECT_GE(e1.first, 0.5);
  EXPECT_EQ(p.sign_at(Rational(e1.first)), -1);
  EXPECT_EQ(p.sign_at(Rational(e1.second)), 1);
  EXPECT_EQ(std::nextafter(e0.first, kInf), e0.second);
  EXPECT_EQ(std::nextafter(e1.first, kInf), e1.second);
  EXPECT_LT(roots[0].compare(q(1, 2)), 0);  // below 1/2
  EXPECT_GT(roots[1].compare(q(1, 2)), 0);  // above 1/2
  // 2^-50.5 lies between 2^-51 and 2^-50.
  EXPECT_GT(roots[0].compare(q(1, 2) - pow2(-50)), 0);
  EXPECT_LT(roots[0].compare(q(1, 2) - pow2(-51)), 0);
  EXPECT_GT(roots[1].compare(q(1, 2) + pow2(-51)), 0);
  EXPECT_LT(roots[1].compare(q(1, 2) + pow2(-50)), 0);
}

TEST(RootIsolation, IrrationalRoot) {
  // 2t^2 - 1 on [0, 1]: sqrt(2)/2 only.
  auto roots = real_roots_in(P({-1, 0, 2}), 0, 1);
  ASSERT_EQ(roots.size(), 1u);
  AlgebraicTime& r = roots[0];
  EXPECT_FALSE(r.is_rational());
  EXPECT_LT(r.lo() * r.lo(), q(1, 2));
  EXPECT_GT(r.hi() * r.hi(), q(1, 2));
  const auto e = r.enclosure(0);
  const Rational lo(e.first), hi(e.second);
  expect_tightest_pair(e, cmp(lo * lo, q(1, 2)), cmp(hi * hi, q(1, 2)));
  // IEEE square root is correctly rounded: sqrt(0.5) is one of the two.
  EXPECT_TRUE(std::sqrt(0.5) == e.first || std::sqrt(0.5) == e.second);
}

TEST(RootIsolation, ManyRationalRoots) {
  // prod_{k=1..9} (t - k/10): nine roots, ascending.
  Polynomial p = P({1});
  for (int k = 1; k <= 9; ++k) p = p * linear(q(k, 10));
  auto roots = real_roots_in(p, 0, 1);
  ASSERT_EQ(roots.size(), 9u);
  for (int k = 1; k <= 9; ++k) EXPECT_EQ(roots[k - 1].compare(q(k, 10)), 0) << "k = " << k;
}

TEST(RootIsolation, NoRoot) {
  EXPECT_TRUE(real_roots_in(P({1, 0, 1}), 0, 1).empty());                  // t^2 + 1
  EXPECT_TRUE(real_roots_in(linear(2), 0, 1).empty());                     // t - 2
  EXPECT_TRUE(real_roots_in(linear(-1) * linear(3), 0, 1).empty());        // (t + 1)(t - 3)
  EXPECT_TRUE(real_roots_in(linear(q(1, 2)), q(3, 4), 1).empty());         // root below a
  EXPECT_TRUE(real_roots_in(P({5}), 0, 1).empty());                        // constant
  EXPECT_THROW(real_roots_in(Polynomial(), 0, 1), std::domain_error);      // zero
}

// ---------------------------------------------------------------------------------------------
// AlgebraicTime

/// The root of (2t^2 - 1)(t - 1/4) near 0.707, isolated in (7/10, 3/4): f(7/10) < 0 < f(3/4).
AlgebraicTime sqrt_half() {
  return AlgebraicTime(P({-1, 0, 2}) * linear(q(1, 4)), q(7, 10), q(3, 4));
}

TEST(AlgebraicTime, ConstructorNeedsASignChange) {
  // f(0) = 1/4 and f(1/8) = (1/32 - 1)(-1/8) > 0: no sign change.
  EXPECT_THROW(AlgebraicTime(P({-1, 0, 2}) * linear(q(1, 4)), 0, q(1, 8)), std::logic_error);
  EXPECT_THROW(AlgebraicTime(linear(q(1, 2)), q(3, 4), q(1, 4)), std::logic_error);  // lo > hi
}

TEST(AlgebraicTime, SignIsExactlyZeroAtASharedIrrationalRoot) {
  AlgebraicTime t = sqrt_half();
  EXPECT_EQ(t.sign_of(P({q(-1, 2), 0, 1})), 0);                // t^2 - 1/2
  EXPECT_EQ(t.sign_of(P({-1, 0, 2}) * linear(-3)), 0);         // (2t^2 - 1)(t + 3)
  EXPECT_EQ(t.sign_of(t.defining_polynomial()), 0);
  EXPECT_EQ(t.sign_of(linear(q(1, 4))), 1);                    // t - 1/4
  EXPECT_EQ(t.sign_of(Polynomial()), 0);
  EXPECT_EQ(t.sign_of(P({-3})), -1);
  EXPECT_FALSE(t.is_rational());
  // Still isolating after the refinements sign_of may have done.
  EXPECT_LT(t.lo() * t.lo(), q(1, 2));
  EXPECT_GT(t.hi() * t.hi(), q(1, 2));
}

TEST(AlgebraicTime, SignNextToAVeryCloseRoot) {
  AlgebraicTime t = sqrt_half();
  // t^2 - (1/2 -+ 2^-200): roots 2^-200-close to the time, on either side.
  EXPECT_EQ(t.sign_of(P({q(-1, 2) - pow2(-200), 0, 1})), -1);
  EXPECT_EQ(t.sign_of(P({q(-1, 2) + pow2(-200), 0, 1})), 1);
  // sqrt(1/2) = 0.70710678118654752440084436...: decimal bounds 1e-19 apart (below one ulp).
  const Rational below(mpz_class("7071067811865475244"), mpz_class("10000000000000000000"));
  const Rational above(mpz_class("7071067811865475245"), mpz_class("10000000000000000000"));
  EXPECT_EQ(t.sign_of(linear(below)), 1);
  EXPECT_EQ(t.sign_of(linear(above)), -1);
  EXPECT_EQ(t.compare(below), 1);
  EXPECT_EQ(t.compare(above), -1);
  EXPECT_EQ(t.compare(q(1, 4)), 1);
  EXPECT_EQ(t.compare(1), -1);
  // A cubic with a root about 2^-300 below the time: at sqrt(1/2), t^2 - 1/2 + 2^-300 = 2^-300
  // and t + 5 > 0, so (t^2 - 1/2 + 2^-300)(t + 5) is positive there.
  EXPECT_EQ(t.sign_of(P({q(-1, 2) + pow2(-300), 0, 1}) * linear(-5)), 1);
}

TEST(AlgebraicTime, EnclosureAroundIrrationalRoot) {
  AlgebraicTime t = sqrt_half();
  const auto coarse = t.enclosure(1e-3);
  const Rational clo(coarse.first), chi(coarse.second);
  EXPECT_LT(clo * clo, q(1, 2));
  EXPECT_GT(chi * chi, q(1, 2));
  EXPECT_LE(chi - clo, Rational(1e-3));
  const auto tight = t.enclosure(0);
  const Rational lo(tight.first), hi(tight.second);
  expect_tightest_pair(tight, cmp(lo * lo, q(1, 2)), cmp(hi * hi, q(1, 2)));
  EXPECT_LE(coarse.first, tight.first);
  EXPECT_GE(coarse.second, tight.second);
}

TEST(AlgebraicTime, EnclosureOfRationalRoots) {
  // (t - 1/2)(t - 3/4) isolated in (2/5, 3/5): refinement lands on the double 1/2 exactly.
  AlgebraicTime half(linear(q(1, 2)) * linear(q(3, 4)), q(2, 5), q(3, 5));
  EXPECT_EQ(half.enclosure(0), std::make_pair(0.5, 0.5));
  EXPECT_TRUE(half.is_rational());
  // 3t - 1 in (0, 1/2): 1/3 is no double, so the two doubles around it.
  AlgebraicTime third(P({-1, 3}), 0, q(1, 2));
  const auto e = third.enclosure(0);
  expect_tightest_pair(e, cmp(Rational(e.first), q(1, 3)), cmp(Rational(e.second), q(1, 3)));
  // A rational time given as such.
  AlgebraicTime r = AlgebraicTime::rational(q(1, 3));
  EXPECT_EQ(r.sign_of(P({-1, 3})), 0);
  EXPECT_EQ(r.enclosure(0), e);
  // t = 2^-1100, below the smallest positive double: enclosed by 0 and 2^-1074.
  AlgebraicTime tiny(P({-pow2(-1100), 1}), 0, 1);
  EXPECT_EQ(tiny.enclosure(0), std::make_pair(0.0, kDenormMin));
  // t = 1 - 2^-60: between 1 - 2^-53 and 1.
  AlgebraicTime near_one(linear(1 - pow2(-60)), q(1, 2), 1);
  EXPECT_EQ(near_one.enclosure(0), std::make_pair(1 - 0x1p-53, 1.0));
}

// ---------------------------------------------------------------------------------------------
// Rationals and doubles

TEST(Rational, ExactDoubles) {
  for (const double d : {0.0, 0.1, -0.1, 1.0, 0x1p-1074, 0x1p-1022, DBL_MAX, -DBL_MAX, 0x1p1023}) {
    const Rational r(d);
    EXPECT_EQ(round_down(r), d);
    EXPECT_EQ(round_up(r), d);
    double out = -1;
    EXPECT_TRUE(to_double_exactly(r, &out)) << d;
    EXPECT_EQ(out, d);
  }
  double out = 0;
  EXPECT_TRUE(to_double_exactly(pow2(200) / pow2(199), &out));
  EXPECT_EQ(out, 2.0);
}

TEST(Rational, OneThird) {
  const Rational third = q(1, 3);
  const double lo = round_down(third), hi = round_up(third);
  EXPECT_LT(Rational(lo), third);
  EXPECT_GT(Rational(hi), third);
  EXPECT_EQ(std::nextafter(lo, kInf), hi);
  double out = 0;
  EXPECT_FALSE(to_double_exactly(third, &out));
  // Negative: the mirror image.
  EXPECT_EQ(round_down(-third), -hi);
  EXPECT_EQ(round_up(-third), -lo);
  EXPECT_FALSE(to_double_exactly(-third, &out));
}

TEST(Rational, JustAboveAndBelowDoubles) {
  EXPECT_EQ(round_down(1 + pow2(-60)), 1.0);
  EXPECT_EQ(round_up(1 + pow2(-60)), 1 + 0x1p-52);
  EXPECT_EQ(round_down(1 - pow2(-60)), 1 - 0x1p-53);
  EXPECT_EQ(round_up(1 - pow2(-60)), 1.0);
  // 2^53 + 1 is the first integer that is no double.
  const Rational odd = pow2(53) + 1;
  EXPECT_EQ(round_down(odd), 0x1p53);
  EXPECT_EQ(round_up(odd), 0x1p53 + 2);
  double out = 0;
  EXPECT_FALSE(to_double_exactly(odd, &out));
  EXPECT_FALSE(to_double_exactly((pow2(200) + 1) / pow2(200), &out));
}

TEST(Rational, Subnormals) {
  const Rational tiny = pow2(-1100);
  EXPECT_EQ(round_down(tiny), 0.0);
  EXPECT_EQ(round_up(tiny), kDenormMin);
  EXPECT_EQ(round_down(-tiny), -kDenormMin);
  EXPECT_EQ(round_up(-tiny), 0.0);
  double out = 0;
  EXPECT_FALSE(to_double_exactly(tiny, &out));
  // 3 * 2^-1075, halfway between 2^-1074 and 2^-1073.
  const Rational between = 3 * pow2(-1075);
  EXPECT_EQ(round_down(between), 0x1p-1074);
  EXPECT_EQ(round_up(between), 0x1p-1073);
  EXPECT_FALSE(to_double_exactly(between, &out));
}

TEST(Rational, BeyondTheLargestDouble) {
  const Rational huge = pow2(1100);
  EXPECT_EQ(round_down(huge), DBL_MAX);
  EXPECT_EQ(round_up(huge), kInf);
  EXPECT_EQ(round_down(-huge), -kInf);
  EXPECT_EQ(round_up(-huge), -DBL_MAX);
  double out = 0;
  EXPECT_FALSE(to_double_exactly(huge, &out));
  EXPECT_FALSE(to_double_exactly(-huge, &out));
  // DBL_MAX + 2^960: above DBL_MAX by less than half its ulp (2^971).
  const Rational above_max = Rational(DBL_MAX) + pow2(960);
  EXPECT_EQ(round_down(above_max), DBL_MAX);
  EXPECT_EQ(round_up(above_max), kInf);
  EXPECT_FALSE(to_double_exactly(above_max, &out));
}

TEST(Rational, DoublesBetweenRationals) {
  const Rational third = q(1, 3);
  EXPECT_TRUE(no_double_strictly_between(Rational(round_down(third)), Rational(round_up(third))));
  EXPECT_TRUE(no_double_strictly_between(third, third + pow2(-70)));
  EXPECT_FALSE(no_double_strictly_between(0, 1));
  EXPECT_FALSE(no_double_strictly_between(0, pow2(-1073)));  // 2^-1074 lies between
  EXPECT_TRUE(no_double_strictly_between(0, pow2(-1074)));
  // split_point: strictly inside, a double while one lies strictly between.
  for (const auto& [lo, hi] : {std::make_pair(Rational(0), Rational(1)),
                               std::make_pair(q(1, 3), q(1, 2)),
                               std::make_pair(Rational(0), pow2(-1073))}) {
    const Rational m = split_point(lo, hi);
    EXPECT_LT(lo, m);
    EXPECT_LT(m, hi);
    double out = 0;
    EXPECT_TRUE(to_double_exactly(m, &out)) << m.get_str();
  }
  const Rational m = split_point(third, third + pow2(-70));  // no double inside: the midpoint
  EXPECT_EQ(m, third + pow2(-71));
}

}  // namespace
}  // namespace exactccd::exact
