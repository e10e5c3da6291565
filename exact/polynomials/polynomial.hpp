// Univariate polynomials over the exact rationals, with the few operations root isolation
// needs: arithmetic, exact evaluation, division with remainder, gcd and Taylor shift.
#pragma once

#include <vector>

#include "core/predicates/motion.hpp"
#include "exact/arithmetic/rational.hpp"

namespace exactccd::exact {

class Polynomial {
 public:
  Polynomial() = default;
  /// Coefficients, c[i] of t^i; trailing zeros are removed.
  explicit Polynomial(std::vector<Rational> c);
  template <int D>
  explicit Polynomial(const predicates::FixedPoly<Rational, D>& p)
      : Polynomial(std::vector<Rational>(p.c.begin(), p.c.end())) {}

  /// -1 for the zero polynomial.
  int degree() const { return static_cast<int>(c_.size()) - 1; }
  bool is_zero() const { return c_.empty(); }
  /// Every coefficient an integer.
  bool has_integer_coefficients() const { return integer_; }
  const std::vector<Rational>& coefficients() const { return c_; }
  const Rational& leading() const { return c_.back(); }

  Rational evaluate(const Rational& t) const;
  /// The exact sign of p(t); in integer arithmetic when every coefficient is an integer
  /// (no normalising gcds), else by evaluate.
  int sign_at(const Rational& t) const;

  Polynomial derivative() const;
  /// This polynomial divided by its leading coefficient (zero stays zero).
  Polynomial monic() const;
  /// g(s) = p(t0 + s), coefficient-wise.
  Polynomial taylor_shift(const Rational& t0) const;

  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a);
  /// Euclidean division a = q b + r, deg r < deg b; b must be non-zero.
  friend void divide(const Polynomial& a, const Polynomial& b, Polynomial* q, Polynomial* r);
  /// The monic gcd (zero only when both are zero).
  friend Polynomial gcd(Polynomial a, Polynomial b);

 private:
  void trim();
  std::vector<Rational> c_;
  bool integer_ = true;  // every coefficient an integer
};

/// p / gcd(p, p'): same roots, all simple. p must be non-zero.
Polynomial square_free_part(const Polynomial& p);

/// The positive multiple of p with coprime integer coefficients (zero stays zero): the same
/// roots and the same signs everywhere, integer evaluations.
Polynomial primitive_part(const Polynomial& p);

/// For a and b with integer coefficients, deg a >= deg b >= 0: the pseudo-remainder
/// r = lc(b)^e a - Q b, e = deg a - deg b + 1, deg r < deg b, in integers; *sign = sign(lc(b)^e),
/// so that where b vanishes, a has the sign of *sign times r.
Polynomial pseudo_remainder(const Polynomial& a, const Polynomial& b, int* sign);

/// Descartes' rule of signs on [0, 1] for R(y) = sum_i r_i y^i (integer or rational r): true
/// when R(0), R(1) are non-zero and S(x) = sum_i r_i x^i (1 + x)^(d - i), whose positive roots
/// are R's roots in (0, 1), has no sign variation: then R has no root in [0, 1].
/// PROOF: proofs/min_separation.md#root-free-polynomials
template <class T>
bool no_root_on_unit_interval(const std::vector<T>& r) {
  const int d = static_cast<int>(r.size()) - 1;
  if (d < 0) return false;
  std::vector<T> s(r.size());
  for (int i = 0; i <= d; ++i) {
    if (sgn(r[i]) == 0) continue;
    long binomial = 1;  // C(d - i, k)
    for (int k = 0; k <= d - i; ++k) {
      s[i + k] += r[i] * binomial;
      binomial = binomial * (d - i - k) / (k + 1);
    }
  }
  if (sgn(s.front()) == 0 || sgn(s.back()) == 0) return false;  // R(0) = 0 or R(1) = 0
  const int first = sgn(s.front());
  for (const T& x : s)
    if (sgn(x) == -first) return false;
  return true;
}

/// Whether p (integer coefficients, non-zero) certainly has no root in [a, b], a < b dyadic
/// (A 2^-K, B 2^-K): p(a), p(b) non-zero and no sign variation in the coefficients of
/// (1 + x)^d p(a + (b - a) x / (1 + x)) (Descartes' rule of signs), all in integers. False
/// decides nothing. PROOF: proofs/min_separation.md#root-free-polynomials
bool descartes_root_free_dyadic(const Polynomial& p, const mpz_class& A, const mpz_class& B,
                                unsigned long K);

/// k with q = Q 2^-k for an integer Q, or -1 when q's denominator is not a power of two.
long dyadic_exponent(const Rational& q);

}  // namespace exactccd::exact
