// Seeded random double-precision CCD queries, and the differential check "default path versus
// exact path" on one query. Shared by tests/differential_test.cpp, tests/allocation_test.cpp,
// tests/rounding_mode_test.cpp, tests/extreme_*_test.cpp and bench/soak.cpp; no GoogleTest
// dependency.
//
// Every query is a pure function of (base seed, generator, index): query i of a generator can be
// regenerated alone, whatever the thread that made it or the number of queries before it.
//
// Degenerate configurations are built exactly: positions at a chosen dyadic time tc and
// velocities are dyadic numbers with few significant bits, and every relation (p inside the
// triangle with weights k/8, edges crossing, a point repeated, collinear points, four points in
// a plane) is an affine combination with dyadic weights, so it holds exactly in double
// arithmetic. x(t0) = X - tc d and x(t1) = X + (1 - tc) d are exact too, and x(tc) = X. Some
// generators then move a few coordinates by a few ulps (std::nextafter), which leaves a
// near-degenerate query that is hard for floating-point filters.
//
// Wide-exponent families spread the binary exponents within one query (up to 2^-1074 next to
// 2^1000), and every family's query is, one time in four, scaled by 2^k with k in
// [-1000, 1000] when that is exact: the same answer at another magnitude.
//
// Draws happen in statement order: never two random draws among the arguments of one call
// (their order is unspecified in C++); braced lists and separate declarations are ordered.
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::random_queries {

// ---------------------------------------------------------------------------------------------
// Queries

/// A double query in the benchmark's row order (vertex-face: p, a, b, c at t0 then at t1;
/// edge-edge: ea0, ea1, eb0, eb1 at t0 then at t1).
struct DoubleQuery {
  QueryType type = QueryType::vertex_face;
  std::array<Eigen::Vector3d, 8> v;
  /// The time at which the generator planted an exact contact or degeneracy (before any
  /// perturbation or inexact scaling); NaN when none.
  double planted_time = std::numeric_limits<double>::quiet_NaN();
  /// k when the generator scaled the whole query by 2^k at the end (exactly), else 0.
  int power_of_two = 0;

  VertexFaceQuery vertex_face() const { return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}; }
  EdgeEdgeQuery edge_edge() const { return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}; }
};

/// The public double API on the query.
inline CcdResult ccd(const DoubleQuery& q, const CcdOptions& options) {
  return q.type == QueryType::vertex_face ? vertex_face_ccd(q.vertex_face(), options)
                                          : edge_edge_ccd(q.edge_edge(), options);
}

inline CcdOptions with_mode(CcdOptions options, Mode mode) {
  options.mode = mode;
  return options;
}

// ---------------------------------------------------------------------------------------------
// Seeds and environment

/// SplitMix64 finaliser: decorrelates consecutive indices into independent generator seeds.
inline std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// EXACTCCD_TEST_SEED when set (decimal or 0x hex), else `fallback`.
inline std::uint64_t seed_from_environment(std::uint64_t fallback) {
  if (const char* env = std::getenv("EXACTCCD_TEST_SEED")) return std::strtoull(env, nullptr, 0);
  return fallback;
}

// ---------------------------------------------------------------------------------------------
// Generators

enum class Family : std::uint8_t {
  /// Full-precision doubles uniform in [-1, 1]^3 (culling and the filters decide most).
  uniform_box,
  /// Small integers in [-2, 2]: coincident, collinear, coplanar and touching configurations
  /// arise by chance, exactly.
  small_integer_grid,
  /// Positions uniform in the unit box, displacements about a tenth of it (simulation-like).
  short_motion,
  /// Exact contact planted at a dyadic tc in [0, 1] (inside, on an edge, at a vertex, edges
  /// crossing, endpoint on an edge, collinear overlap) or an exact in-plane near miss.
  planted_contact,
  /// planted_contact, then 1 to 4 coordinates moved by 1 to 4 ulps each.
  planted_contact_ulps,
  /// planted_contact with tc = 0 or tc = 1 (contact at the ends of the time interval),
  /// half of them perturbed by a few ulps.
  contact_at_endpoints,
  /// All eight positions in one plane with a small-integer basis (coplanar throughout),
  /// half of them perturbed by a few ulps.
  coplanar_throughout,
  /// Degenerate primitives throughout: zero-length edges, parallel or collinear edges,
  /// triangles that are segments or points, collinear triangle vertices; half perturbed.
  degenerate_primitives,
  /// Every coordinate a random double: random sign, a full random 53-bit significand and a
  /// binary exponent uniform in [-100, 100], independently per coordinate (contacts are rare;
  /// the exponent spread within one query is what is hard).
  wide_exponent_100,
  /// The same with exponents in [-300, 300].
  wide_exponent_300,
  /// The same with exponents in [-1000, 1000].
  wide_exponent_1000,
  /// A huge triangle or edge (coordinates 2^900 .. 2^1001) in a plane through the origin, the
  /// other primitive near the origin with subnormal coordinates and subnormal motion across,
  /// onto or along that plane; or the huge one moved by subnormal displacements next to a
  /// subnormal one. Exponent spreads of about 2000 within one query.
  huge_triangle_subnormal_motion,
  /// Resting contact, exact: a vertex on the face (weights k/8) at t = 0, both moving within
  /// the face's fixed plane or the vertex riding a moving face; edges sliding along each other
  /// (collinear overlap, or crossing in a common plane). Half perturbed by a few ulps.
  resting_contact,
  /// Faces stacked in parallel planes at exact gaps 2^-20 .. 2^-52 of their size (some gaps
  /// 0: coplanar), with tangential motion; some gaps close or flip during the step.
  stacked_coplanar,
};

inline constexpr std::array<Family, 14> kAllFamilies = {
    Family::uniform_box,          Family::small_integer_grid,  Family::short_motion,
    Family::planted_contact,      Family::planted_contact_ulps, Family::contact_at_endpoints,
    Family::coplanar_throughout,  Family::degenerate_primitives, Family::wide_exponent_100,
    Family::wide_exponent_300,    Family::wide_exponent_1000,  Family::huge_triangle_subnormal_motion,
    Family::resting_contact,      Family::stacked_coplanar};

inline const char* to_string(Family f) {
  switch (f) {
    case Family::uniform_box: return "uniform_box";
    case Family::small_integer_grid: return "small_integer_grid";
    case Family::short_motion: return "short_motion";
    case Family::planted_contact: return "planted_contact";
    case Family::planted_contact_ulps: return "planted_contact_ulps";
    case Family::contact_at_endpoints: return "contact_at_endpoints";
    case Family::coplanar_throughout: return "coplanar_throughout";
    case Family::degenerate_primitives: return "degenerate_primitives";
    case Family::wide_exponent_100: return "wide_exponent_100";
    case Family::wide_exponent_300: return "wide_exponent_300";
    case Family::wide_exponent_1000: return "wide_exponent_1000";
    case Family::huge_triangle_subnormal_motion: return "huge_triangle_subnormal_motion";
    case Family::resting_contact: return "resting_contact";
    case Family::stacked_coplanar: return "stacked_coplanar";
  }
  return "unknown";
}

/// A generator: a family for one query type.
struct Generator {
  Family family;
  QueryType type;
  std::string name() const {
    return std::string(type == QueryType::vertex_face ? "vf/" : "ee/") + to_string(family);
  }
};

/// How many times fewer queries of a family a test takes than of the others when it loops
/// over every generator with one count: the exact path (and the default path, which falls
/// back to it) costs 0.05-0.2 ms per query on the ordinary families, but about 1 ms (spread
/// +-100), 5 ms (+-300), 50 ms, up to 0.5 s (+-1000), and up to 1.5 ms (edge-edge
/// huge_triangle_subnormal_motion) on wide exponent spreads (at 547347a, issue 10). Lower
/// these as the exact path gets faster.
inline std::uint64_t exact_cost_divisor(Family f) {
  switch (f) {
    case Family::wide_exponent_100: return 10;
    case Family::wide_exponent_300: return 50;
    case Family::wide_exponent_1000: return 500;
    case Family::huge_triangle_subnormal_motion: return 10;
    default: return 1;
  }
}

/// Whether the family's coordinates are of ordinary magnitude (before the final power-of-two
/// scaling): every family but the wide exponent spreads.
inline bool ordinary_magnitudes(Family f) {
  return f != Family::wide_exponent_100 && f != Family::wide_exponent_300 &&
         f != Family::wide_exponent_1000 && f != Family::huge_triangle_subnormal_motion;
}

/// n / exact_cost_divisor(g.family), at least 1: a loop's count for generator g.
inline std::uint64_t affordable_count(const Generator& g, std::uint64_t n) {
  return std::max<std::uint64_t>(1, n / exact_cost_divisor(g.family));
}

/// Number of generators: every family for both query types.
inline constexpr std::size_t kGeneratorCount = 2 * kAllFamilies.size();

/// All generators, vertex-face first.
inline std::array<Generator, kGeneratorCount> all_generators() {
  std::array<Generator, kGeneratorCount> g{};
  for (std::size_t i = 0; i < kAllFamilies.size(); ++i) {
    g[i] = {kAllFamilies[i], QueryType::vertex_face};
    g[i + kAllFamilies.size()] = {kAllFamilies[i], QueryType::edge_edge};
  }
  return g;
}

/// Permutes the axes and mirrors some of them at random (defined below).
inline void permute_and_mirror_axes(DoubleQuery* q, std::mt19937_64& rng);

namespace detail {

using Rng = std::mt19937_64;

inline int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}
inline bool coin(Rng& rng, int one_in = 2) { return uniform_int(rng, 0, one_in - 1) == 0; }

/// k / 2^bits with |k| <= range 2^bits: at most bits + log2(range) + 1 significant bits.
inline double dyadic(Rng& rng, int bits, int range) {
  const long m = static_cast<long>(range) << bits;
  return std::ldexp(static_cast<double>(std::uniform_int_distribution<long>(-m, m)(rng)), -bits);
}

