// The exact minimum-separation procedure: the earliest t in [0, t_max] at which the closed
// primitives come within Euclidean distance delta, by exact root isolation of the region
// polynomials (core/predicates/separation.hpp) and exact signs at each candidate time.
// PROOF: proofs/min_separation.md#theorem-exact-procedure
#pragma once

#include "exact/rational.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::exact {

/// delta >= 0 (delta = 0 is contact, as vertex_face_ccd_exact decides it); options validated.
/// t_from in [0, t_max): the caller has certified that the primitives are never within delta
/// on [0, t_from] when t_from > 0 (the filters' cleared prefix); the search starts there.
CcdResult vertex_face_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                           const CcdOptions& options, double t_from = 0.0);
CcdResult edge_edge_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                         const CcdOptions& options, double t_from = 0.0);

}  // namespace exactccd::exact
