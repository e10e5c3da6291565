// The integer polynomials of the exact stage at double brackets (exact/polynomials/small_polynomial.hpp)
// and their bracketed roots (exact/polynomials/bracketed_root.hpp), against rational arithmetic written
// here independently (GMP mpq: direct evaluation, Taylor shift by composition, the Bernstein
// coefficients from their definition, roots known from the construction).
// PROOF: proofs/exact_ccd.md#small-polynomial-bounds
// PROOF: proofs/exact_ccd.md#descartes-at-doubles
// PROOF: proofs/exact_ccd.md#sign-at-a-bracketed-root
// PROOF: proofs/exact_ccd.md#sign-at-a-root-by-remainders
// PROOF: proofs/exact_ccd.md#quadratic-discriminant
// PROOF: proofs/exact_ccd.md#constant-remainder
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/predicates/fp_environment.hpp"
#include "exact/polynomials/bracketed_root.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/polynomials/root_isolation.hpp"
#include "exact/polynomials/small_polynomial.hpp"
#include "integer_polynomial_support.hpp"
#include "tarski_reference.hpp"
#include "test_scale.hpp"

namespace exactccd::exact {
namespace {

using Q = mpq_class;
using test::tarski_sign_at_root;

struct RationalPolynomial {
  std::vector<Q> c;  // c[i] of t^i
  Q at(const Q& t) const {
    Q r = 0;
    for (std::size_t i = c.size(); i-- > 0;) r = r * t + c[i];
    return r;
  }
};

RationalPolynomial rational(const std::array<mpz_class, 4>& c, int degree) {
  RationalPolynomial p;
  for (int i = 0; i <= degree; ++i) p.c.emplace_back(c[static_cast<std::size_t>(i)]);
  return p;
}

using test::random_integer;

/// A double in [0, 1]: 0, 1, full-precision values of every binade down to subnormals, and
/// short dyadics.
double random_time(std::mt19937_64& rng) {
  switch (rng() % 6) {
    case 0: return (rng() & 1) ? 0.0 : 1.0;
    case 1: return std::ldexp(static_cast<double>(rng() >> 11), -53);
    case 2: {
      const int e = -static_cast<int>(rng() % 1074);
      return std::ldexp(1.0 + static_cast<double>(rng() >> 12) * 0x1p-52, e - 1);
    }
    case 3: return static_cast<double>(rng() % 1025) / 1024.0;
    case 4: return std::ldexp(static_cast<double>(rng() >> 11), -53 - static_cast<int>(rng() % 200));
    default: return static_cast<double>(rng() >> 11) * 0x1p-53;
  }
}

std::array<mpz_class, 4> random_coefficients(std::mt19937_64& rng, int degree, int bits) {
  std::array<mpz_class, 4> c;
  for (int i = 0; i <= degree; ++i)
    c[static_cast<std::size_t>(i)] = random_integer(rng, static_cast<int>(rng() % (bits + 1)));
  if (degree >= 0 && c[static_cast<std::size_t>(degree)] == 0) c[static_cast<std::size_t>(degree)] = 1;
  return c;
}

/// The Bernstein coefficients of p on [a, b] from the definition: p(a + (b - a) s) =
/// sum_j q_j s^j by composition, then beta_j = sum_{i<=j} C(j,i)/C(d,i) q_i.
std::vector<Q> bernstein(const RationalPolynomial& p, const Q& a, const Q& b) {
  const int d = static_cast<int>(p.c.size()) - 1;
  std::vector<Q> q(static_cast<std::size_t>(d + 1), Q(0));
  std::vector<Q> power = {Q(1)};  // (a + h s)^i
  const Q h = b - a;
  for (int i = 0; i <= d; ++i) {
    for (std::size_t j = 0; j < power.size(); ++j) q[j] += p.c[static_cast<std::size_t>(i)] * power[j];
    std::vector<Q> next(power.size() + 1, Q(0));
    for (std::size_t j = 0; j < power.size(); ++j) {
      next[j] += power[j] * a;
      next[j + 1] += power[j] * h;
    }
    power = next;
  }
  auto binom = [](int n, int k) {
    long r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
  };
  std::vector<Q> beta(static_cast<std::size_t>(d + 1), Q(0));
  for (int j = 0; j <= d; ++j)
    for (int i = 0; i <= j; ++i)
      beta[static_cast<std::size_t>(j)] += Q(binom(j, i), binom(d, i)) * q[static_cast<std::size_t>(i)];
  return beta;
}

class SmallPolynomialTest : public ::testing::Test {
 protected:
  predicates::FpEnvironmentGuard nearest{predicates::Rounding::to_nearest};
};

TEST_F(SmallPolynomialTest, ValuesMatchRationalEvaluation) {
  std::mt19937_64 rng(0x5a11);
  const int n = static_cast<int>(test::scaled_count(20000));
  for (int trial = 0; trial < n; ++trial) {
    const int degree = static_cast<int>(rng() % 4);
    const int bits = trial % 3 == 0 ? 1100 : (trial % 3 == 1 ? 200 : 60);
    const auto c = random_coefficients(rng, degree, bits);
    const SmallPolynomial p = SmallPolynomial::from_mpz(c.data(), 4);
    const double t = random_time(rng);
    ASSERT_EQ(p.sign_at(t), sgn(rational(c, degree).at(Q(t)))) << "t = " << t;
  }
}

TEST_F(SmallPolynomialTest, BernsteinSignsMatchRationalBernstein) {
  std::mt19937_64 rng(0xbe25);
  const int n = static_cast<int>(test::scaled_count(20000));
  for (int trial = 0; trial < n; ++trial) {
    const int degree = static_cast<int>(rng() % 4);
    const int bits = trial % 3 == 0 ? 1000 : (trial % 3 == 1 ? 150 : 40);
    const auto c = random_coefficients(rng, degree, bits);
    const SmallPolynomial p = SmallPolynomial::from_mpz(c.data(), 4);
    double a = random_time(rng), b = random_time(rng);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    int signs[4];
    const int count = p.bernstein_signs(a, b, signs);
    const std::vector<Q> beta = bernstein(rational(c, degree), Q(a), Q(b));
    ASSERT_EQ(count, static_cast<int>(beta.size()));
    for (int j = 0; j < count; ++j)
      ASSERT_EQ(signs[j], sgn(beta[static_cast<std::size_t>(j)]))
          << "degree " << degree << " [" << a << ", " << b << "] j = " << j;
  }
}

/// Products of (den t - num) for rational roots, times a positive constant.
SmallPolynomial with_roots(const std::vector<Q>& roots, long scale = 1) {
  return test::with_roots(roots, mpz_class(scale));
}

Q pow2(int e) { return e >= 0 ? Q(mpz_class(1) << e) : Q(1, mpz_class(1) << -e); }

TEST_F(SmallPolynomialTest, RootIteratorFindsEveryRootInOrder) {
  const Q third(1, 3), tenth(1, 10);
  const Q near(Q(3, 10) + pow2(-70));  // within one ulp of 3/10, distinct
  struct Case {
    std::vector<Q> roots;  // with multiplicity
    double t_max;
  };
  const std::vector<Case> cases = {
      {{third}, 1.0},
      {{Q(0), Q(1, 2), Q(1)}, 1.0},          // ends and a split point
      {{third, third}, 1.0},                 // double root, not a double
      {{third, third, third}, 1.0},          // triple root
      {{Q(3, 10), near}, 1.0},               // two roots within one ulp
      {{Q(3, 10), near, Q(3, 10) - pow2(-80)}, 1.0},
      {{Q(1, 4), Q(1, 4), Q(7, 8)}, 1.0},    // double root at a double
      {{tenth, Q(2), Q(-1)}, 1.0},           // roots outside [0, 1]
      {{third, Q(2, 3)}, 0.5},               // t_max cuts the second
      {{Q(1, 2)}, 0.5},                      // root at t_max
      {{pow2(-1000), pow2(-900)}, 1.0},      // tiny roots
      // Closer than one ulp by far: split at the critical points (2,000 bisections otherwise).
      {{Q(3, 10), Q(3, 10) + pow2(-2000)}, 1.0},
      {{Q(3, 10) - pow2(-1500), Q(3, 10), Q(3, 10) + pow2(-500)}, 1.0},
      {{Q(3, 10) - pow2(-700), Q(3, 10) + pow2(-700), Q(9, 10)}, 1.0},
      {{Q(1, 2), Q(1, 2) + pow2(-300)}, 1.0},  // one at a double, one just above it
  };
  for (const Case& c : cases) {
    const SmallPolynomial p = with_roots(c.roots);
    std::vector<Q> expected;
    for (const Q& r : c.roots)
      if (r >= 0 && r <= Q(c.t_max) &&
          std::find(expected.begin(), expected.end(), r) == expected.end())
        expected.push_back(r);
    std::sort(expected.begin(), expected.end());
    SmallPolynomial square_free;
    RootIterator it(p, c.t_max, &square_free);
    std::vector<BracketedRoot> found;
    while (auto r = it.next()) found.push_back(*r);
    ASSERT_EQ(found.size(), expected.size()) << "case with " << c.roots.size() << " roots";
    for (std::size_t i = 0; i < found.size(); ++i) {
      const Q& r = expected[i];
      if (found[i].is_exact()) {
        EXPECT_EQ(Q(found[i].lo()), r);
      } else {
        EXPECT_LT(Q(found[i].lo()), r);
        EXPECT_GT(Q(found[i].hi()), r);
      }
      // Each root's own bracket, dyadic ones included, separates it from every other: the
      // sign of den t - num (zero exactly at that rational root) at the found root.
      for (std::size_t j = 0; j < expected.size(); ++j) {
        const mpz_class line[2] = {-expected[j].get_num(), expected[j].get_den()};
        const SmallPolynomial g = SmallPolynomial::from_mpz(line, 2);
        EXPECT_EQ(found[i].sign_of(g), i == j ? 0 : i > j ? 1 : -1)
            << "root " << i << " against " << j << " of " << c.roots.size();
      }
    }
  }
}

// The split at critical points on its own: every root inside the bracket, each in its own
// dyadic bracket with p changing sign across it, ascending, however close (2^-40 to 2^-8000;
// bisection would take that many steps), for cubics and quadratics; p monotone: none.
TEST_F(SmallPolynomialTest, SplitAtCriticalPointsSeparatesCloseRoots) {
  struct Case {
    std::vector<Q> roots;   // all of p's roots
    std::size_t inside;     // how many lie in (0.29, 0.31)
  };
  const Q c(3, 10);
  const std::vector<Case> cases = {
      {{c, c + pow2(-40)}, 2},
      {{c, c + pow2(-8000)}, 2},
      {{c - pow2(-1500), c, c + pow2(-500)}, 3},
      {{c - pow2(-700), c + pow2(-700), Q(9, 10)}, 2},
      {{c, Q(9, 10), Q(-2)}, 1},
      {{Q(1, 10), Q(9, 10), Q(1, 2)}, 0},
      {{c, Q(1, 2)}, 1},                      // a quadratic, its critical point outside
  };
  for (const Case& k : cases) {
    const MpzPolynomial p = to_mpz_polynomial(with_roots(k.roots));
    DyadicBracket d;
    d.K = 100;
    d.A = mpz_class(Q(Q(29, 100) * Q(mpz_class(1) << 100)).get_num() /
                    Q(Q(29, 100) * Q(mpz_class(1) << 100)).get_den());
    d.B = mpz_class(Q(Q(31, 100) * Q(mpz_class(1) << 100)).get_num() /
                    Q(Q(31, 100) * Q(mpz_class(1) << 100)).get_den());
    const std::optional<std::vector<DyadicBracket>> split = split_at_critical_points(p, d);
    ASSERT_TRUE(split.has_value()) << k.roots.size() << " roots";
    ASSERT_EQ(split->size(), k.inside);
    std::vector<Q> inside;
    for (const Q& r : k.roots)
      if (r > Q(29, 100) && r < Q(31, 100)) inside.push_back(r);
    std::sort(inside.begin(), inside.end());
    for (std::size_t i = 0; i < inside.size(); ++i) {
      const DyadicBracket& b = (*split)[i];
      const Q scale(mpz_class(1) << b.K);
      EXPECT_LT(Q(b.A) / scale, inside[i]);
      EXPECT_GT(Q(b.B) / scale, inside[i]);
      EXPECT_EQ(b.sign_lo, sign_at_dyadic(p, b.A, b.K));
      EXPECT_EQ(-b.sign_lo, sign_at_dyadic(p, b.B, b.K));
      if (i > 0) EXPECT_LE(Q((*split)[i - 1].B) / Q(mpz_class(1) << (*split)[i - 1].K), Q(b.A) / scale);
    }
  }
  // p' without real roots (p monotone): (10t - 3)(t^2 + 1), its one root inside found.
  MpzPolynomial monotone;
  monotone.c = {mpz_class(-3), mpz_class(10), mpz_class(-3), mpz_class(10)};
  monotone.degree = 3;
  DyadicBracket d;
  d.K = 7;
  d.A = 37;  // 0.2890625
  d.B = 39;  // 0.3046875
  const std::optional<std::vector<DyadicBracket>> one = split_at_critical_points(monotone, d);
  ASSERT_TRUE(one.has_value());
  ASSERT_EQ(one->size(), 1u);
  EXPECT_LT(Q((*one)[0].A) / Q(mpz_class(1) << (*one)[0].K), c);
  EXPECT_GT(Q((*one)[0].B) / Q(mpz_class(1) << (*one)[0].K), c);
}

TEST_F(SmallPolynomialTest, SignAtRootMatchesRationalPath) {
  const Q third(1, 3);
  const SmallPolynomial p = with_roots({third, Q(3, 4), Q(-5)});
  struct Case {
    std::vector<Q> g_roots;
    long scale;
  };
  const std::vector<Case> cases = {
      {{third}, 1},                       // common factor: g(r) = 0
      {{third, Q(1, 7)}, -3},             // common factor, other root
      {{third + pow2(-70)}, 1},           // g's root within one ulp, above
      {{third - pow2(-90), Q(2)}, 1},     // below, quadratic
      {{third + pow2(-200), third - pow2(-200)}, -1},
      {{Q(1, 2)}, 2},                     // far
      {{}, -7},                           // constant
  };
  for (const Case& c : cases) {
    const SmallPolynomial g = with_roots(c.g_roots, c.scale);
    Q expected = c.scale;
    for (const Q& r : c.g_roots) expected *= third * r.get_den() - r.get_num();
    SmallPolynomial square_free;
    RootIterator it(p, 1.0, &square_free);
    std::optional<BracketedRoot> r = it.next();
    ASSERT_TRUE(r.has_value());
    ASSERT_FALSE(r->is_exact());
    EXPECT_EQ(r->sign_of(g), sgn(expected)) << c.g_roots.size() << " roots, scale " << c.scale;
  }
}

/// The integer polynomial with the given coefficients (lowest first).
MpzPolynomial mpz_polynomial(std::vector<mpz_class> c) {
  MpzPolynomial p;
  for (std::size_t i = 0; i < c.size(); ++i) p.c[i] = c[i];
  for (int i = static_cast<int>(c.size()) - 1; i >= 0; --i)
    if (p.c[static_cast<std::size_t>(i)] != 0) {
      p.degree = i;
      break;
    }
  return p;
}

/// A dyadic bracket [A, B] 2^-K around the root r of p (only it inside: the caller's roots are
/// far apart), from rational bounds lo < r < hi.
DyadicBracket bracket_around(const MpzPolynomial& p, const Q& lo, const Q& hi, unsigned K) {
  DyadicBracket d;
  d.K = K;
  const mpz_class scale = mpz_class(1) << K;
  d.A = mpz_class(Q(lo * scale).get_num() / Q(lo * scale).get_den()) - 1;
  d.B = mpz_class(Q(hi * scale).get_num() / Q(hi * scale).get_den()) + 1;
  d.sign_lo = sign_at_dyadic(p, d.A, K);
  return d;
}

// The stage's sign at a root (two pseudo-remainders and a quadratic irrationality) against the
// Sturm-Tarski query, an independent algorithm (a signed remainder sequence with contents
// divided out), and against rational evaluation where the root is rational: g sharing the
// root, g's roots (rational, quadratic irrational, double, complex) on both sides within
// 2^-60..2^-400 of an irrational root, every degree of g and p; then random p and g with
// coefficients of 1 to 2,000 bits and every root the iterator brackets.
TEST_F(SmallPolynomialTest, SignAtRootByRemaindersMatchesSturmTarski) {
  // p = (2t^2 - 1)(3t - 1): r = 1/sqrt(2) in (0.70, 0.71), and 1/3.
  const MpzPolynomial p = mpz_polynomial({1, -3, -2, 6});
  const DyadicBracket around_r = bracket_around(p, Q(70, 100), Q(71, 100), 300);
  const DyadicBracket around_third = bracket_around(p, Q(33, 100), Q(34, 100), 90);
  auto big = [](int e) -> mpz_class { return mpz_class(1) << e; };
  struct Case {
    std::vector<mpz_class> g;
    int at_r;      // the sign of g(1/sqrt 2)
    int at_third;  // the sign of g(1/3)
  };
  const std::vector<Case> cases = {
      {{-1, 0, 2}, 0, -1},                                   // shares r
      {{-1, 3}, 1, 0},                                       // shares 1/3
      {{-big(60) - 1, 0, 2 * big(60)}, -1, -1},              // 2t^2 - 1 - 2^-60: roots beyond r
      {{-big(400) + 1, 0, 2 * big(400)}, 1, -1},             // roots just inside r
      {{-mpz_class("7071067811865475244008443621048490392848"), mpz_class(10) * big(0) *
        mpz_class("1000000000000000000000000000000000000000")}, 1, -1},  // t - 0.70710678...(below r)
      {{mpz_class("7071067811865475244008443621048490392849") *
            mpz_class("7071067811865475244008443621048490392849"),
        -2 * mpz_class("7071067811865475244008443621048490392849") *
            mpz_class("10000000000000000000000000000000000000000"),
        mpz_class("10000000000000000000000000000000000000000") *
            mpz_class("10000000000000000000000000000000000000000")}, 1, 1},  // (t - c)^2, c > r
      {{1, 0, 1}, 1, 1},                                     // t^2 + 1: no real root
      {{-5}, -1, -1},                                        // constant
      {{1, -3, -2, 6}, 0, 0},                                // p itself
      {{-1, 2, 2, -4}, 0, -1},                               // (2t^2 - 1)(1 - 2t): degree 3, shares r
      {{0, 1, -3}, -1, 0},                                   // t (1 - 3t)
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const MpzPolynomial g = mpz_polynomial(cases[i].g);
    for (const auto& [d, expected] : {std::pair{&around_r, cases[i].at_r},
                                      std::pair{&around_third, cases[i].at_third}}) {
      const int tarski = tarski_sign_at_root(p, g, d->A, d->B, d->K);
      const int remainders = sign_at_root_by_remainders(p, g, d->A, d->B, d->K, d->sign_lo);
      EXPECT_EQ(remainders, tarski) << "case " << i;
      if (d == &around_third)  // 1/3 is rational: evaluate
        EXPECT_EQ(remainders, sgn(rational(g.c, g.degree).at(Q(1, 3)))) << "case " << i;
      else
        EXPECT_EQ(remainders, expected) << "case " << i;
    }
  }

  std::mt19937_64 rng(20261124);
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int bits = 1 + static_cast<int>(rng() % (trial % 3 == 0 ? 2000 : 64));
    const int degree = 1 + static_cast<int>(rng() % 3);
    const SmallPolynomial q = SmallPolynomial::from_mpz(random_coefficients(rng, degree, bits).data(), 4);
    if (q.degree() < 1) continue;
    SmallPolynomial square_free;
    RootIterator it(q, 1.0, &square_free);
    while (std::optional<BracketedRoot> r = it.next()) {
      if (r->is_exact()) continue;
      // The iterator may have replaced q by its square-free part: the bracket is one of its.
      const MpzPolynomial pm = to_mpz_polynomial(square_free.degree() >= 1 ? square_free : q);
      const Dyadic lo = dyadic(r->lo()), hi = dyadic(r->hi());
      DyadicBracket d;
      d.K = 1100;
      d.A = lo.mantissa == 0 ? mpz_class(0) : mpz_class(mpz_class(lo.mantissa) << (1100 + lo.exponent));
      d.B = mpz_class(mpz_class(hi.mantissa) << (1100 + hi.exponent));
      d.sign_lo = sign_at_dyadic(pm, d.A, d.K);
      if (d.sign_lo == 0 || sign_at_dyadic(pm, d.B, d.K) != -d.sign_lo) continue;
      for (int k = 0; k < 4; ++k) {
        MpzPolynomial g;
        if (k == 0) {
          g = pm;  // shares every root
        } else if (k == 1 && pm.degree <= 2) {
          // pm (2t - 1) + e, e in {-1, 0, 1}: a root within about 2^-bits of r, or r itself.
          std::vector<mpz_class> c(4, mpz_class(0));
          for (int j = 0; j <= pm.degree; ++j) {
            c[static_cast<std::size_t>(j + 1)] += 2 * pm.c[static_cast<std::size_t>(j)];
            c[static_cast<std::size_t>(j)] -= pm.c[static_cast<std::size_t>(j)];
          }
          c[0] += static_cast<long>(rng() % 3) - 1;
          g = mpz_polynomial(c);
        } else {
          const auto c = random_coefficients(rng, static_cast<int>(rng() % 4),
                                             1 + static_cast<int>(rng() % 200));
          g = mpz_polynomial({c[0], c[1], c[2], c[3]});
        }
        const int tarski = tarski_sign_at_root(pm, g, d.A, d.B, d.K);
        const int remainders = sign_at_root_by_remainders(pm, g, d.A, d.B, d.K, d.sign_lo);
        ASSERT_EQ(remainders, tarski) << "trial " << trial << " k " << k;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

/// Quadratics whose discriminant is zero, or within one of zero, or random, with coefficients
/// of `bits` bits (every FixedInt width of the discriminant, and GMP beyond): c2 (k t - m)^2
/// [+ delta]. Roots in and out of [0, 1], c2 of either sign.
std::array<mpz_class, 4> adversarial_quadratic(std::mt19937_64& rng, int bits, int kind) {
  const int part = std::max(1, bits / 3);
  mpz_class a = random_integer(rng, part), k = random_integer(rng, part);
  mpz_class m = random_integer(rng, static_cast<int>(rng() % (part + 1)));
  if (a == 0) a = 1;
  if (k == 0) k = 1;
  if (rng() % 2 == 0) m = abs(k) - 1 - (m % 4);  // root m / k just below 1 (or beyond 0)
  std::array<mpz_class, 4> c;
  c[2] = a * k * k;
  c[1] = -2 * a * k * m;
  c[0] = a * m * m;
  switch (kind) {
    case 0: break;                        // double root m / k
    case 1: c[0] += sgn(a); break;        // no real root, minimum a hair above zero
    case 2: c[0] -= sgn(a); break;        // two roots a hair apart
    default: c = random_coefficients(rng, 2, bits);
  }
  if (c[2] == 0) c[2] = 1;
  return c;
}

// The discriminant's sign in its FixedInt width (or GMP) against GMP, and the double root's
// linear factor against the identity 4 c2 p = (2 c2 t + c1)^2; 40- to 1,100-bit coefficients.
TEST_F(SmallPolynomialTest, QuadraticDiscriminantMatchesGmp) {
  std::mt19937_64 rng(0xd15c);
  const int widths[] = {8, 40, 62, 100, 150, 300, 500, 700, 1100};
  const int n = static_cast<int>(test::scaled_count(20000));
  int zero = 0;
  for (int trial = 0; trial < n; ++trial) {
    const int bits = widths[trial % 9];
    const auto c = adversarial_quadratic(rng, bits, static_cast<int>(rng() % 4));
    const SmallPolynomial p = SmallPolynomial::from_mpz(c.data(), 3);
    ASSERT_EQ(p.degree(), 2);
    const mpz_class discriminant = c[1] * c[1] - 4 * c[2] * c[0];
    ASSERT_EQ(p.quadratic_discriminant_sign(), sgn(discriminant))
        << bits << " bits: " << c[2] << " t^2 + " << c[1] << " t + " << c[0];
    if (discriminant != 0) continue;
    ++zero;
    const MpzPolynomial f = to_mpz_polynomial(p.double_root_factor());
    ASSERT_EQ(f.degree, 1);
    EXPECT_EQ(f.c[1] * f.c[1], 4 * c[2] * c[2]);
    EXPECT_EQ(2 * f.c[1] * f.c[0], 4 * c[2] * c[1]);
    EXPECT_EQ(f.c[0] * f.c[0], 4 * c[2] * c[0]);
  }
  EXPECT_GT(zero, n / 8);
}

// RootIterator on quadratics (double roots, no real root with the minimum a hair above zero,
// two roots a hair apart, random) against the rational path's root isolation (Sturm
// sequences): the same roots in [0, T], in order, each bracket holding its root.
TEST_F(SmallPolynomialTest, RootIteratorOnQuadraticsMatchesRationalRoots) {
  std::mt19937_64 rng(0x9ad2);
  const int widths[] = {6, 20, 40, 62, 100, 200, 400};
  const double t_maxes[] = {1.0, 0.5, 0.75};
  // A floor: the share checked below needs a few hundred draws at any EXACTCCD_TEST_SCALE.
  const int n = static_cast<int>(test::at_least(test::scaled_count(3000), 600));
  int with_roots_found = 0;
  for (int trial = 0; trial < n; ++trial) {
    const int bits = widths[trial % 7];
    const double t_max = t_maxes[rng() % 3];
    const auto c = adversarial_quadratic(rng, bits, static_cast<int>(rng() % 4));
    const SmallPolynomial p = SmallPolynomial::from_mpz(c.data(), 3);
    const std::vector<AlgebraicTime> expected =
        real_roots_in(Polynomial({Q(c[0]), Q(c[1]), Q(c[2])}), Q(0), Q(t_max));
    SmallPolynomial square_free;
    RootIterator it(p, t_max, &square_free);
    std::vector<BracketedRoot> found;
    while (auto r = it.next()) found.push_back(*r);
    ASSERT_EQ(found.size(), expected.size())
        << bits << " bits: " << c[2] << " t^2 + " << c[1] << " t + " << c[0] << ", T = " << t_max;
    with_roots_found += !found.empty();
    for (std::size_t i = 0; i < found.size(); ++i) {
      AlgebraicTime root = expected[i];
      if (found[i].is_exact()) {
        EXPECT_EQ(root.compare(Q(found[i].lo())), 0);
      } else {
        EXPECT_GT(root.compare(Q(found[i].lo())), 0);
        EXPECT_LT(root.compare(Q(found[i].hi())), 0);
      }
    }
  }
  EXPECT_GT(with_roots_found, n / 4);
}

// Cubics with the same adversarial quadratic factors (a double root, a complex pair a hair off
// the real axis, two roots a hair apart) times a line with a root in or near [0, 1]: where the
// iterator splits near a critical point of p instead of halving. Against the rational path's
// Sturm isolation, as above.
TEST_F(SmallPolynomialTest, RootIteratorOnCubicsWithCloseRootsMatchesRationalRoots) {
  std::mt19937_64 rng(0xc0b1);
  const int widths[] = {6, 20, 40, 62, 100, 200};
  // A floor: the share checked below needs a few hundred draws at any EXACTCCD_TEST_SCALE.
  const int n = static_cast<int>(test::at_least(test::scaled_count(3000), 600));
  int several = 0;
  for (int trial = 0; trial < n; ++trial) {
    const int bits = widths[trial % 6];
    const double t_max = rng() % 2 ? 1.0 : 0.75;
    const auto q = adversarial_quadratic(rng, bits, static_cast<int>(rng() % 4));
    mpz_class k = abs(random_integer(rng, 1 + static_cast<int>(rng() % 30)));
    if (k == 0) k = 1;
    const mpz_class m = random_integer(rng, static_cast<int>(mpz_sizeinbase(k.get_mpz_t(), 2)));
    std::array<mpz_class, 4> c;  // q (k t - m)
    for (int i = 0; i <= 2; ++i) {
      c[static_cast<std::size_t>(i + 1)] += q[static_cast<std::size_t>(i)] * k;
      c[static_cast<std::size_t>(i)] -= q[static_cast<std::size_t>(i)] * m;
    }
    const SmallPolynomial p = SmallPolynomial::from_mpz(c.data(), 4);
    std::vector<AlgebraicTime> expected = real_roots_in(
        Polynomial({Q(c[0]), Q(c[1]), Q(c[2]), Q(c[3])}), Q(0), Q(t_max));
    SmallPolynomial square_free;
    RootIterator it(p, t_max, &square_free);
    std::vector<BracketedRoot> found;
    while (auto r = it.next()) found.push_back(*r);
    ASSERT_EQ(found.size(), expected.size())
        << bits << " bits: " << c[3] << " t^3 + " << c[2] << " t^2 + " << c[1] << " t + " << c[0];
    several += found.size() >= 2;
    for (std::size_t i = 0; i < found.size(); ++i) {
      if (found[i].is_exact()) {
        EXPECT_EQ(expected[i].compare(Q(found[i].lo())), 0);
      } else {
        EXPECT_GT(expected[i].compare(Q(found[i].lo())), 0);
        EXPECT_LT(expected[i].compare(Q(found[i].hi())), 0);
      }
    }
  }
  EXPECT_GT(several, n / 10);
}

/// A rational in (-1/2, 3/2) with a denominator of up to `bits` bits.
Q random_rational(std::mt19937_64& rng, int bits) {
  mpz_class den = abs(random_integer(rng, 1 + static_cast<int>(rng() % bits)));
  if (den == 0) den = 1;
  const mpz_class num = random_integer(rng, static_cast<int>(mpz_sizeinbase(den.get_mpz_t(), 2)));
  Q q(num, den);
  q.canonicalize();
  return q + Q(1, 2);
}

// The sign at the roots of p from a constant pseudo-remainder, in fixed size: g = p u + c with
// c = 0 (g(r) = 0 at every root r) or a constant of either sign, p with rational roots
// (repeated ones too) and lc(p) of either sign, coefficients of 2 to 1,100 bits; against the
// rational value of g at each root. A remainder of degree >= 1 (c of degree < deg p) must be
// declined.
TEST_F(SmallPolynomialTest, ConstantRemainderSignMatchesRationalValues) {
  std::mt19937_64 rng(0xc0de);
  const int root_bits[] = {1, 4, 16, 40, 64, 100, 180};
  const int n = static_cast<int>(test::scaled_count(20000));
  int decided = 0, zero = 0;
  for (int trial = 0; trial < n; ++trial) {
    const int dp = 1 + static_cast<int>(rng() % 3);
    const int dg = dp + static_cast<int>(rng() % static_cast<unsigned>(4 - dp));
    const int bits = root_bits[trial % 7];
    std::vector<Q> roots;
    for (int i = 0; i < dp; ++i)
      roots.push_back(i > 0 && rng() % 4 == 0 ? roots.back() : random_rational(rng, bits));
    const long scale = (rng() % 2 ? 1 : -1) * static_cast<long>(1 + rng() % 1000);
    const MpzPolynomial p = to_mpz_polynomial(with_roots(roots, scale));
    // g = p u + c, deg u = dg - dp.
    std::array<mpz_class, 4> g{};
    std::array<mpz_class, 4> u{};
    for (int i = 0; i <= dg - dp; ++i)
      u[static_cast<std::size_t>(i)] = random_integer(rng, 1 + static_cast<int>(rng() % (3 * bits)));
    if (u[static_cast<std::size_t>(dg - dp)] == 0) u[static_cast<std::size_t>(dg - dp)] = 1;
    for (int i = 0; i <= dp; ++i)
      for (int j = 0; j <= dg - dp; ++j)
        g[static_cast<std::size_t>(i + j)] += p.c[static_cast<std::size_t>(i)] * u[static_cast<std::size_t>(j)];
    const int kind = static_cast<int>(rng() % 3);  // 0: c = 0, 1: constant, 2: degree >= 1
    if (kind == 1) g[0] += random_integer(rng, 1 + static_cast<int>(rng() % (3 * bits)));
    if (kind == 2 && dp >= 2) {
      g[0] += random_integer(rng, 8);
      g[1] += 1 + abs(random_integer(rng, 8));
    }
    const SmallPolynomial gs = SmallPolynomial::from_mpz(g.data(), 4);
    const SmallPolynomial ps = SmallPolynomial::from_mpz(p.c.data(), 4);
    int sign = 2;
    const bool answered = gs.sign_at_roots_of(ps, &sign);
    if (kind == 2 && dp >= 2) {
      EXPECT_FALSE(answered) << "a remainder of degree >= 1 was taken for a constant";
      continue;
    }
    // The fixed-size bound: b_g + n (b_p + 1) within 16 limbs, else declined.
    const bool fits = fixed_limbs_for(gs.bits() + (dg - dp + 1) * (ps.bits() + 1)) != 0;
    EXPECT_EQ(answered, fits) << "dp " << dp << " dg " << dg << " bits " << gs.bits() << ", "
                              << ps.bits();
    if (!answered) continue;
    ++decided;
    zero += sign == 0;
    const RationalPolynomial gr = rational(g, dg);
    for (const Q& r : roots)
      ASSERT_EQ(sign, sgn(gr.at(r))) << "dp " << dp << " dg " << dg << " kind " << kind
                                     << " root " << r << " lc(p) " << p.c[static_cast<std::size_t>(dp)];
  }
  EXPECT_GT(decided, n / 2);
  EXPECT_GT(zero, n / 8);
}

TEST_F(SmallPolynomialTest, GcdAndSquareFreePart) {
  const Q third(1, 3);
  const SmallPolynomial p = with_roots({third, third, Q(1, 2)}, 6);
  const SmallPolynomial s = square_free_part(p);
  EXPECT_EQ(s.degree(), 2);
  EXPECT_EQ(s.sign_at(0.5), 0);
  const MpzPolynomial h =
      polynomial_gcd(to_mpz_polynomial(p), to_mpz_polynomial(with_roots({third, Q(1, 5)})));
  ASSERT_EQ(h.degree, 1);
  EXPECT_EQ(h.c[1] * third + h.c[0], 0);  // 3t - 1, primitive
  EXPECT_GT(h.c[1], 0);
}

}  // namespace
}  // namespace exactccd::exact