inline Eigen::Vector3d dyadic_point(Rng& rng, int bits, int range) {
  return {dyadic(rng, bits, range), dyadic(rng, bits, range), dyadic(rng, bits, range)};
}

/// A linearly moving point given by its position X at the planted time and its displacement
/// d over [0, 1]. Affine combinations with constant weights act on both, so a relation built
/// on moving points holds at every time, one built on positions only holds at tc.
struct Moving {
  Eigen::Vector3d X, d;
};

/// w0 x + w1 y (+ w2 z), weights dyadic with few bits: exact for the small dyadics used here.
inline Moving combine(double w0, const Moving& x, double w1, const Moving& y) {
  return {w0 * x.X + w1 * y.X, w0 * x.d + w1 * y.d};
}
inline Moving combine(double w0, const Moving& x, double w1, const Moving& y, double w2,
                      const Moving& z) {
  return {(w0 * x.X + w1 * y.X) + w2 * z.X, (w0 * x.d + w1 * y.d) + w2 * z.d};
}

/// The resolution of positions and displacements of one query.
struct Grid {
  int bits, range;
};

inline Grid random_grid(Rng& rng) { return {uniform_int(rng, 0, 8), uniform_int(rng, 1, 4)}; }

inline Moving random_moving(Rng& rng, const Grid& g) {
  Moving m{dyadic_point(rng, g.bits, g.range), dyadic_point(rng, g.bits, g.range)};
  switch (uniform_int(rng, 0, 5)) {
    case 0: m.d.setZero(); break;                       // at rest
    case 1: m.d[uniform_int(rng, 0, 2)] = 0; break;     // slides in an axis plane
    default: break;
  }
  return m;
}

/// tc = k / 2^s, with tc = 0 and tc = 1 frequent.
inline double random_planted_time(Rng& rng) {
  switch (uniform_int(rng, 0, 7)) {
    case 0: return 0.0;
    case 1: return 1.0;
    default: {
      const int s = uniform_int(rng, 1, 6);
      return std::ldexp(uniform_int(rng, 1, (1 << s) - 1), -s);
    }
  }
}

/// Affine weights (i, j, 8 - i - j) / 8 of a point of a triangle's plane: inside, on an edge,
/// at a vertex, or outside by a multiple of 1/8.
inline void plane_weights(Rng& rng, double w[3]) {
  int i, j;
  switch (uniform_int(rng, 0, 4)) {
    case 0: i = uniform_int(rng, 1, 6), j = uniform_int(rng, 1, 7 - i); break;   // inside
    case 1: i = 0, j = uniform_int(rng, 0, 8); break;                             // on edge
    case 2: i = 8, j = 0; break;                                                  // at vertex
    default: i = uniform_int(rng, -4, 12), j = uniform_int(rng, -4, 12); break;   // anywhere
  }
  int k = 8 - i - j;
  // Shuffle which vertex gets which weight.
  int idx[3] = {0, 1, 2};
  std::shuffle(idx, idx + 3, rng);
  const int raw[3] = {i, j, k};
  for (int m = 0; m < 3; ++m) w[idx[m]] = raw[m] / 8.0;
}

/// Segment parameter: 0 or 1 (endpoint), inside (k/8), or outside the segment.
inline double segment_parameter(Rng& rng) {
  switch (uniform_int(rng, 0, 3)) {
    case 0: return coin(rng) ? 0.0 : 1.0;
    case 1: return uniform_int(rng, -8, 16) / 8.0;
    default: return uniform_int(rng, 1, 7) / 8.0;
  }
}

/// Four moving points with an exact contact (or in-plane near miss) at tc, positions only.
inline std::array<Moving, 4> planted(Rng& rng, QueryType type, const Grid& g) {
  std::array<Moving, 4> m;
  for (auto& x : m) x = random_moving(rng, g);
  if (type == QueryType::vertex_face) {
    // Sometimes a triangle that is a segment or a point at tc only.
    if (coin(rng, 6)) m[3].X = coin(rng) ? m[1].X : 0.5 * m[1].X + 0.5 * m[2].X;
    double w[3];
    plane_weights(rng, w);
    m[0].X = (w[0] * m[1].X + w[1] * m[2].X) + w[2] * m[3].X;
  } else {
    switch (uniform_int(rng, 0, 3)) {
      case 0: {  // the lines meet at X = a0 + s (a1 - a0) = b0 + u (b1 - b0) at tc
        const double s = segment_parameter(rng), u = segment_parameter(rng);
        const Eigen::Vector3d X = m[0].X + s * (m[1].X - m[0].X);
        const Eigen::Vector3d e = dyadic_point(rng, g.bits, g.range);
        m[2].X = X - u * e;
        m[3].X = X + (1 - u) * e;
        break;
      }
      case 1: {  // collinear at tc: b0, b1 on the line of a
        m[2].X = m[0].X + segment_parameter(rng) * (m[1].X - m[0].X);
        m[3].X = m[0].X + segment_parameter(rng) * (m[1].X - m[0].X);
        break;
      }
      case 2: {  // parallel and coplanar at tc
        m[3].X = m[2].X + (uniform_int(rng, -8, 8) / 4.0) * (m[1].X - m[0].X);
        break;
      }
      default: {  // a zero-length edge at tc, on or off the other one
        m[3].X = m[2].X = m[0].X + segment_parameter(rng) * (m[1].X - m[0].X);
        if (coin(rng)) m[3].X = m[2].X = m[2].X + dyadic_point(rng, g.bits + 3, 1);
        break;
      }
    }
  }
  return m;
}

/// Four moving points whose degeneracy holds at every time.
inline std::array<Moving, 4> degenerate_throughout(Rng& rng, QueryType type, const Grid& g) {
  std::array<Moving, 4> m;
  for (auto& x : m) x = random_moving(rng, g);
  const double lambda = uniform_int(rng, -8, 16) / 8.0;
  if (type == QueryType::vertex_face) {
    switch (uniform_int(rng, 0, 3)) {
      case 0: m[2] = m[1]; break;                       // a == b: the triangle is a segment
      case 1: m[3] = m[2] = m[1]; break;                // the triangle is a point
      case 2: m[3] = combine(1 - lambda, m[1], lambda, m[2]); break;  // collinear a, b, c
      default: m[0] = m[uniform_int(rng, 1, 3)]; break;   // p is a vertex of the triangle
    }
    // Sometimes p moves on the line of the first edge as well (collinear throughout).
    if (coin(rng, 4)) m[0] = combine(1 - lambda, m[1], lambda, m[2]);
  } else {
    switch (uniform_int(rng, 0, 4)) {
      case 0: m[1] = m[0]; break;                       // edge a has zero length
      case 1: m[1] = m[0], m[3] = m[2]; break;          // both edges have zero length
      case 2: {                                         // parallel: a1 - a0 = lambda (b1 - b0)
        m[1] = combine(1.0, m[0], lambda, m[3]);
        m[1] = combine(1.0, m[1], -lambda, m[2]);
        break;
      }
      case 3: {  // all four on one moving line o(t) + s e(t)
        const Moving o = m[0], e = m[1];
        m[1] = combine(1.0, o, uniform_int(rng, -8, 8) / 8.0, e);
        m[2] = combine(1.0, o, uniform_int(rng, -8, 8) / 8.0, e);
        m[3] = combine(1.0, o, uniform_int(rng, -8, 8) / 8.0, e);
        break;
      }
      default: m[2] = m[uniform_int(rng, 0, 1)]; break;  // a shared endpoint
    }
  }
  return m;
}

/// Eight positions in the plane o + alpha u + beta v, u, v small integer vectors.
inline std::array<Eigen::Vector3d, 8> coplanar_positions(Rng& rng, const Grid& g) {
  const Eigen::Vector3d o = dyadic_point(rng, g.bits, g.range);
  Eigen::Vector3d u, v;
  for (int k = 0; k < 3; ++k) u[k] = uniform_int(rng, -3, 3), v[k] = uniform_int(rng, -3, 3);
  std::array<Eigen::Vector3d, 8> x;
  for (auto& p : x) {
    // One draw per statement (argument order is unspecified); beta first, as GCC evaluated
    // the former one-expression form, so that the queries are unchanged.
    const double beta = dyadic(rng, g.bits, g.range);
    const double alpha = dyadic(rng, g.bits, g.range);
    p = (o + alpha * u) + beta * v;
  }
  return x;
}

inline std::array<Eigen::Vector3d, 8> positions(const std::array<Moving, 4>& m, double tc) {
  std::array<Eigen::Vector3d, 8> x;
  for (int i = 0; i < 4; ++i) {
    x[i] = m[i].X - tc * m[i].d;
    x[i + 4] = m[i].X + (1 - tc) * m[i].d;
  }
  return x;
}

/// Magnitudes 2^-40 .. 2^40 (about 1e-12 .. 1e12): power-of-two scalings (exact) or decimal
/// ones (rounded: exact degeneracies become near-degenerate), then translations up to 1e8
/// (an integer offset is exact while the coordinates' bits fit).
inline void random_transform(Rng& rng, std::array<Eigen::Vector3d, 8>& x, bool* exact) {
  switch (uniform_int(rng, 0, 3)) {
    case 0: break;
    case 1: {
      const double s = std::ldexp(1.0, uniform_int(rng, -40, 40));
      for (auto& p : x) p *= s;
      break;
    }
    default: {
      const double s = std::pow(10.0, std::uniform_real_distribution<double>(-12, 12)(rng));
      for (auto& p : x) p *= s;
      *exact = false;
      break;
    }
  }
  switch (uniform_int(rng, 0, 3)) {
    case 0: {
      Eigen::Vector3d o;
      for (int k = 0; k < 3; ++k) o[k] = static_cast<double>(uniform_int(rng, -100000000, 100000000));
      for (auto& p : x) p += o;
      *exact = false;  // exact only when the bits fit: not tracked
      break;
    }
    case 1: {
      Eigen::Vector3d o;
      for (int k = 0; k < 3; ++k) o[k] = std::uniform_real_distribution<double>(-1e8, 1e8)(rng);
      for (auto& p : x) p += o;
      *exact = false;
      break;
    }
    default: break;
  }
}

