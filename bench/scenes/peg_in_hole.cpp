// Demonstration scene 3: precise assembly.
//
// A rigid square peg is inserted into a square hole through a static block with a clearance of
// c = 2^-20 s per side (about 1e-6 of the hole's side s), along a planned path: approach from
// above and to the side, align over the hole, insert straight down through it. The path is
// sampled into steps; over each step every peg vertex moves on a straight line, which for a pure
// translation is the rigid motion itself (no rotation is planned, so nothing is approximated).
// Every coordinate is a multiple of a power of two small enough to be an exact double, so each
// sampled pose is exactly the translated peg and the clearance is exactly c.
//
// Variants of the same plan, shifted sideways (along x) by:
//   nominal       0            clearance c on both sides: certified collision-free
//   near_wall     c - 2^-40    clearance 2^-40 s (about 1e-12) on one side: still free
//   flush         c            the peg's side face in the wall's plane: touching contact at the
//                              top edge of the hole (closed sets: touching is contact)
//   offset_2c     2c           overlap c with the block: first contact when the peg's bottom
//                              reaches the block's top face
// For each, every step runs Scene::find_contacts and earliest_contact (certified), the older
// static broad phase behind the same exact narrow phase, and the discrete baseline; the run stops
// at the first step with a contact, as a planner would.
//
// References (self-check; exit status 1 on any disagreement): (a) by hand from the plan: the
// shifted peg first meets the block when its bottom reaches the block's top during the insertion,
// at plan parameter u = (z_align - z_top) / (z_align - z_end) of that segment, so in step
// floor(u n) at t = u n - floor(u n) (n its step count); the unshifted and 2^-40 variants never
// do. (b) per step, in exact rational arithmetic from the positions: the first time the peg's box
// (exactly the peg: it is a box) meets one of the four boxes that make up the block (the peg
// starts clear of the block, so its surface first touches the block's when the solids first
// meet). CCD must report a contact in exactly the steps (b) does, up to the first, with a TOI
// interval enclosing the exact time, and (a) and (b) must agree.
#include <CLI/CLI.hpp>
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "corpus/meshes.hpp"
#include "bench/scenes/scene_cli.hpp"
#include "exactccd/discrete.hpp"
#include "exactccd/scene.hpp"

namespace {

using namespace exactccd;
namespace fs = std::filesystem;
using json = nlohmann::json;

// ---- Geometry (hole side s = 1) ----------------------------------------------------------------

constexpr double kHole = 1.0;        ///< s
constexpr double kOuter = 3.0;       ///< the block's outer side
constexpr double kBlockTop = 1.0;    ///< the block spans 0 <= z <= 1
constexpr double kPegHeight = 2.0;

/// A segment of the plan: the peg's bottom center moves from `from` to `to` in `steps` steps (a
/// power of two, so that every sampled pose is exact).
struct Segment {
  const char* name;
  Eigen::Vector3d from, to;
  int steps;
};

/// The plan for the nominal peg (bottom center; the block's top is at z = 1).
const Segment kPlan[3] = {
    {"approach", {1.5, 1.0, 2.5}, {0.25, 0.125, 1.5}, 32},
    {"align", {0.25, 0.125, 1.5}, {0.0, 0.0, 1.125}, 16},
    {"insert", {0.0, 0.0, 1.125}, {0.0, 0.0, -0.5}, 64},
};

struct Variant {
  std::string name, description;
  mpq_class shift;  ///< along x, exact
};

struct Config {
  int clearance_bits = 20;  ///< c = 2^-clearance_bits
  std::string out = "bench/scenes/out/peg_in_hole";
  int threads = 0;
  Mode mode = Mode::filtered;  ///< of every pair's test (float_only: to watch the self-check fail)
};

mpq_class pow2(int e) {
  mpq_class r(1);
  if (e >= 0)
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(e));
  else
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(-e));
  return r;
}

std::string text(const mpq_class& q) { return q.get_str(); }

/// The contact as (a): by hand from the plan.
struct PlannedContact {
  bool contact = false;
  int segment = -1, step = -1;  ///< step within the segment
  mpq_class toi;                ///< within the step
};

