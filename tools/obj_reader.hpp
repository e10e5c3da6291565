// Triangle meshes from Wavefront OBJ files, for `exactccd rigid` (docs/rigid_scene_format.md).
#pragma once

#include <string>

#include "exactccd/scene.hpp"

namespace exactccd::cli {

struct ObjMesh {
  Positions positions;  ///< the `v` lines, in order
  Triangles triangles;  ///< the `f` lines, polygons split into fans (v0, vk, vk+1)
};

/// Reads the `v` (x y z, an optional w or r g b ignored) and `f` lines (vertex references `i`,
/// `i/t`, `i//n`, `i/t/n`; 1-based, negative ones relative to the vertices read so far) of an
/// OBJ file; every other statement (vt, vn, o, g, s, usemtl, ...) and `#` comments are skipped.
/// Throws InputError naming FILE:LINE for a malformed or non-finite coordinate, a face with
/// fewer than 3 vertices, a reference that is not an integer, 0 or out of range, a face that
/// repeats a vertex; naming FILE for a file that cannot be read or is not a regular file (see
/// LineReader), or that has no vertex.
ObjMesh read_obj(const std::string& path);

}  // namespace exactccd::cli
