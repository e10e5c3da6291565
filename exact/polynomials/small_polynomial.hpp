// Integer polynomials of degree at most 3 in the time t, with exact signs at double times in
// [0, 1] and exact signs of their Bernstein coefficients on intervals with double ends, each
// computed in the smallest FixedInt its bit-length bound admits (GMP beyond). The fast exact
// stage (exact/stages/algebraic_at_doubles.hpp) brackets roots with them; the rare algebraic steps
// (common factors, square-free parts) run in GMP.
// PROOF: proofs/exact_ccd.md#small-polynomial-bounds
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>

#include "exact/arithmetic/fixed_int.hpp"
#include "exact/polynomials/guided_bisection.hpp"
#include "exact/arithmetic/integer_arithmetic.hpp"
#include "exact/arithmetic/integer_bounds.hpp"
#include "exact/arithmetic/wide_interval.hpp"

namespace exactccd::exact {

/// Bits of 2^(d k) p(T 2^-k) for coefficients below 2^b, degree d, 0 <= T <= 2^k.
constexpr long polynomial_value_bits(long coefficient_bits, int degree, long time_exponent) {
  return coefficient_bits + degree * time_exponent + 2;
}

/// Bits of the scaled Bernstein coefficients (lcm of the binomials) x 2^(d K) on [a, b],
/// a = A 2^-K, b = B 2^-K, 0 <= A < B <= 2^K.
constexpr long bernstein_bits(long coefficient_bits, int degree, long time_exponent) {
  return coefficient_bits + degree * time_exponent + 8;
}

/// Coefficients wider than this get the wide-range interval filter
/// (exact/arithmetic/wide_interval.hpp): below it the fixed-size evaluations are already cheap.
constexpr long kWideFilterBits = 320;

/// A double strictly inside (lo, hi), 0 <= lo < hi: the rounded arithmetic middle while the
/// interval spans few binades (Descartes' rule needs short intervals), else the middle in bit
/// order (a root near 0 is reached in at most 64 halvings); false when no double is inside.
/// Any point inside is correct; the choice only sets the speed.
bool split_point(double lo, double hi, double* m);

/// The integer polynomial sum c[i] t^i, degree <= 3.
class SmallPolynomial final : public CubicAtDoubles {
 public:
  SmallPolynomial() = default;  ///< the zero polynomial

  /// From `count` <= 4 coefficients below 2^bits in magnitude (a proven bound).
  template <int N>
  static SmallPolynomial from_fixed(const FixedInt<N>* c, int count, long bits);
  static SmallPolynomial from_mpz(const mpz_class* c, int count);
  /// The same with the coefficients divided by their common power of two (a positive factor:
  /// the same signs and roots, which is all the exact stage asks of a polynomial). Wide
  /// exponent spreads leave hundreds of such trailing zero bits, which every product would
  /// carry. PROOF: proofs/exact_ccd.md#exact-at-double-brackets
  static SmallPolynomial from_mpz_without_power_of_two(const mpz_class* c, int count);

  int degree() const { return degree_; }  ///< -1 for the zero polynomial
  bool is_zero() const { return degree_ < 0; }
  long bits() const { return bits_; }
  /// Coefficients held in GMP (beyond the widest FixedInt): every exact step on them is GMP.
  bool in_gmp() const { return in_gmp_; }

  /// The exact sign of p(t) for a double t in [0, 1].
  int sign_at(double t) const { return sign_at(t, nullptr); }

  /// The signs of p's Bernstein coefficients of its own degree on [a, b] (doubles,
  /// 0 <= a < b <= 1); returns how many (degree + 1). Their sign variations bound the roots in
  /// (a, b) (Descartes); all of one strict sign: p has that sign on [a, b].
  int bernstein_signs(double a, double b, int (&signs)[4]) const;

  std::array<mpz_class, 4> mpz_coefficients() const;

  /// The sign of this polynomial g at every root of p (deg g >= deg p >= 1) when the
  /// pseudo-remainder h = prem(g, p) is a constant (zero when p divides g): sign(lc(p))^n
  /// sign(h), n = deg g - deg p + 1. Computed in the FixedInt that the bound
  /// bits(g) + n (bits(p) + 1) selects; false when h is not constant, the degrees do not
  /// allow it, or the bound exceeds the fixed widths (then ask sign_at_root_by_remainders).
  /// PROOF: proofs/exact_ccd.md#constant-remainder
  bool sign_at_roots_of(const SmallPolynomial& p, int* sign) const;

