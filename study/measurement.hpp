// The study's measurement: each method on each group of a data set, single thread, judged
// against the exact answers (false positives, false negatives, late TOIs, TOI errors) and
// timed.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "study/datasets.hpp"
#include "study/labels.hpp"
#include "study/methods.hpp"

namespace exactccd::study {

/// Examples (file:index) listed per kind of error.
constexpr std::size_t kMaxExamples = 5;

/// One method's results on a set of queries; `add` merges sets.
struct Outcome {
  std::size_t queries = 0, collisions = 0, false_positives = 0, false_negatives = 0;
  std::size_t late = 0, true_positives = 0;
  std::vector<double> toi_errors;  // signed, over true positives with an exact TOI
  std::vector<double> late_errors;  // the toi errors of the late TOIs (>= 0)
  double total_ns = 0.0;           // mean ns per query times queries
  std::vector<std::string> fp_examples, fn_examples, late_examples;

  void add(const Outcome& o) {
    queries += o.queries;
    collisions += o.collisions;
    false_positives += o.false_positives;
    false_negatives += o.false_negatives;
    late += o.late;
    true_positives += o.true_positives;
    toi_errors.insert(toi_errors.end(), o.toi_errors.begin(), o.toi_errors.end());
    late_errors.insert(late_errors.end(), o.late_errors.begin(), o.late_errors.end());
    total_ns += o.total_ns;
    for (auto [to, from] : {std::pair{&fp_examples, &o.fp_examples},
                            std::pair{&fn_examples, &o.fn_examples},
                            std::pair{&late_examples, &o.late_examples}})
      for (const std::string& e : *from)
        if (to->size() < kMaxExamples) to->push_back(e);
  }
  double mean_ns() const { return queries == 0 ? 0.0 : total_ns / static_cast<double>(queries); }
  bool clean() const { return false_positives == 0 && false_negatives == 0 && late == 0; }
};

/// Shortest timed sample: small groups are passed over several times per clock reading pair, so
/// that the clock's own cost (tens of ns) stays below about 0.1% of a sample.
constexpr double kMinSampleNs = 200e3;

/// The signed TOI error of a reported toi against the exact pair [lo, hi]: 0 inside it, else the
/// distance to the nearer end (positive: later). Resolution one ulp: a toi equal to hi > lo is
/// late (t* < hi) with error 0.
double toi_error(double toi, const Reference& ref);

/// The median (the mean of the two middle values for an even count); 0 when empty.
double median_of(std::vector<double> values);

/// A breakdown key of a suite's families: coordinate scale and translation.
struct ScaleKey {
  double offset = 0.0, scale = 1.0;
  bool operator<(const ScaleKey& k) const {
    return offset != k.offset ? offset < k.offset : scale < k.scale;
  }
  std::string label() const {
    if (offset == 0.0) return "scale " + short_number(scale);
    return "offset " + short_number(offset) + (scale == 1.0 ? "" : " scale " + short_number(scale));
  }
};

/// Results of one data set: per group and method, and the merged views.
struct DatasetResults {
  const Dataset* dataset = nullptr;
  std::vector<std::vector<Outcome>> by_group;  // [group][method]
  std::vector<Outcome> total;                  // [method]
  std::map<ScaleKey, std::vector<Outcome>> by_scale;
  std::map<ScaleKey, std::pair<std::size_t, std::size_t>> scale_counts;  // queries, contacts
  // Per base family (a family and its scaled / translated variants), in manifest order.
  std::vector<std::string> bases;
  std::map<std::string, std::vector<Outcome>> by_base;
  std::map<std::string, std::pair<std::size_t, std::size_t>> base_counts;
  std::map<std::string, std::string> base_type;
};

/// Measures every method on every group of `d` (`repetitions` timed samples each), with
/// progress on a terminal.
DatasetResults run_dataset(const Dataset& d, const std::vector<Method>& methods, int repetitions);

}  // namespace exactccd::study
