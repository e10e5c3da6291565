// The one reading of a minimum-separation filter's outcome (linear and rigid motion alike): its
// verdict as the query's result, or the exact path called with what the filter cleared.
// PROOF: proofs/min_separation.md#filters
#pragma once

#include "exact/reference/min_separation.hpp"
#include "filters/separation_filter.hpp"

namespace exactccd {

/// `exact_path(hint)` decides what the filter left uncertain.
template <class ExactPath>
CcdResult separation_result(const filters::SeparationOutcome& f, ExactPath&& exact_path) {
  CcdResult r;
  switch (f.verdict) {
    case filters::SeparationVerdict::never_within:
      r.decided_by =
          f.culled ? Stage::culling : (f.exact_used ? Stage::exact_at_double : Stage::filter);
      return r;
    case filters::SeparationVerdict::contact:
      r.collides = true;
      r.toi_lo = f.toi_lo;
      r.toi_hi = f.toi_hi;
      r.decided_by = f.exact_used ? Stage::exact_at_double : Stage::filter;
      return r;
    case filters::SeparationVerdict::uncertain: break;
  }
  exact::SeparationHint hint;
  hint.t_from = f.cleared_until;
  if (f.bracketed) {
    hint.t_to = f.within_at;
    hint.known_signs = f.known_signs.data();
  }
  return exact_path(hint);
}

}  // namespace exactccd
