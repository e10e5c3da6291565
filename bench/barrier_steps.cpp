// Barrier-method trial steps (issue 27): one full unconstrained step of scenes whose swept boxes
// overlap by the hundred thousand or million and where many close pairs collide, timed through
// exactccd::Scene. Per step: candidates, cuts by time, colliding pairs, the earliest contact, the
// time of earliest_contact and find_contacts on 1 and 2 threads, with the cull by time on and off
// (the same answers, checked), and the process's peak memory.
//
//   exactccd_barrier_steps [--scale S] [--min-separation D] [--repetitions R] [--json]
//                          [--compare-off]
// (--compare-off also runs each step with the cull by time off, after it on: its candidates
// can take gigabytes; the peak memory printed after "on" is the process's up to then.)
//
// Steps (S scales the mesh resolution; S = 1 gives 20k-100k triangles):
//   cloth_on_ball  a wrinkled cloth dropped onto a sphere by a step of 15 cells, jittered
//   many_bodies    a lattice of small spheres flung towards the middle by several diameters
//   resting_slide  a cloth lying on a floor sliding in its plane (contact at t = 0, coplanar
//                  edges throughout), the same cloth wrinkled above
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "corpus/meshes.hpp"
#include "exactccd/scene.hpp"

namespace {

using exactccd::Positions;
using exactccd::Scene;
using exactccd::SceneOptions;
using exactccd::scenes::Mesh;

struct Body {
  Mesh mesh;
  Positions end;
  bool is_static = false;
};

/// The cloth: an n x n grid of width 2 at height z, wrinkled by a few ripples; it falls by `drop`
/// with a random jitter of `jitter` per vertex.
Body falling_cloth(int n, double z, double drop, double jitter, std::mt19937_64& rng) {
  Body b;
  b.mesh = exactccd::scenes::grid_sheet(n, 2.0, {0.0, 0.0, z});
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

std::vector<Body> cloth_on_ball(double scale, std::mt19937_64& rng) {
  const int n = std::max(8, static_cast<int>(std::lround(160 * std::sqrt(scale))));
  const double cell = 2.0 / n;
  std::vector<Body> bodies;
  bodies.push_back(falling_cloth(n, 1.0 + 2 * cell, 15 * cell, 2 * cell, rng));
  Body ball;
  const int slices = std::max(8, static_cast<int>(std::lround(96 * std::sqrt(scale))));
  ball.mesh = exactccd::scenes::uv_sphere({0.0, 0.0, 0.0}, 1.0, slices, slices / 2);
  ball.end = ball.mesh.positions;
  ball.is_static = true;
  bodies.push_back(std::move(ball));
  return bodies;
}

std::vector<Body> many_bodies(double scale, std::mt19937_64& rng) {
  const int k = std::max(2, static_cast<int>(std::lround(12 * std::cbrt(scale))));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Body> bodies;
  const double spacing = 0.25, radius = 0.1;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) {
        const Eigen::Vector3d c = spacing * Eigen::Vector3d(i, j, l) -
                                  spacing * (k - 1) / 2.0 * Eigen::Vector3d::Ones();
        Body b;
        b.mesh = exactccd::scenes::uv_sphere(c, radius, 12, 6);
        // Towards the middle by about two spacings, with a random spin-free wobble.
        const Eigen::Vector3d velocity =
            -0.5 * c + 0.15 * Eigen::Vector3d(u(rng), u(rng), u(rng));
        b.end = exactccd::scenes::translated(b.mesh.positions, velocity);
        bodies.push_back(std::move(b));
      }
  return bodies;
}

std::vector<Body> resting_slide(double scale, std::mt19937_64& rng) {
  const int n = std::max(8, static_cast<int>(std::lround(120 * std::sqrt(scale))));
  const double cell = 2.0 / n;
  std::vector<Body> bodies;
  Body floor;
  floor.mesh = exactccd::scenes::grid_sheet(n / 2, 3.0, {0.0, 0.0, 0.0});
  floor.end = floor.mesh.positions;
  floor.is_static = true;
  bodies.push_back(std::move(floor));
  Body sheet;  // on the floor (z = 0 exactly), sliding by 5 cells along x
  sheet.mesh = exactccd::scenes::grid_sheet(n, 2.0, {0.0, 0.0, 0.0});
  sheet.end = exactccd::scenes::translated(sheet.mesh.positions, {5 * cell, 0.0, 0.0});
  bodies.push_back(std::move(sheet));
  bodies.push_back(falling_cloth(n, 4 * cell, 6 * cell, cell, rng));  // falling onto it
  return bodies;
}

/// Granular media: about 100,000 small meshes at scale 1 (the mesh-level broad phase's case):
/// half static one-triangle debris on a jittered floor, half small boxes falling onto it by
/// about their own size, tumbling apart, some already resting on the debris at t = 0.
std::vector<Body> debris_field(double scale, std::mt19937_64& rng) {
  const int side = std::max(4, static_cast<int>(std::lround(224 * std::sqrt(scale))));
  const double cell = 1.0 / 64;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Body> bodies;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      Body d;
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
      Body b;
      const bool resting = (i + 3 * j) % 7 == 0;  // on the floor at t = 0
      const Eigen::Vector3d lo(i * cell + 0.3 * cell * u(rng), j * cell + 0.3 * cell * u(rng),
                               resting ? 0.0 : 0.5 * cell + 0.5 * cell * u(rng));
      b.mesh = exactccd::scenes::box(lo, lo + 0.6 * cell * Eigen::Vector3d::Ones());
      const Eigen::Vector3d velocity(0.5 * cell * u(rng), 0.5 * cell * u(rng),
                                     resting ? 0.0 : -1.5 * cell);
      b.end = exactccd::scenes::translated(b.mesh.positions, velocity);
      bodies.push_back(std::move(b));
    }
  return bodies;
}

