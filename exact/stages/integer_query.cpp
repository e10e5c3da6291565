#include "exact/stages/integer_query.hpp"

#include "exact/arithmetic/fixed_width_dispatch.hpp"
#include "exact/arithmetic/product_accumulator.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace exactccd::exact {

namespace {

thread_local std::uint64_t g_gmp_computations = 0;

/// The distinct stage widths of the cubic for L = 0 ... kMaxFixedCoordinateBits, in order of L
/// (each width grows with L, so equal widths are consecutive).
struct CubicWidthTable {
  CubicWidths widths[64] = {};
  int count = 0;
};

constexpr CubicWidthTable make_cubic_width_table() {
  CubicWidthTable t;
  for (long L = 0; L <= kMaxFixedCoordinateBits; ++L) {
    const CubicWidths w = cubic_widths(L);
    if (t.count == 0 || !(t.widths[t.count - 1] == w)) t.widths[t.count++] = w;
  }
  return t;
}

constexpr CubicWidthTable kCubicWidthTable = make_cubic_width_table();
static_assert(kCubicWidthTable.count <= 32, "the table of cubic widths is larger than expected");

/// Computes the coefficients in the stage widths of row I of the table.
template <int I>
void fixed_coefficients(const IntegerCoordinates& q, FixedInt<kMaxFixedLimbs> (&out)[4]) {
  constexpr CubicWidths w = kCubicWidthTable.widths[I];
  using Ints = CubicIntegers<FixedInt<w.difference>, FixedInt<w.cross_product>,
                             FixedInt<w.coefficient>>;
  FixedInt<w.coefficient> c[4];
  coplanarity_coefficients<Ints>(q, c);
  for (int i = 0; i < 4; ++i) out[i] = c[i].template resized<kMaxFixedLimbs>();
}

template <std::size_t... I>
void fixed_coefficients(const IntegerCoordinates& q, FixedInt<kMaxFixedLimbs> (&out)[4],
                        std::index_sequence<I...>) {
  const CubicWidths w = cubic_widths(q.bits);
  const bool done = ((kCubicWidthTable.widths[I] == w && (fixed_coefficients<I>(q, out), true)) ||
                     ...);
  if (!done) throw std::logic_error("exactccd: no fixed width for the cubic's coefficients");
}

/// 2^(3k) f(t) at t = T 2^-k in N limbs, from the coefficients kept in kMaxFixedLimbs limbs.
/// Truncating them to N limbs is exact: N is at least their own width (the value's bound exceeds
/// the coefficients').
template <int N>
FixedInt<N> fixed_scaled_value(const FixedInt<kMaxFixedLimbs> (&stored)[4], DyadicTime d) {
  const FixedInt<N> c[4] = {stored[0].resized<N>(), stored[1].resized<N>(),
                            stored[2].resized<N>(), stored[3].resized<N>()};
  return scaled_cubic_value(c, d.numerator, d.exponent);
}

/// t in [0, 1] as T 2^-k; std::domain_error otherwise.
DyadicTime time_in_unit_interval(double t) {
  DyadicTime d;
  if (!dyadic_time(t, &d))
    throw std::domain_error("exactccd: exact test at a time outside [0, 1]");
  return d;
}

}  // namespace

std::uint64_t gmp_computations_in_this_thread() noexcept { return g_gmp_computations; }

IntegerQuery::IntegerQuery(const VertexFaceQuery& q, Arithmetic a)
    : coords_(integer_coordinates(q)), arithmetic_(a) {
  compute_coefficients();
}

IntegerQuery::IntegerQuery(const EdgeEdgeQuery& q, Arithmetic a)
    : coords_(integer_coordinates(q)), arithmetic_(a) {
  compute_coefficients();
}

