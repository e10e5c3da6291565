// Demonstration scene 1: rapid motion through a thin object.
//
// A small body (a polyhedral sphere of radius r) is shot straight down at constant speed through
// a static thin slab: the region slope * y - h/2 <= z <= slope * y + h/2 (vertical thickness h)
// over a square, a flat box sheared so that its faces are not axis-aligned (a generic sheet: with
// axis-aligned faces every face's bounding box is flat, which is a worst case for the static
// broad phase below). This runs for a sweep of time steps dt, several start phases each, and
// checks every step three ways: continuous detection (Scene::find_contacts, swept-box broad
// phase); the same exact narrow phase behind the older static broad phase (boxes at the two ends
// of the step only); and the discrete baseline (triangle intersections at the end of each step,
// then bisection).
//
// Write f(p) = z - slope * y. The slab is |f| <= h/2; the body is convex, laterally inside the
// slab, and thicker than it (f-extent e > h), so the two surfaces touch exactly while the body's
// f range meets [-h/2, h/2]: along a length L = h + e of its path. A test at instants sees that
// only when an instant falls in it, so it starts to miss once speed * dt > L and at
// speed * dt = N L sees about one passage in N; continuous detection sees every one.
//
// Reference (self-check; exit status 1 on any disagreement): for every step up to the first
// contact, the exact first time at which the body's f range meets [-h/2, h/2], computed in
// rational arithmetic from the vertex positions as doubles (each vertex's f is linear in t). The
// certified earliest contact of that step must enclose it, and no earlier step may report a
// contact. The slab's coordinates must be exact (dyadic thickness and slope), which is checked.
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

struct Config {
  double thickness = 1.0 / 128;  ///< h (vertical)
  double radius = 1.0 / 128;     ///< r
  double slope = 0.25;           ///< the slab's faces are z = slope * y +- h/2
  double speed = 1.0;
  double sheet_width = 1.0;
  int sheet_cells = 64;
  int slices = 12, stacks = 6;
  int phases = 8;
  std::vector<double> ratios = {0.1, 0.2, 0.5, 1, 2, 3, 4, 5, 10, 20, 50, 100};
  std::string queries = "contact";
  std::string out = "bench/scenes/out/thin_sheet";
  int threads = 0;
  Mode mode = Mode::filtered;  ///< of every pair's test (float_only: to watch the self-check fail)
};

/// The body's path, laterally: inside the slab, off its grid lines and cell diagonals (a generic
/// spot; the exact tests would handle degenerate ones as well).
constexpr double kPathX = 0.1, kPathY = 0.05;
/// Start phase j of P is (j + kPhaseOffset) / P (2 minus the golden ratio).
constexpr double kPhaseOffset = 0.3819660112501051;

/// f = z - slope * y of vertex i, exactly.
mpq_class level(const Positions& x, Eigen::Index i, const mpq_class& slope) {
  return mpq_class(x(i, 2)) - slope * mpq_class(x(i, 1));
}

struct LevelRange {
  mpq_class min, max;
};

LevelRange level_range(const Positions& x, const mpq_class& slope) {
  LevelRange r{level(x, 0, slope), level(x, 0, slope)};
  for (Eigen::Index i = 1; i < x.rows(); ++i) {
    const mpq_class f = level(x, i, slope);
    if (f < r.min) r.min = f;
    if (f > r.max) r.max = f;
  }
  return r;
}

