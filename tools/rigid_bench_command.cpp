#include "rigid_bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
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

volatile std::size_t g_sink;  // keeps the batch passes' results observable

struct ModeRun {
  Mode mode = Mode::filtered;
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

ModeRun measure(const RigidSet& set, Mode mode, int repetitions, double overhead_ns) {
  CcdOptions options;
  options.mode = mode;
  ModeRun run;
  run.mode = mode;
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

}  // namespace

int run_rigid_bench(const RigidBenchOptions& options) {
  if (options.count < 1) throw UsageError("--rigid-count must be at least 1");
  if (options.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  if (options.modes.empty()) throw UsageError("--modes names no mode");

  const RigidSet set = make_set(options.count, options.seed);
  const double overhead_ns = timer_overhead_ns();
  std::vector<ModeRun> runs;
  for (const Mode m : options.modes) runs.push_back(measure(set, m, options.repetitions, overhead_ns));
  // The certified modes must agree exactly (the exit status); float_only (uncertified) is
  // graded against the first certified mode run instead.
  const ModeRun* reference = nullptr;
  const ModeRun* filtered = nullptr;
  const ModeRun* exact = nullptr;
  bool any_float_only = false;
  for (const ModeRun& r : runs) {
    if (r.mode == Mode::float_only) {
      any_float_only = true;
      continue;
    }
    if (!reference) reference = &r;
    (r.mode == Mode::exact ? exact : filtered) = &r;
  }
  std::size_t disagreeing = 0;
  for (const ModeRun& r : runs)
    if (r.mode != Mode::float_only && &r != reference) disagreeing += disagreements(*reference, r);
  const bool ratio = filtered && exact && exact->mean_ns > 0;

  std::vector<Stage> stages;  // every stage (float_only only when that mode runs)
  for (const Stage st : oracle::all_stages())
    if (st != Stage::float_only || any_float_only) stages.push_back(st);
  if (options.json) {
    nlohmann::ordered_json j;
    j["queries"] = set.size();
    j["vertex_face"] = set.vertex_face.size();
    j["edge_edge"] = set.edge_edge.size();
    j["seed"] = options.seed;
    j["repetitions"] = options.repetitions;
    j["timer_overhead_ns"] = overhead_ns;
    nlohmann::ordered_json modes = nlohmann::ordered_json::array();
    for (const ModeRun& r : runs) {
      nlohmann::ordered_json m;
      m["mode"] = to_string(r.mode);
      m["mean_ns"] = r.mean_ns;
      m["median_ns"] = r.median_ns;
      m["contacts"] = r.contacts;
      nlohmann::ordered_json shares = nlohmann::ordered_json::object();
      for (const Stage s : stages) shares[to_string(s)] = r.stage_share(s);
      m["stage_share"] = std::move(shares);
      if (r.mode == Mode::float_only && reference) {
        const FloatOnlyErrors e = float_only_errors(r, *reference);
        m["graded_against"] = to_string(reference->mode);
        m["false_positives"] = e.false_positives;
        m["false_negatives"] = e.false_negatives;
        m["late_tois"] = e.late;
      }
      modes.push_back(std::move(m));
    }
    j["modes"] = std::move(modes);
    if (ratio) j["mean_ratio_default_over_exact"] = filtered->mean_ns / exact->mean_ns;
    j["disagreements"] = disagreeing;
    std::cout << j.dump(2) << '\n';
  } else {
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
    std::printf("%-10s %9s %12s %12s %9s", "mode", "queries", "mean_ns", "median_ns", "contacts");
    for (const Stage s : stages) std::printf(" %16s", to_string(s));
    std::printf("\n");
    for (const ModeRun& r : runs) {
      std::printf("%-10s %9zu %12.1f %12.1f %9zu", to_string(r.mode), r.answers.size(), r.mean_ns,
                  r.median_ns, r.contacts);
      for (const Stage s : stages) std::printf(" %15.2f%%", 100.0 * r.stage_share(s));
      std::printf("\n");
    }
    if (ratio)
      std::printf("default / exact: mean %.4g (%.1fx faster), median %.4g\n",
                  filtered->mean_ns / exact->mean_ns, exact->mean_ns / filtered->mean_ns,
                  exact->median_ns > 0 ? filtered->median_ns / exact->median_ns : 0.0);
    for (const ModeRun& r : runs) {
      if (r.mode != Mode::float_only || !reference) continue;
      const FloatOnlyErrors e = float_only_errors(r, *reference);
      std::printf(
          "float_only against %s (uncertified, not counted as disagreements): %zu false "
          "positives, %zu false negatives, %zu late TOIs\n",
          to_string(reference->mode), e.false_positives, e.false_negatives, e.late);
    }
    std::printf("disagreements between modes (verdict, toi_lo, toi_hi): %zu\n", disagreeing);
  }
  return disagreeing == 0 ? 0 : 1;
}

}  // namespace exactccd::cli
