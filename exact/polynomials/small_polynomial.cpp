#include "exact/polynomials/small_polynomial.hpp"

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/predicates/double_bits.hpp"
#include "exact/arithmetic/fixed_width_dispatch.hpp"
#include "core/predicates/fp_environment.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/polynomials/interval_sign_at_irrational.hpp"

namespace exactccd::exact {

namespace {

thread_local std::uint64_t g_gmp_steps = 0;

/// r *= T for a GMP time numerator beyond 64 bits.
inline void multiply_by(mpz_class& r, const mpz_class& T) { r *= T; }

/// 2^(d k) p(T 2^-k) by Horner's rule. Reduction modulo 2^(64N) commutes with every step, so the
/// FixedInt result is exact when the final value fits (its bound selected N).
template <class Int, class Time>
Int scaled_value(const Int* c, int d, const Time& T, unsigned k) {
  Int r = c[d];
  for (int i = d - 1; i >= 0; --i) {
    multiply_by(r, T);
    add_shifted(r, c[i], k * static_cast<unsigned>(d - i));
  }
  return r;
}

/// A GMP factor held as odd * 2^shift: a double's mantissa scaled to a common exponent carries
/// up to 1,126 zero bits that a plain product would multiply limb by limb.
struct ShiftedFactor {
  mpz_class odd;
  mp_bitcnt_t shift = 0;
  explicit ShiftedFactor(const mpz_class& x) {
    if (sgn(x) != 0) shift = mpz_scan1(x.get_mpz_t(), 0);
    mpz_tdiv_q_2exp(odd.get_mpz_t(), x.get_mpz_t(), shift);  // exact: those bits are 0
  }
};

inline void multiply_in_place(mpz_class& x, const ShiftedFactor& f) {
  mpz_mul(x.get_mpz_t(), x.get_mpz_t(), f.odd.get_mpz_t());
  mpz_mul_2exp(x.get_mpz_t(), x.get_mpz_t(), f.shift);
}
inline void add_product_by(mpz_class& out, const mpz_class& a, const ShiftedFactor& f) {
  thread_local mpz_class product;  // scratch: its limbs are reused
  mpz_mul(product.get_mpz_t(), a.get_mpz_t(), f.odd.get_mpz_t());
  mpz_mul_2exp(product.get_mpz_t(), product.get_mpz_t(), f.shift);
  out += product;
}
template <class Int>
inline void multiply_in_place(Int& x, const Int& f) {
  x *= f;
}
template <class Int>
inline void add_product_by(Int& out, const Int& a, const Int& f) {
  add_product(out, a, f);
}

/// The signs of the Bernstein coefficients of p (degree d) on [A 2^-K, (A + H) 2^-K]: the
/// Taylor shift q(s) = 2^(d K) p((A + H s) 2^-K) by Horner's rule over polynomials in s, then
/// M b_j = sum_i M C(j, i) / C(d, i) q_i with M = lcm_i C(d, i) (3, 2, 1, 1 for d = 3, 2, 1, 0).
/// In place: q[j] is updated before q[j - 1], which it reads.
/// PROOF: proofs/exact_ccd.md#small-polynomial-bounds
template <class Int, class Factor>
void bernstein_signs_of(const Int* c, int d, const Factor& A, const Factor& H, unsigned K,
                        int (&signs)[4]) {
  Int q[4] = {c[d], Int(0), Int(0), Int(0)};
  for (int i = d - 1; i >= 0; --i) {
    const int deg = d - 1 - i;  // degree of q before this step
    q[deg + 1] = q[deg];
    multiply_in_place(q[deg + 1], H);
    for (int j = deg; j >= 1; --j) {
      multiply_in_place(q[j], A);
      add_product_by(q[j], q[j - 1], H);
    }
    multiply_in_place(q[0], A);
    add_shifted(q[0], c[i], K * static_cast<unsigned>(d - i));
  }
  switch (d) {
    case 0: signs[0] = sign_of(q[0]); return;
    case 1: {
      signs[0] = sign_of(q[0]);
      Int b1 = q[0];
      b1 += q[1];
      signs[1] = sign_of(b1);
      return;
    }
    case 2: {
      signs[0] = sign_of(q[0]);
      Int b1 = q[0];  // 2 b1 = 2 q0 + q1
      b1 += q[0];
      b1 += q[1];
      signs[1] = sign_of(b1);
      Int b2 = q[0];  // b2 = q0 + q1 + q2
      b2 += q[1];
      b2 += q[2];
      signs[2] = sign_of(b2);
      return;
    }
    default: {
      signs[0] = sign_of(q[0]);
      Int three_q0 = q[0];
      multiply_by(three_q0, 3u);
      Int b1 = three_q0;  // 3 b1 = 3 q0 + q1
      b1 += q[1];
      signs[1] = sign_of(b1);
      Int b2 = three_q0;  // 3 b2 = 3 q0 + 2 q1 + q2
      b2 += q[1];
      b2 += q[1];
      b2 += q[2];
      signs[2] = sign_of(b2);
      Int b3 = q[0];  // b3 = q0 + q1 + q2 + q3
      b3 += q[1];
      b3 += q[2];
      b3 += q[3];
      signs[3] = sign_of(b3);
      return;
    }
  }
}

template <int N>
FixedInt<N> fixed_from_mpz(const mpz_class& z) {
  std::uint64_t limbs[N] = {};
  std::size_t count = 0;
  mpz_export(limbs, &count, -1, sizeof limbs[0], 0, 0, z.get_mpz_t());
  const FixedInt<N> m = FixedInt<N>::from_limbs(limbs);
  return sgn(z) < 0 ? -m : m;
}

/// The double t in [0, 1] as T 2^-k; std::domain_error otherwise.
DyadicTime unit_time(double t) {
  DyadicTime d;
  if (!dyadic_time(t, &d))
    throw std::domain_error("exactccd: polynomial sign at a time outside [0, 1]");
  return d;
}

}  // namespace

std::uint64_t gmp_polynomial_steps_in_this_thread() noexcept { return g_gmp_steps; }

SmallPolynomial SmallPolynomial::from_mpz(const mpz_class* c, int count) {
  return from_mpz(c, count, nullptr);
}

SmallPolynomial SmallPolynomial::from_mpz_without_power_of_two(const mpz_class* c, int count) {
  mp_bitcnt_t shift = ~mp_bitcnt_t(0);
  for (int i = 0; i < count; ++i)
    if (sgn(c[i]) != 0) shift = std::min(shift, mpz_scan1(c[i].get_mpz_t(), 0));
  if (shift == ~mp_bitcnt_t(0) || shift == 0) return from_mpz(c, count);
  mpz_class out[4];
  for (int i = 0; i < count; ++i)
    mpz_tdiv_q_2exp(out[i].get_mpz_t(), c[i].get_mpz_t(), shift);  // exact: those bits are 0
  return from_mpz(out, count);
}

SmallPolynomial SmallPolynomial::from_mpz(const mpz_class* c, int count,
                                          const SmallPolynomial* reflection) {
  ++g_gmp_steps;
  SmallPolynomial p;
  long bits = 0;
  for (int i = 0; i < count; ++i) {
    bits = std::max(bits, bit_length(c[i]));
    if (sgn(c[i]) != 0) p.degree_ = i;
  }
  p.bits_ = bits;
  if (fixed_limbs_for(bits) == 0) {
    p.in_gmp_ = true;
    for (int i = 0; i < 4; ++i) p.gmp_[i] = i < count ? c[i] : mpz_class(0);
  } else {
    for (int i = 0; i < 4; ++i)
      p.fixed_[i] = i < count ? fixed_from_mpz<kMaxFixedLimbs>(c[i]) : Stored(0);
  }
  if (bits > kWideFilterBits) p.set_wide_enclosure(reflection);
  return p;
}

// ---- the wide-range interval filter ------------------------------------------------------------
// PROOF: proofs/exact_ccd.md#wide-interval-filter

void SmallPolynomial::set_wide_enclosure(const SmallPolynomial* reflection) {
#if EXACTCCD_X87_INTERVAL
  // The ends are exact long doubles only at 64-bit precision: never under the caller's x87
  // precision control (FpEnvironment.X87ControlWordUnmaskedDoesNotTrapAndIsRestored).
  const predicates::X87EnvironmentGuard extended(predicates::Rounding::upward);
  for (int i = 0; i < 4; ++i) wide_c_[i] = in_gmp_ ? enclosure_of(gmp_[i]) : enclosure_of(fixed_[i]);
  wide_ = true;
  if (in_gmp_ && degree_ >= 1) {
    if (reflection != nullptr && reflection->wide_) {
      // p is the reflection of `reflection`, whose own enclosures are those of p(1 - u).
      for (int i = 0; i < 4; ++i) wide_reflected_c_[i] = reflection->wide_c_[i];
    } else {
      const std::array<mpz_class, 4> r = reflected_coefficients();
      for (int i = 0; i < 4; ++i)
        wide_reflected_c_[i] = enclosure_of(r[static_cast<std::size_t>(i)]);
    }
    wide_reflected_ = true;
  }
#endif
}

bool split_point(double lo, double hi, double* m) {
  double middle;  // of the doubles strictly inside, in bit order
  if (!predicates::middle_double(lo, hi, &middle)) return false;
  if ((lo == 0 && hi >= 0x1p-60) || (lo > 0 && hi <= 0x1p20 * lo)) {
    const double mid = lo + (hi - lo) * 0.5;
    if (lo < mid && mid < hi) {
      *m = mid;
      return true;
    }
  }
  *m = middle;
  return true;
}

#if EXACTCCD_X87_INTERVAL
const X87Interval* SmallPolynomial::wide_coefficients_for(double* t) const {
  if (wide_reflected_ && *t >= 0.5 && *t <= 1.0) {
    *t = 1.0 - *t;  // exact (Sterbenz)
    return wide_reflected_c_;
  }
  return wide_c_;
}

const X87Interval* SmallPolynomial::wide_coefficients_on(double* a, double* b) const {
  if (wide_reflected_ && *a >= 0.5 && *b <= 1.0) {
    const double u_lo = 1.0 - *b, u_hi = 1.0 - *a;  // exact (Sterbenz)
    *a = u_lo, *b = u_hi;
    return wide_reflected_c_;
  }
  return wide_c_;
}

X87Interval SmallPolynomial::wide_value_at(double t) const {
  // Times are in [0, 1] (t >= 0): each Horner step scales by a non-negative point.
  const X87Interval* c = wide_coefficients_for(&t);
  X87Interval r = c[degree_];
  for (int i = degree_ - 1; i >= 0; --i) r = times_nonnegative(r, t) + c[i];
  return r;
}
#endif

void SmallPolynomial::narrow_by_filter(double* lo, double* hi, int sign_lo, int max_steps) const {
#if EXACTCCD_X87_INTERVAL
  if (!wide_ || degree_ < 0) return;
  // One guard for the whole loop; each step's bounds pass through volatile stores, which stay
  // ordered before the rounding mode is restored (as in filtered_sign_at).
  const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
  double m;
  for (int step = 0; step < max_steps && split_point(*lo, *hi, &m); ++step) {
    volatile long double l, h;
    const X87Interval r = wide_value_at(m);
    l = r.lo;
    h = r.hi;
    const int s = certain_sign({l, h});
    if (s == 0) return;
    (s == sign_lo ? *lo : *hi) = m;
  }
#else
  (void)lo, (void)hi, (void)sign_lo, (void)max_steps;
#endif
}

int SmallPolynomial::filtered_sign_at(double t, Approximation* value) const {
#if EXACTCCD_X87_INTERVAL
  if (!wide_ || degree_ < 0) return 0;
  // The bounds leave the guard's scope through volatile stores, which stay ordered before the
  // rounding mode is restored.
  volatile long double lo, hi;
  {
    const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
    const X87Interval r = wide_value_at(t);
    lo = r.lo;
    hi = r.hi;
  }
  const int s = certain_sign({lo, hi});
  if (s != 0 && value) {  // guidance only: the upper bound's leading bits
    int e = 0;
    value->mantissa = static_cast<GuideReal>(std::frexp(static_cast<long double>(hi), &e));
    value->exponent = e;
  }
  return s;
#else
  (void)t, (void)value;
  return 0;
#endif
}

bool SmallPolynomial::filtered_bernstein_signs(double a, double b, int (&signs)[4]) const {
#if EXACTCCD_X87_INTERVAL
  if (!wide_ || degree_ < 0) return false;
  volatile long double lo[4], hi[4];  // leave the guard's scope as in filtered_sign_at
  {
    const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
    // The Taylor shift q(s) = p(a + h s), h = b - a enclosed, by Horner's rule over polynomials
    // in s; then the Bernstein coefficients times lcm C(d, i), as in the exact evaluation.
    // Within [1/2, 1]: p(1 - u)'s Bernstein coefficients on [1 - b, 1 - a], which are p's in
    // reverse order (t = 1 - u reverses the interval).
    const X87Interval* c = wide_coefficients_on(&a, &b);
    const bool reflect = c == wide_reflected_c_;
    const X87Interval A{a, a};
    const X87Interval H{-(static_cast<long double>(a) - b), static_cast<long double>(b) - a};
    const int d = degree_;
    X87Interval q[4] = {c[d], {0, 0}, {0, 0}, {0, 0}};
    for (int i = d - 1; i >= 0; --i) {
      const int deg = d - 1 - i;
      // a >= 0, and H's lower end -(a - b) >= 0 (a - b < 0 rounds up to at most 0).
      q[deg + 1] = times_nonnegative(q[deg], H.lo, H.hi);
      for (int j = deg; j >= 1; --j)
        q[j] = times_nonnegative(q[j], A.lo) + times_nonnegative(q[j - 1], H.lo, H.hi);
      q[0] = times_nonnegative(q[0], A.lo) + c[i];
    }
    const X87Interval two{2, 2}, three{3, 3};
    X87Interval beta[4] = {};
    switch (d) {
      case 0: beta[0] = q[0]; break;
      case 1: beta[0] = q[0], beta[1] = q[0] + q[1]; break;
      case 2: beta[0] = q[0], beta[1] = two * q[0] + q[1], beta[2] = q[0] + q[1] + q[2]; break;
      default:
        beta[0] = q[0];
        beta[1] = three * q[0] + q[1];
        beta[2] = three * q[0] + two * q[1] + q[2];
        beta[3] = q[0] + q[1] + q[2] + q[3];
    }
    for (int j = 0; j <= d; ++j) {
      const int k = reflect ? d - j : j;
      lo[k] = beta[j].lo;
      hi[k] = beta[j].hi;
    }
  }
  for (int j = 0; j <= degree_; ++j) {
    signs[j] = certain_sign({lo[j], hi[j]});
    if (signs[j] == 0) return false;
  }
  return true;
#else
  (void)a, (void)b, (void)signs;
  return false;
#endif
}

int SmallPolynomial::certain_sign_on(double a, double b) const {
#if EXACTCCD_X87_INTERVAL
  if (!wide_ || degree_ < 0) return 0;
  // The range of p over [a, b] by Horner's rule on the interval (each step's interval holds
  // the partial value at every t in [a, b]): enough on the short brackets it is asked about.
  volatile long double lo, hi;  // leave the guard's scope as in filtered_sign_at
  {
    const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
    double t_lo = a, t_hi = b;
    const X87Interval* c = wide_coefficients_on(&t_lo, &t_hi);
    X87Interval r = c[degree_];
    for (int i = degree_ - 1; i >= 0; --i) r = times_nonnegative(r, t_lo, t_hi) + c[i];
    lo = r.lo;
    hi = r.hi;
  }
  if (const int sign = certain_sign({lo, hi})) return sign;
#endif
  int s[4];  // the Bernstein enclosures, tighter on longer brackets
  if (degree_ < 0 || !filtered_bernstein_signs(a, b, s)) return 0;
  for (int j = 1; j <= degree_; ++j)
    if (s[j] != s[0]) return 0;
  return s[0];
}

std::array<mpz_class, 4> SmallPolynomial::mpz_coefficients() const {
  if (in_gmp_) return gmp_;
  return {to_mpz(fixed_[0]), to_mpz(fixed_[1]), to_mpz(fixed_[2]), to_mpz(fixed_[3])};
}

const mpz_class* SmallPolynomial::gmp_coefficients(std::array<mpz_class, 4>* storage) const {
  if (in_gmp_) return gmp_.data();
  *storage = mpz_coefficients();
  return storage->data();
}

int SmallPolynomial::sign_at(double t, Approximation* value) const {
  if (degree_ < 0) {
    if (value) *value = {};
    return 0;
  }
  const DyadicTime d = unit_time(t);
  if (const int s = filtered_sign_at(t, value)) return s;
  const int limbs =
      in_gmp_ ? 0 : fixed_limbs_for(polynomial_value_bits(bits_, degree_, d.exponent));
  const long scale = static_cast<long>(degree_) * d.exponent;  // p(t) = 2^(-d k) r
  if (limbs == 0) {
    ++g_gmp_steps;
    std::array<mpz_class, 4> converted;
    const mpz_class r =
        scaled_value(gmp_coefficients(&converted), degree_, d.numerator, d.exponent);
    if (value) {
      *value = approximate(r);
      value->exponent -= scale;
    }
    return sgn(r);
  }
  return with_limbs(limbs, [&](auto n) {
    constexpr int N = decltype(n)::value;
    const FixedInt<N> c[4] = {fixed_[0].resized<N>(), fixed_[1].resized<N>(),
                              fixed_[2].resized<N>(), fixed_[3].resized<N>()};
    const FixedInt<N> r = scaled_value(c, degree_, d.numerator, d.exponent);
    if (value) {
      *value = approximate(r);
      value->exponent -= scale;
    }
    return r.sign();
  });
}

void SmallPolynomial::approximate_coefficients(Approximation (&c)[4]) const {
  for (int i = 0; i < 4; ++i) c[i] = in_gmp_ ? approximate(gmp_[i]) : approximate(fixed_[i]);
}

int SmallPolynomial::bernstein_signs(double a, double b, int (&signs)[4]) const {
  if (!(0 <= a && a < b && b <= 1))
    throw std::domain_error("exactccd: Bernstein coefficients need 0 <= a < b <= 1");
  if (degree_ < 0) {
    signs[0] = 0;
    return 1;
  }
  if (filtered_bernstein_signs(a, b, signs)) return degree_ + 1;
  const Dyadic da = dyadic(a), db = dyadic(b);
  const int K = std::max({0, -da.exponent, -db.exponent});
  const auto shift_a = static_cast<unsigned>(K + da.exponent);
  const auto shift_b = static_cast<unsigned>(K + db.exponent);
  const int limbs =
      in_gmp_ ? 0 : fixed_limbs_for(bernstein_bits(bits_, degree_, K));
  if (limbs == 0) {
    ++g_gmp_steps;
    std::array<mpz_class, 4> converted;
    const mpz_class A =
        da.mantissa == 0 ? mpz_class(0) : scaled_integer<mpz_class>(da.mantissa, shift_a);
    const mpz_class H = scaled_integer<mpz_class>(db.mantissa, shift_b) - A;
    bernstein_signs_of(gmp_coefficients(&converted), degree_, ShiftedFactor(A), ShiftedFactor(H),
                       static_cast<unsigned>(K), signs);
    return degree_ + 1;
  }
  with_limbs(limbs, [&](auto n) {
    constexpr int N = decltype(n)::value;
    const FixedInt<N> c[4] = {fixed_[0].resized<N>(), fixed_[1].resized<N>(),
                              fixed_[2].resized<N>(), fixed_[3].resized<N>()};
    const FixedInt<N> A =
        da.mantissa == 0 ? FixedInt<N>(0) : FixedInt<N>::scaled(da.mantissa, shift_a);
    const FixedInt<N> H = FixedInt<N>::scaled(db.mantissa, shift_b) - A;
    bernstein_signs_of(c, degree_, A, H, static_cast<unsigned>(K), signs);
  });
  return degree_ + 1;
}

// ---- quadratics: the discriminant -------------------------------------------------------------
// PROOF: proofs/exact_ccd.md#quadratic-discriminant

int SmallPolynomial::quadratic_discriminant_sign() const {
  if (degree_ != 2) throw std::logic_error("exactccd: discriminant of a non-quadratic");
  // |c1^2| < 2^(2b), |4 c2 c0| < 2^(2b+2): the difference is below 2^(2b+3).
  const int limbs = in_gmp_ ? 0 : fixed_limbs_for(2 * bits_ + 3);
  if (limbs == 0) {
    ++g_gmp_steps;
    const std::array<mpz_class, 4> m = mpz_coefficients();
    return sgn(mpz_class(m[1] * m[1] - 4 * m[2] * m[0]));
  }
  return with_limbs(limbs, [&](auto n) {
    constexpr int N = decltype(n)::value;
    const FixedInt<N> c0 = fixed_[0].resized<N>(), c1 = fixed_[1].resized<N>(),
                      c2 = fixed_[2].resized<N>();
    FixedInt<N> four_c2 = c2;
    multiply_by(four_c2, 4u);
    return (c1 * c1 - four_c2 * c0).sign();
  });
}

std::array<mpz_class, 4> SmallPolynomial::reflected_coefficients() const {
  std::array<mpz_class, 4> storage, r;
  if (degree_ < 0) return r;
  const mpz_class* c = gmp_coefficients(&storage);
  // sum_i c_i (1 - u)^i = sum_j (-1)^j (sum_{i >= j} C(i, j) c_i) u^j.
  static constexpr unsigned long kBinomial[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0},
                                                    {1, 3, 3, 1}};
  for (int j = 0; j <= degree_; ++j) {
    mpz_class& rj = r[static_cast<std::size_t>(j)];
    for (int i = j; i <= degree_; ++i)
      mpz_addmul_ui(rj.get_mpz_t(), c[i].get_mpz_t(), kBinomial[i][j]);
    if (j % 2 == 1) rj = -rj;
  }
  return r;
}

