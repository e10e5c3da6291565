// exactccd's rigid CCD against FCL's continuous collision (fcl::continuousCollide, Debian's FCL
// 0.7) where both sweep the same poses: pure rotations (FCL's screw motion with no translation
// along the axis turns at constant angular speed through the poses of the Cayley motion; FCL's
// time of contact is the fraction of the angle, which is our time t) and pure translations
// (FCL's translation motion; t = s).
//
// Data: seeded random rigid pairs near contact (corpus/rigid_queries.hpp; one side moves, the
// other rests): vertex-face and edge-edge, rotations and translations; and the steps of the
// assembly demonstration (bench/scenes/assembly, the plan that meets the stop rib). Each
// primitive is handed to FCL as the same point set: a Convex shape of its 1, 2 or 3 points, or a
// one-triangle mesh with repeated corners ([p, p, p], [a, b, b]); the exact answer is that of the
// same point sets.
//
// For each FCL setting: false positives and false negatives against the exact verdict, the
// error of FCL's time of contact against the exact contact time, time per query (per step for
// the demonstration), single thread. Prints a Markdown table (the README's) and writes JSON.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench/fcl_comparison/fcl_adapter.hpp"
#include "corpus/assembly/assembly_step.hpp"
#include "corpus/assembly/lock_and_key.hpp"
#include "corpus/rigid_queries.hpp"

namespace {

using namespace exactccd;
using namespace exactccd::fcl_comparison;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;
using Eigen::Vector3d;

struct Config {
  std::size_t pairs = 2000;
  std::uint64_t seed = 13;
  int segments = 1280;
  int demo_repeat = 3;
  std::string json_out;
};

/// The exact answer of one query or step.
struct Truth {
  bool collides = false;
  double t_lo = 0, t_hi = 0;  ///< contact time enclosure (when collides)
};

/// One row of the table.
struct Row {
  std::string data, setting;
  std::size_t queries = 0, contacts = 0;
  std::size_t false_positives = 0, false_negatives = 0, both = 0;
  double toi_error_median = 0, toi_error_max = 0;
  double fcl_us = 0, exact_us = 0;  ///< per query (or per step)
  bool per_step = false;
};

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

Row judge(const std::string& data, const Setting& s, const std::vector<Truth>& truth,
          const std::vector<FclAnswer>& fcl, double fcl_us, double exact_us) {
  Row r;
  r.data = data;
  r.setting = s.name;
  r.queries = truth.size();
  r.fcl_us = fcl_us;
  r.exact_us = exact_us;
  std::vector<double> errors;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    r.contacts += truth[i].collides;
    if (fcl[i].collides && !truth[i].collides) ++r.false_positives;
    if (!fcl[i].collides && truth[i].collides) ++r.false_negatives;
    if (fcl[i].collides && truth[i].collides) {
      const double t = 0.5 * truth[i].t_lo + 0.5 * truth[i].t_hi;
      errors.push_back(std::abs(fcl[i].toc - t));
    }
  }
  r.both = errors.size();
  r.toi_error_median = median(errors);
  r.toi_error_max = errors.empty() ? 0 : *std::max_element(errors.begin(), errors.end());
  return r;
}

// ---- Random pairs ------------------------------------------------------------------------------

/// One random pair as FCL sees it: the moving primitive's points and motion, the resting one's.
struct FclPair {
  std::vector<Vector3d> moving, fixed;
  RigidMotion motion;
};

template <class Query>
void run_pairs(const std::string& data, const std::vector<Query>& queries, bool rotation,
               std::vector<Row>& rows) {
  // The exact answers, timed over the whole set (default mode: filters, then the exact path).
  std::vector<Truth> truth(queries.size());
  std::vector<FclPair> pairs(queries.size());
  const auto t0 = Clock::now();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    RigidCcdResult r;
    if constexpr (std::is_same_v<Query, RigidVertexFaceQuery>)
      r = vertex_face_ccd(queries[i]);
    else
      r = edge_edge_ccd(queries[i]);
    if (!r.has_time) throw std::logic_error(data + ": a query without contact time");
    truth[i] = {r.ccd.collides, r.time_lo, r.time_hi};
  }
  const double exact_us = seconds_since(t0) * 1e6 / static_cast<double>(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    if constexpr (std::is_same_v<Query, RigidVertexFaceQuery>) {
      // The face moves, the vertex rests (corpus: other = rest).
      pairs[i] = {{q.a, q.b, q.c}, {q.p}, q.face.rigid};
    } else {
      pairs[i] = {{q.ea0, q.ea1}, {q.eb0, q.eb1}, q.edge_a.rigid};
    }
  }
  for (const Setting& s : settings_for_pairs()) {
    if ((rotation && !s.rotations) || (!rotation && !s.translations)) continue;
    std::vector<Geometry> moving(pairs.size()), fixed(pairs.size());
    std::vector<Pose> end(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      moving[i] = make_points(pairs[i].moving, s.representation);
      fixed[i] = make_points(pairs[i].fixed, s.representation);
      end[i] = end_pose(pairs[i].motion);
    }
    std::vector<FclAnswer> answers(pairs.size());
    const auto t1 = Clock::now();
    for (std::size_t i = 0; i < pairs.size(); ++i)
      answers[i] = continuous_collide(s, moving[i], Pose{}, end[i], fixed[i], rotation);
    const double fcl_us = seconds_since(t1) * 1e6 / static_cast<double>(pairs.size());
    rows.push_back(judge(data, s, truth, answers, fcl_us, exact_us));
    std::fprintf(stderr, "  %s / %s: done\n", data.c_str(), s.name.c_str());
  }
}

