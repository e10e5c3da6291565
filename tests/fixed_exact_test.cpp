// The fixed-size exact integers of the exact-at-double-times stage:
//  - FixedInt<N> arithmetic against GMP (residues modulo 2^(64N), and exact values);
//  - the bit-length bounds of exact/arithmetic/integer_bounds.hpp against the bit lengths the
//  kernels
//    of exact/stages/integer_cubic.hpp really reach, measured by instantiating the same templates
//    with an integer type that records the bit length of every value it produces, on adversarial
//    queries at the bound (coordinates of the largest bit length a width admits, times with the
//    largest admissible exponent k); the bounds must hold and be nearly reached;
//  - the width selection: each computation runs in the FixedInt its bound selects, and in GMP
//    just beyond the largest fixed width, with the same exact results.
// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "corpus/random_queries.hpp"
#include "exact/stages/integer_query.hpp"
#include "fixed_int_support.hpp"
#include "tests/test_scale.hpp"

// ---------------------------------------------------------------------------------------------
// An integer type that records the largest bit length of any value it produces, per stage of
// a computation (the cubic's differences, cross products and dot products are three types).

namespace bit_recording {

thread_local long g_max_bits[3] = {};

template <int Stage>
class Recording {
 public:
  Recording() = default;
  Recording(std::int64_t v) : v_(static_cast<long>(v)) { note(); }  // NOLINT: as mpz_class
  explicit Recording(mpz_class v) : v_(std::move(v)) { note(); }

  const mpz_class& value() const { return v_; }

  friend Recording operator+(const Recording& a, const Recording& b) {
    return Recording(mpz_class(a.v_ + b.v_));
  }
  friend Recording operator-(const Recording& a, const Recording& b) {
    return Recording(mpz_class(a.v_ - b.v_));
  }
  friend Recording operator*(const Recording& a, const Recording& b) {
    return Recording(mpz_class(a.v_ * b.v_));
  }
  friend Recording operator-(const Recording& a) { return Recording(mpz_class(-a.v_)); }
  friend Recording operator<<(const Recording& a, unsigned s) {
    return Recording(mpz_class(a.v_ << s));
  }
  Recording& operator+=(const Recording& o) {
    v_ += o.v_;
    note();
    return *this;
  }
  Recording& operator-=(const Recording& o) {
    v_ -= o.v_;
    note();
    return *this;
  }

 private:
  void note() const {
    g_max_bits[Stage] = std::max(g_max_bits[Stage], exactccd::exact::bit_length(v_));
  }
  mpz_class v_;
};

// The operations the kernels call (found by argument-dependent lookup). The products and the
// shifted terms are values in their own right, as they are for GMP; a product is formed in the
// stage of the value it is added to, as FixedInt::product forms it in that width.
template <int S>
int sign_of(const Recording<S>& x) {
  return sgn(x.value());
}
template <int S>
void multiply_by(Recording<S>& r, std::uint64_t m) {
  r = Recording<S>(mpz_class(r.value() * exactccd::exact::mpz_from_u64(m)));
}
template <int S>
void add_shifted(Recording<S>& r, const Recording<S>& c, unsigned s) {
  r += c << s;
}
template <int S, int A, int B>
void add_product(Recording<S>& out, const Recording<A>& a, const Recording<B>& b) {
  out += Recording<S>(mpz_class(a.value() * b.value()));
}
template <int S, int A, int B>
void sub_product(Recording<S>& out, const Recording<A>& a, const Recording<B>& b) {
  out -= Recording<S>(mpz_class(a.value() * b.value()));
}

/// One type for a whole computation (values, contact tests).
using RecordingInt = Recording<0>;
/// The cubic's three stages.
using RecordingCubic = exactccd::exact::CubicIntegers<Recording<0>, Recording<1>, Recording<2>>;

void reset() {
  for (long& m : g_max_bits) m = 0;
}

}  // namespace bit_recording

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