/// 1 to 4 coordinates moved by 1 to 4 ulps each, in a random direction. A zero coordinate
/// becomes a subnormal, whose exact form needs ~1100-bit integers and makes the exact path
/// ~100 times slower: such moves are kept, but only one in four.
inline void perturb_ulps(Rng& rng, std::array<Eigen::Vector3d, 8>& x) {
  const int n = uniform_int(rng, 1, 4);
  for (int i = 0; i < n; ++i) {
    double& c = x[uniform_int(rng, 0, 7)][uniform_int(rng, 0, 2)];
    if (c == 0 && !coin(rng, 4)) continue;
    const double toward = coin(rng) ? std::numeric_limits<double>::infinity()
                                    : -std::numeric_limits<double>::infinity();
    for (int k = uniform_int(rng, 1, 4); k > 0; --k) c = std::nextafter(c, toward);
  }
}


// ---- wide exponent spreads (wide_exponent_*, huge_triangle_subnormal_motion) -----------------

/// A random double: random sign, a full random 53-bit significand (2^e (1 + f), f a random
/// 52-bit fraction), binary exponent e uniform in [lo, hi] (within [-1022, 1023]: a normal
/// double).
inline double random_full_double(Rng& rng, int lo, int hi) {
  const std::uint64_t significand = (rng() >> 11) | (std::uint64_t{1} << 52);
  const int e = uniform_int(rng, lo, hi);
  const double m = std::ldexp(static_cast<double>(significand), e - 52);
  return coin(rng) ? m : -m;
}

/// Exponent uniform in [-spread, spread].
inline double wide_exponent_double(Rng& rng, int spread) {
  return random_full_double(rng, -spread, spread);
}

/// Magnitude in [2^900, 2^1001), random sign.
inline double huge_double(Rng& rng) { return random_full_double(rng, 900, 1000); }

/// A random multiple of 2^-1074 below 2^(bits - 1074) in magnitude (bits <= 48: below 2^-1026,
/// a subnormal or 0), random sign. Sums and differences of a few such numbers, and their
/// doubles and quadruples, stay below 2^-1022 and on the 2^-1074 grid: exact.
inline double subnormal_double(Rng& rng, int bits) {
  const double m = std::ldexp(static_cast<double>(rng() >> (64 - bits)), -1074);
  return coin(rng) ? m : -m;
}

/// Signed subnormal offsets of a primitive from a plane at t = 0 and t = 1: crossing it at
/// t = 1/2 (planted) or at another time, touching it at t = 0 or t = 1, in it throughout,
/// missing it (one side throughout), or random. `planted` receives the time the offsets vanish
/// at when it is dyadic (NaN otherwise).
inline std::array<double, 2> subnormal_offsets(Rng& rng, int bits, double* planted) {
  const double g = subnormal_double(rng, bits);
  const double h = subnormal_double(rng, bits);
  *planted = std::numeric_limits<double>::quiet_NaN();
  switch (uniform_int(rng, 0, 6)) {
    case 0: *planted = 0.5; return {g, -g};
    case 1: return {g, std::signbit(g) == std::signbit(h) ? -h : h};  // crosses (or touches)
    case 2: *planted = 0.0; return {0.0, h};
    case 3: *planted = 1.0; return {g, 0.0};
    case 4: *planted = 0.0; return {0.0, 0.0};
    case 5: return {g, std::signbit(g) == std::signbit(h) ? h : -h};  // one side throughout
    default: return {g, h};
  }
}

/// huge_triangle_subnormal_motion. Axes (u, v, w); the huge primitive lies in the plane
/// w = 2^m u (m in {0, 1, 2}; w = 0 when untilted) through the origin, the small one has
/// coordinates below 2^-1024 on the 2^-1074 grid, so that every coordinate below is computed
/// exactly. Vertex-face: a huge triangle around the origin (one vertex per quadrant pair) and
/// p with subnormal (u, v) and subnormal offsets from the plane; or (untilted) the huge
/// triangle's w coordinates moved by subnormal amounts and p subnormal, static or moving.
/// Edge-edge: a huge edge through the origin (a1 = -2^j a0) or not, and a subnormal edge with
/// offsets from the plane; or the huge edge's w coordinates moved by subnormal amounts. Then
/// the axes are permuted and mirrored.
inline void huge_and_subnormal(Rng& rng, QueryType type, DoubleQuery* q) {
  const int bits = uniform_int(rng, 1, 48);
  const bool vice_versa = coin(rng, 3);  // the huge primitive moves by subnormal amounts
  const int m = vice_versa || coin(rng, 3) ? -1 : uniform_int(rng, 0, 2);  // -1: untilted
  const auto plane_w = [m](double u) { return m < 0 ? 0.0 : std::ldexp(u, m); };
  const auto small_point = [&rng, bits] {
    const double u = subnormal_double(rng, bits);
    const double v = subnormal_double(rng, bits);
    return std::array<double, 2>{u, v};
  };
  // The huge primitive's rows at t = 0 (and t = 1 until moved), with w on the plane.
  const auto huge_rows = [&](std::initializer_list<int> rows,
                             const std::vector<std::array<double, 2>>& uv) {
    std::size_t i = 0;
    for (int r : rows) {
      const std::array<double, 2>& p = uv[i++];
      q->v[r] = q->v[r + 4] = {p[0], p[1], plane_w(p[0])};
    }
  };
  // Subnormal w motion of the huge primitive (vice versa).
  const auto lift = [&](std::initializer_list<int> rows) {
    for (int r : rows) {
      if (!coin(rng, 3)) q->v[r][2] = subnormal_double(rng, bits);
      q->v[r + 4][2] = subnormal_double(rng, bits);
    }
  };
  // A small point at t = 0 and t = 1: on the plane plus offsets, or free and subnormal.
  const auto small_rows = [&](int row, const std::array<double, 2>& offsets) {
    const std::array<double, 2> p0 = small_point();
    const std::array<double, 2> p1 = coin(rng, 4) ? p0 : small_point();
    q->v[row] = {p0[0], p0[1], plane_w(p0[0]) + offsets[0]};
    q->v[row + 4] = {p1[0], p1[1], plane_w(p1[0]) + offsets[1]};
  };
  double planted = std::numeric_limits<double>::quiet_NaN();
  if (type == QueryType::vertex_face) {
    // Quadrants (+, +), (-, +), (+-, -): the origin is often inside the triangle.
    std::vector<std::array<double, 2>> tri(3);
    for (int i = 0; i < 3; ++i) {
      const double u = std::fabs(huge_double(rng));
      const double v = std::fabs(huge_double(rng));
      tri[i] = {i == 0 ? u : i == 1 ? -u : (coin(rng) ? u : -u), i == 2 ? -v : v};
    }
    huge_rows({1, 2, 3}, tri);
    if (vice_versa) lift({1, 2, 3});
    small_rows(0, subnormal_offsets(rng, bits, &planted));
  } else {
    std::vector<std::array<double, 2>> edge(2);
    {
      const double u = huge_double(rng);
      const double v = huge_double(rng);
      edge[0] = {u, v};
    }
    if (coin(rng)) {  // through the origin
      const int j = uniform_int(rng, -2, 2);
      edge[1] = {-std::ldexp(edge[0][0], j), -std::ldexp(edge[0][1], j)};
    } else {
      const double u = huge_double(rng);
      const double v = huge_double(rng);
      edge[1] = {u, v};
    }
    huge_rows({0, 1}, edge);
    if (vice_versa) lift({0, 1});
    const std::array<double, 2> g = subnormal_offsets(rng, bits, &planted);
    small_rows(2, g);
    small_rows(3, coin(rng) ? g : subnormal_offsets(rng, bits, &planted));
    planted = std::numeric_limits<double>::quiet_NaN();  // two ends' offsets: not tracked
    if (coin(rng))  // the small edge first
      for (int k : {0, 4}) std::swap(q->v[k], q->v[k + 2]), std::swap(q->v[k + 1], q->v[k + 3]);
  }
  // Where the small primitive meets the plane of a static huge one (when dyadic).
  q->planted_time = vice_versa ? std::numeric_limits<double>::quiet_NaN() : planted;
  permute_and_mirror_axes(q, rng);
}

// ---- resting contact and stacked faces ---------------------------------------------------------

/// The plane o + alpha u + beta v, u and v small integer vectors (not parallel), o dyadic of
/// grid g; with alpha and beta on grid g (or k/8 combinations of such) every point is exact.
struct Plane {
  Eigen::Vector3d o, u, v;
  Eigen::Vector3d at(double alpha, double beta) const { return (o + alpha * u) + beta * v; }
};

inline Plane random_plane(Rng& rng, const Grid& g) {
  Plane P;
  P.o = dyadic_point(rng, g.bits, g.range);
  do {
    for (int k = 0; k < 3; ++k) {
      P.u[k] = uniform_int(rng, -3, 3);
      P.v[k] = uniform_int(rng, -3, 3);
    }
  } while (P.u[1] * P.v[2] == P.u[2] * P.v[1] && P.u[2] * P.v[0] == P.u[0] * P.v[2] &&
           P.u[0] * P.v[1] == P.u[1] * P.v[0]);  // u x v = 0: parallel (or zero)
  return P;
}

using Point2d = std::array<double, 2>;

inline Point2d dyadic_point2(Rng& rng, const Grid& g) {
  const double a = dyadic(rng, g.bits, g.range);
  const double b = dyadic(rng, g.bits, g.range);
  return {a, b};
}

