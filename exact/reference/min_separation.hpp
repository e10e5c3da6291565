// The exact minimum-separation procedure: the earliest t in [0, t_max] at which the closed
// primitives come within Euclidean distance delta, by exact root isolation of the region
// polynomials (core/predicates/separation.hpp) and exact signs at each candidate time.
// PROOF: proofs/min_separation.md#theorem-exact-procedure
#pragma once

#include "exact/arithmetic/rational.hpp"
#include "exact/reference/rigid_ccd.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::exact {

/// delta >= 0 (delta = 0 is contact, as vertex_face_ccd_exact decides it); options validated.
/// What the filters certified: never within delta on [0, t_from] when t_from > 0; when
/// t_to > 0, within delta at t_to, and known_signs[k] (-1, 0, +1, or 2 for unknown) is the
/// constant sign of region polynomial k (core/predicates/separation.hpp's numbering) over
/// [t_from, t_to]. The search is confined to what they leave open.
struct SeparationHint {
  double t_from = 0.0;
  double t_to = 0.0;
  const signed char* known_signs = nullptr;
};

/// delta >= 0 (delta = 0 is contact, as vertex_face_ccd_exact decides it); options validated.
CcdResult vertex_face_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                           const CcdOptions& options,
                                           const SeparationHint& hint = {});
CcdResult edge_edge_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                         const CcdOptions& options,
                                         const SeparationHint& hint = {});

/// Rigid (or per-vertex linear) motion: the region polynomials of the four points on the common
/// denominator W with delta^2 W^2 in place of delta^2 (degree <= 30 in s); the hint as above, in s.
/// PROOF: proofs/min_separation.md#rigid-separation
CcdResult rigid_min_separation_exact(const RationalRigidQuery& query, const Rational& delta,
                                     const CcdOptions& options, const SeparationHint& hint = {});

}  // namespace exactccd::exact