using bit_recording::Recording;
using bit_recording::RecordingCubic;
using bit_recording::RecordingInt;
using exact::FixedInt;
using exact::IntegerQuery;

std::uint64_t test_seed() {
  static const std::uint64_t seed = [] {
    const std::uint64_t s = seed_from_environment(0xf1ed);
    std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n", static_cast<unsigned long long>(s));
    return s;
  }();
  return seed;
}

// ---- FixedInt against GMP ----------------------------------------------------------------------

/// A random integer of random sign with a random bit length in [0, max_bits].
mpz_class random_integer(std::mt19937_64& rng, int max_bits) {
  const int bits = std::uniform_int_distribution<int>(0, max_bits)(rng);
  mpz_class z = 0;
  for (int done = 0; done < bits; done += 64) z = (z << 64) + exact::mpz_from_u64(rng());
  if (bits > 0) z >>= static_cast<unsigned>((bits + 63) / 64 * 64 - bits);
  if (bits > 0 && rng() % 4 != 0) mpz_setbit(z.get_mpz_t(), static_cast<mp_bitcnt_t>(bits - 1));
  return rng() % 2 ? mpz_class(-z) : z;
}

template <int N>
void check_fixed_arithmetic(std::mt19937_64& rng, int rounds) {
  SCOPED_TRACE("N = " + std::to_string(N));
  for (int i = 0; i < rounds; ++i) {
    // Operands that fit (the normal use) and some that wrap (residues must still agree).
    const int bits = i % 4 == 0 ? 64 * N + 40 : 64 * N - 1;
    const mpz_class a = residue(random_integer(rng, bits), N);
    const mpz_class b = residue(random_integer(rng, bits), N);
    const FixedInt<N> fa = fixed_from<N>(a), fb = fixed_from<N>(b);
    ASSERT_EQ(exact::to_mpz(fa), a);
    ASSERT_EQ(fa.sign(), sgn(a));
    ASSERT_EQ(exact::bit_length(fa), exact::bit_length(a));
    ASSERT_EQ(exact::to_mpz(fa + fb), residue(a + b, N));
    ASSERT_EQ(exact::to_mpz(fa - fb), residue(a - b, N));
    ASSERT_EQ(exact::to_mpz(fa * fb), residue(a * b, N));
    ASSERT_EQ(exact::to_mpz(-fa), residue(-a, N));
    const unsigned s = static_cast<unsigned>(rng() % (64 * N + 8));
    ASSERT_EQ(exact::to_mpz(fa << s), residue(a << s, N)) << "s = " << s;
    const std::uint64_t m = rng() >> (rng() % 64);
    FixedInt<N> fm = fa;
    fm.multiply_by(m);
    ASSERT_EQ(exact::to_mpz(fm), residue(a * exact::mpz_from_u64(m), N));
    const auto mantissa = static_cast<std::int64_t>(rng() >> 11) * (rng() % 2 ? 1 : -1);
    ASSERT_EQ(exact::to_mpz(FixedInt<N>::scaled(mantissa, s)),
              residue(mpz_class(static_cast<long>(mantissa)) << s, N));
    // Widening keeps the value; narrowing is reduction modulo 2^(64M).
    ASSERT_EQ(exact::to_mpz(fa.template resized<N + 2>()), a);
    if constexpr (N > 1) {
      ASSERT_EQ(exact::to_mpz(fa.template resized<N - 1>()), residue(a, N - 1));
    }
    // The leading bits used for guidance: a ~ m 2^e with 1/2 <= |m| <= 1 (for a < 0 of two
    // limbs or more from |a| - 1, so e may be one less at a power of two).
    const exact::Approximation approx = exact::approximate(fa);
    if (a == 0) {
      ASSERT_EQ(approx.mantissa, 0);
    } else {
      ASSERT_LE(approx.exponent, exact::bit_length(a));
      ASSERT_GE(approx.exponent, exact::bit_length(a) - (a < 0 ? 1 : 0));
      ASSERT_GE(std::fabs(static_cast<double>(approx.mantissa)), 0.5);
      ASSERT_LE(std::fabs(static_cast<double>(approx.mantissa)), 1.0);
      ASSERT_EQ(approx.mantissa < 0, a < 0);
      const mpq_class back = mpq_class(static_cast<double>(approx.mantissa)) *
                             mpq_class(mpz_class(1) << static_cast<unsigned>(approx.exponent));
      const mpq_class error = abs(back - mpq_class(a)) / abs(mpq_class(a));
      ASSERT_LE(error, mpq_class(1, 1 << 20));
    }
  }
}

