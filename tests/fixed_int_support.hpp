// FixedInt values built from GMP integers, for the tests that compare fixed-size arithmetic
// with GMP (fixed_exact_test, fixed_product_test, exact_cubic_retry_test).
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <cstdint>

#include "exact/arithmetic/fixed_int.hpp"

namespace exactccd::test {

/// z modulo 2^(64N), as the representative in [-2^(64N-1), 2^(64N-1)).
inline mpz_class residue(const mpz_class& z, int limbs) {
  const mpz_class modulus = mpz_class(1) << (64 * limbs);
  mpz_class r;
  mpz_fdiv_r(r.get_mpz_t(), z.get_mpz_t(), modulus.get_mpz_t());
  if (r >= modulus / 2) r -= modulus;
  return r;
}

/// The FixedInt<N> holding z modulo 2^(64N) (z itself when it fits).
template <int N>
exact::FixedInt<N> fixed_from(const mpz_class& z) {
  const mpz_class r = residue(z, N);
  const mpz_class modulus = mpz_class(1) << (64 * N);
  mpz_class u = r < 0 ? mpz_class(r + modulus) : r;  // the two's complement pattern
  std::uint64_t limbs[N] = {};
  std::size_t count = 0;
  mpz_export(limbs, &count, -1, sizeof limbs[0], 0, 0, u.get_mpz_t());
  return exact::FixedInt<N>::from_limbs(limbs);
}

}  // namespace exactccd::test
