// Univariate polynomials over the exact rationals, with the few operations root isolation
// needs: arithmetic, exact evaluation, division with remainder, gcd and Taylor shift.
#pragma once

#include <vector>

#include "core/predicates/motion.hpp"
#include "exact/rational.hpp"

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

}  // namespace exactccd::exact