TEST(FixedInt, MatchesGmpResidues) {
  std::mt19937_64 rng(test_seed());
  const int rounds = static_cast<int>(scaled_count(3000, scale_from_environment()));
  check_fixed_arithmetic<1>(rng, rounds);
  check_fixed_arithmetic<2>(rng, rounds);
  check_fixed_arithmetic<3>(rng, rounds);
  check_fixed_arithmetic<4>(rng, rounds);
  check_fixed_arithmetic<7>(rng, rounds);
  check_fixed_arithmetic<16>(rng, rounds);
}

TEST(FixedInt, EdgeValues) {
  // The extremes of the admitted range, zero, and carries across every limb.
  using F = FixedInt<3>;
  const mpz_class top = (mpz_class(1) << 191) - 1;
  EXPECT_EQ(exact::to_mpz(fixed_from<3>(top)), top);
  EXPECT_EQ(exact::to_mpz(fixed_from<3>(mpz_class(-top))), -top);
  EXPECT_EQ(exact::to_mpz(F(-1) + F(1)), 0);
  EXPECT_EQ(F(0).sign(), 0);
  EXPECT_EQ(F(-1).sign(), -1);
  EXPECT_EQ(exact::to_mpz(F(-1) * F(-1)), 1);
  EXPECT_EQ(exact::to_mpz((F(1) << 128) - F(1)), (mpz_class(1) << 128) - 1);
  EXPECT_EQ(exact::to_mpz(F(INT64_MIN)), mpz_class(static_cast<long>(INT64_MIN)));
  EXPECT_EQ(exact::to_mpz(F::scaled(INT64_MIN + 1, 120)),
            mpz_class(static_cast<long>(INT64_MIN + 1)) << 120);
  EXPECT_EQ(exact::bit_length(F(0)), 0);
  EXPECT_EQ(static_cast<double>(exact::approximate(F(-1)).mantissa), -0.5);
  EXPECT_EQ(exact::approximate(F(-1)).exponent, 1);
  EXPECT_EQ(exact::approximate(-(F(1) << 130)).exponent, 130);  // |a| - 1 = 2^130 - 1
  EXPECT_EQ(exact::approximate(-(F(1) << 64)).exponent, 65);
  EXPECT_EQ(static_cast<double>(exact::approximate(F(-3)).mantissa), -0.75);
}

// ---- adversarial queries at the bound ----------------------------------------------------------

/// The largest odd integer of at most min(L, 53) bits, times 2^(L - 53) for L > 53: the largest
/// magnitude a coordinate can have when the query's integers have L bits (E = 0).
double extreme(int bits) {
  if (bits <= 53) return std::ldexp(1.0, bits) - 1.0;
  return std::ldexp(std::ldexp(1.0, 53) - 1.0, bits - 53);
}

/// Every coordinate +-extreme(L) (signs from `signs`, bit i for coordinate i), except
/// coordinate `unit` which is +-1: then E = 0 and the query's integers have exactly L bits.
DoubleQuery adversarial_query(QueryType type, int bits, std::uint32_t signs, int unit) {
  DoubleQuery q;
  q.type = type;
  for (int i = 0; i < 24; ++i) {
    const double magnitude = i == unit ? 1.0 : extreme(bits);
    q.v[i / 3][i % 3] = (signs >> i) & 1 ? -magnitude : magnitude;
  }
  return q;
}

