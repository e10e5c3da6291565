// Scenes at extreme magnitudes: Scene::find_contacts and Scene::earliest_contact (default mode)
// against a brute force that decides every pair the scene's rules allow with vertex_face_ccd /
// edge_edge_ccd in Mode::exact. Scenes are scaled by 1e-150 and 1e150 (coordinates rounded:
// the brute force on the same doubles decides; products of three coordinates underflow or
// overflow in double) and by 2^-500 and 2^500 (exact: the contacts must also equal those of
// the unscaled scene), and one scene mixes magnitudes (a tiny cloth falling through a huge
// floor). Coordinates are dyadic before scaling, so that contacts are exact touchings at dyadic
// times, and each test asserts a minimum number of contacts.
//
// EXACTCCD_TEST_SEED overrides the seed, EXACTCCD_TEST_SCALE multiplies the number of scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "corpus/random_queries.hpp"
#include "exactccd/scene.hpp"
#include "tests/scene_support.hpp"
#include "tests/test_scale.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

constexpr std::uint64_t kDefaultSeed = 0x5ce7e7e3eULL;

// ---------------------------------------------------------------------------------------------
// A scene against the brute force (tests/scene_support.hpp)

/// The scene against the brute force under `ccd` (toi_width 0: identical contacts and earliest
/// contact; coarse: the same pairs, each enclosure containing the tight one and no wider than
/// asked, and earliest_contact equal to find_contacts' earliest). Returns the brute force's
/// tight contacts.
std::vector<SceneContact> check_scene(const SceneSpec& spec, const CcdOptions& ccd) {
  SceneOptions options;
  options.ccd = ccd;
  CcdOptions tight = ccd;
  tight.mode = Mode::exact;
  tight.toi_width = 0;
  const std::vector<SceneContact> want =
      brute_force(prepare_reference(spec), tight, options.self_collision).contacts;
  Scene scene = make_scene(spec);
  const SceneResult got = scene.find_contacts(options);
  const EarliestContact earliest = scene.earliest_contact(options);
  EXPECT_EQ(earliest.collides, !want.empty());
  if (ccd.toi_width == 0) {
    EXPECT_TRUE(same_contacts(got.contacts, want));
    if (!want.empty()) {
      const SceneContact first = earliest_of(want);
      EXPECT_TRUE(same_contact(got.earliest, first))
          << "got " << describe(got.earliest) << ", expected " << describe(first);
      EXPECT_TRUE(same_contact(earliest.contact, first))
          << "got " << describe(earliest.contact) << ", expected " << describe(first);
    }
  } else {
    EXPECT_EQ(got.contacts.size(), want.size());
    for (std::size_t k = 0; k < std::min(got.contacts.size(), want.size()); ++k) {
      const SceneContact& g = got.contacts[k];
      const SceneContact& w = want[k];
      EXPECT_TRUE(g.pair == w.pair) << "got " << describe(g) << ", expected " << describe(w);
      CcdResult coarse, exact_tight;
      coarse.collides = exact_tight.collides = true;
      coarse.toi_lo = g.toi_lo, coarse.toi_hi = g.toi_hi;
      exact_tight.toi_lo = w.toi_lo, exact_tight.toi_hi = w.toi_hi;
      const std::string error = check_coarse_toi(coarse, exact_tight, ccd.toi_width);
      EXPECT_TRUE(error.empty()) << error << ": got " << describe(g) << ", tight "
                                 << describe(w);
    }
    if (!got.contacts.empty()) {
      EXPECT_TRUE(same_contact(earliest.contact, got.earliest))
          << "earliest_contact " << describe(earliest.contact) << ", find_contacts "
          << describe(got.earliest);
    }
  }
  return want;
}

// ---------------------------------------------------------------------------------------------
// Meshes (dyadic coordinates)

using Rng = std::mt19937_64;

/// k / 16, k uniform in [lo * 16, hi * 16].
double sixteenth(Rng& rng, double lo, double hi) {
  return std::uniform_int_distribution<int>(int(lo * 16), int(hi * 16))(rng) / 16.0;
}