  /// For degree 2 (c2 t^2 + c1 t + c0): the exact sign of the discriminant c1^2 - 4 c2 c0, in
  /// the FixedInt its bound 2 bits() + 3 selects (GMP beyond). Negative: no real root; zero: a
  /// double root. PROOF: proofs/exact_ccd.md#quadratic-discriminant
  int quadratic_discriminant_sign() const;
  /// For degree 2 with a zero discriminant: 2 c2 t + c1, whose only root is p's double root
  /// -c1 / (2 c2) (p = (2 c2 t + c1)^2 / (4 c2)). PROOF: proofs/exact_ccd.md#quadratic-discriminant
  SmallPolynomial double_root_factor() const;
  /// p(1 - u) as a polynomial in u (exact integers, GMP): near t = 1, where doubles in t are
  /// 2^-53 apart, u = 1 - t is resolved down to 2^-1074.
  /// PROOF: proofs/exact_ccd.md#certain-signs-first
  SmallPolynomial reflected() const;
  std::array<mpz_class, 4> reflected_coefficients() const;

  /// The wide-range filter alone (no exact step): the sign of p(t) at the double t, or of p on
  /// all of [a, b] (0 <= a < b <= 1, all Bernstein coefficients of one certain strict sign),
  /// when its enclosures certify it; 0 when they cannot tell or p has no enclosures (bits() <=
  /// kWideFilterBits). Never 0 for "p vanishes": a certain sign is strict.
  /// PROOF: proofs/exact_ccd.md#wide-interval-filter
  int certain_sign_at(double t) const { return filtered_sign_at(t, nullptr); }
  int certain_sign_on(double a, double b) const;
  /// Bisects the bracket [*lo, *hi] of p's only root inside (p(*lo) of sign sign_lo, p(*hi) of
  /// the other, both non-zero) at split_point's doubles with signs from the wide-range filter
  /// alone, under one x87 guard, until a sign is uncertain, no double is left inside, or
  /// max_steps halvings. PROOF: proofs/exact_ccd.md#certain-signs-first
  void narrow_by_filter(double* lo, double* hi, int sign_lo, int max_steps) const;

  // CubicAtDoubles (guided_bisection): exact sign at a double t in [0, 1], rounded values.
  int sign_at(double t, Approximation* value) const override;
  void approximate_coefficients(Approximation (&c)[4]) const override;

 private:
  using Stored = FixedInt<kMaxFixedLimbs>;
  /// The coefficients in GMP: gmp_ itself when held there (no copy), else converted into
  /// *storage.
  const mpz_class* gmp_coefficients(std::array<mpz_class, 4>* storage) const;
  /// Encloses the coefficients for the wide-range filter when bits_ > kWideFilterBits.
  /// `reflection`: the polynomial this one is the reflection of (its enclosures are this one's
  /// reflected enclosures), or nullptr.
  void set_wide_enclosure(const SmallPolynomial* reflection = nullptr);
  static SmallPolynomial from_mpz(const mpz_class* c, int count,
                                  const SmallPolynomial* reflection);
  /// The certified sign from the filter, 0 when it cannot tell (then decide exactly).
  int filtered_sign_at(double t, Approximation* value) const;
#if EXACTCCD_X87_INTERVAL
  /// The enclosure of p(t), t >= 0 a double; needs X87EnvironmentGuard(Rounding::upward).
  X87Interval wide_value_at(double t) const;
  /// The enclosures to evaluate at the time t in [0, 1]: p's at t, or for t >= 1/2 (when held)
  /// p(1 - u)'s at u = 1 - t (exact).
  const X87Interval* wide_coefficients_for(double* t) const;
  /// The same for an interval [a, b] in [0, 1]: within [1/2, 1] (when held) p(1 - u)'s on
  /// [1 - b, 1 - a], both ends exact.
  const X87Interval* wide_coefficients_on(double* a, double* b) const;
#endif
  bool filtered_bernstein_signs(double a, double b, int (&signs)[4]) const;