exact::IntegerCoordinates coordinates_of(const DoubleQuery& q) {
  return q.type == QueryType::vertex_face ? exact::integer_coordinates(q.vertex_face())
                                          : exact::integer_coordinates(q.edge_edge());
}

IntegerQuery integer_query(const DoubleQuery& q,
                           IntegerQuery::Arithmetic a = IntegerQuery::Arithmetic::fixed_first) {
  return q.type == QueryType::vertex_face ? IntegerQuery(q.vertex_face(), a)
                                          : IntegerQuery(q.edge_edge(), a);
}

/// The largest bit lengths of the values of the cubic's computation on q: the coordinates and
/// their differences, the cross products, the dot products (the coefficients).
struct CubicBits {
  long difference = 0, cross_product = 0, coefficient = 0;
  long largest() const { return std::max({difference, cross_product, coefficient}); }
};

CubicBits cubic_bits_reached(const exact::IntegerCoordinates& c, Recording<2> (&out)[4]) {
  bit_recording::reset();
  exact::coplanarity_coefficients<RecordingCubic>(c, out);
  return {bit_recording::g_max_bits[0], bit_recording::g_max_bits[1], bit_recording::g_max_bits[2]};
}

/// ... of 2^(3k) f(t) at t = T 2^-k.
long value_bits_reached(const Recording<2> (&c)[4], std::uint64_t T, unsigned k) {
  bit_recording::reset();
  exact::scaled_cubic_value(c, T, k);
  return bit_recording::g_max_bits[2];
}

/// ... of the contact test at t = T 2^-k.
long contact_bits_reached(const exact::IntegerCoordinates& c, std::uint64_t T, unsigned k) {
  bit_recording::reset();
  exact::contact_at_time<RecordingInt>(c, T, k);
  return bit_recording::g_max_bits[0];
}

/// T 2^-k in (0, 1] with T odd and as large as allowed: T = 2^k - 1 (k <= 53) or 2^53 - 1.
double time_with_exponent(unsigned k) {
  if (k == 0) return 1.0;
  const double T = k <= 53 ? std::ldexp(1.0, static_cast<int>(k)) - 1.0 : std::ldexp(1.0, 53) - 1.0;
  return std::ldexp(T, -static_cast<int>(k));
}

/// The largest bit length of the cubic's computation on the adversarial query.
long cubic_score(QueryType type, int bits, std::uint32_t signs) {
  Recording<2> c[4];
  return cubic_bits_reached(coordinates_of(adversarial_query(type, bits, signs, 23)), c).largest();
}

/// The bit length of sum |c_i|, which bounds the values near t = 1.
long coefficient_sum_score(QueryType type, int bits, std::uint32_t signs) {
  Recording<2> c[4];
  cubic_bits_reached(coordinates_of(adversarial_query(type, bits, signs, 23)), c);
  mpz_class sum = 0;
  for (const Recording<2>& ci : c) sum += abs(ci.value());
  return exact::bit_length(sum);
}

/// Random sign patterns, kept by hill climbing on `score`: inputs near the worst case.
template <class Score>
std::vector<std::uint32_t> adversarial_signs(QueryType type, int bits, std::mt19937_64& rng,
                                             int restarts, Score score) {
  std::vector<std::uint32_t> out;
  for (int r = 0; r < restarts; ++r) {
    auto signs = static_cast<std::uint32_t>(rng() & 0xffffff);
    long best = score(type, bits, signs);
    for (bool improved = true; improved;) {
      improved = false;
      for (int i = 0; i < 23; ++i) {
        const std::uint32_t flipped = signs ^ (1u << i);
        const long s = score(type, bits, flipped);
        if (s > best) best = s, signs = flipped, improved = true;
      }
    }
    out.push_back(signs);
  }
  return out;
}

/// The largest L whose coefficients fit in `limbs` limbs.
int largest_bits_for_coefficients(int limbs) { return (64 * limbs - 1 - 10) / 3; }

