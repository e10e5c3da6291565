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

#include "corpus/barrier_steps.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/scene.hpp"
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

// ROOT/vertex-face and ROOT/edge-edge created; refused before any work when they hold an
// earlier run's data_K.csv files and `overwrite` is refuse.
void prepare_folders(const fs::path& root, Overwrite overwrite) {
  for (const fs::path& folder : {root / "vertex-face", root / "edge-edge"}) {
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
}

// Each type's queries in order, kQueriesPerFile to a file ROOT/<type>/data_K.csv, written in
// parallel; an earlier run's files beyond these are kept and named. Returns the file count.
std::size_t write_query_files(const fs::path& root, const std::vector<sim::SimulationQuery>& queries,
                              const std::vector<std::uint8_t>& truth, Overwrite overwrite) {
  const fs::path folders[2] = {root / "vertex-face", root / "edge-edge"};
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
  tbb::parallel_for(std::size_t{0}, chunks.size(),
                    [&](std::size_t k) { write_chunk(chunks[k], queries, truth, overwrite); });
  // An earlier, larger run's files beyond this run's: kept (never deleted), but named.
  std::vector<std::string> left;
  for (const fs::path& folder : folders)
    for (const fs::path& file : data_files_in(folder))
      if (std::none_of(chunks.begin(), chunks.end(),
                       [&](const FileChunk& c) { return c.path == file; }))
        left.push_back(file.string());
  warn_files_left_in_place(left, root.string());
  return chunks.size();
}

// `simulate --barrier-step NAME`: the candidates the scene's broad phase hands to the narrow
// phase in one barrier-method trial step (corpus/barrier_steps.hpp), as benchmark queries.
int run_simulate_barrier(const SimulateOptions& options) {
  if (options.out_dir.empty()) throw UsageError("--out: the folder name is empty");
  const std::vector<std::string>& names = corpus::barrier_step_names();
  if (std::find(names.begin(), names.end(), options.barrier_step) == names.end()) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw UsageError("--barrier-step: unknown step '" + options.barrier_step + "' (one of " +
                     list + ")");
  }
  if (!(options.barrier_scale > 0 && options.barrier_scale <= 1))
    throw UsageError("--barrier-scale must lie in (0, 1], got " +
                     format_double(options.barrier_scale));
  const fs::path root = fs::path(options.out_dir) / "barrier" / options.barrier_step;
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  prepare_folders(root, overwrite);

  const auto start = std::chrono::steady_clock::now();
  Scene scene = corpus::make_scene(corpus::barrier_step(options.barrier_step, options.barrier_scale));
  SceneOptions scene_options;
  scene_options.record_candidates = true;
  const SceneResult result = scene.find_contacts(scene_options);
  std::vector<sim::SimulationQuery> queries;
  queries.reserve(result.candidates.size());
  for (const ScenePair& pair : result.candidates) {
    sim::SimulationQuery q;
    q.type = pair.type;
    if (pair.type == QueryType::vertex_face) {
      const VertexFaceQuery v = scene.vertex_face_query(pair);
      q.points = {v.p_t0, v.a_t0, v.b_t0, v.c_t0, v.p_t1, v.a_t1, v.b_t1, v.c_t1};
    } else {
      const EdgeEdgeQuery e = scene.edge_edge_query(pair);
      q.points = {e.ea0_t0, e.ea1_t0, e.eb0_t0, e.eb1_t0, e.ea0_t1, e.ea1_t1, e.eb0_t1, e.eb1_t1};
    }
    queries.push_back(q);
  }
  const double scene_seconds = seconds_since(start);
  const auto truth_start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> truth =
      options.exact_truth ? exact_truth(queries) : std::vector<std::uint8_t>(queries.size(), 0);
  const double truth_seconds = seconds_since(truth_start);
  const std::size_t files = write_query_files(root, queries, truth, overwrite);

  std::size_t count[2] = {}, collide[2] = {};
  for (std::size_t i = 0; i < queries.size(); ++i) {
    ++count[static_cast<int>(queries[i].type)];
    collide[static_cast<int>(queries[i].type)] += truth[i];
  }
  std::printf("barrier step %s at scale %g: %zu candidates in %.2f s (the scene's own contacts: "
              "%zu)\n",
              options.barrier_step.c_str(), options.barrier_scale,
              queries.size(), scene_seconds, result.contacts.size());
  if (options.exact_truth)
    std::printf("truth from the exact path in %.2f s (%d threads)\n", truth_seconds,
                tbb::this_task_arena::max_concurrency());
  for (int t = 0; t < 2; ++t)
    std::printf("%-12s %10zu queries %10s collisions\n", to_string(static_cast<QueryType>(t)),
                count[t],
                options.exact_truth ? std::to_string(collide[t]).c_str() : "-");
  std::printf("wrote %zu files under %s\n", files, root.string().c_str());
  return kExitAgree;
}

}  // namespace

int run_simulate(const SimulateOptions& options) {
  if (!options.barrier_step.empty()) return run_simulate_barrier(options);
  try {
    sim::validate(options.config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (options.out_dir.empty()) throw UsageError("--out: the folder name is empty");
  const fs::path root = fs::path(options.out_dir) / "simulation";
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  prepare_folders(root, overwrite);

  const auto generation_start = std::chrono::steady_clock::now();
  const std::vector<sim::SimulationQuery> queries =
      sim::generate_simulation_queries(options.config);
  const double generation_seconds = seconds_since(generation_start);

  const auto truth_start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> truth =
      options.exact_truth ? exact_truth(queries) : std::vector<std::uint8_t>(queries.size(), 0);
  const double truth_seconds = seconds_since(truth_start);

  const auto write_start = std::chrono::steady_clock::now();
  const std::size_t files = write_query_files(root, queries, truth, overwrite);
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
  std::printf("wrote %zu files under %s in %.2f s\n", files, root.string().c_str(),
              write_seconds);
  return kExitAgree;
}

}  // namespace exactccd::cli
