#include "generate_command.hpp"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>
#include <stdexcept>
#include <vector>

#include "corpus/corpus_writer.hpp"
#include "corpus/point_families.hpp"
#include "oracle/common.hpp"
#include "oracle/inspection.hpp"
#include "oracle/inspection_report.hpp"
#include "oracle/inspector_page.hpp"
#include "oracle/output_file.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

namespace {

namespace fs = std::filesystem;

// Creates `folder` (and its parents) when missing; throws OutputError when it cannot.
void check_output_folder(const fs::path& folder) {
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error))
    throw OutputError(folder.string(), "is not a directory (--out takes a folder)");
  fs::create_directories(folder, error);
  if (error) throw OutputError(folder.string(), "cannot create the folder: " + error.message());
}

// The corpus layout of corpus.hpp: per family data_0.csv and toi_0.csv, then manifest.json.
// Every target is checked before the first is written, so that a refusal writes nothing.
void write_corpus_files(const families::Corpus& corpus, const fs::path& root,
                        Overwrite overwrite) {
  struct Target {
    fs::path path;
    std::string text;
  };
  std::vector<Target> targets;
  for (const families::GeneratedFamily& g : corpus.families) {
    const fs::path folder = root / families::family_folder(g.family);
    targets.push_back({folder / "data_0.csv", families::data_csv_text(g)});
    targets.push_back({folder / "toi_0.csv", families::toi_csv_text(g)});
  }
  targets.push_back({root / "manifest.json", families::manifest_text(corpus)});
  for (const Target& t : targets) {
    std::error_code error;
    if (fs::exists(t.path, error)) check_output_path(t.path.string(), overwrite, "--out");
  }
  for (const Target& t : targets) {
    check_output_folder(t.path.parent_path());
    write_file_atomically(t.path.string(), t.text, overwrite, "--out");
  }

  // Files of an earlier run in the family folders that this run did not replace.
  static const std::regex earlier_output("(data|toi)_[0-9]+\\.csv");
  std::vector<std::string> left;
  std::error_code error;
  for (fs::directory_iterator family(root, error); !error && family != fs::directory_iterator();
       family.increment(error)) {
    const std::string name = family->path().filename().string();
    if (!families::is_family_name(name) && !families::is_min_separation_family(name)) continue;
    for (const char* type : {"vertex-face", "edge-edge"}) {
      std::error_code list_error;
      for (fs::directory_iterator file(family->path() / type, list_error);
           !list_error && file != fs::directory_iterator(); file.increment(list_error)) {
        const fs::path& p = file->path();
        if (!std::regex_match(p.filename().string(), earlier_output)) continue;
        if (std::none_of(targets.begin(), targets.end(),
                         [&](const Target& t) { return t.path == p; }))
          left.push_back(p.string());
      }
    }
  }
  std::sort(left.begin(), left.end());
  warn_files_left_in_place(left, root.string());
}

// --type KIND: the point kind's families, DIR/<family>.csv each (the kind's file form, truth
// from the exact path), every target checked before the first is written.
int run_generate_points(const GenerateOptions& options, PrimitiveKind kind) {
  if (options.min_separation)
    throw UsageError("--min-separation: not with --type (the point kinds' families are of "
                     "contact)");
  std::vector<families::PointFamily> all =
      families::generate_point_families(kind, options.seed, options.per_family);
  std::vector<families::PointFamily> chosen;
  for (const std::string& name : options.families)
    if (std::none_of(all.begin(), all.end(),
                     [&](const families::PointFamily& f) { return f.name == name; })) {
      std::string names;
      for (const families::PointFamily& f : all) names += (names.empty() ? "" : ", ") + f.name;
      throw UsageError("--families: unknown family '" + name + "' of --type " +
                       to_string(kind) + " (" + names + ")");
    }
  for (families::PointFamily& f : all)
    if (options.families.empty() ||
        std::find(options.families.begin(), options.families.end(), f.name) !=
            options.families.end())
      chosen.push_back(std::move(f));
  if (options.out_dir.empty()) throw UsageError("--out: the folder name is empty");
  const fs::path root(options.out_dir);
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  check_output_folder(root);
  for (const families::PointFamily& f : chosen) {
    std::error_code error;
    const fs::path path = root / (f.name + ".csv");
    if (fs::exists(path, error)) check_output_path(path.string(), overwrite, "--out");
  }
  std::size_t mismatches = 0;
  std::printf("seed %llu, %d queries per family, --type %s (exactccd check --type %s FILE)\n",
              static_cast<unsigned long long>(options.seed), options.per_family, to_string(kind),
              to_string(kind));
  std::printf("%-28s %8s %11s  %s\n", "family", "queries", "collisions", "construction");
  for (const families::PointFamily& f : chosen) {
    write_file_atomically((root / (f.name + ".csv")).string(), families::point_family_csv(f),
                          overwrite, "--out");
    std::size_t collisions = 0;
    for (const CcdResult& r : f.exact) collisions += r.collides;
    std::printf("%-28s %8zu %11zu  %s (%s)\n", f.name.c_str(), f.members.size(), collisions,
                f.what.c_str(), f.collides ? "collides" : "misses");
    for (const std::string& line : families::point_claim_mismatches(f)) {
      std::cerr << "exactccd: construction mismatch: " << line << '\n';
      ++mismatches;
    }
  }
  if (mismatches > 0) {
    std::printf("%zu members contradict their construction (listed on stderr)\n", mismatches);
    return kExitDisagree;
  }
  return kExitAgree;
}

