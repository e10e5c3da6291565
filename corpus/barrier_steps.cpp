#include "corpus/barrier_steps.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace exactccd::corpus {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The cloth: an n x n grid of width 2 at height z, wrinkled by a few ripples; it falls by `drop`
/// with a random jitter of `jitter` per vertex.
StepBody falling_cloth(int n, double z, double drop, double jitter, std::mt19937_64& rng) {
  StepBody b;
  b.mesh = scenes::grid_sheet(n, 2.0, {0.0, 0.0, z});
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  b.end = b.mesh.positions;
  for (Eigen::Index v = 0; v < b.mesh.positions.rows(); ++v) {
    const double x = b.mesh.positions(v, 0), y = b.mesh.positions(v, 1);
    b.mesh.positions(v, 2) += 0.02 * std::sin(9 * x) * std::cos(7 * y);
    for (int k = 0; k < 3; ++k)
      b.end(v, k) = b.mesh.positions(v, k) + jitter * u(rng) - (k == 2 ? drop : 0.0);
  }
  return b;
}

std::vector<StepBody> cloth_on_ball(double scale, std::mt19937_64& rng) {
  const int n = std::max(8, static_cast<int>(std::lround(160 * std::sqrt(scale))));
  const double cell = 2.0 / n;
  std::vector<StepBody> bodies;
  bodies.push_back(falling_cloth(n, 1.0 + 2 * cell, 15 * cell, 2 * cell, rng));
  StepBody ball;
  const int slices = std::max(8, static_cast<int>(std::lround(96 * std::sqrt(scale))));
  ball.mesh = scenes::uv_sphere({0.0, 0.0, 0.0}, 1.0, slices, slices / 2);
  ball.end = ball.mesh.positions;
  ball.is_static = true;
  bodies.push_back(std::move(ball));
  return bodies;
}

std::vector<StepBody> many_bodies(double scale, std::mt19937_64& rng) {
  const int k = std::max(2, static_cast<int>(std::lround(12 * std::cbrt(scale))));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<StepBody> bodies;
  const double spacing = 0.25, radius = 0.1;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) {
        const Eigen::Vector3d c = spacing * Eigen::Vector3d(i, j, l) -
                                  spacing * (k - 1) / 2.0 * Eigen::Vector3d::Ones();
        StepBody b;
        b.mesh = scenes::uv_sphere(c, radius, 12, 6);
        // Towards the middle by about two spacings, with a random spin-free wobble.
        const Eigen::Vector3d velocity =
            -0.5 * c + 0.15 * Eigen::Vector3d(u(rng), u(rng), u(rng));
        b.end = scenes::translated(b.mesh.positions, velocity);
        bodies.push_back(std::move(b));
      }
  return bodies;
}

std::vector<StepBody> resting_slide(double scale, std::mt19937_64& rng) {
  const int n = std::max(8, static_cast<int>(std::lround(120 * std::sqrt(scale))));
  const double cell = 2.0 / n;
  std::vector<StepBody> bodies;
  StepBody floor;
  floor.mesh = scenes::grid_sheet(n / 2, 3.0, {0.0, 0.0, 0.0});
  floor.end = floor.mesh.positions;
  floor.is_static = true;
  bodies.push_back(std::move(floor));
  StepBody sheet;  // on the floor (z = 0 exactly), sliding by 5 cells along x
  sheet.mesh = scenes::grid_sheet(n, 2.0, {0.0, 0.0, 0.0});
  sheet.end = scenes::translated(sheet.mesh.positions, {5 * cell, 0.0, 0.0});
  bodies.push_back(std::move(sheet));
  bodies.push_back(falling_cloth(n, 4 * cell, 6 * cell, cell, rng));  // falling onto it
  return bodies;
}

/// Granular media: about 100,000 small meshes at scale 1 (the mesh-level broad phase's case):
/// half static one-triangle debris on a jittered floor, half small boxes falling onto it by
/// about their own size, tumbling apart, some already resting on the debris at t = 0.
std::vector<StepBody> debris_field(double scale, std::mt19937_64& rng) {
  const int side = std::max(4, static_cast<int>(std::lround(224 * std::sqrt(scale))));
  const double cell = 1.0 / 64;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<StepBody> bodies;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      StepBody d;
      const Eigen::Vector3d c(i * cell + 0.2 * cell * u(rng), j * cell + 0.2 * cell * u(rng), 0.0);
      d.mesh.positions.resize(3, 3);
      d.mesh.positions.row(0) = c.transpose();
      d.mesh.positions.row(1) = (c + Eigen::Vector3d(0.9 * cell, 0.1 * cell * u(rng), 0.0)).transpose();
      d.mesh.positions.row(2) = (c + Eigen::Vector3d(0.1 * cell, 0.9 * cell, 0.0)).transpose();
      d.mesh.triangles.resize(1, 3);
      d.mesh.triangles << 0, 1, 2;
      d.end = d.mesh.positions;
      d.is_static = true;
      bodies.push_back(std::move(d));
    }
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      StepBody b;
      const bool resting = (i + 3 * j) % 7 == 0;  // on the floor at t = 0
      const Eigen::Vector3d lo(i * cell + 0.3 * cell * u(rng), j * cell + 0.3 * cell * u(rng),
                               resting ? 0.0 : 0.5 * cell + 0.5 * cell * u(rng));
      b.mesh = scenes::box(lo, lo + 0.6 * cell * Eigen::Vector3d::Ones());
      const Eigen::Vector3d velocity(0.5 * cell * u(rng), 0.5 * cell * u(rng),
                                     resting ? 0.0 : -1.5 * cell);
      b.end = scenes::translated(b.mesh.positions, velocity);
      bodies.push_back(std::move(b));
    }
  return bodies;
}


