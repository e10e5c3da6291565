// Double-double arithmetic (core/predicates/double_double.hpp), used only for root guesses: sums
// and products of two doubles are exact (hi + lo equals the exact value, checked in rationals), and
// a double-double expression's value is within 2^-100 of its magnitude's terms on random inputs,
// where plain doubles lose everything (a difference of large equal-ish products).
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>

#include "core/predicates/double_double.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using predicates::dd::DoubleDouble;

mpq_class exact(const DoubleDouble& x) { return mpq_class(x.hi) + mpq_class(x.lo); }

TEST(DoubleDouble, SumsAndProductsOfTwoDoublesAreExact) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 10000; ++i) {
    const double a = std::ldexp(u(rng), static_cast<int>(rng() % 60) - 30);
    const double b = std::ldexp(u(rng), static_cast<int>(rng() % 60) - 30);
    EXPECT_EQ(exact(predicates::dd::difference(a, b)), mpq_class(a) - mpq_class(b));
    EXPECT_EQ(exact(DoubleDouble{a, 0} * DoubleDouble{b, 0}), mpq_class(a) * mpq_class(b));
  }
}

TEST(DoubleDouble, KeepsAboutOneHundredBitsWherePlainDoublesCancel) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  int plain_lost = 0;
  for (int i = 0; i < 10000; ++i) {
    // x y - z w with z w = x y (1 + 2^-60): the difference is about 2^-60 of the products.
    const double x = 1 + u(rng), y = 1 + u(rng), z = x * (1 + 0x1p-30), w = y * (1 - 0x1p-30);
    const DoubleDouble r = DoubleDouble{x, 0} * DoubleDouble{y, 0} -
                           DoubleDouble{z, 0} * DoubleDouble{w, 0};
    const mpq_class truth = mpq_class(x) * y - mpq_class(z) * w;
    const mpq_class error = exact(r) - truth;
    EXPECT_LE(std::fabs(error.get_d()), 0x1p-100 * 4) << i;
    plain_lost += (x * y - z * w) != truth.get_d();
  }
  EXPECT_GT(plain_lost, 1000);  // the case is one where plain doubles do lose
}

}  // namespace
}  // namespace exactccd