/// Affine weights k/8 of a point of the closed triangle: inside, on an edge or at a vertex.
inline void closed_face_weights(Rng& rng, double w[3]) {
  do plane_weights(rng, w);
  while (w[0] < 0 || w[1] < 0 || w[2] < 0);
}

inline Point2d weighted(const double w[3], const Point2d& a, const Point2d& b, const Point2d& c) {
  return {(w[0] * a[0] + w[1] * b[0]) + w[2] * c[0], (w[0] * a[1] + w[1] * b[1]) + w[2] * c[1]};
}

/// x + s (y - x), s = k/8 in [0, 1].
inline Point2d along(const Point2d& x, const Point2d& y, double s) {
  return {x[0] + s * (y[0] - x[0]), x[1] + s * (y[1] - x[1])};
}

/// The ends of a segment through X: X - s d and X + (1 - s) d, s = k/8 in [0, 1].
inline std::array<Point2d, 2> segment_through(Rng& rng, const Point2d& X, const Grid& g) {
  const double s = uniform_int(rng, 0, 8) / 8.0;
  const Point2d d = dyadic_point2(rng, g);
  return {Point2d{X[0] - s * d[0], X[1] - s * d[1]},
          Point2d{X[0] + (1 - s) * d[0], X[1] + (1 - s) * d[1]}};
}

/// Two segments of the plane crossing (or touching at an end: s = 0 or 1) at one point.
inline std::array<Point2d, 4> crossing_segments(Rng& rng, const Grid& g) {
  const Point2d a0 = dyadic_point2(rng, g);
  const Point2d a1 = dyadic_point2(rng, g);
  const Point2d X = along(a0, a1, uniform_int(rng, 0, 8) / 8.0);
  const std::array<Point2d, 2> b = segment_through(rng, X, g);
  return {a0, a1, b[0], b[1]};
}

/// resting_contact. All weights k/8 on the grids of random_grid: every coordinate is exact
/// (as in planted), so each relation below holds exactly in doubles.
/// - vertex-face, in the plane: triangle and vertex move within one fixed plane (the triangle
///   rigidly or each vertex on its own); p(0) is on the closed face, p(1) on it too (other
///   weights) or anywhere in the plane: contact at t = 0, coplanar throughout.
/// - vertex-face, riding: p is a fixed k/8 combination of the moving vertices (any motion):
///   on the face throughout.
/// - edge-edge, collinear: four points on one line, the edges overlapping at t = 0 (and at
///   t = 1 or not) as they slide along it.
/// - edge-edge, crossing: both edges in one plane, crossing (or touching at an end) at t = 0,
///   crossing again at t = 1 or anywhere in the plane.
inline void resting(Rng& rng, QueryType type, DoubleQuery* q) {
  const Grid g = random_grid(rng);
  if (type == QueryType::vertex_face) {
    if (coin(rng, 4)) {  // riding a moving face
      std::array<Moving, 4> m;
      for (auto& x : m) x = random_moving(rng, g);
      double w[3];
      closed_face_weights(rng, w);
      m[0] = combine(w[0], m[1], w[1], m[2], w[2], m[3]);
      q->v = positions(m, 0.0);
      return;
    }
    const Plane P = random_plane(rng, g);
    std::array<Point2d, 3> t0, t1;
    for (auto& x : t0) x = dyadic_point2(rng, g);
    const bool rigid = coin(rng);
    const Point2d shift = dyadic_point2(rng, g);
    for (int i = 0; i < 3; ++i)
      t1[i] = rigid ? Point2d{t0[i][0] + shift[0], t0[i][1] + shift[1]} : dyadic_point2(rng, g);
    double w[3];
    closed_face_weights(rng, w);
    const Point2d p0 = weighted(w, t0[0], t0[1], t0[2]);
    Point2d p1;
    if (coin(rng)) {
      closed_face_weights(rng, w);
      p1 = weighted(w, t1[0], t1[1], t1[2]);
    } else {
      p1 = dyadic_point2(rng, g);
    }
    q->v[0] = P.at(p0[0], p0[1]);
    q->v[4] = P.at(p1[0], p1[1]);
    for (int i = 0; i < 3; ++i) {
      q->v[1 + i] = P.at(t0[i][0], t0[i][1]);
      q->v[5 + i] = P.at(t1[i][0], t1[i][1]);
    }
    return;
  }
  if (coin(rng)) {  // collinear: o + s e
    const Eigen::Vector3d o = dyadic_point(rng, g.bits, g.range);
    Eigen::Vector3d e;
    do
      for (int k = 0; k < 3; ++k) e[k] = uniform_int(rng, -3, 3);
    while (e.isZero());
    const auto overlapping = [&] {  // a0, a1, b0, b1 parameters, b0 within [a0, a1]
      const double a0 = dyadic(rng, g.bits, g.range);
      const double a1 = dyadic(rng, g.bits, g.range);
      const double b0 = a0 + (uniform_int(rng, 0, 8) / 8.0) * (a1 - a0);
      const double b1 = dyadic(rng, g.bits, g.range);
      return std::array<double, 4>{a0, a1, b0, b1};
    };
    const std::array<double, 4> s0 = overlapping();
    std::array<double, 4> s1;
    if (coin(rng)) {
      s1 = overlapping();
    } else {
      for (double& x : s1) x = dyadic(rng, g.bits, g.range);
    }
    for (int i = 0; i < 4; ++i) {
      q->v[i] = o + s0[i] * e;
      q->v[i + 4] = o + s1[i] * e;
    }
  } else {  // crossing in a common plane
    const Plane P = random_plane(rng, g);
    const std::array<Point2d, 4> x0 = crossing_segments(rng, g);
    std::array<Point2d, 4> x1;
    if (coin(rng)) {
      x1 = crossing_segments(rng, g);
    } else {
      for (auto& x : x1) x = dyadic_point2(rng, g);
    }
    for (int i = 0; i < 4; ++i) {
      q->v[i] = P.at(x0[i][0], x0[i][1]);
      q->v[i + 4] = P.at(x1[i][0], x1[i][1]);
    }
  }
  if (coin(rng))  // edge b first
    for (int k : {0, 4}) std::swap(q->v[k], q->v[k + 2]), std::swap(q->v[k + 1], q->v[k + 3]);
}

/// stacked_coplanar. Layers z = s1 x + s2 y + gap, slopes s1, s2 in {-1/2, ..., 1/2} (k/4);
/// x and y are multiples of 2^-10 of magnitude at most 5/4, so s1 x + s2 y is a multiple of
/// 2^-12 of magnitude at most 5/4; the gap is 0 or +-2^-k, k in [20, 52]: every z is a
/// multiple of 2^-52 below 2 in magnitude, hence a double (their spacing there is at most
/// 2^-52), and every coordinate is exact. One primitive (the triangle; edge a) lies in the
/// layer gap 0, the other in the layer of gap g0 at t = 0 and g1 at t = 1 (g1 = g0 mostly:
/// stacked throughout; else 0 or -g0: the gap closes at t = 1 or flips at t = 1/2). Each
/// vertex slides tangentially within its layer; the small primitive lies over the other
/// (weights k/8, crossing projections) or anywhere. Then the axes are permuted and mirrored.
inline void stacked(Rng& rng, QueryType type, DoubleQuery* q) {
  const double s1 = uniform_int(rng, -2, 2) / 4.0;
  const double s2 = uniform_int(rng, -2, 2) / 4.0;
  double g0 = 0.0;
  if (!coin(rng, 4)) {
    const double sign = coin(rng) ? 1.0 : -1.0;
    g0 = std::ldexp(sign, -uniform_int(rng, 20, 52));
  }
  double g1 = g0;
  double planted = std::numeric_limits<double>::quiet_NaN();
  switch (uniform_int(rng, 0, 7)) {
    case 0: g1 = 0, planted = 1.0; break;
    case 1: g1 = -g0, planted = 0.5; break;
    default: break;
  }
  const auto xy = [&rng] {
    const double x = uniform_int(rng, -64, 64) / 64.0;
    const double y = uniform_int(rng, -64, 64) / 64.0;
    return Point2d{x, y};
  };
  const auto at = [s1, s2](const Point2d& p, double gap) {
    return Eigen::Vector3d(p[0], p[1], (s1 * p[0] + s2 * p[1]) + gap);
  };
  // Tangential motion: a common slide by at most 1/4 (rigid) or each point on its own.
  const bool rigid = coin(rng);
  const Point2d slide = {uniform_int(rng, -16, 16) / 64.0, uniform_int(rng, -16, 16) / 64.0};
  const auto moved = [&](const Point2d& p) {
    return rigid ? Point2d{p[0] + slide[0], p[1] + slide[1]} : xy();
  };
  const bool over = !coin(rng, 4);  // the small primitive over the other one
  if (type == QueryType::vertex_face) {
    std::array<Point2d, 3> t0, t1;
    for (auto& x : t0) x = xy();
    for (int i = 0; i < 3; ++i) t1[i] = moved(t0[i]);
    double w[3];
    closed_face_weights(rng, w);
    const Point2d p0 = over ? weighted(w, t0[0], t0[1], t0[2]) : xy();
    const Point2d p1 = moved(p0);
    q->v[0] = at(p0, g0);
    q->v[4] = at(p1, g1);
    for (int i = 0; i < 3; ++i) {
      q->v[1 + i] = at(t0[i], 0.0);
      q->v[5 + i] = at(t1[i], 0.0);
    }
  } else {
    // Crossing segments on the grid 2^-6 in [-1, 1]: ends multiples of 2^-9 within [-2, 2],
    // halved (exactly) into [-1, 1].
    std::array<Point2d, 4> x0 = crossing_segments(rng, Grid{6, 1});
    for (auto& p : x0) p = {0.5 * p[0], 0.5 * p[1]};
    if (!over)
      for (int i = 2; i < 4; ++i) x0[i] = xy();
    for (int i = 0; i < 4; ++i) {
      const double gap0 = i < 2 ? 0.0 : g0, gap1 = i < 2 ? 0.0 : g1;
      q->v[i] = at(x0[i], gap0);
      q->v[i + 4] = at(moved(x0[i]), gap1);
    }
    if (coin(rng))  // edge b first
      for (int k : {0, 4}) std::swap(q->v[k], q->v[k + 2]), std::swap(q->v[k + 1], q->v[k + 3]);
  }
  q->planted_time = planted;
  permute_and_mirror_axes(q, rng);
}

}  // namespace detail

