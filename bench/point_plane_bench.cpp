// Point-plane CCD (point_plane_ccd): 20,000 points falling onto a static floor from heights up
// to 0.1 by up to 0.2 (about three quarters cross it), each mode timed in one loop, the best of
// three passes.   ./build/bench/point_plane_bench
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "exactccd/ccd.hpp"

int main() {
  using V = Eigen::Vector3d;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<exactccd::PointPlaneQuery> queries;
  for (int i = 0; i < 20000; ++i) {
    const V p0(2 * u(rng) - 1, 2 * u(rng) - 1, 0.1 * u(rng));
    const V p1 = p0 + V(0.2 * u(rng) - 0.1, 0.2 * u(rng) - 0.1, -0.2 * u(rng));
    queries.push_back({p0, V(0, 0, 0), V(0, 0, 1), p1, V(0, 0, 0), V(0, 0, 1)});
  }
  for (const auto mode :
       {exactccd::Mode::float_only, exactccd::Mode::filtered, exactccd::Mode::exact}) {
    exactccd::CcdOptions options;
    options.mode = mode;
    double best = 1e300;
    int collisions = 0;
    for (int pass = 0; pass < 3; ++pass) {
      const auto start = std::chrono::steady_clock::now();
      collisions = 0;
      for (const auto& q : queries) collisions += exactccd::point_plane_ccd(q, options).collides;
      best = std::min(
          best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("%-10s %zu queries, %d collisions, %.0f ns per query\n",
                exactccd::to_string(mode), queries.size(), collisions,
                best / static_cast<double>(queries.size()) * 1e9);
  }
  return 0;
}
