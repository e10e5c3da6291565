// Scene-level CCD benchmark (issue 5 targets): one step of a folded cloth of about 100,000
// triangles with self-collision, on 1 and 2 threads; the earliest-contact call against the
// all-pairs call on the same step; the candidate pairs against the pairs whose swept boxes
// actually overlap, counted independently (a uniform grid, corpus/broad_phase.hpp).
//
//   ./build/bench/scene_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// A second case, a fast body crossing a static sheet in one step, shows the earliest-contact call
// where contacts are many and spread over the step.
//
// Minimum separation (issue 12 target: at most 1.5x): the same cloth step, one thread, with
// SceneOptions::min_separation = 1e-4 of the cloth's size against 0, in the same run:
//
//   ./build/bench/scene_bench --benchmark_filter='cloth_step/min_separation' \
//       --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// The first run of each all-pairs case prints how its candidates were decided (each pair's test
// run alone, its stage and time): where the time goes when the ratio is high; counters
// by_culling, by_filter, by_exact hold the same counts.
//
// The cloth: an n x n grid folded over itself (two layers joined by a half-cylinder), wrinkled;
// over the step the upper layer falls towards the lower one by more than the gap in places, so
// the step has contacts. Each iteration sets the step's motion (so the hierarchies are refitted,
// as in a new step) and runs the call.
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "corpus/meshes.hpp"
#include "corpus/broad_phase.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/scene.hpp"

