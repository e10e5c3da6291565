// `exactccd rigid`: runs a rigid-body scene file (docs/rigid_scene_format.md) step by step with
// Scene::earliest_contact and prints the first contact of each step with its features.
#pragma once

#include <optional>
#include <string>

namespace exactccd::cli {

struct RigidOptions {
  std::string scene_path;  ///< the JSON scene file
  bool json = false;       ///< --json: one JSON object instead of text
  /// --min-separation: the minimum separation delta (finite, >= 0), in place of the file's
  /// "min_separation".
  std::optional<double> min_separation;
};

/// Exit statuses of `exactccd rigid`, for its --help.
extern const char* const kRigidExitStatusHelp;

/// Runs the subcommand: 0 when every step is collision-free, 1 when some step has a contact
/// (with a minimum separation delta > 0: the bodies come within delta). Throws InputError for a
/// bad scene file, UsageError for a negative or non-finite --min-separation.
int run_rigid(const RigidOptions& options);

}  // namespace exactccd::cli
