// TwoSum (core/predicates/double_double.hpp): hi + lo equals a + b exactly, checked in
// rationals on random doubles of spread exponents, and hi is the rounded sum.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>

#include "core/predicates/double_double.hpp"

namespace exactccd {
namespace {

using predicates::dd::DoubleDouble;

mpq_class exact(const DoubleDouble& x) { return mpq_class(x.hi) + mpq_class(x.lo); }

TEST(DoubleDouble, TwoSumIsExact) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 10000; ++i) {
    const double a = std::ldexp(u(rng), static_cast<int>(rng() % 120) - 60);
    const double b = std::ldexp(u(rng), static_cast<int>(rng() % 120) - 60);
    const DoubleDouble s = predicates::dd::two_sum(a, b);
    EXPECT_EQ(exact(s), mpq_class(a) + mpq_class(b)) << i;
    EXPECT_EQ(s.hi, a + b) << i;
  }
}

}  // namespace
}  // namespace exactccd
