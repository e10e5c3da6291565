// `exactccd`: the command-line oracle. `check` decides benchmark CSV files (exactly by default)
// and compares with their truth column; `grade` judges another code's answers (and TOIs)
// exactly; `simulate` writes simulation-like queries; `generate` the degenerate families (or
// the minimum-separation families);
// `bench` times the modes; `study` measures the uncertified methods' errors against the exact
// truth; `rigid` runs a rigid-body scene file.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

#include "bench_command.hpp"
#include "corpus/barrier_steps.hpp"
#include "oracle/barrier_report.hpp"
#include "rigid_bench_command.hpp"
#include "check_command.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/version.hpp"
#include "generate_command.hpp"
#include "grade_command.hpp"
#include "inspect_command.hpp"
#include "rigid_command.hpp"
#include "oracle/command_line.hpp"
#include "oracle/common.hpp"
#include "oracle/names.hpp"
#include "simulate_command.hpp"

namespace {

using namespace exactccd::cli;
using namespace exactccd::oracle;

constexpr const char* kExitStatusHelp =
    "Exit status:\n"
    "  0  all ran and everything agrees (check: every decision equals the truth column;\n"
    "     grade: every answer is correct and every toi conservative; bench: the certified\n"
    "     modes (filtered, exact) agree with the truth; simulate and rigid: always, a\n"
    "     contact being an answer, not a disagreement)\n"
    "  1  some disagreement (check: a decision differs from the truth column; grade: a\n"
    "     false positive, a false negative or a toi later than the exact one; bench: a\n"
    "     certified mode disagrees with the truth)\n"
    "  2  bad command line, malformed or unreadable input, or an output that cannot be\n"
    "     written (a full disk, an existing file without --force); one line on stderr:\n"
    "     'exactccd: FILE:LINE: what'\n"
    "  3  internal error (a bug in exactccd, or out of memory)\n"
    "generate: 0 written, every member as constructed; 1 written, but a member's exact\n"
    "  verdict or TOI contradicts its construction; 2 and 3 as above.\n"
    "study: 0 the certified methods show no false positive, false negative or late TOI;\n"
    "  1 one of them does; 2 and 3 as above.\n";

constexpr const char* kModeHelp =
    "The path that decides: filtered (culling, certified interval filters, exact fallback: "
    "always exact), float_only (uncertified double-precision cubic test, for comparison), "
    "exact (the exact rational procedure only). 'default' is accepted as the old name of "
    "filtered";

// --mode and --modes: a name parse_mode_name accepts (the canonical names, or the alias
// "default" of filtered); else an error listing them.
CLI::Validator mode_name_check() {
  std::string names;
  for (const std::string& name : mode_names()) names += (names.empty() ? "" : ",") + name;
  return CLI::Validator(
      [](std::string& text) {
        return parse_mode_name(text) ? std::string()
                                     : "unknown mode " + exactccd::quote_for_message(text) +
                                           ": expected " + mode_names_text();
      },
      "{" + names + "}");
}

// The study program: beside this one when installed together, else where the build put it
// (EXACTCCD_STUDY_PROGRAM, empty when this build has no study).
std::string study_program() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path sibling = self.parent_path() / "exactccd_study";
    if (std::filesystem::is_regular_file(sibling, error)) return sibling.string();
  }
  return EXACTCCD_STUDY_PROGRAM;
}

