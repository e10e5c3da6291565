// Runs a computation in the FixedInt width its proven bit-length bound selects: each
// computation is compiled for every width 1 ... kMaxFixedLimbs, and the bound picks one at run
// time, before computing.
// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
#pragma once

#include <stdexcept>
#include <type_traits>

#include "exact/arithmetic/integer_bounds.hpp"

namespace exactccd::exact {

/// Calls f(std::integral_constant<int, N>{}) for the limb count n in [1, kMaxFixedLimbs] (as
/// fixed_limbs_for gives it when not 0).
template <class F>
decltype(auto) with_limbs(int n, F&& f) {
  static_assert(kMaxFixedLimbs == 16, "extend the cases below");
  switch (n) {
    case 1: return f(std::integral_constant<int, 1>{});
    case 2: return f(std::integral_constant<int, 2>{});
    case 3: return f(std::integral_constant<int, 3>{});
    case 4: return f(std::integral_constant<int, 4>{});
    case 5: return f(std::integral_constant<int, 5>{});
    case 6: return f(std::integral_constant<int, 6>{});
    case 7: return f(std::integral_constant<int, 7>{});
    case 8: return f(std::integral_constant<int, 8>{});
    case 9: return f(std::integral_constant<int, 9>{});
    case 10: return f(std::integral_constant<int, 10>{});
    case 11: return f(std::integral_constant<int, 11>{});
    case 12: return f(std::integral_constant<int, 12>{});
    case 13: return f(std::integral_constant<int, 13>{});
    case 14: return f(std::integral_constant<int, 14>{});
    case 15: return f(std::integral_constant<int, 15>{});
    case 16: return f(std::integral_constant<int, 16>{});
    default: throw std::logic_error("exactccd: no fixed-size integer of that width");
  }
}

}  // namespace exactccd::exact
