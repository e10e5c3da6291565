#include "inspect_command.hpp"

#include <iostream>

#include "oracle/common.hpp"
#include "oracle/inspector_page.hpp"
#include "oracle/names.hpp"
#include "oracle/output_file.hpp"
#include "rigid_command.hpp"
#include "rigid_scene_file.hpp"

namespace exactccd::cli {

using namespace exactccd::oracle;

namespace {

bool is_scene_file(const std::string& path) {
  return path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

// The first contact of a step of a rigid scene file, as the rigid query the scene decided.
std::string inspect_scene_step(const InspectOptions& options) {
  const RigidSceneFile file = read_rigid_scene_file(options.path);
  InspectSettings settings = options.settings;
  if (!options.mode_given) settings.mode = file.mode;
  if (!options.t_max_given) settings.t_max = file.t_max;
  if (!options.min_separation_given) settings.min_separation = file.min_separation;
  if (options.step && (*options.step == 0 || *options.step > file.step_count))
    throw InputError(options.path, 0,
                     "--step " + std::to_string(*options.step) + " is not a step of the scene (1 to " +
                         std::to_string(file.step_count) + ")");
  RigidSceneFile run_file = file;
  run_file.mode = settings.mode == Mode::float_only ? Mode::filtered : settings.mode;
  run_file.t_max = settings.t_max;
  Scene scene;
  std::string json;
  std::optional<std::size_t> found;
  run_rigid_steps(run_file, settings.min_separation, options.path, scene,
                  [&](std::size_t k, const RigidStepResult& r) {
                    const bool wanted = options.step ? k + 1 == *options.step : r.earliest.collides;
                    if (!wanted) return true;
                    found = k + 1;
                    if (!r.earliest.collides) return false;
                    const ScenePair& pair = r.earliest.contact.pair;
                    const std::string title = "step " + std::to_string(k + 1) + " of " +
                                              options.path + ": " +
                                              contact_features_text(scene, file, pair);
                    if (pair.type == QueryType::vertex_face)
                      json = rigid_inspection_json(scene.rigid_vertex_face_query(pair), settings,
                                                   title, options.path, {"p", "a", "b", "c"}, k + 1);
                    else if (pair.type == QueryType::point_plane) {
                      const PointPlaneSource source{options.path, std::nullopt, std::nullopt,
                                                    k + 1, std::nullopt, title};
                      json = file.bodies[pair.first_mesh].kind == BodyKind::rigid
                                 ? rigid_point_plane_inspection_json(
                                       scene.rigid_point_plane_query(pair), settings, source)
                                 : point_plane_inspection_json(scene.point_plane_query(pair),
                                                               settings, source);
                    }
                    else
                      json = rigid_inspection_json(scene.rigid_edge_edge_query(pair), settings,
                                                   title, options.path,
                                                   {"ea0", "ea1", "eb0", "eb1"}, k + 1);
                    return false;
                  });
  if (!found)
    throw InputError(options.path, 0, "collision-free in every step: no contact to inspect");
  if (json.empty())
    throw InputError(options.path, 0,
                     "step " + std::to_string(*found) + " is collision-free: no contact to inspect");
  return json;
}

}  // namespace

int run_inspect(const InspectOptions& options) {
  validate_t_max(options.settings.t_max);
  validate_min_separation(options.settings.min_separation);
  const Overwrite overwrite = options.force ? Overwrite::replace : Overwrite::refuse;
  if (options.html_given && options.html_path.empty())
    throw UsageError("--html: the file name is empty");
  if (!options.html_path.empty()) check_output_path(options.html_path, overwrite, "--html");

  if (!options.html_path.empty()) require_inspector();
  if (options.step && !is_scene_file(options.path))
    throw UsageError("--step needs a rigid scene file (FILE.json)");
  if (is_scene_file(options.path) && (options.index_given || options.type || options.primitive))
    throw UsageError("--index and --type apply to a query file, not to a scene file (use --step)");
  const std::string json =
      is_scene_file(options.path)
          ? inspect_scene_step(options)
          : inspect_file_query(options.path, options.type, options.index, options.settings,
                               options.primitive);
  if (!options.html_path.empty())
    write_file_atomically(options.html_path, inspector_page(json), overwrite, "--html");
  std::cout << (options.json ? json + "\n" : inspection_text(json));
  return kExitAgree;
}

}  // namespace exactccd::cli
