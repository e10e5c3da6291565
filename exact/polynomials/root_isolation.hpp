// Exact isolation of the real roots of a rational polynomial in a closed interval
// (Sturm sequences, bisection). PROOF: proofs/exact_ccd.md#lemma-root-isolation
#pragma once

#include <vector>

#include "exact/polynomials/algebraic_time.hpp"

namespace exactccd::exact {

class SturmSequence {
 public:
  /// p square-free and non-zero.
  explicit SturmSequence(const Polynomial& p);
  /// Sign changes of the sequence at t, zeros skipped.
  int variations(const Rational& t) const;
  /// Number of distinct roots in the half-open interval (a, b], a < b (any a, b).
  int count_roots(const Rational& a, const Rational& b) const {
    return variations(a) - variations(b);
  }

 private:
  std::vector<Polynomial> seq_;
};

/// True when p (non-zero) certainly has no root in [a, b] (a < b): p(a) and p(b) non-zero and
/// no sign variation among the coefficients of (1 + x)^d p(a + (b - a) x / (1 + x)), whose
/// positive roots are p's roots in (a, b) (Descartes' rule of signs). False decides nothing.
/// PROOF: proofs/min_separation.md#root-free-polynomials
bool certainly_root_free(const Polynomial& p, const Rational& a, const Rational& b);

/// The distinct real roots of the non-zero polynomial p in [a, b] (0 <= a < b), ascending,
/// each a rational AlgebraicTime or an isolating interval of p's square-free part.
std::vector<AlgebraicTime> real_roots_in(const Polynomial& p, const Rational& a,
                                         const Rational& b);

}  // namespace exactccd::exact