void IntegerQuery::compute_coefficients() {
  coefficient_limbs_ = arithmetic_ == Arithmetic::gmp
                           ? 0
                           : fixed_limbs_for(cubic_coefficient_bits(coords_.bits));
  if (coefficient_limbs_ == 0) {
    ++g_gmp_computations;
    gmp_.emplace();
    // GMP requested: the plain reference; beyond the fixed widths: sums of mantissa products
    // (exact/arithmetic/product_accumulator.hpp, the same integers).
    if (arithmetic_ == Arithmetic::fixed_first)
      accumulated_coplanarity_coefficients(coords_, gmp_->c);
    else
      coplanarity_coefficients(coords_, gmp_->c);
    return;
  }
  fixed_coefficients(coords_, fixed_,
                     std::make_index_sequence<static_cast<std::size_t>(kCubicWidthTable.count)>());
}

int IntegerQuery::value_limbs(double t) const {
  const DyadicTime d = time_in_unit_interval(t);
  return value_limbs(d);
}

int IntegerQuery::value_limbs(DyadicTime d) const {
  if (coefficient_limbs_ == 0) return 0;  // coefficients in GMP (or GMP requested)
  return fixed_limbs_for(cubic_value_bits(coords_.bits, d.exponent));
}

int IntegerQuery::contact_limbs(double t) const {
  const DyadicTime d = time_in_unit_interval(t);
  if (arithmetic_ == Arithmetic::gmp) return 0;
  return fixed_limbs_for(contact_bits(coords_.bits, d.exponent));
}

void IntegerQuery::gmp_coefficients(mpz_class (&c)[4]) const {
  for (int i = 0; i < 4; ++i) c[i] = gmp_ ? gmp_->c[i] : to_mpz(fixed_[i]);
}

std::array<mpz_class, 4> IntegerQuery::coefficients() const {
  mpz_class c[4];
  gmp_coefficients(c);
  return {c[0], c[1], c[2], c[3]};
}

namespace {

/// 2^(3k) f(t) in GMP for any finite t >= 0 (t > 1 included: then k = 0 and T an integer when
/// t >= 2^53, else T 2^-k with T > 2^k, outside the fixed-size bounds).
mpz_class gmp_scaled_value(const mpz_class (&c)[4], double t) {
  const Dyadic d = dyadic(t);
  if (d.mantissa == 0) return c[0];
  if (d.exponent >= 0) {
    const mpz_class T = mpz_class(d.mantissa) << static_cast<unsigned>(d.exponent);
    return scaled_cubic_value(c, T, 0);
  }
  return scaled_cubic_value(c, static_cast<std::uint64_t>(d.mantissa),
                            static_cast<unsigned>(-d.exponent));
}

}  // namespace

mpz_class IntegerQuery::gmp_scaled_value_at(double t) const {
  ++g_gmp_computations;
  mpz_class converted[4];
  if (!gmp_) gmp_coefficients(converted);
  return gmp_scaled_value(*(gmp_ ? &gmp_->c : &converted), t);
}

mpz_class IntegerQuery::scaled_value_at(double t) const {
  const DyadicTime d = time_in_unit_interval(t);
  const int limbs = value_limbs(d);
  if (limbs == 0) return gmp_scaled_value_at(t);
  return with_limbs(limbs, [&](auto n) {
    return to_mpz(fixed_scaled_value<decltype(n)::value>(fixed_, d));
  });
}

int IntegerQuery::sign_at(double t, Approximation* value) const {
  DyadicTime d;
  const int limbs = dyadic_time(t, &d) ? value_limbs(d) : 0;  // t > 1: GMP
  if (limbs != 0) {
    return with_limbs(limbs, [&](auto n) {
      const auto r = fixed_scaled_value<decltype(n)::value>(fixed_, d);
      if (value) {
        *value = approximate(r);
        value->exponent -= 3L * d.exponent;  // f(t) = 2^(-3k) r
      }
      return sign_of(r);
    });
  }
  if (!(t >= 0) || !std::isfinite(t))
    throw std::domain_error("exactccd: cubic sign at a time that is not a finite t >= 0");
  const mpz_class r = gmp_scaled_value_at(t);
  if (value) {
    *value = approximate(r);
    const Dyadic dt = dyadic(t);
    if (dt.exponent < 0) value->exponent += 3L * dt.exponent;  // f(t) = 2^(-3k) r, k = -exponent
  }
  return sign_of(r);
}

