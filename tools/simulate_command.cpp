#include "simulate_command.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <stdexcept>

#include "check.hpp"
#include "cli_common.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::cli {

namespace fs = std::filesystem;

std::vector<std::uint8_t> exact_truth(const std::vector<sim::SimulationQuery>& queries) {
  std::vector<std::uint8_t> truth(queries.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const sim::SimulationQuery& q = queries[i];
                        const RationalQuery exact =
                            q.type == QueryType::vertex_face
                                ? to_rational(vertex_face_query(q.points))
                                : to_rational(edge_edge_query(q.points));
                        truth[i] = exact_ccd(exact).collides ? 1 : 0;
                      }
                    });
  return truth;
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Removes data_K.csv files a previous run left in `dir`, so that the folder holds exactly the
// new set.
void remove_old_data_files(const fs::path& dir) {
  static const std::regex data_file("data_[0-9]+\\.csv");
  std::error_code error;
  if (!fs::is_directory(dir, error)) return;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), data_file))
      stale.push_back(entry.path());
  for (const fs::path& p : stale) fs::remove(p);
}

struct FileChunk {
  fs::path path;
  std::vector<std::size_t> indices;  // into the query list
};

void write_chunk(const FileChunk& chunk, const std::vector<sim::SimulationQuery>& queries,
                 const std::vector<std::uint8_t>& truth) {
  std::string text;
  text.reserve(chunk.indices.size() * 8 * 128);
  for (const std::size_t i : chunk.indices)
    append_query_rows(text, queries[i].points, truth[i] != 0);
  std::ofstream out(chunk.path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw UsageError(chunk.path.string() + ": write failed");
}

}  // namespace

int run_simulate(const SimulateOptions& options) {
  try {
    sim::validate(options.config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const fs::path root = fs::path(options.out_dir) / "simulation";
  const fs::path folders[2] = {root / "vertex-face", root / "edge-edge"};
  for (const fs::path& folder : folders) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error || !fs::is_directory(folder))
      throw UsageError(folder.string() + ": cannot create the folder (--out)");
  }

  const auto generation_start = std::chrono::steady_clock::now();
  const std::vector<sim::SimulationQuery> queries =
      sim::generate_simulation_queries(options.config);
  const double generation_seconds = seconds_since(generation_start);

  const auto truth_start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> truth =
      options.exact_truth ? exact_truth(queries) : std::vector<std::uint8_t>(queries.size(), 0);
  const double truth_seconds = seconds_since(truth_start);

  // Files: each type's queries in generation order, kQueriesPerFile to a file.
  std::vector<FileChunk> chunks;
  for (const QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    const fs::path& folder = folders[type == QueryType::vertex_face ? 0 : 1];
    remove_old_data_files(folder);
    std::size_t in_type = 0, file_index = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (queries[i].type != type) continue;
      if (in_type++ % kQueriesPerFile == 0)
        chunks.push_back({folder / ("data_" + std::to_string(file_index++) + ".csv"), {}});
      chunks.back().indices.push_back(i);
    }
  }
  const auto write_start = std::chrono::steady_clock::now();
  tbb::parallel_for(std::size_t{0}, chunks.size(),
                    [&](std::size_t k) { write_chunk(chunks[k], queries, truth); });
  const double write_seconds = seconds_since(write_start);

  // Counts by pair kind and type.
  constexpr int kKinds = 3;
  std::size_t count[kKinds][2] = {}, collide[kKinds][2] = {};
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const int k = static_cast<int>(queries[i].kind), t = static_cast<int>(queries[i].type);
    ++count[k][t];
    collide[k][t] += truth[i];
  }
  const sim::SimulationConfig& c = options.config;
  std::printf("simulation: sheet %dx%d, %d steps, seed %llu\n", c.sheet_resolution,
              c.sheet_resolution, c.steps, static_cast<unsigned long long>(c.seed));
  std::printf("generated %zu queries in %.2f s\n", queries.size(), generation_seconds);
  if (options.exact_truth)
    std::printf("truth from the exact path in %.2f s (%d threads)\n", truth_seconds,
                tbb::this_task_arena::max_concurrency());
  else
    std::printf("truth not computed (--truth none): truth column 0\n");
  std::printf("%-14s %-12s %10s %11s\n", "pairs", "type", "queries", "collisions");
  std::size_t total[2] = {}, total_collide[2] = {};
  auto row = [&](const char* kind, int t, std::size_t n, std::size_t hits) {
    char hits_text[32] = "-";
    if (options.exact_truth) std::snprintf(hits_text, sizeof hits_text, "%zu", hits);
    std::printf("%-14s %-12s %10zu %11s\n", kind,
                t < 0 ? "all" : to_string(static_cast<QueryType>(t)), n, hits_text);
  };
  for (int k = 0; k < kKinds; ++k)
    for (int t = 0; t < 2; ++t) {
      row(sim::to_string(static_cast<sim::PairKind>(k)), t, count[k][t], collide[k][t]);
      total[t] += count[k][t];
      total_collide[t] += collide[k][t];
    }
  for (int t = 0; t < 2; ++t) row("TOTAL", t, total[t], total_collide[t]);
  row("TOTAL", -1, total[0] + total[1], total_collide[0] + total_collide[1]);
  std::printf("wrote %zu files under %s in %.2f s\n", chunks.size(), root.string().c_str(),
              write_seconds);
  return kExitAgree;
}

}  // namespace exactccd::cli
