// What the rigid filters (contact and minimum separation) ask of exact arithmetic at double
// parameters, as an interface: filters/rigid_filter.hpp and filters/rigid_separation_filter.hpp
// know only this, exact/stages/rigid_exact_stage.hpp implements it, and the pipeline joins them.
// PROOF: proofs/rigid_ccd.md#toi-tightening
#pragma once

namespace exactccd::predicates {

/// Exact signs at doubles of the query's polynomials, consulted only where interval signs are
/// uncertain: the reduced coplanarity polynomial g (contact), or a region polynomial of the
/// query's minimum separation (each, or any positive multiple of it). Must not depend on the
/// rounding mode.
class RigidExactStage {
 public:
  /// The exact sign (-1, 0, +1) of g at the double s in [0, t_max].
  virtual int coplanarity_sign_at(double s) = 0;
  /// The exact sign of region polynomial k (core/predicates/separation.hpp's numbering) of the
  /// query's separation with delta = its min_separation, at the double s in [0, t_max].
  virtual int region_sign_at(int k, double s) = 0;

 protected:
  ~RigidExactStage() = default;
};

}  // namespace exactccd::predicates
