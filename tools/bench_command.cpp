#include "bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <tbb/parallel_for.h>

#include "bench_timing.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "oracle/check.hpp"
#include "oracle/common.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/names.hpp"
#include "simulate_command.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

namespace {

// The queries of one data set as the double API takes them, with their truth.
struct Dataset {
  std::string label;
  std::string truth_source;  // "truth column" or "exact path"
  std::vector<VertexFaceQuery> vertex_face;
  std::vector<std::uint8_t> vertex_face_truth;
  std::vector<EdgeEdgeQuery> edge_edge;
  std::vector<std::uint8_t> edge_edge_truth;
  std::vector<PointPlaneQuery> point_plane;  ///< files of --type pl
  std::vector<std::uint8_t> point_plane_truth;

  std::size_t size() const { return vertex_face.size() + edge_edge.size() + point_plane.size(); }
  /// Query k of the data set in that order (vertex-face, edge-edge, point-plane), decided.
  CcdResult decide(std::size_t k, const CcdOptions& options) const {
    if (k < vertex_face.size()) return vertex_face_ccd(vertex_face[k], options);
    k -= vertex_face.size();
    if (k < edge_edge.size()) return edge_edge_ccd(edge_edge[k], options);
    return point_plane_ccd(point_plane[k - edge_edge.size()], options);
  }
  /// Query k's truth column.
  bool truth(std::size_t k) const {
    if (k < vertex_face.size()) return vertex_face_truth[k];
    k -= vertex_face.size();
    if (k < edge_edge.size()) return edge_edge_truth[k];
    return point_plane_truth[k - edge_edge.size()];
  }
};

/// A point-plane file's queries as doubles (bench times the double API).
void load_point_plane(const std::string& file, Dataset& d) {
  const PrimitiveQueryFile input = read_primitive_query_file(file, PrimitiveKind::point_plane);
  for (const PrimitiveQueryRecord& r : input.queries) {
    Eigen::Vector3d x[6];
    for (std::size_t k = 0; k < 6; ++k)
      if (!exact::to_double_exactly(r.points[k].x, &x[k].x()) ||
          !exact::to_double_exactly(r.points[k].y, &x[k].y()) ||
          !exact::to_double_exactly(r.points[k].z, &x[k].z()))
        throw InputError(file, r.first_line + k,
                         "a coordinate is not exactly a double: point-plane queries are "
                         "decided on doubles only");
    if (x[2].isZero(0) || x[5].isZero(0))
      throw InputError(file, r.first_line, "a zero normal: no plane");
    d.point_plane.push_back({x[0], x[1], x[2], x[3], x[4], x[5]});
    d.point_plane_truth.push_back(r.truth);
  }
}

Dataset load_path(const std::string& path, const std::optional<QueryType>& type,
                  const std::optional<PrimitiveKind>& primitive) {
  Dataset d;
  d.label = path;
  d.truth_source = "truth column";
  if (primitive) require_regular_file(path, std::string("a query file of --type ") +
                                                to_string(*primitive));
  const std::vector<std::string> files =
      primitive ? std::vector<std::string>{path} : find_query_files(path);
  std::vector<std::string> empty_files;
  if (primitive == PrimitiveKind::point_plane) {
    load_point_plane(path, d);
    if (d.point_plane.empty()) empty_files.push_back(path);
    require_some_queries(empty_files, files.size(), d.size());
    return d;
  }
  for (const std::string& file : files) {
    const QueryFile input =
        primitive ? as_edge_edge_file(read_primitive_query_file(file, *primitive))
                  : read_query_file(file, resolve_query_type(file, type));
    if (input.queries.empty()) empty_files.push_back(file);
    for (const QueryRecord& record : input.queries) {
      std::size_t bad_row = 0;
      const std::optional<QueryPoints> points = exact_doubles(record.query, &bad_row);
      if (!points)
        throw InputError(file, record.line_of_row(bad_row),
                         "a coordinate is not exactly a double: bench times the double API "
                         "(check --mode exact decides such queries)");
      if (input.type == QueryType::vertex_face) {
        d.vertex_face.push_back(vertex_face_query(*points));
        d.vertex_face_truth.push_back(record.truth);
      } else {
        d.edge_edge.push_back(edge_edge_query(*points));
        d.edge_edge_truth.push_back(record.truth);
      }
    }
  }
  require_some_queries(empty_files, files.size(), d.size());
  return d;
}

Dataset simulation_dataset(const sim::SimulationConfig& config, double* truth_seconds) {
  std::vector<sim::SimulationQuery> queries;
  try {
    queries = sim::generate_simulation_queries(config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const auto start = Clock::now();
  const std::vector<std::uint8_t> truth = exact_truth(queries);
  *truth_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  Dataset d;
  d.label = "simulation";
  d.truth_source = "exact path";
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (queries[i].type == QueryType::vertex_face) {
      d.vertex_face.push_back(vertex_face_query(queries[i].points));
      d.vertex_face_truth.push_back(truth[i]);
    } else {
      d.edge_edge.push_back(edge_edge_query(queries[i].points));
      d.edge_edge_truth.push_back(truth[i]);
    }
  }
  return d;
}

volatile std::size_t g_sink;  // keeps the batch passes' results observable

/// max_ns: the kWorstCandidates slowest single calls are each repeated kWorstRetimes times.
constexpr std::size_t kWorstCandidates = 16;
constexpr int kWorstRetimes = 2;

/// A data set's answers from the exact path at one minimum separation delta > 0: the truth
/// for that delta (a file's truth column is for contact), and the TOIs the errors are
/// measured against.
struct ExactAnswers {
  std::vector<CcdResult> answers;  ///< in the data set's query order (Dataset::decide)
};

ExactAnswers exact_answers(const Dataset& d, double delta) {
  CcdOptions options;
  options.mode = Mode::exact;
  options.min_separation = delta;
  ExactAnswers a;
  a.answers.resize(d.size());
  tbb::parallel_for(std::size_t{0}, d.size(),
                    [&](std::size_t k) { a.answers[k] = d.decide(k, options); });
  return a;
}

/// The diagonal of the box of every coordinate of the data set (its "scene size").
double dataset_size(const Dataset& d) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  auto add = [&](const Eigen::Vector3d& x) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  };
  for (const VertexFaceQuery& q : d.vertex_face)
    for (const auto* x : {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1})
      add(*x);
  for (const EdgeEdgeQuery& q : d.edge_edge)
    for (const auto* x : {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1,
                          &q.eb0_t1, &q.eb1_t1})
      add(*x);
  for (const PointPlaneQuery& q : d.point_plane)  // the points and the planes' origins
    for (const auto* x : {&q.p_t0, &q.origin_t0, &q.p_t1, &q.origin_t1}) add(*x);
  return d.size() == 0 ? 0.0 : (hi - lo).norm();
}

