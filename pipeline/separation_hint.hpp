// What a minimum-separation filter certified, handed to the exact procedure (linear and rigid
// motion alike): no contact before cleared_until, and a bracket with known signs when it has one.
// PROOF: proofs/min_separation.md#filters
#pragma once

#include "exact/reference/min_separation.hpp"
#include "filters/filter_outcome.hpp"

namespace exactccd::pipeline {

/// Points into f (its known signs): use while f lives.
inline exact::SeparationHint separation_hint(const filters::FilterOutcome& f) {
  exact::SeparationHint hint;
  hint.t_from = f.cleared_until;
  if (f.bracketed) {
    hint.t_to = f.within_at;
    hint.known_signs = f.known_signs.data();
  }
  return hint;
}

}  // namespace exactccd::pipeline
