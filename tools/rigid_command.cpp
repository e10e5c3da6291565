#include "rigid_command.hpp"

#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "end_pose.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/scene.hpp"
#include "oracle/common.hpp"
#include "rigid_scene_file.hpp"

namespace exactccd::cli {

const char* const kRigidExitStatusHelp =
    "Exit status:\n"
    "  0  the scene ran: each step's first contact, or collision-free, is printed (a contact\n"
    "     is an answer, not a disagreement; 1 is the other subcommands' disagreement)\n"
    "  2  bad command line, or a scene or OBJ file that cannot be read or is malformed; one\n"
    "     line on stderr: 'exactccd: FILE: where: what'\n"
    "  3  internal error (a bug in exactccd, or out of memory)\n";

namespace {

using oracle::format_double;
using Json = nlohmann::json;

bool moves(const RigidMotion& m) {
  return m.cayley != Eigen::Vector3d::Zero() || m.translation != Eigen::Vector3d::Zero();
}

/// One side of a contact: the body and its primitive, with the primitive's vertices.
struct Feature {
  MeshId body = 0;
  const char* primitive = "vertex";  ///< vertex, triangle or edge
  std::uint32_t index = 0;
  std::vector<std::int32_t> vertices;  ///< a triangle's or an edge's vertex indices
};

std::pair<Feature, Feature> features_of(const Scene& scene, const ScenePair& p) {
  Feature a, b;
  a.body = p.first_mesh;
  a.index = p.first_index;
  b.body = p.second_mesh;
  b.index = p.second_index;
  if (p.type == QueryType::point_plane) {
    b.primitive = "plane";
  } else if (p.type == QueryType::vertex_face) {
    b.primitive = "triangle";
    const Triangles& t = scene.triangles(p.second_mesh);
    for (int k = 0; k < 3; ++k) b.vertices.push_back(t(p.second_index, k));
  } else {
    a.primitive = b.primitive = "edge";
    const Edges& ea = scene.edges(p.first_mesh);
    const Edges& eb = scene.edges(p.second_mesh);
    a.vertices = {ea(p.first_index, 0), ea(p.first_index, 1)};
    b.vertices = {eb(p.second_index, 0), eb(p.second_index, 1)};
  }
  return {a, b};
}

std::string text_of(const Feature& f, const RigidSceneFile& file) {
  // A plane is one primitive: no index.
  std::string s = std::string(f.primitive) == "plane"
                      ? std::string("the plane")
                      : std::string(f.primitive) + " " + std::to_string(f.index);
  if (!f.vertices.empty()) {
    s += " (vertices";
    for (std::int32_t v : f.vertices) s += " " + std::to_string(v);
    s += ")";
  }
  return s + " of body " + std::to_string(f.body) + " '" + printable(file.bodies[f.body].name) + "'";
}

Json json_of(const Feature& f, const RigidSceneFile& file) {
  Json j = {{"body", f.body}, {"name", file.bodies[f.body].name}, {f.primitive, f.index}};
  if (!f.vertices.empty()) j["vertices"] = f.vertices;
  return j;
}

Json nullable(bool defined, double value) { return defined ? Json(value) : Json(nullptr); }

void print_text(const RigidOptions& o, const RigidSceneFile& file, double delta,
                const Scene& scene, const std::vector<RigidStepResult>& steps) {
  std::size_t rigid = 0;
  for (const SceneBody& b : file.bodies) rigid += b.kind == BodyKind::rigid;
  std::cout << o.scene_path << ": " << file.bodies.size()
            << (file.bodies.size() == 1 ? " body (" : " bodies (") << rigid << " rigid), "
            << steps.size() << (steps.size() == 1 ? " step" : " steps") << ", mode "
            << to_string(file.mode) << ", t_max "
            << format_double(file.t_max);
  // Only when set: the header of a contact-only run stays as it was.
  if (delta > 0) std::cout << ", min_separation " << format_double(delta);
  std::cout << "\n";
  std::optional<std::size_t> first;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const RigidStepResult& r = steps[k];
    std::cout << "step " << k + 1 << ": ";
    if (!r.earliest.collides) {
      std::cout << "collision-free";
    } else {
      if (!first) first = k;
      const SceneContact& c = r.earliest.contact;
      std::cout << "contact at s in [" << format_double(c.toi_lo) << ", "
                << format_double(c.toi_hi) << "]";
      if (c.has_time)
        std::cout << ", time in [" << format_double(c.time_lo) << ", " << format_double(c.time_hi)
                  << "]";
      const auto [a, b] = features_of(scene, c.pair);
      std::cout << ": " << to_string(c.pair.type) << ", " << text_of(a, file) << " against "
                << text_of(b, file);
    }
    if (r.start_rounding > 0)
      std::cout << " (start pose rounded to doubles by at most " << format_double(r.start_rounding)
                << ")";
    std::cout << "\n";
  }
  if (first)
    std::cout << "first contact in step " << *first + 1 << "\n";
  else
    std::cout << "collision-free in every step\n";
}

void print_json(const RigidOptions& o, const RigidSceneFile& file, double delta,
                const Scene& scene, const std::vector<RigidStepResult>& steps) {
  Json bodies = Json::array();
  for (const SceneBody& b : file.bodies)
    bodies.push_back({{"name", b.name},
                      {"kind", to_string(b.kind)},
                      {"vertices", b.positions.rows()},
                      {"triangles", b.triangles.rows()},
                      {"steps", b.steps.size()}});
  Json out = {{"scene", o.scene_path},
              {"mode", to_string(file.mode)},
              {"t_max", file.t_max},
              {"toi_width", file.toi_width},
              {"min_separation", delta},
              {"bodies", bodies},
              {"first_contact_step", nullptr}};
  Json list = Json::array();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const RigidStepResult& r = steps[k];
    Json step = {{"step", k + 1},
                 {"start_rounding", r.start_rounding},
                 {"collides", r.earliest.collides},
                 {"contact", nullptr}};
    if (r.earliest.collides) {
      if (out["first_contact_step"].is_null()) out["first_contact_step"] = k + 1;
      const SceneContact& c = r.earliest.contact;
      const auto [a, b] = features_of(scene, c.pair);
      step["contact"] = {{"type", to_string(c.pair.type)},
                         {"s_lo", c.toi_lo},
                         {"s_hi", c.toi_hi},
                         {"time_lo", nullable(c.has_time, c.time_lo)},
                         {"time_hi", nullable(c.has_time, c.time_hi)},
                         {"first", json_of(a, file)},
                         {"second", json_of(b, file)}};
    }
    list.push_back(step);
  }
  out["steps"] = list;
  // Names are the user's bytes: invalid UTF-8 is replaced rather than thrown on.
  std::cout << out.dump(2, ' ', false, Json::error_handler_t::replace) << "\n";
}