SmallPolynomial SmallPolynomial::reflected() const {
  if (degree_ < 0) return {};
  return from_mpz(reflected_coefficients().data(), degree_ + 1, this);
}

SmallPolynomial SmallPolynomial::double_root_factor() const {
  if (degree_ != 2) throw std::logic_error("exactccd: double root of a non-quadratic");
  // |2 c2| < 2^(b+1), |c1| < 2^b.
  if (in_gmp_ || fixed_limbs_for(bits_ + 1) == 0) {
    const std::array<mpz_class, 4> m = mpz_coefficients();
    const mpz_class c[2] = {m[1], mpz_class(2 * m[2])};
    return from_mpz(c, 2);
  }
  Stored c[2] = {fixed_[1], fixed_[2]};
  c[1] += fixed_[2];
  return from_fixed(c, 2, bits_ + 1);
}

// ---- the sign at the roots of a divisor, in fixed size ----------------------------------------
// PROOF: proofs/exact_ccd.md#constant-remainder

bool SmallPolynomial::sign_at_roots_of(const SmallPolynomial& p, int* sign) const {
  const int dg = degree_, dp = p.degree_;
  if (dp < 1 || dg < dp || in_gmp_ || p.in_gmp_) return false;
  const int n = dg - dp + 1;  // elimination steps, each multiplying by lc(p)
  const int limbs = fixed_limbs_for(bits_ + n * (p.bits_ + 1));
  if (limbs == 0) return false;
  return with_limbs(limbs, [&](auto w) {
    constexpr int N = decltype(w)::value;
    FixedInt<N> a[4] = {fixed_[0].resized<N>(), fixed_[1].resized<N>(), fixed_[2].resized<N>(),
                        fixed_[3].resized<N>()};
    const FixedInt<N> b[4] = {p.fixed_[0].resized<N>(), p.fixed_[1].resized<N>(),
                              p.fixed_[2].resized<N>(), p.fixed_[3].resized<N>()};
    const FixedInt<N>& lc = b[dp];
    for (int k = dg; k >= dp; --k) {  // lc a - a_k t^(k - dp) b: the t^k term cancels
      const FixedInt<N> lead = a[k];
      for (int i = 0; i < k; ++i) a[i] *= lc;
      for (int i = 0; i < dp; ++i) a[i + k - dp] -= lead * b[i];
      a[k] = 0;
    }
    for (int i = 1; i < dp; ++i)
      if (a[i].sign() != 0) return false;  // h of degree >= 1
    const int epsilon = lc.sign() < 0 && n % 2 == 1 ? -1 : 1;
    *sign = epsilon * a[0].sign();
    return true;
  });
}

