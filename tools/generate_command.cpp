#include "generate_command.hpp"

#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "cli_common.hpp"
#include "corpus.hpp"

namespace exactccd::cli {

int run_generate(const GenerateOptions& options) {
  if (options.per_family < families::kMinPerFamily || options.per_family > families::kMaxPerFamily)
    throw UsageError("--per-family must lie in [" + std::to_string(families::kMinPerFamily) + ", " +
                     std::to_string(families::kMaxPerFamily) + "], got " +
                     std::to_string(options.per_family));
  for (const std::string& name : options.families)
    if (!families::is_family_name(name))
      throw UsageError("--families: unknown family '" + name +
                       "' (a base family such as vf_interior, or <base>@s1e-12, @s1e-6, @s1e6, "
                       "@s1e12, @t1e4, @t1e8; see exactccd generate --help)");

  const auto start = std::chrono::steady_clock::now();
  const families::Corpus corpus =
      families::generate_corpus(options.seed, options.per_family, options.families);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    families::write_corpus(corpus, options.out_dir);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string(e.what()) + " (--out)");
  }

  std::size_t mismatches = 0, queries = 0, collisions = 0;
  for (const families::GeneratedFamily& g : corpus.families)
    for (const std::string& line : families::claim_mismatches(g)) {
      std::cerr << "exactccd: construction mismatch: " << line << '\n';
      ++mismatches;
    }
  std::printf("seed %llu, %d queries per family, exact path in %.2f s (%d threads)\n",
              static_cast<unsigned long long>(options.seed), options.per_family, seconds,
              tbb::this_task_arena::max_concurrency());
  std::printf("%-30s %-12s %8s %11s %14s\n", "family", "type", "queries", "collisions",
              "kept verdict");
  for (const families::GeneratedFamily& g : corpus.families) {
    char kept[32] = "-";
    if (g.family.is_variant())
      std::snprintf(kept, sizeof kept, "%zu/%zu", g.kept_verdict, g.family.members.size());
    std::printf("%-30s %-12s %8zu %11zu %14s\n", g.family.name.c_str(), to_string(g.family.type),
                g.family.members.size(), g.collisions(), kept);
    queries += g.family.members.size();
    collisions += g.collisions();
  }
  std::printf("TOTAL %zu families, %zu queries, %zu collisions; wrote %s/manifest.json\n",
              corpus.families.size(), queries, collisions, options.out_dir.c_str());
  if (mismatches > 0) {
    std::printf("%zu members contradict their construction (listed on stderr)\n", mismatches);
    return kExitDisagree;
  }
  return kExitAgree;
}

}  // namespace exactccd::cli
