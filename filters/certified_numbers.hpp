// The number type the filters compute in (core/predicates: intervals with directed rounding),
// by its short names in the filters' namespace.
#pragma once

#include "core/predicates/interval.hpp"

namespace exactccd::filters {

using predicates::certain_strict_sign;
using predicates::certainly_has_sign;
using predicates::certified_sign;
using predicates::CertifiedSign;
using predicates::Interval;
using predicates::RoundingGuard;

}  // namespace exactccd::filters
