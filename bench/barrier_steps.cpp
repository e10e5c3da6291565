// Barrier-method trial steps (issue 27) through exactccd::Scene: the report of
// oracle/barrier_report.hpp over the steps of corpus/barrier_steps.hpp (also
// `exactccd bench --barrier-steps`).
//
//   exactccd_barrier_steps [--scale S] [--min-separation D] [--repetitions R] [--json]
//                          [--compare-off] [--earliest-only] [--steps NAME...]
// (--compare-off also runs each step with the cull by time off, after it on: its candidates
// can take gigabytes; the peak memory printed after "on" is the process's up to then.)
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "corpus/barrier_steps.hpp"
#include "oracle/barrier_report.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Barrier-method trial steps through exactccd::Scene (issue 27)"};
  exactccd::oracle::BarrierReportOptions o;
  app.add_option("--scale", o.scale, "Mesh resolution factor (1: 20k-650k triangles)")
      ->check(CLI::Range(0.01, 20.0));
  app.add_option("--min-separation", o.min_separation, "Minimum separation of every pair")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--repetitions", o.repetitions, "Timed runs per figure (median)")
      ->check(CLI::Range(1, 100));
  app.add_flag("--json", o.json, "One JSON object per step and setting");
  app.add_flag("--compare-off", o.compare_off,
               "Also run each step with the cull by time off (same answers, checked)");
  app.add_flag("--earliest-only", o.earliest_only,
               "Time earliest_contact only (find_contacts runs once, for the checks)");
  app.add_option("--steps", o.steps, "Run only these steps (default: all)")
      ->check(CLI::IsMember(exactccd::corpus::barrier_step_names()));
  CLI11_PARSE(app, argc, argv);
  try {
    return exactccd::oracle::run_barrier_report(o, stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exactccd_barrier_steps: %s\n", e.what());
    return 2;
  }
}
