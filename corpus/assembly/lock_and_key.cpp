#include "corpus/assembly/lock_and_key.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace exactccd::assembly {

namespace {

using Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

/// Builds a mesh part by part.
class Builder {
 public:
  int vertex(const Vector3d& p) {
    vertices_.push_back(p);
    return static_cast<int>(vertices_.size()) - 1;
  }
  void triangle(int a, int b, int c) { triangles_.push_back({a, b, c}); }
  /// The quad a b c d (counterclockwise seen from where it faces) as two triangles.
  void quad(int a, int b, int c, int d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  void begin_part(const std::string& name) {
    parts_.push_back({name, vertex_count(), 0, triangle_count(), 0});
  }
  void end_part() {
    parts_.back().vertex_end = vertex_count();
    parts_.back().triangle_end = triangle_count();
  }
  void positions(std::vector<Vector3d>& out) const { out = vertices_; }
  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  int triangle_count() const { return static_cast<int>(triangles_.size()); }

  PartMesh finish() {
    PartMesh out;
    out.parts = parts_;
    out.mesh.positions.resize(static_cast<Eigen::Index>(vertices_.size()), 3);
    for (std::size_t i = 0; i < vertices_.size(); ++i)
      out.mesh.positions.row(static_cast<Eigen::Index>(i)) = vertices_[i].transpose();
    out.mesh.triangles.resize(static_cast<Eigen::Index>(triangles_.size()), 3);
    for (std::size_t f = 0; f < triangles_.size(); ++f)
      for (int k = 0; k < 3; ++k)
        out.mesh.triangles(static_cast<Eigen::Index>(f), k) = triangles_[f][k];
    return out;
  }

 private:
  std::vector<Vector3d> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Part> parts_;
};

/// The circumscribed radius of an n-gon whose inscribed radius is at least `inscribed` (a
/// relative margin of 1e-15 covers the rounding of cos and of the vertices' coordinates).
double circumradius_for_inscribed(double inscribed, int n) {
  return inscribed / std::cos(kPi / n) * (1 + 1e-15);
}

/// n vertices on the circle of radius r at height z, at angles 2 pi k / n.
std::vector<int> ring(Builder& b, double r, double z, int n) {
  std::vector<int> out(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * kPi * k / n;
    out[static_cast<std::size_t>(k)] = b.vertex({r * std::cos(phi), r * std::sin(phi), z});
  }
  return out;
}

/// A closed tube about the z axis: parts "<name> inner wall" (normals toward the axis),
/// "<name> outer wall", "<name> ends". Inner and outer are circumscribed radii.
void tube(Builder& b, const std::string& name, double inner, double outer, double z0, double z1,
          int n) {
  b.begin_part(name + " inner wall");
  const std::vector<int> ib = ring(b, inner, z0, n), it = ring(b, inner, z1, n);
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    b.quad(ib[k], it[k], it[j], ib[j]);  // faces the axis
  }
  b.end_part();
  b.begin_part(name + " outer wall");
  const std::vector<int> ob = ring(b, outer, z0, n), ot = ring(b, outer, z1, n);
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    b.quad(ob[k], ob[j], ot[j], ot[k]);  // faces away from the axis
  }
  b.end_part();
  b.begin_part(name + " ends");  // triangles only: their vertices belong to the walls
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    b.quad(it[k], ot[k], ot[j], it[j]);  // top, +z
    b.quad(ib[k], ib[j], ob[j], ob[k]);  // bottom, -z
  }
  b.end_part();
}

/// The closed box [lo, hi] in a frame (origin o, axes u, v, w): corners o + x u + y v + z w.
void framed_box(Builder& b, const std::string& name, const Vector3d& lo, const Vector3d& hi,
                const Vector3d& o, const Vector3d& u, const Vector3d& v, const Vector3d& w) {
  b.begin_part(name);
  int c[8];
  for (int i = 0; i < 8; ++i) {
    const double x = (i & 1) ? hi.x() : lo.x(), y = (i & 2) ? hi.y() : lo.y(),
                 z = (i & 4) ? hi.z() : lo.z();
    c[i] = b.vertex(o + x * u + y * v + z * w);
  }
  b.quad(c[0], c[2], c[3], c[1]);  // -w
  b.quad(c[4], c[5], c[7], c[6]);  // +w
  b.quad(c[0], c[1], c[5], c[4]);  // -v
  b.quad(c[2], c[6], c[7], c[3]);  // +v
  b.quad(c[0], c[4], c[6], c[2]);  // -u
  b.quad(c[1], c[3], c[7], c[5]);  // +u
  b.end_part();
}

