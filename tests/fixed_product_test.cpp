// FixedInt<N>::product of an A-limb and a B-limb integer against GMP, for every pair of widths
// the cubic's kernels use and both of its implementations (native 128-bit multiplications for
// one- and two-limb operands, the schoolbook product otherwise): the product modulo 2^(64N),
// hence the exact product when N >= A + B (proofs/filters.md#fixed-size-exact-at-doubles).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "exact/arithmetic/fixed_int.hpp"
#include "exact/arithmetic/integer_arithmetic.hpp"
#include "test_support.hpp"
#include "fixed_int_support.hpp"

namespace exactccd::test {
namespace {

using exact::FixedInt;

/// Any value of `limbs` limbs: random bit patterns, and the extremes (0, +-1, the most negative
/// and the largest values, single limbs of all ones) that carries and sign corrections meet.
mpz_class random_value(std::mt19937_64& rng, int limbs) {
  const mpz_class top = mpz_class(1) << (64 * limbs - 1);
  mpz_class z = 0;
  switch (rng() % 8) {
    case 0: break;
    case 1: z = rng() % 2 ? 1 : -1; break;
    case 2: z = -top; break;
    case 3: z = top - 1; break;
    case 4: z = mpz_class(rng() % 2 ? -1 : 1) << (64 * (limbs - 1) + rng() % 64); break;
    default:
      for (int i = 0; i < limbs; ++i) z = (z << 64) + exact::mpz_from_u64(rng() >> (rng() % 64));
  }
  return residue(z, limbs);  // a value of `limbs` limbs
}

template <int N, int A, int B>
void check_products(std::mt19937_64& rng, int rounds) {
  SCOPED_TRACE("N = " + std::to_string(N) + ", A = " + std::to_string(A) +
               ", B = " + std::to_string(B));
  for (int i = 0; i < rounds; ++i) {
    const mpz_class a = random_value(rng, A), b = random_value(rng, B);
    const FixedInt<N> p = FixedInt<N>::product(fixed_from<A>(a), fixed_from<B>(b));
    ASSERT_EQ(exact::to_mpz(p), residue(a * b, N)) << a.get_str() << " * " << b.get_str();
    if constexpr (N >= A + B) ASSERT_EQ(exact::to_mpz(p), a * b);
  }
}

TEST(FixedProduct, MatchesGmpForEveryWidthPair) {
  std::mt19937_64 rng(test_seed("fixed products"));
  const int rounds = static_cast<int>(scaled_count(4000, scale_from_environment()));
  check_products<1, 1, 1>(rng, rounds);  // native, reduced
  check_products<2, 1, 1>(rng, rounds);  // native, exact
  check_products<3, 1, 1>(rng, rounds);
  check_products<2, 2, 1>(rng, rounds);  // native, reduced
  check_products<3, 2, 1>(rng, rounds);  // native, exact
  check_products<3, 1, 2>(rng, rounds);
  check_products<5, 2, 1>(rng, rounds);
  check_products<4, 2, 2>(rng, rounds);  // schoolbook
  check_products<6, 4, 2>(rng, rounds);
  check_products<7, 3, 3>(rng, rounds);
  check_products<3, 3, 3>(rng, rounds);  // schoolbook, reduced
}

}  // namespace
}  // namespace exactccd::test
