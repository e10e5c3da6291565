// Random test scenes shared by tests/scene_test.cpp and tests/scene_min_separation_test.cpp:
// triangle soups and jittered grids, some static, moving by small, medium or large translations
// (passing through each other), sometimes on a dyadic lattice (exact ties).
//
// EXACTCCD_TEST_SEED overrides the seed.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <utility>

#include "scene_support.hpp"

namespace exactccd::test {

using Rng = std::mt19937_64;

inline std::uint64_t test_seed() {
  std::uint64_t seed = 0x5ce7e5eedULL;
  if (const char* env = std::getenv("EXACTCCD_TEST_SEED")) seed = std::strtoull(env, nullptr, 0);
  std::cout << "[ seed     ] EXACTCCD_TEST_SEED=" << seed << "\n";
  return seed;
}

inline double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
inline int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

/// A triangle soup: n random vertices in a ball, m triangles of three distinct random vertices
/// (some vertices may belong to no triangle).
inline MeshSpec soup(Rng& rng, int n, int m, const Eigen::Vector3d& center, double radius) {
  MeshSpec s;
  s.start.resize(n, 3);
  for (int v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) s.start(v, k) = center[k] + uniform(rng, -radius, radius);
  s.triangles.resize(m, 3);
  for (int f = 0; f < m; ++f) {
    int a = uniform_int(rng, 0, n - 1), b, c;
    do b = uniform_int(rng, 0, n - 1); while (b == a);
    do c = uniform_int(rng, 0, n - 1); while (c == a || c == b);
    s.triangles.row(f) << a, b, c;
  }
  s.end = s.start;
  return s;
}

/// Rounds to a multiple of 2^-bits: dyadic coordinates make touching and coplanar contacts
/// (exact ties) frequent.
inline void quantize(Positions& x, int bits) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    x.data()[i] = std::ldexp(std::round(std::ldexp(x.data()[i], bits)), -bits);
}

/// A random scene: 2-4 meshes (grids and soups of 5-60 triangles), some static, each moving by
/// a random translation (small, medium or large: passing through the others) plus per-vertex
/// jitter, or not at all; sometimes on a dyadic lattice.
inline SceneSpec random_scene(Rng& rng) {
  SceneSpec spec;
  const int mesh_count = uniform_int(rng, 2, 4);
  const bool dyadic = uniform_int(rng, 0, 2) == 0;
  for (int i = 0; i < mesh_count; ++i) {
    const Eigen::Vector3d center(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1));
    MeshSpec m;
    if (uniform_int(rng, 0, 1) == 0) {
      const int triangles = uniform_int(rng, 5, 60);
      m = soup(rng, uniform_int(rng, 4, std::max(5, triangles / 2 + 3)), triangles, center,
               uniform(rng, 0.1, 0.5));
    } else {
      int nx, ny;
      do {
        nx = uniform_int(rng, 2, 7);
        ny = uniform_int(rng, 2, 7);
      } while (2 * (nx - 1) * (ny - 1) < 5 || 2 * (nx - 1) * (ny - 1) > 60);
      Eigen::Vector3d u, v;
      for (int k = 0; k < 3; ++k) {
        u[k] = uniform(rng, -0.6, 0.6);
        v[k] = uniform(rng, -0.6, 0.6);
      }
      m = grid(nx, ny, center - 0.5 * (u + v), u, v);
      for (Eigen::Index r = 0; r < m.start.rows(); ++r)
        for (int k = 0; k < 3; ++k) m.start(r, k) += uniform(rng, -0.02, 0.02);
    }
    m.is_static = uniform_int(rng, 0, 3) == 0;
    m.end = m.start;
    if (!m.is_static && uniform_int(rng, 0, 5) != 0) {
      const double scale = std::array<double, 3>{0.05, 0.4, 2.0}[uniform_int(rng, 0, 2)];
      Eigen::Vector3d shift;
      for (int k = 0; k < 3; ++k) shift[k] = uniform(rng, -scale, scale);
      const double jitter = uniform(rng, 0.0, 0.1);
      for (Eigen::Index r = 0; r < m.end.rows(); ++r)
        for (int k = 0; k < 3; ++k) m.end(r, k) += shift[k] + uniform(rng, -jitter, jitter);
    }
    if (dyadic) {
      quantize(m.start, 4);
      quantize(m.end, 4);
      if (m.is_static) m.end = m.start;
    }
    spec.push_back(std::move(m));
  }
  return spec;
}

}  // namespace exactccd::test
