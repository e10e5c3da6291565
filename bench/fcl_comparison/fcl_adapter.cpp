#include "bench/fcl_comparison/fcl_adapter.hpp"

#include <fcl/fcl.h>

#include <stdexcept>

namespace exactccd::fcl_comparison {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

template <class BV>
std::shared_ptr<void> bvh(const std::vector<Vector3d>& v,
                          const std::vector<fcl::Triangle>& t) {
  auto m = std::make_shared<fcl::BVHModel<BV>>();
  m->beginModel(static_cast<int>(t.size()), static_cast<int>(v.size()));
  m->addSubModel(v, t);
  m->endModel();
  return m;
}

const fcl::CollisionGeometry<double>* geometry(const Geometry& g) {
  return static_cast<const fcl::CollisionGeometry<double>*>(g.object.get());
}

/// A copy of a mesh model (the polynomial solver moves the vertices of the models it gets).
template <class BV>
std::shared_ptr<fcl::BVHModel<BV>> copy_of(const Geometry& g) {
  return std::make_shared<fcl::BVHModel<BV>>(
      *static_cast<const fcl::BVHModel<BV>*>(g.object.get()));
}

fcl::Transform3d transform(const Pose& p) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = p.rotation;
  t.translation() = p.translation;
  return t;
}

}  // namespace

std::vector<Setting> settings_for_pairs() {
  std::vector<Setting> s;
  s.push_back({"conservative advancement, Convex shapes, GJK libccd", Representation::convex,
               Solver::conservative_advancement, true, 10, true, true});
  s.push_back({"conservative advancement, Convex shapes, GJK indep", Representation::convex,
               Solver::conservative_advancement, false, 10, true, true});
  s.push_back({"conservative advancement, BVHModel<OBBRSS>", Representation::mesh,
               Solver::conservative_advancement, true, 10, true, true});
  s.push_back({"conservative advancement, BVHModel<RSS>", Representation::mesh_rss,
               Solver::conservative_advancement, true, 10, true, true});
  s.push_back({"naive, 10 samples, BVHModel<OBBRSS>", Representation::mesh, Solver::naive, true,
               10, true, true});
  s.push_back({"naive, 100 samples, BVHModel<OBBRSS>", Representation::mesh, Solver::naive, true,
               100, true, true});
  s.push_back({"polynomial solver, BVHModel<OBBRSS>", Representation::mesh, Solver::polynomial,
               true, 10, false, true});
  return s;
}

std::vector<Setting> settings_for_meshes() {
  std::vector<Setting> s;
  s.push_back({"conservative advancement, BVHModel<OBBRSS>", Representation::mesh,
               Solver::conservative_advancement, true, 10, true, true});
  s.push_back({"conservative advancement, BVHModel<RSS>", Representation::mesh_rss,
               Solver::conservative_advancement, true, 10, true, true});
  s.push_back({"naive, 10 samples, BVHModel<OBBRSS>", Representation::mesh, Solver::naive, true,
               10, true, true});
  s.push_back({"naive, 100 samples, BVHModel<OBBRSS>", Representation::mesh, Solver::naive, true,
               100, true, true});
  s.push_back({"polynomial solver, BVHModel<OBBRSS>", Representation::mesh, Solver::polynomial,
               true, 10, false, true});
  return s;
}

