// The one result of every certified filter (contact and minimum separation, linear and rigid
// motion): a verdict it certifies, or `uncertain` with what it did certify for the exact path.
// The pipeline (pipeline/dispatch.hpp) reads it in one place.
// PROOF: proofs/pipeline.md#one-pipeline
#pragma once

#include <array>
#include <cstdint>

#include "core/predicates/separation_exact_stage.hpp"

namespace exactccd::filters {

using predicates::kMaxSeparationPolynomials;

struct FilterOutcome {
  enum class Verdict : std::uint8_t {
    no_contact,  ///< certainly no contact (within delta) on [0, t_max]
    contact,     ///< certainly a contact, the first at t* in [toi_lo, toi_hi]
    uncertain,   ///< not decided: the exact path decides
  };
  Verdict verdict = Verdict::uncertain;
  /// For a contact: toi_lo <= t* <= toi_hi (for contact without separation, t* is the only
  /// root of the coplanarity polynomial there, of certain opposite signs at both ends, or
  /// toi_lo == toi_hi == t*).
  double toi_lo = 0.0, toi_hi = 0.0;
  /// The bracket meets the requested width (the tightest pair of doubles for width 0); when
  /// false, the pipeline narrows it with the exact stage.
  bool toi_final = false;
  /// no_contact because the swept boxes are apart (Stage::culling).
  bool culled = false;
  /// Exact arithmetic at doubles decided the verdict (Stage::exact_at_double).
  bool exact_used = false;
  /// The verdict is the intervals', the TOI narrowed with exact signs (Stage::filter_exact_toi).
  bool toi_exact = false;
  /// Uncertain because subdivision could not isolate the cubic's roots (its interval
  /// coefficients too wide, or a multiple root): a tighter enclosure of the cubic may decide.
  bool roots_unresolved = false;
  /// When uncertain: no contact on [0, cleared_until] (certified when > 0).
  double cleared_until = 0.0;
  /// When uncertain and bracketed (minimum separation): within delta at within_at, so t* lies
  /// in (cleared_until, within_at], and known_signs[k] (-1, 0, +1; 2 unknown) is the constant
  /// sign of region polynomial k over that bracket.
  bool bracketed = false;
  double within_at = 0.0;
  std::array<signed char, kMaxSeparationPolynomials> known_signs{};
};

}  // namespace exactccd::filters