/// A random scene of dyadic coordinates (multiples of 1/16 or 1/64) in [-2, 3]^3: a static box,
/// a sheet falling onto it (contacts at dyadic times, touching ones included), a soup of
/// triangles moving by a dyadic translation, and sometimes a second falling box.
SceneSpec random_scene(Rng& rng) {
  SceneSpec spec;
  MeshSpec box = box_mesh({0, 0, 0}, {1, 1, 1});
  box.is_static = true;
  spec.push_back(box);

  const Eigen::Vector3d corner(sixteenth(rng, -0.5, 0.5), sixteenth(rng, -0.5, 0.5),
                               sixteenth(rng, 1, 1.5));
  MeshSpec sheet = grid(5, 5, corner, {1, sixteenth(rng, -0.25, 0.25), 0},
                        {sixteenth(rng, -0.25, 0.25), 1, sixteenth(rng, -0.25, 0.25)});
  sheet.end = sheet.start;
  const Eigen::Vector3d fall(sixteenth(rng, -0.25, 0.25), sixteenth(rng, -0.25, 0.25),
                             -sixteenth(rng, 0.5, 1.5));
  for (Eigen::Index r = 0; r < sheet.end.rows(); ++r) sheet.end.row(r) += fall.transpose();
  spec.push_back(sheet);

  MeshSpec soup;
  const int n = 12, m = 10;
  soup.start.resize(n, 3);
  for (int v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) soup.start(v, k) = sixteenth(rng, -0.5, 1.5);
  soup.triangles.resize(m, 3);
  for (int f = 0; f < m; ++f) {
    int a = std::uniform_int_distribution<int>(0, n - 1)(rng), b, c;
    do b = std::uniform_int_distribution<int>(0, n - 1)(rng); while (b == a);
    do c = std::uniform_int_distribution<int>(0, n - 1)(rng); while (c == a || c == b);
    soup.triangles.row(f) << a, b, c;
  }
  soup.end = soup.start;
  for (Eigen::Index r = 0; r < soup.end.rows(); ++r)
    for (int k = 0; k < 3; ++k) soup.end(r, k) += sixteenth(rng, -1, 1);
  spec.push_back(soup);

  if (std::uniform_int_distribution<int>(0, 1)(rng) == 0) {
    const double x = sixteenth(rng, -0.5, 0.75), y = sixteenth(rng, -0.5, 0.75);
    MeshSpec falling = box_mesh({x, y, 1.25}, {x + 0.5, y + 0.5, 1.75});
    falling.end = falling.start;
    falling.end.col(2).array() -= sixteenth(rng, 0.25, 1);
    spec.push_back(falling);
  }
  return spec;
}

std::uint64_t seed() {
  const std::uint64_t s = seed_from_environment(kDefaultSeed);
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu EXACTCCD_TEST_SCALE=%g\n",
              static_cast<unsigned long long>(s), scale_from_environment());
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------------
// Tests

// Scaled by 2^-500 and 2^500 (exact): the contacts equal the brute force's on the scaled scene
// and those of the unscaled scene.
TEST(ExtremeScene, ScaledByTwoToThePlusMinus500EqualsUnscaled) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(seed());
  std::size_t contacts = 0;
  const std::uint64_t scenes = scaled_count(4);
  for (std::uint64_t i = 0; i < scenes; ++i) {
    const SceneSpec spec = random_scene(rng);
    const std::vector<SceneContact> unscaled = check_scene(spec, {});
    for (int k : {-500, 500}) {
      SCOPED_TRACE("scene " + std::to_string(i) + " scaled by 2^" + std::to_string(k));
      const std::vector<SceneContact> got = check_scene(scaled(spec, std::ldexp(1.0, k)), {});
      EXPECT_TRUE(same_contacts(got, unscaled));
      contacts += got.size();
    }
  }
  std::printf("[ info     ] %zu contacts over %llu scenes x 2 scales, %.2f s\n", contacts,
              static_cast<unsigned long long>(scenes), seconds_since(start));
  EXPECT_GE(contacts, 20 * scenes);
}

