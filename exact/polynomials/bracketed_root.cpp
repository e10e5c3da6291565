// PROOF: proofs/exact_ccd.md#descartes-at-doubles
// PROOF: proofs/exact_ccd.md#sign-at-a-bracketed-root
#include "exact/polynomials/bracketed_root.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>
#include <cstdint>

#include "core/predicates/double_bits.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/polynomials/interval_sign_at_irrational.hpp"

namespace exactccd::exact {

namespace {

/// The doubles lo < hi as a dyadic bracket with a common exponent.
DyadicBracket dyadic_bracket(double lo, double hi, int sign_lo) {
  const Dyadic dl = dyadic(lo), dh = dyadic(hi);
  DyadicBracket d;
  d.K = static_cast<unsigned>(std::max({0, -dl.exponent, -dh.exponent}));
  d.A = dl.mantissa == 0 ? mpz_class(0)
                         : scaled_integer<mpz_class>(dl.mantissa, d.K + dl.exponent);
  d.B = dh.mantissa == 0 ? mpz_class(0)
                         : scaled_integer<mpz_class>(dh.mantissa, d.K + dh.exponent);
  d.sign_lo = sign_lo;
  return d;
}

/// Sign variations of s[0..n), zeros skipped (Descartes).
int variations(const int (&s)[4], int n) {
  int v = 0, last = 0;
  for (int i = 0; i < n; ++i) {
    if (s[i] == 0) continue;
    if (last != 0 && s[i] != last) ++v;
    last = s[i];
  }
  return v;
}

bool one_strict_sign(const int (&s)[4], int n) {
  bool same = s[0] != 0;
  for (int i = 1; i < n && same; ++i) same = s[i] == s[0];
  return same;
}

/// Beyond this many dyadic brackets while isolating roots closer than one ulp a query goes to
/// the rational path (the bound only keeps a pathological input from running long).
constexpr int kMaxDyadicSteps = 4096;

/// The exact sign of g at the root of p in d (the only root of p there, simple; p non-zero at
/// the ends): exact at an exact root, else by remainders (the Sturm-Tarski query's answer at a
/// fraction of its cost).
/// PROOF: proofs/exact_ccd.md#sign-at-a-bracketed-root
/// PROOF: proofs/exact_ccd.md#sign-at-a-root-by-remainders
int sign_in_dyadic_bracket(const MpzPolynomial& p, const MpzPolynomial& g, const DyadicBracket& d) {
  if (d.is_exact()) return sign_at_dyadic(g, d.A, d.K);
  return sign_at_root_by_remainders(p, g, d.A, d.B, d.K, d.sign_lo);
}

/// Beyond this many bits past the doubles' exponent the split at critical points gives up
/// (the bisection below then decides, or the step cap hands the query to the rational path).
constexpr unsigned kMaxCriticalBits = 1u << 14;

/// A dyadic enclosure [L, U] 2^-k of (P + tau sqrt(E)) / Q, Q != 0, E >= 0.
std::pair<mpz_class, mpz_class> enclosure_at(const mpz_class& P, int tau, const mpz_class& E,
                                            const mpz_class& Q, unsigned k) {
  mpz_class S;  // floor(sqrt(E 4^k)) <= sqrt(E) 2^k < S + 1
  mpz_class E_scaled = E << (2 * k);
  mpz_sqrt(S.get_mpz_t(), E_scaled.get_mpz_t());
  const mpz_class base = P << k;
  mpz_class n_lo = tau > 0 ? mpz_class(base + S) : mpz_class(base - S - 1);
  mpz_class n_hi = tau > 0 ? mpz_class(base + S + 1) : mpz_class(base - S);
  if (sgn(S) == 0 && sgn(E) == 0) n_lo = n_hi = base;  // rational: exact numerator
  if (sgn(Q) < 0) {
    std::swap(n_lo, n_hi);
    n_lo = -n_lo;
    n_hi = -n_hi;
  }
  const mpz_class q = abs(Q);
  mpz_class L, U;
  mpz_fdiv_q(L.get_mpz_t(), n_lo.get_mpz_t(), q.get_mpz_t());
  mpz_cdiv_q(U.get_mpz_t(), n_hi.get_mpz_t(), q.get_mpz_t());
  return {L, U};
}

}  // namespace

std::optional<std::vector<DyadicBracket>> split_at_critical_points(const MpzPolynomial& p,
                                                                  const DyadicBracket& d) {
  if (p.degree < 2) return std::nullopt;
  // p' and its real roots c = (P + tau sqrt(E)) / Q; at each, the sign of p from
  // prem(p, p') (of degree <= 1: p(c) = r(c) / lc(p')^n).
  MpzPolynomial dp;
  for (std::size_t i = 1; i <= static_cast<std::size_t>(p.degree); ++i)
    dp.c[i - 1] = p.c[i] * static_cast<unsigned long>(i);
  dp.degree = p.degree - 1;
  mpz_class P, Q, E;
  int roots;
  if (dp.degree == 1) {
    P = -dp.c[0];
    Q = dp.c[1];
    E = 0;
    roots = 1;
  } else {
    E = dp.c[1] * dp.c[1] - 4 * dp.c[2] * dp.c[0];
    P = -dp.c[1];
    Q = 2 * dp.c[2];
    roots = sgn(E) > 0 ? 2 : 0;  // E <= 0: p' keeps one sign, p is monotone: one piece
  }
  int sign_at_critical[2];
  {
    // From an enclosure where the exact integers would be wide, else (or when it cannot tell)
    // exactly, from r = prem(p, p') computed once when first needed.
    const long exact_bits = max_coefficient_bits(p) + 3 * max_coefficient_bits(dp);
    MpzPolynomial r;
    int factor = 0;
    for (int k = 0; k < roots; ++k) {
      const int tau = k == 0 ? 1 : -1;
      std::optional<int> sign;
      if (exact_bits > kIntervalFirstBits)
        sign = interval_sign_at_irrational(p, P, tau, E, Q, exact_bits);
      if (!sign) {
        if (factor == 0) factor = pseudo_remainder(p, dp, &r);
        const mpz_class alpha = r.degree >= 1 ? r.c[1] : mpz_class(0);
        const mpz_class beta = r.degree >= 0 ? r.c[0] : mpz_class(0);
        sign = factor * sgn(Q) * sign_plus_sqrt(alpha * P + beta * Q, tau * alpha, E);
      }
      sign_at_critical[k] = *sign;
    }
  }
  for (unsigned extra = 64; extra <= kMaxCriticalBits; extra *= 2) {
    const unsigned K = d.K + extra;
    const mpz_class lo = d.A << extra, hi = d.B << extra;
    // The critical points' enclosures, ascending, those that can meet (lo, hi).
    std::vector<std::pair<mpz_class, mpz_class>> inside;
    bool resolved = true;
    for (int k = 0; k < roots && resolved; ++k) {
      auto [L, U] = enclosure_at(P, k == 0 ? 1 : -1, E, Q, K);
      if (U <= lo || L >= hi) continue;  // c <= a or c >= b: no piece boundary inside
      if (L <= lo || U >= hi) {          // straddles an end: finer
        resolved = false;
        break;
      }
      // No root of p in [L, U]: p monotone on [L, c] and [c, U], p(L), p(c), p(U) of one sign.
      if (sign_at_dyadic(p, L, K) != sign_at_critical[k] ||
          sign_at_dyadic(p, U, K) != sign_at_critical[k]) {
        resolved = false;
        break;
      }
      inside.emplace_back(std::move(L), std::move(U));
    }
    if (!resolved) continue;
    std::sort(inside.begin(), inside.end());
    if (inside.size() == 2 && inside[0].second >= inside[1].first) continue;  // overlapping
    // The monotone pieces between them: each holds a root iff p changes sign across it.
    std::vector<DyadicBracket> found;
    mpz_class from = lo;
    for (std::size_t k = 0; k <= inside.size(); ++k) {
      const mpz_class to = k < inside.size() ? inside[k].first : hi;
      const int s_from = sign_at_dyadic(p, from, K), s_to = sign_at_dyadic(p, to, K);
      if (s_from * s_to < 0) {
        DyadicBracket b;
        b.A = from;
        b.B = to;
        b.K = K;
        b.sign_lo = s_from;
        found.push_back(std::move(b));
      }
      if (k < inside.size()) from = inside[k].second;
    }
    return found;
  }
  return std::nullopt;
}

namespace {

/// A double strictly inside (lo, hi) near a critical point of p (a root of p', or the real
/// part of its complex pair) that lies in [lo, hi], from p's rounded coefficients; false when
/// there is none. Two roots closer than the interval (or a complex pair near it) straddle that
/// point, which halving reaches one bit of their distance per step. Guidance only: any double
/// inside is a correct split (Lemma 10).
bool critical_split_point(const SmallPolynomial& p, double lo, double hi, double* m) {
  if (p.degree() < 2) return false;
  Approximation c[4];
  p.approximate_coefficients(c);
  long scale = LONG_MIN;
  for (const Approximation& ci : c)
    if (ci.mantissa != 0) scale = std::max(scale, ci.exponent);
  double a[4];
  for (int i = 0; i < 4; ++i)  // p ~ 2^scale sum a_i t^i; tiny terms may vanish
    a[i] = c[i].mantissa == 0 ? 0.0
                              : std::ldexp(c[i].mantissa, static_cast<int>(std::max(
                                                               -1100L, c[i].exponent - scale)));
  const double A = 3 * a[3], B = 2 * a[2], C = a[1];  // p' ~ A t^2 + B t + C
  double candidates[2];
  int count = 0;
  if (A == 0) {
    if (B != 0) candidates[count++] = -C / B;
  } else {
    const double discriminant = B * B - 4 * A * C;
    if (!(discriminant > 0)) {
      candidates[count++] = -B / (2 * A);  // a double critical point, or a complex pair's
    } else {
      const double q = -0.5 * (B + std::copysign(std::sqrt(discriminant), B));
      candidates[count++] = q / A;
      if (q != 0) candidates[count++] = C / q;
    }
  }
  const double middle = lo + (hi - lo) / 2;
  bool found = false;
  for (int i = 0; i < count; ++i) {
    double x = candidates[i];
    if (!(x >= lo && x <= hi)) continue;  // NaN included
    if (x == lo) x = std::nextafter(lo, hi);
    if (x == hi) x = std::nextafter(hi, lo);
    if (!(lo < x && x < hi)) continue;
    if (!found || std::fabs(x - middle) < std::fabs(*m - middle)) *m = x;
    found = true;
  }
  return found;
}

}  // namespace

bool BracketedRoot::refine() {
  double m;
  if (is_exact() || fine_ || !split_point(lo_, hi_, &m)) return false;
  const int s = p_->sign_at(m);
  if (s == 0) lo_ = hi_ = m;
  else (s == sign_lo_ ? lo_ : hi_) = m;
  return true;
}

std::pair<double, double> BracketedRoot::enclosure(double width) const {
  if (is_exact() || fine_) return {lo_, hi_};
  return guided_bisection(*p_, lo_, hi_, width);
}

void BracketedRoot::narrow_by_filter(int max_steps) {
  if (is_exact() || fine_) return;
  p_->narrow_by_filter(&lo_, &hi_, sign_lo_, max_steps);
}

namespace {

/// Doubles l <= x 2^-K <= h for an integer x >= 0 (mpz_get_d_2exp truncates toward zero: the
/// truncation is a lower bound, one unit of its 53rd bit more an upper bound; both scaled
/// exactly unless below 2^-1074, where the lower bound becomes 0 and the upper 2^-1074).
std::pair<double, double> dyadic_enclosure(const mpz_class& x, unsigned K) {
  if (sgn(x) == 0) return {0.0, 0.0};
  long e = 0;
  const double d = mpz_get_d_2exp(&e, x.get_mpz_t());  // x = (d + rho) 2^e, 0 <= rho < 2^-53
  const long shift = e - static_cast<long>(K);
  if (shift < -1021) {  // d 2^shift may not be a double: 0 <= x 2^-K < 2^shift
    const double above = std::ldexp(1.0, static_cast<int>(std::max(shift, -1074L)));
    return {0.0, above};
  }
  // d and d + 2^-53 (<= 1) have 53 significant bits, the lowest at 2^(shift - 53) >= 2^-1074.
  return {std::ldexp(d, static_cast<int>(shift)),
          std::ldexp(d + 0x1p-53, static_cast<int>(shift))};
}

}  // namespace

std::optional<BracketedRoot> BracketedRoot::reflected(const SmallPolynomial* p_reflected) const {
  if (!(lo_ >= 0.5 && hi_ <= 1.0)) return std::nullopt;
  if (fine_) {
    // u = 1 - r in (uA 2^-K, uB 2^-K), uA = 2^K - B, uB = 2^K - A: enclosed by doubles, then
    // certified as a bracket of p_reflected's only root there by signs and Descartes' rule.
    if (fine_->is_exact()) return std::nullopt;
    const mpz_class one = mpz_class(1) << fine_->K;
    const double u_lo = dyadic_enclosure(mpz_class(one - fine_->B), fine_->K).first;
    const double u_hi = dyadic_enclosure(mpz_class(one - fine_->A), fine_->K).second;
    if (!(u_lo < u_hi) || u_hi > 0.5) return std::nullopt;
    const int s_lo = p_reflected->sign_at(u_lo), s_hi = p_reflected->sign_at(u_hi);
    if (s_lo == 0 || s_hi != -s_lo) return std::nullopt;
    int s[4];
    if (variations(s, p_reflected->bernstein_signs(u_lo, u_hi, s)) != 1) return std::nullopt;
    return BracketedRoot(p_reflected, u_lo, u_hi, s_lo);
  }
  if (is_exact()) return BracketedRoot::at(p_reflected, 1.0 - lo_);
  // p(hi) has the sign -sign_lo (a simple root inside): the reflected bracket's lower end.
  return BracketedRoot(p_reflected, 1.0 - hi_, 1.0 - lo_, -sign_lo_);
}

int BracketedRoot::certain_sign_of(const SmallPolynomial& g) const {
  if (fine_ || g.is_zero()) return 0;
  return is_exact() ? g.certain_sign_at(lo_) : g.certain_sign_on(lo_, hi_);
}

int BracketedRoot::sign_of(const SmallPolynomial& g) {
  if (g.is_zero()) return 0;
  int sign = 0;
  if (fine_) {
    if (g.sign_at_roots_of(*p_, &sign)) return sign;
    return sign_in_dyadic_bracket(to_mpz_polynomial(*p_), to_mpz_polynomial(g), *fine_);
  }
  for (int step = 0;; ++step) {
    if (is_exact()) return g.sign_at(lo_);
    int s[4];
    const int n = g.bernstein_signs(lo_, hi_, s);
    if (one_strict_sign(s, n)) return s[0];  // g has that sign on all of [lo, hi]
    // Degenerate contacts: g is often a multiple of p (h = 0), which no bracket can decide.
    // PROOF: proofs/exact_ccd.md#constant-remainder
    if (step == 0 && g.sign_at_roots_of(*p_, &sign)) return sign;
    if (step < 2) {
      if (!refine()) break;
    } else if (step == 2 && !p_->in_gmp() && !g.in_gmp()) {
      // Straight to adjacent doubles, Newton-guided, a few signs in fixed size. In GMP each
      // sign costs a pass over thousands of bits, and the remainders below decide on any
      // bracket of the root: go to them at once.
      const auto [l, h] = guided_bisection(*p_, lo_, hi_, 0.0);
      if (l == lo_ && h == hi_) break;
      lo_ = l;
      hi_ = h;
    } else {
      break;
    }
  }
  // g's Bernstein signs cannot tell on [lo, hi] (adjacent doubles, or any bracket in GMP).
  return sign_in_dyadic_bracket(to_mpz_polynomial(*p_), to_mpz_polynomial(g),
                                dyadic_bracket(lo_, hi_, sign_lo_));
}

RootIterator::RootIterator(const SmallPolynomial& p, double t_max,
                           SmallPolynomial* square_free_storage)
    : p_(&p), storage_(square_free_storage) {
  if (p.degree() < 1) return;  // constants: no root (the zero polynomial is not passed)
  if (p.degree() == 2) {
    // Descartes' rule alone would bisect down to one ulp around a double root, or around the
    // minimum of a quadratic without real roots that nearly touches zero.
    // PROOF: proofs/exact_ccd.md#quadratic-discriminant
    const int discriminant = p.quadratic_discriminant_sign();
    if (discriminant < 0) return;  // no real root
    if (discriminant == 0) {       // the same root, simple, as the only root of a line
      square_free_ = true;
      *storage_ = p.double_root_factor();
      p_ = storage_;
    }
  }
  if (p_->sign_at(t_max) == 0) push({t_max, t_max, Kind::point});
  push({0.0, t_max, Kind::interval});
  if (p_->sign_at(0.0) == 0) push({0.0, 0.0, Kind::point});
}

std::optional<BracketedRoot> RootIterator::next() {
  while (size_ > 0) {
    const Item it = stack_[--size_];
    if (it.kind == Kind::point) return BracketedRoot::at(p_, it.lo);
    if (it.kind == Kind::fine) {
      DyadicBracket& d = fine_[static_cast<std::size_t>(it.index)];
      return BracketedRoot(p_, it.lo, it.hi, std::move(d));
    }
    int s[4];
    const int n = p_->bernstein_signs(it.lo, it.hi, s);
    const int v = variations(s, n);
    if (v == 0) continue;
    if (v == 1 && s[0] != 0 && s[n - 1] != 0) return BracketedRoot(p_, it.lo, it.hi, s[0]);
    double m;
    if (!split_point(it.lo, it.hi, &m)) {
      if (!square_free_) {
        square_free_ = true;
        if (!square_free_by_residue(*p_)) {  // else p's roots are simple already
          *storage_ = square_free_part(*p_);
          p_ = storage_;
        }
        push(it);  // the same roots, now simple
        continue;
      }
      isolate_beyond_doubles(it);
      continue;
    }
    // Near a critical point first, a few times per iterator (a poor guess peels off little).
    if (guided_splits_ < kMaxGuidedSplits && critical_split_point(*p_, it.lo, it.hi, &m))
      ++guided_splits_;
    const int sm = p_->sign_at(m);
    push({m, it.hi, Kind::interval});
    if (sm == 0) push({m, m, Kind::point});
    push({it.lo, m, Kind::interval});
  }
  return std::nullopt;
}

void RootIterator::push(const Item& it) {
  if (size_ == kMaxItems) throw UnresolvedAtDoubles{};
  stack_[size_++] = it;
}

/// The roots of the square-free p strictly inside the adjacent doubles (lo, hi), isolated by
/// the same Descartes bisection on dyadic rationals; pushed so that they come out in ascending
/// order. An end that is a root was emitted on its own (a tested split point or interval end):
/// next to it the Bernstein coefficients show no variation once the bracket is short, so it is
/// not emitted again.
void RootIterator::isolate_beyond_doubles(const Item& it) {
  const MpzPolynomial p = to_mpz_polynomial(*p_);
  std::vector<DyadicBracket> found, pending;
  if (std::optional<std::vector<DyadicBracket>> split =
          split_at_critical_points(p, dyadic_bracket(it.lo, it.hi, 0)))
    found = std::move(*split);
  else
    pending.push_back(dyadic_bracket(it.lo, it.hi, 0));  // sign_lo is set when a root is found
  for (int step = 0; !pending.empty(); ++step) {
    if (step == kMaxDyadicSteps) throw UnresolvedAtDoubles{};
    DyadicBracket d = std::move(pending.back());
    pending.pop_back();
    if (d.is_exact()) {  // a dyadic root found at a split point
      found.push_back(std::move(d));
      continue;
    }
    int s[4];
    const int n = bernstein_signs_dyadic(p, d.A, d.B, d.K, s);
    const int v = variations(s, n);
    if (v == 0) continue;
    if (v == 1 && s[0] != 0 && s[n - 1] != 0) {
      d.sign_lo = s[0];
      found.push_back(std::move(d));
      continue;
    }
    // Split at the middle M: the right half first onto `pending`, so the left comes out
    // first; M itself when it is a root.
    DyadicBracket left = d, right = d;
    left.A <<= 1, left.B <<= 1, ++left.K;
    right.A = left.A, right.B = left.B, right.K = left.K;
    const mpz_class M = (left.A + left.B) >> 1;
    left.B = M;
    right.A = M;
    pending.push_back(std::move(right));
    if (sign_at_dyadic(p, M, left.K) == 0) {
      DyadicBracket point;
      point.A = point.B = M;
      point.K = left.K;
      pending.push_back(std::move(point));
    }
    pending.push_back(std::move(left));
  }
  // `found` is ascending (left halves before points before right halves); pushed in reverse
  // so that the stack pops them ascending.
  for (auto i = found.size(); i-- > 0;) {
    fine_.push_back(std::move(found[i]));
    push({it.lo, it.hi, Kind::fine, static_cast<int>(fine_.size() - 1)});
  }
}

bool earlier(BracketedRoot& r, BracketedRoot& b) {
  for (;;) {
    if (r.lo() >= b.hi()) return false;  // r >= r.lo >= b.hi >= b
    if (r.hi() < b.lo()) return true;
    if (r.hi() == b.lo()) return !(r.is_exact() && b.is_exact());  // equal only if both are it
    BracketedRoot& wider = (r.hi() - r.lo()) >= (b.hi() - b.lo()) ? r : b;
    BracketedRoot& other = &wider == &r ? b : r;
    if (!wider.refine() && !other.refine()) return false;  // the same adjacent pair
  }
}

}  // namespace exactccd::exact
