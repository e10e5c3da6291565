// Demonstration scene 4: precise assembly with rotation (issue 13). A barrel key is inserted
// into a warded lock over its drill pin and turned (lock_and_key.hpp), with clearances of
// 2^-20 of the chamber's radius. Every step is decided exactly by an exactccd::Scene (the lock a
// static mesh, the key a rigid body; its broad phase culls the coaxial walls by their cylinder
// ranges), the rigid CCD functions on every candidate pair. Two variants of
// the plan:
//   free  turn to 90 degrees in 15-degree steps: certified collision-free;
//   stop  turn on to 120 degrees: the bit meets the stop rib (at 97.5 degrees) in the step from
//         90 to 105 degrees; the first contact is reported with its features and its TOI (s and
//         time).
// Side by side, the chord approximation of every step (each key vertex on the straight line
// between its start and end positions, the linear CCD functions on the swept boxes of
// rigid_broad_phase.hpp): per step, the contacts it invents and the ones it misses, pair by pair, against the
// exact answer.
//
// Self-check (exit status 1): no contact in the free variant and in the insertion steps; the
// stop variant's first contact lies in the step that reaches the rib; in the insertion steps
// (pure translations) the chord and the rigid motion are the same motion, so the two must find
// the same contacts.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "corpus/assembly/assembly_step.hpp"
#include "corpus/assembly/lock_and_key.hpp"
#include "corpus/assembly/rigid_broad_phase.hpp"
#include "bench/scenes/scene_cli.hpp"