PlannedContact planned_contact(const mpq_class& shift, const mpq_class& clearance) {
  PlannedContact p;
  // The peg's side at x = 1/2 - c + shift reaches into the block (x >= 1/2) iff shift >= c. Until
  // the insertion the peg's bottom stays above the block's top (z >= 1.125 > 1), so the first
  // contact is on the insertion segment, when the bottom reaches z = 1.
  if (shift < clearance) return p;
  const Segment& insert = kPlan[2];
  const mpq_class u = (mpq_class(insert.from.z()) - kBlockTop) /
                      (mpq_class(insert.from.z()) - mpq_class(insert.to.z()));
  const mpq_class steps = u * insert.steps;
  mpz_class whole;
  mpz_fdiv_q(whole.get_mpz_t(), steps.get_num_mpz_t(), steps.get_den_mpz_t());
  p.contact = true;
  p.segment = 2;
  p.step = static_cast<int>(whole.get_si());
  p.toi = steps - mpq_class(whole);
  return p;
}

struct Detection {
  bool detected = false;
  int step = -1;  ///< global step index
  double toi_lo = 0, toi_hi = 0;
  json pair;  ///< the earliest pair, for CCD and static_bvh
};

json pair_json(const ScenePair& p) {
  return {{"type", to_string(p.type)},
          {"first_mesh", p.first_mesh},
          {"first_index", p.first_index},
          {"second_mesh", p.second_mesh},
          {"second_index", p.second_index}};
}

json detection_json(const Detection& d) {
  json j = {{"detected", d.detected}};
  if (d.detected) {
    j["step"] = d.step;
    j["toi_lo"] = d.toi_lo;
    j["toi_hi"] = d.toi_hi;
    if (!d.pair.is_null()) j["pair"] = d.pair;
  }
  return j;
}

struct Outcome {
  int steps_run = 0;
  std::uint64_t candidates = 0, static_candidates = 0;
  Detection ccd, static_bvh, discrete;
  std::optional<scenes::TimeInterval> reference;  ///< (b) at the step where it first found contact
  int reference_step = -1;
  json contact_point;  ///< where the earliest CCD pair touches, at its toi (doubles)
  std::vector<json> poses;  ///< the peg's bottom center at the instants
  scenes::QueryBatch queries;
};

/// Global step index -> (segment, step within it).
std::pair<int, int> locate(int global) {
  for (int s = 0; s < 3; ++s) {
    if (global < kPlan[s].steps) return {s, global};
    global -= kPlan[s].steps;
  }
  throw std::logic_error("step outside the plan");
}