  int degree_ = -1;
  long bits_ = 0;
  bool in_gmp_ = false;  // coefficients in gmp_ (beyond the widest FixedInt)
  Stored fixed_[4] = {Stored(Stored::Uninitialized{}), Stored(Stored::Uninitialized{}),
                      Stored(Stored::Uninitialized{}), Stored(Stored::Uninitialized{})};
  std::array<mpz_class, 4> gmp_;
#if EXACTCCD_X87_INTERVAL
  bool wide_ = false;
  X87Interval wide_c_[4];
  /// For GMP coefficients: enclosures of p(1 - u)'s, which near t = 1 (u = 1 - t, exact for
  /// t >= 1/2) avoid the cancellation of p's terms there.
  bool wide_reflected_ = false;
  X87Interval wide_reflected_c_[4];
#endif
};

template <int N>
SmallPolynomial SmallPolynomial::from_fixed(const FixedInt<N>* c, int count, long bits) {
  static_assert(N <= kMaxFixedLimbs, "wider than the stored coefficients");
  SmallPolynomial p;
  p.bits_ = bits;
  for (int i = 0; i < 4; ++i) {
    p.fixed_[i] = i < count ? c[i].template resized<kMaxFixedLimbs>() : Stored(0);
    if (i < count && c[i].sign() != 0) p.degree_ = i;
  }
  if (bits > kWideFilterBits) p.set_wide_enclosure();
  return p;
}

// ---- GMP steps of the exact stage (rare: only where doubles cannot decide) -------------------

/// How many GMP steps (any function below, or an evaluation beyond the fixed widths) the
/// calling thread ran: tells tests which decisions stayed in fixed-size integers.
std::uint64_t gmp_polynomial_steps_in_this_thread() noexcept;

struct MpzPolynomial {
  std::array<mpz_class, 4> c;
  int degree = -1;
};

MpzPolynomial to_mpz_polynomial(const SmallPolynomial& p);
/// The primitive greatest common divisor (content 1, positive leading coefficient); the zero
/// polynomial when both are zero.
MpzPolynomial polynomial_gcd(MpzPolynomial a, MpzPolynomial b);
/// p divided by its gcd with p' (same roots, each simple); p of degree >= 1.
SmallPolynomial square_free_part(const SmallPolynomial& p);
/// True only when p (degree 1 to 3) has no multiple complex root: its discriminant is non-zero
/// modulo a prime (then it is non-zero). False when that residue is 0, which an integer
/// discriminant of a square-free p is with probability about 2^-61: the caller then computes
/// square_free_part. A few word operations per coefficient limb instead of a polynomial gcd.
/// PROOF: proofs/exact_ccd.md#square-free-by-a-residue
bool square_free_by_residue(const SmallPolynomial& p);
SmallPolynomial to_small_polynomial(const MpzPolynomial& p);

/// Beyond the doubles (GMP): the exact sign of p at T 2^-k, and the signs of p's Bernstein
/// coefficients on [A 2^-K, B 2^-K] (0 <= A < B); the latter returns how many.
int sign_at_dyadic(const MpzPolynomial& p, const mpz_class& T, unsigned k);
int bernstein_signs_dyadic(const MpzPolynomial& p, const mpz_class& A, const mpz_class& B,
                           unsigned K, int (&signs)[4]);

/// The pseudo-remainder r of a by b (deg a >= deg b >= 0): lc(b)^n a = Q b + r with
/// n = deg a - deg b + 1 and deg r < deg b; returns the sign of lc(b)^n, so that at every root x
/// of b, a(x) has the sign of the returned value times r(x).
int pseudo_remainder(MpzPolynomial a, const MpzPolynomial& b, MpzPolynomial* r);

/// The exact sign of X + Y sqrt(D), D >= 0.
int sign_plus_sqrt(const mpz_class& X, const mpz_class& Y, const mpz_class& D);

/// The same sign by two pseudo-remainders and one quadratic irrationality, no gcd: with
/// h = prem(g, p) (degree < deg p <= 3) and the real roots s of h located against r (against the
/// bracket's ends, then by the sign of p at s from prem(p, h)). `sign_lo` is the sign of p at
/// A 2^-K. A constant number of multiplications; what the stage uses.
/// PROOF: proofs/exact_ccd.md#sign-at-a-root-by-remainders
int sign_at_root_by_remainders(const MpzPolynomial& p, const MpzPolynomial& g, const mpz_class& A,
                               const mpz_class& B, unsigned K, int sign_lo);

}  // namespace exactccd::exact
