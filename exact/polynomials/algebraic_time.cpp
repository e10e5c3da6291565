#include "exact/polynomials/algebraic_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "core/predicates/double_bits.hpp"

namespace exactccd::exact {

namespace {
using predicates::bits_of;
using predicates::double_of;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

bool no_double_strictly_between(const Rational& lo, const Rational& hi) {
  const double first_above = std::nextafter(round_down(lo), kInf);
  return cmp(Rational(first_above), hi) >= 0;
}

Rational split_point(const Rational& lo, const Rational& hi) {
  if (sgn(lo) >= 0) {
    const double first = std::nextafter(round_down(lo), kInf);  // smallest double > lo
    const double last = std::nextafter(round_up(hi), -kInf);    // largest double < hi
    if (first <= last) {
      // For non-negative doubles the bit patterns are ordered like the values, so the middle
      // pattern halves the number of doubles left: at most 64 steps to the tightest pair.
      const std::uint64_t a = bits_of(first), b = bits_of(last);
      return Rational(double_of(a + (b - a) / 2));
    }
  }
  Rational mid = lo + hi;
  mid /= 2;
  return mid;
}

AlgebraicTime AlgebraicTime::rational(Rational value) {
  AlgebraicTime t;
  t.set_rational(std::move(value));
  return t;
}

AlgebraicTime::AlgebraicTime(Polynomial f, Rational lo, Rational hi)
    : f_(std::move(f)), lo_(std::move(lo)), hi_(std::move(hi)) {
  sign_f_lo_ = f_.sign_at(lo_);
  if (cmp(lo_, hi_) >= 0 || sign_f_lo_ == 0 || f_.sign_at(hi_) != -sign_f_lo_)
    throw std::logic_error("exactccd: AlgebraicTime needs a sign change of f on (lo, hi)");
}

void AlgebraicTime::set_rational(Rational value) {
  lo_ = value;
  hi_ = std::move(value);
  rational_ = true;
}

void AlgebraicTime::refine_once() {
  if (rational_) return;
  Rational m = split_point(lo_, hi_);
  const int s = f_.sign_at(m);
  if (s == 0) {
    set_rational(std::move(m));
  } else if (s == sign_f_lo_) {
    lo_ = std::move(m);
  } else {
    hi_ = std::move(m);
  }
}

int AlgebraicTime::sign_of(const Polynomial& g) {
  if (g.is_zero()) return 0;
  if (rational_) return g.sign_at(lo_);
  // g(t) = sign rho(t) with deg rho < deg f, since f(t) = 0: for an integer f the primitive
  // pseudo-remainder (integers, no normalising gcd; proofs (b')), else the rational remainder.
  int sign = 1;
  Polynomial rho;
  if (f_.has_integer_coefficients()) {
    const Polynomial G = primitive_part(g);  // a positive multiple: the same sign at t
    rho = G.degree() < f_.degree() ? G : primitive_part(pseudo_remainder(G, f_, &sign));
  } else {
    divide(g, f_, nullptr, &rho);
  }
  return sign * reduced_sign_of(rho);
}

int AlgebraicTime::reduced_sign_of(const Polynomial& rho) {
  if (rho.degree() <= 0) return rho.is_zero() ? 0 : sgn(rho.leading());
  if (rho.degree() == 1) {
    // rho = c1 t + c0 has the sign of c1 (t - q), q = -c0 / c1.
    const Rational q = -rho.coefficients()[0] / rho.coefficients()[1];
    return sgn(rho.coefficients()[1]) * compare(q);
  }
  bool zero_checked = false;
  for (;;) {
    if (rational_) return rho.sign_at(lo_);
    if (const int s = sign_if_root_free(rho); s != 0) return s;
    if (!zero_checked) {
      // rho(t) = 0 iff gcd(f, rho) vanishes at t; the gcd divides the square-free f, so its
      // only possible root in (lo, hi) is t, simple, and shows as a sign change.
      const Polynomial h = gcd(f_, rho);
      if (h.degree() >= 1 && h.sign_at(lo_) != h.sign_at(hi_)) return 0;
      zero_checked = true;
    }
    // Halve the interval's width before the next (costlier) test: across binades one
    // bit-order split may shrink the width very little.
    const Rational target = (hi_ - lo_) / 2;
    while (!rational_ && cmp(hi_ - lo_, target) > 0) refine_once();
  }
}

int AlgebraicTime::sign_if_root_free(const Polynomial& rho) const {
  // PROOF: proofs/exact_ccd.md#lemma-sign-at-algebraic-time
  const long kl = dyadic_exponent(lo_), kh = dyadic_exponent(hi_);
  if (rho.has_integer_coefficients() && kl >= 0 && kh >= 0) {
    // Descartes' rule on the dyadic interval, in integers (b').
    const auto K = static_cast<unsigned long>(std::max(kl, kh));
    mpz_class A, B;
    mpz_mul_2exp(A.get_mpz_t(), lo_.get_num_mpz_t(), K - static_cast<unsigned long>(kl));
    mpz_mul_2exp(B.get_mpz_t(), hi_.get_num_mpz_t(), K - static_cast<unsigned long>(kh));
    return descartes_root_free_dyadic(rho, A, B, K) ? rho.sign_at(lo_) : 0;
  }
  // rho keeps the sign of rho(lo) on [lo, hi] when |rho(lo)| > sum_k |rho^(k)(lo)/k!| w^k.
  const Polynomial shifted = rho.taylor_shift(lo_);
  const auto& d = shifted.coefficients();
  const Rational w = hi_ - lo_;
  Rational bound = 0, wk = 1;
  for (std::size_t k = 1; k < d.size(); ++k) {
    wk *= w;
    bound += abs(d[k]) * wk;
  }
  const Rational rho_lo = d.empty() ? Rational(0) : d[0];
  return cmp(abs(rho_lo), bound) > 0 ? sgn(rho_lo) : 0;
}

int AlgebraicTime::compare(const Rational& q) {
  if (rational_) return cmp(lo_, q);
  if (cmp(q, lo_) <= 0) return 1;
  if (cmp(q, hi_) >= 0) return -1;
  // q lies inside (lo, hi), which holds the single, simple root t of f: f(q) has the sign of
  // f(lo) exactly when q lies between lo and t.
  const int s = f_.sign_at(q);
  if (s == 0) return 0;
  return s == sign_f_lo_ ? 1 : -1;
}

int compare(AlgebraicTime& a, AlgebraicTime& b) {
  if (a.is_rational()) return -b.compare(a.lo());
  if (b.is_rational()) return a.compare(b.lo());
  // Equal iff a is a root of b's polynomial inside b's isolating interval, which holds
  // only for b's own root. PROOF: proofs/exact_ccd.md#lemma-sign-at-algebraic-time
  if (cmp(a.hi(), b.lo()) <= 0) return -1;  // isolating intervals already apart
  if (cmp(b.hi(), a.lo()) <= 0) return 1;
  const Rational b_lo = b.lo(), b_hi = b.hi();
  if (a.sign_of(b.defining_polynomial()) == 0 && a.compare(b_lo) > 0 && a.compare(b_hi) < 0)
    return 0;
  for (;;) {  // distinct: refine both until their intervals separate
    if (a.is_rational()) return -b.compare(a.lo());
    if (b.is_rational()) return a.compare(b.lo());
    if (cmp(a.hi(), b.lo()) <= 0) return -1;
    if (cmp(b.hi(), a.lo()) <= 0) return 1;
    a.refine_once();
    b.refine_once();
  }
}

std::pair<double, double> AlgebraicTime::enclosure(double width) {
  for (;;) {
    const double dl = round_down(lo_), dh = round_up(hi_);
    if (rational_ || no_double_strictly_between(lo_, hi_) ||
        (width > 0 && difference_at_most(dh, dl, width)))
      return {dl, dh};
    refine_once();
  }
}

}  // namespace exactccd::exact