Outcome run_variant(const Config& c, const Variant& v, const scenes::Mesh& block,
                    const std::array<scenes::Box3, 4>& block_boxes, const scenes::Mesh& peg,
                    scenes::QueryCsvWriter& writer, std::vector<std::string>& failures) {
  Outcome out;
  const double shift = v.shift.get_d();
  if (mpq_class(shift) != v.shift) throw std::logic_error("shift is not a double");
  // Poses: the bottom center at every instant of the plan, exact (checked).
  std::vector<Eigen::Vector3d> poses;
  for (const Segment& s : kPlan)
    for (int i = (poses.empty() ? 0 : 1); i <= s.steps; ++i) {
      const Eigen::Vector3d p = s.from + (s.to - s.from) * (static_cast<double>(i) / s.steps);
      for (int a = 0; a < 3; ++a) {
        const mpq_class want = mpq_class(s.from[a]) +
                               (mpq_class(s.to[a]) - mpq_class(s.from[a])) * i / s.steps;
        if (mpq_class(p[a]) != want) throw std::logic_error("plan pose is not exact");
      }
      poses.push_back(p + Eigen::Vector3d(shift, 0, 0));
    }
  const auto placed = [&](std::size_t k) {
    const Positions x = scenes::translated(peg.positions, poses[k]);
    // Exact translation: the peg stays exactly a box of the planned size.
    for (Eigen::Index i = 0; i < x.rows(); ++i)
      for (int a = 0; a < 3; ++a)
        if (mpq_class(x(i, a)) != mpq_class(peg.positions(i, a)) + mpq_class(poses[k][a]))
          throw std::logic_error("a pose of the peg is not exact");
    return x;
  };

  Scene scene;
  scene.add_static_mesh(block.positions, block.triangles);
  Positions start = placed(0);
  const MeshId peg_id = scene.add_mesh(start, peg.triangles);
  out.poses.push_back({poses[0].x(), poses[0].y(), poses[0].z()});
  const int total = static_cast<int>(poses.size()) - 1;
  for (int k = 0; k < total; ++k) {
    const Positions end = placed(static_cast<std::size_t>(k) + 1);
    out.poses.push_back({poses[k + 1].x(), poses[k + 1].y(), poses[k + 1].z()});
    scene.set_motion(peg_id, start, end);

    // (b): the first time the peg's box meets one of the block's boxes.
    std::optional<scenes::TimeInterval> reference;
    for (const scenes::Box3& b : block_boxes) {
      const auto meet = scenes::moving_box_meets_box(scenes::bounds(start), scenes::bounds(end), b);
      if (meet && (!reference || meet->first < reference->first)) reference = meet;
    }

    SceneOptions options;
    options.max_threads = c.threads;
    options.ccd.mode = c.mode;
    options.record_candidates = true;
    const SceneResult swept = scene.find_contacts(options);
    out.candidates += swept.stats.vertex_face_candidates + swept.stats.edge_edge_candidates;
    const EarliestContact earliest = scene.earliest_contact(options);
    options.broad_phase = BroadPhase::static_bvh;
    options.record_candidates = false;
    const SceneResult fixed = scene.find_contacts(options);
    out.static_candidates += fixed.stats.vertex_face_candidates + fixed.stats.edge_edge_candidates;
    const DiscreteResult discrete = discrete_collision(scene);
    writer.add_step(scene, swept);

    const auto [segment, local] = locate(k);
    const std::string at = v.name + ", " + kPlan[segment].name + " step " +
                           std::to_string(local) + ": ";
    if (reference && swept.contacts.empty())
      failures.push_back(at + "CCD missed a contact (reference: t = " + text(reference->first) +
                         ")");
    if (!reference && !swept.contacts.empty())
      failures.push_back(at + "CCD reported a contact the reference excludes");
    if (reference && !swept.contacts.empty() &&
        !(mpq_class(swept.earliest.toi_lo) <= reference->first &&
          reference->first <= mpq_class(swept.earliest.toi_hi)))
      failures.push_back(at + "the earliest TOI interval does not enclose the exact time " +
                         text(reference->first));
    if (earliest.collides != !swept.contacts.empty() ||
        (earliest.collides && !(earliest.contact.pair == swept.earliest.pair &&
                                earliest.contact.toi_lo == swept.earliest.toi_lo &&
                                earliest.contact.toi_hi == swept.earliest.toi_hi)))
      failures.push_back(at + "earliest_contact differs from find_contacts' earliest");

    const auto record = [&](Detection& d, bool hit, double lo, double hi, const ScenePair* p) {
      if (!hit || d.detected) return;
      d.detected = true;
      d.step = k;
      d.toi_lo = lo;
      d.toi_hi = hi;
      if (p) d.pair = pair_json(*p);
    };
    record(out.ccd, !swept.contacts.empty(), swept.earliest.toi_lo, swept.earliest.toi_hi,
           &swept.earliest.pair);
    record(out.static_bvh, !fixed.contacts.empty(), fixed.earliest.toi_lo,
           fixed.earliest.toi_hi, &fixed.earliest.pair);
    record(out.discrete, discrete.collides, discrete.toi_lo, discrete.toi_hi, nullptr);
    if (reference && out.reference_step < 0) {
      out.reference = reference;
      out.reference_step = k;
    }
    if (!swept.contacts.empty()) {
      // Where the earliest pair touches: its first primitive's vertices at toi_lo.
      const ScenePair& p = swept.earliest.pair;
      const double t = swept.earliest.toi_lo;
      json points = json::array();
      const auto at_t = [t](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        const Eigen::Vector3d x = (1 - t) * a + t * b;
        return json{x.x(), x.y(), x.z()};
      };
      if (p.type == QueryType::vertex_face) {
        const VertexFaceQuery q = scene.vertex_face_query(p);
        points.push_back(at_t(q.p_t0, q.p_t1));
      } else {
        const EdgeEdgeQuery q = scene.edge_edge_query(p);
        points.push_back(at_t(q.ea0_t0, q.ea0_t1));
        points.push_back(at_t(q.ea1_t0, q.ea1_t1));
      }
      out.contact_point = {{"pair", pair_json(p)}, {"first_primitive_at_toi", points}};
    }
    out.steps_run = k + 1;
    start = end;
    if (!swept.contacts.empty() || reference) break;  // a planner stops at the first contact
  }
  out.queries = writer.flush();
  return out;
}

