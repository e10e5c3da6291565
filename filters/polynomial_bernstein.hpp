// A polynomial of degree N in the Bernstein basis on [0, t_max], and de Casteljau halving,
// written over the number type (instantiated with Interval for certified enclosures: every
// coefficient interval then contains the exact Bernstein coefficient). Convex-hull property:
// on a parameter interval the polynomial lies between its smallest and largest Bernstein
// coefficient, and its derivative between N times the smallest and largest difference of
// consecutive ones. PROOF: proofs/rigid_ccd.md#root-isolation
#pragma once

#include <array>
#include <cstddef>

#include "core/predicates/motion.hpp"
#include "filters/certified_numbers.hpp"

namespace exactccd::filters {

template <class NT, int N>
using Bernstein = std::array<NT, N + 1>;

constexpr int binomial(int n, int k) {
  int r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// Bernstein coefficients on u in [0, 1] of f(t_max u), from the power basis in t:
/// with a_i = f_i t_max^i / C(N, i), b_j = sum_{i <= j} C(j, i) a_i.
template <class NT, int N>
EXACTCCD_CERTIFIED Bernstein<NT, N> bernstein_of(const predicates::FixedPoly<NT, N>& f,
                                                 const NT& t_max) {
  NT a[N + 1];
  NT power(1);
  for (int i = 0; i <= N; ++i) {
    a[i] = f.c[i] * power / NT(binomial(N, i));
    power = power * t_max;
  }
  Bernstein<NT, N> b;
  for (int j = 0; j <= N; ++j) {
    NT sum = a[0];
    for (int i = 1; i <= j; ++i) sum = sum + NT(binomial(j, i)) * a[i];
    b[j] = sum;
  }
  return b;
}

/// The cubic's coefficients by the same formula written out: fewer operations (the coplanarity
/// cubic of every linear query passes here). PROOF: proofs/filters.md#bernstein-no-root
template <class NT>
EXACTCCD_CERTIFIED Bernstein<NT, 3> bernstein_of(const predicates::FixedPoly<NT, 3>& f,
                                                 const NT& t_max) {
  const NT a1 = f.c[1] * t_max;
  const NT a2 = f.c[2] * t_max * t_max;
  const NT a3 = f.c[3] * t_max * t_max * t_max;
  return {f.c[0], f.c[0] + a1 / 3, f.c[0] + (a1 * 2 + a2) / 3, f.c[0] + a1 + a2 + a3};
}

/// Bernstein coefficients of the two halves of the parameter interval (degree N = M - 1).
template <class NT, std::size_t M>
EXACTCCD_CERTIFIED void de_casteljau_halves(const std::array<NT, M>& b, std::array<NT, M>& left,
                                            std::array<NT, M>& right) {
  constexpr int N = static_cast<int>(M) - 1;
  std::array<NT, M> work = b;
  left[0] = work[0];
  right[N] = work[N];
  for (int r = 1; r <= N; ++r) {
    for (int i = 0; i + r <= N; ++i) work[i] = (work[i] + work[i + 1]) * NT(0.5);
    left[r] = work[0];
    right[N - r] = work[N - r];
  }
}

/// The sign every coefficient certainly has (so the polynomial has on the whole interval), or 0.
template <std::size_t M>
EXACTCCD_CERTIFIED int strict_sign_of_all(const std::array<Interval, M>& b) {
  const int s = certain_strict_sign(b[0]);
  for (std::size_t i = 1; i < M && s != 0; ++i)
    if (!certainly_has_sign(b[i], s)) return 0;
  return s;
}

/// The derivative's Bernstein coefficients N (b[i+1] - b[i]) all of one certain strict sign.
template <std::size_t M>
EXACTCCD_CERTIFIED bool certainly_monotone(const std::array<Interval, M>& b) {
  const int d = certain_strict_sign(b[1] - b[0]);
  if (d == 0) return false;
  for (std::size_t i = 1; i + 1 < M; ++i)
    if (!certainly_has_sign(b[i + 1] - b[i], d)) return false;
  return true;
}

}  // namespace exactccd::filters