/// Triangulates the flat region between two closed polygons in the plane z = const, the inner
/// one inside the outer one (vertex indices of `b`, positions xy), by a constrained Delaunay
/// triangulation of both outlines keeping the faces between them. Triangles face +z when
/// `up`, else -z.
void triangulate_ring(Builder& b, const std::vector<int>& inner, const std::vector<int>& outer,
                      const std::vector<Vector3d>& xy, bool up) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
  Cdt cdt;
  for (const std::vector<int>* loop : {&inner, &outer}) {
    std::vector<Cdt::Vertex_handle> h;
    for (int v : *loop) {
      h.push_back(cdt.insert(K::Point_2(xy[static_cast<std::size_t>(v)].x(),
                                        xy[static_cast<std::size_t>(v)].y())));
      h.back()->info() = v;
    }
    for (std::size_t k = 0; k < h.size(); ++k) cdt.insert_constraint(h[k], h[(k + 1) % h.size()]);
  }
  if (cdt.number_of_vertices() != inner.size() + outer.size())
    throw std::logic_error("plate: coincident outline vertices");
  // Faces between the outlines: reached from the infinite face across exactly one constraint
  // (flood fill without crossing constraints, level by level).
  std::map<Cdt::Face_handle, int> level;
  std::vector<std::pair<Cdt::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    const auto [seed, l] = seeds.back();
    seeds.pop_back();
    if (level.count(seed)) continue;
    std::vector<Cdt::Face_handle> stack{seed};
    level[seed] = l;
    while (!stack.empty()) {
      const Cdt::Face_handle f = stack.back();
      stack.pop_back();
      for (int e = 0; e < 3; ++e) {
        const Cdt::Face_handle g = f->neighbor(e);
        if (level.count(g)) continue;
        if (cdt.is_constrained({f, e})) {
          seeds.insert(seeds.begin(), {g, l + 1});  // after every face of this level
        } else {
          level[g] = l;
          stack.push_back(g);
        }
      }
    }
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (level[f] != 1) continue;
    const int a = f->vertex(0)->info(), c1 = f->vertex(1)->info(), c2 = f->vertex(2)->info();
    if (up)
      b.triangle(a, c1, c2);  // CGAL's faces are counterclockwise
    else
      b.triangle(a, c2, c1);
  }
}

}  // namespace

const std::string& PartMesh::part_of_vertex(int v) const {
  static const std::string unknown = "?";
  for (const Part& p : parts)
    if (v >= p.vertex_begin && v < p.vertex_end) return p.name;
  return unknown;
}

const std::string& PartMesh::part_of_triangle(int f) const {
  static const std::string unknown = "?";
  for (const Part& p : parts)
    if (f >= p.triangle_begin && f < p.triangle_end) return p.name;
  return unknown;
}

Dimensions dimensions(const LockDesign& design) {
  if (design.segments < 8 || design.segments > 1 << 20)
    throw std::invalid_argument("lock and key: segments must be in [8, 2^20]");
  if (design.clearance_bits < 4 || design.clearance_bits > 40)
    throw std::invalid_argument("lock and key: clearance bits must be in [4, 40]");
  if (!(design.stop_degrees > 20 && design.stop_degrees < 170))
    throw std::invalid_argument("lock and key: the stop must stand between 20 and 170 degrees");
  Dimensions d;
  d.clearance = std::ldexp(1.0, -design.clearance_bits);
  const double c = d.clearance;
  // Exact dyadic heights: the bit's top stops c below the plate.
  d.bit_top = d.chamber_top - c;
  d.bit_bottom = d.bit_top - 0.375;
  d.key_tip = d.bit_bottom - 0.25;
  d.key_top = d.key_tip + 3.0;
  d.insertion = 1.0 + c;  // the barrel's tip starts at plate_top + 0.125
  d.pivot = Vector3d(0, 0, (d.key_tip + d.key_top) / 2);
  return d;
}