/// The run's minimum separation: --min-separation when given, else the file's (validated as it
/// was read).
double min_separation_of(const RigidOptions& o, const RigidSceneFile& file) {
  return o.min_separation ? *o.min_separation : file.min_separation;
}

}  // namespace

std::string contact_features_text(const Scene& scene, const RigidSceneFile& file,
                                  const ScenePair& pair) {
  const auto [a, b] = features_of(scene, pair);
  return std::string(to_string(pair.type)) + ", " + text_of(a, file) + " against " +
         text_of(b, file);
}

std::vector<RigidStepResult> run_rigid_steps(const RigidSceneFile& file, double delta,
                                             const std::string& scene_path, Scene& scene,
                                             const RigidStepVisitor& visit) {
  std::vector<Positions> start;  // each body's positions at the start of the current step
  for (std::size_t i = 0; i < file.bodies.size(); ++i) {
    const SceneBody& b = file.bodies[i];
    try {
      switch (b.kind) {
        case BodyKind::rigid: scene.add_rigid_body(b.positions, b.triangles); break;
        case BodyKind::fixed: scene.add_static_mesh(b.positions, b.triangles); break;
        case BodyKind::deformable: scene.add_mesh(b.positions, b.triangles); break;
        case BodyKind::plane: scene.add_plane(b.origin, b.normal); break;
      }
    } catch (const std::invalid_argument& e) {  // validated already; kept as a bad-input error
      throw InputError(scene_path, 0, "bodies[" + std::to_string(i) + "]: " + e.what());
    }
    start.push_back(b.positions);
  }
  SceneOptions o;
  o.ccd.t_max = file.t_max;
  o.ccd.toi_width = file.toi_width;
  o.ccd.mode = file.mode;
  o.min_separation = delta;  // the scene gives every pair this delta
  std::vector<RigidStepResult> results;
  for (std::size_t k = 0; k < file.step_count; ++k) {
    RigidStepResult r;
    for (std::size_t i = 0; i < file.bodies.size(); ++i) {
      const SceneBody& b = file.bodies[i];
      const auto id = static_cast<MeshId>(i);
      if (b.kind == BodyKind::rigid) {
        // A step starts where the previous one ended: its exact end pose rounded to doubles.
        if (k > 0 && k - 1 < b.steps.size() && moves(b.steps[k - 1])) {
          double rounding = 0.0;
          start[i] = rounded_end_pose(start[i], b.steps[k - 1], &rounding,
                                      scene_path + ": bodies[" + std::to_string(i) + "]");
          r.start_rounding = std::max(r.start_rounding, rounding);
        }
        scene.set_rigid_motion(id, start[i], k < b.steps.size() ? b.steps[k] : RigidMotion{});
      } else if (b.kind == BodyKind::deformable && k < 2) {
        // The first step moves it to its end positions; it rests there afterwards.
        if (k == 0)
          scene.set_motion(id, b.positions, b.end_positions);
        else
          scene.set_motion(id, b.end_positions, b.end_positions);
      }
    }
    r.earliest = scene.earliest_contact(o);
    results.push_back(r);
    if (visit && !visit(k, results.back())) break;
  }
  return results;
}

int run_rigid(const RigidOptions& options) {
  // The command line first: a bad --min-separation is refused before any file is read.
  if (options.min_separation) oracle::validate_min_separation(*options.min_separation);
  const RigidSceneFile file = read_rigid_scene_file(options.scene_path);
  const double delta = min_separation_of(options, file);
  Scene scene;
  const std::vector<RigidStepResult> results =
      run_rigid_steps(file, delta, options.scene_path, scene);
  if (options.json)
    print_json(options, file, delta, scene, results);
  else
    print_text(options, file, delta, scene, results);
  // A contact is reported in the output; the exit status is that of a run that worked (1 is the
  // other subcommands' disagreement with a truth, which a scene run has none of).
  return oracle::kExitAgree;
}

}  // namespace exactccd::cli
