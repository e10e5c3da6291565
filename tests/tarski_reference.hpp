// The Sturm-Tarski query of the sign of g at a bracketed root of p: the independent reference
// the tests check sign_at_root_by_remainders against (the exact stage used it before; about 5x
// its cost on wide coefficients, its remainder sequence divides out contents with gcds).
// PROOF: proofs/exact_ccd.md#sign-at-a-bracketed-root
#pragma once

#include <gmpxx.h>

#include "exact/polynomials/small_polynomial.hpp"

namespace exactccd::test {

using exact::MpzPolynomial;

/// Integer polynomials of degree <= 5 (p' g before its reduction modulo p).
struct WidePolynomial {
  mpz_class c[6];
  int degree = -1;
  void set_degree() {
    degree = -1;
    for (int i = 5; i >= 0; --i)
      if (sgn(c[i]) != 0) {
        degree = i;
        return;
      }
  }
};

inline WidePolynomial widen(const MpzPolynomial& p) {
  WidePolynomial w;
  for (int i = 0; i < 4; ++i) w.c[i] = p.c[static_cast<std::size_t>(i)];
  w.set_degree();
  return w;
}

/// A positive multiple of -(a mod b) (deg b >= 0), divided by its content: the next element of
/// a signed remainder sequence up to a positive factor, which changes no sign.
inline WidePolynomial negated_remainder(WidePolynomial r, const WidePolynomial& b) {
  const int sign_lead = sgn(b.c[b.degree]);
  int multiplications = 0;
  while (r.degree >= b.degree) {
    const int shift = r.degree - b.degree;
    const mpz_class lead = r.c[r.degree];
    for (int i = 0; i <= r.degree; ++i) r.c[i] *= b.c[b.degree];
    for (int i = 0; i <= b.degree; ++i) r.c[i + shift] -= lead * b.c[i];
    r.set_degree();
    ++multiplications;
  }
  // r = lc(b)^m (a mod b); -(a mod b) has the sign of -sign(lc(b))^m r.
  const bool negate = !(sign_lead < 0 && multiplications % 2 == 1);
  mpz_class g = 0;
  for (int i = 0; i <= r.degree; ++i) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), r.c[i].get_mpz_t());
  for (int i = 0; i <= r.degree; ++i) {
    mpz_divexact(r.c[i].get_mpz_t(), r.c[i].get_mpz_t(), g.get_mpz_t());
    if (negate) r.c[i] = -r.c[i];
  }
  return r;
}

inline int sign_at_dyadic(const WidePolynomial& p, const mpz_class& T, unsigned k) {
  if (p.degree < 0) return 0;
  mpz_class r = p.c[p.degree];
  for (int i = p.degree - 1; i >= 0; --i) {
    r *= T;
    r += p.c[i] << (k * static_cast<unsigned>(p.degree - i));
  }
  return sgn(r);
}

/// The sign of g at the only root r of p in the open interval (A 2^-K, B 2^-K), where p does
/// not vanish at the ends: Var(a) - Var(b) of the signed remainder sequence of p and
/// (p' g mod p), whose cost does not depend on how close r is to a root of g.
inline int tarski_sign_at_root(const MpzPolynomial& p, const MpzPolynomial& g, const mpz_class& A,
                        const mpz_class& B, unsigned K) {
  if (g.degree < 0) return 0;
  // S0 = p, S1 = positive multiple of (p' g mod p), S_{k+1} = -(S_{k-1} mod S_k) up to a
  // positive factor; at most five elements (degrees strictly decrease from 3).
  WidePolynomial s[6];
  s[0] = widen(p);
  WidePolynomial product;
  for (int i = 1; i <= p.degree; ++i)
    for (int j = 0; j <= g.degree; ++j)
      product.c[i - 1 + j] += p.c[static_cast<std::size_t>(i)] * i * g.c[static_cast<std::size_t>(j)];
  product.set_degree();
  // p' g mod p, as a positive multiple: -(negated remainder) would flip it; negate back.
  s[1] = negated_remainder(product, s[0]);
  for (int i = 0; i <= s[1].degree; ++i) s[1].c[i] = -s[1].c[i];
  int count = 2;
  while (count < 6 && s[count - 1].degree >= 0) {
    if (s[count - 1].degree == 0) break;
    s[count] = negated_remainder(s[count - 2], s[count - 1]);
    if (s[count].degree < 0) break;
    ++count;
  }
  if (s[1].degree < 0) count = 1;  // p' g is a multiple of p... impossible for square-free p
  auto variations = [&](const mpz_class& T) {
    int v = 0, last = 0;
    for (int i = 0; i < count; ++i) {
      const int si = sign_at_dyadic(s[i], T, K);
      if (si == 0) continue;
      if (last != 0 && si != last) ++v;
      last = si;
    }
    return v;
  };
  return variations(A) - variations(B);
}

}  // namespace exactccd::test