/// The exact first time t in [0, 1] at which the body's f range meets [-half, half], when every
/// vertex's f decreases over the step (checked). The set {t : min_v f_v(t) <= half} is [a, 1]
/// with a the first vertex's arrival at the top face's plane; {t : max_v f_v(t) >= -half} is
/// [0, b] with b the last vertex's departure from the bottom face's plane.
std::optional<mpq_class> first_contact(const Positions& start, const Positions& end,
                                       const mpq_class& slope, const mpq_class& half) {
  std::optional<mpq_class> arrive, leave;  // a, b
  for (Eigen::Index i = 0; i < start.rows(); ++i) {
    const mpq_class f0 = level(start, i, slope), f1 = level(end, i, slope);
    if (!(f1 < f0)) throw std::logic_error("thin sheet reference: a vertex does not move down");
    // f(t) = f0 - t (f0 - f1).
    if (f1 <= half) {
      const mpq_class a = f0 <= half ? mpq_class(0) : mpq_class((f0 - half) / (f0 - f1));
      if (!arrive || a < *arrive) arrive = a;
    }
    if (f0 >= -half) {
      const mpq_class b = f1 >= -half ? mpq_class(1) : mpq_class((f0 + half) / (f0 - f1));
      if (!leave || b > *leave) leave = b;
    }
  }
  if (arrive && leave && *arrive <= *leave) return arrive;
  return std::nullopt;
}

struct Detection {
  bool detected = false;
  int step = -1;  ///< first step with a contact
  double toi_lo = 0, toi_hi = 0;  ///< within that step
  int steps_with_contact = 0;
};

json to_json(const Detection& d, double dt) {
  json j = {{"detected", d.detected}, {"steps_with_contact", d.steps_with_contact}};
  if (d.detected) {
    j["step"] = d.step;
    j["toi_lo"] = d.toi_lo;
    j["toi_hi"] = d.toi_hi;
    j["time_lo"] = (d.step + d.toi_lo) * dt;
    j["time_hi"] = (d.step + d.toi_hi) * dt;
  }
  return j;
}

struct Run {
  double ratio = 0, dt = 0, phase = 0;
  int steps = 0;
  std::vector<double> centers_z;  ///< the body's center at the instants k dt (x, y fixed)
  // The reference.
  bool contact = false;
  int contact_step = -1;
  mpq_class contact_toi;         ///< exact, within contact_step
  bool sampled_overlap = false;  ///< the f ranges overlap at some instant k dt
  // The three detectors.
  Detection ccd, static_bvh, discrete;
  std::uint64_t vertex_face_candidates = 0, edge_edge_candidates = 0;
  std::uint64_t static_candidates = 0;  ///< pairs the static broad phase passed on
  std::optional<scenes::QueryBatch> queries;

