// Rigid (and per-vertex linear) motion as instances of the one pipeline (pipeline/dispatch.hpp):
// contact (the reduced coplanarity polynomial and inclusion) and minimum separation (the rigid
// region polynomials and `within`). Both filters cull and normalise inside, on interval boxes of
// the motion. PROOF: proofs/pipeline.md#one-pipeline
#pragma once

#include <utility>

#include "core/float_only/rigid_float_only_ccd.hpp"
#include "exact/reference/min_separation.hpp"
#include "exact/reference/rigid_ccd.hpp"
#include "exact/stages/rigid_exact_stage.hpp"
#include "filters/rigid_filter.hpp"
#include "filters/rigid_separation_filter.hpp"
#include "pipeline/separation_hint.hpp"

namespace exactccd::pipeline {

/// What the two rigid problems share: the query, the float test, no culling or scaling here.
struct RigidProblem {
  using Query = predicates::DoubleRigidQuery;
  using ExactStage = exact::RigidExactStageAtDoubles;
  /// Uncertified, for comparison only (a distance sampled when min_separation > 0).
  static CcdResult float_only(const Query& q, const CcdOptions& o) {
    return float_only::rigid_ccd(q, o);
  }
  static bool culled(const Query&, const CcdOptions&) { return false; }
  static constexpr int normalising_exponent(const Query&) { return 0; }
  static Query scaled(const Query& q, int) { return q; }
  /// The filters report final TOIs.
  static std::pair<double, double> tighten(ExactStage&, double lo, double hi, const CcdOptions&) {
    return {lo, hi};
  }
};

/// Rigid contact. PROOF: proofs/rigid_ccd.md#filters
struct RigidContact : RigidProblem {
  static CcdResult exact(const Query& q, const CcdOptions& o) {
    return exact::rigid_ccd_exact(exact::rational_query(q), o);
  }
  static ExactStage exact_stage(const Query& q, const CcdOptions&) { return ExactStage(q); }
  static FilterOutcome filter(const Query& q, const CcdOptions& o, ExactStage& stage) {
    return filters::rigid_ccd_filter(q, o, stage);
  }
  static CcdResult after_filter(const Query& q, const CcdOptions& o, const FilterOutcome&,
                                ExactStage&) {
    return exact(q, o);
  }
};

/// Rigid minimum separation delta = options.min_separation > 0.
/// PROOF: proofs/min_separation.md#rigid-separation
struct RigidSeparation : RigidProblem {
  static CcdResult rational(const Query& q, const CcdOptions& o,
                            const exact::SeparationHint& hint) {
    return exact::rigid_min_separation_exact(exact::rational_query(q),
                                             exact::Rational(o.min_separation), o, hint);
  }
  static CcdResult exact(const Query& q, const CcdOptions& o) { return rational(q, o, {}); }
  static ExactStage exact_stage(const Query& q, const CcdOptions& o) {
    return ExactStage(q, o.min_separation);
  }
  static FilterOutcome filter(const Query& q, const CcdOptions& o, ExactStage& stage) {
    return filters::rigid_separation_filter(q, o, stage);
  }
  static CcdResult after_filter(const Query& q, const CcdOptions& o, const FilterOutcome& f,
                                ExactStage&) {
    return rational(q, o, separation_hint(f));
  }
};

}  // namespace exactccd::pipeline