// ---- GMP steps ---------------------------------------------------------------------------------

namespace {

void set_degree(MpzPolynomial& p) {
  p.degree = -1;
  for (int i = 3; i >= 0; --i)
    if (sgn(p.c[i]) != 0) {
      p.degree = i;
      return;
    }
}

/// Content 1 and a positive leading coefficient.
void make_primitive(MpzPolynomial& p) {
  if (p.degree < 0) return;
  mpz_class g = 0;
  for (int i = 0; i <= p.degree; ++i) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), p.c[i].get_mpz_t());
  if (sgn(p.c[p.degree]) < 0) g = -g;
  for (int i = 0; i <= p.degree; ++i) mpz_divexact(p.c[i].get_mpz_t(), p.c[i].get_mpz_t(), g.get_mpz_t());
}

/// The pseudo-remainder of a by b (deg b >= 0): lc(b)^e a - Q b of degree < deg b.
MpzPolynomial pseudo_remainder(MpzPolynomial r, const MpzPolynomial& b) {
  while (r.degree >= b.degree) {
    const int shift = r.degree - b.degree;
    const mpz_class lead = r.c[r.degree];
    for (int i = 0; i <= r.degree; ++i) r.c[i] *= b.c[b.degree];
    for (int i = 0; i <= b.degree; ++i) r.c[i + shift] -= lead * b.c[i];
    set_degree(r);  // the leading term cancelled exactly
  }
  return r;
}

}  // namespace