// DIR/index.html and DIR/inspect/<family>.html: a browsable index of the suite, one inspector
// page per family on a representative member (its first colliding one, else its first).
void write_suite_index(const families::Corpus& corpus, const fs::path& root, Overwrite overwrite) {
  InspectionFolder pages((root / "inspect").string(), overwrite, "--html");
  InspectSettings settings;
  settings.min_separation = corpus.min_separation.value_or(0.0);
  IndexSection table{"Families", "",
                     {"family", "type", "queries", "collisions", "inspected member", "what it is"},
                     {}};
  for (const families::GeneratedFamily& g : corpus.families) {
    std::size_t member = 0;
    for (std::size_t i = 0; i < g.exact.size(); ++i)
      if (g.exact[i].collides) {
        member = i;
        break;
      }
    const fs::path data = root / families::family_folder(g.family) / "data_0.csv";
    const QueryFile file = read_query_file(data.string(), g.family.type);
    const std::string page = pages.add_page(
        g.family.name,
        inspection_json(file.queries.at(member), g.family.type, data.string(), member, settings));
    table.rows.push_back({{g.family.name, to_string(g.family.type),
                           std::to_string(g.family.members.size()), std::to_string(g.collisions()),
                           "query " + std::to_string(member) + " (" +
                               g.family.members[member].label + ")",
                           g.family.description},
                          {"inspect/" + page}});
  }
  const std::string intro =
      "The queries exactccd generate wrote here (seed " + std::to_string(corpus.seed) + ", " +
      std::to_string(corpus.per_family) + " per family" +
      (corpus.min_separation ? ", minimum separation " + format_double(*corpus.min_separation)
                             : std::string()) +
      "), with the exact path's truth. Each family links to the inspector of one member.";
  write_file_atomically((root / "index.html").string(),
                        index_page("exactccd generate: the suite", intro, {table}), overwrite,
                        "--html");
}

}  // namespace

int run_generate(const GenerateOptions& options) {
  if (options.per_family < families::kMinPerFamily || options.per_family > families::kMaxPerFamily)
    throw UsageError("--per-family must lie in [" + std::to_string(families::kMinPerFamily) + ", " +
                     std::to_string(families::kMaxPerFamily) + "], got " +
                     std::to_string(options.per_family));
  if (options.primitive && options.html)
    throw UsageError("--html indexes the vertex-face and edge-edge families (not --type)");
  if (options.primitive) return run_generate_points(options, *options.primitive);
  if (options.min_separation) {
    const std::string problem = families::min_separation_delta_problem(*options.min_separation);
    if (!problem.empty())
      throw UsageError("--min-separation " + problem + ", got " +
                       format_double(*options.min_separation));
    for (const std::string& name : options.families)
      if (!families::is_min_separation_family(name)) {
        std::string names;
        for (const std::string& n : families::min_separation_family_names())
          names += (names.empty() ? "" : ", ") + n;
        throw UsageError("--families: unknown minimum-separation family '" + name +
                         "' (with --min-separation: " + names + ")");
      }
  }
  for (const std::string& name : options.families)
    if (!options.min_separation && !families::is_family_name(name)) {
      std::string suffixes;
      for (const families::Variant& v : families::variants())
        suffixes += (suffixes.empty() ? "" : ", ") + std::string(v.suffix);
      throw UsageError("--families: unknown family '" + name +
                       "' (a base family such as vf_interior, a random family such as "
                       "vf_wide_exponent_1000, or a base family with one of the suffixes " +
                       suffixes + "; see exactccd generate --help)");
    }

  if (options.out_dir.empty()) throw UsageError("--out: the folder name is empty");
  const fs::path root(options.out_dir);
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  check_output_folder(root);
  // An earlier run's manifest: refused before the work (the other files after it, once known).
  check_output_path((root / "manifest.json").string(), overwrite, "--out");
  if (options.html) {
    require_inspector();
    check_output_path((root / "index.html").string(), overwrite, "--html");
  }

  const auto start = std::chrono::steady_clock::now();
  const families::Corpus corpus =
      options.min_separation
          ? families::generate_min_separation_corpus(*options.min_separation, options.seed,
                                                     options.per_family, options.families)
          : families::generate_corpus(options.seed, options.per_family, options.families);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_corpus_files(corpus, root, overwrite);
  if (options.html) write_suite_index(corpus, root, overwrite);

  std::size_t mismatches = 0, queries = 0, collisions = 0;
  for (const families::GeneratedFamily& g : corpus.families)
    for (const std::string& line : families::claim_mismatches(g)) {
      std::cerr << "exactccd: construction mismatch: " << line << '\n';
      ++mismatches;
    }
  std::printf("seed %llu, %d queries per family, exact path in %.2f s (%d threads)\n",
              static_cast<unsigned long long>(options.seed), options.per_family, seconds,
              tbb::this_task_arena::max_concurrency());
  if (options.min_separation)
    std::printf("minimum separation %s: collisions are queries within that distance\n",
                format_double(*options.min_separation).c_str());
  std::printf("%-36s %-12s %8s %11s %14s\n", "family", "type", "queries", "collisions",
              "kept verdict");
  for (const families::GeneratedFamily& g : corpus.families) {
    char kept[32] = "-";
    if (g.family.is_variant())
      std::snprintf(kept, sizeof kept, "%zu/%zu", g.kept_verdict, g.family.members.size());
    std::printf("%-36s %-12s %8zu %11zu %14s\n", g.family.name.c_str(), to_string(g.family.type),
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