/// The coordinate bits at which some stage of the cubic is at the top of its width: the
/// largest L for each width of the differences, the cross products and the coefficients.
std::vector<int> cubic_boundary_bits() {
  std::vector<int> out;
  for (int limbs = 1; limbs <= exact::kMaxFixedLimbs; ++limbs) {
    for (int L :
         {64 * limbs - 1 - 2, (64 * limbs - 1 - 5) / 2, largest_bits_for_coefficients(limbs)})
      if (L >= 1 && L <= exact::kMaxFixedCoordinateBits) out.push_back(L);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

TEST(FixedSizeBounds, CubicStagesStayWithinTheirBoundsAndSelectTheirWidths) {
  std::mt19937_64 rng(test_seed());
  CubicBits widest_gap;
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    for (int L : cubic_boundary_bits()) {
      SCOPED_TRACE(std::string(to_string(type)) + ", L = " + std::to_string(L));
      const exact::CubicWidths widths = exact::cubic_widths(L);
      CubicBits reached;
      for (std::uint32_t signs : adversarial_signs(type, L, rng, 4, cubic_score)) {
        const DoubleQuery q = adversarial_query(type, L, signs, 23);
        const exact::IntegerCoordinates c = coordinates_of(q);
        ASSERT_EQ(c.bits, L);
        Recording<2> recorded[4];
        const CubicBits bits = cubic_bits_reached(c, recorded);
        EXPECT_LE(bits.difference, exact::difference_bits(L));
        EXPECT_LE(bits.cross_product, exact::cross_product_bits(L));
        EXPECT_LE(bits.coefficient, exact::cubic_coefficient_bits(L));
        reached.difference = std::max(reached.difference, bits.difference);
        reached.cross_product = std::max(reached.cross_product, bits.cross_product);
        reached.coefficient = std::max(reached.coefficient, bits.coefficient);
        // The widths the bounds select, and the same coefficients as GMP.
        const IntegerQuery fixed = integer_query(q);
        ASSERT_EQ(fixed.coefficient_limbs(), widths.coefficient);
        const auto coefficients = fixed.coefficients();
        for (int i = 0; i < 4; ++i) ASSERT_EQ(coefficients[i], recorded[i].value());
        // One bit more: a stage at the top of its width takes the next (GMP beyond the largest).
        const exact::CubicWidths next = exact::cubic_widths(L + 1);
        EXPECT_TRUE(next.difference > widths.difference ||
                    next.cross_product > widths.cross_product ||
                    next.coefficient > widths.coefficient || next.coefficient == 0);
        const IntegerQuery wider = integer_query(adversarial_query(type, L + 1, signs, 23));
        ASSERT_EQ(wider.coefficient_limbs(), next.coefficient);
        if (L == exact::kMaxFixedCoordinateBits) ASSERT_EQ(wider.coefficient_limbs(), 0);
        ASSERT_EQ(wider.coefficients(), integer_query(adversarial_query(type, L + 1, signs, 23),
                                                      IntegerQuery::Arithmetic::gmp)
                                            .coefficients());
      }
      // The inputs are adversarial: each bound is nearly reached (none is vacuous; the
      // coefficients' sums absolute values, where a determinant of entries of one magnitude
      // reaches 4 of 6 terms).
      EXPECT_EQ(reached.difference, exact::difference_bits(L));
      EXPECT_GE(reached.cross_product, exact::cross_product_bits(L) - 2);
      EXPECT_GE(reached.coefficient, exact::cubic_coefficient_bits(L) - 5);
      widest_gap.cross_product =
          std::max(widest_gap.cross_product, exact::cross_product_bits(L) - reached.cross_product);
      widest_gap.coefficient =
          std::max(widest_gap.coefficient, exact::cubic_coefficient_bits(L) - reached.coefficient);
    }
  }
  std::printf("cross products reach the bound within %ld bits, coefficients within %ld\n",
              widest_gap.cross_product, widest_gap.coefficient);
}

TEST(FixedSizeBounds, ValuesAtTheLargestAdmissibleExponentStayWithinTheBound) {
  std::mt19937_64 rng(test_seed() + 1);
  long total = 0;
  std::map<std::tuple<int, int, long>, long> reached;  // (type, L, k) -> largest bits reached
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    for (int L : {5, 30, 60, 61, 100, 200, 300, largest_bits_for_coefficients(16)}) {
      for (std::uint32_t signs : adversarial_signs(type, L, rng, 4, coefficient_sum_score)) {
        const DoubleQuery q = adversarial_query(type, L, signs, 23);
        const exact::IntegerCoordinates c = coordinates_of(q);
        Recording<2> recorded[4];
        cubic_bits_reached(c, recorded);
        const IntegerQuery fixed = integer_query(q);
        const IntegerQuery gmp = integer_query(q, IntegerQuery::Arithmetic::gmp);
        const int first = fixed.coefficient_limbs();
        ASSERT_GT(first, 0);
        for (int limbs = first; limbs <= exact::kMaxFixedLimbs; ++limbs) {
          // The largest k whose values fit in `limbs` limbs (none when even k = 0 does not).
          const long k_max = (64L * limbs - 1 - 11 - 3L * L) / 3;
          if (k_max < 0) continue;
          for (long k : {k_max, k_max + 1}) {
            if (k > 1074) continue;
            const double t = time_with_exponent(static_cast<unsigned>(k));
            exact::DyadicTime d;
            ASSERT_TRUE(exact::dyadic_time(t, &d));
            ASSERT_EQ(d.exponent, static_cast<unsigned>(k));
            SCOPED_TRACE("L = " + std::to_string(L) + ", k = " + std::to_string(k) + ", limbs " +
                         std::to_string(limbs));
            const long bits = value_bits_reached(recorded, d.numerator, d.exponent);
            EXPECT_LE(bits, exact::cubic_value_bits(L, k));
            if (k == k_max && k <= 53) {
              long& best = reached[{static_cast<int>(type), L, k}];
              best = std::max(best, bits);
            }
            // At k_max the width is `limbs`; one more and the next width, or GMP beyond.
            const int expected =
                k == k_max ? limbs : (limbs < exact::kMaxFixedLimbs ? limbs + 1 : 0);
            ASSERT_EQ(fixed.value_limbs(t), expected);
            // The value itself: fixed (or GMP beyond) against GMP throughout.
            ASSERT_EQ(fixed.scaled_value_at(t), gmp.scaled_value_at(t));
            ASSERT_EQ(fixed.cubic_sign_at(t), gmp.cubic_sign_at(t));
            ++total;
          }
        }
      }
    }
  }
  EXPECT_GT(total, 100);
  // Nearly reached where t = 1 - 2^-k is close to 1 (for k > 53, T < 2^53 is far below 2^k
  // and c0 2^(3k) dominates: the bound, which covers every t of exponent k, is loose there).
  long widest_gap = 0;
  for (const auto& [key, bits] : reached) {
    const auto& [type, L, k] = key;
    EXPECT_GE(bits, exact::cubic_value_bits(L, k) - 10) << type << " L = " << L << " k = " << k;
    widest_gap = std::max(widest_gap, exact::cubic_value_bits(L, k) - bits);
  }
  EXPECT_GT(reached.size(), 10u);
  std::printf("values near t = 1 reach the bound within %ld bits\n", widest_gap);
}