namespace {

using namespace exactccd;
using namespace exactccd::assembly;
namespace fs = std::filesystem;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

struct Config {
  LockDesign design;
  double step_degrees = 15.0;
  int insert_steps = 8;
  std::string out = "bench/scenes/out/assembly";
  int threads = 1;
  int repeat = 3;             ///< exact step timed this many times (median)
  bool chord = true;          ///< the chord comparison
  std::size_t box_only_sample = 300;  ///< pairs of the box-only broad phase decided and timed
  double min_separation = 0.0;  ///< the exact steps' minimum separation (0: contact)
};

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

json vec(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

/// The key's part names of a pair's key primitive and lock primitive.
json describe(const PairContact& c, const PartMesh& key, const PartMesh& lock,
              const StepMeshes& m) {
  json j = {{"kind", to_string(c.pair.kind)}, {"key_index", c.pair.key},
            {"lock_index", c.pair.lock},      {"s_lo", c.toi_lo},
            {"s_hi", c.toi_hi}};
  if (c.has_time) {
    j["t_lo"] = c.time_lo;
    j["t_hi"] = c.time_hi;
  }
  switch (c.pair.kind) {
    case PairKind::key_vertex_lock_face:
      j["key_part"] = key.part_of_vertex(c.pair.key);
      j["lock_part"] = lock.part_of_triangle(c.pair.lock);
      break;
    case PairKind::lock_vertex_key_face:
      j["key_part"] = key.part_of_triangle(c.pair.key);
      j["lock_part"] = lock.part_of_vertex(c.pair.lock);
      break;
    case PairKind::edge_edge:
      j["key_part"] = key.part_of_vertex((*m.key_edges)(c.pair.key, 0));
      j["lock_part"] = lock.part_of_vertex((*m.lock_edges)(c.pair.lock, 0));
      j["key_edge"] = {(*m.key_edges)(c.pair.key, 0), (*m.key_edges)(c.pair.key, 1)};
      j["lock_edge"] = {(*m.lock_edges)(c.pair.lock, 0), (*m.lock_edges)(c.pair.lock, 1)};
      break;
  }
  return j;
}

/// Positions of the given key vertices along the step: the arc (position_at) and the chord.
json paths(const Positions& start, const RigidMotion& motion, const std::vector<int>& vertices,
           int samples) {
  json out = json::array();
  for (int v : vertices) {
    const Eigen::Vector3d x0 = start.row(v).transpose();
    const Eigen::Vector3d x1 = position_at(motion, x0, 1.0);
    json arc = json::array(), chord = json::array();
    for (int k = 0; k <= samples; ++k) {
      const double s = static_cast<double>(k) / samples;
      arc.push_back(vec(position_at(motion, x0, s)));
      chord.push_back(vec((1 - s) * x0 + s * x1));
    }
    out.push_back({{"vertex", v}, {"arc", arc}, {"chord", chord}});
  }
  return out;
}

struct VariantResult {
  json steps = json::array();
  json first_contact;  ///< null when free
  std::vector<double> turn_ms, insert_ms;
  std::size_t invented = 0, missed = 0;
  int chord_steps_invented = 0, chord_steps_missed = 0;
};

VariantResult run_variant(const Config& c, const std::string& name, double turn_to,
                          const PartMesh& key, const PartMesh& lock, const Edges& key_edges,
                          const Edges& lock_edges, std::vector<std::string>& failures) {
  VariantResult out;
  Plan plan;
  plan.insert_steps = c.insert_steps;
  plan.step_degrees = c.step_degrees;
  plan.turn_to_degrees = turn_to;
  const std::vector<PlanStep> steps = plan_steps(c.design, plan);
  const StepMeshes m{&key.mesh.triangles, &key_edges, &lock.mesh.positions, &lock.mesh.triangles,
                     &lock_edges};
  // The exact path through exactccd::Scene: the lock static, the key a rigid body.
  Scene scene;
  const MeshId lock_id = scene.add_static_mesh(lock.mesh.positions, lock.mesh.triangles);
  const MeshId key_id = scene.add_rigid_body(key.mesh.positions, key.mesh.triangles);
  const auto same = [](const Edges& a, const Edges& b) { return a.rows() == b.rows() && a == b; };
  if (!same(scene.edges(key_id), key_edges) || !same(scene.edges(lock_id), lock_edges))
    failures.push_back(name + ": the Scene's edges are not unique_edges'");
  // The box-only broad phase (arc boxes, no cylinder ranges): the pairs the ranges save, a sample
  // decided.
  RigidBroadPhase exact_bp(lock.mesh.positions, lock.mesh.triangles, key.mesh.triangles);
  RigidBroadPhase chord_bp(lock.mesh.positions, lock.mesh.triangles, key.mesh.triangles);
  std::vector<int> bit_vertices;
  for (const Part& p : key.parts)
    if (p.name == "bit")
      for (int v = p.vertex_begin; v < p.vertex_end; ++v) bit_vertices.push_back(v);

  for (std::size_t k = 0; k < steps.size(); ++k) {
    const PlanStep& step = steps[k];
    const Positions start = key_positions_at_start(key, c.design, step);
    const std::string where = name + ", " + step.phase + " step " + std::to_string(step.index);

    // The exact decision, timed (broad phase, then every candidate).
    std::vector<double> step_ms;
    SceneResult result;
    for (int r = 0; r < std::max(1, c.repeat); ++r) {
      // Each run a fresh step: back at rest first (untimed), so that the key's hierarchies and
      // cylinder ranges are recomputed for the step's start positions as in a walk of the plan.
      scene.set_rigid_motion(key_id, key.mesh.positions, RigidMotion{});
      const auto t0 = Clock::now();
      scene.set_rigid_motion(key_id, start, step.motion);
      SceneOptions options;
      options.min_separation = c.min_separation;
      result = scene.find_contacts(options);
      step_ms.push_back(ms_since(t0));
    }
    const StepDecision exact = from_scene(result, key_id, lock_id);
    const std::size_t candidates = exact.queries;
    const double total_ms = median(step_ms);
    (step.phase == "turn" ? out.turn_ms : out.insert_ms).push_back(total_ms);

    json j = {{"phase", step.phase},
              {"index", step.index},
              {"angle_from", step.angle_from},
              {"angle_to", step.angle_to}};
    j["exact"] = {{"candidates", candidates},
                  {"contacts", exact.contacts.size()},
                  {"collides", exact.collides},
                  {"scene_cylinder_cuts", result.stats.cylinder_culled},
                  {"ms", total_ms}};
    if (exact.collides) j["exact"]["earliest"] = describe(exact.earliest, key, lock, m);

    // What the cylinder ranges save: the box-only broad phase's pairs, a sample decided.
    {
      const Candidates boxes = exact_bp.rigid_step(start, step.motion);
      j["exact"]["candidates_boxes_only"] = boxes.size();
      if (c.box_only_sample > 0 && boxes.size() > candidates) {
        Candidates sample;
        const std::size_t every = std::max<std::size_t>(1, boxes.size() / c.box_only_sample);
        std::size_t i = 0;
        for (const auto& p : boxes.moving_vertex_static_face)
          if (i++ % every == 0) sample.moving_vertex_static_face.push_back(p);
        for (const auto& p : boxes.static_vertex_moving_face)
          if (i++ % every == 0) sample.static_vertex_moving_face.push_back(p);
        for (const auto& p : boxes.edge_edge)
          if (i++ % every == 0) sample.edge_edge.push_back(p);
        const auto t0 = Clock::now();
        const StepDecision d = decide_rigid(m, start, step.motion, sample);
        const double us = ms_since(t0) * 1000 / static_cast<double>(sample.size());
        j["exact"]["boxes_only_sample"] = {
            {"pairs", sample.size()},
            {"us_per_pair", us},
            {"decided_by_exact", d.decided_by_exact},
            {"estimated_ms", us * static_cast<double>(boxes.size()) / 1000}};
      }
    }

    // The chord approximation of the same step.
    if (c.chord) {
      Positions end(start.rows(), 3);
      for (Eigen::Index i = 0; i < start.rows(); ++i)
        end.row(i) = position_at(step.motion, start.row(i).transpose(), 1.0).transpose();
      const Candidates chord_candidates = chord_bp.linear_step(start, end);
      const StepDecision chord = decide_linear(m, start, end, chord_candidates);
      const std::size_t invented = count_not_in(chord.contacts, exact.contacts);
      const std::size_t missed = count_not_in(exact.contacts, chord.contacts);
      out.invented += invented;
      out.missed += missed;
      out.chord_steps_invented += chord.collides && !exact.collides;
      out.chord_steps_missed += exact.collides && !chord.collides;
      j["chord"] = {{"candidates", chord_candidates.size()},
                    {"contacts", chord.contacts.size()},
                    {"collides", chord.collides},
                    {"invented", invented},
                    {"missed", missed}};
      if (chord.collides) j["chord"]["earliest"] = describe(chord.earliest, key, lock, m);
      if (step.phase == "insert" && (invented || missed))
        failures.push_back(where + ": the chord of a translation differs from the rigid motion");
    }

    if (exact.collides && step.phase == "insert" && c.min_separation == 0)
      failures.push_back(where + ": contact during the insertion");
    if (exact.collides && out.first_contact.is_null()) {
      const PairContact& e = exact.earliest;
      json f = describe(e, key, lock, m);
      f["step"] = where;
      f["plan_step"] = k;
      f["angle_from"] = step.angle_from;
      f["angle_to"] = step.angle_to;
      if (e.has_time) {
        f["angle_lo"] = step.angle_from + e.time_lo * (step.angle_to - step.angle_from);
        f["angle_hi"] = step.angle_from + e.time_hi * (step.angle_to - step.angle_from);
      }
      f["pairs_in_contact_this_step"] = exact.contacts.size();
      // Where it touches (doubles, for the picture): the vertex of a vertex-face pair at the
      // contact time, the two edges' closest points for an edge-edge pair.
      const auto at = [&](const Eigen::Vector3d& x0) {
        return position_at(step.motion, x0, e.toi_lo);
      };
      if (e.pair.kind == PairKind::lock_vertex_key_face) {
        f["contact_point"] = vec(lock.mesh.positions.row(e.pair.lock).transpose());
      } else if (e.pair.kind == PairKind::key_vertex_lock_face) {
        f["contact_point"] = vec(at(start.row(e.pair.key).transpose()));
      } else {
        const Eigen::Vector3d a0 = at(start.row(key_edges(e.pair.key, 0)).transpose()),
                              a1 = at(start.row(key_edges(e.pair.key, 1)).transpose()),
                              b0 = lock.mesh.positions.row(lock_edges(e.pair.lock, 0)).transpose(),
                              b1 = lock.mesh.positions.row(lock_edges(e.pair.lock, 1)).transpose();
        // Closest points of the two lines (they meet at the contact).
        const Eigen::Vector3d u = a1 - a0, v = b1 - b0, w = a0 - b0;
        const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), uw = u.dot(w), vw = v.dot(w);
        const double den = uu * vv - uv * uv;
        const double t = den != 0 ? (uv * vw - vv * uw) / den : 0.0;
        f["contact_point"] = vec(a0 + t * u);
      }
      // Picture data: the bit's corners and one vertex of the barrel's inner wall, along the
      // arc and the chord of the step; the key's start pose.
      f["paths"] = paths(start, step.motion, bit_vertices, 64);
      out.first_contact = f;
    }
    out.steps.push_back(j);
    std::printf("  %-6s %2d  %6.1f-%6.1f deg  candidates %7zu (boxes only %9zu)  exact: %s  "
                "%7.2f ms", step.phase.c_str(), step.index, step.angle_from, step.angle_to,
                candidates, j["exact"]["candidates_boxes_only"].get<std::size_t>(),
                exact.collides ? "CONTACT" : "free   ", total_ms);
    if (c.chord)
      std::printf("  | chord: %s invented %7zu missed %3zu", j["chord"]["collides"].get<bool>()
                                                                 ? "contact"
                                                                 : "free   ",
                  j["chord"]["invented"].get<std::size_t>(),
                  j["chord"]["missed"].get<std::size_t>());
    std::printf("\n");
  }
  return out;
}

int run(const Config& c) {
  const auto t_start = Clock::now();
  const PartMesh key = make_key(c.design), lock = make_lock(c.design);
  const Edges key_edges = unique_edges(key.mesh.triangles);
  const Edges lock_edges = unique_edges(lock.mesh.triangles);
  const Dimensions d = dimensions(c.design);
  std::printf("assembly: key %ld triangles, lock %ld triangles (%d segments per circle); "
              "clearance c = 2^-%d = %.3g; turn steps of %g degrees about the z axis\n",
              static_cast<long>(key.mesh.triangles.rows()),
              static_cast<long>(lock.mesh.triangles.rows()), c.design.segments,
              c.design.clearance_bits, d.clearance, c.step_degrees);

  std::vector<std::string> failures;
  json variants = json::array();
  const struct {
    const char* name;
    double turn_to;
    const char* description;
  } plans[] = {{"free", 90.0, "insert, then turn to 90 degrees (the stop stands at 97.5)"},
               {"stop", 120.0, "insert, then turn on to 120 degrees: past the stop"}};
  for (const auto& p : plans) {
    std::printf("\n%s: %s\n", p.name, p.description);
    const VariantResult r =
        run_variant(c, p.name, p.turn_to, key, lock, key_edges, lock_edges, failures);
    const bool expect_contact = p.turn_to > c.design.stop_degrees;
    const bool designed = c.min_separation == 0;  // the designed verdicts are for contact
    if (designed && !expect_contact && !r.first_contact.is_null())
      failures.push_back(std::string(p.name) + ": a contact on a path that clears everything");
    if (designed && expect_contact) {
      if (r.first_contact.is_null())
        failures.push_back(std::string(p.name) + ": no contact although the path meets the stop");
      else if (!(r.first_contact["angle_from"].get<double>() < c.design.stop_degrees &&
                 c.design.stop_degrees < r.first_contact["angle_to"].get<double>()))
        failures.push_back(std::string(p.name) + ": the first contact is not in the step that "
                                                 "reaches the stop");
    }
    if (r.first_contact.is_null()) {
      std::printf("  => CERTIFIED COLLISION-FREE\n");
    } else {
      const json& f = r.first_contact;
      std::printf("  => first contact in %s: %s, key %s #%d / lock %s #%d, s in [%.17g, %.17g]",
                  f["step"].get<std::string>().c_str(), f["kind"].get<std::string>().c_str(),
                  f["key_part"].get<std::string>().c_str(), f["key_index"].get<int>(),
                  f["lock_part"].get<std::string>().c_str(), f["lock_index"].get<int>(),
                  f["s_lo"].get<double>(), f["s_hi"].get<double>());
      if (f.contains("t_lo"))
        std::printf(", time in [%.17g, %.17g] (angle %.6f deg)", f["t_lo"].get<double>(),
                    f["t_hi"].get<double>(), f["angle_lo"].get<double>());
      std::printf("\n");
    }
    std::printf("  exact step (%d thread%s, median of %d runs): turn median %.2f ms, max %.2f ms; "
                "insert median %.2f ms\n",
                c.threads, c.threads == 1 ? "" : "s", c.repeat, median(r.turn_ms),
                r.turn_ms.empty() ? 0.0 : *std::max_element(r.turn_ms.begin(), r.turn_ms.end()),
                median(r.insert_ms));
    if (c.chord)
      std::printf("  chord approximation: %zu contacts invented, %zu missed (pairs); steps with "
                  "an invented contact %d, with a missed contact %d\n",
                  r.invented, r.missed, r.chord_steps_invented, r.chord_steps_missed);
    variants.push_back({{"name", p.name},
                        {"description", p.description},
                        {"turn_to", p.turn_to},
                        {"steps", r.steps},
                        {"first_contact", r.first_contact},
                        {"turn_ms_median", median(r.turn_ms)},
                        {"turn_ms_max", r.turn_ms.empty() ? 0.0
                                                          : *std::max_element(r.turn_ms.begin(),
                                                                              r.turn_ms.end())},
                        {"insert_ms_median", median(r.insert_ms)},
                        {"chord_invented", r.invented},
                        {"chord_missed", r.missed},
                        {"chord_steps_invented", r.chord_steps_invented},
                        {"chord_steps_missed", r.chord_steps_missed}});
  }

  // The rib, the bit and the radii the pictures draw.
  json rib = json::array(), bit = json::array();
  for (const Part& p : lock.parts)
    if (p.name == "stop rib")
      for (int v = p.vertex_begin; v < p.vertex_end; ++v)
        rib.push_back(vec(lock.mesh.positions.row(v).transpose()));
  for (const Part& p : key.parts)
    if (p.name == "bit")
      for (int v = p.vertex_begin; v < p.vertex_end; ++v)
        bit.push_back(vec(key.mesh.positions.row(v).transpose()));
  const double seconds = std::chrono::duration<double>(Clock::now() - t_start).count();
  const json summary = {
      {"scene", "assembly"},
      {"segments", c.design.segments},
      {"clearance", d.clearance},
      {"clearance_bits", c.design.clearance_bits},
      {"step_degrees", c.step_degrees},
      {"stop_degrees", c.design.stop_degrees},
      {"threads", c.threads},
      {"repeat", c.repeat},
      {"key_triangles", key.mesh.triangles.rows()},
      {"lock_triangles", lock.mesh.triangles.rows()},
      {"dimensions",
       {{"pin_radius", d.pin_radius},
        {"barrel_inner_vertex_radius", key.mesh.positions.row(0).head<2>().norm()},
        {"barrel_outer", d.barrel_outer},
        {"bit_root", d.bit_root},
        {"bit_tip", d.bit_tip},
        {"bit_half_width", d.bit_half_width},
        {"chamber_inscribed", std::hypot(d.bit_tip, d.bit_half_width) + d.clearance},
        {"outer", d.outer},
        {"bit_bottom", d.bit_bottom},
        {"bit_top", d.bit_top},
        {"pivot", vec(d.pivot)}}},
      {"rib", rib},
      {"bit", bit},
      {"variants", variants},
      {"self_check", {{"passed", failures.empty()}, {"failures", failures}}},
      {"seconds", seconds}};
  fs::create_directories(c.out);
  std::ofstream(fs::path(c.out) / "summary.json") << summary.dump(1) << "\n";
  std::printf("\nself-check: %s\n", failures.empty() ? "passed" : "FAILED");
  for (const std::string& f : failures) std::printf("FAIL %s\n", f.c_str());
  std::printf("%.1f s; summary in %s/summary.json\n", seconds, c.out.c_str());
  return failures.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Config c;
  CLI::App app{
      "Scene 4, precise assembly with rotation: a barrel key inserted over a drill pin and turned "
      "in a warded lock, clearances 2^-20; every step decided exactly (rigid CCD), the chord "
      "approximation counted against it. Writes OUT/summary.json. Exit status 1 when the "
      "self-check fails."};
  app.add_option("--out", c.out, "Output folder")->capture_default_str();
  app.add_option("--segments", c.design.segments, "Sides of every polygonal circle")
      ->capture_default_str()
      ->check(CLI::Range(8, 1 << 20));
  app.add_option("--clearance-bits", c.design.clearance_bits, "Clearance c = 2^-BITS")
      ->capture_default_str()
      ->check(CLI::Range(4, 40));
  app.add_option("--step-degrees", c.step_degrees, "Angle of each turn step")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 60.0));
  app.add_option("--threads", c.threads, "Threads (0: all; the timings are for 1)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--repeat", c.repeat, "Runs of each exact step (median time)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--box-only-sample", c.box_only_sample,
                 "Pairs of the box-only broad phase decided per step to estimate their cost "
                 "(0: none)")
      ->capture_default_str();
  app.add_flag("!--no-chord", c.chord, "Skip the chord comparison");
  app.add_option("--min-separation", c.min_separation,
                 "Minimum separation of the exact steps (0: contact; the designed verdicts are "
                 "checked only at 0)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  std::unique_ptr<tbb::global_control> threads;
  return exactccd::scenes::parse_and_run(app, argc, argv, "exactccd_assembly", [&] {
    if (c.threads > 0)
      threads = std::make_unique<tbb::global_control>(
          tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(c.threads));
    return run(c);
  });
}