PartMesh make_key(const LockDesign& design) {
  const Dimensions d = dimensions(design);
  const int n = design.segments;
  Builder b;
  // The barrel's inner wall clears the pin by c: its inscribed radius is pin_radius + c.
  const double inner = circumradius_for_inscribed(d.pin_radius + d.clearance, n);
  tube(b, "barrel", inner, d.barrel_outer, d.key_tip, d.key_top, n);
  framed_box(b, "bit", {d.bit_root, -d.bit_half_width, d.bit_bottom},
             {d.bit_tip, d.bit_half_width, d.bit_top}, Vector3d::Zero(), Vector3d::UnitX(),
             Vector3d::UnitY(), Vector3d::UnitZ());
  return b.finish();
}

PartMesh make_lock(const LockDesign& design) {
  const Dimensions d = dimensions(design);
  const int n = design.segments;
  const double c = d.clearance;
  Builder b;

  // The drill pin: a prism with fan caps.
  b.begin_part("pin");
  {
    const std::vector<int> bottom = ring(b, d.pin_radius, 0.0, n), top = ring(b, d.pin_radius,
                                                                               d.pin_top, n);
    const int bc = b.vertex({0, 0, 0}), tc = b.vertex({0, 0, d.pin_top});
    for (int k = 0; k < n; ++k) {
      const int j = (k + 1) % n;
      b.quad(bottom[k], bottom[j], top[j], top[k]);
      b.triangle(tc, top[k], top[j]);
      b.triangle(bc, bottom[j], bottom[k]);
    }
  }
  b.end_part();

  // The chamber: its inner wall clears the bit's far corners by c.
  const double bit_reach = std::hypot(d.bit_tip, d.bit_half_width);
  tube(b, "chamber", circumradius_for_inscribed(bit_reach + c, n), d.outer, 0.0, d.chamber_top, n);

  // The keyhole plate: a round hole clearing the barrel by c, a slot clearing the bit by c.
  b.begin_part("plate");
  {
    const double hole = circumradius_for_inscribed(d.barrel_outer + c, n);
    const double slot_half = d.bit_half_width + c, slot_end = d.bit_tip + c;
    const double corner_x = std::sqrt(hole * hole - slot_half * slot_half);
    const double corner_angle = std::atan2(slot_half, corner_x);
    std::vector<Vector3d> contour;  // counterclockwise from just past the slot
    for (int k = 0; k < n; ++k) {
      const double phi = 2 * kPi * k / n;
      if (phi <= corner_angle || phi >= 2 * kPi - corner_angle) continue;
      contour.emplace_back(hole * std::cos(phi), hole * std::sin(phi), 0);
    }
    contour.emplace_back(corner_x, -slot_half, 0);
    contour.emplace_back(slot_end, -slot_half, 0);
    contour.emplace_back(slot_end, slot_half, 0);
    contour.emplace_back(corner_x, slot_half, 0);
    std::vector<int> ib, it, ob, ot;
    for (const Vector3d& p : contour) {
      ib.push_back(b.vertex({p.x(), p.y(), d.chamber_top}));
      it.push_back(b.vertex({p.x(), p.y(), d.plate_top}));
    }
    ob = ring(b, d.outer, d.chamber_top, n);
    ot = ring(b, d.outer, d.plate_top, n);
    std::vector<Vector3d> xy;
    b.positions(xy);
    triangulate_ring(b, it, ot, xy, true);
    triangulate_ring(b, ib, ob, xy, false);
    const int m = static_cast<int>(contour.size());
    for (int k = 0; k < m; ++k) {
      const int j = (k + 1) % m;
      b.quad(ib[k], it[k], it[j], ib[j]);  // the keyhole's wall faces the hole
    }
    for (int k = 0; k < n; ++k) {
      const int j = (k + 1) % n;
      b.quad(ob[k], ob[j], ot[j], ot[k]);
    }
  }
  b.end_part();

  // The stop rib: a slab standing in the chamber at the stop angle, reaching in to radius
  // 0.998 (the bit reaches 1.0005), tilted by 0.1 rad about its radial axis so that the first
  // contact is between two features in general position.
  {
    const double alpha = design.stop_degrees * kPi / 180, tilt = 0.1;
    const Vector3d radial(std::cos(alpha), std::sin(alpha), 0);
    const Vector3d tangential(-std::sin(alpha), std::cos(alpha), 0);
    const Vector3d v = std::cos(tilt) * tangential + std::sin(tilt) * Vector3d::UnitZ();
    const Vector3d w = -std::sin(tilt) * tangential + std::cos(tilt) * Vector3d::UnitZ();
    const double z_mid = 0.59375;
    framed_box(b, "stop rib", {0.998, -1.0 / 128, -0.34375}, {1.125, 1.0 / 128, 0.34375},
               Vector3d(0, 0, z_mid), radial, v, w);
  }
  return b.finish();
}

