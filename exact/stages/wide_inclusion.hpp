// The contact test at a root of the coplanarity cubic for queries whose coordinates exceed the
// fixed widths (widely spread exponents): the inclusion orientations formed once per query by
// the product accumulator, and their signs at each root decided by the wide-range filter
// first, in every projection that allows it, exactly only where no projection decides.
//
// On wide spreads a projection's orientation often nearly vanishes at the root (the cubic's
// dominant part is that orientation times one far larger coordinate), and roots lie within
// 2^-53 of t = 1, where doubles cannot bracket them finely: there the signs are read in
// u = 1 - t, which doubles resolve down to 2^-1074.
// PROOF: proofs/exact_ccd.md#certain-signs-first
#pragma once

#include <optional>

#include "exact/polynomials/bracketed_root.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/polynomials/small_polynomial.hpp"

namespace exactccd::exact {

/// The orientations of Lemmas 3 and 4 as polynomials in t, each formed when first asked for,
/// and its reflection p(1 - u) when first asked for. Vertex-face (rows p, a, b, c): normal(k) = O_k(a, b, c),
/// edge(k, i) = O_k(a, b, p), O_k(b, c, p), O_k(c, a, p). Edge-edge (rows a0, a1, b0, b1):
/// normal(k) = ((a1 - a0) x (b1 - b0))_k, edge(k, i) = O_k(a0, a1, b0), O_k(a0, a1, b1),
/// O_k(b0, b1, a0), O_k(b0, b1, a1). Positive multiples (common powers of two removed): the
/// same signs.
class WideInclusionPolynomials {
 public:
  explicit WideInclusionPolynomials(const IntegerCoordinates& q) : q_(q) {}
  const IntegerCoordinates& coordinates() const { return q_; }
  /// Slots: normal k at k, edge (k, i) at 3 + 4 k + i.
  static constexpr int normal_slot(int k) { return k; }
  static constexpr int edge_slot(int k, int i) { return 3 + 4 * k + i; }
  const SmallPolynomial& normal(int k) { return polynomial(normal_slot(k)); }
  const SmallPolynomial& edge(int k, int i) { return polynomial(edge_slot(k, i)); }
  const SmallPolynomial& reflected_edge(int k, int i) { return reflected(edge_slot(k, i)); }
  const SmallPolynomial& polynomial(int slot);
  const SmallPolynomial& reflected(int slot);

 private:
  static constexpr int kSlots = 15;
  const IntegerCoordinates& q_;
  std::optional<SmallPolynomial> poly_[kSlots], reflected_[kSlots];
};

/// Whether the primitives touch at the root r of the cubic (coplanar there): 1 or 0, or -1
/// when the triangle is degenerate (vertex-face) or the edges parallel (edge-edge) at r, which
/// Lemma 3 (b) / 4 (b) decide (the caller's general route). May narrow r's bracket. Throws
/// UnresolvedAtDoubles as BracketedRoot::sign_of does.
int wide_contact_at(WideInclusionPolynomials& polynomials, BracketedRoot& r);

}  // namespace exactccd::exact
