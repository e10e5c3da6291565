// The contact test at roots for wide coordinates (exact/stages/wide_inclusion.hpp) and what it is made
// of, against independent exact arithmetic: the product accumulator's sums and polynomials
// (exact/arithmetic/product_accumulator.hpp) against GMP and the generic predicates over mpz_class; the
// reflection p(1 - u) against an expansion written here; the projection-by-projection
// inclusion predicates with partly known signs against point_in_triangle_at and
// segments_intersect_at; brackets narrowed and reflected against exact signs.
// PROOF: proofs/exact_ccd.md#product-accumulator
// PROOF: proofs/exact_ccd.md#certain-signs-first
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/predicates/fp_environment.hpp"
#include "core/predicates/inclusion.hpp"
#include "corpus/random_queries.hpp"
#include "exact/stages/algebraic_at_doubles.hpp"
#include "exact/polynomials/bracketed_root.hpp"
#include "exactccd/ccd.hpp"
#include "exact/arithmetic/fixed_width_dispatch.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/arithmetic/product_accumulator.hpp"
#include "exact/polynomials/small_polynomial.hpp"
#include "exact/stages/wide_inclusion.hpp"
#include "integer_polynomial_support.hpp"
#include "test_scale.hpp"

namespace exactccd::exact {
namespace {

using test::random_integer;
using test::with_roots;

IntegerCoordinates coordinates_of(const random_queries::DoubleQuery& q) {
  return q.type == QueryType::vertex_face ? integer_coordinates(q.vertex_face())
                                          : integer_coordinates(q.edge_edge());
}

// Sums of random signed products of two and three mantissas at shifts up to 6,000 bits against
// mpz, with exact cancellations (each term added and taken away again) and zeros.
TEST(ProductAccumulator, SumsEqualMpz) {
  std::mt19937_64 rng(5);
  const int n = static_cast<int>(test::at_least(test::scaled_count(3000), 500));
  int zeros = 0;
  for (int i = 0; i < n; ++i) {
    ProductAccumulator acc(ProductAccumulator::kMaxLimbs);
    mpz_class z = 0;
    const int terms = 1 + static_cast<int>(rng() % 40);
    std::vector<std::int64_t> m(3);
    for (int t = 0; t < terms; ++t) {
      for (auto& mi : m) {
        const auto magnitude = static_cast<std::int64_t>(rng() >> (11 + rng() % 53));  // < 2^53
        mi = (rng() & 1) ? -magnitude : magnitude;
      }
      const unsigned long shift = rng() % 6000;
      const bool negative = rng() & 1;
      const bool three = rng() & 1;
      mpz_class p = mpz_class(static_cast<long>(m[0])) * static_cast<long>(m[1]);
      if (three) p *= static_cast<long>(m[2]);
      p <<= shift;
      const int repeats = (rng() % 4 == 0) ? 2 : 1;  // added and taken away: an exact 0
      for (int r = 0; r < repeats; ++r) {
        const bool neg = r == 0 ? negative : !negative;
        if (three) acc.add_product(m[0], m[1], m[2], shift, neg);
        else acc.add_product(m[0], m[1], shift, neg);
        if (neg) z -= p;
        else z += p;
      }
    }
    ASSERT_EQ(acc.to_mpz(), z) << "sum " << i;
    zeros += sgn(z) == 0;
  }
  EXPECT_GT(zeros, 0);
  // A carry through every limb: (2^53 - 1) 2^(53 i) for i < 110 is 2^5830 - 1 (all ones), plus
  // one; and the same taken away again from the negative side.
  {
    ProductAccumulator acc(ProductAccumulator::kMaxLimbs);
    const std::int64_t ones = (std::int64_t{1} << 53) - 1;
    for (unsigned long i = 0; i < 110; ++i) acc.add_product(ones, 1, 53 * i, false);
    acc.add_product(1, 1, 0, false);
    EXPECT_EQ(acc.to_mpz(), mpz_class(1) << 5830);
    for (unsigned long i = 0; i < 110; ++i) acc.add_product(ones, -1, 1, 53 * i, false);
    acc.add_product(-1, 1, 1, 0, false);
    EXPECT_EQ(acc.to_mpz(), 0);
  }
  // Beyond the width it was given: an error, never a wrong sum.
  ProductAccumulator small(2);
  EXPECT_THROW(small.add_product(1, 1, 200, false), std::length_error);
  EXPECT_THROW(ProductAccumulator(ProductAccumulator::kMaxLimbs + 1), std::length_error);
}

// The cubic from 192 accumulated triple products equals the one formed in mpz_class from the
// coordinate differences, on every generator's queries (wide spreads, subnormals, huge
// coordinates, coincident points, zeros).
TEST(ProductAccumulator, CubicEqualsTheMpzCubic) {
  const std::uint64_t n = test::at_least(test::scaled_count(200), 40);
  int checked = 0;
  for (const random_queries::Generator& g : random_queries::all_generators())
    for (std::uint64_t i = 0; i < n; ++i) {
      const IntegerCoordinates c = coordinates_of(random_queries::generate(g, 13, i));
      mpz_class plain[4], accumulated[4];
      coplanarity_coefficients(c, plain);
      accumulated_coplanarity_coefficients(c, accumulated);
      for (int k = 0; k < 4; ++k)
        ASSERT_EQ(accumulated[k], plain[k]) << g.name() << " #" << i << " coefficient " << k;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

/// The coefficients divided by their common power of two, as the stage's polynomials are.
std::array<mpz_class, 4> primitive_in_two(std::array<mpz_class, 4> c) {
  mp_bitcnt_t shift = ~mp_bitcnt_t(0);
  for (const mpz_class& ci : c)
    if (sgn(ci) != 0) shift = std::min(shift, mpz_scan1(ci.get_mpz_t(), 0));
  if (shift != ~mp_bitcnt_t(0))
    for (mpz_class& ci : c) ci >>= shift;  // exact
  return c;
}

template <int D>
std::array<mpz_class, 4> padded(const predicates::FixedPoly<mpz_class, D>& p) {
  std::array<mpz_class, 4> c;
  for (int i = 0; i <= D; ++i) c[static_cast<std::size_t>(i)] = p.c[static_cast<std::size_t>(i)];
  return primitive_in_two(c);
}

// Every orientation of WideInclusionPolynomials equals the generic predicate's polynomial in
// mpz_class (orient2d_along_axis and cross over the moving points), up to the common power of
// two both remove; and its reflection is p(1 - u) expanded here.
TEST(WideInclusionPolynomials, EqualTheGenericOrientations) {
  const std::uint64_t n = test::at_least(test::scaled_count(60), 12);
  int checked = 0;
  for (const random_queries::Generator& g : random_queries::all_generators())
    for (std::uint64_t i = 0; i < n; ++i) {
      const IntegerCoordinates c = coordinates_of(random_queries::generate(g, 17, i));
      WideInclusionPolynomials w(c);
      predicates::Vec3<predicates::FixedPoly<mpz_class, 1>> x[4];
      for (int p = 0; p < 4; ++p) {
        predicates::Vec3<mpz_class> x0, x1;
        for (int k = 0; k < 3; ++k) {
          const mpz_class a = integer_coordinate<mpz_class>(c, p, k);
          const mpz_class b = integer_coordinate<mpz_class>(c, p + 4, k);
          (k == 0 ? x0.x : k == 1 ? x0.y : x0.z) = a;
          (k == 0 ? x1.x : k == 1 ? x1.y : x1.z) = b;
        }
        x[p] = predicates::linear_motion(x0, x1);
      }
      const bool vf = c.type == QueryType::vertex_face;
      for (int k = 0; k < 3; ++k) {
        const auto normal = vf ? predicates::orient2d_along_axis(k, x[1], x[2], x[3])
                               : cross(x[1] - x[0], x[3] - x[2])[k];
        ASSERT_EQ(w.normal(k).mpz_coefficients(), padded(normal)) << g.name() << " #" << i;
        const int edges = vf ? 3 : 4;
        for (int e = 0; e < edges; ++e) {
          static constexpr int kVf[3][3] = {{1, 2, 0}, {2, 3, 0}, {3, 1, 0}};
          static constexpr int kEe[4][3] = {{0, 1, 2}, {0, 1, 3}, {2, 3, 0}, {2, 3, 1}};
          const int* r = vf ? kVf[e] : kEe[e];
          const auto o = predicates::orient2d_along_axis(k, x[r[0]], x[r[1]], x[r[2]]);
          const SmallPolynomial& p = w.edge(k, e);
          ASSERT_EQ(p.mpz_coefficients(), padded(o)) << g.name() << " #" << i;
          // p(1 - u) = sum_i c_i (1 - u)^i, expanded by repeated multiplication by (1 - u).
          const std::array<mpz_class, 4> pc = p.mpz_coefficients();
          std::array<mpz_class, 4> expanded{}, power{1, 0, 0, 0};
          for (int d = 0; d < 4; ++d) {
            for (int j = 0; j < 4; ++j) expanded[j] += pc[d] * power[j];
            for (int j = 3; j >= 1; --j) power[j] = power[j] - power[j - 1];
          }
          ASSERT_EQ(w.reflected_edge(k, e).mpz_coefficients(), expanded);
        }
      }
      ++checked;
    }
  EXPECT_GT(checked, 50);
}

// Random integer points, coplanar by construction (including collinear and coincident ones),
// whose orientation signs are known exactly; `certain_*` answers the true sign or "unknown" at
// random (never a wrong sign, never for a zero value), the exact ones the true sign. The
// projection-by-projection predicates must equal the generic ones whenever they decide, and
// leave only degenerate configurations (-1).
struct RandomSigns {
  using Point = predicates::Vec3<predicates::FixedPoly<long, 0>>;
  const Point* x;  // 4 points: vertex-face p, a, b, c; edge-edge a0, a1, b0, b1
  bool vf;
  std::mt19937_64* rng;
  int exact_calls = 0;

  static int sign(long v) { return (v > 0) - (v < 0); }
  long normal_value(int k) const {
    return vf ? predicates::orient2d_along_axis(k, x[1], x[2], x[3]).c[0]
              : cross(x[1] - x[0], x[3] - x[2])[k].c[0];
  }
  long edge_value(int k, int i) const {
    static constexpr int kVf[3][3] = {{1, 2, 0}, {2, 3, 0}, {3, 1, 0}};
    static constexpr int kEe[4][3] = {{0, 1, 2}, {0, 1, 3}, {2, 3, 0}, {2, 3, 1}};
    const int* r = vf ? kVf[i] : kEe[i];
    return predicates::orient2d_along_axis(k, x[r[0]], x[r[1]], x[r[2]]).c[0];
  }
  int maybe(int s) { return ((*rng)() & 1) ? s : 0; }
  int certain_normal(int k) { return maybe(sign(normal_value(k))); }
  int certain_edge(int k, int i) { return maybe(sign(edge_value(k, i))); }
  int normal(int k) { return ++exact_calls, sign(normal_value(k)); }
  int edge(int k, int i) { return ++exact_calls, sign(edge_value(k, i)); }
};

TEST(InclusionByProjections, EqualsTheGenericPredicatesWithPartlyKnownSigns) {
  std::mt19937_64 rng(23);
  const int n = static_cast<int>(test::at_least(test::scaled_count(40000), 5000));
  int decided_without_exact = 0, degenerate = 0, contacts = 0;
  for (int i = 0; i < n; ++i) {
    // Points o + s u + r v with small integers s, r (a random plane through o spanned by u, v;
    // u, v dependent or zero at times: degenerate planes and triangles).
    auto vec = [&](int range) {
      return predicates::Vec3<long>{static_cast<long>(rng() % (2 * range + 1)) - range,
                                    static_cast<long>(rng() % (2 * range + 1)) - range,
                                    static_cast<long>(rng() % (2 * range + 1)) - range};
    };
    const auto o = vec(5);
    const auto u = vec(rng() % 5 == 0 ? 0 : 3);
    const auto v = rng() % 5 == 0 ? u : vec(3);
    RandomSigns::Point x[4];
    for (auto& p : x) {
      const long s = static_cast<long>(rng() % 7) - 3, r = static_cast<long>(rng() % 7) - 3;
      p.x.c[0] = o.x + s * u.x + r * v.x;
      p.y.c[0] = o.y + s * u.y + r * v.y;
      p.z.c[0] = o.z + s * u.z + r * v.z;
    }
    const bool vf = rng() & 1;
    RandomSigns signs{x, vf, &rng};
    const int got = vf ? predicates::point_in_triangle_by_projections(signs)
                       : predicates::segments_intersect_by_projections(signs);
    auto exact = [](const predicates::FixedPoly<long, 0>& q) { return RandomSigns::sign(q.c[0]); };
    const bool want = vf ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], exact)
                         : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], exact);
    if (got < 0) {
      ++degenerate;
      for (int k = 0; k < 3; ++k) ASSERT_EQ(signs.normal_value(k), 0) << "case " << i;
      continue;
    }
    ASSERT_EQ(got == 1, want) << "case " << i << (vf ? " vertex-face" : " edge-edge");
    decided_without_exact += signs.exact_calls == 0;
    contacts += want;
  }
  EXPECT_GT(decided_without_exact, n / 10);
  EXPECT_GT(degenerate, 0);
  EXPECT_GT(contacts, n / 20);
}

