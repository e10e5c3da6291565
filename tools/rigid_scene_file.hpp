// The scene files of `exactccd rigid` (the format: docs/rigid_scene_format.md): bodies as OBJ
// files or inline arrays, each rigid, static or deformable, or a static plane (a floor), rigid
// bodies with one motion or a list of steps; options t_max, toi_width, mode, min_separation.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "exactccd/types.hpp"

namespace exactccd::cli {

enum class BodyKind { rigid, fixed, deformable, plane };

/// "rigid", "static", "deformable", "plane".
const char* to_string(BodyKind kind);

struct SceneBody {
  std::string name;     ///< "name", or "body K"
  BodyKind kind = BodyKind::rigid;
  Positions positions;  ///< at the start of the first step
  Triangles triangles;
  /// A deformable body's positions at the end of the first step (equal to `positions` when the
  /// file gives none).
  Positions end_positions;
  /// A rigid body's motions, one per step (empty: at rest).
  std::vector<RigidMotion> steps;
  /// A plane's point and normal (kind plane: Scene::add_plane; no positions).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
};

struct RigidSceneFile {
  std::vector<SceneBody> bodies;
  double t_max = 1.0;
  double toi_width = 0.0;
  Mode mode = Mode::filtered;
  /// The minimum separation delta >= 0 (SceneOptions::min_separation; 0: contact).
  double min_separation = 0.0;
  /// max(1, the longest list of steps).
  std::size_t step_count = 1;
};

/// Reads and validates the file; OBJ paths are relative to its folder. Throws InputError naming
/// the file and the offending key path (bodies[1].steps[0].axis, ...) for: a file that cannot
/// be read or is not a regular file, invalid JSON, a missing or unknown key, a value of the
/// wrong type, a non-finite number, an index out of range or a triangle repeating a vertex, a
/// row count that does not match, a turn of 180 degrees or more or about a zero axis, an
/// option outside its domain (t_max in (0, 1], toi_width >= 0, min_separation >= 0, mode
/// filtered, exact or float_only, or default, the old name of filtered); OBJ errors as read_obj.
RigidSceneFile read_rigid_scene_file(const std::string& path);

}  // namespace exactccd::cli