TEST(FixedSizeBounds, ContactTestAtTheLargestAdmissibleExponentStaysWithinTheBound) {
  std::mt19937_64 rng(test_seed() + 2);
  long total = 0;
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    for (int L : {3, 40, 61, 120, 250, 500}) {
      for (int trial = 0; trial < 6; ++trial) {
        // Contact tests do all their work on coplanar, touching configurations; random signs
        // of extreme coordinates give projections of every orientation.
        const auto signs = static_cast<std::uint32_t>(rng() & 0xffffff);
        const DoubleQuery q = adversarial_query(type, L, signs, static_cast<int>(rng() % 24));
        const exact::IntegerCoordinates c = coordinates_of(q);
        const IntegerQuery fixed = integer_query(q);
        const IntegerQuery gmp = integer_query(q, IntegerQuery::Arithmetic::gmp);
        for (int limbs = 1; limbs <= exact::kMaxFixedLimbs; ++limbs) {
          const long k_max = (64L * limbs - 1 - 4) / 2 - L;
          if (k_max < 0) continue;
          for (long k : {k_max, k_max + 1}) {
            if (k > 1074) continue;
            const double t = time_with_exponent(static_cast<unsigned>(k));
            exact::DyadicTime d;
            ASSERT_TRUE(exact::dyadic_time(t, &d));
            SCOPED_TRACE("L = " + std::to_string(L) + ", k = " + std::to_string(k));
            const long bits = contact_bits_reached(c, d.numerator, d.exponent);
            EXPECT_LE(bits, exact::contact_bits(L, k));
            const int expected =
                k == k_max ? limbs : (limbs < exact::kMaxFixedLimbs ? limbs + 1 : 0);
            ASSERT_EQ(fixed.contact_limbs(t), expected);
            ASSERT_EQ(fixed.contact_at(t), gmp.contact_at(t));
            ASSERT_EQ(fixed.contact_at(t),
                      exact::contact_at_time<RecordingInt>(c, d.numerator, d.exponent));
            ++total;
          }
        }
      }
    }
  }
  EXPECT_GT(total, 100);
}