// Scaled by 1e-150 and 1e150 (rounded): the brute force on the same doubles decides.
TEST(ExtremeScene, ScaledByTenToThePlusMinus150EqualsBruteForce) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(seed() + 1);
  std::size_t contacts = 0;
  const std::uint64_t scenes = scaled_count(4);
  for (std::uint64_t i = 0; i < scenes; ++i) {
    const SceneSpec spec = random_scene(rng);
    for (double factor : {1e-150, 1e150}) {
      SCOPED_TRACE("scene " + std::to_string(i) + " scaled by " + hex(factor));
      contacts += check_scene(scaled(spec, factor), {}).size();
    }
  }
  std::printf("[ info     ] %zu contacts over %llu scenes x 2 scales, %.2f s\n", contacts,
              static_cast<unsigned long long>(scenes), seconds_since(start));
  EXPECT_GE(contacts, 20 * scenes);
}

// t_max below 1 and coarse widths pass through at every extreme scale.
TEST(ExtremeScene, TmaxAndCoarseWidthAtExtremeScales) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(seed() + 2);
  std::size_t contacts = 0;
  const SceneSpec spec = random_scene(rng);
  // Below scale 1, every subset_stride()-th combination of scale and options.
  std::size_t combination = 0, checked = 0;
  for (double factor : {0x1p-500, 0x1p500, 1e-150, 1e150}) {
    for (const auto& [t_max, width] : {std::pair{0.5, 0.0}, std::pair{0.75, 1e-3},
                                       std::pair{0.625, 0.1}, std::pair{1.0, 0.5}}) {
      if (combination++ % subset_stride() != 0) continue;
      SCOPED_TRACE("scaled by " + hex(factor) + ", t_max " + hex(t_max) + ", toi_width " +
                   hex(width));
      CcdOptions ccd;
      ccd.t_max = t_max;
      ccd.toi_width = width;
      contacts += check_scene(scaled(spec, factor), ccd).size();
      ++checked;
    }
  }
  std::printf("[ info     ] %zu contacts over %zu combinations, %.2f s\n", contacts, checked,
              seconds_since(start));
  EXPECT_GE(contacts, 40 * checked);
}

/// A tiny cloth (side `small`) falling through a huge static floor (side `large`) at the
/// origin: the cloth crosses z = 0 at t = 1/2 (starting at height `small`, ending at -small),
/// where the floor's vertex at the origin and its edges through it are: vertex-face contacts
/// (cloth vertices on floor triangles, the floor's central vertex on cloth triangles) and
/// edge-edge contacts (cloth edges across the floor's edges).
SceneSpec cloth_through_floor(double small, double large) {
  MeshSpec floor = grid(5, 5, {-large, -large, 0}, {2 * large, 0, 0}, {0, 2 * large, 0});
  floor.is_static = true;
  // The cloth is offset by a quarter of its cell so that its edges cross the floor's axes.
  MeshSpec cloth = grid(5, 5, {-0.4375 * small, -0.3125 * small, small}, {small, 0, 0},
                        {0, small, 0.25 * small});
  cloth.end = cloth.start;
  cloth.end.col(2).array() -= 2 * small;
  return {floor, cloth};
}

// Mixed magnitudes in one scene: 2^-500 cloth through a 2^500 floor (exact dyadics), and 1e-150
// through 1e150 (rounded); a brute force on every pair decides (exponent spreads of ~1000 bits
// make the exact path slow: the scene is small).
TEST(ExtremeScene, TinyClothThroughHugeFloor) {
  const auto start = std::chrono::steady_clock::now();
  std::size_t contacts = 0;
  for (const auto& [small, large] : {std::pair{0x1p-500, 0x1p500}, std::pair{1e-150, 1e150},
                                     std::pair{0x1p-1000, 0x1p1000}}) {
    SCOPED_TRACE("cloth " + hex(small) + ", floor " + hex(large));
    const std::vector<SceneContact> got = check_scene(cloth_through_floor(small, large), {});
    contacts += got.size();
    // At least each of the 25 cloth vertices on the floor.
    EXPECT_GE(got.size(), 25u);
  }
  std::printf("[ info     ] %zu contacts, %.2f s\n", contacts, seconds_since(start));
}

}  // namespace
}  // namespace exactccd::test