MpzPolynomial to_mpz_polynomial(const SmallPolynomial& p) {
  ++g_gmp_steps;
  MpzPolynomial m;
  m.c = p.mpz_coefficients();
  set_degree(m);
  return m;
}

SmallPolynomial to_small_polynomial(const MpzPolynomial& p) {
  return SmallPolynomial::from_mpz(p.c.data(), 4);
}

MpzPolynomial polynomial_gcd(MpzPolynomial a, MpzPolynomial b) {
  if (a.degree < b.degree) std::swap(a, b);
  while (b.degree >= 0) {
    MpzPolynomial r = pseudo_remainder(a, b);
    make_primitive(r);
    a = std::move(b);
    b = std::move(r);
  }
  make_primitive(a);
  return a;
}

int sign_at_dyadic(const MpzPolynomial& p, const mpz_class& T, unsigned k) {
  ++g_gmp_steps;
  if (p.degree < 0) return 0;
  return sgn(scaled_value(p.c.data(), p.degree, T, k));
}

int bernstein_signs_dyadic(const MpzPolynomial& p, const mpz_class& A, const mpz_class& B,
                           unsigned K, int (&signs)[4]) {
  if (p.degree < 0) {
    signs[0] = 0;
    return 1;
  }
  const mpz_class H = B - A;
  bernstein_signs_of(p.c.data(), p.degree, A, H, K, signs);
  return p.degree + 1;
}