/// The seed of query `index` of generator g under `seed`.
inline std::uint64_t query_seed(std::uint64_t seed, const Generator& g, std::uint64_t index) {
  const std::uint64_t tag = (static_cast<std::uint64_t>(g.family) << 8) |
                            static_cast<std::uint64_t>(g.type);
  return mix64(mix64(seed ^ mix64(tag)) ^ index);
}

/// The per-query random engine of query `index` of generator g under `seed`.
inline std::mt19937_64 query_rng(std::uint64_t seed, const Generator& g, std::uint64_t index) {
  return std::mt19937_64(query_seed(seed, g, index));
}

/// The exponent k of the final power-of-two scaling of query `index` of g: k uniform in
/// [-1000, 1000] for one query in four, 0 for the others. Drawn from a stream of its own, so
/// that the unscaled query and the rest of the query's stream (the differential check's option
/// choices) do not depend on it.
inline int power_of_two_exponent(std::uint64_t seed, const Generator& g, std::uint64_t index) {
  detail::Rng rng(mix64(query_seed(seed, g, index) ^ 0x2b992ddfa23249d6ULL));
  if (!detail::coin(rng, 4)) return 0;
  return detail::uniform_int(rng, -1000, 1000);
}

/// Multiplies every coordinate by 2^k when every product is a double (finite, and no bit lost
/// below 2^-1074): scaling space by 2^k > 0 changes no contact and no contact time, so the
/// scaled query has the same answer (and planted time). Returns whether it scaled; otherwise
/// q is left as it was.
inline bool scale_if_exact(DoubleQuery* q, int k) {
  std::array<Eigen::Vector3d, 8> v;
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = q->v[i][c], s = std::ldexp(x, k);
      if (!std::isfinite(s) || std::ldexp(s, -k) != x) return false;
      v[i][c] = s;
    }
  q->v = v;
  return true;
}

/// Query `index` of generator g under `seed` before the final power-of-two scaling; `rng`
/// continues the query's stream.
inline DoubleQuery generate_unscaled(const Generator& g, std::uint64_t seed, std::uint64_t index,
                                     std::mt19937_64& rng) {
  using namespace detail;
  rng = query_rng(seed, g, index);
  DoubleQuery q;
  q.type = g.type;
  bool exact = true;
  bool perturb = false;
  bool transform = true;  // random_transform: the families of ordinary magnitudes
  switch (g.family) {
    case Family::uniform_box: {
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (auto& p : q.v) p = {u(rng), u(rng), u(rng)};
      exact = false;
      break;
    }
    case Family::small_integer_grid:
      for (auto& p : q.v)
        p = {double(uniform_int(rng, -2, 2)), double(uniform_int(rng, -2, 2)),
             double(uniform_int(rng, -2, 2))};
      exact = false;
      break;
    case Family::short_motion: {
      std::uniform_real_distribution<double> u(0.0, 1.0), du(-0.1, 0.1);
      for (int i = 0; i < 4; ++i) {
        q.v[i] = {u(rng), u(rng), u(rng)};
        // One draw per statement, z first, as GCC evaluated the former constructor arguments.
        const double dz = du(rng);
        const double dy = du(rng);
        const double dx = du(rng);
        q.v[i + 4] = q.v[i] + Eigen::Vector3d(dx, dy, dz);
      }
      exact = false;
      break;
    }
    case Family::planted_contact:
    case Family::planted_contact_ulps:
    case Family::contact_at_endpoints: {
      const Grid grid = random_grid(rng);
      const double tc = g.family == Family::contact_at_endpoints ? (coin(rng) ? 0.0 : 1.0)
                                                                 : random_planted_time(rng);
      q.v = positions(planted(rng, g.type, grid), tc);
      q.planted_time = tc;
      perturb = g.family == Family::planted_contact_ulps ||
                (g.family == Family::contact_at_endpoints && coin(rng));
      break;
    }
    case Family::coplanar_throughout:
      q.v = coplanar_positions(rng, random_grid(rng));
      perturb = coin(rng);
      break;
    case Family::degenerate_primitives: {
      const Grid grid = random_grid(rng);
      const double tc = random_planted_time(rng);
      q.v = positions(degenerate_throughout(rng, g.type, grid), tc);
      perturb = coin(rng);
      break;
    }
    // The families below keep their magnitudes (a decimal scaling or a translation would
    // overflow or round away what makes them hard); the final power-of-two scaling varies them.
    case Family::wide_exponent_100:
    case Family::wide_exponent_300:
    case Family::wide_exponent_1000: {
      const int spread = g.family == Family::wide_exponent_100   ? 100
                         : g.family == Family::wide_exponent_300 ? 300
                                                                 : 1000;
      for (auto& p : q.v)
        for (int k = 0; k < 3; ++k) p[k] = wide_exponent_double(rng, spread);
      transform = false;
      break;
    }
    case Family::huge_triangle_subnormal_motion:
      huge_and_subnormal(rng, g.type, &q);
      transform = false;
      break;
    case Family::resting_contact:
      resting(rng, g.type, &q);
      q.planted_time = 0.0;  // in contact at t = 0
      perturb = coin(rng);
      transform = false;
      break;
    case Family::stacked_coplanar:
      stacked(rng, g.type, &q);
      transform = false;
      break;
  }
  if (transform) random_transform(rng, q.v, &exact);
  if (!exact) q.planted_time = std::numeric_limits<double>::quiet_NaN();
  if (perturb) {
    detail::perturb_ulps(rng, q.v);
    q.planted_time = std::numeric_limits<double>::quiet_NaN();
  }
  return q;
}

/// Query `index` of generator g under `seed`; `rng` continues the query's stream (for option
/// choices that must be reproducible with the query). One query in four is the unscaled query
/// times 2^k, k = power_of_two_exponent(...), when that is exact (q.power_of_two = k).
inline DoubleQuery generate(const Generator& g, std::uint64_t seed, std::uint64_t index,
                            std::mt19937_64& rng) {
  DoubleQuery q = generate_unscaled(g, seed, index, rng);
  const int k = power_of_two_exponent(seed, g, index);
  if (k != 0 && scale_if_exact(&q, k)) q.power_of_two = k;
  return q;
}

inline DoubleQuery generate(const Generator& g, std::uint64_t seed, std::uint64_t index) {
  std::mt19937_64 rng;
  return generate(g, seed, index, rng);
}

inline DoubleQuery generate_unscaled(const Generator& g, std::uint64_t seed, std::uint64_t index) {
  std::mt19937_64 rng;
  return generate_unscaled(g, seed, index, rng);
}

// ---------------------------------------------------------------------------------------------
// Extreme magnitudes (tests/extreme_magnitude_test.cpp)
//
// Coordinates over the whole double range, 2^-1074 (the smallest subnormal) to DBL_MAX, mixed
// within one query, with differences that overflow. Two exact facts give ground truth:
//  - Multiplying one axis of every point by 2^s is an invertible linear map of space: a point is
//    in a triangle, or two segments meet, at time t iff their images are, so the contact times
//    (verdict and TOI) do not change. The double products are exact unless bits fall below
//    2^-1074; scale_axes says whether they are.
//  - A layered query keeps each primitive in a plane z = const that moves along z: its contact
//    times follow from one linear function of t and a 2-D test, decided here in rationals.

namespace detail {

/// A binary exponent in [-1074, 1023]: in the subnormal range, near the overflow threshold,
/// near 1, or uniform over the whole range.
inline int random_exponent(Rng& rng) {
  switch (uniform_int(rng, 0, 4)) {
    case 0: return uniform_int(rng, -1074, -1023);
    case 1: return uniform_int(rng, 1000, 1023);
    case 2: return uniform_int(rng, -4, 4);
    default: return uniform_int(rng, -1074, 1023);
  }
}

/// 2^e (1 + f), f a random fraction of 52 bits or of at most 3 (equal values and exact ties
/// likely); rounded for e < -1022 (a subnormal, or 0 below 2^-1075). For e = 1023, one in
/// eight is DBL_MAX.
inline double random_magnitude(Rng& rng, int e) {
  if (e >= 1023 && coin(rng, 8)) return std::numeric_limits<double>::max();
  const int bits = coin(rng) ? uniform_int(rng, 0, 3) : 52;
  const std::uint64_t f = bits == 0 ? 0 : rng() >> (64 - bits);
  return std::ldexp(1.0 + std::ldexp(static_cast<double>(f), -bits), std::min(e, 1023));
}

inline double random_signed(Rng& rng, int e) {
  const double m = random_magnitude(rng, e);
  return coin(rng) ? m : -m;
}

/// floor(log2) of the largest |coordinate| of each axis (subnormals included); INT_MIN for an
/// axis of zeros.
inline std::array<int, 3> axis_exponents(const std::array<Eigen::Vector3d, 8>& x) {
  std::array<int, 3> e;
  e.fill(std::numeric_limits<int>::min());
  for (const auto& p : x)
    for (int k = 0; k < 3; ++k)
      if (p[k] != 0) e[k] = std::max(e[k], std::ilogb(p[k]));
  return e;
}

}  // namespace detail

