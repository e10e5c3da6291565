// PROOF: proofs/exact_ccd.md#interval-sign-at-an-irrational
#include "exact/interval_sign_at_irrational.hpp"

#include <mpfr.h>

#include <algorithm>

namespace exactccd::exact {

namespace {

thread_local IntervalIrrationalCounts g_counts;

/// MPFR numbers of one precision, cleared on every return. MPFR rounds each operation in the
/// direction it is given, whatever the hardware's rounding mode.
class Numbers {
 public:
  static constexpr int kCount = 12;
  explicit Numbers(mpfr_prec_t precision) {
    for (mpfr_t& x : x_) mpfr_init2(x, precision);
  }
  ~Numbers() {
    for (mpfr_t& x : x_) mpfr_clear(x);
  }
  Numbers(const Numbers&) = delete;
  Numbers& operator=(const Numbers&) = delete;
  mpfr_ptr operator[](int i) { return x_[i]; }

 private:
  mpfr_t x_[kCount];
};

/// [lo, hi] := [lo, hi] [s_lo, s_hi], rounded outward: for s_lo >= 0 (the roots the stage
/// asks about lie in [0, 1]) each end is one product, chosen by the sign of that end; else the
/// least and the greatest of the four end-point products (t: eight temporaries).
void multiply(mpfr_ptr lo, mpfr_ptr hi, mpfr_srcptr s_lo, mpfr_srcptr s_hi, mpfr_ptr (&t)[8]) {
  if (mpfr_sgn(s_lo) >= 0) {
    mpfr_mul(t[0], lo, mpfr_sgn(lo) >= 0 ? s_lo : s_hi, MPFR_RNDD);
    mpfr_mul(hi, hi, mpfr_sgn(hi) >= 0 ? s_hi : s_lo, MPFR_RNDU);
    mpfr_swap(lo, t[0]);
    return;
  }
  mpfr_srcptr a[2] = {lo, hi}, b[2] = {s_lo, s_hi};
  for (int i = 0; i < 4; ++i) {
    mpfr_mul(t[i], a[i / 2], b[i % 2], MPFR_RNDD);
    mpfr_mul(t[4 + i], a[i / 2], b[i % 2], MPFR_RNDU);
  }
  mpfr_ptr least = t[0], greatest = t[4];
  for (int i = 1; i < 4; ++i) {
    if (mpfr_less_p(t[i], least)) least = t[i];
    if (mpfr_greater_p(t[4 + i], greatest)) greatest = t[4 + i];
  }
  mpfr_set(lo, least, MPFR_RNDN);  // exact: the same precision
  mpfr_set(hi, greatest, MPFR_RNDN);
}

/// The sign of p(s) when its enclosure at `precision` bits excludes 0, else 0 (undecided).
int sign_at_precision(const MpzPolynomial& p, const mpz_class& P, int tau, const mpz_class& D,
                      const mpz_class& Q, mpfr_prec_t precision) {
  Numbers n(precision);
  mpfr_ptr s_lo = n[0], s_hi = n[1], v_lo = n[2], v_hi = n[3];
  mpfr_ptr t[8] = {n[4], n[5], n[6], n[7], n[8], n[9], n[10], n[11]};
  // [s_lo, s_hi] holds s = (P + tau sqrt(D)) / Q: sqrt(D) from D's roundings (D >= 0, sqrt
  // increasing), negated exactly, P added and Q divided with each end rounded outward.
  mpfr_set_z(s_lo, D.get_mpz_t(), MPFR_RNDD);
  mpfr_sqrt(s_lo, s_lo, MPFR_RNDD);
  mpfr_set_z(s_hi, D.get_mpz_t(), MPFR_RNDU);
  mpfr_sqrt(s_hi, s_hi, MPFR_RNDU);
  if (tau < 0) {
    mpfr_swap(s_lo, s_hi);
    mpfr_neg(s_lo, s_lo, MPFR_RNDN);  // exact
    mpfr_neg(s_hi, s_hi, MPFR_RNDN);
  }
  mpfr_add_z(s_lo, s_lo, P.get_mpz_t(), MPFR_RNDD);
  mpfr_add_z(s_hi, s_hi, P.get_mpz_t(), MPFR_RNDU);
  if (sgn(Q) < 0) mpfr_swap(s_lo, s_hi);  // dividing by a negative number swaps the ends
  mpfr_div_z(s_lo, s_lo, Q.get_mpz_t(), MPFR_RNDD);
  mpfr_div_z(s_hi, s_hi, Q.get_mpz_t(), MPFR_RNDU);
  // p(s) by Horner's rule: each step's interval holds the exact partial value at s.
  const auto& c = p.c;
  mpfr_set_z(v_lo, c[static_cast<std::size_t>(p.degree)].get_mpz_t(), MPFR_RNDD);
  mpfr_set_z(v_hi, c[static_cast<std::size_t>(p.degree)].get_mpz_t(), MPFR_RNDU);
  for (int i = p.degree - 1; i >= 0; --i) {
    multiply(v_lo, v_hi, s_lo, s_hi, t);
    mpfr_add_z(v_lo, v_lo, c[static_cast<std::size_t>(i)].get_mpz_t(), MPFR_RNDD);
    mpfr_add_z(v_hi, v_hi, c[static_cast<std::size_t>(i)].get_mpz_t(), MPFR_RNDU);
  }
  if (mpfr_sgn(v_lo) > 0) return 1;
  if (mpfr_sgn(v_hi) < 0) return -1;
  return 0;
}

}  // namespace

std::optional<int> interval_sign_at_irrational(const MpzPolynomial& p, const mpz_class& P,
                                               int tau, const mpz_class& D, const mpz_class& Q,
                                               long max_bits) {
  if (p.degree < 0 || sgn(Q) == 0 || sgn(D) < 0) return std::nullopt;  // not ours to decide
  for (long bits = 128; bits <= max_bits; bits *= 4) {
    ++g_counts.attempts;
    if (const int sign = sign_at_precision(p, P, tau, D, Q, static_cast<mpfr_prec_t>(bits))) {
      ++g_counts.decided;
      return sign;
    }
  }
  return std::nullopt;
}

long max_coefficient_bits(const MpzPolynomial& p) {
  long bits = 0;
  for (int i = 0; i <= p.degree; ++i)
    bits = std::max(
        bits, static_cast<long>(mpz_sizeinbase(p.c[static_cast<std::size_t>(i)].get_mpz_t(), 2)));
  return bits;
}

IntervalIrrationalCounts interval_irrational_counts_in_this_thread() noexcept { return g_counts; }

}  // namespace exactccd::exact
