// exactccd_soak: the differential test at scale. Decides N seeded random queries (the
// generators of corpus/random_queries.hpp, round robin: ordinary and near-degenerate families,
// wide exponent spreads, resting contact, stacked coplanar faces, each scaled by 2^k one time
// in four) with the default path and with the exact path, in parallel, and compares them as
// tests/differential_test.cpp does: same verdict, identical tightest TOI pair, a coarse
// toi_width enclosing t*, and t_max < 1 on one query in eight. Query i is a pure function of
// (seed, i): any failure replays alone. The wide-exponent generators dominate the time (their
// exact path costs up to 0.5 s per query today).
//
// Exit status: 0 all agree; 1 some disagreement (each printed, with the query in the benchmark
// CSV format for `exactccd check`); 2 bad command line.
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "corpus/random_queries.hpp"

namespace {

using namespace exactccd;
using namespace exactccd::random_queries;

constexpr std::size_t kGenerators = kGeneratorCount;
constexpr std::size_t kMaxReported = 10;
using PerGenerator = std::array<DifferentialStats, kGenerators>;

struct Failure {
  std::uint64_t index;  // global query index
  Generator generator;
  std::uint64_t generator_index;
  Disagreement disagreement;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_summary(const PerGenerator& stats, const std::array<Generator, kGenerators>& gens,
                   double seconds) {
  std::printf("%-36s %11s %10s", "generator", "queries", "collide");
  for (Stage st : default_path_stages()) std::printf(" %16s", to_string(st));
  std::printf(" %10s %7s\n", "fallback", "disagr");
  DifferentialStats total;
  const auto row = [](const std::string& name, const DifferentialStats& s) {
    std::printf("%-36s %11llu %10llu", name.c_str(), static_cast<unsigned long long>(s.queries),
                static_cast<unsigned long long>(s.collisions));
    for (Stage st : default_path_stages())
      std::printf(" %15.3f%%", s.queries ? 100.0 * double(s.stage[static_cast<int>(st)]) /
                                              double(s.queries)
                                        : 0.0);
    std::printf(" %10llu %7llu\n",
                static_cast<unsigned long long>(s.stage[static_cast<int>(Stage::exact)]),
                static_cast<unsigned long long>(s.disagreements));
  };
  for (std::size_t g = 0; g < kGenerators; ++g) {
    row(gens[g].name(), stats[g]);
    total += stats[g];
  }
  row("total", total);
  std::printf("coarse-width checks %llu, t_max < 1 checks %llu\n",
              static_cast<unsigned long long>(total.width_checks),
              static_cast<unsigned long long>(total.t_max_checks));
  std::printf("%.1f s, %.0f queries/s\n", seconds,
              seconds > 0 ? double(total.queries) / seconds : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t queries = 100000000;
  std::uint64_t seed = 1;
  int threads = static_cast<int>(tbb::this_task_arena::max_concurrency());
  CLI::App app(
      "Soak test: the default path (culling, filters, exact fallback) against the exact path "
      "on seeded random vertex-face and edge-edge queries, including near-degenerate ones.",
      "exactccd_soak");
  app.add_option("--queries", queries, "Number of queries")->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "Base seed; query i depends on (seed, i) only")
      ->capture_default_str();
  app.add_option("--threads", threads, "Worker threads")->capture_default_str()
      ->check(CLI::Range(1, 1024));
  app.footer("Exit status: 0 all agree, 1 some disagreement, 2 bad command line.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }

  const std::array<Generator, kGenerators> gens = all_generators();
  std::printf("exactccd_soak: %llu queries, seed %llu, %d threads, %zu generators round robin\n",
              static_cast<unsigned long long>(queries), static_cast<unsigned long long>(seed),
              threads, kGenerators);
  std::fflush(stdout);

  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  tbb::task_group_context context;
  tbb::combinable<PerGenerator> stats;
  std::atomic<std::uint64_t> done{0}, failures{0};
  std::mutex failure_mutex;
  std::vector<Failure> reported;

  const auto start = std::chrono::steady_clock::now();
  std::mutex finished_mutex;
  std::condition_variable finished_cv;
  bool finished = false;

  std::thread worker([&] {
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::uint64_t>(0, queries, 256),
          [&](const tbb::blocked_range<std::uint64_t>& r) {
            PerGenerator& local = stats.local();
            std::uint64_t n = 0;
            for (std::uint64_t i = r.begin(); i != r.end(); ++i) {
              if (context.is_group_execution_cancelled()) break;
              const std::size_t g = i % kGenerators;
              const std::uint64_t gi = i / kGenerators;
              std::mt19937_64 rng;
              const DoubleQuery q = generate(gens[g], seed, gi, rng);
              Disagreement d = differential_check(q, rng, local[g]);
              ++n;
              if (d.what.empty()) continue;
              ++failures;
              std::lock_guard<std::mutex> lock(failure_mutex);
              if (reported.size() < kMaxReported)
                reported.push_back({i, gens[g], gi, std::move(d)});
              context.cancel_group_execution();  // stop soon: one replayable failure is enough
            }
            done += n;
          },
          context);
    });
    std::lock_guard<std::mutex> lock(finished_mutex);
    finished = true;
    finished_cv.notify_all();
  });

  {
    std::unique_lock<std::mutex> lock(finished_mutex);
    while (!finished_cv.wait_for(lock, std::chrono::seconds(10), [&] { return finished; })) {
      const double s = seconds_since(start);
      const std::uint64_t n = done.load();
      std::fprintf(stderr, "[%7.0f s] %llu / %llu queries (%.1f%%), %.0f queries/s, %llu disagreements\n",
                   s, static_cast<unsigned long long>(n), static_cast<unsigned long long>(queries),
                   100.0 * double(n) / double(queries), double(n) / s,
                   static_cast<unsigned long long>(failures.load()));
    }
  }
  worker.join();

  PerGenerator total{};
  stats.combine_each([&](const PerGenerator& p) {
    for (std::size_t g = 0; g < kGenerators; ++g) total[g] += p[g];
  });
  print_summary(total, gens, seconds_since(start));

  if (failures.load() == 0) {
    std::printf("OK: default path == exact path on all %llu queries\n",
                static_cast<unsigned long long>(done.load()));
    return 0;
  }
  std::printf("FAILED: %llu disagreement(s) (stopped early after the first)\n",
              static_cast<unsigned long long>(failures.load()));
  for (const Failure& f : reported) {
    const Disagreement& d = f.disagreement;
    std::printf("\n--- query %llu (%s #%llu, seed %llu): %s\n", static_cast<unsigned long long>(f.index),
                f.generator.name().c_str(), static_cast<unsigned long long>(f.generator_index),
                static_cast<unsigned long long>(seed), d.report().c_str());
    // The truth column is the exact path's verdict under the failing options.
    std::printf("benchmark CSV (replay: exactccd check --type %s --t-max %.17g FILE.csv):\n%s",
                f.generator.type == QueryType::vertex_face ? "vf" : "ee", d.options.t_max,
                to_csv(d.query, d.exact_result.collides).c_str());
  }
  return 1;
}
