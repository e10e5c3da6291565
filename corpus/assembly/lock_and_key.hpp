// The precise-assembly demonstration with rotation: a barrel key turned in a warded lock.
//
// Everything turns about the z axis. The lock (static) is a drill pin (a polygonal cylinder on
// the axis), a chamber (a polygonal tube), a keyhole plate on top of it (a round hole with a
// slot for the key's bit) and a stop rib inside the chamber. The key (rigid) is a barrel (a
// polygonal tube) that slides over the drill pin, with a rectangular bit on its side. Every
// tight fit has the clearance c (2^-20 of the chamber's radius by default), measured between
// polygons the way that survives turning: the inscribed circle of the outer polygon minus the
// circumscribed circle of the inner one.
//
// The plan: insert the key along -z with the bit aligned with the slot (pure translations; every
// pose exact), then turn it about the z axis in steps (pure rotations about the axis through
// the key's centre, RigidMotion::turn). The stop rib stands in the chamber at 97.5 degrees and
// reaches to just inside the bit's tip: a turn past it makes contact, a turn to 90 degrees does
// not.
//
// Meshes are built procedurally; every part is closed with outward triangles; each mesh is a
// soup of its parts (parts do not share vertices), and `parts` names each part's vertex and
// triangle ranges.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "corpus/meshes.hpp"
#include "exactccd/rigid.hpp"

namespace exactccd::assembly {

/// A named range of a mesh: vertices [vertex_begin, vertex_end), triangles [triangle_begin,
/// triangle_end).
struct Part {
  std::string name;
  int vertex_begin = 0, vertex_end = 0;
  int triangle_begin = 0, triangle_end = 0;
};

struct PartMesh {
  scenes::Mesh mesh;
  std::vector<Part> parts;
  /// The part holding vertex v / triangle f ("?" if none).
  const std::string& part_of_vertex(int v) const;
  const std::string& part_of_triangle(int f) const;
};

struct LockDesign {
  int segments = 1280;         ///< polygon sides of every cylinder (the resolution)
  int clearance_bits = 20;     ///< c = 2^-clearance_bits
  double stop_degrees = 97.5;  ///< the stop rib's angle
};

/// Dimensions (chamber radius about 1; z up; the lock spans 0 <= z <= 1.25).
struct Dimensions {
  double clearance = 0;            ///< c
  double pin_radius = 0.25;        ///< the pin's circumscribed radius
  double pin_top = 1.125;          ///< the pin spans 0 <= z <= pin_top
  double barrel_outer = 0.5;       ///< the barrel's outer circumscribed radius
  double bit_root = 0.4375;        ///< the bit spans bit_root <= x <= bit_tip (key frame)
  double bit_tip = 1.0;
  double bit_half_width = 1.0 / 32;  ///< |y| <= bit_half_width
  double chamber_top = 1.0;        ///< the chamber spans 0 <= z <= chamber_top
  double plate_top = 1.25;         ///< the plate spans chamber_top <= z <= plate_top
  double outer = 1.25;             ///< the lock's outer radius
  double key_tip = 0;              ///< the barrel's lower end at the inserted pose
  double key_top = 0;              ///< the barrel's upper end at the inserted pose
  double bit_bottom = 0;           ///< the bit spans bit_bottom <= z <= bit_top (inserted)
  double bit_top = 0;
  double insertion = 0;            ///< the key starts this far above its inserted pose
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  ///< the key's centre, on the z axis
};

Dimensions dimensions(const LockDesign& design);

/// The key at its inserted pose (bit along +x): barrel inner wall, outer wall, ends, bit.
PartMesh make_key(const LockDesign& design);

/// The lock: pin, chamber, plate, stop rib.
PartMesh make_lock(const LockDesign& design);

/// One step of the plan: the key's positions at its start and its motion over the step.
struct PlanStep {
  std::string phase;       ///< "insert" or "turn"
  int index = 0;           ///< within the phase
  double angle_from = 0;   ///< the key's angle at the start (degrees; turn steps)
  double angle_to = 0;     ///< at the end
  RigidMotion motion;
};

struct Plan {
  int insert_steps = 8;          ///< the insertion, in equal exact translations
  double step_degrees = 15.0;    ///< each turn
  double turn_to_degrees = 90.0; ///< the last pose's angle
};

/// The plan's steps.
std::vector<PlanStep> plan_steps(const LockDesign& design, const Plan& plan);

/// The key's positions at the start of `step` (n x 3): during the insertion the inserted pose
/// translated (exact); when turning, the inserted pose turned by step.angle_from about the
/// z axis through the pivot (position_at: within a few ulps of that pose).
Positions key_positions_at_start(const PartMesh& key, const LockDesign& design,
                                 const PlanStep& step);

/// The distinct edges (i < j) of a triangle list, sorted.
Edges unique_edges(const Triangles& triangles);

}  // namespace exactccd::assembly