/// The pseudo-remainder lc(b)^n a = Q b + r, n = deg a - deg b + 1 (deg a >= deg b >= 0), and
/// the sign of lc(b)^n: r(x) has the sign of that times a(x) at every root x of b.
int pseudo_remainder(MpzPolynomial a, const MpzPolynomial& b, MpzPolynomial* r) {
  const int n = a.degree - b.degree + 1;
  for (int k = a.degree; k >= b.degree; --k) {
    const mpz_class lead = a.c[static_cast<std::size_t>(k)];
    for (int i = 0; i <= a.degree; ++i)
      a.c[static_cast<std::size_t>(i)] *= b.c[static_cast<std::size_t>(b.degree)];
    for (int i = 0; i <= b.degree; ++i)
      a.c[static_cast<std::size_t>(i + k - b.degree)] -= lead * b.c[static_cast<std::size_t>(i)];
    a.c[static_cast<std::size_t>(k)] = 0;  // cancelled exactly
  }
  set_degree(a);
  *r = a;
  return (sgn(b.c[static_cast<std::size_t>(b.degree)]) < 0 && n % 2 == 1) ? -1 : 1;
}

/// The sign of X + Y sqrt(D), D >= 0.
int sign_plus_sqrt(const mpz_class& X, const mpz_class& Y, const mpz_class& D) {
  const int sx = sgn(X), sy = sgn(Y);
  if (sy == 0 || sgn(D) == 0) return sx;
  if (sx == 0 || sx == sy) return sy;
  const int c = cmp(mpz_class(X * X), mpz_class(Y * Y * D));  // |X| against |Y| sqrt(D)
  return c > 0 ? sx : c < 0 ? sy : 0;
}