// Brackets of roots near t = 1 and near 0, from the root iterator on polynomials with wide
// coefficients (times 2^1000: the wide-range filter is on): narrowing keeps a bracket of the
// same root (exact signs at the new ends), the reflected bracket holds u = 1 - r (exact signs
// of p(1 - u) at its ends), and every certain sign equals the exact one.
TEST(BracketedRootReflection, KeepsTheRootAndCertainSignsAreExact) {
  predicates::FpEnvironmentGuard nearest{predicates::Rounding::to_nearest};
  std::mt19937_64 rng(29);
  const int n = static_cast<int>(test::at_least(test::scaled_count(300), 60));
  int reflected = 0, certain = 0;
  const mpz_class wide = mpz_class(1) << 1000;
  for (int i = 0; i < n; ++i) {
    // A root 1 - 2^-e (e up to 900: beyond the doubles below 1) or e 2^-f, and two others.
    const unsigned e = 1 + static_cast<unsigned>(rng() % 900);
    const mpq_class near_one = 1 - mpq_class(1, mpz_class(1) << e);
    const mpq_class other(random_integer(rng, 20), mpz_class(1) << (20 + rng() % 40));
    const mpq_class third(abs(random_integer(rng, 10)) + 1, abs(random_integer(rng, 10)) + 1);
    const SmallPolynomial p = with_roots({near_one, other, third}, wide);
    const SmallPolynomial g = with_roots({near_one + mpq_class(random_integer(rng, 8),
                                                                mpz_class(1) << (e + rng() % 40)),
                                          third + 1},
                                         wide);
    SmallPolynomial storage;
    RootIterator roots(p, 1.0, &storage);
    while (std::optional<BracketedRoot> r = roots.next()) {
      BracketedRoot exact_copy = *r;
      const int truth = exact_copy.sign_of(g);
      r->narrow_by_filter(80);
      if (!r->is_exact() && r->polynomial() == &p) {
        // Still a bracket of the root: exact signs of opposite strict signs at the ends.
        const int lo = p.sign_at(r->lo()), hi = p.sign_at(r->hi());
        ASSERT_NE(lo, 0);
        ASSERT_EQ(hi, -lo);
      }
      if (const int s = r->certain_sign_of(g)) {
        ++certain;
        ASSERT_EQ(s, truth) << "case " << i;
      }
      const SmallPolynomial p_reflected = r->polynomial() ? r->polynomial()->reflected()
                                                          : SmallPolynomial();
      if (std::optional<BracketedRoot> u = r->reflected(&p_reflected)) {
        ++reflected;
        if (!u->is_exact()) {
          const int lo = p_reflected.sign_at(u->lo()), hi = p_reflected.sign_at(u->hi());
          ASSERT_NE(lo, 0);
          ASSERT_EQ(hi, -lo);
        }
        u->narrow_by_filter(80);
        if (const int s = u->certain_sign_of(g.reflected())) {
          ++certain;
          ASSERT_EQ(s, truth) << "case " << i << " reflected";
        }
        ASSERT_EQ(u->sign_of(g.reflected()), truth) << "case " << i << " reflected, exact";
      }
    }
  }
  EXPECT_GT(reflected, n / 2);
  EXPECT_GT(certain, n);
}

