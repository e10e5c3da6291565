// The certified floating-point search for the first contact: the coplanarity cubic's roots
// are isolated by Bernstein subdivision with interval coefficients, each candidate interval is
// excluded or confirmed by interval inclusion tests, and a confirmed root is refined by
// certified bisection. Anything undecided is reported as uncertain, never guessed.
// PROOF: proofs/filters.md#cubic-filter
#pragma once

#include <cstdint>
#include <utility>

#include "core/predicates/contact_exact_stage.hpp"
#include "core/predicates/motion.hpp"
#include "filters/certified_numbers.hpp"
#include "filters/filter_outcome.hpp"

namespace exactccd::filters {

using predicates::ContactExactStage;

/// `Inclusion` provides, for a time interval T (an Interval inside [0, t_max]):
///   bool excluded(const Interval& T)            -- certainly no contact at any t in T;
///   bool excluded_in_leading_projection(const Interval& T)
///                                               -- the same, tried in one projection only;
///   bool certainly_included(const Interval& T)  -- contact at every coplanar t in T.
/// Must be called with a RoundingGuard held. `tighter_cubic_available`: the caller retries with
/// a tighter enclosure of the cubic when roots_unresolved, so the search gives up (uncertain,
/// roots_unresolved) as soon as a node of width 1/4 or less that survives exclusion has no
/// Bernstein coefficient of certain sign: its enclosure is then too wide to isolate anything.
template <class Inclusion>
EXACTCCD_CERTIFIED
FilterOutcome cubic_filter(const predicates::FixedPoly<Interval, 3>& cubic, double t_max,
                           double toi_width, const Inclusion& inclusion, ContactExactStage& exact,
                           bool tighter_cubic_available = false);

/// True when all four Bernstein coefficients of the cubic on [0, t_max] are certainly
/// non-zero with one sign: no coplanar instant, hence no contact. Needs a RoundingGuard. (The
/// interval stage of the test whose semi-static stage is coplanarity_cubic_root_free_semistatic.)
EXACTCCD_CERTIFIED
bool coplanarity_cubic_root_free_interval(const predicates::FixedPoly<Interval, 3>& cubic,
                                          double t_max);

}  // namespace exactccd::filters

#include "filters/cubic_filter_impl.hpp"
