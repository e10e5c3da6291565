#include "corpus/rigid_queries.hpp"

#include <cmath>
#include <random>

#include <Eigen/Geometry>

namespace exactccd::rigid_queries {

namespace {

using Eigen::Vector3d;

struct Draw {
  std::mt19937_64 rng;
  explicit Draw(std::uint64_t seed, std::size_t index) : rng(seed * 0x9E3779B97F4A7C15ull + index) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vector3d point(double size) {
    const double x = uniform(-size, size);
    const double y = uniform(-size, size);
    const double z = uniform(-size, size);
    return {x, y, z};
  }
  Vector3d direction() {
    for (;;) {
      const Vector3d v = point(1.0);
      if (v.norm() > 0.1 && v.norm() <= 1.0) return v / v.norm();
    }
  }
  RigidMotion turn(double max_degrees, bool translate, double size) {
    const double angle = uniform(-max_degrees, max_degrees) * M_PI / 180.0;
    const Vector3d pivot = point(size);
    const Vector3d axis = direction();
    const Vector3d d = translate ? point(size) : Vector3d::Zero();
    return RigidMotion::turn(pivot, axis, angle, d);
  }
  /// 0, or +-2^e * scale with e uniform in [-40, -2].
  double offset(double scale) {
    if (scale == 0.0) return 0.0;
    const double e = uniform(-40.0, -2.0);
    const double sign = uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    return sign * std::exp2(e) * scale;
  }
};

/// The first body's motion, and the second's given where its primitive is at s0 (x_s0) and at
/// s = 0 (x0, output): a rigid turn of its own, or straight lines, placed so that at s0 its
/// primitive is where the generator put it.
SideMotion other_side(Draw& draw, const RigidQueryOptions& o, const Vector3d* at_s0, int n,
                      double s0, Vector3d* start) {
  SideMotion side;
  if (o.other == OtherMotion::rest) {
    side = SideMotion::of(RigidMotion{});
    for (int i = 0; i < n; ++i) start[i] = at_s0[i];
    return side;
  }
  if (o.other == OtherMotion::linear) {
    side.kind = PathKind::linear;
    const Vector3d velocity = draw.point(1.0);
    for (int i = 0; i < n; ++i) {
      const Vector3d v = velocity + 0.1 * draw.point(1.0);
      start[i] = at_s0[i] - s0 * v;
      side.linear_end[i] = start[i] + v;
    }
    return side;
  }
  // A rigid turn whose pose at s0 is close to the identity's: find x0 with x(s0) = at_s0 by
  // inverting the motion at s0 (in doubles; the query is whatever those doubles are).
  const RigidMotion m =
      draw.turn(o.pure_translation ? 0.0 : o.max_angle_degrees / 2, !o.pure_rotation, 1.0);
  RigidMotion inverse;  // x = c + s0 d + R (x0 - c)  =>  x0 = c + R^T (x - c - s0 d)
  inverse.pivot = m.pivot;
  inverse.cayley = -s0 * m.cayley;  // C(-v) = C(v)^T
  for (int i = 0; i < n; ++i) start[i] = position_at(inverse, at_s0[i] - s0 * m.translation, 1.0);
  return SideMotion::of(m);
}

}  // namespace

std::vector<RigidVertexFaceQuery> random_rigid_vertex_face(std::uint64_t seed, std::size_t count,
                                                            const RigidQueryOptions& o) {
  std::vector<RigidVertexFaceQuery> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    Draw draw(seed, i);
    RigidVertexFaceQuery q;
    q.a = draw.point(1.0);
    q.b = draw.point(1.0);
    q.c = draw.point(1.0);
    const RigidMotion face =
        draw.turn(o.pure_translation ? 0.0 : o.max_angle_degrees, !o.pure_rotation, 1.0);
    q.face = SideMotion::of(face);
    const double s0 = draw.uniform(0.0, 1.0);
    const double u = draw.uniform(0.0, 1.0);
    const double v = draw.uniform(0.0, 1.0 - u);
    const Vector3d a = position_at(face, q.a, s0), b = position_at(face, q.b, s0),
                   c = position_at(face, q.c, s0);
    const Vector3d normal = (b - a).cross(c - a).normalized();
    const double size = (b - a).norm() + (c - a).norm();
    const Vector3d at_s0 = a + u * (b - a) + v * (c - a) + draw.offset(o.offset_scale * size) * normal;
    q.vertex = other_side(draw, o, &at_s0, 1, s0, &q.p);
    out.push_back(q);
  }
  return out;
}

std::vector<RigidEdgeEdgeQuery> random_rigid_edge_edge(std::uint64_t seed, std::size_t count,
                                                        const RigidQueryOptions& o) {
  std::vector<RigidEdgeEdgeQuery> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    Draw draw(seed, i);
    RigidEdgeEdgeQuery q;
    q.ea0 = draw.point(1.0);
    q.ea1 = draw.point(1.0);
    const RigidMotion edge =
        draw.turn(o.pure_translation ? 0.0 : o.max_angle_degrees, !o.pure_rotation, 1.0);
    q.edge_a = SideMotion::of(edge);
    const double s0 = draw.uniform(0.0, 1.0);
    const Vector3d a0 = position_at(edge, q.ea0, s0), a1 = position_at(edge, q.ea1, s0);
    // Edge b crosses edge a's pose at s0 at a random point, in a random direction, and is
    // moved off along the common normal.
    const Vector3d hit = a0 + draw.uniform(0.0, 1.0) * (a1 - a0);
    const Vector3d direction = draw.direction();
    const double before = draw.uniform(0.05, 1.0), after = draw.uniform(0.05, 1.0);
    Vector3d normal = (a1 - a0).cross(direction);
    if (normal.norm() > 0) normal.normalize();
    const Vector3d offset = draw.offset(o.offset_scale * (a1 - a0).norm()) * normal;
    const Vector3d at_s0[2] = {hit - before * direction + offset, hit + after * direction + offset};
    Vector3d start[2];
    q.edge_b = other_side(draw, o, at_s0, 2, s0, start);
    q.eb0 = start[0];
    q.eb1 = start[1];
    out.push_back(q);
  }
  return out;
}

}  // namespace exactccd::rigid_queries