/// Multiplies axis k of every point by 2^shift[k]. Returns whether every product is exact
/// (finite, and no bit lost below 2^-1074): then the query has its original answer.
inline bool scale_axes(DoubleQuery* q, const std::array<int, 3>& shift) {
  bool exact = true;
  for (auto& p : q->v)
    for (int k = 0; k < 3; ++k) {
      const double s = std::ldexp(p[k], shift[k]);
      if (!std::isfinite(s) || std::ldexp(s, -shift[k]) != p[k]) exact = false;
      p[k] = s;
    }
  if (!exact) q->planted_time = std::numeric_limits<double>::quiet_NaN();
  return exact;
}

/// Scales each axis by a power of two so that its largest |coordinate| lies in
/// [2^top[k], 2^(top[k] + 1)), top[k] in [-1074, 1023]: never overflows, and is exact unless
/// bits fall below 2^-1074 (returned). An axis of zeros stays zero.
inline bool place_axes(DoubleQuery* q, const std::array<int, 3>& top) {
  const std::array<int, 3> e = detail::axis_exponents(q->v);
  std::array<int, 3> shift{};
  for (int k = 0; k < 3; ++k)
    shift[k] = e[k] == std::numeric_limits<int>::min() ? 0 : top[k] - e[k];
  return scale_axes(q, shift);
}

/// Scales the whole query by one power of two so that its largest |coordinate| lies in
/// [2^top, 2^(top + 1)), top in [-1074, 1023]: never overflows, and is exact unless bits fall
/// below 2^-1074 (returned). A query of zeros stays zero.
inline bool place_query(DoubleQuery* q, int top) {
  const std::array<int, 3> e = detail::axis_exponents(q->v);
  const int largest = *std::max_element(e.begin(), e.end());
  const int shift = largest == std::numeric_limits<int>::min() ? 0 : top - largest;
  return scale_axes(q, {shift, shift, shift});
}

/// The smallest top for place_query that keeps every bit of the query: its coordinates span
/// the binary digits from 2^top(q) down to the lowest set bit, and the lowest must stay at or
/// above 2^-1074. -1074 for a query of zeros.
inline int lowest_exact_top(const DoubleQuery& q) {
  int high = std::numeric_limits<int>::min(), low = std::numeric_limits<int>::max();
  for (const auto& p : q.v)
    for (int k = 0; k < 3; ++k) {
      if (p[k] == 0) continue;
      int e = 0;
      const double m = std::frexp(std::fabs(p[k]), &e);  // |x| = m 2^e, m in [1/2, 1)
      auto mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
      int lowest = e - 53;
      while ((mantissa & 1) == 0) mantissa >>= 1, ++lowest;
      high = std::max(high, e - 1);
      low = std::min(low, lowest);
    }
  return high == std::numeric_limits<int>::min() ? -1074 : -1074 + (high - low);
}

/// Translates each axis so that its extreme coordinates are opposite, when every difference
/// is exact (returned; the query is left alone otherwise). A translation changes no answer;
/// placed at the top of the range afterwards, the query's differences overflow.
inline bool center_axes(DoubleQuery* q) {
  DoubleQuery c = *q;
  for (int k = 0; k < 3; ++k) {
    double lo = q->v[0][k], hi = lo;
    for (const auto& p : q->v) lo = std::min(lo, p[k]), hi = std::max(hi, p[k]);
    const double mid = 0.5 * lo + 0.5 * hi;
    for (auto& p : c.v) {
      const double moved = p[k] - mid;
      if (mpq_class(moved) != mpq_class(p[k]) - mpq_class(mid)) return false;
      p[k] = moved;
    }
  }
  *q = c;
  return true;
}

/// Permutes the axes and mirrors some of them at random: exact, and an isometry (no answer
/// changes).
inline void permute_and_mirror_axes(DoubleQuery* q, std::mt19937_64& rng) {
  std::array<int, 3> axis{0, 1, 2};
  std::shuffle(axis.begin(), axis.end(), rng);
  const std::array<bool, 3> mirror{detail::coin(rng), detail::coin(rng), detail::coin(rng)};
  for (auto& p : q->v) {
    const Eigen::Vector3d old = p;
    for (int k = 0; k < 3; ++k) p[k] = mirror[k] ? -old[axis[k]] : old[axis[k]];
  }
}

/// Eight points whose coordinates are 0 or of random sign and magnitude 2^e (1 + f), e drawn
/// from `exponents` for each coordinate: mixed magnitudes within one query (subnormal next to
/// normal, tiny next to huge, differences that overflow). Contacts are rare; the exact path
/// decides.
inline DoubleQuery random_mixed_magnitude_query(std::mt19937_64& rng, QueryType type,
                                                const std::vector<int>& exponents) {
  DoubleQuery q;
  q.type = type;
  for (auto& p : q.v)
    for (int k = 0; k < 3; ++k)
      p[k] = detail::coin(rng, 8) ? 0.0
                                  : detail::random_signed(
                                        rng, exponents[detail::uniform_int(
                                                 rng, 0, static_cast<int>(exponents.size()) - 1)]);
  return q;
}

/// A query built together with its exact answer over [0, 1].
struct QueryWithAnswer {
  DoubleQuery query;
  bool collides = false;
  mpq_class toi;  ///< t*, when collides
};

