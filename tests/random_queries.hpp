// Seeded random double-precision CCD queries, and the differential check "default path versus
// exact path" on one query. Shared by tests/differential_test.cpp, tests/allocation_test.cpp,
// tests/rounding_mode_test.cpp and bench/soak.cpp; no GoogleTest dependency.
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
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

#include "exactccd/ccd.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::test {

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

/// EXACTCCD_TEST_SCALE when set (a positive factor on loop counts), else 1.
inline double scale_from_environment() {
  if (const char* env = std::getenv("EXACTCCD_TEST_SCALE")) {
    const double s = std::strtod(env, nullptr);
    if (s > 0 && std::isfinite(s)) return s;
  }
  return 1.0;
}

inline std::uint64_t scaled_count(std::uint64_t n, double scale) {
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(n * scale)));
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
};

inline constexpr std::array<Family, 8> kAllFamilies = {
    Family::uniform_box,          Family::small_integer_grid,  Family::short_motion,
    Family::planted_contact,      Family::planted_contact_ulps, Family::contact_at_endpoints,
    Family::coplanar_throughout,  Family::degenerate_primitives};

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

/// All generators, vertex-face first.
inline std::array<Generator, 16> all_generators() {
  std::array<Generator, 16> g{};
  for (std::size_t i = 0; i < kAllFamilies.size(); ++i) {
    g[i] = {kAllFamilies[i], QueryType::vertex_face};
    g[i + kAllFamilies.size()] = {kAllFamilies[i], QueryType::edge_edge};
  }
  return g;
}

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
  for (auto& p : x) p = (o + dyadic(rng, g.bits, g.range) * u) + dyadic(rng, g.bits, g.range) * v;
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

}  // namespace detail

/// The per-query random engine of query `index` of generator g under `seed`.
inline std::mt19937_64 query_rng(std::uint64_t seed, const Generator& g, std::uint64_t index) {
  const std::uint64_t tag = (static_cast<std::uint64_t>(g.family) << 8) |
                            static_cast<std::uint64_t>(g.type);
  return std::mt19937_64(mix64(mix64(seed ^ mix64(tag)) ^ index));
}

/// Query `index` of generator g under `seed`; `rng` continues the query's stream (for option
/// choices that must be reproducible with the query).
inline DoubleQuery generate(const Generator& g, std::uint64_t seed, std::uint64_t index,
                            std::mt19937_64& rng) {
  using namespace detail;
  rng = query_rng(seed, g, index);
  DoubleQuery q;
  q.type = g.type;
  bool exact = true;
  bool perturb = false;
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
        q.v[i + 4] = q.v[i] + Eigen::Vector3d(du(rng), du(rng), du(rng));
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
  }
  random_transform(rng, q.v, &exact);
  if (!exact) q.planted_time = std::numeric_limits<double>::quiet_NaN();
  if (perturb) {
    detail::perturb_ulps(rng, q.v);
    q.planted_time = std::numeric_limits<double>::quiet_NaN();
  }
  return q;
}

inline DoubleQuery generate(const Generator& g, std::uint64_t seed, std::uint64_t index) {
  std::mt19937_64 rng;
  return generate(g, seed, index, rng);
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

/// Tightest-pair comparison: same verdict and, when colliding, identical TOI doubles.
inline std::string check_tight(const CcdResult& d, const CcdResult& e) {
  if (d.collides != e.collides) return "verdict differs";
  if (d.collides && (d.toi_lo != e.toi_lo || d.toi_hi != e.toi_hi)) return "toi differs";
  if (!d.collides && (d.toi_lo != 0 || d.toi_hi != 0 || e.toi_lo != 0 || e.toi_hi != 0))
    return "toi not 0 without contact";
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

}  // namespace exactccd::test
