// FCL 0.7 (Debian's libfcl-dev) as the comparison runs it: the objects a query or a demo step
// becomes, the transforms of a RigidMotion, and one call of fcl::continuousCollide per setting.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::fcl_comparison {

/// How a primitive or a mesh is handed to FCL.
enum class Representation {
  convex,     ///< fcl::Convex of the primitive's 1, 2 or 3 points (GJK distances)
  mesh,       ///< fcl::BVHModel<OBBRSS> (degenerate triangles for points and segments)
  mesh_rss,   ///< fcl::BVHModel<RSS>
};

enum class Solver { conservative_advancement, naive, polynomial };

/// One way of calling continuousCollide.
struct Setting {
  std::string name;
  Representation representation = Representation::mesh;
  Solver solver = Solver::conservative_advancement;
  bool libccd = true;       ///< GJK solver (for convex shapes): libccd, else FCL's own
  int iterations = 10;      ///< num_max_iterations (the naive solver's samples)
  bool rotations = true;    ///< run on rotations (screw motion)
  bool translations = true; ///< run on translations (translation motion)
};

/// The settings the comparison runs (see the README's table).
std::vector<Setting> settings_for_pairs();
std::vector<Setting> settings_for_meshes();

/// An FCL geometry built once (opaque; shared so that copies are cheap).
struct Geometry {
  std::shared_ptr<void> object;  ///< an fcl::CollisionGeometry<double>
  Representation representation = Representation::mesh;
};

/// The geometry of 1 to 3 points (a vertex, an edge, a triangle) or of a mesh.
Geometry make_points(const std::vector<Eigen::Vector3d>& points, Representation r);
Geometry make_mesh(const Positions& positions, const Triangles& triangles, Representation r);

/// The rigid transform x -> R x + T of a motion's end pose (s = 1): R = C(q) (in doubles from
/// the matrix form), T = c + d - R c.
struct Pose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};
Pose end_pose(const RigidMotion& m);
/// The pose composed: first `first`, then `then`.
Pose compose(const Pose& then, const Pose& first);

struct FclAnswer {
  bool collides = false;
  double toc = 1;  ///< FCL's time of contact: the fraction of its motion (angle or distance)
};

/// continuousCollide of `moving` from pose `from` to pose `to` (screw motion when `rotation`,
/// else translation motion) against `fixed` at rest (identity). For the polynomial solver the
/// models are copied first (the solver moves their vertices).
FclAnswer continuous_collide(const Setting& s, const Geometry& moving, const Pose& from,
                             const Pose& to, const Geometry& fixed, bool rotation);

}  // namespace exactccd::fcl_comparison
