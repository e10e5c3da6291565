/// \file
/// For building ipc-toolkit's own CCD tests against ExactCCD: the build copies those tests with
/// every `TightInclusionCCD` renamed `ExactCCDAsTightInclusion` and this header included first.
/// The class takes TightInclusionCCD's constructor arguments and constants; the tolerance and
/// the iteration limit mean nothing to an exact method and are ignored. The margin keeps
/// ExactCCD's default cap max_margin = 1e-4, TightInclusionCCD's.
#pragma once

#include "exact_ccd.hpp"

namespace ipc {

class ExactCCDAsTightInclusion : public exactccd_ipc::ExactCCD {
public:
    static constexpr double DEFAULT_TOLERANCE = 1e-6;
    static constexpr long DEFAULT_MAX_ITERATIONS = 10'000'000L;
    static constexpr double DEFAULT_CONSERVATIVE_RESCALING = 0.8;
    static constexpr double SMALL_TOI = 1e-6;

    explicit ExactCCDAsTightInclusion(
        double /*tolerance*/ = DEFAULT_TOLERANCE,
        long /*max_iterations*/ = DEFAULT_MAX_ITERATIONS,
        double conservative_rescaling = DEFAULT_CONSERVATIVE_RESCALING)
        : ExactCCD(conservative_rescaling)
    {
    }
};

} // namespace ipc
