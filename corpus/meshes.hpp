// Meshes and query output shared by the demonstration scenes (bench/scenes).
//
// Builders return a vertex list and a triangle list in the types of exactccd/scene.hpp. Closed
// meshes have outward-facing triangles (counterclockwise seen from outside); every coordinate is
// the double computed from the arguments as written below, so with dyadic arguments (multiples of
// a power of two, small enough) the coordinates are exactly the intended values.
#pragma once

#include <Eigen/Core>
#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "exactccd/scene.hpp"

namespace exactccd::scenes {

struct Mesh {
  Positions positions;
  Triangles triangles;
};

/// The axis-aligned box [lo, hi]: 8 vertices, 12 triangles.
Mesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/// The box [lo, hi] with its top (z = hi.z) and bottom (z = lo.z) faces divided into nx x ny
/// grids of cells (two triangles each) and each side face into one strip of quads between the
/// grids' boundary vertices. Closed. subdivided_box(lo, hi, 1, 1) has the topology of box().
Mesh subdivided_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int nx, int ny);

/// A flat sheet in the plane z = center.z covering [center.x - width/2, center.x + width/2] x
/// [center.y - width/2, center.y + width/2]: n x n square cells, two triangles each (diagonal from
/// the cell's lower-left to its upper-right corner), normals +z. Vertex (i, j) (0 <= i, j <= n, i
/// along x) has index j * (n + 1) + i and x = center.x - width/2 + width * i / n (likewise y).
Mesh grid_sheet(int n, double width, const Eigen::Vector3d& center);

/// A sheet with thickness: subdivided_box over [center - (width/2, width/2, thickness/2),
/// center + (width/2, width/2, thickness/2)], its two large faces n x n grids.
Mesh thin_slab(int n, double width, double thickness, const Eigen::Vector3d& center);

/// A polyhedral sphere inscribed in the sphere (center, radius): vertex 0 is the north pole
/// center + (0, 0, radius), the last vertex the south pole center - (0, 0, radius), and
/// stacks - 1 rings of `slices` vertices between them at polar angles pi k / stacks. The poles are
/// the body's unique highest and lowest points (along z). Needs slices >= 3, stacks >= 2.
Mesh uv_sphere(const Eigen::Vector3d& center, double radius, int slices, int stacks);

/// An open tube (no caps) of the given radius around the segment from `p0` to `p1`: `segments`
/// + 1 rings of `sides` vertices (ring k at p0 + k / segments (p1 - p0)), two triangles per
/// quad. Needs sides >= 3, segments >= 1 and p0 != p1.
Mesh open_tube(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double radius, int sides,
               int segments);

/// A closed axis-aligned box.
struct Box3 {
  Eigen::Vector3d lo, hi;
};

/// A block with a square through-hole along z: the square [-outer/2, outer/2]^2 minus the open
/// square (-hole/2, hole/2)^2, both centered at (center_x, center_y), between z = z_bottom and
/// z = z_top, as the union of four boxes: two spanning the whole outer width in y on either side
/// of the hole in x (first x below, then above), two closing the hole's sides in y (y below, then
/// above). The hole's walls are exactly the planes x = center_x +- hole/2 and
/// y = center_y +- hole/2 when those sums are exact.
std::array<Box3, 4> square_hole_block_boxes(double center_x, double center_y, double outer,
                                            double hole, double z_bottom, double z_top);

/// The mesh of square_hole_block_boxes: the four boxes' meshes (box()) one after the other, a
/// triangle soup whose inner faces touch, which is enough for a static obstacle (pairs between
/// static meshes are never tested).
Mesh block_with_square_hole(double center_x, double center_y, double outer, double hole,
                            double z_bottom, double z_top);

/// `positions` with `offset` added to every row (each coordinate rounded once).
Positions translated(const Positions& positions, const Eigen::Vector3d& offset);

/// The smallest box holding every row of `positions`.
Box3 bounds(const Positions& positions);

/// Exact times in [0, 1] (rational, closed interval).
struct TimeInterval {
  mpq_class first, last;
};

/// The reference the scenes check CCD against, in exact rational arithmetic on the doubles: the
/// times t in [0, 1] at which the closed box whose bounds move linearly from `start` to `end`
/// (lo(t) = (1 - t) start.lo + t end.lo, likewise hi) meets the closed box `fixed`; nullopt when
/// it never does. The solution of six linear inequalities in t, so an interval.
/// A translated mesh's bounding box moves exactly so when the translation adds the same offset
/// to every vertex without rounding (dyadic coordinates) or, with rounding, when each bound is
/// attained by one vertex throughout (a unique extreme vertex, such as a sphere's pole).
std::optional<TimeInterval> moving_box_meets_box(const Box3& start, const Box3& end,
                                                 const Box3& fixed);

/// Counts of what QueryCsvWriter::flush wrote.
struct QueryBatch {
  std::size_t index = 0;  ///< K of data_K.csv
  std::size_t vertex_face = 0, edge_edge = 0;                      ///< queries written
  std::size_t vertex_face_colliding = 0, edge_edge_colliding = 0;  ///< of which truth 1
};

/// Writes the candidate pairs of scene steps as queries in the benchmark's CSV format, each
/// coordinate as its exact fraction (append_query_rows): <dir>/queries/vertex-face/data_K.csv and
/// <dir>/queries/edge-edge/data_K.csv, one pair of files per batch (flush), the truth column 1
/// exactly for the step's colliding pairs. Those files are what `exactccd check` reads.
class QueryCsvWriter {
 public:
  /// Creates the two folders and removes the data_K.csv files a previous run left in them.
  /// Throws std::runtime_error when a folder cannot be created.
  explicit QueryCsvWriter(const std::string& dir);

  /// Adds every candidate of `result`, read from `scene` now (so call it before the scene's next
  /// set_motion). `result` must come from scene.find_contacts with record_candidates set and the
  /// benchmark's interval (ccd.t_max == 1): the truth column is membership in result.contacts.
  /// Throws std::invalid_argument when the result holds contacts but no candidates.
  void add_step(const Scene& scene, const SceneResult& result);

  /// Writes what add_step gathered since the last flush as data_K.csv, K = the number of earlier
  /// flushes (a type without queries gets no file). Throws std::runtime_error on a write error.
  QueryBatch flush();

  const std::string& vertex_face_folder() const { return folders_[0]; }
  const std::string& edge_edge_folder() const { return folders_[1]; }

 private:
  std::string folders_[2];
  std::string text_[2];
  QueryBatch pending_;
};

}  // namespace exactccd::scenes