namespace {

int coefficient_sign(const MpzPolynomial& p, int i) {
  return sgn(p.c[static_cast<std::size_t>(i)]);
}

}  // namespace

int sign_at_root_by_remainders(const MpzPolynomial& p, const MpzPolynomial& g,
                               const mpz_class& A, const mpz_class& B, unsigned K, int sign_lo) {
  ++g_gmp_steps;
  if (g.degree < 0) return 0;
  // h = prem(g, p): at the root r of p, h(r) = sign_h * (positive) * g(r).
  MpzPolynomial h = g;
  int sign_h = 1;
  if (g.degree >= p.degree) sign_h = pseudo_remainder(g, p, &h);
  if (h.degree <= 0) return sign_h * (h.degree < 0 ? 0 : coefficient_sign(h, 0));
  // h of degree 1 or 2 (< deg p): its real roots s = (P + sigma sqrt(D)) / Q, sigma = +-1.
  mpz_class P, Q, D;
  int roots = 1;  // counted with multiplicity
  if (h.degree == 1) {
    P = -h.c[0];
    Q = h.c[1];
    D = 0;
  } else {
    D = h.c[1] * h.c[1] - 4 * h.c[2] * h.c[0];
    if (sgn(D) < 0) return sign_h * coefficient_sign(h, 2);  // h has the sign of lc(h) on R
    P = -h.c[1];
    Q = 2 * h.c[2];
    roots = 2;
  }
  // The sign of p at a root s of h: from an enclosure where the exact integers would be wide,
  // else (or when the enclosure cannot tell) from q = prem(p, h), of degree <= 1, whose value
  // at s has the sign of sign_q * p(s); q is computed once, when first needed.
  const long exact_bits = max_coefficient_bits(p) + 3 * max_coefficient_bits(h);
  MpzPolynomial q;
  int sign_q = 0;
  auto p_sign_at_root_of_h = [&](int sigma) {
    if (exact_bits > kIntervalFirstBits)
      if (const std::optional<int> s = interval_sign_at_irrational(p, P, sigma, D, Q, exact_bits))
        return *s;
    if (sign_q == 0) sign_q = pseudo_remainder(p, h, &q);
    const mpz_class alpha = q.degree >= 1 ? q.c[1] : mpz_class(0);
    const mpz_class beta = q.degree >= 0 ? q.c[0] : mpz_class(0);
    return sign_q * sgn(Q) * sign_plus_sqrt(alpha * P + beta * Q, sigma * alpha, D);
  };
  const mpz_class scale = mpz_class(1) << K;
  const int sign_Q = sgn(Q);
  // sign(r - s) for each root s of h, from s against a = A 2^-K and b = B 2^-K, and the sign of
  // p at s: r is the only root of p in (a, b), with p(a) of sign sign_lo and p(b) the other.
  int product = sign_h * coefficient_sign(h, h.degree);
  for (int k = 0; k < roots; ++k) {
    const int sigma = k == 0 ? 1 : -1;
    const int s_minus_a = sign_Q * sign_plus_sqrt(P * scale - Q * A, sigma * scale, D);
    const int s_minus_b = sign_Q * sign_plus_sqrt(P * scale - Q * B, sigma * scale, D);
    int r_minus_s;
    if (s_minus_a <= 0) {
      r_minus_s = 1;
    } else if (s_minus_b >= 0) {
      r_minus_s = -1;
    } else {  // a < s < b: p(s) = 0 puts s at r, p(s) of p(a)'s sign between a and r
      const int p_at_s = p_sign_at_root_of_h(sigma);
      r_minus_s = p_at_s == 0 ? 0 : p_at_s == sign_lo ? 1 : -1;
    }
    product *= r_minus_s;
    if (product == 0) return 0;
  }
  return product;  // D = 0: the double root was counted twice, as it should
}