int run_scene(const Config& c) {
  const auto start_time = std::chrono::steady_clock::now();
  const mpq_class clearance = pow2(-c.clearance_bits);
  const double cl = clearance.get_d();
  const double half_peg = kHole / 2 - cl;  // exact: 1/2 - 2^-bits
  const scenes::Mesh peg = scenes::box({-half_peg, -half_peg, 0}, {half_peg, half_peg, kPegHeight});
  const auto block_boxes = scenes::square_hole_block_boxes(0, 0, kOuter, kHole, 0, kBlockTop);
  const scenes::Mesh block = scenes::block_with_square_hole(0, 0, kOuter, kHole, 0, kBlockTop);
  const std::vector<Variant> variants = {
      {"nominal", "the planned path: clearance c on both sides", mpq_class(0)},
      {"near_wall", "shifted by c - 2^-40: clearance 2^-40 on one side", clearance - pow2(-40)},
      {"flush", "shifted by c: the peg's side in the wall's plane (touching)", clearance},
      {"offset_2c", "shifted by 2c: overlapping the block by c", 2 * clearance},
  };
  fs::create_directories(c.out);
  scenes::QueryCsvWriter writer(c.out);

  std::vector<std::string> failures;
  json variants_json = json::array();
  std::printf("peg in hole: hole side s = %g, peg side s - 2c, clearance c = 2^-%d s = %.3g s per "
              "side; block %gx%gx%g; plan: %s %d + %s %d + %s %d steps (pure translation)\n\n",
              kHole, c.clearance_bits, cl, kOuter, kOuter, kBlockTop, kPlan[0].name,
              kPlan[0].steps, kPlan[1].name, kPlan[1].steps, kPlan[2].name, kPlan[2].steps);
  for (const Variant& v : variants) {
    const PlannedContact planned = planned_contact(v.shift, clearance);
    const Outcome o = run_variant(c, v, block, block_boxes, peg, writer, failures);

    // (a) against (b).
    const bool reference_contact = o.reference.has_value();
    if (planned.contact != reference_contact)
      failures.push_back(v.name + ": the plan and the per-step reference disagree on contact");
    if (planned.contact && reference_contact) {
      const auto [segment, local] = locate(o.reference_step);
      if (segment != planned.segment || local != planned.step || o.reference->first != planned.toi)
        failures.push_back(v.name + ": the plan and the per-step reference disagree on the TOI");
    }

    std::printf("%-10s %s\n", v.name.c_str(), v.description.c_str());
    std::printf("  %d steps, %llu candidate pairs decided (swept BVH), %llu (static BVH)\n",
                o.steps_run, static_cast<unsigned long long>(o.candidates),
                static_cast<unsigned long long>(o.static_candidates));
    if (planned.contact)
      std::printf("  expected (by hand from the plan): contact in %s step %d at t = %s = %.17g\n",
                  kPlan[planned.segment].name, planned.step, text(planned.toi).c_str(),
                  planned.toi.get_d());
    else
      std::printf("  expected (by hand from the plan): no contact\n");
    const auto describe = [&](const char* who, const Detection& d, bool certified) {
      if (!d.detected) {
        std::printf("  %-9s no contact over the whole path%s\n", who,
                    certified ? ": CERTIFIED COLLISION-FREE" : "");
        return;
      }
      const auto [segment, local] = locate(d.step);
      std::printf("  %-9s first contact in %s step %d, t in [%.17g, %.17g]\n", who,
                  kPlan[segment].name, local, d.toi_lo, d.toi_hi);
    };
    describe("CCD:", o.ccd, c.mode != Mode::float_only);
    describe("static:", o.static_bvh, false);
    describe("discrete:", o.discrete, false);
    std::printf("\n");

    json j = {{"name", v.name},
              {"description", v.description},
              {"shift_x", v.shift.get_d()},
              {"shift_x_exact", text(v.shift)},
              {"steps_run", o.steps_run},
              {"candidates", o.candidates},
              {"static_candidates", o.static_candidates},
              {"poses", o.poses},
              {"expected", {{"contact", planned.contact}}},
              {"ccd", detection_json(o.ccd)},
              {"static_bvh", detection_json(o.static_bvh)},
              {"discrete", detection_json(o.discrete)},
              {"queries",
               {{"file_index", o.queries.index},
                {"vertex_face", o.queries.vertex_face},
                {"edge_edge", o.queries.edge_edge},
                {"vertex_face_colliding", o.queries.vertex_face_colliding},
                {"edge_edge_colliding", o.queries.edge_edge_colliding}}}};
    if (planned.contact) {
      const int global = kPlan[0].steps + kPlan[1].steps + planned.step;
      j["expected"] = {{"contact", true},
                       {"segment", kPlan[planned.segment].name},
                       {"segment_step", planned.step},
                       {"step", global},
                       {"toi_exact", text(planned.toi)},
                       {"toi", planned.toi.get_d()}};
    }
    if (!o.contact_point.is_null()) j["ccd"]["contact"] = o.contact_point;
    variants_json.push_back(j);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  std::printf("every step checked against the exact references: %s\n",
              failures.empty() ? "CCD agrees (contacts, their absence, TOI enclosures)"
                               : "FAILURES");
  if (c.mode != Mode::filtered) std::printf("pair tests in mode %s\n", to_string(c.mode));
  for (const std::string& f : failures) std::printf("FAIL %s\n", f.c_str());
  std::printf("%.2f s; summary and queries under %s\n", seconds, c.out.c_str());

  json plan = json::array();
  for (const Segment& s : kPlan)
    plan.push_back({{"name", s.name},
                    {"from", {s.from.x(), s.from.y(), s.from.z()}},
                    {"to", {s.to.x(), s.to.y(), s.to.z()}},
                    {"steps", s.steps}});
  json boxes = json::array();
  for (const scenes::Box3& b : block_boxes)
    boxes.push_back({{"lo", {b.lo.x(), b.lo.y(), b.lo.z()}}, {"hi", {b.hi.x(), b.hi.y(), b.hi.z()}}});
  const json summary = {
      {"scene", "peg_in_hole"},
      {"hole", kHole},
      {"outer", kOuter},
      {"block_top", kBlockTop},
      {"block_boxes", boxes},
      {"peg", {{"side", 2 * half_peg}, {"height", kPegHeight}}},
      {"clearance", cl},
      {"clearance_exact", text(clearance)},
      {"plan", plan},
      {"motion", "pure translation, each vertex linear over a step: exactly rigid"},
      {"queries",
       "queries/{vertex-face,edge-edge}/data_K.csv, K = variants[].queries.file_index: every "
       "candidate of every step run (benchmark CSV, exact fractions, truth from the contacts)"},
      {"mode", to_string(c.mode)},
      {"self_check", {{"passed", failures.empty()}, {"failures", failures}}},
      {"seconds", seconds},
      {"variants", variants_json}};
  std::ofstream(fs::path(c.out) / "summary.json") << summary.dump(1) << "\n";
  return failures.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Config c;
  CLI::App app{
      "Scene 3, precise assembly: a square peg inserted into a square hole with a clearance of "
      "2^-20 of its side (about 1e-6) along a planned path, and the same path shifted sideways. "
      "Certifies the nominal path collision-free or reports the first contact with its TOI; "
      "compares with the static-box broad phase and the discrete baseline; checks every step "
      "against exact references; writes OUT/summary.json and the queries (OUT/queries). Exit "
      "status 1 when CCD disagrees with a reference."};
  app.add_option("--out", c.out, "Output folder")->capture_default_str();
  app.add_option("--clearance-bits", c.clearance_bits,
                 "Clearance per side c = 2^-BITS of the hole's side")
      ->capture_default_str()
      ->check(CLI::Range(2, 39));
  exactccd::scenes::add_threads_and_mode_options(app, c.threads, c.mode);
  return exactccd::scenes::parse_and_run(app, argc, argv, "exactccd_peg_in_hole",
                                          [&] { return run_scene(c); });
}
