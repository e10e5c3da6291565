// Numbers in the study's labels and tables.
#pragma once

#include <string>

namespace exactccd::study {

/// x for labels: a power of ten as 1eN (1e-6, 1e8), anything else as %g (0, 1, 0.5, 2.5e-07).
std::string short_number(double x);

}  // namespace exactccd::study