namespace {

/// The Mersenne prime 2^61 - 1: products of residues fit 128 bits, reduced by shifts.
constexpr std::uint64_t kResiduePrime = (std::uint64_t{1} << 61) - 1;

std::uint64_t residue_product(std::uint64_t a, std::uint64_t b) {
  const unsigned __int128 x = static_cast<unsigned __int128>(a) * b;
  std::uint64_t r = static_cast<std::uint64_t>(x & kResiduePrime) +
                    static_cast<std::uint64_t>(x >> 61);
  r = (r & kResiduePrime) + (r >> 61);
  return r >= kResiduePrime ? r - kResiduePrime : r;
}

std::uint64_t residue_sum(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t r = a + b;  // both < 2^61: no overflow
  return r >= kResiduePrime ? r - kResiduePrime : r;
}

std::uint64_t residue_of(const mpz_class& x) {
  static_assert(sizeof(unsigned long) == 8, "a 64-bit unsigned long for mpz_fdiv_ui");
  return mpz_fdiv_ui(x.get_mpz_t(), kResiduePrime);  // in [0, prime), also for negative x
}

std::uint64_t residue_of(long k) {
  const std::uint64_t m = static_cast<std::uint64_t>(k < 0 ? -k : k) % kResiduePrime;
  return k < 0 && m != 0 ? kResiduePrime - m : m;
}

}  // namespace

