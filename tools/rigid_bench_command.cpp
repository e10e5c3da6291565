#include "rigid_bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "bench_timing.hpp"
#include "corpus/rigid_queries.hpp"
#include "exactccd/rigid.hpp"
#include "oracle/common.hpp"
#include "oracle/names.hpp"

namespace exactccd::cli {

namespace {

using oracle::UsageError;

/// The seeded queries: vertex-face then edge-edge, each a third with the second body turning,
/// moving linearly and at rest.
struct RigidSet {
  std::vector<RigidVertexFaceQuery> vertex_face;
  std::vector<RigidEdgeEdgeQuery> edge_edge;
  std::size_t size() const { return vertex_face.size() + edge_edge.size(); }
};

RigidSet make_set(std::size_t count, std::uint64_t seed) {
  using rigid_queries::OtherMotion;
  RigidSet set;
  const OtherMotion kinds[3] = {OtherMotion::rigid, OtherMotion::linear, OtherMotion::rest};
  const std::size_t per_type[2] = {count / 2, count - count / 2};
  for (int type = 0; type < 2; ++type)
    for (int k = 0; k < 3; ++k) {
      const std::size_t n = per_type[type] / 3 + (static_cast<std::size_t>(k) < per_type[type] % 3);
      rigid_queries::RigidQueryOptions o;
      o.other = kinds[k];
      const std::uint64_t group_seed = seed * 6 + static_cast<std::uint64_t>(3 * type + k);
      if (type == 0) {
        const auto q = rigid_queries::random_rigid_vertex_face(group_seed, n, o);
        set.vertex_face.insert(set.vertex_face.end(), q.begin(), q.end());
      } else {
        const auto q = rigid_queries::random_rigid_edge_edge(group_seed, n, o);
        set.edge_edge.insert(set.edge_edge.end(), q.begin(), q.end());
      }
    }
  return set;
}

/// A side's vertex i at s = 1 from x0, its position at s = 0 (in doubles: only a scale).
Eigen::Vector3d end_of(const SideMotion& side, const Eigen::Vector3d& x0, std::size_t i) {
  return side.kind == PathKind::rigid ? position_at(side.rigid, x0, 1.0) : side.linear_end[i];
}

/// The diagonal of the box of every query's positions at s = 0 and s = 1: the set's size, which
/// --relative-separation multiplies.
double set_size(const RigidSet& set) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  const auto add = [&](const SideMotion& side, std::initializer_list<Eigen::Vector3d> start) {
    std::size_t i = 0;
    for (const Eigen::Vector3d& x : start) {
      for (const Eigen::Vector3d& y : {x, end_of(side, x, i++)}) {
        lo = lo.cwiseMin(y);
        hi = hi.cwiseMax(y);
      }
    }
  };
  for (const RigidVertexFaceQuery& q : set.vertex_face) {
    add(q.vertex, {q.p});
    add(q.face, {q.a, q.b, q.c});
  }
  for (const RigidEdgeEdgeQuery& q : set.edge_edge) {
    add(q.edge_a, {q.ea0, q.ea1});
    add(q.edge_b, {q.eb0, q.eb1});
  }
  return set.size() == 0 ? 0.0 : (hi - lo).norm();
}

volatile std::size_t g_sink;  // keeps the batch passes' results observable

struct ModeRun {
  Mode mode = Mode::filtered;
  double delta = 0.0;    // the minimum separation of the run (0: contact)
  double factor = -1.0;  // delta / size as given with --relative-separation; -1: delta absolute
  double mean_ns = 0.0, median_ns = 0.0;
  std::size_t contacts = 0;
  std::vector<std::size_t> stage_counts;  // by Stage value
  std::vector<CcdResult> answers;         // vertex-face, then edge-edge

