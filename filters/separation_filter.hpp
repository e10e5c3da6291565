// Certified floating-point decisions for minimum-separation CCD (delta > 0): culling by swept
// boxes more than delta apart, then a search over adaptively subdivided time intervals
// (separating directions, signs of the region polynomials) for the first time within delta.
// `uncertain` sends the query to the exact path. PROOF: proofs/min_separation.md#filters
#pragma once

#include <array>
#include <cstdint>

#include "core/predicates/separation_exact_stage.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filters {

/// Certainly never within delta: the swept boxes are more than delta apart on one axis.
bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta);
bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta);

using predicates::kMaxSeparationPolynomials;

enum class SeparationVerdict : std::uint8_t {
  never_within,  ///< certainly never within delta on [0, t_max]
  contact,       ///< certainly within delta, first at t* in [toi_lo, toi_hi]
  uncertain,
};

struct SeparationOutcome {
  SeparationVerdict verdict = SeparationVerdict::uncertain;
  /// When contact: toi_lo <= t* <= toi_hi, the tightest pair of doubles (or toi_width).
  double toi_lo = 0.0, toi_hi = 0.0;
  /// never_within because the swept boxes are more than delta apart (Stage::culling).
  bool culled = false;
  /// Exact integer arithmetic was needed (signs at double times, or the region polynomials'
  /// exact coefficients) for the verdict or the TOI.
  bool exact_used = false;
  /// When uncertain: never within delta on [0, cleared_until] (certified when > 0).
  double cleared_until = 0.0;
  /// When uncertain and bracketed: within delta at within_at, so t* lies in
  /// (cleared_until, within_at], and known_signs[k] (-1, 0, +1; 2 unknown) is the constant
  /// sign of region polynomial k over that bracket.
  bool bracketed = false;
  double within_at = 0.0;
  std::array<signed char, kMaxSeparationPolynomials> known_signs{};
};

/// The interval stages on finite input, options validated, delta = options.min_separation > 0;
/// `exact` answers for the same query (exact/stages/separation_exact_signs.hpp) where the
/// intervals cannot tell. Called rounding to nearest, without flush-to-zero (the library's
/// entries set it; the whole-step test relies on it and the rest sets its own mode). No heap
/// allocation but the exact stage's.
SeparationOutcome vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options,
                                                const predicates::SeparationExactStage& exact);
SeparationOutcome edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options,
                                              const predicates::SeparationExactStage& exact);

}  // namespace exactccd::filters
