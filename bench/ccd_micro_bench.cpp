// Time per query of each mode (float_only, default, exact) through the public double API, on
// the simulation-like set (small config, bench/simulation) and on the shipped sample queries.
//   ./build/bench/ccd_micro_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// The "per_query" counter is seconds per query (shown in the time unit of the table).
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <vector>

#include "exact/rational.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "simulation_queries.hpp"

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

const QuerySet& sample_set() {
  static const QuerySet set = [] {
    QuerySet s;
    for (const auto& path : exactccd::find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
      const auto type = exactccd::query_type_from_path(path);
      if (!type) continue;
      for (const auto& record : exactccd::read_query_file(path, *type).queries) {
        std::array<Eigen::Vector3d, 8> p;
        for (int row = 0; row < 8; ++row) {
          const auto& r = record.query.points[row];
          double x, y, z;
          if (!exactccd::exact::to_double_exactly(r.x, &x) ||
              !exactccd::exact::to_double_exactly(r.y, &y) ||
              !exactccd::exact::to_double_exactly(r.z, &z))
            throw std::runtime_error(path + ": a coordinate is not a double");
          p[row] = {x, y, z};
        }
        add(s, *type, p);
      }
    }
    return s;
  }();
  return set;
}

void decide_all(benchmark::State& state, const QuerySet& (*queries)(), Mode mode) {
  const QuerySet& set = queries();
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

}  // namespace

BENCHMARK_MAIN();
