// A time of the exact path: a rational, or the unique root of a square-free rational
// polynomial f inside an open interval (lo, hi) with rational endpoints, f(lo) f(hi) < 0.
// Signs of other polynomials at such a time are decided exactly.
// PROOF: proofs/exact_ccd.md#lemma-sign-at-algebraic-time
#pragma once

#include <utility>

#include "core/predicates/motion.hpp"
#include "exact/polynomials/polynomial.hpp"

namespace exactccd::exact {

class AlgebraicTime {
 public:
  static AlgebraicTime rational(Rational value);
  /// f square-free, lo < hi, f(lo) and f(hi) non-zero of opposite signs, and the time the
  /// ONLY root of f in (lo, hi) (compare and sign_of rely on it; real_roots_in ensures it).
  AlgebraicTime(Polynomial f, Rational lo, Rational hi);

  bool is_rational() const { return rational_; }
  /// The value when is_rational(), else the current lower end of the isolating interval.
  const Rational& lo() const { return lo_; }
  const Rational& hi() const { return hi_; }
  const Polynomial& defining_polynomial() const { return f_; }

  /// Exact sign (-1, 0, +1) of g at this time. May refine the isolating interval.
  int sign_of(const Polynomial& g);
  template <int D>
  int sign_of(const predicates::FixedPoly<Rational, D>& g) {
    if (rational_) return sgn(horner(g));
    return sign_of(Polynomial(g));
  }

  /// Halves the isolating interval (in the ordering of doubles while a double lies inside it);
  /// may discover that the time is a rational number.
  void refine_once();

  /// Doubles lo <= t <= hi: the tightest such pair when width == 0, otherwise a pair with
  /// hi - lo <= width or the tightest, whichever comes first.
  std::pair<double, double> enclosure(double width);

  /// Exact comparison with a rational.
  int compare(const Rational& q);

 private:
  AlgebraicTime() = default;
  template <int D>
  Rational horner(const predicates::FixedPoly<Rational, D>& g) const {
    Rational r = g.c[D];
    for (int i = D - 1; i >= 0; --i) {
      r *= lo_;
      r += g.c[i];
    }
    return r;
  }
  void set_rational(Rational value);
  /// The sign at this time of rho, of degree below deg f: refines until rho is certainly
  /// root-free on the isolating interval, or the zero test holds.
  int reduced_sign_of(const Polynomial& rho);
  /// rho's sign on all of [lo, hi] when certainly root-free there, else 0: Descartes' rule in
  /// integers (integer rho, dyadic ends), else the rational Taylor bound.
  int sign_if_root_free(const Polynomial& rho) const;

  Polynomial f_;
  Rational lo_, hi_;
  int sign_f_lo_ = 0;
  bool rational_ = false;
};

/// Exact comparison of two algebraic times (-1, 0, +1). May refine both.
int compare(AlgebraicTime& a, AlgebraicTime& b);

/// A point strictly inside (lo, hi), 0 <= lo < hi: the middle double in the ordering of
/// doubles when one lies strictly inside, else the rational midpoint.
Rational split_point(const Rational& lo, const Rational& hi);

/// True when no double lies strictly between lo and hi.
bool no_double_strictly_between(const Rational& lo, const Rational& hi);

}  // namespace exactccd::exact
