#include "study/measurement.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "oracle/progress.hpp"

namespace exactccd::study {

double toi_error(double toi, const Reference& ref) {
  if (toi < ref.lo) return toi - ref.lo;
  if (toi > ref.hi) return toi - ref.hi;
  return 0.0;
}

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  return 0.5 * (*std::max_element(values.begin(), values.begin() + mid) + upper);
}

namespace {

using Clock = std::chrono::steady_clock;

void judge(const CcdResult& r, const Reference& ref, Outcome& o, const Dataset& d,
           const Origin& origin) {
  auto where = [&] { return d.files[origin.file] + ":" + std::to_string(origin.index); };
  ++o.queries;
  o.collisions += r.collides;
  if (r.collides && !ref.collides) {
    if (o.false_positives++ < kMaxExamples) o.fp_examples.push_back(where());
  } else if (!r.collides && ref.collides) {
    if (o.false_negatives++ < kMaxExamples) o.fn_examples.push_back(where());
  } else if (r.collides) {
    ++o.true_positives;
    if (!ref.has_toi) return;
    // A conservative method reports toi_lo <= t*; for a double, toi <= t* iff toi <= lo.
    const double error = toi_error(r.toi_lo, ref);
    o.toi_errors.push_back(error);
    if (r.toi_lo > ref.lo) {
      o.late_errors.push_back(error);
      if (o.late++ < kMaxExamples) o.late_examples.push_back(where());
    }
  }
}

double nanoseconds(Clock::duration d) {
  return static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(d).count());
}

volatile std::size_t g_sink;  // keeps the timed passes' results observable

// One untimed pass for the verdicts, then `repetitions` timed samples of whole passes (single
// thread, one clock reading pair per sample); mean time: the median sample / queries.
Outcome measure(const Dataset& d, const Group& g, const Method& m, int repetitions) {
  return with_method(m, [&](auto&& decide_vertex_face, auto&& decide_edge_edge) {
    Outcome o;
    const auto verdict_start = Clock::now();
    for (std::size_t i = 0; i < g.vertex_face.size(); ++i)
      judge(decide_vertex_face(g.vertex_face[i]), g.vertex_face_ref[i], o, d,
            g.vertex_face_origin[i]);
    for (std::size_t i = 0; i < g.edge_edge.size(); ++i)
      judge(decide_edge_edge(g.edge_edge[i]), g.edge_edge_ref[i], o, d, g.edge_edge_origin[i]);
    const double first_pass_ns = nanoseconds(Clock::now() - verdict_start);
    if (g.size() == 0) return o;

    const int passes =
        static_cast<int>(std::max(1.0, std::ceil(kMinSampleNs / std::max(first_pass_ns, 1.0))));
    std::vector<double> samples;
    for (int rep = 0; rep < repetitions; ++rep) {
      std::size_t collisions = 0;
      const auto start = Clock::now();
      for (int pass = 0; pass < passes; ++pass) {
        for (const VertexFaceQuery& q : g.vertex_face) collisions += decide_vertex_face(q).collides;
        for (const EdgeEdgeQuery& q : g.edge_edge) collisions += decide_edge_edge(q).collides;
      }
      const auto stop = Clock::now();
      g_sink = collisions;
      samples.push_back(nanoseconds(stop - start) / (static_cast<double>(passes) * g.size()));
    }
    o.total_ns = median_of(samples) * static_cast<double>(g.size());
    return o;
  });
}

}  // namespace

DatasetResults run_dataset(const Dataset& d, const std::vector<Method>& methods,
                           int repetitions) {
  DatasetResults r;
  r.dataset = &d;
  r.total.assign(methods.size(), Outcome{});
  oracle::Progress progress;
  for (std::size_t k = 0; k < d.groups.size(); ++k) {
    const Group& g = d.groups[k];
    std::vector<Outcome> outcomes;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      progress.update(k, d.groups.size(), d.name + " " + g.name + " " + methods[m].label(), m,
                      methods.size());
      outcomes.push_back(measure(d, g, methods[m], repetitions));
      r.total[m].add(outcomes.back());
    }
    if (d.suite) {
      const ScaleKey key{g.offset, g.scale};
      auto& merged = r.by_scale[key];
      if (merged.empty()) merged.assign(methods.size(), Outcome{});
      for (std::size_t m = 0; m < methods.size(); ++m) merged[m].add(outcomes[m]);
      r.scale_counts[key].first += g.size();
      r.scale_counts[key].second += g.contacts();
      auto& base = r.by_base[g.base];
      if (base.empty()) {
        base.assign(methods.size(), Outcome{});
        r.bases.push_back(g.base);
        r.base_type[g.base] = g.type_name;
      }
      for (std::size_t m = 0; m < methods.size(); ++m) base[m].add(outcomes[m]);
      r.base_counts[g.base].first += g.size();
      r.base_counts[g.base].second += g.contacts();
    }
    r.by_group.push_back(std::move(outcomes));
  }
  return r;
}

}  // namespace exactccd::study
