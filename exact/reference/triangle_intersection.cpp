// Exact closed-triangle intersection (exact/reference/triangle_intersection.hpp).
// PROOF: proofs/discrete.md#triangle-test
#include "exact/reference/triangle_intersection.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <stdexcept>

#include "core/predicates/fp_environment.hpp"

namespace exactccd::exact {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;

/// The point set of a possibly degenerate triangle: a proper triangle (dimension 2), a segment
/// with distinct ends v[0], v[1] (dimension 1) or the point v[0] (dimension 0).
struct Shape {
  int dimension = 2;
  Point v[3];
};

Shape shape_of(const Point& p, const Point& q, const Point& r) {
  if (!CGAL::collinear(p, q, r)) return {2, {p, q, r}};
  // Three collinear points: the middle one (in the order along their line) lies on the closed
  // segment between the other two, which is then their convex hull. Some point is in the middle,
  // so when neither q nor p is, r is.
  Point lo = p, hi = q;
  if (CGAL::collinear_are_ordered_along_line(p, q, r)) {
    lo = p, hi = r;
  } else if (CGAL::collinear_are_ordered_along_line(q, p, r)) {
    lo = q, hi = r;
  }
  // Equal ends: the third point lies between them, so all three are that point.
  if (lo == hi) return {0, {lo, lo, lo}};
  return {1, {lo, hi, hi}};
}

Triangle triangle(const Shape& s) { return {s.v[0], s.v[1], s.v[2]}; }
Segment segment(const Shape& s) { return {s.v[0], s.v[1]}; }

/// Each call below meets CGAL's preconditions: triangles and segments are non-degenerate.
bool shapes_intersect(const Shape& a, const Shape& b) {
  if (a.dimension < b.dimension) return shapes_intersect(b, a);
  switch (a.dimension * 3 + b.dimension) {
    case 2 * 3 + 2: return CGAL::do_intersect(triangle(a), triangle(b));
    case 2 * 3 + 1: return CGAL::do_intersect(triangle(a), segment(b));
    case 2 * 3 + 0: return CGAL::do_intersect(triangle(a), b.v[0]);
    case 1 * 3 + 1: return CGAL::do_intersect(segment(a), segment(b));
    case 1 * 3 + 0: return CGAL::do_intersect(segment(a), b.v[0]);
    default: return a.v[0] == b.v[0];
  }
}

Point point(const Eigen::Vector3d& x) {
  if (!x.allFinite())
    throw std::invalid_argument("exactccd: triangles_intersect needs finite coordinates");
  return {x.x(), x.y(), x.z()};
}

}  // namespace

bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                         const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                         const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  // The kernel's static filters bound the rounding errors of round-to-nearest arithmetic with
  // gradual underflow (proofs/filters.md#fp-environment).
  const predicates::RoundToNearestGuard nearest;
  return shapes_intersect(shape_of(point(a0), point(a1), point(a2)),
                          shape_of(point(b0), point(b1), point(b2)));
}

}  // namespace exactccd::exact
