// PROOF: proofs/exact_ccd.md#certain-signs-first
#include "exact/stages/wide_inclusion.hpp"

#include <array>

#include "core/predicates/inclusion.hpp"
#include "exact/arithmetic/product_accumulator.hpp"

namespace exactccd::exact {

namespace {

/// Halvings of a root's bracket with filtered signs (a few long-double operations each): first
/// a few, which decide most signs; all the way (64 reach adjacent doubles from any bracket)
/// only when a sign is still unknown. Speed settings only.
constexpr int kFirstNarrowingSteps = 24;
constexpr int kFullNarrowingSteps = 80;

/// O_k(x, y, z) = cross2(x, y) + cross2(y, z) + cross2(z, x).
/// PROOF: proofs/exact_ccd.md#product-accumulator
std::array<Cross2Term, 3> orientation(int x, int y, int z) {
  return {Cross2Term{x, y, false}, Cross2Term{y, z, false}, Cross2Term{z, x, false}};
}

/// The sign of each orientation at r from the wide-range filter alone (0: unknown), after
/// narrowing r's bracket with filtered signs; for a root in [1/2, 1], in u = 1 - t.
class CertainSigns {
 public:
  CertainSigns(WideInclusionPolynomials& polynomials, BracketedRoot& r)
      : polynomials_(polynomials), r_(r) {
    narrow(kFirstNarrowingSteps);
  }
  // Lemma 3 / 4 signs by index (core/predicates/inclusion.hpp).
  int certain_normal(int k) { return certain(WideInclusionPolynomials::normal_slot(k)); }
  int certain_edge(int k, int i) { return certain(WideInclusionPolynomials::edge_slot(k, i)); }
  int normal(int k) { return r_.sign_of(polynomials_.normal(k)); }
  int edge(int k, int i) { return r_.sign_of(polynomials_.edge(k, i)); }

 private:
  /// Narrows r's bracket, then, once it lies in [1/2, 1], the bracket of u = 1 - r.
  void narrow(int steps) {
    if (!u_) {
      r_.narrow_by_filter(steps);
      const SmallPolynomial* p = r_.polynomial();
      if (r_.lo() >= 0.5 && (p != nullptr || r_.is_exact())) {
        if (p != nullptr) p_reflected_ = p->reflected();
        u_ = r_.reflected(&p_reflected_);
      }
    }
    if (u_) u_->narrow_by_filter(steps);
  }
  int certain_now(int slot) {
    return u_ ? u_->certain_sign_of(polynomials_.reflected(slot))
              : r_.certain_sign_of(polynomials_.polynomial(slot));
  }
  int certain(int slot) {
    int s = certain_now(slot);
    if (s == 0 && !fully_narrowed_) {
      fully_narrowed_ = true;
      narrow(kFullNarrowingSteps);
      s = certain_now(slot);
    }
    return s;
  }

  WideInclusionPolynomials& polynomials_;
  BracketedRoot& r_;
  SmallPolynomial p_reflected_;
  std::optional<BracketedRoot> u_;
  bool fully_narrowed_ = false;
};

}  // namespace

const SmallPolynomial& WideInclusionPolynomials::polynomial(int slot) {
  std::optional<SmallPolynomial>& p = poly_[slot];
  if (p) return *p;
  mpz_class c[3];
  const bool vf = q_.type == QueryType::vertex_face;
  if (slot < 3) {
    const int k = slot;
    if (vf) {
      const auto terms = orientation(1, 2, 3);  // a, b, c
      accumulated_cross2_coefficients(q_, k, terms.data(), 3, c);
    } else {
      // cross2(a1 - a0, b1 - b0)
      //   = cross2(a1, b1) - cross2(a1, b0) - cross2(a0, b1) + cross2(a0, b0)
      const Cross2Term terms[4] = {{1, 3, false}, {1, 2, true}, {0, 3, true}, {0, 2, false}};
      accumulated_cross2_coefficients(q_, k, terms, 4, c);
    }
  } else {
    const int k = (slot - 3) / 4, i = (slot - 3) % 4;
    // Vertex-face: O_k(a, b, p), O_k(b, c, p), O_k(c, a, p); edge-edge: O_k(a0, a1, b0),
    // O_k(a0, a1, b1), O_k(b0, b1, a0), O_k(b0, b1, a1).
    static constexpr int kVf[3][3] = {{1, 2, 0}, {2, 3, 0}, {3, 1, 0}};
    static constexpr int kEe[4][3] = {{0, 1, 2}, {0, 1, 3}, {2, 3, 0}, {2, 3, 1}};
    const int* rows = vf ? kVf[i] : kEe[i];
    const auto terms = orientation(rows[0], rows[1], rows[2]);
    accumulated_cross2_coefficients(q_, k, terms.data(), 3, c);
  }
  p = SmallPolynomial::from_mpz_without_power_of_two(c, 3);
  return *p;
}

const SmallPolynomial& WideInclusionPolynomials::reflected(int slot) {
  std::optional<SmallPolynomial>& p = reflected_[slot];
  if (!p) p = polynomial(slot).reflected();
  return *p;
}

int wide_contact_at(WideInclusionPolynomials& polynomials, BracketedRoot& r) {
  CertainSigns signs(polynomials, r);
  return polynomials.coordinates().type == QueryType::vertex_face
             ? predicates::point_in_triangle_by_projections(signs)
             : predicates::segments_intersect_by_projections(signs);
}

}  // namespace exactccd::exact