/// A bundle of k x k thin rods along z (open tubes), twisted in one step by `turn` radians end
/// to end about the bundle's axis (each vertex on the chord of its turn, by an angle that grows
/// with its height) and pulled together towards the middle of its length (by up to 40%, where
/// rods 0.05 apart come to overlap by 0.05): neighbouring rods meet along their length.
std::vector<StepBody> twisted_rods(double scale, std::mt19937_64& rng) {
  const int k = 8;
  const int segments = std::max(4, static_cast<int>(std::lround(100 * scale)));
  const int sides = 8;
  const double spacing = 0.25, radius = 0.1, length = 4.0, turn = kPi / 2;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<StepBody> bodies;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double x = spacing * (i - (k - 1) / 2.0), y = spacing * (j - (k - 1) / 2.0);
      StepBody b;
      b.mesh = scenes::open_tube({x, y, 0.0}, {x, y, length}, radius, sides, segments);
      b.end = b.mesh.positions;
      for (Eigen::Index v = 0; v < b.end.rows(); ++v) {
        const Eigen::RowVector3d p = b.mesh.positions.row(v);
        const double a = turn * p(2) / length + 0.01 * u(rng);
        // The rod's axis comes closer to the bundle's; its cross-section keeps its size.
        const double tighten = 1.0 - 0.4 * std::sin(kPi * p(2) / length);
        const double qx = p(0) - (1.0 - tighten) * x, qy = p(1) - (1.0 - tighten) * y;
        b.end(v, 0) = std::cos(a) * qx - std::sin(a) * qy;
        b.end(v, 1) = std::sin(a) * qx + std::cos(a) * qy;
      }
      bodies.push_back(std::move(b));
    }
  return bodies;
}

/// A thick slab (a closed subdivided box) pushed forward along x by half its width between two
/// static rollers (open tubes along y) whose gap is 0.2 narrower than the slab's thickness of 0.4,
/// and squeezed by a quarter of its thickness over the step.
std::vector<StepBody> rollers(double scale, std::mt19937_64& rng) {
  const int n = std::max(8, static_cast<int>(std::lround(150 * std::sqrt(scale))));
  const int around = std::max(8, static_cast<int>(std::lround(96 * std::sqrt(scale))));
  const double thickness = 0.4, gap = 0.2, roller = 0.5;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<StepBody> bodies;
  StepBody slab;
  slab.mesh = scenes::thin_slab(n, 2.0, thickness, {-1.6, 0.0, 0.0});  // 0.1 short of them
  slab.end = slab.mesh.positions;
  const double cell = 2.0 / n;
  for (Eigen::Index v = 0; v < slab.end.rows(); ++v) {
    slab.end(v, 0) += 1.0 + 0.2 * cell * u(rng);
    slab.end(v, 1) += 0.2 * cell * u(rng);
    slab.end(v, 2) *= 0.75;
  }
  bodies.push_back(std::move(slab));
  for (const double side : {-1.0, 1.0}) {
    StepBody r;
    const double z = side * (gap / 2 + roller);
    r.mesh = scenes::open_tube({0.0, -1.5, z}, {0.0, 1.5, z}, roller, around, around);
    r.end = r.mesh.positions;
    r.is_static = true;
    bodies.push_back(std::move(r));
  }
  return bodies;
}

}  // namespace

const std::vector<std::string>& barrier_step_names() {
  static const std::vector<std::string> names = {"cloth_on_ball", "many_bodies",  "resting_slide",
                                                 "debris_field",  "twisted_rods", "rollers"};
  return names;
}

std::vector<StepBody> barrier_step(const std::string& name, double scale) {
  if (!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("barrier_step: the scale must be positive and finite");
  std::mt19937_64 rng(27);
  if (name == "cloth_on_ball") return cloth_on_ball(scale, rng);
  if (name == "many_bodies") return many_bodies(scale, rng);
  if (name == "resting_slide") return resting_slide(scale, rng);
  if (name == "debris_field") return debris_field(scale, rng);
  if (name == "twisted_rods") return twisted_rods(scale, rng);
  if (name == "rollers") return rollers(scale, rng);
  throw std::invalid_argument("barrier_step: no step named \"" + name + "\"");
}

Scene make_scene(const std::vector<StepBody>& bodies) {
  Scene scene;
  for (const StepBody& b : bodies) {
    if (b.is_static) {
      scene.add_static_mesh(b.mesh.positions, b.mesh.triangles);
    } else {
      const MeshId id = scene.add_mesh(b.mesh.positions, b.mesh.triangles);
      scene.set_motion(id, b.mesh.positions, b.end);
    }
  }
  return scene;
}

}  // namespace exactccd::corpus
