// Barrier-method trial steps (issue 27): one full unconstrained step of a scene whose swept boxes
// overlap by the hundred thousand or million and where many close pairs collide, as a simulator
// of the IPC family asks about before its line search. Each step is a list of bodies (a mesh,
// its end positions, static or moving linearly), reproducible bit for bit from its name, the
// scale and a fixed seed.
//
// Steps (scale 1 gives 20k-650k triangles; the resolution grows with the scale):
//   cloth_on_ball  a wrinkled cloth dropped onto a sphere by a step of 15 cells, jittered
//   many_bodies    a lattice of small spheres flung towards the middle by several diameters
//   resting_slide  a cloth lying on a floor sliding in its plane (contact at t = 0, coplanar
//                  edges throughout), the same cloth wrinkled above
//   debris_field   granular media: about 100,000 small meshes at scale 1, static one-triangle
//                  debris and small boxes falling onto it (some resting on it at t = 0)
//   twisted_rods   a bundle of 64 thin rods twisted by a quarter turn end to end in one step
//                  and pulled together in the middle: neighbouring rods meet along their length
//   rollers        a thick slab pushed forward between two static rollers whose gap is
//                  narrower than the slab, and squeezed by a quarter of its thickness
#pragma once

#include <string>
#include <vector>

#include "corpus/meshes.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::corpus {

/// One body of a step: its mesh (start positions), its end positions, static or moving.
struct StepBody {
  scenes::Mesh mesh;
  Positions end;
  bool is_static = false;
};

/// The names of the steps, in the order above.
const std::vector<std::string>& barrier_step_names();

/// The bodies of the named step at `scale` (> 0). Throws std::invalid_argument for an unknown
/// name or a scale that is not positive and finite.
std::vector<StepBody> barrier_step(const std::string& name, double scale);

/// A scene of the bodies: static meshes with add_static_mesh, moving ones with add_mesh and
/// set_motion.
Scene make_scene(const std::vector<StepBody>& bodies);

}  // namespace exactccd::corpus
