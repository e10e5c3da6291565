// `exactccd rigid`: runs a rigid-body scene file (docs/rigid_scene_format.md) step by step with
// Scene::earliest_contact and prints the first contact of each step with its features.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exactccd/scene.hpp"
#include "rigid_scene_file.hpp"

namespace exactccd::cli {

struct RigidOptions {
  std::string scene_path;  ///< the JSON scene file
  bool json = false;       ///< --json: one JSON object instead of text
  /// --min-separation: the minimum separation delta (finite, >= 0), in place of the file's
  /// "min_separation".
  std::optional<double> min_separation;
};

/// One step of a scene run: its earliest contact, and how far rounding moved the start poses.
struct RigidStepResult {
  EarliestContact earliest;
  double start_rounding = 0.0;  ///< largest rounding of a rigid body's start pose
};

/// Called after each step with the scene still in that step's motions; false stops the run.
using RigidStepVisitor = std::function<bool(std::size_t step, const RigidStepResult& result)>;

/// Adds the file's bodies to `scene` (empty) and runs its steps with Scene::earliest_contact
/// (each step from the previous step's exact end pose rounded to doubles), with minimum
/// separation `delta`. Throws InputError naming `scene_path`.
std::vector<RigidStepResult> run_rigid_steps(const RigidSceneFile& file, double delta,
                                             const std::string& scene_path, Scene& scene,
                                             const RigidStepVisitor& visit = {});

/// "vertex_face, vertex 3 of body 0 'box' against triangle 7 (vertices 1 2 3) of body 1 ..."
std::string contact_features_text(const Scene& scene, const RigidSceneFile& file,
                                  const ScenePair& pair);

/// Exit statuses of `exactccd rigid`, for its --help.
extern const char* const kRigidExitStatusHelp;

/// Runs the subcommand: 0 when every step is collision-free, 1 when some step has a contact
/// (with a minimum separation delta > 0: the bodies come within delta). Throws InputError for a
/// bad scene file, UsageError for a negative or non-finite --min-separation.
int run_rigid(const RigidOptions& options);

}  // namespace exactccd::cli
