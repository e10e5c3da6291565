// What the contact filter asks of exact arithmetic at double times, as an interface: the filter
// (filters/cubic_filter.hpp) knows only this, exact/stages/contact_exact_stage.hpp implements it,
// and the pipeline joins the two, so that filters and exact are siblings.
// PROOF: proofs/filters.md#exact-at-double-times
#pragma once

#include <utility>

namespace exactccd::predicates {

/// Exact answers at double times, consulted only where the interval tests cannot decide
/// (exact/stages/contact_exact_stage.hpp implements it with exact integer arithmetic; the
/// filters know only this, and the pipeline joins the two).
/// Must not depend on the rounding mode.
class ContactExactStage {
 public:
  /// The exact sign of the coplanarity cubic at the double t in [0, t_max].
  virtual int cubic_sign_at(double t) = 0;
  /// Exact contact test at a double t where the cubic vanishes.
  virtual bool contact_at(double t) = 0;
  /// The tightest pair of doubles around the only, simple root of the cubic in [lo, hi]
  /// (certain opposite non-zero signs at lo and hi); equal when the root is a double.
  virtual std::pair<double, double> bisect_root(double lo, double hi) = 0;
  /// Enclosures in doubles of the cubic's exact coefficients times one positive power of two
  /// (lo[i] <= c_i 2^-s <= hi[i]): a positive multiple of the cubic, for the filter's retry
  /// where its interval cubic is too wide. From the same exact cubic the other answers use, so
  /// it is computed once per query. PROOF: proofs/filters.md#exact-cubic-retry
  virtual void cubic_coefficient_bounds(double (&lo)[4], double (&hi)[4]) = 0;

 protected:
  ~ContactExactStage() = default;
};

}  // namespace exactccd::predicates
