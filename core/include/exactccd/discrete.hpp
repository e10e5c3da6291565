/// \file
/// Discrete collision detection: the classic baseline that CCD is compared with.
///
/// Discrete detection looks at the scene at instants only: it reports the triangle pairs that
/// intersect at the end of the step (an exact test), and when there are any it backtracks by
/// bisection to approximate the first contact, as simulators did before continuous detection.
/// It misses every contact that begins and ends within the step (a thin object passed through),
/// which is why it exists here: to count those misses.
#pragma once

#include <cstdint>
#include <vector>

#include "exactccd/export.hpp"
#include "exactccd/scene.hpp"

namespace exactccd {

/// Two triangles of the scene, (first_mesh, first_triangle) < (second_mesh, second_triangle).
struct TrianglePair {
  MeshId first_mesh = 0;              ///< the mesh of the first triangle
  std::uint32_t first_triangle = 0;   ///< the first triangle's row in Scene::triangles
  MeshId second_mesh = 0;             ///< the mesh of the second triangle
  std::uint32_t second_triangle = 0;  ///< the second triangle's row in Scene::triangles

  /// Equal pairs: every field equal.

  friend bool operator==(const TrianglePair& a, const TrianglePair& b) {
    return a.first_mesh == b.first_mesh && a.first_triangle == b.first_triangle &&
           a.second_mesh == b.second_mesh && a.second_triangle == b.second_triangle;
  }
  /// Lexicographic order of (first_mesh, first_triangle, second_mesh, second_triangle).
  friend EXACTCCD_API bool operator<(const TrianglePair& a, const TrianglePair& b);
};

/// Every pair of closed triangles that share a point (exact test on the doubles) when each
/// vertex is at the double nearest to (1 - t) x_start + t x_end, ties to even (exactly x_start
/// at t = 0 and x_end at t = 1). Pairs follow the scene's rules: none between two static meshes, pairs within
/// a moving mesh only when `self_collision`, and never two triangles sharing a vertex. Sorted.
/// \param scene the meshes and their motion.
/// \param t the instant, in [0, 1].
/// \param self_collision whether pairs within one moving mesh count.
/// \return the intersecting pairs, sorted.
/// \throws std::invalid_argument unless 0 <= t <= 1.
EXACTCCD_API std::vector<TrianglePair> intersecting_triangle_pairs(const Scene& scene, double t,
                                                                   bool self_collision = true);

/// Options of discrete_collision.
struct DiscreteOptions {
  /// Whether pairs within one moving mesh count (as SceneOptions::self_collision).
  bool self_collision = true;
  /// Bisection steps of the backtracking (each halves the bracket of the first contact), in
  /// [0, 60]; std::invalid_argument otherwise.
  int bisection_steps = 20;
};

/// The answer of discrete_collision.
struct DiscreteResult {
  /// True when some triangle pair intersects at the end of the step.
  bool collides = false;
  /// When collides: the approximate first contact time, the earliest instant that bisection
  /// found intersecting (the bracket [toi_lo, toi_hi] has width 2^-bisection_steps, or is two
  /// consecutive doubles once no double lies between its ends; the positions at toi_lo do not
  /// intersect unless toi_lo == 0). Not certified: contacts that start and end between two
  /// probed instants are not seen. +infinity when !collides, as CcdResult's (\ref no_contact_toi).
  double toi_lo = kNoContactToi;
  /// The upper end of the bracket (see toi_lo): positions there intersect. +infinity when
  /// !collides.
  double toi_hi = kNoContactToi;
  /// The pairs intersecting at the end of the step.
  std::vector<TrianglePair> pairs_at_end;
};

/// The discrete baseline over the scene's step: the pairs intersecting at its end and, when
/// there are any, the bisection bracket of the first intersecting instant.
/// \param scene the meshes and their motion.
/// \param options self-collision and the number of bisection steps.
/// \return the verdict, the bracket, the pairs at the end.
/// \throws std::invalid_argument unless 0 <= options.bisection_steps <= 60.
EXACTCCD_API DiscreteResult discrete_collision(const Scene& scene,
                                               const DiscreteOptions& options = {});

}  // namespace exactccd
