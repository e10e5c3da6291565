#include "simulate_command.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"
#include "oracle/common.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/output_file.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

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

// The data_K.csv files in `dir` (none when it does not exist), sorted.
std::vector<fs::path> data_files_in(const fs::path& dir) {
  static const std::regex data_file("data_[0-9]+\\.csv");
  std::vector<fs::path> found;
  std::error_code error;
  if (!fs::is_directory(dir, error)) return found;
  for (fs::directory_iterator it(dir, error); !error && it != fs::directory_iterator();
       it.increment(error))
    if (std::regex_match(it->path().filename().string(), data_file)) found.push_back(it->path());
  if (error) throw OutputError(dir.string(), "cannot list the folder: " + error.message());
  std::sort(found.begin(), found.end());
  return found;
}

struct FileChunk {
  fs::path path;
  std::vector<std::size_t> indices;  // into the query list
};

void write_chunk(const FileChunk& chunk, const std::vector<sim::SimulationQuery>& queries,
                 const std::vector<std::uint8_t>& truth, Overwrite overwrite) {
  std::string text;
  text.reserve(chunk.indices.size() * 8 * 128);
  for (const std::size_t i : chunk.indices)
    append_query_rows(text, queries[i].points, truth[i] != 0);
  write_file_atomically(chunk.path.string(), text, overwrite, "--out");
}

}  // namespace

int run_simulate(const SimulateOptions& options) {
  try {
    sim::validate(options.config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (options.out_dir.empty()) throw UsageError("--out: the folder name is empty");
  const fs::path root = fs::path(options.out_dir) / "simulation";
  const fs::path folders[2] = {root / "vertex-face", root / "edge-edge"};
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  for (const fs::path& folder : folders) {  // refuse before the work, not after it
    const std::vector<fs::path> earlier = data_files_in(folder);
    if (!earlier.empty() && overwrite == Overwrite::refuse)
      throw OutputError(earlier.front().string(),
                        "exists (an earlier run's output); pass --force to replace it (--out)");
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw OutputError(folder.string(), "cannot create the folder: " + error.message());
    if (!fs::is_directory(folder, error))
      throw OutputError(folder.string(), "cannot create the folder: not a directory");
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
                    [&](std::size_t k) { write_chunk(chunks[k], queries, truth, overwrite); });
  const double write_seconds = seconds_since(write_start);
  // An earlier, larger run's files beyond this run's: kept (never deleted), but named.
  std::vector<std::string> left;
  for (const fs::path& folder : folders)
    for (const fs::path& file : data_files_in(folder))
      if (std::none_of(chunks.begin(), chunks.end(),
                       [&](const FileChunk& c) { return c.path == file; }))
        left.push_back(file.string());
  warn_files_left_in_place(left, root.string());

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
