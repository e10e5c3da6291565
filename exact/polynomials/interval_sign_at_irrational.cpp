// PROOF: proofs/exact_ccd.md#interval-sign-at-an-irrational
#include "exact/polynomials/interval_sign_at_irrational.hpp"

#include <mpfr.h>

#include <algorithm>

namespace exactccd::exact {

namespace {

thread_local IntervalIrrationalCounts g_counts;

/// The first precision tried, doubled at each further attempt. Every attempt converts p's wide
/// coefficients, so each costs at least a pass over their bits: few attempts pay. (On spreads
/// of +-300 most signs need 512 bits, on +-1000 up to 2,048; a speed setting only.)
constexpr long kFirstPrecision = 512;

/// [lo, hi] in MPFR at one precision, cleared on return. MPFR rounds each operation in the
/// direction it is given, whatever the hardware's rounding mode.
class Interval {
 public:
  explicit Interval(mpfr_prec_t precision) {
    mpfr_init2(lo, precision);
    mpfr_init2(hi, precision);
  }
  ~Interval() {
    mpfr_clear(lo);
    mpfr_clear(hi);
  }
  Interval(const Interval&) = delete;
  Interval& operator=(const Interval&) = delete;

  void set(const mpz_class& z) {
    mpfr_set_z(lo, z.get_mpz_t(), MPFR_RNDD);
    mpfr_set_z(hi, z.get_mpz_t(), MPFR_RNDU);
  }
  void add(const mpz_class& z) {
    mpfr_add_z(lo, lo, z.get_mpz_t(), MPFR_RNDD);
    mpfr_add_z(hi, hi, z.get_mpz_t(), MPFR_RNDU);
  }
  /// this *= s, rounded outward: for s.lo >= 0 each end is one product, chosen by the sign of
  /// that end; else the least of the four end-point products rounded down and the greatest
  /// rounded up (t: scratch of the same precision).
  void multiply(const Interval& s, Interval (&t)[4]) {
    if (mpfr_sgn(s.lo) >= 0) {
      mpfr_mul(t[0].lo, lo, mpfr_sgn(lo) >= 0 ? s.lo : s.hi, MPFR_RNDD);
      mpfr_mul(hi, hi, mpfr_sgn(hi) >= 0 ? s.hi : s.lo, MPFR_RNDU);
      mpfr_swap(lo, t[0].lo);
      return;
    }
    mpfr_srcptr a[2] = {lo, hi}, b[2] = {s.lo, s.hi};
    for (int i = 0; i < 4; ++i) {
      mpfr_mul(t[i].lo, a[i / 2], b[i % 2], MPFR_RNDD);
      mpfr_mul(t[i].hi, a[i / 2], b[i % 2], MPFR_RNDU);
    }
    mpfr_ptr least = t[0].lo, greatest = t[0].hi;
    for (int i = 1; i < 4; ++i) {
      if (mpfr_less_p(t[i].lo, least)) least = t[i].lo;
      if (mpfr_greater_p(t[i].hi, greatest)) greatest = t[i].hi;
    }
    mpfr_swap(lo, least);  // the same precision: exact
    mpfr_swap(hi, greatest);
  }
  /// +1 or -1 when the interval excludes 0, else 0.
  int sign() const {
    if (mpfr_sgn(lo) > 0) return 1;
    if (mpfr_sgn(hi) < 0) return -1;
    return 0;
  }

  mpfr_t lo, hi;
};

/// The sign of p(s) when its enclosure at `precision` bits excludes 0, else 0 (undecided).
int sign_at_precision(const MpzPolynomial& p, const mpz_class& P, int tau, const mpz_class& D,
                      const mpz_class& Q, mpfr_prec_t precision) {
  Interval s(precision), v(precision);
  Interval t[4] = {Interval(precision), Interval(precision), Interval(precision),
                   Interval(precision)};
  // s holds (P + tau sqrt(D)) / Q: sqrt(D) from D's roundings (D >= 0, sqrt increasing),
  // negated exactly, P added and Q divided with each end rounded outward.
  mpfr_set_z(s.lo, D.get_mpz_t(), MPFR_RNDD);
  mpfr_sqrt(s.lo, s.lo, MPFR_RNDD);
  mpfr_set_z(s.hi, D.get_mpz_t(), MPFR_RNDU);
  mpfr_sqrt(s.hi, s.hi, MPFR_RNDU);
  if (tau < 0) {
    mpfr_swap(s.lo, s.hi);
    mpfr_neg(s.lo, s.lo, MPFR_RNDN);  // exact
    mpfr_neg(s.hi, s.hi, MPFR_RNDN);
  }
  s.add(P);
  if (sgn(Q) < 0) mpfr_swap(s.lo, s.hi);  // dividing by a negative number swaps the ends
  mpfr_div_z(s.lo, s.lo, Q.get_mpz_t(), MPFR_RNDD);
  mpfr_div_z(s.hi, s.hi, Q.get_mpz_t(), MPFR_RNDU);
  // p(s) by Horner's rule: each step's interval holds the exact partial value at s.
  v.set(p.c[static_cast<std::size_t>(p.degree)]);
  for (int i = p.degree - 1; i >= 0; --i) {
    v.multiply(s, t);
    v.add(p.c[static_cast<std::size_t>(i)]);
  }
  return v.sign();
}

}  // namespace

std::optional<int> interval_sign_at_irrational(const MpzPolynomial& p, const mpz_class& P,
                                               int tau, const mpz_class& D, const mpz_class& Q,
                                               long max_bits) {
  if (p.degree < 0 || sgn(Q) == 0 || sgn(D) < 0) return std::nullopt;  // not ours to decide
  for (long bits = kFirstPrecision; bits <= max_bits; bits *= 2) {
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
