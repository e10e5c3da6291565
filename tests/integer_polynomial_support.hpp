// Random integers and integer polynomials with known rational roots, for the tests of the exact
// stage's integer polynomials (small_polynomial_test, wide_exponent_stage_test).
#pragma once

#include <gmpxx.h>

#include <random>
#include <vector>

#include "exact/polynomials/small_polynomial.hpp"

namespace exactccd::test {

/// A random integer of exactly `bits` bits (or 0 for bits = 0), random sign.
inline mpz_class random_integer(std::mt19937_64& rng, int bits) {
  if (bits == 0) return 0;
  mpz_class z = 1;
  for (int b = 1; b < bits; ++b) z = 2 * z + static_cast<int>(rng() & 1);
  return (rng() & 1) ? mpz_class(-z) : z;
}

/// The product of (den t - num) over the rational roots, times `scale`.
inline exact::SmallPolynomial with_roots(const std::vector<mpq_class>& roots,
                                         const mpz_class& scale = 1) {
  std::vector<mpz_class> c = {scale};
  for (const mpq_class& r : roots) {
    std::vector<mpz_class> next(c.size() + 1, mpz_class(0));
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i + 1] += c[i] * r.get_den();
      next[i] -= c[i] * r.get_num();
    }
    c = next;
  }
  return exact::SmallPolynomial::from_mpz(c.data(), static_cast<int>(c.size()));
}

}  // namespace exactccd::test