void IntegerQuery::approximate_coefficients(Approximation (&c)[4]) const {
  if (gmp_) {
    for (int i = 0; i < 4; ++i) c[i] = approximate(gmp_->c[i]);
    return;
  }
  with_limbs(coefficient_limbs_, [&](auto n) {  // in their own width: fewer limbs to read
    constexpr int N = decltype(n)::value;
    for (int i = 0; i < 4; ++i) c[i] = approximate(fixed_[i].resized<N>());
  });
}

bool IntegerQuery::contact_at(double t) const {
  const DyadicTime d = time_in_unit_interval(t);
  const int limbs = contact_limbs(t);
  if (limbs == 0) {
    ++g_gmp_computations;
    return contact_at_time<mpz_class>(coords_, d.numerator, d.exponent);
  }
  // Positions in P limbs, products in 2P (at most the widest fixed width), else full width.
  const int position_limbs =
      fixed_limbs_for(contact_position_bits(coords_.bits, static_cast<long>(d.exponent)));
  if (position_limbs != 0 && 2 * position_limbs <= kMaxFixedLimbs) {
    return with_limbs(position_limbs, [&](auto n) {
      constexpr int P = decltype(n)::value;
      if constexpr (2 * P <= kMaxFixedLimbs) {
        return contact_at_time_widening<P>(coords_, d.numerator, d.exponent);
      } else {
        return contact_at_time<FixedInt<P>>(coords_, d.numerator, d.exponent);  // not reached
      }
    });
  }
  return with_limbs(limbs, [&](auto n) {
    return contact_at_time<FixedInt<decltype(n)::value>>(coords_, d.numerator, d.exponent);
  });
}

void IntegerQuery::scaled_coefficient_bounds(double (&lo)[4], double (&hi)[4]) const {
  LeadingBits b[4];
  int sign[4];
  if (gmp_) {
    for (int i = 0; i < 4; ++i) b[i] = leading_bits(gmp_->c[i]), sign[i] = sign_of(gmp_->c[i]);
  } else {
    with_limbs(coefficient_limbs_, [&](auto n) {  // in their own width
      constexpr int N = decltype(n)::value;
      for (int i = 0; i < 4; ++i) {
        const FixedInt<N> c = fixed_[i].resized<N>();
        b[i] = leading_bits(c), sign[i] = sign_of(c);
      }
    });
  }
  // |c_i| < 2^(e_i + bits(m_i)), its bit length: dividing by 2^s, s the largest bit length,
  // leaves the largest |c_i| in [1/2, 1) and every one below 1.
  long s = LONG_MIN;
  for (const LeadingBits& bi : b)
    if (bi.m != 0) s = std::max(s, bi.e + 64 - __builtin_clzll(bi.m));
  for (int i = 0; i < 4; ++i) {
    double low = 0, high = 0;  // bounds of |c_i| 2^-s
    if (b[i].m != 0) {
      const long k = b[i].e - s;  // |c_i| 2^-s = (m + r 2^-e) 2^k, 0 <= r 2^-e < 1
      if (k >= -1074) {
        // m 2^k and (m + 1) 2^k are doubles (m + 1 <= 2^53, k >= -1074): ldexp is exact.
        low = std::ldexp(static_cast<double>(b[i].m), static_cast<int>(k));
        high = b[i].inexact ? std::ldexp(static_cast<double>(b[i].m + 1), static_cast<int>(k))
                            : low;
      } else {
        high = 0x1p-1021;  // |c_i| 2^-s < 2^(k + 53) <= 2^-1021
      }
    }
    lo[i] = sign[i] < 0 ? -high : low;
    hi[i] = sign[i] < 0 ? -low : high;
  }
}

}  // namespace exactccd::exact