Geometry make_points(const std::vector<Vector3d>& points, Representation r) {
  if (points.empty() || points.size() > 3)
    throw std::invalid_argument("make_points: 1 to 3 points");
  Geometry g;
  g.representation = r;
  if (r == Representation::convex) {
    auto vertices = std::make_shared<std::vector<Vector3d>>(points);
    auto faces = std::make_shared<std::vector<int>>();
    int face_count = 0;
    if (points.size() == 3) {  // both sides of the triangle
      *faces = {3, 0, 1, 2, 3, 0, 2, 1};
      face_count = 2;
    }
    auto c = std::make_shared<fcl::Convexd>(vertices, face_count, faces);
    c->computeLocalAABB();
    g.object = c;
    return g;
  }
  // A mesh of one triangle: the points repeated for a vertex ([p, p, p]) or an edge ([a, b, b]).
  const std::vector<Vector3d> v = {points[0], points[points.size() > 1 ? 1 : 0],
                                   points[points.size() - 1]};
  const std::vector<fcl::Triangle> t = {fcl::Triangle(0, 1, 2)};
  g.object = r == Representation::mesh_rss ? bvh<fcl::RSSd>(v, t) : bvh<fcl::OBBRSSd>(v, t);
  return g;
}

Geometry make_mesh(const Positions& positions, const Triangles& triangles, Representation r) {
  if (r == Representation::convex) throw std::invalid_argument("make_mesh: meshes only");
  std::vector<Vector3d> v(static_cast<std::size_t>(positions.rows()));
  for (Eigen::Index i = 0; i < positions.rows(); ++i)
    v[static_cast<std::size_t>(i)] = positions.row(i).transpose();
  std::vector<fcl::Triangle> t;
  t.reserve(static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    t.emplace_back(triangles(f, 0), triangles(f, 1), triangles(f, 2));
  Geometry g;
  g.representation = r;
  g.object = r == Representation::mesh_rss ? bvh<fcl::RSSd>(v, t) : bvh<fcl::OBBRSSd>(v, t);
  return g;
}

Pose end_pose(const RigidMotion& m) {
  const Vector3d& q = m.cayley;
  const double qq = q.squaredNorm();
  Matrix3d skew;
  skew << 0, -q.z(), q.y(), q.z(), 0, -q.x(), -q.y(), q.x(), 0;
  Pose p;
  p.rotation = ((1 - qq) * Matrix3d::Identity() + 2 * q * q.transpose() + 2 * skew) / (1 + qq);
  p.translation = m.pivot + m.translation - p.rotation * m.pivot;
  return p;
}

Pose compose(const Pose& then, const Pose& first) {
  return {then.rotation * first.rotation, then.rotation * first.translation + then.translation};
}

FclAnswer continuous_collide(const Setting& s, const Geometry& moving, const Pose& from,
                             const Pose& to, const Geometry& fixed, bool rotation) {
  fcl::ContinuousCollisionRequestd request;
  request.num_max_iterations = static_cast<std::size_t>(s.iterations);
  request.ccd_motion_type = rotation ? fcl::CCDM_SCREW : fcl::CCDM_TRANS;
  request.gjk_solver_type = s.libccd ? fcl::GST_LIBCCD : fcl::GST_INDEP;
  request.ccd_solver_type = s.solver == Solver::naive      ? fcl::CCDC_NAIVE
                            : s.solver == Solver::polynomial ? fcl::CCDC_POLYNOMIAL_SOLVER
                                                             : fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  fcl::ContinuousCollisionResultd result;
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  if (s.solver == Solver::polynomial) {
    if (rotation) throw std::invalid_argument("the polynomial solver takes translations only");
    // It moves the models' vertices: give it copies.
    std::shared_ptr<fcl::CollisionGeometry<double>> a, b;
    if (moving.representation == Representation::mesh_rss) {
      a = copy_of<fcl::RSSd>(moving);
      b = copy_of<fcl::RSSd>(fixed);
    } else {
      a = copy_of<fcl::OBBRSSd>(moving);
      b = copy_of<fcl::OBBRSSd>(fixed);
    }
    fcl::continuousCollide(a.get(), transform(from), transform(to), b.get(), identity, identity,
                           request, result);
  } else {
    fcl::continuousCollide(geometry(moving), transform(from), transform(to), geometry(fixed),
                           identity, identity, request, result);
  }
  return {result.is_collide, result.time_of_contact};
}

}  // namespace exactccd::fcl_comparison
