#include "study/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>

#include "study/labels.hpp"

namespace exactccd::study {

namespace {

struct ErrorStats {
  double max_abs = 0.0, median_abs = 0.0, median = 0.0, max_late_by = 0.0, max_early_by = 0.0;
};

// Late TOIs by how late: the upper ends of the bins (a late toi equal to the exact pair's upper
// end has error 0: less than one ulp late).
constexpr double kLateBins[] = {1e-15, 1e-12, 1e-9, 1e-6, 1e-3};

Json late_histogram(const Outcome& o) {
  std::vector<std::size_t> counts(std::size(kLateBins) + 1, 0);
  for (const double e : o.late_errors) {
    std::size_t k = 0;
    while (k < std::size(kLateBins) && e > kLateBins[k]) ++k;
    ++counts[k];
  }
  Json j;
  for (std::size_t k = 0; k < std::size(kLateBins); ++k)
    j["<=" + short_number(kLateBins[k])] = counts[k];
  j[">" + short_number(kLateBins[std::size(kLateBins) - 1])] = counts.back();
  return j;
}

ErrorStats error_stats(const Outcome& o) {
  ErrorStats s;
  std::vector<double> abs_errors;
  for (const double e : o.toi_errors) {
    abs_errors.push_back(std::abs(e));
    s.max_abs = std::max(s.max_abs, std::abs(e));
    s.max_late_by = std::max(s.max_late_by, e);
    s.max_early_by = std::max(s.max_early_by, -e);
  }
  s.median_abs = median_of(abs_errors);
  s.median = median_of(o.toi_errors);
  return s;
}

Json outcome_json(const Outcome& o, const Method& m) {
  const ErrorStats s = error_stats(o);
  Json j;
  j["method"] = m.name;
  j["setting"] = m.setting;
  j["label"] = m.label();
  j["parameter"] = m.parameter;
  j["certified"] = m.certified;
  j["queries"] = o.queries;
  j["collisions"] = o.collisions;
  j["false_positives"] = o.false_positives;
  j["false_negatives"] = o.false_negatives;
  j["late_tois"] = o.late;
  j["true_positives"] = o.true_positives;
  j["toi_errors_measured"] = o.toi_errors.size();
  j["max_abs_toi_error"] = s.max_abs;
  j["median_abs_toi_error"] = s.median_abs;
  j["median_toi_error"] = s.median;
  j["max_late_by"] = s.max_late_by;
  j["max_early_by"] = s.max_early_by;
  j["late_by"] = late_histogram(o);
  j["mean_ns"] = o.mean_ns();
  j["examples"] = {{"false_positives", o.fp_examples},
                   {"false_negatives", o.fn_examples},
                   {"late_tois", o.late_examples}};
  return j;
}

Json methods_json(const std::vector<Outcome>& outcomes, const std::vector<Method>& methods) {
  Json a = Json::array();
  for (std::size_t m = 0; m < methods.size(); ++m)
    a.push_back(outcome_json(outcomes[m], methods[m]));
  return a;
}

}  // namespace

Json study_json(const std::vector<DatasetResults>& results, const std::vector<Method>& methods,
                int repetitions, double min_separation) {
  Json j;
  j["command"] = "exactccd study";
  j["min_separation"] = min_separation;
  j["timing"] = {{"threads", 1},
                 {"repetitions", repetitions},
                 {"min_sample_ns", kMinSampleNs},
                 {"mean_ns", "median over the repetitions of (sample time / queries decided in "
                             "it); a sample is one or more whole passes over a group"}};
  j["toi_error"] =
      "reported toi (toi_lo for an enclosure) minus the exact first contact time t*, as its "
      "signed distance to the exact path's tightest pair [lo, hi]; late: toi > lo (t* < toi)";
  Json datasets = Json::array();
  for (const DatasetResults& r : results) {
    const Dataset& d = *r.dataset;
    Json dj;
    dj["name"] = d.name;
    dj["path"] = d.path;
    dj["queries"] = d.size();
    dj["contacts"] = d.contacts();
    dj["truth"] = d.truth_source;
    dj["exact_toi"] = d.toi_source;
    dj["methods"] = methods_json(r.total, methods);
    if (d.suite) {
      dj["suite"] = d.suite_info;
      Json families = Json::array();
      for (std::size_t k = 0; k < d.groups.size(); ++k) {
        const Group& g = d.groups[k];
        Json fj;
        fj["name"] = g.name;
        fj["base"] = g.base;
        fj["type"] = g.type_name;
        fj["scale"] = g.scale;
        fj["offset"] = g.offset;
        fj["description"] = g.description;
        fj["parameters"] = g.parameters;
        fj["queries"] = g.size();
        fj["contacts"] = g.contacts();
        fj["methods"] = methods_json(r.by_group[k], methods);
        families.push_back(std::move(fj));
      }
      dj["families"] = std::move(families);
      Json scales = Json::array();
      for (const auto& [key, outcomes] : r.by_scale) {
        Json sj;
        sj["label"] = key.label();
        sj["scale"] = key.scale;
        sj["offset"] = key.offset;
        sj["queries"] = r.scale_counts.at(key).first;
        sj["contacts"] = r.scale_counts.at(key).second;
        sj["methods"] = methods_json(outcomes, methods);
        scales.push_back(std::move(sj));
      }
      dj["scales"] = std::move(scales);
      Json bases = Json::array();
      for (const std::string& base : r.bases) {
        Json bj;
        bj["base"] = base;
        bj["type"] = r.base_type.at(base);
        bj["queries"] = r.base_counts.at(base).first;
        bj["contacts"] = r.base_counts.at(base).second;
        bj["methods"] = methods_json(r.by_base.at(base), methods);
        bases.push_back(std::move(bj));
      }
      dj["bases"] = std::move(bases);
    }
    datasets.push_back(std::move(dj));
  }
  j["datasets"] = std::move(datasets);
  return j;
}

namespace {

// The fewest significant digits that read back as x (1.47e-05, not 1.4699999999999999e-05).
std::string shortest_text(double x) {
  char buffer[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    if (std::strtod(buffer, nullptr) == x) break;
  }
  return buffer;
}

std::string format_error(double e) {
  if (e == 0.0) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2e", e);
  return buffer;
}

std::string markdown_escape(std::string s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// One row per method: time, errors.
void summary_markdown(std::ostream& out, const std::vector<Outcome>& outcomes,
                      const std::vector<Method>& methods) {
  out << "| method | mean ns/query | false positives | false negatives | late TOIs | "
         "max \\|TOI error\\| | median \\|TOI error\\| | max late by |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const Outcome& o = outcomes[m];
    const ErrorStats s = error_stats(o);
    char ns[32];
    std::snprintf(ns, sizeof ns, "%.1f", o.mean_ns());
    out << "| " << markdown_escape(methods[m].label())
        << (methods[m].certified ? " (certified)" : "") << " | " << ns << " | " << o.false_positives
        << " | " << o.false_negatives << " | " << o.late << " | " << format_error(s.max_abs)
        << " | " << format_error(s.median_abs) << " | " << format_error(s.max_late_by) << " |\n";
  }
}

// One row per family or scale, one `FP / FN / late` cell per method.
void breakdown_header(std::ostream& out, const std::string& first,
                      const std::vector<std::string>& extra, const std::vector<Method>& methods) {
  out << "| " << first;
  for (const std::string& e : extra) out << " | " << e;
  for (const Method& m : methods) out << " | " << markdown_escape(m.label());
  out << " |\n|---";
  for (std::size_t k = 0; k < extra.size(); ++k) out << "|---:";
  for (std::size_t k = 0; k < methods.size(); ++k) out << "|:---:";
  out << "|\n";
}

void breakdown_cells(std::ostream& out, const std::vector<Outcome>& outcomes) {
  for (const Outcome& o : outcomes)
    out << " | " << o.false_positives << " / " << o.false_negatives << " / " << o.late;
  out << " |\n";
}

}  // namespace

void study_markdown(std::ostream& out, const std::vector<DatasetResults>& results,
                    const std::vector<Method>& methods, double min_separation) {
  if (min_separation > 0.0)
    out << "minimum separation: " << shortest_text(min_separation)
        << " (a query collides when its primitives come within this Euclidean distance; "
           "float_only: the common practice with eps = D; tolerance: distance <= D + eps at a "
           "cubic root; filtered and exact: min_separation = D; verdicts and exact TOIs: the "
           "exact path at D)\n\n";
  for (const DatasetResults& r : results) {
    const Dataset& d = *r.dataset;
    out << "### " << markdown_escape(d.name) << "\n\n"
        << d.size() << " queries, " << d.contacts() << " with contact; `" << d.path
        << "`; verdicts: " << d.truth_source << "; exact TOIs: " << d.toi_source << ".\n\n";
    summary_markdown(out, r.total, methods);
    out << '\n';
    if (!d.suite) continue;
    out << "#### " << markdown_escape(d.name)
        << " per coordinate scale and translation (false positives / false negatives / late "
           "TOIs)\n\n";
    breakdown_header(out, "variant", {"queries", "contacts"}, methods);
    for (const auto& [key, outcomes] : r.by_scale) {
      const auto& counts = r.scale_counts.at(key);
      out << "| " << key.label() << " | " << counts.first << " | " << counts.second;
      breakdown_cells(out, outcomes);
    }
    out << "\n#### " << markdown_escape(d.name)
        << " per base family, all scales and translations together (false positives / false "
           "negatives / late TOIs)\n\n";
    breakdown_header(out, "base family", {"type", "queries", "contacts"}, methods);
    for (const std::string& base : r.bases) {
      const auto& counts = r.base_counts.at(base);
      out << "| " << markdown_escape(base) << " | " << r.base_type.at(base) << " | "
          << counts.first << " | " << counts.second;
      breakdown_cells(out, r.by_base.at(base));
    }
    out << "\n#### " << markdown_escape(d.name)
        << " per family (false positives / false negatives / late TOIs)\n\n";
    breakdown_header(out, "family", {"type", "queries", "contacts"}, methods);
    for (std::size_t k = 0; k < d.groups.size(); ++k) {
      const Group& g = d.groups[k];
      out << "| " << markdown_escape(g.name) << " | " << g.type_name << " | " << g.size() << " | "
          << g.contacts();
      breakdown_cells(out, r.by_group[k]);
    }
    out << '\n';
  }
}

}  // namespace exactccd::study