namespace {

using exactccd::Positions;
using exactccd::Triangles;

constexpr double pi = 3.14159265358979323846;

struct FoldedCloth {
  int n = 0;
  Triangles triangles;
  Positions start, end;
};

/// Point of the folded sheet at arc-length coordinate u in [0, 1] and width coordinate v.
Eigen::Vector3d fold(double u, double v, double radius, double wrinkle, double phase) {
  // Lower layer longer than the upper one, and not by a whole number of grid cells: the
  // layers' grid lines do not coincide.
  const double half = 0.53 - pi * radius / 2;
  double x, z;
  if (u <= half) {
    x = u;
    z = 0;
  } else if (u <= half + pi * radius) {
    const double phi = (u - half) / radius;
    x = half + radius * std::sin(phi);
    z = radius - radius * std::cos(phi);
  } else {
    x = half - (u - half - pi * radius);
    z = 2 * radius;
  }
  z += wrinkle * std::sin(9 * pi * v + phase) * std::sin(7 * pi * x + phase);
  // A slight shear along the fold, for the same reason (aligned grids make every crossing a
  // degenerate contact on an edge, which only the exact path decides).
  const double y = v + 0.0123 * (z + x * x);
  return {x, y, z};
}

/// How far the upper layer drops at the bumps, in gaps between the layers: 0.5 never reaches
/// the lower layer (no contact), 1.05 reaches it at the end of the step, 2 halfway through.
FoldedCloth make_cloth(int n, double drop_in_gaps) {
  FoldedCloth c;
  c.n = n;
  const double h = 1.0 / (n - 1);
  const double radius = 3 * h;  // layers 6 edge lengths apart
  c.start.resize(n * n, 3);
  c.end.resize(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = i * h, v = j * h;
      const Eigen::Vector3d x0 = fold(u, v, radius, 0.5 * h, 0.0);
      // Over the step the upper layer sags towards the lower one; at a few bumps it drops by
      // slightly more than the gap, so the layers meet there (the step has contacts).
      Eigen::Vector3d x1 = fold(u, v, radius, 0.75 * h, 0.3);
      if (x0.z() > radius) {
        // Full drop away from the fold, none at the fold itself (the fold keeps its shape).
        const double from_fold = std::min(1.0, std::max(0.0, (0.53 - pi * radius / 2 - x0.x()) / 0.1));
        const double bump = std::pow((0.5 + 0.5 * std::sin(3 * pi * v)) *
                                         (0.5 + 0.5 * std::sin(5 * pi * x0.x())),
                                     8);
        x1.z() -= from_fold * 2 * radius * (0.5 + (drop_in_gaps - 0.5) * bump);
      }
      x1.x() += 0.3 * h;
      c.start.row(i * n + j) = x0.transpose();
      c.end.row(i * n + j) = x1.transpose();
    }
  c.triangles.resize(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + 1, cc = a + n, d = cc + 1;
      c.triangles.row(f++) << a, cc, b;
      c.triangles.row(f++) << b, cc, d;
    }
  return c;
}

/// The scenarios: no contact, contact at the end of the step, contact halfway.
constexpr double kDrops[] = {0.5, 1.05, 2.0};
const char* const kScenarioNames[] = {"no_contact", "late_contact", "mid_contact"};

/// 224 x 224 vertices: 99,458 triangles.
const FoldedCloth& cloth(int scenario) {
  static const FoldedCloth c[] = {make_cloth(224, kDrops[0]), make_cloth(224, kDrops[1]),
                                  make_cloth(224, kDrops[2])};
  return c[scenario];
}

/// The cloth's size: the longest side of its box at the start of the step (about 1).
double cloth_size(const FoldedCloth& c) {
  return (c.start.colwise().maxCoeff() - c.start.colwise().minCoeff()).maxCoeff();
}

/// The minimum separation of the min_separation benchmarks: 1e-4 of the cloth's size.
double separation_of(const FoldedCloth& c) { return 1e-4 * cloth_size(c); }

/// One cloth step per iteration with `options` (scenario: state.range(0)).
template <bool Earliest>
void run_cloth_step(benchmark::State& state, const exactccd::SceneOptions& options) {
  const FoldedCloth& c = cloth(static_cast<int>(state.range(0)));
  state.SetLabel(kScenarioNames[state.range(0)]);
  exactccd::Scene scene;
  const exactccd::MeshId id = scene.add_mesh(c.start, c.triangles);
  scene.set_motion(id, c.start, c.end);
  // Builds the hierarchies once, as the first step would (with the measured call: with a
  // minimum separation an all-pairs call can take a minute, which earliest need not pay).
  if constexpr (Earliest)
    scene.earliest_contact(options);
  else
    scene.find_contacts(options);
  std::size_t contacts = 0, candidates = 0, tests = 0, built = 0;
  for (auto _ : state) {
    scene.set_motion(id, c.start, c.end);  // marks the hierarchies for a refit, as a new step
    if constexpr (Earliest) {
      const auto r = scene.earliest_contact(options);
      contacts = r.collides ? 1 : 0;
      candidates = r.stats.vertex_face_candidates + r.stats.edge_edge_candidates;
      tests = r.stats.narrow_phase_tests;
      built += r.stats.hierarchies_built;
      benchmark::DoNotOptimize(r.contact.toi_lo);
    } else {
      const auto r = scene.find_contacts(options);
      contacts = r.contacts.size();
      candidates = r.stats.vertex_face_candidates + r.stats.edge_edge_candidates;
      tests = r.stats.narrow_phase_tests;
      built += r.stats.hierarchies_built;
      benchmark::DoNotOptimize(r.contacts.data());
    }
  }
  state.counters["triangles"] = static_cast<double>(c.triangles.rows());
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["narrow_tests"] = static_cast<double>(tests);
  state.counters["rebuilds"] = static_cast<double>(built);
}

template <bool Earliest>
void BM_ClothStep(benchmark::State& state) {
  exactccd::SceneOptions options;
  options.max_threads = static_cast<int>(state.range(1));
  run_cloth_step<Earliest>(state, options);
}
// Arguments: scenario (0 no contact, 1 late contact, 2 mid-step contact), threads.
BENCHMARK_TEMPLATE(BM_ClothStep, false)->Name("cloth_step/all_pairs")
    ->ArgsProduct({{0, 1, 2}, {1, 2}})->ArgNames({"scenario", "threads"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_ClothStep, true)->Name("cloth_step/earliest")
    ->ArgsProduct({{1, 2}, {1, 2}})->ArgNames({"scenario", "threads"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

/// How the cloth step's candidates are decided with a given min_separation: each candidate's
/// test run again alone (one thread, outside the timed loop), its stage counted and its time
/// summed per stage. Computed once per (scenario, delta) and printed then.
struct StageReport {
  static constexpr int kStages = static_cast<int>(exactccd::Stage::float_only) + 1;
  std::size_t candidates = 0, contacts = 0;
  std::array<std::size_t, kStages> count{};
  std::array<double, kStages> seconds{};
};

const StageReport& stage_report(int scenario, bool with_delta) {
  using exactccd::Stage;
  static StageReport reports[3][2];
  static bool done[3][2] = {};
  StageReport& report = reports[scenario][with_delta ? 1 : 0];
  if (done[scenario][with_delta ? 1 : 0]) return report;
  done[scenario][with_delta ? 1 : 0] = true;
  const FoldedCloth& c = cloth(scenario);
  const double delta = with_delta ? separation_of(c) : 0.0;
  exactccd::Scene scene;
  const exactccd::MeshId id = scene.add_mesh(c.start, c.triangles);
  scene.set_motion(id, c.start, c.end);
  exactccd::SceneOptions options;
  options.max_threads = 1;
  options.record_candidates = true;
  options.min_separation = delta;
  const auto r = scene.find_contacts(options);
  report.candidates = r.candidates.size();
  report.contacts = r.contacts.size();
  exactccd::CcdOptions ccd;
  ccd.min_separation = delta;
  for (const exactccd::ScenePair& p : r.candidates) {
    const auto start = std::chrono::steady_clock::now();
    const exactccd::CcdResult t = p.type == exactccd::QueryType::vertex_face
                                      ? exactccd::vertex_face_ccd(scene.vertex_face_query(p), ccd)
                                      : exactccd::edge_edge_ccd(scene.edge_edge_query(p), ccd);
    const auto stage = static_cast<std::size_t>(t.decided_by);
    ++report.count[stage];
    report.seconds[stage] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::printf("cloth %s, min_separation %.3g: %zu candidates, %zu contacts; by stage:",
              kScenarioNames[scenario], delta, report.candidates, report.contacts);
  for (int s = 0; s < StageReport::kStages; ++s) {
    const auto k = static_cast<std::size_t>(s);
    if (report.count[k] != 0)
      std::printf(" %s %zu (%.1f ms)", exactccd::to_string(static_cast<Stage>(s)),
                  report.count[k], 1e3 * report.seconds[k]);
  }
  std::printf("\n");
  std::fflush(stdout);
  return report;
}

/// The cloth step on one thread with min_separation 0 or 1e-4 of the cloth's size (issue 12);
/// for the all-pairs call, counters of the pairs each stage decided (from stage_report).
template <bool Earliest>
void BM_ClothStepSeparation(benchmark::State& state) {
  const int scenario = static_cast<int>(state.range(0));
  const bool with_delta = state.range(1) != 0;
  exactccd::SceneOptions options;
  options.max_threads = 1;
  options.min_separation = with_delta ? separation_of(cloth(scenario)) : 0.0;
  run_cloth_step<Earliest>(state, options);
  state.counters["min_separation"] = options.min_separation;
  if constexpr (!Earliest) {
    using exactccd::Stage;
    const StageReport& stages = stage_report(scenario, with_delta);
    const auto count = [&](Stage s) {
      return static_cast<double>(stages.count[static_cast<std::size_t>(s)]);
    };
    state.counters["by_culling"] = count(Stage::culling);
    state.counters["by_filter"] = count(Stage::filter) + count(Stage::filter_exact_toi);
    state.counters["by_exact"] = count(Stage::exact_at_double) + count(Stage::exact);
  }
}
// Arguments: scenario, delta (0: none, 1: 1e-4 of the cloth's size).
BENCHMARK_TEMPLATE(BM_ClothStepSeparation, false)->Name("cloth_step/min_separation/all_pairs")
    ->ArgsProduct({{0, 1, 2}, {0, 1}})->ArgNames({"scenario", "delta"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_ClothStepSeparation, true)->Name("cloth_step/min_separation/earliest")
    ->ArgsProduct({{1, 2}, {0, 1}})->ArgNames({"scenario", "delta"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

/// The older scheme on the same step: hierarchies over the positions at the two instants. Its
/// cost, and the contacts it misses (counted against the swept hierarchy's, same step).
void BM_ClothStepStaticScheme(benchmark::State& state) {
  const FoldedCloth& c = cloth(static_cast<int>(state.range(0)));
  state.SetLabel(kScenarioNames[state.range(0)]);
  exactccd::Scene scene;
  const exactccd::MeshId id = scene.add_mesh(c.start, c.triangles);
  scene.set_motion(id, c.start, c.end);
  exactccd::SceneOptions options;
  options.max_threads = static_cast<int>(state.range(1));
  const std::size_t swept_contacts = scene.find_contacts(options).contacts.size();
  options.broad_phase = exactccd::BroadPhase::static_bvh;
  scene.find_contacts(options);
  std::size_t contacts = 0, candidates = 0;
  for (auto _ : state) {
    scene.set_motion(id, c.start, c.end);
    const auto r = scene.find_contacts(options);
    contacts = r.contacts.size();
    candidates = r.stats.vertex_face_candidates + r.stats.edge_edge_candidates;
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["missed"] = static_cast<double>(swept_contacts - contacts);
  state.counters["candidates"] = static_cast<double>(candidates);
}
BENCHMARK(BM_ClothStepStaticScheme)->Name("cloth_step/static_bvh")
    ->ArgsProduct({{1, 2}, {2}})->ArgNames({"scenario", "threads"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

/// The cloth step (2 threads) with the certified contact geometry of every contact
/// (Scene::contact_geometry, serially after find_contacts), against find_contacts alone in
/// cloth_step/all_pairs (issue 28: the cost of asking for the geometry).
void BM_ClothStepWithGeometry(benchmark::State& state) {
  const FoldedCloth& c = cloth(static_cast<int>(state.range(0)));
  state.SetLabel(kScenarioNames[state.range(0)]);
  exactccd::Scene scene;
  const exactccd::MeshId id = scene.add_mesh(c.start, c.triangles);
  scene.set_motion(id, c.start, c.end);
  exactccd::SceneOptions options;
  options.max_threads = 2;
  scene.find_contacts(options);
  std::size_t contacts = 0, resolved = 0;
  for (auto _ : state) {
    scene.set_motion(id, c.start, c.end);
    const auto r = scene.find_contacts(options);
    contacts = r.contacts.size();
    resolved = 0;
    for (const exactccd::SceneContact& contact : r.contacts)
      resolved += scene.contact_geometry(contact).kind == exactccd::ContactKind::point;
    benchmark::DoNotOptimize(resolved);
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["point_kind"] = static_cast<double>(resolved);
}
BENCHMARK(BM_ClothStepWithGeometry)->Name("cloth_step/all_pairs_with_geometry")
    ->DenseRange(1, 2)->ArgNames({"scenario"})->Unit(benchmark::kMillisecond)->UseRealTime();

/// A fast body through a static sheet within one step: a sphere (uv, 48 x 24: 2,208 triangles)
/// of radius 0.2 crossing a 128 x 128-cell sheet (32,768 triangles) from 0.25 above to 0.25
/// below; its first contact is near t = 0.1 and tens of thousands of pairs collide. This is the case
/// the earliest-contact call is for: once a contact is known, pairs that could only meet later
/// are culled over the shortened window.
void BM_ImpactStep(benchmark::State& state) {
  static const auto sheet = exactccd::scenes::grid_sheet(128, 1.0, {0.5, 0.5, 0.0});
  static const auto body = exactccd::scenes::uv_sphere({0.5013, 0.4987, 0.25}, 0.2, 48, 24);
  static const exactccd::Positions end =
      exactccd::scenes::translated(body.positions, {0.0123, -0.0077, -0.5});
  exactccd::Scene scene;
  scene.add_static_mesh(sheet.positions, sheet.triangles);
  const exactccd::MeshId id = scene.add_mesh(body.positions, body.triangles);
  exactccd::SceneOptions options;
  options.max_threads = static_cast<int>(state.range(1));
  const bool earliest = state.range(0) == 1;
  state.SetLabel(earliest ? "earliest" : "all_pairs");
  scene.set_motion(id, body.positions, end);
  scene.find_contacts(options);
  std::size_t contacts = 0, tests = 0;
  double toi = 0;
  for (auto _ : state) {
    scene.set_motion(id, body.positions, end);
    if (earliest) {
      const auto r = scene.earliest_contact(options);
      contacts = r.collides ? 1 : 0;
      tests = r.stats.narrow_phase_tests;
      toi = r.contact.toi_lo;
    } else {
      const auto r = scene.find_contacts(options);
      contacts = r.contacts.size();
      tests = r.stats.narrow_phase_tests;
      toi = r.earliest.toi_lo;
    }
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["narrow_tests"] = static_cast<double>(tests);
  state.counters["earliest_toi"] = toi;
}
// Arguments: call (0 all pairs, 1 earliest), threads.
BENCHMARK(BM_ImpactStep)->Name("impact_step")->ArgsProduct({{0, 1}, {1, 2}})
    ->ArgNames({"earliest", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();

/// A floor (issue 28): the same sphere falling onto the floor z = 0, its lowest point from 0.25
/// above to 0.25 below it within one step, the floor given three ways: Scene::add_plane (one certified test
/// per vertex), a static 256 x 256-cell grid (131,072 triangles, the usual mesh floor) and two
/// static triangles. Contacts are point-plane pairs for the plane, vertex-face and edge-edge
/// pairs for the meshes; the earliest contact is the same time.
void BM_FloorStep(benchmark::State& state) {
  static const auto grid = exactccd::scenes::grid_sheet(256, 4.0, {0.5, 0.5, 0.0});
  static const auto body = exactccd::scenes::uv_sphere({0.5013, 0.4987, 0.45}, 0.2, 48, 24);
  static const exactccd::Positions end =
      exactccd::scenes::translated(body.positions, {0.0123, -0.0077, -0.5});
  exactccd::Scene scene;
  const int floor = static_cast<int>(state.range(0));
  const char* const names[] = {"plane", "grid_256x256", "two_triangles"};
  state.SetLabel(names[floor]);
  if (floor == 0) {
    scene.add_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  } else if (floor == 1) {
    scene.add_static_mesh(grid.positions, grid.triangles);
  } else {
    exactccd::Positions x(4, 3);
    x << -1.5, -1.5, 0, 2.5, -1.5, 0, 2.5, 2.5, 0, -1.5, 2.5, 0;
    exactccd::Triangles t(2, 3);
    t << 0, 1, 2, 0, 2, 3;
    scene.add_static_mesh(x, t);
  }
  const exactccd::MeshId id = scene.add_mesh(body.positions, body.triangles);
  exactccd::SceneOptions options;
  options.max_threads = 2;
  options.self_collision = false;
  scene.set_motion(id, body.positions, end);
  scene.find_contacts(options);
  std::size_t contacts = 0, tests = 0;
  double toi = 0;
  for (auto _ : state) {
    scene.set_motion(id, body.positions, end);
    const auto r = scene.find_contacts(options);
    contacts = r.contacts.size();
    tests = r.stats.narrow_phase_tests;
    toi = r.earliest.toi_lo;
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["narrow_tests"] = static_cast<double>(tests);
  state.counters["earliest_toi"] = toi;
}
// Argument: the floor (0 plane, 1 grid mesh, 2 two triangles).
BENCHMARK(BM_FloorStep)->Name("floor_step")->DenseRange(0, 2)->ArgNames({"floor"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

/// Candidates against the pairs whose swept boxes overlap, counted by a different broad phase
/// (uniform grid) over all primitive pairs, pairs sharing a vertex excluded.
void report_candidate_ratio(int scenario) {
  const FoldedCloth& c = cloth(scenario);
  exactccd::Scene scene;
  const exactccd::MeshId id = scene.add_mesh(c.start, c.triangles);
  scene.set_motion(id, c.start, c.end);
  const auto r = scene.find_contacts();
  const exactccd::Edges& edges = scene.edges(id);
  using exactccd::sim::Box;
  auto box_of = [&](std::initializer_list<int> vertices) {
    Box b{{c.start(*vertices.begin(), 0), c.start(*vertices.begin(), 1), c.start(*vertices.begin(), 2)},
          {c.start(*vertices.begin(), 0), c.start(*vertices.begin(), 1), c.start(*vertices.begin(), 2)}};
    for (int v : vertices)
      for (const Positions* x : {&c.start, &c.end})
        for (int k = 0; k < 3; ++k) {
          b.lo[k] = std::min(b.lo[k], (*x)(v, k));
          b.hi[k] = std::max(b.hi[k], (*x)(v, k));
        }
    return b;
  };
  std::vector<Box> vertex_boxes, edge_boxes, face_boxes;
  for (int v = 0; v < c.start.rows(); ++v) vertex_boxes.push_back(box_of({v}));
  for (int e = 0; e < edges.rows(); ++e) edge_boxes.push_back(box_of({edges(e, 0), edges(e, 1)}));
  for (int f = 0; f < c.triangles.rows(); ++f)
    face_boxes.push_back(box_of({c.triangles(f, 0), c.triangles(f, 1), c.triangles(f, 2)}));
  std::size_t vf = 0, ee = 0;
  for (const auto& [v, f] : exactccd::sim::overlapping_pairs(vertex_boxes, face_boxes)) {
    const auto t = c.triangles.row(f);
    if (t(0) != static_cast<int>(v) && t(1) != static_cast<int>(v) && t(2) != static_cast<int>(v)) ++vf;
  }
  for (const auto& [i, j] : exactccd::sim::overlapping_pairs(edge_boxes, edge_boxes)) {
    if (i >= j) continue;
    if (edges(i, 0) == edges(j, 0) || edges(i, 0) == edges(j, 1) || edges(i, 1) == edges(j, 0) ||
        edges(i, 1) == edges(j, 1))
      continue;
    ++ee;
  }
  std::printf(
      "cloth %s, %ld triangles: candidates vertex-face %llu, edge-edge %llu; swept boxes overlapping "
      "(independent grid count) vertex-face %zu, edge-edge %zu; ratio %.3f; contacts %zu\n",
      kScenarioNames[scenario], static_cast<long>(c.triangles.rows()),
      static_cast<unsigned long long>(r.stats.vertex_face_candidates),
      static_cast<unsigned long long>(r.stats.edge_edge_candidates), vf, ee,
      static_cast<double>(r.stats.vertex_face_candidates + r.stats.edge_edge_candidates) /
          static_cast<double>(vf + ee),
      r.contacts.size());
}

}  // namespace

int main(int argc, char** argv) {
  for (int scenario = 0; scenario < 3; ++scenario) report_candidate_ratio(scenario);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