  double reference_steps() const { return contact_step + contact_toi.get_d(); }
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// The scene's fixed parts.
struct Setup {
  scenes::Mesh slab, body;  ///< body centered at the origin
  mpq_class slope, half;    ///< exact slope and h/2
  double extent = 0;        ///< the body's f-extent (max - min over its vertices)
  double below_center = 0;  ///< f(center) - min f over the body's vertices
};

Setup make_setup(const Config& c) {
  Setup s;
  s.slope = c.slope;
  s.half = mpq_class(c.thickness) / 2;
  s.slab = scenes::thin_slab(c.sheet_cells, c.sheet_width, c.thickness, Eigen::Vector3d::Zero());
  // Shear: z += slope * y. The reference needs the faces exactly planar: check every vertex.
  for (Eigen::Index i = 0; i < s.slab.positions.rows(); ++i) {
    auto p = s.slab.positions.row(i);
    const mpq_class want = mpq_class(p(2)) + s.slope * mpq_class(p(1));
    p(2) += c.slope * p(1);
    if (mpq_class(p(2)) != want)
      throw CLI::ValidationError(
          "--thickness and --slope must make the slab's coordinates exact doubles (choose "
          "dyadic values, e.g. 1/128 and 1/4)");
  }
  s.body = scenes::uv_sphere(Eigen::Vector3d::Zero(), c.radius, c.slices, c.stacks);
  const LevelRange r = level_range(s.body.positions, s.slope);
  s.extent = mpq_class(r.max - r.min).get_d();
  s.below_center = -r.min.get_d();
  if (!(s.extent > c.thickness))
    throw CLI::ValidationError("the body must be thicker than the slab (radius > thickness/2)");
  return s;
}

Run run_one(const Config& c, const Setup& s, double ratio, int phase_index,
            scenes::QueryCsvWriter* writer, bool write_all, std::vector<std::string>& failures) {
  Run run;
  run.ratio = ratio;
  run.dt = ratio * c.thickness / c.speed;
  // Phases off the dyadic grid, so that the discrete baseline's bisection does not land on the
  // contact time by chance.
  run.phase = (phase_index + kPhaseOffset) / c.phases;
  const double step_length = c.speed * run.dt;
  // The body's lowest vertex (in f) starts (1 + phase) steps above the top face: the first
  // contact is at about (1 + phase) dt, inside step 1 (exactly, up to rounding of positions).
  const double z0 =
      kPathY * c.slope + c.thickness / 2 + s.below_center + (1 + run.phase) * step_length;
  const auto at_instant = [&](int k) {
    run.centers_z.push_back(z0 - k * step_length);
    return scenes::translated(s.body.positions,
                              Eigen::Vector3d(kPathX, kPathY, run.centers_z.back()));
  };

  Scene scene;
  scene.add_static_mesh(s.slab.positions, s.slab.triangles);
  Positions start = at_instant(0);
  const MeshId body_id = scene.add_mesh(start, s.body.triangles);
  const std::string where =
      "ratio " + std::to_string(ratio) + ", phase " + std::to_string(run.phase);

  for (int k = 0;; ++k) {
    if (k > 100000) throw std::logic_error("thin sheet: the body never got past the slab");
    const Positions end = at_instant(k + 1);
    scene.set_motion(body_id, start, end);

    const std::optional<mpq_class> reference = first_contact(start, end, s.slope, s.half);
    const LevelRange at_end = level_range(end, s.slope);
    if (at_end.min <= s.half && at_end.max >= -s.half) run.sampled_overlap = true;
    if (reference && !run.contact) {
      run.contact = true;
      run.contact_step = k;
      run.contact_toi = *reference;
    }

    SceneOptions options;
    options.max_threads = c.threads;
    options.ccd.mode = c.mode;
    options.record_candidates = writer != nullptr;
    const SceneResult swept = scene.find_contacts(options);
    run.vertex_face_candidates += swept.stats.vertex_face_candidates;
    run.edge_edge_candidates += swept.stats.edge_edge_candidates;
    const EarliestContact earliest = scene.earliest_contact(options);
    options.broad_phase = BroadPhase::static_bvh;
    options.record_candidates = false;
    const SceneResult fixed = scene.find_contacts(options);
    run.static_candidates += fixed.stats.vertex_face_candidates + fixed.stats.edge_edge_candidates;
    const DiscreteResult discrete = discrete_collision(scene);

    // Self-checks against the reference, up to the first contact: until then the two are apart,
    // so their surfaces first meet when the f ranges do. Afterwards the surfaces cross each
    // other, and a step in which no vertex passes a face and no two edges meet has no
    // vertex-face or edge-edge contact although the ranges overlap: those steps are recorded only.
    const std::string at = where + ", step " + std::to_string(k) + ": ";
    if (!run.contact || k == run.contact_step) {
      if (reference && swept.contacts.empty())
        failures.push_back(at + "CCD missed the first contact (reference: t = " +
                           std::to_string(reference->get_d()) + ")");
      if (!reference && !swept.contacts.empty())
        failures.push_back(at + "CCD reported a contact before the first one");
      if (reference && !swept.contacts.empty()) {
        const SceneContact& e = swept.earliest;
        if (!(mpq_class(e.toi_lo) <= *reference && *reference <= mpq_class(e.toi_hi)))
          failures.push_back(at + "the earliest TOI interval does not enclose the exact time");
      }
    }
    if (earliest.collides != !swept.contacts.empty() ||
        (earliest.collides && !(earliest.contact.pair == swept.earliest.pair &&
                                earliest.contact.toi_lo == swept.earliest.toi_lo &&
                                earliest.contact.toi_hi == swept.earliest.toi_hi)))
      failures.push_back(at + "earliest_contact differs from find_contacts' earliest");
    // The static broad phase feeds the same exact narrow phase: it may miss pairs, never add.
    for (const SceneContact& f : fixed.contacts)
      if (!std::binary_search(
              swept.contacts.begin(), swept.contacts.end(), f,
              [](const SceneContact& a, const SceneContact& b) { return a.pair < b.pair; }))
        failures.push_back(at + "static_bvh reported a pair find_contacts does not");

    const auto record = [&](Detection& d, bool hit, double lo, double hi) {
      if (!hit) return;
      ++d.steps_with_contact;
      if (d.detected) return;
      d.detected = true;
      d.step = k;
      d.toi_lo = lo;
      d.toi_hi = hi;
    };
    record(run.ccd, !swept.contacts.empty(), swept.earliest.toi_lo, swept.earliest.toi_hi);
    record(run.static_bvh, !fixed.contacts.empty(), fixed.earliest.toi_lo, fixed.earliest.toi_hi);
    record(run.discrete, discrete.collides, discrete.toi_lo, discrete.toi_hi);

    if (writer && (write_all || (reference && k == run.contact_step)))
      writer->add_step(scene, swept);
    run.steps = k + 1;
    start = end;
    if (at_end.max < -s.half) break;  // wholly below the slab
  }
  if (!run.contact) failures.push_back(where + ": the reference found no contact (set-up)");
  if (writer) run.queries = writer->flush();
  return run;
}

json run_json(const Run& r) {
  json j = {{"phase", r.phase},
            {"steps", r.steps},
            {"centers_z", r.centers_z},
            {"reference",
             {{"contact", r.contact},
              {"step", r.contact_step},
              {"toi", r.contact_toi.get_d()},
              {"time", r.reference_steps() * r.dt},
              {"sampled_overlap", r.sampled_overlap}}},
            {"ccd", to_json(r.ccd, r.dt)},
            {"static_bvh", to_json(r.static_bvh, r.dt)},
            {"discrete", to_json(r.discrete, r.dt)},
            {"candidates",
             {{"vertex_face", r.vertex_face_candidates},
              {"edge_edge", r.edge_edge_candidates},
              {"static_bvh", r.static_candidates}}}};
  if (r.queries)
    j["queries"] = {{"file_index", r.queries->index},
                    {"vertex_face", r.queries->vertex_face},
                    {"edge_edge", r.queries->edge_edge},
                    {"vertex_face_colliding", r.queries->vertex_face_colliding},
                    {"edge_edge_colliding", r.queries->edge_edge_colliding}};
  return j;
}

int run_scene(const Config& c) {
  if (!(c.thickness > 0 && c.radius > 0 && c.speed > 0 && c.sheet_cells >= 1 &&
        c.sheet_width / 2 > std::abs(kPathX) + 2 * c.radius &&
        c.sheet_width / 2 > std::abs(kPathY) + 2 * c.radius))
    throw CLI::ValidationError("need thickness, radius, speed > 0 and a sheet wider than the "
                               "body's path");
  for (const double ratio : c.ratios)
    if (!(ratio > 0)) throw CLI::ValidationError("--ratios must be > 0");
  const auto start_time = std::chrono::steady_clock::now();
  const Setup s = make_setup(c);
  fs::create_directories(c.out);
  std::optional<scenes::QueryCsvWriter> writer;
  if (c.queries != "none") writer.emplace(c.out);

  std::vector<std::string> failures;
  std::vector<std::vector<Run>> runs;
  for (const double ratio : c.ratios) {
    runs.emplace_back();
    for (int p = 0; p < c.phases; ++p) {
      // Queries: every step of every run (all), or the first-contact step of the first phase.
      const bool write = writer && (c.queries == "all" || p == 0);
      runs.back().push_back(
          run_one(c, s, ratio, p, write ? &*writer : nullptr, c.queries == "all", failures));
    }
  }
  const double seconds = seconds_since(start_time);

  // ---- Table ----
  const double overlap_length = c.thickness + s.extent;
  std::printf("thin sheet: slab %gx%g, vertical thickness h = %g, faces z = %g y +- h/2 "
              "(%d triangles); body: sphere r = %g (%d triangles) falling at speed %g\n",
              c.sheet_width, c.sheet_width, c.thickness, c.slope,
              static_cast<int>(s.slab.triangles.rows()), c.radius,
              static_cast<int>(s.body.triangles.rows()), c.speed);
  std::printf("body and slab overlap along L = h + body extent = %.4g = %.3g h of the path; %d "
              "start phases per time step\n\n",
              overlap_length, overlap_length / c.thickness, c.phases);
  std::printf("%10s %8s %5s | %6s %6s %6s %6s | %9s %9s %9s\n", "speed*dt/h", "dt", "steps",
              "CCD", "static", "discr.", "sampl.", "CCD", "static", "discrete");
  std::printf("%10s %8s %5s | %27s | %29s\n", "", "", "", "runs with a contact found",
              "TOI error, steps (max)");
  int discrete_mismatches = 0, static_late = 0;
  json table = json::array();
  for (const std::vector<Run>& row : runs) {
    int ccd = 0, fixed = 0, discrete = 0, predicted = 0, steps = 0;
    double ccd_error = 0, static_error = 0, discrete_error = 0;
    json row_json = json::array();
    for (const Run& r : row) {
      ccd += r.ccd.detected;
      fixed += r.static_bvh.detected;
      discrete += r.discrete.detected;
      predicted += r.sampled_overlap;
      steps = std::max(steps, r.steps);
      if (r.discrete.detected != r.sampled_overlap) ++discrete_mismatches;
      // Errors of the reported first contact: CCD and static_bvh report toi_lo, the discrete
      // baseline its earliest intersecting instant (toi_hi).
      const double reference = r.reference_steps();
      if (r.ccd.detected)
        ccd_error = std::max(ccd_error, std::abs(r.ccd.step + r.ccd.toi_lo - reference));
      if (r.static_bvh.detected) {
        const double e = r.static_bvh.step + r.static_bvh.toi_lo - reference;
        static_error = std::max(static_error, std::abs(e));
        static_late += e > 0;
      }
      if (r.discrete.detected)
        discrete_error =
            std::max(discrete_error, std::abs(r.discrete.step + r.discrete.toi_hi - reference));
      row_json.push_back(run_json(r));
    }
    const int n = static_cast<int>(row.size());
    const auto fraction = [n](int k) { return std::to_string(k) + "/" + std::to_string(n); };
    const auto error = [](int hits, double e) {
      char text[32] = "-";
      if (hits > 0) std::snprintf(text, sizeof text, "%.2e", e);
      return std::string(text);
    };
    std::printf("%10g %8.3g %5d | %6s %6s %6s %6s | %9s %9s %9s\n", row.front().ratio,
                row.front().dt, steps, fraction(ccd).c_str(), fraction(fixed).c_str(),
                fraction(discrete).c_str(), fraction(predicted).c_str(),
                error(ccd, ccd_error).c_str(), error(fixed, static_error).c_str(),
                error(discrete, discrete_error).c_str());
    const auto optional_error = [](int hits, double e) { return hits > 0 ? json(e) : json(); };
    table.push_back({{"ratio", row.front().ratio},
                     {"dt", row.front().dt},
                     {"step_over_overlap_length", row.front().ratio * c.thickness / overlap_length},
                     {"hits",
                      {{"ccd", ccd},
                       {"static_bvh", fixed},
                       {"discrete", discrete},
                       {"sampling_predicts", predicted}}},
                     {"max_toi_error_steps",
                      {{"ccd", optional_error(ccd, ccd_error)},
                       {"static_bvh", optional_error(fixed, static_error)},
                       {"discrete", optional_error(discrete, discrete_error)}}},
                     {"runs", row_json}});
  }
  std::printf(
      "\nruns: start phases; sampl.: runs in which some instant k dt finds the body and the slab "
      "overlapping (exact), i.e. what any test at instants can see.\nTOI error: |reported first "
      "contact - exact first contact| in steps (CCD and static_bvh: toi_lo; discrete: the "
      "earliest instant its bisection found intersecting).\n");
  if (static_late)
    std::printf("static_bvh reported a first contact later than the true one in %d runs (it "
                "missed the earliest pair and found a later one)\n",
                static_late);
  std::printf("every step up to the first contact checked against the exact reference: %s\n",
              failures.empty() ? "CCD found each first contact, none earlier, TOI enclosed"
                               : "FAILURES");
  if (discrete_mismatches)
    std::printf("note: %d runs where discrete differs from the sampling prediction\n",
                discrete_mismatches);
  if (c.mode != Mode::filtered) std::printf("pair tests in mode %s\n", to_string(c.mode));
  for (const std::string& f : failures) std::printf("FAIL %s\n", f.c_str());
  std::printf("%zu runs in %.2f s; summary and queries under %s\n",
              runs.size() * static_cast<std::size_t>(c.phases), seconds, c.out.c_str());

  const json summary = {
      {"scene", "thin_sheet"},
      {"sheet",
       {{"width", c.sheet_width},
        {"thickness", c.thickness},
        {"slope", c.slope},
        {"cells", c.sheet_cells},
        {"triangles", s.slab.triangles.rows()}}},
      {"body",
       {{"shape", "uv_sphere"},
        {"radius", c.radius},
        {"slices", c.slices},
        {"stacks", c.stacks},
        {"path_x", kPathX},
        {"path_y", kPathY},
        {"extent", s.extent},
        {"triangles", s.body.triangles.rows()},
        {"velocity", {0, 0, -c.speed}}}},
      {"overlap_length", overlap_length},
      {"phases", c.phases},
      {"queries",
       c.queries == "none"
           ? json("none")
           : json("queries/{vertex-face,edge-edge}/data_K.csv, K = runs[].queries.file_index "
                  "(benchmark CSV, exact fractions, truth from the step's contacts); " +
                  std::string(c.queries == "all" ? "every step of every run"
                                                 : "the first-contact step of the first run of "
                                                   "each time step"))},
      {"mode", to_string(c.mode)},
      {"self_check", {{"passed", failures.empty()}, {"failures", failures}}},
      {"discrete_runs_differing_from_sampling", discrete_mismatches},
      {"static_bvh_runs_reporting_late", static_late},
      {"seconds", seconds},
      {"table", table}};
  std::ofstream(fs::path(c.out) / "summary.json") << summary.dump(1) << "\n";
  return failures.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Config c;
  CLI::App app{
      "Scene 1, rapid motion through a thin object: a small body shot through a thin slab at "
      "several time steps. Compares continuous detection with the static-box broad phase and "
      "the discrete baseline, checks every step up to the first contact against the exact "
      "reference, writes OUT/summary.json and the CCD candidates as benchmark CSV "
      "(OUT/queries). Exit status 1 when CCD disagrees with the reference."};
  app.add_option("--out", c.out, "Output folder")->capture_default_str();
  app.add_option("--thickness", c.thickness, "Slab thickness h, vertical (dyadic)")
      ->capture_default_str();
  app.add_option("--slope", c.slope, "The slab's faces are z = slope * y +- h/2 (dyadic)")
      ->capture_default_str();
  app.add_option("--radius", c.radius, "Body radius r (> h/2)")->capture_default_str();
  app.add_option("--speed", c.speed, "Body speed")->capture_default_str();
  app.add_option("--cells", c.sheet_cells, "Grid cells per side of the slab's faces")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  app.add_option("--ratios", c.ratios, "The values of speed*dt/h")->capture_default_str();
  app.add_option("--phases", c.phases,
                 "Start phases per time step (first contact near (1 + (j + 0.382)/P) dt)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  app.add_option("--queries", c.queries,
                 "CCD candidates written as CSV: contact (the first-contact step of each time "
                 "step's first run), all (every step of every run), none")
      ->capture_default_str()
      ->check(CLI::IsMember({"contact", "all", "none"}));
  exactccd::scenes::add_threads_and_mode_options(app, c.threads, c.mode);
  return exactccd::scenes::parse_and_run(app, argc, argv, "exactccd_thin_sheet",
                                          [&] { return run_scene(c); });
}
