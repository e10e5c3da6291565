// Time per query of each mode (float_only, default, exact) through the public double API, on
// the simulation-like set (small config, corpus/simulation_queries.hpp) and on the shipped sample queries.
//   ./build/bench/ccd_micro_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// The "per_query" counter is seconds per query (shown in the time unit of the table).
//
// Stage cost (stage/...): the queries of a data set that the default path decides in one stage
// (exact_at_double, filter_exact_toi), timed alone in default and in float_only mode: the cost
// of that stage's queries, and what the uncertified test costs on the same queries. Data sets:
// the full simulation-like set (as `exactccd bench --simulation`), the sample queries, the
// scene queries and the degenerate suite.
//   ./build/bench/ccd_micro_bench --benchmark_filter=stage/ --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "corpus/simulation_queries.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"

namespace {

using exactccd::CcdOptions;
using exactccd::Mode;

struct QuerySet {
  std::vector<exactccd::VertexFaceQuery> vertex_face;
  std::vector<exactccd::EdgeEdgeQuery> edge_edge;
  std::size_t size() const { return vertex_face.size() + edge_edge.size(); }
};

void add(QuerySet& set, exactccd::QueryType type, const std::array<Eigen::Vector3d, 8>& p) {
  if (type == exactccd::QueryType::vertex_face)
    set.vertex_face.push_back({p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]});
  else
    set.edge_edge.push_back({p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]});
}

const QuerySet& simulation_set() {
  static const QuerySet set = [] {
    QuerySet s;
    for (const auto& q :
         exactccd::sim::generate_simulation_queries(exactccd::sim::small_simulation_config()))
      add(s, q.type, q.points);
    return s;
  }();
  return set;
}

/// Every query of the benchmark CSV files under `path` (coordinates must be doubles).
QuerySet load_set(const std::string& path) {
  QuerySet s;
  for (const auto& file : exactccd::find_query_files(path)) {
    const auto type = exactccd::query_type_from_path(file);
    if (!type) continue;
    for (const auto& record : exactccd::read_query_file(file, *type).queries) {
      std::array<Eigen::Vector3d, 8> p;
      for (int row = 0; row < 8; ++row) {
        const auto& r = record.query.points[row];
        double x, y, z;
        if (!exactccd::exact::to_double_exactly(r.x, &x) ||
            !exactccd::exact::to_double_exactly(r.y, &y) ||
            !exactccd::exact::to_double_exactly(r.z, &z))
          throw std::runtime_error(file + ": a coordinate is not a double");
        p[row] = {x, y, z};
      }
      add(s, *type, p);
    }
  }
  return s;
}

/// A data set next to the sample queries (tests/data/<name>).
std::string data_set_path(const char* name) {
  const std::string sample = EXACTCCD_SAMPLE_QUERIES;
  return sample.substr(0, sample.rfind('/') + 1) + name;
}

const QuerySet& sample_set() {
  static const QuerySet set = load_set(EXACTCCD_SAMPLE_QUERIES);
  return set;
}

const QuerySet& scene_set() {
  static const QuerySet set = load_set(data_set_path("scene-queries"));
  return set;
}

const QuerySet& degenerate_suite_set() {
  static const QuerySet set = load_set(data_set_path("degenerate-suite"));
  return set;
}

/// The full simulation-like set (exactccd bench --simulation).
const QuerySet& full_simulation_set() {
  static const QuerySet set = [] {
    QuerySet s;
    for (const auto& q : exactccd::sim::generate_simulation_queries({}))
      add(s, q.type, q.points);
    return s;
  }();
  return set;
}

/// The queries of `set` that the default path decides in `stage`.
const QuerySet& decided_in(const QuerySet& (*set)(), exactccd::Stage stage) {
  static std::map<std::pair<const QuerySet& (*)(), exactccd::Stage>, QuerySet> subsets;
  const auto key = std::make_pair(set, stage);
  if (const auto it = subsets.find(key); it != subsets.end()) return it->second;
  QuerySet& out = subsets[key];
  const CcdOptions options;
  for (const auto& q : set().vertex_face)
    if (exactccd::vertex_face_ccd(q, options).decided_by == stage) out.vertex_face.push_back(q);
  for (const auto& q : set().edge_edge)
    if (exactccd::edge_edge_ccd(q, options).decided_by == stage) out.edge_edge.push_back(q);
  return out;
}

/// Decides every query of `set` per iteration; counters: queries, collisions, time per query.
void time_set(benchmark::State& state, const QuerySet& set, Mode mode) {
  CcdOptions options;
  options.mode = mode;
  std::size_t collisions = 0;
  for (auto _ : state) {
    collisions = 0;
    for (const auto& q : set.vertex_face)
      collisions += exactccd::vertex_face_ccd(q, options).collides;
    for (const auto& q : set.edge_edge) collisions += exactccd::edge_edge_ccd(q, options).collides;
    benchmark::DoNotOptimize(collisions);
  }
  state.counters["queries"] = static_cast<double>(set.size());
  state.counters["collisions"] = static_cast<double>(collisions);
  state.counters["per_query"] = benchmark::Counter(
      static_cast<double>(set.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void decide_all(benchmark::State& state, const QuerySet& (*queries)(), Mode mode) {
  time_set(state, queries(), mode);
}

BENCHMARK_CAPTURE(decide_all, simulation_float_only, simulation_set, Mode::float_only)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, simulation_default, simulation_set, Mode::filtered)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, simulation_exact, simulation_set, Mode::exact)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, sample_float_only, sample_set, Mode::float_only)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, sample_default, sample_set, Mode::filtered)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, sample_exact, sample_set, Mode::exact)
    ->Unit(benchmark::kMillisecond);

void decide_stage(benchmark::State& state, const QuerySet& (*queries)(), exactccd::Stage stage,
                  Mode mode) {
  time_set(state, decided_in(queries, stage), mode);
}

#define EXACTCCD_STAGE_BENCH(SET, STAGE)                                                    \
  BENCHMARK_CAPTURE(decide_stage, stage/SET/STAGE/default, SET##_set,                       \
                    exactccd::Stage::STAGE, Mode::filtered)                                 \
      ->Unit(benchmark::kMicrosecond);                                                      \
  BENCHMARK_CAPTURE(decide_stage, stage/SET/STAGE/float_only, SET##_set,                    \
                    exactccd::Stage::STAGE, Mode::float_only)                               \
      ->Unit(benchmark::kMicrosecond)

EXACTCCD_STAGE_BENCH(full_simulation, exact_at_double);
EXACTCCD_STAGE_BENCH(full_simulation, filter_exact_toi);
EXACTCCD_STAGE_BENCH(sample, exact_at_double);
EXACTCCD_STAGE_BENCH(sample, filter_exact_toi);
EXACTCCD_STAGE_BENCH(scene, exact_at_double);
EXACTCCD_STAGE_BENCH(scene, filter_exact_toi);
EXACTCCD_STAGE_BENCH(degenerate_suite, exact_at_double);
EXACTCCD_STAGE_BENCH(degenerate_suite, filter_exact_toi);
// The other stages, for the whole picture of where a data set's mean goes: queries the interval
// filters decide alone, and those left to the exact path.
EXACTCCD_STAGE_BENCH(full_simulation, filter);
EXACTCCD_STAGE_BENCH(full_simulation, exact);
EXACTCCD_STAGE_BENCH(sample, filter);
EXACTCCD_STAGE_BENCH(sample, exact);
EXACTCCD_STAGE_BENCH(scene, filter);
EXACTCCD_STAGE_BENCH(scene, exact);

}  // namespace

BENCHMARK_MAIN();
