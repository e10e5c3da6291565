// The study's reports: one JSON document, or Markdown tables (per data set; for a suite also
// per coordinate scale and translation, per base family and per family).
#pragma once

#include <ostream>
#include <vector>

#include "study/measurement.hpp"

namespace exactccd::study {

/// The JSON document; "min_separation" is D (0: contact).
Json study_json(const std::vector<DatasetResults>& results, const std::vector<Method>& methods,
                int repetitions, double min_separation = 0.0);

/// The Markdown tables; with D > 0 first a line "minimum separation: D" and what it means.
void study_markdown(std::ostream& out, const std::vector<DatasetResults>& results,
                    const std::vector<Method>& methods, double min_separation = 0.0);

}  // namespace exactccd::study
