// compute_epsilon for the semi-static filter, CGAL-style: the error constants of
// filters/coplanarity_semistatic.hpp evaluated from the filter's own code (det3 and the Bernstein
// sums, instantiated on the error-tracking type), with every entry a rounded difference of input
// doubles. Exact rationals: the tests compare them with the literals kSingle and kTriple.
// PROOF: proofs/filters.md#error-tracking
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <stdexcept>

#include "filters/coplanarity_semistatic.hpp"
#include "static_filter_error.hpp"

namespace exactccd::filters::semistatic {

// The filter decides only with column maxima in [kMin, kMax] = [2^-200, 2^200].
static_assert(kMin == 0x1p-200 && kMax == 0x1p200, "update SemistaticError's exponent range");
using SemistaticError = StaticFilterError<-200, 200>;

/// A difference vector of the filter as det3 sees it: each entry a rounded difference of its
/// coordinate column.
struct ErrorVector3 {
  SemistaticError cx = SemistaticError::rounded_difference(0);
  SemistaticError cy = SemistaticError::rounded_difference(1);
  SemistaticError cz = SemistaticError::rounded_difference(2);
  const SemistaticError& x() const { return cx; }
  const SemistaticError& y() const { return cy; }
  const SemistaticError& z() const { return cz; }
};

/// Error of a value of degree (1, 1, 1), in units of Mx My Mz.
inline mpq_class error_of_determinant_value(const SemistaticError& value) {
  if (value.degree() != SemistaticError::Degree{1, 1, 1})
    throw std::domain_error("semi-static: a determinant value must have degree (1, 1, 1)");
  return value.error();
}

/// Bound on |fl(D) - D| / (Mx My Mz) for b0 = det3(v0, w0, u0) and b3 = det3(v1, w1, u1).
inline mpq_class single_determinant_error() {
  const ErrorVector3 v0{}, v1{}, w0{}, w1{}, u0{}, u1{};
  return std::max(error_of_determinant_value(det3(v0, w0, u0)),
                  error_of_determinant_value(det3(v1, w1, u1)));
}

/// The same for the sums 3 b1 and 3 b2 as the filter computes them.
inline mpq_class triple_sum_error() {
  const ErrorVector3 v0{}, v1{}, w0{}, w1{}, u0{}, u1{};
  return std::max(error_of_determinant_value(bernstein_b1_times_3(v0, v1, w0, w1, u0, u1)),
                  error_of_determinant_value(bernstein_b2_times_3(v0, v1, w0, w1, u0, u1)));
}

/// The smallest constant K whose threshold covers an error bound: the filter compares with
/// fl(K fl(fl(Mx My) Mz)) >= K Mx My Mz (1 - u)^3 (three roundings, none underflows as
/// Mx My Mz >= 2^-600), so K is sound when K (1 - u)^3 >= the error.
inline mpq_class constant_covering(const mpq_class& error) {
  const mpq_class one_minus_u = 1 - SemistaticError::unit_roundoff();
  return error / (one_minus_u * one_minus_u * one_minus_u);
}

/// The certified constants: kSingle and kTriple must be at least these.
inline mpq_class compute_epsilon_single() { return constant_covering(single_determinant_error()); }
inline mpq_class compute_epsilon_triple() { return constant_covering(triple_sum_error()); }

}  // namespace exactccd::filters::semistatic
