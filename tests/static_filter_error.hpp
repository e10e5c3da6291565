// An error-tracking number type, after CGAL's Static_filter_error: evaluating a floating-point
// expression on it yields a certified bound on that expression's rounding error. A value stands
// for every double the expression can compute at that point, and carries
//   bound: an upper bound on |computed value|,
//   error: an upper bound on |computed value - exact value| (the same expression evaluated in
//          exact arithmetic on the exact inputs),
// both in units of the value's scale Mx^dx My^dy Mz^dz, where Mk is the maximum of the computed
// leaves of coordinate k and (dx, dy, dz) the value's degree. Unlike CGAL's type (half an ulp of
// the bound), each rounding costs u times the bound: relative errors do not depend on the scale,
// so the bound holds for column maxima that are not powers of two.
//
// The bound arithmetic is exact (mpq): a constant computed with it is certified, not rounded.
// Model: IEEE double, round to nearest, u = 2^-53; every column maximum Mk in
// [2^kMinExponent, 2^kMaxExponent] (the caller's range check); each product may underflow
// (absolute error at most 2^-1075); sums and differences of doubles whose exact result is
// subnormal are exact, so they keep the relative model; overflow is ruled out or reported.
// PROOF: proofs/filters.md#error-tracking
#pragma once

#include <gmpxx.h>

#include <array>
#include <stdexcept>
#include <utility>

namespace exactccd::filters {

template <int kMinExponent, int kMaxExponent>
class StaticFilterError {
  static_assert(kMinExponent <= kMaxExponent, "empty column-maximum range");

 public:
  /// Factors per coordinate column; sums need equal degrees (one scale for all their terms).
  using Degree = std::array<int, 3>;

  /// A difference of two input doubles in coordinate `axis`, rounded once: e = fl(x - y). Its
  /// column maximum is taken over the computed |e|, so |e| <= 1; the exact E = x - y has
  /// e = E (1 + d), |d| <= u, so |e - E| <= u |E| <= u / (1 - u).
  static StaticFilterError rounded_difference(int axis) {
    Degree degree{0, 0, 0};
    degree.at(static_cast<std::size_t>(axis)) = 1;
    const mpq_class u = unit_roundoff();
    return StaticFilterError(mpq_class(1), mpq_class(u / (1 - u)), degree);
  }

  static mpq_class unit_roundoff() { return power_of_two(-53); }

  const mpq_class& bound() const { return bound_; }
  const mpq_class& error() const { return error_; }
  const Degree& degree() const { return degree_; }

  /// fl(a * b): exact product of the computed operands, then one rounding.
  friend StaticFilterError operator*(const StaticFilterError& a, const StaticFilterError& b) {
    return fused_multiply_add(a, b, StaticFilterError(0, 0, sum(a.degree_, b.degree_)));
  }

  /// fl(a + b) and fl(a - b): the bounds do not depend on the signs.
  friend StaticFilterError operator+(const StaticFilterError& a, const StaticFilterError& b) {
    require_same_degree(a.degree_, b.degree_);
    const mpq_class u = unit_roundoff();
    const mpq_class s = a.bound_ + b.bound_;
    return checked(s * (1 + u), u * s + a.error_ + b.error_, a.degree_);
  }
  friend StaticFilterError operator-(const StaticFilterError& a, const StaticFilterError& b) {
    return a + b;
  }
  /// -a is exact.
  friend StaticFilterError operator-(const StaticFilterError& a) { return a; }

  /// fl(a * b + c) with one rounding (an FMA; a plain product when c is an exact zero). With
  /// p = a * b + c on the computed operands and P the exact one,
  /// |p - P| <= |a| e_b + |b| e_a + e_a e_b + e_c, and |fl(p) - p| <= u |p| + (underflow).
  friend StaticFilterError fused_multiply_add(const StaticFilterError& a, const StaticFilterError& b,
                                              const StaticFilterError& c) {
    const Degree degree = sum(a.degree_, b.degree_);
    require_same_degree(degree, c.degree_);
    const mpq_class u = unit_roundoff(), underflow = underflow_error(degree);
    const mpq_class p = a.bound_ * b.bound_ + c.bound_;
    return checked(p * (1 + u) + underflow,
                   u * p + underflow + a.bound_ * b.error_ + b.bound_ * a.error_ +
                       a.error_ * b.error_ + c.error_,
                   degree);
  }

 private:
  StaticFilterError(mpq_class bound, mpq_class error, Degree degree)
      : bound_(std::move(bound)), error_(std::move(error)), degree_(degree) {}

  static mpq_class power_of_two(int e) {
    mpq_class r(1);
    if (e >= 0) mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    else mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    return r;
  }

  static int total(const Degree& d) { return d[0] + d[1] + d[2]; }
  static Degree sum(const Degree& a, const Degree& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
  }

  static void require_same_degree(const Degree& a, const Degree& b) {
    if (a != b)
      throw std::domain_error(
          "StaticFilterError: sum of terms of different degrees (no common scale)");
  }

  /// A rounding that underflows errs by at most 2^-1075 absolutely, i.e. 2^-1075 / scale in
  /// units of a scale >= 2^(kMinExponent * degree).
  static mpq_class underflow_error(const Degree& d) {
    return power_of_two(-1075 - kMinExponent * total(d));
  }

  /// |computed| <= bound * scale <= bound * 2^(kMaxExponent * degree) must stay below the
  /// overflow threshold, or the model (and the filter) would be wrong.
  static StaticFilterError checked(mpq_class bound, mpq_class error, const Degree& degree) {
    if (bound * power_of_two(kMaxExponent * total(degree)) > power_of_two(1023))
      throw std::overflow_error("StaticFilterError: the expression may overflow");
    return StaticFilterError(std::move(bound), std::move(error), degree);
  }

  mpq_class bound_, error_;
  Degree degree_;
};

}  // namespace exactccd::filters