struct Measurement {
  std::string dataset;
  Mode mode = Mode::filtered;
  double delta = 0.0;  // the minimum separation of the run (0: contact)
  double size = 0.0;  // the data set's size (box diagonal), which a relative delta multiplies
  double factor = -1.0;  // delta / size as given with --relative-separation; -1: delta absolute
  // Against the exact path's TOIs (delta > 0 only): contacts both report whose toi_lo lies
  // after the exact toi_hi (not conservative), and the largest |toi_lo - exact toi_lo|.
  bool toi_checked = false;
  std::size_t late_tois = 0;
  double max_toi_error = 0.0;
  CheckTally tally;  // verdicts against the truth and deciding stages, as `check` counts them
  double mean_ns = 0.0, median_ns = 0.0;
  double max_ns = 0.0;  // the slowest query: its fastest of kWorstRetimes + 1 single calls
};

Measurement measure(const Dataset& d, Mode mode, double delta, const ExactAnswers* exact,
                    int repetitions, double overhead_ns) {
  CcdOptions options;
  options.mode = mode;
  options.min_separation = delta;
  Measurement m;
  m.dataset = d.label;
  m.mode = mode;
  m.delta = delta;
  m.toi_checked = exact != nullptr;
  auto compare_toi = [&m](const CcdResult& r, const CcdResult& e) {
    if (!r.collides || !e.collides) return;
    m.late_tois += r.toi_lo > e.toi_hi;
    m.max_toi_error = std::max(m.max_toi_error, std::abs(r.toi_lo - e.toi_lo));
  };

  // One pass timing each query on its own; it also gives the verdicts.
  std::vector<double> per_query;
  per_query.reserve(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto start = Clock::now();
    const CcdResult r = d.decide(i, options);
    const auto stop = Clock::now();
    per_query.push_back(nanoseconds(stop - start));
    if (exact) {
      count_query(m.tally, r, exact->answers[i].collides);
      compare_toi(r, exact->answers[i]);
    } else {
      count_query(m.tally, r, d.truth(i));
    }
  }
  // The slowest queries timed again, each keeping its fastest call: one interrupt or page fault
  // during a single call must not pass for the query's cost.
  std::vector<std::size_t> order(per_query.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const std::size_t slow = std::min(kWorstCandidates, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(slow), order.end(),
                    [&](std::size_t a, std::size_t b) { return per_query[a] > per_query[b]; });
  for (std::size_t k = 0; k < slow; ++k) {
    const std::size_t i = order[k];
    double best = per_query[i];
    for (int again = 0; again < kWorstRetimes; ++again) {
      const auto start = Clock::now();
      const bool collides = d.decide(i, options).collides;
      const auto stop = Clock::now();
      g_sink = collides;
      best = std::min(best, nanoseconds(stop - start));
    }
    m.max_ns = std::max(m.max_ns, best - overhead_ns);
  }
  m.median_ns = median(per_query) - overhead_ns;

  // Batch passes: one clock reading around all queries, so no timer cost per query.
  std::vector<double> per_pass;
  for (int rep = 0; rep < repetitions; ++rep) {
    std::size_t collisions = 0;
    const auto start = Clock::now();
    for (const VertexFaceQuery& q : d.vertex_face)
      collisions += vertex_face_ccd(q, options).collides;
    for (const EdgeEdgeQuery& q : d.edge_edge) collisions += edge_edge_ccd(q, options).collides;
    for (const PointPlaneQuery& q : d.point_plane)
      collisions += point_plane_ccd(q, options).collides;
    const auto stop = Clock::now();
    g_sink = collisions;
    if (d.size() > 0) per_pass.push_back(nanoseconds(stop - start) / static_cast<double>(d.size()));
  }
  m.mean_ns = median(per_pass);
  return m;
}

bool certified(Mode mode) { return mode != Mode::float_only; }

void print_table(const std::vector<Measurement>& results) {
  std::size_t width = 7;
  for (const Measurement& m : results) width = std::max(width, m.dataset.size());
  bool separation = false;
  for (const Measurement& m : results) separation = separation || m.delta > 0;
  std::printf("%-*s %-10s", static_cast<int>(width), "dataset", "mode");
  if (separation) std::printf(" %10s %8s %11s", "delta", "toi_late", "toi_err_max");
  std::printf(" %9s %10s %10s %9s %9s %10s", "queries", "mean_ns", "median_ns", "false_pos",
              "false_neg", "max_ns");
  const std::vector<Stage>& stages = all_stages();
  std::vector<int> widths;
  for (const Stage s : stages) {
    widths.push_back(std::max(8, static_cast<int>(std::char_traits<char>::length(to_string(s)))));
    std::printf(" %*s", widths.back(), to_string(s));
  }
  std::printf("\n");
  for (const Measurement& m : results) {
    std::printf("%-*s %-10s", static_cast<int>(width), m.dataset.c_str(), to_string(m.mode));
    if (separation && m.toi_checked)
      std::printf(" %10.3g %8zu %11.3g", m.delta, m.late_tois, m.max_toi_error);
    else if (separation)
      std::printf(" %10.3g %8s %11s", m.delta, "-", "-");
    std::printf(" %9zu %10.1f %10.1f %9zu %9zu %10.0f", m.tally.queries, m.mean_ns,
                m.median_ns, m.tally.false_positives, m.tally.false_negatives, m.max_ns);
    for (std::size_t k = 0; k < stages.size(); ++k)
      std::printf(" %*.2f%%", widths[k] - 1, 100.0 * m.tally.stage_share(stages[k]));
    std::printf("\n");
  }
}

void print_json(const std::vector<Measurement>& results, const std::vector<Dataset>& datasets,
                int repetitions, double overhead_ns) {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const Measurement& m : results) {
    nlohmann::ordered_json j;
    j["dataset"] = m.dataset;
    j["mode"] = to_string(m.mode);
    j["min_separation"] = m.delta;
    j["size"] = m.size;
    if (m.factor >= 0) j["min_separation_factor"] = m.factor;
    if (m.toi_checked) {
      j["late_tois"] = m.late_tois;
      j["max_toi_error"] = m.max_toi_error;
    }
    j["queries"] = m.tally.queries;
    j["mean_ns"] = m.mean_ns;
    j["median_ns"] = m.median_ns;
    j["max_ns"] = m.max_ns;
    j["false_positives"] = m.tally.false_positives;
    j["false_negatives"] = m.tally.false_negatives;
    nlohmann::ordered_json shares = nlohmann::ordered_json::object();
    nlohmann::ordered_json counts = nlohmann::ordered_json::object();
    for (const Stage s : all_stages()) {
      shares[to_string(s)] = m.tally.stage_share(s);
      counts[to_string(s)] = m.tally.stage_count(s);
    }
    j["stage_share"] = std::move(shares);
    j["stage_counts"] = std::move(counts);
    j["collisions"] = m.tally.collisions;
    for (const Dataset& d : datasets)
      if (d.label == m.dataset) j["truth"] = m.toi_checked ? "exact path" : d.truth_source;
    j["repetitions"] = repetitions;
    j["timer_overhead_ns"] = overhead_ns;
    all.push_back(std::move(j));
  }
  std::cout << all.dump(2) << '\n';
}

}  // namespace