Scene make_scene(const std::vector<Body>& bodies) {
  Scene scene;
  for (const Body& b : bodies) {
    if (b.is_static) {
      scene.add_static_mesh(b.mesh.positions, b.mesh.triangles);
    } else {
      const exactccd::MeshId id = scene.add_mesh(b.mesh.positions, b.mesh.triangles);
      scene.set_motion(id, b.mesh.positions, b.end);
    }
  }
  return scene;
}

/// The same contacts (pairs and TOI doubles, both sorted by pair) and the same earliest.
bool same_contacts(const exactccd::SceneResult& a, const exactccd::SceneResult& b) {
  if (a.contacts.size() != b.contacts.size() || !(a.earliest.pair == b.earliest.pair) ||
      a.earliest.toi_lo != b.earliest.toi_lo || a.earliest.toi_hi != b.earliest.toi_hi)
    return false;
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    const exactccd::SceneContact& x = a.contacts[k];
    const exactccd::SceneContact& y = b.contacts[k];
    if (!(x.pair == y.pair) || x.toi_lo != y.toi_lo || x.toi_hi != y.toi_hi) return false;
  }
  return true;
}

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

template <class F>
double median_ms(int repetitions, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Barrier-method trial steps through exactccd::Scene (issue 27)"};
  double scale = 1.0, delta = 0.0;
  int repetitions = 3;
  bool json = false, compare_off = false;
  app.add_option("--scale", scale, "Mesh resolution factor (1: 20k-100k triangles)")
      ->check(CLI::Range(0.01, 20.0));
  app.add_option("--min-separation", delta, "Minimum separation of every pair")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--repetitions", repetitions, "Timed runs per figure (median)")
      ->check(CLI::Range(1, 100));
  app.add_flag("--json", json, "One JSON object per step and setting");
  app.add_flag("--compare-off", compare_off,
               "Also run each step with the cull by time off (same answers, checked)");
  bool earliest_only = false;
  app.add_flag("--earliest-only", earliest_only,
               "Time earliest_contact only (find_contacts runs once, for the checks)");
  std::vector<std::string> only;
  app.add_option("--steps", only, "Run only these steps (default: all)")
      ->check(CLI::IsMember({"cloth_on_ball", "many_bodies", "resting_slide", "debris_field"}));
  CLI11_PARSE(app, argc, argv);

  struct Step {
    const char* name;
    std::vector<Body> (*make)(double, std::mt19937_64&);
  };
  const Step steps[] = {{"cloth_on_ball", cloth_on_ball},
                        {"many_bodies", many_bodies},
                        {"resting_slide", resting_slide},
                        {"debris_field", debris_field}};
  if (!json)
    std::printf("%-14s %-5s %8s %10s %10s %9s %12s %9s %9s %9s %9s\n", "step", "time", "tris",
                "candidates", "time_cuts", "contacts", "earliest", "ec_1t_ms", "ec_2t_ms",
                "fc_1t_ms", "fc_2t_ms");
  for (const Step& step : steps) {
    if (!only.empty() && std::find(only.begin(), only.end(), step.name) == only.end()) continue;
    std::mt19937_64 rng(27);
    const std::vector<Body> bodies = step.make(scale, rng);
    long triangles = 0;
    for (const Body& b : bodies) triangles += static_cast<long>(b.mesh.triangles.rows());
    Scene scene = make_scene(bodies);
    exactccd::SceneResult reference;
    for (const bool by_time : {true, false}) {
      if (!by_time && !compare_off) break;
      SceneOptions o;
      o.min_separation = delta;
      o.cull_by_time = by_time;
      double ms[2][2];  // [earliest, find][threads - 1]
      exactccd::SceneResult r;
      exactccd::EarliestContact e;
      for (int threads = 1; threads <= 2; ++threads) {
        o.max_threads = threads;
        ms[0][threads - 1] = median_ms(repetitions, [&] { e = scene.earliest_contact(o); });
        ms[1][threads - 1] = median_ms(earliest_only ? 1 : repetitions,
                                       [&] { r = scene.find_contacts(o); });
      }
      if (!(e.contact.pair == r.earliest.pair) || e.contact.toi_lo != r.earliest.toi_lo ||
          e.contact.toi_hi != r.earliest.toi_hi) {
        std::fprintf(stderr, "%s: earliest_contact differs from find_contacts().earliest\n",
                     step.name);
        return 1;
      }
      if (by_time) {
        reference = r;
      } else if (!same_contacts(r, reference)) {
        std::fprintf(stderr, "%s: the cull by time changed an answer\n", step.name);
        return 1;
      }
      const unsigned long long candidates =
          r.stats.vertex_face_candidates + r.stats.edge_edge_candidates;
      if (json) {
        std::printf(
            "{\"step\": \"%s\", \"cull_by_time\": %s, \"min_separation\": %.17g, \"triangles\": "
            "%ld, \"candidates\": %llu, \"time_culled\": %llu, \"contacts\": %zu, "
            "\"earliest\": %.17g, \"earliest_contact_ms\": [%.3f, %.3f], "
            "\"find_contacts_ms\": [%.3f, %.3f], \"peak_mib\": %.1f}\n",
            step.name, by_time ? "true" : "false", delta, triangles, candidates,
            static_cast<unsigned long long>(r.stats.time_culled), r.contacts.size(),
            r.earliest.toi_lo, ms[0][0], ms[0][1], ms[1][0], ms[1][1], peak_mib());
      } else {
        std::printf("%-14s %-5s %8ld %10llu %10llu %9zu %12.6g %9.1f %9.1f %9.1f %9.1f\n",
                    step.name, by_time ? "on" : "off", triangles, candidates,
                    static_cast<unsigned long long>(r.stats.time_culled), r.contacts.size(),
                    r.earliest.toi_lo, ms[0][0], ms[0][1], ms[1][0], ms[1][1]);
      }
    }
  }
  if (!json) std::printf("peak memory %.1f MiB\n", peak_mib());
  return 0;
}
