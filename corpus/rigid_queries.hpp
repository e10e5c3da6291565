// Seeded random rigid-motion queries near contact, shared by the tests, `exactccd bench --rigid`
// and the FCL comparison: a triangle (or an edge) of one body turning about a random axis
// through a random pivot (up to +-170 degrees, with or without a translation of the pivot), and
// a vertex (or an edge) of a second body placed on the first primitive's pose at a random
// parameter s0, then moved off it by a small random offset, moving rigidly or linearly. Most
// of them collide (about 90% with the default options: an offset of 2^-40 to 2^-2 of the size
// rarely carries the second primitive clear of the first's whole sweep), at contacts close to
// tangency; the rest pass within that offset.
//
// Query i of a seed is a pure function of (seed, i).
#pragma once

#include <cstdint>
#include <vector>

#include "exactccd/rigid.hpp"

namespace exactccd::rigid_queries {

/// What the second body does.
enum class OtherMotion : std::uint8_t { rigid, linear, rest };

/// How the generated queries move.
struct RigidQueryOptions {
  /// The first body's pivot stays in place (a pure rotation; FCL's screw motion with zero
  /// translation sweeps the same poses).
  bool pure_rotation = false;
  /// Nothing turns (every Cayley vector is zero): the first body's pivot moves on a straight
  /// line, so every point of it does (FCL's translation motion sweeps the same poses). The draws
  /// are those of the default options, with the angles replaced by zero.
  bool pure_translation = false;
  /// Largest |angle| of a turn in degrees (< 180).
  double max_angle_degrees = 170.0;
  /// The second body: rigid (its own turn), linear (a deformable mesh's vertices) or at rest.
  OtherMotion other = OtherMotion::rigid;
  /// Offset of the second primitive from the first's pose at s0, relative to the primitive size:
  /// drawn log-uniformly in [2^-40, 2^-2] times this, with a random sign (0: exactly on it, up
  /// to the rounding of the placement).
  double offset_scale = 1.0;
};

std::vector<RigidVertexFaceQuery> random_rigid_vertex_face(std::uint64_t seed, std::size_t count,
                                                            const RigidQueryOptions& options = {});
std::vector<RigidEdgeEdgeQuery> random_rigid_edge_edge(std::uint64_t seed, std::size_t count,
                                                        const RigidQueryOptions& options = {});

}  // namespace exactccd::rigid_queries