std::vector<PlanStep> plan_steps(const LockDesign& design, const Plan& plan) {
  if (plan.insert_steps < 1 || (plan.insert_steps & (plan.insert_steps - 1)) != 0 ||
      plan.insert_steps > 1024)
    throw std::invalid_argument("plan: insert steps must be a power of two in [1, 1024]");
  if (!(plan.step_degrees > 0 && plan.step_degrees <= 60))
    throw std::invalid_argument("plan: a turn step must be in (0, 60] degrees");
  if (!(plan.turn_to_degrees >= 0 && plan.turn_to_degrees < 179))
    throw std::invalid_argument("plan: the final angle must be in [0, 179) degrees");
  const Dimensions d = dimensions(design);
  std::vector<PlanStep> steps;
  for (int k = 0; k < plan.insert_steps; ++k) {
    PlanStep s;
    s.phase = "insert";
    s.index = k;
    s.motion.pivot = d.pivot;
    s.motion.translation = Vector3d(0, 0, -d.insertion / plan.insert_steps);  // exact
    steps.push_back(s);
  }
  const int turns = static_cast<int>(std::ceil(plan.turn_to_degrees / plan.step_degrees - 1e-9));
  for (int k = 0; k < turns; ++k) {
    PlanStep s;
    s.phase = "turn";
    s.index = k;
    s.angle_from = k * plan.step_degrees;
    s.angle_to = std::min(plan.turn_to_degrees, (k + 1) * plan.step_degrees);
    s.motion = RigidMotion::turn(d.pivot, Vector3d::UnitZ(),
                                 (s.angle_to - s.angle_from) * kPi / 180);
    steps.push_back(s);
  }
  return steps;
}

Positions key_positions_at_start(const PartMesh& key, const LockDesign& design,
                                 const PlanStep& step) {
  const Dimensions d = dimensions(design);
  Positions x = key.mesh.positions;
  if (step.phase == "insert") {
    // Above the inserted pose by the part of the insertion still ahead (exact dyadics).
    const int n = static_cast<int>(std::lround(-d.insertion / step.motion.translation.z()));
    const double lift = d.insertion * (n - step.index) / n;
    x.col(2).array() += lift;
    return x;
  }
  if (step.angle_from == 0) return x;
  const RigidMotion pose =
      RigidMotion::turn(d.pivot, Vector3d::UnitZ(), step.angle_from * kPi / 180);
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    x.row(i) = position_at(pose, key.mesh.positions.row(i).transpose(), 1.0).transpose();
  return x;
}

Edges unique_edges(const Triangles& triangles) {
  std::vector<std::pair<std::int32_t, std::int32_t>> e;
  e.reserve(static_cast<std::size_t>(triangles.rows()) * 3);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = triangles(f, k), b = triangles(f, (k + 1) % 3);
      e.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  Edges out(static_cast<Eigen::Index>(e.size()), 2);
  for (std::size_t i = 0; i < e.size(); ++i) {
    out(static_cast<Eigen::Index>(i), 0) = e[i].first;
    out(static_cast<Eigen::Index>(i), 1) = e[i].second;
  }
  return out;
}

}  // namespace exactccd::assembly