namespace detail {

struct Point2 {
  mpq_class x, y;
};

/// Twice the signed area of (a, b, c).
inline mpq_class orient2(const Point2& a, const Point2& b, const Point2& c) {
  return mpq_class((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// c lies in the closed bounding box of a and b (on the closed segment, if collinear).
inline bool in_box(const Point2& a, const Point2& b, const Point2& c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

/// The closed segments [p0, p1] and [q0, q1] (either may be a point) meet.
inline bool segments_meet_2d(const Point2& p0, const Point2& p1, const Point2& q0,
                             const Point2& q1) {
  const int o1 = sgn(orient2(p0, p1, q0)), o2 = sgn(orient2(p0, p1, q1));
  const int o3 = sgn(orient2(q0, q1, p0)), o4 = sgn(orient2(q0, q1, p1));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && in_box(p0, p1, q0)) || (o2 == 0 && in_box(p0, p1, q1)) ||
         (o3 == 0 && in_box(q0, q1, p0)) || (o4 == 0 && in_box(q0, q1, p1));
}

/// (1 - t) a0 + t a1, exactly.
inline mpq_class lerp(double a0, double a1, const mpq_class& t) {
  return mpq_class((1 - t) * mpq_class(a0) + t * mpq_class(a1));
}

inline Point2 lerp2(const std::array<double, 2>& p0, const std::array<double, 2>& p1,
                    const mpq_class& t) {
  return {lerp(p0[0], p1[0], t), lerp(p0[1], p1[1], t)};
}

inline Point2 point2(const std::array<double, 2>& p) { return {mpq_class(p[0]), mpq_class(p[1])}; }

/// Where the gap g(t) = (1 - t) g0 + t g1 vanishes in [0, 1].
enum class GapZeros { never, once, always };
inline GapZeros gap_zeros(const mpq_class& g0, const mpq_class& g1, mpq_class* t) {
  if (sgn(g0) == 0 && sgn(g1) == 0) return GapZeros::always;
  if (sgn(g0) * sgn(g1) > 0) return GapZeros::never;
  *t = g0 / (g0 - g1);
  return GapZeros::once;
}

/// Heights of two layers at t = 0 and t = 1 (the first primitive's, then the second's), of
/// random magnitudes: the second starts above the first and ends below it (or the reverse), so
/// that the layers meet once, sometimes exactly at t = 0 or t = 1, sometimes always.
inline std::array<double, 4> random_layer_heights(Rng& rng) {
  const auto value = [&rng] {
    return coin(rng, 6) ? 0.0 : random_signed(rng, random_exponent(rng));
  };
  double u0 = value(), v0 = value(), u1 = value(), v1 = value();
  switch (uniform_int(rng, 0, 9)) {
    case 0: v0 = u0; break;           // the layers meet at t = 0
    case 1: v1 = u1; break;           // ... at t = 1
    case 2: v0 = u0, v1 = u1; break;  // ... always
    default: break;
  }
  // first: za0 <= zb0 and za1 >= zb1
  double za0 = std::min(u0, v0), zb0 = std::max(u0, v0);
  double za1 = std::max(u1, v1), zb1 = std::min(u1, v1);
  if (coin(rng)) std::swap(za0, zb0), std::swap(za1, zb1);
  return {za0, za1, zb0, zb1};
}

/// A random point aimed at the closed segment [a, b]: at an end, in the middle, one ulp off
/// an end, or anywhere (rounding may move it off; the answer is computed exactly anyway).
inline std::array<double, 2> aim_at_segment(Rng& rng, const std::array<double, 2>& a,
                                            const std::array<double, 2>& b) {
  std::array<double, 2> x = a;
  switch (uniform_int(rng, 0, 4)) {
    case 0: break;
    case 1: x = {0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]}; break;
    case 2: x = {0.25 * a[0] + 0.75 * b[0], 0.25 * a[1] + 0.75 * b[1]}; break;
    case 3: {
      double& c = x[uniform_int(rng, 0, 1)];
      const double moved = std::nextafter(c, coin(rng) ? std::numeric_limits<double>::infinity()
                                                       : -std::numeric_limits<double>::infinity());
      if (std::isfinite(moved)) c = moved;  // not beyond DBL_MAX
      break;
    }
    default:
      x = {random_signed(rng, random_exponent(rng)), random_signed(rng, random_exponent(rng))};
  }
  return x;
}

/// x - t d and x + (1 - t) d, the positions at 0 and 1 of a point at x at the double time t
/// moving by d; d is dropped (the point is at rest) where they would overflow.
inline std::pair<std::array<double, 2>, std::array<double, 2>> moving_through(
    const std::array<double, 2>& x, const std::array<double, 2>& d, double t) {
  std::array<double, 2> p0, p1;
  for (int k = 0; k < 2; ++k) {
    p0[k] = x[k] - t * d[k];
    p1[k] = x[k] + (1 - t) * d[k];
    if (!std::isfinite(p0[k]) || !std::isfinite(p1[k])) p0[k] = p1[k] = x[k];
  }
  return {p0, p1};
}

/// A 2-D displacement: zero, or of random magnitudes.
inline std::array<double, 2> random_displacement(Rng& rng) {
  if (coin(rng, 3)) return {0.0, 0.0};
  return {random_signed(rng, random_exponent(rng)), random_signed(rng, random_exponent(rng))};
}

/// 2-D points at a common random scale, or each at its own (thin shapes spanning the range);
/// some coordinates zero.
inline std::array<double, 2> random_point2(Rng& rng, int common_exponent) {
  const int e = coin(rng, 3) ? random_exponent(rng) : common_exponent - uniform_int(rng, 0, 3);
  std::array<double, 2> p;
  for (double& c : p) c = coin(rng, 6) ? 0.0 : random_signed(rng, std::max(e, -1074));
  return p;
}

}  // namespace detail

/// A layered vertex-face query: the triangle has fixed (x, y), non-degenerate, and one height
/// z moving from za0 to za1; p moves freely. p is aimed at a vertex, an edge or the inside of
/// the triangle, or one ulp off, at the time the layers meet. Magnitudes are random over the
/// whole range and mixed (a needle through a huge triangle, a huge motion through a tiny one);
/// differences may overflow. The answer: p meets the triangle's plane where the linear gap
/// zp(t) - za(t) vanishes (once, or always), and p's (x, y) there decides, in rationals.
inline QueryWithAnswer layered_vertex_face(std::mt19937_64& rng) {
  using namespace detail;
  std::array<std::array<double, 2>, 3> tri;
  std::array<Point2, 3> t2;
  do {
    const int e = random_exponent(rng);
    for (int i = 0; i < 3; ++i) {
      tri[i] = random_point2(rng, e);
      t2[i] = point2(tri[i]);
    }
  } while (sgn(orient2(t2[0], t2[1], t2[2])) == 0);
  const int orientation = sgn(orient2(t2[0], t2[1], t2[2]));

  const int i = uniform_int(rng, 0, 2);
  std::array<double, 2> x = aim_at_segment(rng, tri[i], tri[(i + 1) % 3]);
  if (coin(rng, 5))  // inside, away from the edges (up to rounding)
    for (int k = 0; k < 2; ++k) x[k] = (0.25 * tri[0][k] + 0.25 * tri[1][k]) + 0.5 * tri[2][k];

  const std::array<double, 4> z = random_layer_heights(rng);  // triangle, then p
  QueryWithAnswer out;
  mpq_class tc;
  const GapZeros zeros = gap_zeros(mpq_class(z[2]) - mpq_class(z[0]),
                                   mpq_class(z[3]) - mpq_class(z[1]), &tc);
  // p is at x when the layers meet (at a random time if they always do).
  const double aim_time = zeros == GapZeros::once
                              ? tc.get_d()
                              : std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  const auto [p0, p1] = moving_through(x, random_displacement(rng), aim_time);

  DoubleQuery& q = out.query;
  q.type = QueryType::vertex_face;
  q.v[0] = {p0[0], p0[1], z[2]};
  q.v[4] = {p1[0], p1[1], z[3]};
  for (int k = 0; k < 3; ++k) {
    q.v[1 + k] = {tri[k][0], tri[k][1], z[0]};
    q.v[5 + k] = {tri[k][0], tri[k][1], z[1]};
  }

  // The answer. s_j(t) = orientation * orient2(tri_j, tri_j+1, p(t)) is affine in t, and p(t)
  // is in the closed triangle iff all three are >= 0.
  if (zeros == GapZeros::once) {
    const Point2 p = lerp2(p0, p1, tc);
    bool inside = true;
    for (int j = 0; j < 3; ++j)
      inside = inside && orientation * sgn(orient2(t2[j], t2[(j + 1) % 3], p)) >= 0;
    out.collides = inside;
    out.toi = tc;
  } else if (zeros == GapZeros::always) {
    // The first t in [0, 1] with every s_j(t) >= 0.
    mpq_class lo(0), hi(1);
    bool empty = false;
    for (int j = 0; j < 3; ++j) {
      const mpq_class s0 = orientation * orient2(t2[j], t2[(j + 1) % 3], point2(p0));
      const mpq_class s1 = orientation * orient2(t2[j], t2[(j + 1) % 3], point2(p1));
      if (sgn(s0) < 0 && sgn(s1) < 0) empty = true;
      else if (sgn(s0) < 0) lo = std::max(lo, mpq_class(s0 / (s0 - s1)));
      else if (sgn(s1) < 0) hi = std::min(hi, mpq_class(s0 / (s0 - s1)));
    }
    out.collides = !empty && lo <= hi;
    out.toi = lo;
  }
  permute_and_mirror_axes(&q, rng);
  return out;
}

/// A layered edge-edge query: edge a has fixed (x, y) and one height moving from za0 to za1;
/// edge b has its own height and its ends move freely in (x, y) (at rest when the layers always
/// meet). b is aimed through a point of a (an end, the middle, one ulp off, or anywhere) at the
/// time the layers meet; zero-length edges occur. Magnitudes as in layered_vertex_face. The
/// answer: the layers meet where a linear gap vanishes, and the 2-D segments there decide.
inline QueryWithAnswer layered_edge_edge(std::mt19937_64& rng) {
  using namespace detail;
  const int e = random_exponent(rng);
  const std::array<double, 2> a0 = random_point2(rng, e);
  const std::array<double, 2> a1 = coin(rng, 10) ? a0 : random_point2(rng, e);
  const std::array<double, 2> x = aim_at_segment(rng, a0, a1);
  // b's ends x - u w and x + (1 - u) w (or a single point), through x.
  std::array<double, 2> w = {random_signed(rng, random_exponent(rng)),
                             random_signed(rng, random_exponent(rng))};
  if (coin(rng, 10)) w = {0.0, 0.0};
  const double u = std::array<double, 4>{0.0, 1.0, 0.5, 0.25}[uniform_int(rng, 0, 3)];
  const auto [b0, b1] = moving_through(x, w, u);

  const std::array<double, 4> z = random_layer_heights(rng);  // edge a, then edge b
  QueryWithAnswer out;
  mpq_class tc;
  const GapZeros zeros = gap_zeros(mpq_class(z[2]) - mpq_class(z[0]),
                                   mpq_class(z[3]) - mpq_class(z[1]), &tc);
  std::array<double, 2> d0{0.0, 0.0}, d1{0.0, 0.0};
  if (zeros == GapZeros::once) {
    d0 = random_displacement(rng);
    d1 = coin(rng) ? d0 : random_displacement(rng);
  }
  const double aim_time = zeros == GapZeros::once ? tc.get_d() : 0.0;
  const auto [b00, b01] = moving_through(b0, d0, aim_time);
  const auto [b10, b11] = moving_through(b1, d1, aim_time);

  DoubleQuery& q = out.query;
  q.type = QueryType::edge_edge;
  q.v[0] = {a0[0], a0[1], z[0]};
  q.v[1] = {a1[0], a1[1], z[0]};
  q.v[2] = {b00[0], b00[1], z[2]};
  q.v[3] = {b10[0], b10[1], z[2]};
  q.v[4] = {a0[0], a0[1], z[1]};
  q.v[5] = {a1[0], a1[1], z[1]};
  q.v[6] = {b01[0], b01[1], z[3]};
  q.v[7] = {b11[0], b11[1], z[3]};

  if (zeros != GapZeros::never) {
    // When the layers always meet, nothing moves in (x, y): contact from t = 0 iff the segments
    // meet at all.
    const mpq_class t = zeros == GapZeros::once ? tc : mpq_class(0);
    out.collides = segments_meet_2d(point2(a0), point2(a1), lerp2(b00, b01, t), lerp2(b10, b11, t));
    out.toi = t;
  }
  if (coin(rng))  // edge b first
    for (int k : {0, 4}) std::swap(q.v[k], q.v[k + 2]), std::swap(q.v[k + 1], q.v[k + 3]);
  permute_and_mirror_axes(&q, rng);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Printing

/// A double in C99 hexadecimal (%a): exact and readable back by strtod.
inline std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

/// The query as C++ initialisers with %a coordinates.
inline std::string describe(const DoubleQuery& q) {
  std::string s = q.type == QueryType::vertex_face ? "vertex-face" : "edge-edge";
  for (const auto& p : q.v) s += "\n  {" + hex(p.x()) + ", " + hex(p.y()) + ", " + hex(p.z()) + "}";
  return s;
}

inline std::string describe(const CcdResult& r) {
  std::string s = r.collides ? "collides, toi [" + hex(r.toi_lo) + ", " + hex(r.toi_hi) + "]"
                             : "no contact";
  return s + " (" + to_string(r.decided_by) + ")";
}

inline std::string describe(const CcdOptions& o) {
  return "t_max " + hex(o.t_max) + ", toi_width " + hex(o.toi_width) + ", mode " +
         to_string(o.mode);
}

/// The query in the benchmark's CSV format (8 rows x_num,x_den,y_num,y_den,z_num,z_den,truth;
/// every double is an exact fraction with a power-of-two denominator), replayable with
/// `exactccd check --type vf|ee FILE`.
inline std::string to_csv(const DoubleQuery& q, bool truth) {
  std::string s;
  for (const auto& p : q.v) {
    for (int k = 0; k < 3; ++k) {
      const mpq_class r(p[k]);
      s += r.get_num().get_str() + "," + r.get_den().get_str() + ",";
    }
    s += truth ? "1\n" : "0\n";
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// The differential check: default path (Mode::filtered) against the exact path (Mode::exact)

/// Number of Stage values (Stage::float_only is the last one).
inline constexpr int kStageCount = static_cast<int>(Stage::float_only) + 1;

/// The stages of the default path, in pipeline order (every Stage but float_only).
inline std::array<Stage, kStageCount - 1> default_path_stages() {
  std::array<Stage, kStageCount - 1> s{};
  for (int i = 0; i + 1 < kStageCount; ++i) s[i] = static_cast<Stage>(i);
  return s;
}

struct DifferentialStats {
  std::uint64_t queries = 0, collisions = 0;
  std::uint64_t stage[kStageCount] = {};  // default path, indexed by Stage
  std::uint64_t width_checks = 0, t_max_checks = 0;
  std::uint64_t disagreements = 0;

  DifferentialStats& operator+=(const DifferentialStats& o) {
    queries += o.queries, collisions += o.collisions;
    for (int i = 0; i < kStageCount; ++i) stage[i] += o.stage[i];
    width_checks += o.width_checks, t_max_checks += o.t_max_checks;
    disagreements += o.disagreements;
    return *this;
  }
};

/// The exact value of hi - lo is at most w.
inline bool exact_width_at_most(double lo, double hi, double w) {
  return mpq_class(hi) - mpq_class(lo) <= mpq_class(w);
}

/// [lo, hi] is [x, x] or two consecutive doubles.
inline bool is_tightest_pair(double lo, double hi) {
  return lo == hi || std::nextafter(lo, std::numeric_limits<double>::infinity()) == hi;
}

/// Checks `coarse` (default path, toi_width = w > 0) against `tight` (exact path, toi_width =
/// 0) on a query that collides: same verdict, [lo, hi] contains t*, and hi - lo <= w exactly
/// or [lo, hi] is already the tightest pair. tight = [L, H] is the tightest pair around t*: if
/// L == H then t* = L, else t* is strictly between L and H and no double lies in (L, H), so a
/// double enclosure [lo, hi] of t* is exactly one with lo <= L and H <= hi.
inline std::string check_coarse_toi(const CcdResult& coarse, const CcdResult& tight, double w) {
  if (!coarse.collides) return "coarse toi_width: verdict differs";
  const bool contains = tight.toi_lo == tight.toi_hi
                            ? coarse.toi_lo <= tight.toi_lo && tight.toi_lo <= coarse.toi_hi
                            : coarse.toi_lo <= tight.toi_lo && tight.toi_hi <= coarse.toi_hi;
  if (!contains) return "coarse toi_width: [toi_lo, toi_hi] misses t*";
  if (!exact_width_at_most(coarse.toi_lo, coarse.toi_hi, w) &&
      !is_tightest_pair(coarse.toi_lo, coarse.toi_hi))
    return "coarse toi_width: toi_hi - toi_lo > toi_width";
  return {};
}

/// Both TOI fields +infinity, the no-contact convention (written out, not the library's constant).
inline bool is_no_contact_toi(const CcdResult& r) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return r.toi_lo == inf && r.toi_hi == inf;
}

/// Tightest-pair comparison: same verdict and, when colliding, identical TOI doubles.
inline std::string check_tight(const CcdResult& d, const CcdResult& e) {
  if (d.collides != e.collides) return "verdict differs";
  if (d.collides && (d.toi_lo != e.toi_lo || d.toi_hi != e.toi_hi)) return "toi differs";
  if (!d.collides && !(is_no_contact_toi(d) && is_no_contact_toi(e)))
    return "toi not +infinity without contact";
  return {};
}

struct Disagreement {
  std::string what;
  DoubleQuery query;
  CcdOptions options;
  CcdResult default_result, exact_result;

  std::string report() const {
    return what + "\n query: " + describe(query) + "\n options: " + describe(options) +
           "\n default: " + describe(default_result) + "\n exact:   " + describe(exact_result);
  }
};

/// Default versus exact on one query: toi_width = 0 over [0, 1]; for a collision, a random
/// coarse toi_width; one query in eight, a second comparison over [0, t_max] with t_max the
/// planted time, just before it, or random. `rng` (the query's stream) picks the options.
/// Returns the first disagreement, if any (what is empty when all agree).
inline Disagreement differential_check(const DoubleQuery& q, std::mt19937_64& rng,
                                       DifferentialStats& stats) {
  Disagreement out;
  out.query = q;
  CcdOptions options;
  CcdResult d = ccd(q, options);
  CcdResult e = ccd(q, with_mode(options, Mode::exact));
  ++stats.queries;
  ++stats.stage[static_cast<int>(d.decided_by)];
  if (d.collides) ++stats.collisions;
  const auto fail = [&](std::string what, const CcdOptions& o, const CcdResult& dr,
                        const CcdResult& er) {
    ++stats.disagreements;
    out.what = std::move(what);
    out.options = o;
    out.default_result = dr;
    out.exact_result = er;
    return out;
  };
  if (std::string w = check_tight(d, e); !w.empty()) return fail(w, options, d, e);
  if (e.decided_by != Stage::exact) return fail("exact mode not decided by Stage::exact", options, d, e);

  if (e.collides) {
    // Widths from far below one ulp of t* up to the whole interval.
    static constexpr double kWidths[] = {0x1p-60, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 1.0};
    CcdOptions coarse;
    coarse.toi_width = kWidths[detail::uniform_int(rng, 0, 6)];
    const CcdResult dc = ccd(q, coarse);
    ++stats.width_checks;
    if (std::string w = check_coarse_toi(dc, e, coarse.toi_width); !w.empty())
      return fail(w, coarse, dc, e);
  }

  if (detail::coin(rng, 8)) {
    CcdOptions partial;
    const double tc = q.planted_time;
    switch (detail::uniform_int(rng, 0, 2)) {
      case 0: partial.t_max = tc > 0 ? tc : 0.5; break;
      case 1: partial.t_max = tc > 0 ? std::nextafter(tc, 0.0) : 0x1p-20; break;
      default: partial.t_max = std::uniform_real_distribution<double>(0x1p-30, 1.0)(rng); break;
    }
    if (!(partial.t_max > 0)) partial.t_max = 0.5;
    const CcdResult dp = ccd(q, partial);
    const CcdResult ep = ccd(q, with_mode(partial, Mode::exact));
    ++stats.t_max_checks;
    if (std::string w = check_tight(dp, ep); !w.empty())
      return fail("t_max < 1: " + w, partial, dp, ep);
  }
  return out;
}

/// Default versus exact over [0, t_max], t_max in (0, 1), with a coarse toi_width: the same
/// verdict as the exact path's tightest answer over [0, t_max] (tight), and when colliding,
/// default and exact-mode enclosures of it no wider than asked. t_max is the planted time, the
/// exact contact time over [0, 1], a double just below or above either, a dyadic, or random;
/// `rng` (the query's stream) picks it and the width. Counts into stats: queries and stages
/// (of the default path, coarse), collisions over [0, t_max], t_max_checks, and width_checks
/// (the colliding ones).
inline Disagreement partial_interval_coarse_check(const DoubleQuery& q, std::mt19937_64& rng,
                                                  DifferentialStats& stats) {
  Disagreement out;
  out.query = q;
  CcdOptions tight;
  const double tc = q.planted_time;
  switch (detail::uniform_int(rng, 0, 5)) {
    case 0: tight.t_max = tc; break;
    case 1: tight.t_max = std::nextafter(tc, detail::coin(rng) ? 0.0 : 1.0); break;
    case 2:
    case 3: {  // at the exact contact time over [0, 1], or a double beside it
      const CcdResult whole = ccd(q, with_mode(CcdOptions{}, Mode::exact));
      if (!whole.collides) break;
      tight.t_max = detail::coin(rng) ? whole.toi_lo : whole.toi_hi;
      if (detail::coin(rng))
        tight.t_max = std::nextafter(tight.t_max, detail::coin(rng) ? 0.0 : 1.0);
      break;
    }
    case 4: tight.t_max = detail::uniform_int(rng, 1, 15) / 16.0; break;
    default: break;
  }
  if (!(tight.t_max > 0 && tight.t_max < 1))  // NaN planted time, 0, 1, or none chosen
    tight.t_max = std::uniform_real_distribution<double>(0x1p-30, 1.0)(rng);
  static constexpr double kWidths[] = {1e-6, 1e-3, 0.1, 0.5, 1.0};
  CcdOptions coarse = tight;
  coarse.toi_width = kWidths[detail::uniform_int(rng, 0, 4)];

  const CcdResult ep = ccd(q, with_mode(tight, Mode::exact));
  const CcdResult dc = ccd(q, coarse);
  const CcdResult ec = ccd(q, with_mode(coarse, Mode::exact));
  ++stats.queries;
  ++stats.stage[static_cast<int>(dc.decided_by)];
  ++stats.t_max_checks;
  const auto fail = [&](std::string what, const CcdOptions& o, const CcdResult& got) {
    ++stats.disagreements;
    out.what = "t_max < 1, coarse toi_width: " + std::move(what);
    out.options = o;
    out.default_result = got;
    out.exact_result = ep;
    return out;
  };
  for (const CcdResult* r : {&dc, &ec}) {
    const char* who = r == &dc ? "filtered mode" : "exact mode";
    if (r->collides != ep.collides) return fail(std::string(who) + ": verdict differs", coarse, *r);
    if (!r->collides && !is_no_contact_toi(*r))
      return fail(std::string(who) + ": toi not +infinity without contact", coarse, *r);
    if (r->collides)
      if (std::string w = check_coarse_toi(*r, ep, coarse.toi_width); !w.empty())
        return fail(std::string(who) + ": " + w, coarse, *r);
  }
  if (ep.collides) {
    ++stats.collisions;
    ++stats.width_checks;
  }
  return out;
}

}  // namespace exactccd::random_queries