// ---- The demonstration's steps ----------------------------------------------------------------

void run_demo(const Config& c, std::vector<Row>& rows, json& steps_json) {
  using namespace exactccd::assembly;
  LockDesign design;
  design.segments = c.segments;
  const PartMesh key = make_key(design), lock = make_lock(design);
  Plan plan;
  plan.turn_to_degrees = 120;  // through the stop: one step with contact
  const std::vector<PlanStep> steps = plan_steps(design, plan);
  const Dimensions d = dimensions(design);
  const double pi = 3.14159265358979323846;

  // Exact: the demonstration's path, an exactccd::Scene (the lock static, the key a rigid
  // body), median of a few runs per step, each a fresh step.
  Scene scene;
  const MeshId lock_id = scene.add_static_mesh(lock.mesh.positions, lock.mesh.triangles);
  const MeshId key_id = scene.add_rigid_body(key.mesh.positions, key.mesh.triangles);
  std::vector<Truth> truth(steps.size());
  std::vector<double> exact_ms(steps.size());
  std::vector<Pose> from(steps.size()), to(steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const PlanStep& step = steps[k];
    const Positions start = key_positions_at_start(key, design, step);
    std::vector<double> ms;
    StepDecision decision;
    for (int r = 0; r < std::max(1, c.demo_repeat); ++r) {
      scene.set_rigid_motion(key_id, key.mesh.positions, RigidMotion{});
      const auto t0 = Clock::now();
      scene.set_rigid_motion(key_id, start, step.motion);
      decision = from_scene(scene.find_contacts({}), key_id, lock_id);
      ms.push_back(seconds_since(t0) * 1e3);
    }
    exact_ms[k] = median(ms);
    truth[k] = {decision.collides, decision.earliest.time_lo, decision.earliest.time_hi};
    // FCL's poses of the key's body (its inserted pose): translated up, or turned.
    if (step.phase == "insert") {
      const int n = plan.insert_steps;
      from[k].translation = Vector3d(0, 0, d.insertion * (n - step.index) / n);
      to[k].translation = Vector3d(0, 0, d.insertion * (n - step.index - 1) / n);
    } else {
      from[k] = end_pose(RigidMotion::turn(d.pivot, Vector3d::UnitZ(), step.angle_from * pi / 180));
      to[k] = end_pose(RigidMotion::turn(d.pivot, Vector3d::UnitZ(), step.angle_to * pi / 180));
    }
  }
  for (const Setting& s : settings_for_meshes()) {
    const Geometry key_g = make_mesh(key.mesh.positions, key.mesh.triangles, s.representation);
    const Geometry lock_g = make_mesh(lock.mesh.positions, lock.mesh.triangles, s.representation);
    for (const bool turning : {true, false}) {
      if ((turning && !s.rotations) || (!turning && !s.translations)) continue;
      std::vector<Truth> t;
      std::vector<FclAnswer> answers;
      std::vector<double> fcl_ms, ours;
      for (std::size_t k = 0; k < steps.size(); ++k) {
        if ((steps[k].phase == "turn") != turning) continue;
        const auto t0 = Clock::now();
        const FclAnswer a = continuous_collide(s, key_g, from[k], to[k], lock_g, turning);
        fcl_ms.push_back(seconds_since(t0) * 1e3);
        answers.push_back(a);
        t.push_back(truth[k]);
        ours.push_back(exact_ms[k]);
        steps_json.push_back({{"setting", s.name},
                              {"phase", steps[k].phase},
                              {"index", steps[k].index},
                              {"exact_collides", truth[k].collides},
                              {"exact_t_lo", truth[k].t_lo},
                              {"exact_t_hi", truth[k].t_hi},
                              {"exact_ms", exact_ms[k]},
                              {"fcl_collides", a.collides},
                              {"fcl_toc", a.toc},
                              {"fcl_ms", fcl_ms.back()}});
      }
      const std::string data = std::string("demo ") + (turning ? "turn" : "insert") + " steps (" +
                               std::to_string(key.mesh.triangles.rows()) + " + " +
                               std::to_string(lock.mesh.triangles.rows()) + " triangles)";
      Row r = judge(data, s, t, answers, median(fcl_ms) * 1e3, median(ours) * 1e3);
      r.per_step = true;
      rows.push_back(r);
      std::fprintf(stderr, "  %s / %s: done\n", data.c_str(), s.name.c_str());
    }
  }
}

