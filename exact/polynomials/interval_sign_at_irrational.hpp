// The sign of an integer polynomial at a quadratic irrational (P + tau sqrt(D)) / Q from
// interval enclosures in MPFR (directed rounding) at increasing precision: what the exact
// algebraic signs try first where their integers are wide. The exact computation (prem and a
// squared comparison) multiplies the bit lengths of its inputs; the enclosure needs only as
// many bits as |p(s)| is smaller than p's terms, which on inputs of widely spread exponents is
// often far fewer. An exact zero is never decided here: its enclosure always contains 0, and
// the caller decides exactly.
// PROOF: proofs/exact_ccd.md#interval-sign-at-an-irrational
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <optional>

#include "exact/polynomials/small_polynomial.hpp"

namespace exactccd::exact {

/// The sign of p at s = (P + tau sqrt(D)) / Q (Q != 0, D >= 0, tau = +-1) when an outward-
/// rounded interval evaluation at some precision of 512 * 2^i bits, at most `max_bits`,
/// excludes 0; nullopt otherwise (never for p(s) = 0 exactly).
std::optional<int> interval_sign_at_irrational(const MpzPolynomial& p, const mpz_class& P,
                                               int tau, const mpz_class& D, const mpz_class& Q,
                                               long max_bits);

/// Where the exact sign at an irrational would multiply integers of more bits than this (the
/// callers estimate bits(p) + 3 bits(h), h the polynomial whose root it is), the enclosure is
/// tried first. Below it the exact integers are cheap, and an enclosure that fails (at an
/// exact root, e.g. a touching contact) would cost more than it saves. A speed setting only.
constexpr long kIntervalFirstBits = 4096;

/// The largest bit length of p's coefficients.
long max_coefficient_bits(const MpzPolynomial& p);

/// How many interval attempts (one per precision) the calling thread made, and how many of
/// them decided: for tests and benchmarks.
struct IntervalIrrationalCounts {
  std::uint64_t attempts = 0, decided = 0;
};
IntervalIrrationalCounts interval_irrational_counts_in_this_thread() noexcept;

}  // namespace exactccd::exact