// The stage at double brackets with the wide contact test against the same stage with the
// general predicates and exact signs only (the route before it, its reference), on every
// generator whose coordinates exceed the fixed widths: the same verdict and the same tightest
// TOI pair, query by query. Also through the default pipeline (its filters first).
TEST(WideContactTest, AgreesWithTheGeneralRouteOnWideGenerators) {
  predicates::FpEnvironmentGuard nearest{predicates::Rounding::to_nearest};
  const std::uint64_t n = test::at_least(test::scaled_count(1500), 200);
  int wide = 0, contacts = 0;
  for (const random_queries::Generator& g : random_queries::all_generators())
    for (std::uint64_t i = 0; i < n; ++i) {
      const random_queries::DoubleQuery q = random_queries::generate(g, 37, i);
      // Within the fixed widths (inclusion polynomials below 2^(2L + 6), Lemma 10a) the stage
      // never takes the wide contact test.
      if (fixed_limbs_for(2L * coordinates_of(q).bits + 6) != 0) {
        if (i >= 8) break;  // this generator stays within the fixed widths: a few suffice
        continue;
      }
      ++wide;
      const bool vf = q.type == QueryType::vertex_face;
      CcdOptions o;
      o.toi_width = 0;
      auto run = [&](bool on) {
        use_wide_contact_test_in_this_thread(on);
        const auto r = vf ? vertex_face_ccd_at_doubles(q.vertex_face(), o)
                          : edge_edge_ccd_at_doubles(q.edge_edge(), o);
        use_wide_contact_test_in_this_thread(true);
        return r;
      };
      const auto fast = run(true), reference = run(false);
      ASSERT_TRUE(fast && reference) << g.name() << " #" << i;
      ASSERT_EQ(fast->collides, reference->collides) << g.name() << " #" << i;
      if (reference->collides) {
        ++contacts;
        ASSERT_EQ(fast->toi_lo, reference->toi_lo) << g.name() << " #" << i;
        ASSERT_EQ(fast->toi_hi, reference->toi_hi) << g.name() << " #" << i;
      }
      const CcdResult pipeline = vf ? vertex_face_ccd(q.vertex_face(), o)
                                    : edge_edge_ccd(q.edge_edge(), o);
      ASSERT_EQ(pipeline.collides, reference->collides) << g.name() << " #" << i;
    }
  std::printf("[ wide     ] %d queries with coordinates in GMP, %d contacts\n", wide, contacts);
  // The +-300 and +-1000 spreads and the huge-against-subnormal generators leave the fixed
  // widths: about 3 n queries in all, at any test scale.
  EXPECT_GT(wide, static_cast<int>(2 * n));
  EXPECT_GT(contacts, 20);
}