TEST(FixedSizeBounds, GmpOnlyBeyondTheLargestFixedWidth) {
  // A query whose integers have 1,000 bits: its coefficients need GMP; a query of ordinary
  // spread at a subnormal time: its value needs GMP, its coefficients do not. Both agree with
  // GMP throughout, and GMP computations are counted.
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    const DoubleQuery wide = adversarial_query(type, 1000, 0x5a5a5a, 7);
    const IntegerQuery w = integer_query(wide);
    EXPECT_EQ(w.coefficient_limbs(), 0);
    EXPECT_EQ(w.value_limbs(0.5), 0);
    const std::uint64_t before = exact::gmp_computations_in_this_thread();
    const IntegerQuery w2 = integer_query(wide);
    EXPECT_GT(exact::gmp_computations_in_this_thread(), before);
    EXPECT_EQ(w2.coefficients(), integer_query(wide, IntegerQuery::Arithmetic::gmp).coefficients());

    const DoubleQuery ordinary = adversarial_query(type, 60, 0x123456, 3);
    const IntegerQuery o = integer_query(ordinary);
    const IntegerQuery og = integer_query(ordinary, IntegerQuery::Arithmetic::gmp);
    EXPECT_GT(o.coefficient_limbs(), 0);
    const double tiny = std::ldexp(3.0, -1074);  // a subnormal time: k = 1074
    EXPECT_EQ(o.value_limbs(tiny), 0);
    EXPECT_EQ(o.contact_limbs(tiny), 0);
    EXPECT_GT(o.value_limbs(0.75), 0);
    EXPECT_EQ(o.scaled_value_at(tiny), og.scaled_value_at(tiny));
    EXPECT_EQ(o.cubic_sign_at(tiny), og.cubic_sign_at(tiny));
    EXPECT_EQ(o.contact_at(tiny), og.contact_at(tiny));
  }
}

TEST(FixedSizeBounds, AllZeroQuery) {
  // L = 0: the cubic vanishes identically and every point coincides at every time.
  DoubleQuery q;
  for (auto& p : q.v) p.setZero();
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    q.type = type;
    const IntegerQuery z = integer_query(q);
    EXPECT_EQ(z.coordinates().bits, 0);
    EXPECT_EQ(z.cubic_sign_at(0.5), 0);
    EXPECT_TRUE(z.contact_at(0.25));
    EXPECT_THROW(z.contact_at(1.5), std::domain_error);
    EXPECT_THROW(z.contact_at(-0.5), std::domain_error);
  }
}

}  // namespace
}  // namespace exactccd::test
