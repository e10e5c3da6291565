// The barrier-step report (`exactccd bench --barrier-steps`, bench/exactccd_barrier_steps): each
// trial step of corpus/barrier_steps.hpp through exactccd::Scene, with per step its triangles,
// candidates, cuts by time, colliding pairs, earliest contact, the median time of
// earliest_contact and find_contacts on 1 and 2 threads, and its peak memory. Checked
// on the way: earliest_contact equals find_contacts().earliest, and with `compare_off` the cull
// by time changes no answer.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace exactccd::oracle {

struct BarrierReportOptions {
  double scale = 1.0;           ///< mesh resolution factor (corpus::barrier_step)
  double min_separation = 0.0;  ///< SceneOptions::min_separation of every step
  int repetitions = 3;          ///< timed runs per figure (median)
  bool json = false;            ///< one JSON object per step and setting
  bool compare_off = false;     ///< also each step with the cull by time off (same answers)
  bool earliest_only = false;   ///< time earliest_contact only (find_contacts runs once)
  std::vector<std::string> steps;  ///< the steps to run (empty: all)
};

/// Runs the report to `out`. Returns 0, or 1 when a check failed (named on stderr). Throws
/// std::invalid_argument for an unknown step, a scale or separation out of range, or fewer than
/// one repetition.
int run_barrier_report(const BarrierReportOptions& options, std::FILE* out);

}  // namespace exactccd::oracle
