// The study's reports: one JSON document, or Markdown tables (per data set; for a suite also
// per coordinate scale and translation, per base family and per family).
#pragma once

#include <ostream>
#include <vector>

#include "bench/study/measurement.hpp"

namespace exactccd::study {

Json study_json(const std::vector<DatasetResults>& results, const std::vector<Method>& methods,
                int repetitions);

void study_markdown(std::ostream& out, const std::vector<DatasetResults>& results,
                    const std::vector<Method>& methods);

}  // namespace exactccd::study