int run_bench(const BenchOptions& options) {
  if (options.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  if (options.modes.empty()) throw UsageError("--modes names no mode");

  std::vector<Dataset> datasets;
  std::vector<std::string> notes;
  std::vector<std::string> paths = options.paths;
  if (paths.empty() && !options.simulation) paths.push_back(options.default_path);
  for (const std::string& path : paths)
    datasets.push_back(load_path(path, options.type, options.primitive));
  if (options.simulation) {
    double truth_seconds = 0.0;
    datasets.push_back(simulation_dataset(options.simulation_config, &truth_seconds));
    char note[256];
    const sim::SimulationConfig& c = options.simulation_config;
    std::snprintf(note, sizeof note,
                  "simulation: sheet %dx%d, %d steps, seed %llu; truth from the exact path "
                  "(parallel) in %.1f s",
                  c.sheet_resolution, c.sheet_resolution, c.steps,
                  static_cast<unsigned long long>(c.seed), truth_seconds);
    notes.push_back(note);
  }

  const double overhead_ns = timer_overhead_ns();
  std::vector<Measurement> results;
  for (const Dataset& d : datasets) {
    const double size = dataset_size(d);
    for (const double separation : options.min_separations) {
      const double delta = options.relative_separation ? separation * size : separation;
      validate_min_separation(delta);
      // delta > 0: the truth column (for contact) does not apply; the exact path's does.
      std::optional<ExactAnswers> exact;
      if (delta > 0) exact = exact_answers(d, delta);
      for (const Mode mode : options.modes) {
        results.push_back(measure(d, mode, delta, exact ? &*exact : nullptr, options.repetitions,
                                  overhead_ns));
        results.back().size = size;
        if (options.relative_separation) results.back().factor = separation;
      }
    }
    if (options.relative_separation) {
      char note[160];
      std::snprintf(note, sizeof note, "%s: size (box diagonal) %.6g; delta = factor x size",
                    d.label.c_str(), size);
      notes.push_back(note);
    }
  }

  if (options.json) {
    print_json(results, datasets, options.repetitions, overhead_ns);
  } else {
    std::printf(
        "single thread; mean_ns: median over %d passes of (pass time / queries); median_ns: "
        "median of single-query times minus the empty timed region (%.1f ns, median of "
        "100001 steady_clock pairs); max_ns: the slowest query (the %zu slowest single calls "
        "repeated %d times, each keeping its fastest)\n",
        options.repetitions, overhead_ns, kWorstCandidates, kWorstRetimes);
    for (const Dataset& d : datasets)
      if (d.point_plane.empty())
        std::printf("%s: %zu queries (%zu vertex-face, %zu edge-edge), truth: %s\n",
                    d.label.c_str(), d.size(), d.vertex_face.size(), d.edge_edge.size(),
                    d.truth_source.c_str());
      else
        std::printf("%s: %zu point-plane queries, truth: %s\n", d.label.c_str(), d.size(),
                    d.truth_source.c_str());
    for (const std::string& note : notes) std::printf("%s\n", note.c_str());
    std::printf("last columns: share of queries decided by each stage\n");
    if (std::any_of(results.begin(), results.end(), [](const Measurement& m) {
          return m.delta > 0;
        }))
      std::printf("delta > 0: truth and TOIs from the exact path at that delta; toi_late: "
                  "contacts whose toi_lo is after the exact toi_hi; toi_err_max: largest "
                  "|toi_lo - exact toi_lo|\n");
    print_table(results);
  }
  for (const Measurement& m : results)
    if (certified(m.mode) && m.tally.disagreements() > 0) return kExitDisagree;
  return kExitAgree;
}

}  // namespace exactccd::cli
