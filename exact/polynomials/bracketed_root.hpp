// Roots of small integer polynomials bracketed between doubles, and exact signs of other
// polynomials at them: the root isolation (Descartes' rule on Bernstein coefficients) and the
// sign evaluation of the fast exact stage (exact/stages/algebraic_at_doubles.hpp). Fixed-size
// integers on doubles; GMP only for common factors, square-free parts and brackets finer than the
// doubles.
// PROOF: proofs/exact_ccd.md#descartes-at-doubles
// PROOF: proofs/exact_ccd.md#sign-at-a-bracketed-root
#pragma once

#include <gmpxx.h>

#include <optional>
#include <utility>
#include <vector>

#include "exact/polynomials/small_polynomial.hpp"

namespace exactccd::exact {

/// Thrown where the stage gives up (a step cap reached, a full root stack); the caller then
/// decides with the rational path.
struct UnresolvedAtDoubles {};

/// A bracket on dyadic rationals beyond the doubles (GMP): [A 2^-K, B 2^-K], A < B, holding
/// one simple root of p with p(A 2^-K) of sign `sign_lo` (non-zero) and p(B 2^-K) of the
/// other; or the exact root A 2^-K when A == B.
struct DyadicBracket {
  mpz_class A, B;
  unsigned K = 0;
  int sign_lo = 0;
  bool is_exact() const { return A == B; }
};

/// The roots of p (degree 2 or 3, square-free) strictly inside (A 2^-K, B 2^-K), each in its
/// own dyadic bracket, ascending: the interval cut at enclosures of the critical points of p
/// (roots of p', quadratic irrationals) on which p keeps the sign it has at them, into pieces
/// where p is monotone. A constant number of exact steps per doubling of the precision, however
/// close the roots are; nullopt when the enclosures need more than 2^14 bits beyond 2^-K
/// (then bisect).
/// PROOF: proofs/exact_ccd.md#roots-closer-than-one-ulp
std::optional<std::vector<DyadicBracket>> split_at_critical_points(const MpzPolynomial& p,
                                                                  const DyadicBracket& d);

/// A root r of the polynomial p: exact (lo == hi, a double), or the only root of p in the open
/// interval (lo, hi) of doubles, simple, with p(lo) and p(hi) non-zero of opposite signs; or,
/// when lo and hi are adjacent doubles holding several roots of p, one of them in a dyadic
/// bracket (`fine`) inside (lo, hi). p must outlive the root.
class BracketedRoot {
 public:
  static BracketedRoot at(const SmallPolynomial* p, double t) { return {p, t, t, 0}; }
  BracketedRoot(const SmallPolynomial* p, double lo, double hi, int sign_lo)
      : p_(p), lo_(lo), hi_(hi), sign_lo_(sign_lo) {}
  BracketedRoot(const SmallPolynomial* p, double lo, double hi, DyadicBracket fine)
      : p_(p), lo_(lo), hi_(hi), sign_lo_(0), fine_(std::move(fine)) {}

  bool is_exact() const { return lo_ == hi_; }
  /// The polynomial whose root this is (nullptr for an exact root given without one).
  const SmallPolynomial* polynomial() const { return p_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }

  /// Halves the bracket (may find r exactly); false when no double lies strictly inside.
  bool refine();

  /// The reported enclosure: exact; the adjacent doubles around a root beyond the doubles; or
  /// guided bisection to `width` (0: the tightest pair of doubles, canonical).
  std::pair<double, double> enclosure(double width) const;

  /// Narrows the bracket of doubles by bisection with p's signs from the wide-range filter
  /// alone (SmallPolynomial::certain_sign_at), until a sign is uncertain, no double is left
  /// inside, or `max_steps` halvings: no exact step. Nothing for an exact root or a bracket
  /// beyond the doubles. PROOF: proofs/exact_ccd.md#certain-signs-first
  void narrow_by_filter(int max_steps);
  /// The sign of g(r) when the wide-range filter certifies it on the bracket (g's enclosures of
  /// one strict sign on all of [lo, hi], or at the exact root), else 0: no exact step, and
  /// never 0 for g(r) = 0. PROOF: proofs/exact_ccd.md#certain-signs-first
  int certain_sign_of(const SmallPolynomial& g) const;

  /// For a bracket of doubles in [1/2, 1] (or an exact root there): the same root as a root u =
  /// 1 - r of p_reflected = p(1 - u) (SmallPolynomial::reflected of p), bracketed by
  /// [1 - hi, 1 - lo] (exact: Sterbenz); nullopt elsewhere. A sign of g(1 - u) at u is the
  /// sign of g at r. PROOF: proofs/exact_ccd.md#certain-signs-first
  std::optional<BracketedRoot> reflected(const SmallPolynomial* p_reflected) const;

  /// The exact sign of g(r); may narrow the bracket. Throws UnresolvedAtDoubles past the
  /// step cap. PROOF: proofs/exact_ccd.md#sign-at-a-bracketed-root
  /// PROOF: proofs/exact_ccd.md#constant-remainder
  int sign_of(const SmallPolynomial& g);

 private:
  const SmallPolynomial* p_;
  double lo_, hi_;
  int sign_lo_;
  std::optional<DyadicBracket> fine_;
};

/// r < b exactly, or false when r >= b or when both lie strictly inside the same pair of
/// adjacent doubles (then either gives the same reported enclosure). May refine both.
bool earlier(BracketedRoot& r, BracketedRoot& b);

/// The roots of a non-zero polynomial p in [0, t_max] (t_max a double in (0, 1]), in
/// ascending order, each once. A quadratic is first screened by its discriminant (negative: no
/// root; zero: the double root's line instead of p). Descartes' rule on Bernstein coefficients
/// over intervals with double ends: no sign variation, no root inside; one, exactly one
/// (simple); more, split at a double (the first few times near a critical point of p, from its
/// rounded coefficients). An interval without a double inside that still shows two variations
/// holds a multiple root or several roots within one ulp: p is replaced by its square-free part
/// (the same roots, simple) in *square_free_storage, and if that is not enough the interval's
/// roots are isolated on dyadic rationals (GMP). Both p and the storage must outlive the roots.
/// PROOF: proofs/exact_ccd.md#descartes-at-doubles
/// PROOF: proofs/exact_ccd.md#quadratic-discriminant
class RootIterator {
 public:
  RootIterator(const SmallPolynomial& p, double t_max, SmallPolynomial* square_free_storage);
  std::optional<BracketedRoot> next();

 private:
  enum class Kind : std::uint8_t { interval, point, fine };
  struct Item {
    double lo, hi;
    Kind kind;
    int index = 0;  // fine: into fine_
  };
  void push(const Item& it);
  void isolate_beyond_doubles(const Item& it);

  static constexpr int kMaxItems = 192;
  /// Splits at a double near a critical point of p before plain halving (guidance only).
  static constexpr int kMaxGuidedSplits = 8;
  int guided_splits_ = 0;
  const SmallPolynomial* p_;
  SmallPolynomial* storage_;
  bool square_free_ = false;
  Item stack_[kMaxItems];
  int size_ = 0;
  std::vector<DyadicBracket> fine_;  // GMP steps only: never filled on the fast path
};

}  // namespace exactccd::exact