std::string number(double x, int digits = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, x);
  return b;
}

void print_markdown(const std::vector<Row>& rows) {
  std::printf("| data | queries (exact contacts) | FCL setting | FCL false positives | FCL false "
              "negatives | TOI error, median / max (both report contact) | FCL | exactccd |\n");
  std::printf("|---|---:|---|---:|---:|---|---:|---:|\n");
  for (const Row& r : rows) {
    const auto t = [&](double us) {
      return r.per_step ? number(us / 1000) + " ms/step" : number(us) + " µs";
    };
    std::printf("| %s | %zu (%zu) | %s | %zu | %zu | %s | %s | %s |\n", r.data.c_str(), r.queries,
                r.contacts, r.setting.c_str(), r.false_positives, r.false_negatives,
                r.both ? (number(r.toi_error_median, 2) + " / " + number(r.toi_error_max, 2) +
                          " (" + std::to_string(r.both) + ")")
                             .c_str()
                       : "-",
                t(r.fcl_us).c_str(), t(r.exact_us).c_str());
  }
}

int run(const Config& c) {
  std::vector<Row> rows;
  namespace rq = exactccd::rigid_queries;
  rq::RigidQueryOptions rotation;
  rotation.pure_rotation = true;
  rotation.other = rq::OtherMotion::rest;
  rq::RigidQueryOptions translation = rotation;
  translation.pure_rotation = false;
  translation.pure_translation = true;
  run_pairs("vertex-face, rotation", rq::random_rigid_vertex_face(c.seed, c.pairs, rotation), true,
            rows);
  run_pairs("edge-edge, rotation", rq::random_rigid_edge_edge(c.seed, c.pairs, rotation), true,
            rows);
  run_pairs("vertex-face, translation",
            rq::random_rigid_vertex_face(c.seed, c.pairs, translation), false, rows);
  run_pairs("edge-edge, translation", rq::random_rigid_edge_edge(c.seed, c.pairs, translation),
            false, rows);
  json steps = json::array();
  if (c.segments > 0) run_demo(c, rows, steps);
  print_markdown(rows);
  if (!c.json_out.empty()) {
    json out = {{"pairs", c.pairs}, {"seed", c.seed}, {"segments", c.segments},
                {"demo_steps", steps}, {"rows", json::array()}};
    for (const Row& r : rows)
      out["rows"].push_back({{"data", r.data},
                             {"setting", r.setting},
                             {"queries", r.queries},
                             {"contacts", r.contacts},
                             {"false_positives", r.false_positives},
                             {"false_negatives", r.false_negatives},
                             {"both_contact", r.both},
                             {"toi_error_median", r.toi_error_median},
                             {"toi_error_max", r.toi_error_max},
                             {"fcl_us", r.fcl_us},
                             {"exact_us", r.exact_us},
                             {"per_step", r.per_step}});
    std::ofstream(c.json_out) << out.dump(1) << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Config c;
  CLI::App app{
      "exactccd's rigid CCD against FCL's continuousCollide on pure rotations and pure "
      "translations: seeded random pairs near contact and the assembly demonstration's steps. "
      "Prints a Markdown table (single thread)."};
  app.add_option("--pairs", c.pairs, "Random pairs per data set")->capture_default_str();
  app.add_option("--seed", c.seed, "Seed of the random pairs")->capture_default_str();
  app.add_option("--segments", c.segments,
                 "Resolution of the demonstration's lock and key (0: no demonstration)")
      ->capture_default_str();
  app.add_option("--demo-repeat", c.demo_repeat, "Runs of each exact demo step (median)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--json", c.json_out, "Also write the rows and the demo's steps here");
  CLI11_PARSE(app, argc, argv);
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  try {
    return run(c);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exactccd_fcl_comparison: %s\n", e.what());
    return 3;
  }
}
