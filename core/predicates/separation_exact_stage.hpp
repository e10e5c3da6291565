// What the minimum-separation filter asks of exact arithmetic at double times, as an interface:
// the filter (filters/separation_search.hpp) knows only this, exact/stages/separation_exact_signs
// implements it, and the pipeline joins the two, so that filters and exact are siblings.
// PROOF: proofs/min_separation.md#interval-search
#pragma once

#include <array>
#include <cstdint>

#include "core/predicates/interval.hpp"
#include "core/predicates/motion.hpp"

namespace exactccd::predicates {

/// The most region polynomials a separation has (edge-edge: 24).
inline constexpr int kMaxSeparationPolynomials = 24;
/// Every region polynomial of a separation (its numbering), padded to degree 6.
using SeparationCoefficientTable =
    std::array<FixedPoly<Interval, 6>, kMaxSeparationPolynomials>;
/// An enclosure of every region polynomial (over a piece, or at an instant).
using SeparationValues = std::array<Interval, kMaxSeparationPolynomials>;

/// Which separation (core/predicates/separation.hpp) a query's region polynomials are.
enum class SeparationPair : std::uint8_t { vertex_face, edge_edge };

/// Exact answers about region polynomial k of one query at double times t in [0, 1]. Only
/// sign_at, probe_at's sign and exact_coefficients decide; the guesses never do.
class SeparationExactStage {
 public:
  /// The exact sign at t and, for a polynomial with an integer kernel, a Newton guess of its
  /// root from the same value (NaN when there is none; `kernel` false for the others). The sign
  /// is always exact: never a default 0 that would read as a root.
  struct Probe {
    bool kernel = false;
    int sign = 0;
    double newton = 0.0;
  };
  /// The exact sign (-1, 0, +1) of polynomial k at t.
  virtual int sign_at(int k, double t) const = 0;
  /// One probe of the tightening at t.
  virtual Probe probe_at(int k, double t) const = 0;
  /// A guess of k's root in (lo, hi), 0 < lo < hi: the secant through its exact values at the
  /// ends; NaN when there is none.
  virtual double secant_guess(int k, double lo, double hi) const = 0;
  /// A guess of k's root in (lo, hi) where it changes sign and is monotone (Newton's method on
  /// its kernel in plain arithmetic); NaN when k has no kernel.
  virtual double newton_guess(int k, double lo, double hi) const = 0;
  /// Every region polynomial from its exact coefficients, each times its own positive power of
  /// two and rounded outwards once. PROOF: proofs/min_separation.md#exact-coefficients
  virtual void exact_coefficients(SeparationCoefficientTable* out) const = 0;
  /// Whether any call so far needed exact integer arithmetic (the query's stage is then
  /// exact_at_double).
  virtual bool used_exact_arithmetic() const = 0;

 protected:
  ~SeparationExactStage() = default;
};

}  // namespace exactccd::predicates