bool square_free_by_residue(const SmallPolynomial& p) {
  const int d = p.degree();
  if (d == 1) return true;
  if (d != 2 && d != 3) return false;
  const std::array<mpz_class, 4> m = p.mpz_coefficients();
  std::uint64_t c[4];
  for (int i = 0; i < 4; ++i) c[i] = residue_of(m[static_cast<std::size_t>(i)]);
  auto mul = [](std::initializer_list<std::uint64_t> f) {
    std::uint64_t r = 1;
    for (std::uint64_t x : f) r = residue_product(r, x);
    return r;
  };
  std::uint64_t discriminant;
  if (d == 2) {  // c1^2 - 4 c2 c0
    discriminant = residue_sum(mul({c[1], c[1]}), mul({residue_of(-4L), c[2], c[0]}));
  } else {  // a t^3 + b t^2 + c t + e: b^2c^2 - 4ac^3 - 4b^3e - 27a^2e^2 + 18abce
    const std::uint64_t a = c[3], b = c[2], cc = c[1], e = c[0];
    discriminant = mul({b, b, cc, cc});
    discriminant = residue_sum(discriminant, mul({residue_of(-4L), a, cc, cc, cc}));
    discriminant = residue_sum(discriminant, mul({residue_of(-4L), b, b, b, e}));
    discriminant = residue_sum(discriminant, mul({residue_of(-27L), a, a, e, e}));
    discriminant = residue_sum(discriminant, mul({residue_of(18L), a, b, cc, e}));
  }
  return discriminant != 0;
}

SmallPolynomial square_free_part(const SmallPolynomial& p) {
  const MpzPolynomial a = to_mpz_polynomial(p);
  if (a.degree < 1) throw std::invalid_argument("exactccd: square-free part of a constant");
  MpzPolynomial derivative;
  for (int i = 1; i <= a.degree; ++i) derivative.c[i - 1] = a.c[i] * i;
  set_degree(derivative);
  const MpzPolynomial h = polynomial_gcd(a, derivative);
  if (h.degree < 1) return p;
  // a / h: h is primitive and divides a over the rationals, so the quotient has integer
  // coefficients (Gauss's lemma) and every division below is exact.
  MpzPolynomial r = a, q;
  for (int k = a.degree - h.degree; k >= 0; --k) {
    mpz_divexact(q.c[k].get_mpz_t(), r.c[k + h.degree].get_mpz_t(), h.c[h.degree].get_mpz_t());
    for (int i = 0; i <= h.degree; ++i) r.c[i + k] -= q.c[k] * h.c[i];
  }
  set_degree(q);
  return to_small_polynomial(q);
}

}  // namespace exactccd::exact
