// `exactccd bench --rigid`: time per query of the rigid-body modes (filtered, exact, and on
// request float_only) on seeded random rigid pairs near contact (corpus/rigid_queries.hpp), with
// the certified modes' answers checked against each other bit for bit and float_only's graded
// against the first certified mode (false positives, false negatives, late TOIs); each minimum
// separation delta (--min-separation) is one such run of every mode, graded at that delta.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::cli {

struct RigidBenchOptions {
  /// Queries in all: half vertex-face, half edge-edge; of each, a third each with the second
  /// body turning, moving linearly (a deformable mesh) and at rest.
  std::size_t count = 20000;
  std::uint64_t seed = 1;
  std::vector<Mode> modes = {Mode::filtered, Mode::exact};
  /// Batch passes per mode but exact; mean_ns is their median. Exact (milliseconds per query)
  /// is timed by its single calls only.
  int repetitions = 5;
  bool json = false;
  /// --min-separation: each delta (or factor, with relative_separation) is one run per mode.
  std::vector<double> min_separations = {0.0};
  /// --relative-separation: the deltas are factors of the query set's size (the diagonal of the
  /// box of every position at s = 0 and s = 1).
  bool relative_separation = false;
};

/// Runs the benchmark. Exit status 1 when two certified modes (filtered, exact) give different
/// answers to a query (verdict, toi_lo or toi_hi) at some delta, else 0; float_only's errors
/// are reported, not counted. Throws UsageError for an empty query set, mode list or list of
/// deltas, or a delta that is negative or not finite.
int run_rigid_bench(const RigidBenchOptions& options);

}  // namespace exactccd::cli