// `exactccd study ARGS` runs `exactccd_study ARGS`: the study is a program of the benchmarks
// (study). Returns only when it cannot be run.
int forward_to_study(int argc, char** argv) {
  const std::string program = study_program();
  if (program.empty()) {
    report_error("study: the study program exactccd_study is not part of this build (configure "
                 "with -DEXACTCCD_BUILD_BENCH=ON or -DEXACTCCD_BUILD_TESTS=ON)");
    return kExitBadInput;
  }
  std::vector<char*> args = {const_cast<char*>(program.c_str())};
  for (int k = 2; k < argc; ++k) args.push_back(argv[k]);
  args.push_back(nullptr);
  execv(program.c_str(), args.data());
  report_error("study: cannot run the study program " + program + ": " + std::strerror(errno) +
               " (build the target exactccd_study)");
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "study") == 0) return forward_to_study(argc, argv);
  // Output to a file or pipe in one buffer as large as any summary or help text (the help has
  // outgrown stdio's 4 KiB): a failed write then surfaces in finish()'s fflush, with its reason.
  static char stdout_buffer[1 << 16];
  if (!isatty(STDOUT_FILENO)) std::setvbuf(stdout, stdout_buffer, _IOFBF, sizeof stdout_buffer);

  CLI::App app(
      "Exact continuous collision detection oracle for the CCD benchmark "
      "(Wang et al. 2021): vertex-face and edge-edge queries, decided exactly.",
      "exactccd");
  app.footer(kExitStatusHelp);
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("exactccd ") + exactccd::library_version(),
                       "Print the version of the library and exit");

  CheckOptions check_options;
  std::string check_type;
  CLI::App* check = app.add_subcommand(
      "check",
      "Decide every query of benchmark CSV files and compare with their truth column "
      "(table per file and TOTAL on stdout, with the share of queries each stage decided).");
  check->footer(kExitStatusHelp);
  check
      ->add_option("--format", check_options.format,
                   "table: per file and TOTAL, within 100 columns (names below the files' "
                   "common folder, stage shares abbreviated); wide: every column in full; csv: "
                   "the same rows as CSV; json: one object (mode, queries, collisions, "
                   "false_positives, false_negatives, seconds, stage_counts, stage_share, "
                   "files[...])")
      ->check(CLI::IsMember({"table", "wide", "csv", "json"}))
      ->capture_default_str();
  bool check_json = false;
  check->add_flag("--json", check_json, "The same as --format json");
  std::string check_mode = exactccd::to_string(exactccd::Mode::filtered);
  check->add_option("--mode", check_mode,
                    std::string(kModeHelp) +
                        ". Coordinates must be doubles, except with --mode exact, which decides "
                        "any rational query exactly")
      ->check(mode_name_check())
      ->capture_default_str();
  check->add_option("--out", check_options.out_path,
                    "Write one line per query: file,index,collides,toi_lo,toi_hi (index 0-based "
                    "in its file, TOI with 17 significant digits, inf when no contact)");
  add_force_flag(check, check_options.force);
  add_check_type_option(check, check_type);
  add_t_max_option(check, check_options.t_max);
  add_min_separation_option(check, check_options.min_separation);
  check
      ->add_option("PATH", check_options.paths,
                   "CSV files, or directories searched for vertex-face/*.csv and "
                   "edge-edge/*.csv")
      ->required();

  GradeOptions grade_options;
  std::string grade_type;
  CLI::App* grade =
      app.add_subcommand("grade",
                         "Judge another code's answers to one benchmark CSV file against the exact "
                         "decision: false positives, false negatives, non-conservative TOIs.");
  grade->footer(std::string("Answers file: one line per query, in order: 0, 1, or 1,toi (toi a "
                            "decimal double, the\ncode's time of impact; it is conservative iff "
                            "toi <= the exact first contact time).\nA no-contact line may carry "
                            "the +infinity convention's toi: 0,inf.\n\n") +
                kExitStatusHelp);
  grade->add_option("--queries", grade_options.queries_path, "The benchmark CSV file")->required();
  grade->add_option("--answers", grade_options.answers_path, "The answers file")->required();
  grade->add_flag("--json", grade_options.json, "Print one JSON object instead of text");
  add_check_type_option(grade, grade_type);
  add_t_max_option(grade, grade_options.t_max);
  add_min_separation_option(grade, grade_options.min_separation);
  grade->add_option("--html", grade_options.html_path,
                    "Also write REPORT.html: the grading tables and an inspector page for each of "
                    "the first findings of each kind, in the folder REPORT_files beside it "
                    "(refused if either exists, without --force)");
  grade->add_option("--html-limit", grade_options.html_limit,
                    "Inspector pages per kind of finding in the --html report")
      ->check(numeric_text(true) & CLI::NonNegativeNumber)
      ->capture_default_str();
  add_force_flag(grade, grade_options.force);

  SimulateOptions simulate_options;
  std::string simulate_truth = "exact";
  CLI::App* simulate = app.add_subcommand(
      "simulate",
      "Write simulation-like queries (a sheet draping over a sphere, two rigid bodies passing "
      "each other: every pair whose swept boxes overlap) as benchmark CSV files, each "
      "coordinate as its exact fraction, to DIR/simulation/{vertex-face,edge-edge}/data_K.csv "
      "(at most 100000 queries per file; a folder already holding data_K.csv files is "
      "refused without --force, and files this run does not replace are left in place).");
  simulate->footer(kExitStatusHelp);
  simulate->add_option("--out", simulate_options.out_dir, "The output folder DIR")->required();
  add_force_flag(simulate, simulate_options.force);
  // Not a structured binding: the run lambda below uses them (clang 14 refuses captures of
  // structured bindings, a C++20 feature).
  CLI::Option *simulate_resolution, *simulate_steps, *simulate_seed;
  std::tie(simulate_resolution, simulate_steps, simulate_seed) =
      add_simulation_options(simulate, simulate_options.config);
  simulate
      ->add_option("--barrier-step", simulate_options.barrier_step,
                   "Write instead the candidate pairs of a barrier-method trial step (the "
                   "scene's broad phase, as exactccd bench --barrier-steps runs it: "
                   "cloth_on_ball, many_bodies, resting_slide, debris_field, twisted_rods, "
                   "rollers) to DIR/barrier/NAME/{vertex-face,edge-edge}/data_K.csv");
  CLI::Option* simulate_barrier_scale =
      simulate
          ->add_option("--barrier-scale", simulate_options.barrier_scale,
                       "Mesh resolution of --barrier-step, in (0, 1] (1: 20k-650k triangles, "
                       "millions of candidates)")
          ->check(numeric_text(false))
          ->capture_default_str();
  simulate
      ->add_option("--truth", simulate_truth,
                   "exact: the truth column from the exact path (in parallel); none: all 0")
      ->check(CLI::IsMember({"exact", "none"}))
      ->capture_default_str();

  BenchOptions bench_options;
  bench_options.default_path = EXACTCCD_SAMPLE_QUERIES;
  std::string bench_type;
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Time each mode on data sets (single thread) and count its false positives and false "
      "negatives against the truth: mean and median ns per query, share of queries decided by "
      "each stage. Each PATH (a CSV file or a folder) is one data set; with none and no "
      "--simulation, the shipped sample queries.");
  bench->footer(
      "mean_ns: the median over the repetitions of (time of one pass over all queries / "
      "queries). median_ns: the median of the queries' single timed calls, less the median "
      "cost of an empty timed region (reported). max_ns: the slowest query, its fastest of "
      "three single calls.\n\n" +
      std::string(kExitStatusHelp));
  bench->add_flag("--json", bench_options.json,
                  "Print a JSON array, one object per data set, delta and mode (dataset, mode, "
                  "min_separation, size, min_separation_factor, queries, "
                  "mean_ns, median_ns, false_positives, false_negatives, stage_share, ...)");
  // One comma-separated argument each (as the study's --widths), so that a PATH after them stays
  // a PATH.
  std::vector<std::string> bench_modes = mode_names();
  CLI::Option* bench_modes_option =
      bench->add_option("--modes", bench_modes,
                        "Comma-separated modes: float_only,filtered,exact ('default': filtered)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(mode_name_check())
      ->capture_default_str();
  bench
      ->add_option("--repetitions", bench_options.repetitions,
                   "Timed passes per data set and mode")
      ->check(numeric_text(true))
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  bench->add_flag("--simulation", bench_options.simulation,
                  "Add the simulation-like set, generated in memory (truth: the exact path)");
  CLI::Option* bench_resolution = nullptr;
  CLI::Option* bench_steps = nullptr;
  CLI::Option* bench_seed = nullptr;
  std::tie(bench_resolution, bench_steps, bench_seed) =
      add_simulation_options(bench, bench_options.simulation_config);
  add_check_type_option(bench, bench_type);
  bench
      ->add_option("--min-separation", bench_options.min_separations,
                   "Comma-separated minimum separations delta >= 0, each a run of every mode "
                   "(0: contact, truth from the data set; delta > 0: truth and TOIs from the "
                   "exact path at delta, float_only is then the common practice: the float "
                   "cubic's roots, the distance at each compared with delta)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(numeric_text(false))
      ->capture_default_str();
  bench->add_flag("--relative-separation", bench_options.relative_separation,
                  "Read --min-separation as factors of each data set's size (the diagonal of "
                  "the box of all its coordinates)");
  bench->add_option("PATH", bench_options.paths, "CSV files or folders, one data set each");
  RigidBenchOptions rigid_bench_options;
  bool bench_rigid = false;
  bench->add_flag("--rigid", bench_rigid,
                  "Time the rigid-body modes (filtered, exact; float_only on request, graded "
                  "against the first certified mode) on seeded random rigid pairs near contact "
                  "instead (--rigid-count, --seed, --modes, --repetitions, --min-separation, "
                  "--relative-separation, --json; each delta a run of every mode); exit status 1 "
                  "when the certified modes' answers differ");
  CLI::Option* bench_rigid_count =
      bench->add_option("--rigid-count", rigid_bench_options.count, "Rigid pairs (with --rigid)")
          ->check(numeric_text(true))
          ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}))
          ->capture_default_str();
  exactccd::oracle::BarrierReportOptions barrier_options;
  bool bench_barrier = false;
  bench->add_flag("--barrier-steps", bench_barrier,
                  "Run barrier-method trial steps through the scene instead (cloth on a ball, "
                  "many bodies, resting and sliding contact, debris, twisted rods, rollers: "
                  "--barrier-scale, --barrier-step, --repetitions, --min-separation, --json): "
                  "candidates, cuts by time, contacts, the earliest contact, and the median time "
                  "of earliest_contact and find_contacts on 1 and 2 threads; exit status 1 when "
                  "earliest_contact differs from find_contacts' earliest");
  CLI::Option* bench_barrier_scale =
      bench->add_option("--barrier-scale", barrier_options.scale,
                        "Mesh resolution of the barrier steps (1: 20k-650k triangles)")
          ->check(numeric_text(false))
          ->check(CLI::Range(0.01, 20.0))
          ->capture_default_str();
  CLI::Option* bench_barrier_step =
      bench->add_option("--barrier-step", barrier_options.steps,
                        "Only these barrier steps (repeatable; default: all)")
          ->check(CLI::IsMember(exactccd::corpus::barrier_step_names()));

  // `exactccd study` runs the study program of the benchmarks (study): see forward_to_study.
  app.add_subcommand(
      "study",
      "Numerical-stability study: each method or setting (float_only; the tolerance method, "
      "distance <= eps at a cubic root, at each eps; the filtered path at each TOI width; exact) "
      "against the exact truth on each data set (runs the program exactccd_study of the "
      "benchmarks; see exactccd study --help).");

  GenerateOptions generate_options;
  CLI::App* generate = app.add_subcommand(
      "generate",
      "Write reproducible families of hard and degenerate queries with exact truth and TOI "
      "(from the exact path): DIR/manifest.json and, per family, "
      "DIR/<family>/<vertex-face|edge-edge>/data_0.csv (benchmark CSV, exact fractions) and "
      "toi_0.csv (index,collides,toi_lo,toi_hi). Each base family has colliding members and "
      "near misses 1 ulp and 2^-k away; the random families (wide exponent spreads) have no "
      "construction and take their truth from the exact path.");
  {
    std::string bases;
    for (const std::string& name : exactccd::families::base_family_names())
      bases += (bases.empty() ? "" : ", ") + name;
    std::string randoms;
    for (const std::string& name : exactccd::families::random_family_names())
      randoms += (randoms.empty() ? "" : ", ") + name;
    std::string suffixes;
    for (const auto& v : exactccd::families::variants())
      suffixes += (suffixes.empty() ? "" : ", ") + std::string(v.suffix);  // "@s1e-12, ..."
    std::string separations;
    for (const std::string& name : exactccd::families::min_separation_family_names())
      separations += (separations.empty() ? "" : ", ") + name;
    generate->footer("Families: " + bases + "; each of them scaled or translated in double "
                     "arithmetic (@s, @t: no claim) or scaled by 2^k (@p2^k: claims kept where "
                     "exact), named <family>" + suffixes + "; and the random families without "
                     "claims " + randoms + ". With --min-separation D: " + separations +
                     " (within distance D exactly at the constructed time, near misses 1 ulp "
                     "and ~2^-k D farther).\n\nExit "
                     "status: 0 written, every member as constructed; 1 written, but some "
                     "member's exact verdict or TOI contradicts its construction (listed on "
                     "stderr); 2 bad command line, an unwritable folder, or an earlier run's "
                     "files there without --force; 3 internal error.");
  }
  generate->add_option("--out", generate_options.out_dir, "The output folder DIR")->required();
  add_force_flag(generate, generate_options.force);
  generate->add_flag("--html", generate_options.html,
                     "Also write DIR/index.html, a browsable index of the suite, and one inspector "
                     "page per family (a representative member) in DIR/inspect");
  generate->add_option("--seed", generate_options.seed, "Seed of the constructions")
      ->check(seed_text())
      ->capture_default_str();
  generate
      ->add_option("--per-family", generate_options.per_family,
                   "Queries per family (groups of a boundary contact and its near misses)")
      ->check(numeric_text(true))
      ->check(CLI::Range(exactccd::families::kMinPerFamily, exactccd::families::kMaxPerFamily))
      ->capture_default_str();
  generate
      ->add_option("--families", generate_options.families,
                   "Comma-separated family names (default: all)")
      ->delimiter(',');
  std::string generate_type;
  generate
      ->add_option("--type", generate_type,
                   "Write the degenerate families of a point kind instead, DIR/<family>.csv "
                   "each in the kind's file form (check them with exactccd check --type KIND): "
                   "pe, pe2d, pp, pp2d or pl")
      ->check(CLI::IsMember({"pe", "pe2d", "pp", "pp2d", "pl"}));
  double generate_min_separation = 0.0;
  CLI::Option* generate_min_separation_option =
      generate
          ->add_option("--min-separation", generate_min_separation,
                       "Write the minimum-separation families for this delta instead (0 or a "
                       "double in [2^-900, 2^900]; e.g. 0.0009765625, 0x1p-10, 0.3): truth and "
                       "TOI of minimum-separation CCD, delta in the manifest")
          ->check(numeric_text(false));

  RigidOptions rigid_options;
  CLI::App* rigid = app.add_subcommand(
      "rigid",
      "Run a rigid-body scene file (JSON, docs/rigid_scene_format.md: bodies as OBJ files or "
      "inline arrays, rigid, static or deformable; rigid motions as Cayley vectors or turns, one "
      "or a list of steps) and print the first contact of each step (Scene::earliest_contact): "
      "its bodies and features (vertex-face: vertex, triangle; edge-edge: edges), the enclosure "
      "of the motion parameter s and, for pure rotations of one rate, of the time; or "
      "collision-free. Each step starts from the previous step's exact end pose rounded to "
      "doubles.");
  rigid->footer(kRigidExitStatusHelp);
  rigid->add_option("SCENE", rigid_options.scene_path, "The JSON scene file")->required();
  rigid->add_flag("--json", rigid_options.json,
                  "Print one JSON object (scene, mode, t_max, toi_width, min_separation, bodies, "
                  "steps[{step, start_rounding, collides, contact{type, s_lo, s_hi, time_lo, "
                  "time_hi, first, second}}], first_contact_step)");
  double rigid_min_separation = 0.0;
  CLI::Option* rigid_min_separation_option =
      rigid
          ->add_option("--min-separation", rigid_min_separation,
                       "Minimum separation delta >= 0 (finite): a step's contact is the first s "
                       "at which primitives of two bodies come within Euclidean distance delta "
                       "(0: contact). Replaces the scene file's \"min_separation\"")
          ->check(numeric_text(false));

  InspectOptions inspect_options;
  std::string inspect_type, inspect_mode = exactccd::to_string(exactccd::Mode::filtered);
  CLI::App* inspect = app.add_subcommand(
      "inspect",
      "Show one query of a benchmark CSV file (or the first contact of a step of a rigid scene "
      "file, FILE.json): its answer in a mode, the exact and float_only "
      "answers, the polynomial that decides it with its roots as exact brackets and the "
      "inclusion test at each, and the contact geometry; with --html, as one self-contained "
      "page (a 3D view with a time slider, a plot of the polynomial, a panel; nothing fetched "
      "at view time) for a browser.");
  inspect->footer(kExitStatusHelp);
  inspect->add_option("FILE", inspect_options.path, "The benchmark CSV file")->required();
  inspect->add_option("--index", inspect_options.index, "The 0-based query index in FILE")
      ->check(numeric_text(true) & CLI::NonNegativeNumber)
      ->capture_default_str();
  inspect->add_option("--mode", inspect_mode,
                      std::string(kModeHelp) +
                          ". Coordinates must be doubles, except with --mode exact")
      ->check(mode_name_check())
      ->capture_default_str();
  add_check_type_option(inspect, inspect_type);
  add_t_max_option(inspect, inspect_options.settings.t_max);
  add_min_separation_option(inspect, inspect_options.settings.min_separation);
  inspect->add_option("--html", inspect_options.html_path,
                      "Write the inspector page OUT.html (refused if it exists, without --force)");
  add_force_flag(inspect, inspect_options.force);
  inspect->add_flag("--json", inspect_options.json,
                    "Print the inspection as JSON (the page's data) instead of text");
  std::size_t inspect_step = 0;
  CLI::Option* inspect_step_option =
      inspect
          ->add_option("--step", inspect_step,
                       "With a rigid scene file (FILE.json, as exactccd rigid runs it): show the "
                       "first contact of this step (1-based; default: the first step with one)")
          ->check(numeric_text(true) & CLI::NonNegativeNumber);

  // CLI11 would only say that a subcommand is required.
  if (argc >= 2 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
      names += (names.empty() ? "" : ", ") + command->get_name();
      known = known || command->get_name() == argv[1];
    }
    if (!known) {
      report_error("unknown subcommand " + exactccd::quote_for_message(argv[1]) + " (one of " +
                   names + "; see exactccd --help)");
      return kExitBadInput;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return finish(app.exit(e));  // --help
    report_error(std::string(e.what()) + " (see exactccd --help)");
    return kExitBadInput;
  }
  // Every failure ends as one line on stderr, 'exactccd: <what>', with its exit status.
  return run_reporting_errors([&] {
    if (check->parsed()) {
      if (check_json) check_options.format = "json";
      check_options.type = parse_type_name(check_type);
      check_options.primitive = exactccd::primitive_kind_from_name(check_type);
      check_options.mode = *parse_mode_name(check_mode);
      return run_check(check_options);
    }
    if (simulate->parsed()) {
      if (simulate_options.barrier_step.empty() && simulate_barrier_scale->count() > 0)
        throw UsageError("--barrier-scale needs --barrier-step");
      if (!simulate_options.barrier_step.empty())
        for (CLI::Option* option : {simulate_resolution, simulate_steps, simulate_seed})
          if (option->count() > 0)
            throw UsageError(option->get_name() + " does not apply to --barrier-step");
      simulate_options.exact_truth = simulate_truth == "exact";
      return run_simulate(simulate_options);
    }
    if (bench_rigid && bench_barrier) throw UsageError("--rigid and --barrier-steps: choose one");
    if (bench->parsed() && bench_rigid) {
      for (CLI::Option* option : {bench_resolution, bench_steps})
        if (option->count() > 0) throw UsageError(option->get_name() + " needs --simulation");
      if (bench_options.simulation || !bench_options.paths.empty())
        throw UsageError("--rigid runs its own queries (no PATH, no --simulation)");
      rigid_bench_options.seed = bench_options.simulation_config.seed;
      rigid_bench_options.repetitions = bench_options.repetitions;
      rigid_bench_options.json = bench_options.json;
      rigid_bench_options.min_separations = bench_options.min_separations;
      rigid_bench_options.relative_separation = bench_options.relative_separation;
      if (bench_modes_option->count() > 0) {  // else filtered, exact
        rigid_bench_options.modes.clear();
        for (const std::string& name : bench_modes)
          rigid_bench_options.modes.push_back(*parse_mode_name(name));
      }
      return run_rigid_bench(rigid_bench_options);
    }
    if (bench->parsed() && bench_barrier) {
      for (CLI::Option* option : {bench_resolution, bench_steps, bench_seed, bench_rigid_count,
                                  bench_modes_option})
        if (option->count() > 0)
          throw UsageError(option->get_name() + " does not apply to --barrier-steps");
      if (bench_options.simulation || !bench_options.paths.empty() || bench_rigid ||
          bench_options.relative_separation)
        throw UsageError("--barrier-steps runs its own scenes (no PATH, --simulation, --rigid "
                         "or --relative-separation)");
      if (bench_options.min_separations.size() != 1)
        throw UsageError("--barrier-steps takes one --min-separation");
      barrier_options.min_separation = bench_options.min_separations.front();
      barrier_options.repetitions = bench_options.repetitions;
      barrier_options.json = bench_options.json;
      try {
        return exactccd::oracle::run_barrier_report(barrier_options, stdout);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());  // a delta out of range
      }
    }
    for (CLI::Option* option : {bench_barrier_scale, bench_barrier_step})
      if (option->count() > 0) throw UsageError(option->get_name() + " needs --barrier-steps");
    if (bench_rigid_count->count() > 0) throw UsageError("--rigid-count needs --rigid");
    if (bench->parsed()) {
      for (CLI::Option* option : {bench_resolution, bench_steps, bench_seed})
        if (option->count() > 0 && !bench_options.simulation)
          throw UsageError(option->get_name() + " needs --simulation");
      bench_options.type = parse_type_name(bench_type);
      bench_options.primitive = exactccd::primitive_kind_from_name(bench_type);
      bench_options.modes.clear();
      for (const std::string& name : bench_modes)
        bench_options.modes.push_back(*parse_mode_name(name));
      return run_bench(bench_options);
    }
    if (rigid->parsed()) {
      if (rigid_min_separation_option->count() > 0)
        rigid_options.min_separation = rigid_min_separation;
      return run_rigid(rigid_options);
    }
    if (generate->parsed()) {
      if (generate_min_separation_option->count() > 0)
        generate_options.min_separation = generate_min_separation;
      if (!generate_type.empty())
        generate_options.primitive = exactccd::primitive_kind_from_name(generate_type);
      return run_generate(generate_options);
    }
    if (inspect->parsed()) {
      inspect_options.type = parse_type_name(inspect_type);
      inspect_options.primitive = exactccd::primitive_kind_from_name(inspect_type);
      inspect_options.settings.mode = *parse_mode_name(inspect_mode);
      if (inspect_step_option->count() > 0) inspect_options.step = inspect_step;
      inspect_options.mode_given = inspect->get_option("--mode")->count() > 0;
      inspect_options.t_max_given = inspect->get_option("--t-max")->count() > 0;
      inspect_options.min_separation_given = inspect->get_option("--min-separation")->count() > 0;
      inspect_options.index_given = inspect->get_option("--index")->count() > 0;
      inspect_options.html_given = inspect->get_option("--html")->count() > 0;
      return run_inspect(inspect_options);
    }
    grade_options.type = parse_type_name(grade_type);
    grade_options.primitive = exactccd::primitive_kind_from_name(grade_type);
    return run_grade(grade_options);
  });
}
