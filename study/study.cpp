#include "study/study.hpp"

#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "study/datasets.hpp"
#include "study/measurement.hpp"
#include "study/methods.hpp"
#include "study/report.hpp"
#include "oracle/common.hpp"
#include "oracle/output_file.hpp"

namespace exactccd::study {

using namespace exactccd::oracle;

int run_study(const StudyOptions& options) {
  if (options.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  if (options.paths.empty() && !options.simulation)
    throw UsageError("no data set: give a PATH or --simulation");
  for (const double w : options.widths)
    if (!(w >= 0.0 && std::isfinite(w)))
      throw UsageError("--widths: every width must be finite and >= 0, got " + format_double(w));
  for (const double eps : options.tolerances)
    if (!(eps >= 0.0 && std::isfinite(eps)))
      throw UsageError("--eps: every eps must be finite and >= 0, got " + format_double(eps));
  validate_min_separation(options.min_separation);

  // Opened before the work, so that an unwritable --out-md fails at once.
  std::optional<OutputFile> md_file;
  if (!options.out_md.empty())
    md_file.emplace(options.out_md, options.force ? Overwrite::replace : Overwrite::refuse,
                    "--out-md");

  std::vector<Dataset> datasets;
  for (const std::string& path : options.paths) {
    const double delta = options.min_separation;
    datasets.push_back(is_suite(path) ? load_suite(path, options.type, delta)
                                      : load_plain(path, options.type, delta));
  }
  if (options.simulation)
    datasets.push_back(load_simulation(options.simulation_config, options.min_separation));
  // Distinct names: the report names its plots after them.
  std::map<std::string, int> seen;
  for (Dataset& d : datasets)
    if (++seen[d.name] > 1) d.name += "-" + std::to_string(seen[d.name]);

  const std::vector<Method> methods =
      methods_of(options.tolerances, options.widths, options.min_separation);
  std::vector<DatasetResults> results;
  for (const Dataset& d : datasets) results.push_back(run_dataset(d, methods, options.repetitions));

  if (options.json)
    std::cout << study_json(results, methods, options.repetitions, options.min_separation)
                     .dump(2)
              << '\n';
  else
    study_markdown(std::cout, results, methods, options.min_separation);
  if (md_file) {
    std::ostringstream markdown;
    study_markdown(markdown, results, methods, options.min_separation);
    md_file->write(markdown.str());
    md_file->commit();
  }

  for (const DatasetResults& r : results)
    for (std::size_t m = 0; m < methods.size(); ++m)
      if (methods[m].certified && !r.total[m].clean()) return kExitDisagree;
  return kExitAgree;
}

}  // namespace exactccd::study
