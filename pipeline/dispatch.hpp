// The one certified pipeline. Every problem (pair kind, motion kind, contact or minimum
// separation) is an instance of `certified_ccd<Problem>`: the mode chosen, culling, exact
// power-of-two normalisation, the certified filters, the TOI narrowed by the exact stage, the
// exact path from what the filters certified. The stage that decided is read here only.
// PROOF: proofs/pipeline.md#one-pipeline
#pragma once

#include <tuple>
#include <utility>

#include "exactccd/types.hpp"
#include "filters/filter_outcome.hpp"
#include "pipeline/held_at_start.hpp"

namespace exactccd::pipeline {

using filters::FilterOutcome;

/// The stage that decided a verdict the filters certified.
inline Stage stage_of(const FilterOutcome& f) {
  if (f.culled) return Stage::culling;
  if (f.exact_used) return Stage::exact_at_double;
  if (f.toi_exact || (f.verdict == FilterOutcome::Verdict::contact && !f.toi_final))
    return Stage::filter_exact_toi;
  return Stage::filter;
}

/// The members of a problem without culling, scaling or an exact stage beside its exact path
/// (the point-plane instances): it derives from this and gives Query, exact, float_only and
/// filter; the filter's uncertain queries go to Derived::exact.
template <class Derived, class QueryType>
struct WithoutExactStage {
  struct NoStage {};
  static bool culled(const QueryType&, const CcdOptions&) { return false; }
  static constexpr int normalising_exponent(const QueryType&) { return 0; }
  static QueryType scaled(const QueryType& q, int) { return q; }
  static NoStage exact_stage(const QueryType&, const CcdOptions&) { return {}; }
  static std::pair<double, double> tighten(NoStage&, double lo, double hi, const CcdOptions&) {
    return {lo, hi};
  }
  static CcdResult after_filter(const QueryType& q, const CcdOptions& o, const FilterOutcome&,
                                NoStage&) {
    return Derived::exact(q, o);
  }
};

/// A Problem is a struct of static members (pipeline/linear_problems.hpp,
/// pipeline/rigid_problems.hpp):
///   Query                                   the validated query, finite doubles;
///   float_only(q, o) -> CcdResult           the uncertified float test (Mode::float_only);
///   exact(q, o) -> CcdResult                the exact path alone (Mode::exact);
///   culled(q, o) -> bool                    certain no contact by exact box comparisons;
///   normalising_exponent(q) -> int, scaled(q, s) -> Query
///                                           exact scaling by 2^s (0: none);
///   exact_stage(q, o) -> Stage              exact answers at doubles, built when first asked;
///   filter(q, o, stage) -> FilterOutcome    the certified filters;
///   tighten(stage, lo, hi, o) -> pair       the filter's TOI narrowed (when not toi_final);
///   after_filter(q, o, f, stage) -> CcdResult   the exact path from what f certified.
/// Options are validated and the FP state set by the caller (the public entry points).
template <class Problem>
CcdResult certified_ccd_over_step(const typename Problem::Query& query,
                                  const CcdOptions& options) {
  switch (options.mode) {
    case Mode::float_only: return Problem::float_only(query, options);
    case Mode::exact: return Problem::exact(query, options);
    case Mode::filtered: break;
  }
  CcdResult r;
  if (Problem::culled(query, options)) {
    r.decided_by = Stage::culling;
    return r;
  }
  typename Problem::Query scaled;
  const typename Problem::Query* q = &query;
  if (const int s = Problem::normalising_exponent(query); s != 0) {
    scaled = Problem::scaled(query, s);
    q = &scaled;
  }
  auto stage = Problem::exact_stage(*q, options);
  const FilterOutcome f = Problem::filter(*q, options, stage);
  if (f.verdict == FilterOutcome::Verdict::uncertain)
    return Problem::after_filter(*q, options, f, stage);
  r.decided_by = stage_of(f);
  if (f.verdict == FilterOutcome::Verdict::no_contact) return r;
  r.collides = true;
  r.toi_lo = f.toi_lo;
  r.toi_hi = f.toi_hi;
  if (!f.toi_final) std::tie(r.toi_lo, r.toi_hi) = Problem::tighten(stage, r.toi_lo, r.toi_hi, options);
  return r;
}

/// The instance's answer with the state at the start (held_at_start.hpp): t_max = 0 asks for
/// it alone, and every answer says whether t* = 0 (CcdResult::starts_within).
template <class Problem>
CcdResult certified_ccd(const typename Problem::Query& query, const CcdOptions& options) {
  const auto decide = [](const typename Problem::Query& q, const CcdOptions& o) {
    return certified_ccd_over_step<Problem>(q, o);
  };
  if (options.t_max == 0.0) return decided_at_start(query, options, decide);
  return with_start_flag(decide(query, options), query, options, decide);
}

}  // namespace exactccd::pipeline