  double stage_share(Stage s) const {
    return answers.empty() ? 0.0
                           : static_cast<double>(stage_counts[static_cast<std::size_t>(s)]) /
                                 static_cast<double>(answers.size());
  }
};

ModeRun measure(const RigidSet& set, Mode mode, double delta, int repetitions,
                double overhead_ns) {
  CcdOptions options;
  options.mode = mode;
  options.min_separation = delta;
  ModeRun run;
  run.mode = mode;
  run.delta = delta;
  run.stage_counts.assign(oracle::all_stages().size(), 0);
  run.answers.reserve(set.size());
  std::vector<double> per_query;
  per_query.reserve(set.size());
  auto record = [&](const CcdResult& r, Clock::duration d) {
    per_query.push_back(nanoseconds(d));
    run.answers.push_back(r);
    run.contacts += r.collides;
    ++run.stage_counts[static_cast<std::size_t>(r.decided_by)];
  };
  for (const RigidVertexFaceQuery& q : set.vertex_face) {
    const auto start = Clock::now();
    const RigidCcdResult r = vertex_face_ccd(q, options);
    record(r.ccd, Clock::now() - start);
  }
  for (const RigidEdgeEdgeQuery& q : set.edge_edge) {
    const auto start = Clock::now();
    const RigidCcdResult r = edge_edge_ccd(q, options);
    record(r.ccd, Clock::now() - start);
  }
  double sum = 0.0;
  for (const double ns : per_query) sum += ns;
  run.median_ns = median(per_query) - overhead_ns;
  if (mode == Mode::exact) {  // milliseconds per query: the single calls' mean, no repetitions
    run.mean_ns = sum / static_cast<double>(per_query.size()) - overhead_ns;
    return run;
  }
  std::vector<double> per_pass;
  for (int rep = 0; rep < repetitions; ++rep) {
    std::size_t contacts = 0;
    const auto start = Clock::now();
    for (const RigidVertexFaceQuery& q : set.vertex_face)
      contacts += vertex_face_ccd(q, options).ccd.collides;
    for (const RigidEdgeEdgeQuery& q : set.edge_edge)
      contacts += edge_edge_ccd(q, options).ccd.collides;
    const auto stop = Clock::now();
    g_sink = contacts;
    per_pass.push_back(nanoseconds(stop - start) / static_cast<double>(set.size()));
  }
  run.mean_ns = median(per_pass);
  return run;
}

/// float_only's errors against a certified run: contacts it invents or misses, and contacts
/// both find whose reported toi_lo lies after the certified toi_hi (not conservative).
struct FloatOnlyErrors {
  std::size_t false_positives = 0, false_negatives = 0, late = 0;
};

FloatOnlyErrors float_only_errors(const ModeRun& float_only, const ModeRun& certified) {
  FloatOnlyErrors e;
  for (std::size_t i = 0; i < float_only.answers.size(); ++i) {
    const CcdResult &x = float_only.answers[i], &y = certified.answers[i];
    e.false_positives += x.collides && !y.collides;
    e.false_negatives += !x.collides && y.collides;
    e.late += x.collides && y.collides && x.toi_lo > y.toi_hi;
  }
  return e;
}

/// Queries whose answers (verdict, toi_lo, toi_hi) differ between the two runs.
std::size_t disagreements(const ModeRun& a, const ModeRun& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.answers.size(); ++i) {
    const CcdResult &x = a.answers[i], &y = b.answers[i];
    n += x.collides != y.collides || x.toi_lo != y.toi_lo || x.toi_hi != y.toi_hi;
  }
  return n;
}

/// The runs of one delta, one per mode, and how they compare: the certified ones with the first
/// of them (the reference), float_only graded against it.
struct DeltaRuns {
  std::vector<ModeRun> runs;

