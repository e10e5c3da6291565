// PROOF: proofs/exact_ccd.md#exact-at-double-brackets
#include "exact/stages/algebraic_at_doubles.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <tuple>
#include <type_traits>

#include "core/predicates/inclusion.hpp"
#include "exact/arithmetic/fixed_width_dispatch.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/stages/integer_query.hpp"
#include "exact/polynomials/bracketed_root.hpp"
#include "exact/polynomials/small_polynomial.hpp"
#include "exact/arithmetic/product_accumulator.hpp"
#include "exact/arithmetic/trimmed_integer.hpp"
#include "exact/stages/wide_inclusion.hpp"

namespace exactccd::exact {

namespace {

thread_local std::uint64_t g_unresolved = 0;
thread_local bool g_wide_contact_test = true;

template <int N, int D>
SmallPolynomial small(const predicates::FixedPoly<FixedInt<N>, D>& g, long bits) {
  return SmallPolynomial::from_fixed(g.c.data(), D + 1, bits);
}

template <int D>
SmallPolynomial small(const predicates::FixedPoly<mpz_class, D>& g, long) {
  return SmallPolynomial::from_mpz_without_power_of_two(g.c.data(), D + 1);
}

/// The same from TrimmedInteger coefficients: their common power of two is the least exponent.
template <int D>
SmallPolynomial small(const predicates::FixedPoly<TrimmedInteger, D>& g, long) {
  unsigned long shift = ~0ul;
  for (const TrimmedInteger& x : g.c)
    if (x.sign() != 0) shift = std::min(shift, x.exponent());
  mpz_class c[D + 1];
  for (int i = 0; i <= D; ++i) {
    const TrimmedInteger& x = g.c[static_cast<std::size_t>(i)];
    if (x.sign() != 0)
      mpz_mul_2exp(c[i].get_mpz_t(), x.odd_part().get_mpz_t(), x.exponent() - shift);
  }
  return SmallPolynomial::from_mpz(c, D + 1);
}

template <class CI>
using Moving = predicates::MovingPoint<CI>;

template <class CI>
Moving<CI> moving_point(const IntegerCoordinates& q, int row) {
  Moving<CI> m;
  predicates::FixedPoly<CI, 1>* axes[3] = {&m.x, &m.y, &m.z};
  for (int axis = 0; axis < 3; ++axis) {
    const CI x0 = integer_coordinate<CI>(q, row, axis);
    CI d = integer_coordinate<CI>(q, row + 4, axis);
    d -= x0;
    axes[axis]->c = {x0, d};
  }
  return m;
}

/// Every inclusion polynomial has coefficients below 2^(2L + 6).
/// PROOF: proofs/exact_ccd.md#small-polynomial-bounds
long inclusion_bits(int coordinate_bits) { return 2L * coordinate_bits + 6; }

template <class CI>
bool contact_at(const IntegerCoordinates& q, const Moving<CI> (&x)[4], BracketedRoot& r) {
  const long bits = inclusion_bits(q.bits);
  auto sign_at = [&](const auto& g) { return r.sign_of(small(g, bits)); };
  return q.type == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

/// The contact test at roots, for one query: for coordinates in GMP (beyond the fixed widths)
/// first by wide_contact_at (exact/stages/wide_inclusion.hpp), whose orientations are formed once per
/// query; the general predicates decide what it leaves (degenerate triangles, parallel edges)
/// and every query within the fixed widths. The moving points in CI are formed when first
/// needed.
template <class CI>
class ContactTest {
 public:
  explicit ContactTest(const IntegerCoordinates& q) : q_(q), wide_(q) {}

  bool at(BracketedRoot& r) {
    if constexpr (kWideCoordinates) {
      if (g_wide_contact_test) {
        const int decided = wide_contact_at(wide_, r);
        if (decided >= 0) return decided == 1;
      }
    }
    return contact_at(q_, points(), r);
  }

  const Moving<CI> (&points())[4] {
    if (!ready_) {
      for (int i = 0; i < 4; ++i) x_[i] = moving_point<CI>(q_, i);
      ready_ = true;
    }
    return x_;
  }

 private:
  /// Coordinates in GMP: the orientations' coefficients span thousands of bits, and an exact
  /// sign at an irrational root costs remainders over them.
  static constexpr bool kWideCoordinates =
      std::is_same_v<CI, TrimmedInteger> || std::is_same_v<CI, mpz_class>;

  /// Within the fixed widths: nothing (the polynomials' storage would be a large, unused frame).
  struct NoWidePolynomials {
    explicit NoWidePolynomials(const IntegerCoordinates&) {}
  };

  const IntegerCoordinates& q_;
  std::conditional_t<kWideCoordinates, WideInclusionPolynomials, NoWidePolynomials> wide_;
  Moving<CI> x_[4];
  bool ready_ = false;
};

/// The same candidates as exact/reference/exact_ccd.cpp (vertex_edge_candidates): the first non-zero
/// component of cross(y - x, p - x), else (p - x).(p - y).
/// PROOF: proofs/exact_ccd.md#lemma-vertex-edge-candidates
template <class CI>
SmallPolynomial vertex_edge_candidate(const Moving<CI>& p, const Moving<CI>& x,
                                      const Moving<CI>& y, long bits) {
  const auto n = cross(y - x, p - x);
  for (int k = 0; k < 3; ++k) {
    SmallPolynomial c = small(n[k], bits);
    if (!c.is_zero()) return c;
  }
  return small(dot(p - x, p - y), bits);
}

CcdResult no_contact() {
  CcdResult r;
  r.decided_by = Stage::exact;
  return r;
}

CcdResult contact(const BracketedRoot& root, const CcdOptions& options) {
  CcdResult r;
  r.decided_by = Stage::exact;
  r.collides = true;
  std::tie(r.toi_lo, r.toi_hi) = root.enclosure(options.toi_width);
  return r;
}

template <class CI>
CcdResult decide(const IntegerCoordinates& q, const SmallPolynomial& cubic,
                 const CcdOptions& options) {
  ContactTest<CI> test(q);
  if (!cubic.is_zero()) {  // contact implies coplanarity: only the cubic's roots are candidates
    SmallPolynomial square_free;
    RootIterator roots(cubic, options.t_max, &square_free);
    while (std::optional<BracketedRoot> r = roots.next())
      if (test.at(*r)) return contact(*r, options);
    return no_contact();
  }
  // Coplanar throughout: contact at t = 0, else the first contact lies on an edge.
  BracketedRoot zero = BracketedRoot::at(nullptr, 0.0);
  if (test.at(zero)) return contact(zero, options);
  const Moving<CI>(&x)[4] = test.points();
  const long bits = inclusion_bits(q.bits);
  SmallPolynomial candidates[4], square_free[4];
  int count = 0;
  if (q.type == QueryType::vertex_face) {
    candidates[count++] = vertex_edge_candidate(x[0], x[1], x[2], bits);
    candidates[count++] = vertex_edge_candidate(x[0], x[2], x[3], bits);
    candidates[count++] = vertex_edge_candidate(x[0], x[3], x[1], bits);
  } else {
    candidates[count++] = vertex_edge_candidate(x[0], x[2], x[3], bits);
    candidates[count++] = vertex_edge_candidate(x[1], x[2], x[3], bits);
    candidates[count++] = vertex_edge_candidate(x[2], x[0], x[1], bits);
    candidates[count++] = vertex_edge_candidate(x[3], x[0], x[1], bits);
  }
  std::optional<BracketedRoot> best;
  for (int k = 0; k < count; ++k) {
    if (candidates[k].degree() < 1) continue;
    RootIterator roots(candidates[k], options.t_max, &square_free[k]);
    while (std::optional<BracketedRoot> r = roots.next()) {
      if (r->is_exact() && r->lo() == 0) continue;  // t = 0 was tried
      if (best && !earlier(*r, *best)) break;       // ascending: no later root is earlier
      if (test.at(*r)) {
        best = *r;
        break;
      }
    }
  }
  return best ? contact(*best, options) : no_contact();
}

/// The coplanarity cubic of q; `known` (of the same query, or nullptr) holds it already when
/// its coefficients are in GMP: the same function of the same integer coordinates.
SmallPolynomial cubic_of(const IntegerCoordinates& q, const IntegerQuery* known) {
  const long bits = cubic_coefficient_bits(q.bits);
  const int limbs = fixed_limbs_for(bits);
  if (limbs == 0) {
    if (known && known->coefficient_limbs() == 0) {
      const std::array<mpz_class, 4> c = known->coefficients();
      return SmallPolynomial::from_mpz_without_power_of_two(c.data(), 4);
    }
    mpz_class c[4];
    accumulated_coplanarity_coefficients(q, c);
    return SmallPolynomial::from_mpz_without_power_of_two(c, 4);
  }
  return with_limbs(limbs, [&](auto n) {
    FixedInt<decltype(n)::value> c[4];
    coplanarity_coefficients(q, c);
    return SmallPolynomial::from_fixed(c, 4, bits);
  });
}

std::optional<CcdResult> at_doubles(const IntegerCoordinates& q, const CcdOptions& options,
                                    const IntegerQuery* known) {
  try {
    const SmallPolynomial cubic = cubic_of(q, known);
    // The coordinate type holds every inclusion polynomial: a few widths suffice.
    const int limbs = fixed_limbs_for(inclusion_bits(q.bits));
    if (limbs != 0 && limbs <= 2) return decide<FixedInt<2>>(q, cubic, options);
    if (limbs != 0 && limbs <= 4) return decide<FixedInt<4>>(q, cubic, options);
    if (limbs != 0 && limbs <= 8) return decide<FixedInt<8>>(q, cubic, options);
    if (limbs != 0) return decide<FixedInt<16>>(q, cubic, options);
    if (prefers_trimmed_integers(q)) return decide<TrimmedInteger>(q, cubic, options);
    return decide<mpz_class>(q, cubic, options);
  } catch (const UnresolvedAtDoubles&) {
    ++g_unresolved;
    return std::nullopt;
  }
}

}  // namespace

std::optional<CcdResult> vertex_face_ccd_at_doubles(const VertexFaceQuery& q,
                                                    const CcdOptions& options,
                                                    const IntegerQuery* known) {
  return at_doubles(known ? known->coordinates() : integer_coordinates(q), options, known);
}

std::optional<CcdResult> edge_edge_ccd_at_doubles(const EdgeEdgeQuery& q,
                                                  const CcdOptions& options,
                                                  const IntegerQuery* known) {
  return at_doubles(known ? known->coordinates() : integer_coordinates(q), options, known);
}

std::uint64_t unresolved_at_doubles_in_this_thread() noexcept { return g_unresolved; }

void use_wide_contact_test_in_this_thread(bool on) noexcept { g_wide_contact_test = on; }

}  // namespace exactccd::exact