// The filter's sign of a wide polynomial over a bracket (Horner on the interval, then the
// Bernstein enclosures) never differs from the exact signs in the bracket: random polynomials
// of 400- to 3,000-bit coefficients, some with roots placed in or next to the bracket.
TEST(CertainSignOn, NeverContradictsExactSigns) {
  predicates::FpEnvironmentGuard nearest{predicates::Rounding::to_nearest};
  std::mt19937_64 rng(31);
  const int n = static_cast<int>(test::at_least(test::scaled_count(4000), 800));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int decided = 0;
  for (int i = 0; i < n; ++i) {
    const int bits = 400 + static_cast<int>(rng() % 2600);
    double a = unit(rng), b = unit(rng);
    if (a > b) std::swap(a, b);
    if (rng() % 2 == 0)  // a short bracket
      b = std::nextafter(a, 2.0) + (b - a) * std::ldexp(1.0, -static_cast<int>(rng() % 50));
    if (!(a < b && b <= 1)) continue;
    SmallPolynomial p;
    if (rng() % 2 == 0) {
      mpz_class c[4];
      for (auto& ci : c) ci = random_integer(rng, bits - static_cast<int>(rng() % 64));
      p = SmallPolynomial::from_mpz(c, 4);
    } else {  // a root just outside or inside [a, b]
      const mpq_class r = mpq_class(b) + mpq_class(static_cast<long>(rng() % 5) - 2,
                                                   mpz_class(1) << (60 + rng() % 60));
      p = with_roots({r, mpq_class(static_cast<long>(rng() % 7), 3)}, random_integer(rng, bits));
    }
    const int s = p.certain_sign_on(a, b);
    if (s == 0) continue;
    ++decided;
    ASSERT_EQ(p.sign_at(a), s) << "case " << i;
    ASSERT_EQ(p.sign_at(b), s) << "case " << i;
    for (int k = 0; k < 4; ++k) {
      const double t = a + (b - a) * unit(rng);
      if (t >= a && t <= b) ASSERT_EQ(p.sign_at(t), s) << "case " << i;
    }
  }
  EXPECT_GT(decided, n / 4);
}

}  // namespace
}  // namespace exactccd::exact