  const ModeRun* reference() const {
    for (const ModeRun& r : runs)
      if (r.mode != Mode::float_only) return &r;
    return nullptr;
  }
  const ModeRun* of(Mode mode) const {
    for (const ModeRun& r : runs)
      if (r.mode == mode) return &r;
    return nullptr;
  }
  /// Queries on which a certified run differs from the reference, summed over the runs.
  std::size_t disagreeing() const {
    std::size_t n = 0;
    for (const ModeRun& r : runs)
      if (r.mode != Mode::float_only && &r != reference()) n += disagreements(*reference(), r);
    return n;
  }
  /// filtered's mean over exact's, when both ran (0 otherwise).
  double ratio() const {
    const ModeRun *filtered = of(Mode::filtered), *exact = of(Mode::exact);
    return filtered && exact && exact->mean_ns > 0 ? filtered->mean_ns / exact->mean_ns : 0.0;
  }
};

using Json = nlohmann::ordered_json;

Json json_of(const ModeRun& r, const DeltaRuns& group, const std::vector<Stage>& stages) {
  Json m;
  m["mode"] = to_string(r.mode);
  m["min_separation"] = r.delta;
  if (r.factor >= 0) m["min_separation_factor"] = r.factor;
  m["mean_ns"] = r.mean_ns;
  m["median_ns"] = r.median_ns;
  m["contacts"] = r.contacts;
  Json shares = Json::object();
  for (const Stage s : stages) shares[to_string(s)] = r.stage_share(s);
  m["stage_share"] = std::move(shares);
  const ModeRun* reference = group.reference();
  if (r.mode == Mode::float_only && reference) {
    const FloatOnlyErrors e = float_only_errors(r, *reference);
    m["graded_against"] = to_string(reference->mode);
    m["false_positives"] = e.false_positives;
    m["false_negatives"] = e.false_negatives;
    m["late_tois"] = e.late;
  }
  if (r.mode == Mode::filtered && group.ratio() > 0) m["mean_ratio_over_exact"] = group.ratio();
  return m;
}

void print_json(const RigidBenchOptions& options, const RigidSet& set, double size,
                double overhead_ns, const std::vector<DeltaRuns>& groups,
                const std::vector<Stage>& stages, std::size_t disagreeing) {
  Json j;
  j["queries"] = set.size();
  j["vertex_face"] = set.vertex_face.size();
  j["edge_edge"] = set.edge_edge.size();
  j["seed"] = options.seed;
  j["repetitions"] = options.repetitions;
  j["timer_overhead_ns"] = overhead_ns;
  j["size"] = size;
  Json modes = Json::array();
  for (const DeltaRuns& g : groups)
    for (const ModeRun& r : g.runs) modes.push_back(json_of(r, g, stages));
  j["modes"] = std::move(modes);
  // The first delta's (the only one by default), as before deltas could be given.
  if (groups.front().ratio() > 0) j["mean_ratio_filtered_over_exact"] = groups.front().ratio();
  j["disagreements"] = disagreeing;
  std::cout << j.dump(2) << '\n';
}

