#include "study/methods.hpp"

#include "study/labels.hpp"

namespace exactccd::study {

std::vector<Method> methods_of(const std::vector<double>& tolerances,
                               const std::vector<double>& widths, double min_separation) {
  std::vector<Method> methods;
  methods.push_back({Kind::float_only, 0.0, "float_only", "", false});
  for (const double eps : tolerances)
    methods.push_back({Kind::tolerance, eps, "tolerance", "eps=" + short_number(eps), false});
  for (const double width : widths)
    methods.push_back({Kind::filtered, width, "filtered", "width=" + short_number(width), true});
  methods.push_back({Kind::exact, 0.0, "exact", "", true});
  for (Method& m : methods) m.min_separation = min_separation;
  return methods;
}

}  // namespace exactccd::study
