// Mean time per query of the exact path on the shipped sample queries, by query type.
//   ./build/bench/exact_path_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// The "per_query" counter is seconds per query (shown in the time unit of the table).
#include <benchmark/benchmark.h>

#include <vector>

#include "exactccd/query_file.hpp"

namespace {

std::vector<exactccd::RationalQuery> sample_queries(exactccd::QueryType type) {
  std::vector<exactccd::RationalQuery> out;
  for (const auto& path : exactccd::find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
    if (exactccd::query_type_from_path(path) != type) continue;
    for (auto& record : exactccd::read_query_file(path, type).queries)
      out.push_back(std::move(record.query));
  }
  return out;
}

void decide_all(benchmark::State& state, exactccd::QueryType type) {
  const auto queries = sample_queries(type);
  std::size_t collisions = 0;
  for (auto _ : state) {
    collisions = 0;
    for (const auto& q : queries) collisions += exactccd::exact_ccd(q).collides;
    benchmark::DoNotOptimize(collisions);
  }
  state.counters["queries"] = static_cast<double>(queries.size());
  state.counters["collisions"] = static_cast<double>(collisions);
  state.counters["per_query"] = benchmark::Counter(
      static_cast<double>(queries.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(decide_all, vertex_face, exactccd::QueryType::vertex_face)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, edge_edge, exactccd::QueryType::edge_edge)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