void print_text(const RigidBenchOptions& options, const RigidSet& set, double size,
                double overhead_ns, const std::vector<DeltaRuns>& groups,
                const std::vector<Stage>& stages, std::size_t disagreeing) {
  // The delta column (and the delta after each summary line) only when some delta is set.
  bool separation = false;
  for (const DeltaRuns& g : groups) separation = separation || g.runs.front().delta > 0;
  std::printf(
      "rigid pairs near contact: %zu queries (%zu vertex-face, %zu edge-edge; a third each with "
      "the other body turning, linear, at rest), seed %llu\n",
      set.size(), set.vertex_face.size(), set.edge_edge.size(),
      static_cast<unsigned long long>(options.seed));
  std::printf(
      "single thread; mean_ns: median over %d passes of (pass time / queries), for exact the "
      "mean of the single timed calls (milliseconds each); median_ns: median of single-query "
      "times; both less the empty timed region (%.1f ns); last columns: share of queries "
      "decided by each stage\n",
      options.repetitions, overhead_ns);
  if (options.relative_separation)
    std::printf("size (box diagonal at s = 0 and s = 1) %.6g; delta = factor x size\n", size);
  if (separation)
    std::printf("delta > 0: contact when the primitives come within delta, the TOI the earliest "
                "such s\n");
  std::printf("%-10s", "mode");
  if (separation) std::printf(" %10s", "delta");
  std::printf(" %9s %12s %12s %9s", "queries", "mean_ns", "median_ns", "contacts");
  for (const Stage s : stages) std::printf(" %16s", to_string(s));
  std::printf("\n");
  for (const DeltaRuns& g : groups)
    for (const ModeRun& r : g.runs) {
      std::printf("%-10s", to_string(r.mode));
      if (separation) std::printf(" %10.3g", r.delta);
      std::printf(" %9zu %12.1f %12.1f %9zu", r.answers.size(), r.mean_ns, r.median_ns,
                  r.contacts);
      for (const Stage s : stages) std::printf(" %15.2f%%", 100.0 * r.stage_share(s));
      std::printf("\n");
    }
  for (const DeltaRuns& g : groups) {
    char at[64] = "";
    if (separation) std::snprintf(at, sizeof at, " at delta %.17g", g.runs.front().delta);
    const ModeRun *filtered = g.of(Mode::filtered), *exact = g.of(Mode::exact);
    if (g.ratio() > 0)
      std::printf("filtered / exact%s: mean %.4g (%.1fx faster), median %.4g\n", at, g.ratio(),
                  1.0 / g.ratio(),
                  exact->median_ns > 0 ? filtered->median_ns / exact->median_ns : 0.0);
    const ModeRun* reference = g.reference();
    for (const ModeRun& r : g.runs) {
      if (r.mode != Mode::float_only || !reference) continue;
      const FloatOnlyErrors e = float_only_errors(r, *reference);
      std::printf(
          "float_only against %s%s (uncertified, not counted as disagreements): %zu false "
          "positives, %zu false negatives, %zu late TOIs\n",
          to_string(reference->mode), at, e.false_positives, e.false_negatives, e.late);
    }
  }
  std::printf("disagreements between modes (verdict, toi_lo, toi_hi): %zu\n", disagreeing);
}

}  // namespace

int run_rigid_bench(const RigidBenchOptions& options) {
  if (options.count < 1) throw UsageError("--rigid-count must be at least 1");
  if (options.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  if (options.modes.empty()) throw UsageError("--modes names no mode");
  if (options.min_separations.empty()) throw UsageError("--min-separation names no delta");

  const RigidSet set = make_set(options.count, options.seed);
  const double size = set_size(set);
  // Every delta checked before any is timed: a bad one is refused at once.
  std::vector<double> deltas;
  for (const double separation : options.min_separations) {
    deltas.push_back(options.relative_separation ? separation * size : separation);
    oracle::validate_min_separation(deltas.back());
  }
  const double overhead_ns = timer_overhead_ns();
  std::vector<DeltaRuns> groups;
  for (std::size_t k = 0; k < deltas.size(); ++k) {
    DeltaRuns g;
    for (const Mode m : options.modes) {
      g.runs.push_back(measure(set, m, deltas[k], options.repetitions, overhead_ns));
      if (options.relative_separation) g.runs.back().factor = options.min_separations[k];
    }
    groups.push_back(std::move(g));
  }
  // The certified modes must agree exactly at each delta (the exit status); float_only
  // (uncertified) is graded against the first certified mode of its delta instead.
  std::size_t disagreeing = 0;
  for (const DeltaRuns& g : groups) disagreeing += g.disagreeing();

  const bool any_float_only = std::find(options.modes.begin(), options.modes.end(),
                                        Mode::float_only) != options.modes.end();
  std::vector<Stage> stages;  // every stage (float_only only when that mode runs)
  for (const Stage st : oracle::all_stages())
    if (st != Stage::float_only || any_float_only) stages.push_back(st);
  if (options.json)
    print_json(options, set, size, overhead_ns, groups, stages, disagreeing);
  else
    print_text(options, set, size, overhead_ns, groups, stages, disagreeing);
  return disagreeing == 0 ? 0 : 1;
}

}  // namespace exactccd::cli
