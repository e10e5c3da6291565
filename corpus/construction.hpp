// The exact construction toolkit of the families (families.cpp, min_separation_families.cpp):
// seeded random numbers whose output is fixed by the C++ standard, exact rational vectors, the
// canonical construction (rows, t*, the near misses' outward moves), the random frame (signed
// axis permutation, relabelled vertices, dyadic translation and common velocity) that places it
// in doubles exactly or not at all, and the near misses' exact moves. Internal to the corpus.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/predicates/motion.hpp"
#include "corpus/families.hpp"

namespace exactccd::families::construction {

using Q = mpq_class;
using P3 = std::array<Q, 3>;

// ---------------------------------------------------------------------------------------------
// Random numbers: mt19937_64 (its output is fixed by the C++ standard) and modulo reduction
// (not the standard distributions, whose output differs between standard libraries).

// Draws happen in statement order: never two draws among the arguments of one function call
// (their order is unspecified in C++); braced lists and separate declarators are ordered.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  long uniform(long lo, long hi) {
    const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<long>(engine_() % span);
  }
  bool coin() { return (engine_() >> 17) & 1u; }
  /// 64 random bits.
  std::uint64_t bits() { return engine_(); }
  int sign() { return coin() ? 1 : -1; }
  /// k / den, k uniform in [lo, hi].
  Q dyadic(long lo, long hi, long den) {
    Q q(uniform(lo, hi), den);
    q.canonicalize();
    return q;
  }
  Q nonzero_dyadic(long lo, long hi, long den) {
    for (;;) {
      Q q = dyadic(lo, hi, den);
      if (sgn(q) != 0) return q;
    }
  }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(uniform(0, static_cast<long>(v.size()) - 1))];
  }

 private:
  std::mt19937_64 engine_;
};

inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

inline std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

// ---------------------------------------------------------------------------------------------
// Exact vectors

inline Q canon(Q q) {
  q.canonicalize();
  return q;
}
/// n / d in lowest terms (GMP compares only canonical fractions correctly).
inline Q frac(long n, long d) { return canon(Q(n, d)); }
inline P3 p3(const Q& x, const Q& y, const Q& z) { return {canon(x), canon(y), canon(z)}; }
inline P3 operator+(const P3& a, const P3& b) { return p3(a[0] + b[0], a[1] + b[1], a[2] + b[2]); }
inline P3 operator-(const P3& a, const P3& b) { return p3(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
inline P3 operator*(const Q& s, const P3& a) { return p3(s * a[0], s * a[1], s * a[2]); }
// The geometry is the predicates' (core/predicates/motion.hpp), over exact rationals held as
// polynomials of degree 0: their operations evaluate each GMP expression at once (a gmpxx
// expression returned by `auto` would refer to temporaries that are gone).
using Constant = predicates::FixedPoly<Q, 0>;
inline predicates::Vec3<Constant> vec(const P3& a) {
  return {Constant{{a[0]}}, Constant{{a[1]}}, Constant{{a[2]}}};
}
inline Q dot(const P3& a, const P3& b) { return canon(predicates::dot(vec(a), vec(b)).c[0]); }
inline P3 cross(const P3& a, const P3& b) {
  const predicates::Vec3<Constant> c = predicates::cross(vec(a), vec(b));
  return p3(c.x.c[0], c.y.c[0], c.z.c[0]);
}
inline Q det3(const P3& a, const P3& b, const P3& c) { return dot(a, cross(b, c)); }
/// 2D orientation of (a, b, c) in the xy plane.
inline Q orient2(const P3& a, const P3& b, const P3& c) {
  return canon(predicates::orient2d_along_axis(2, vec(a), vec(b), vec(c)).c[0]);
}
inline P3 zero3() { return p3(0, 0, 0); }

inline Q pow2(int e) {
  Q r(1);
  if (e >= 0)
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(e));
  else
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<unsigned long>(-e));
  return r;
}

/// n / 2^floor(log2 n) for tc = m/n: velocities unit(tc) * w put every vertex on a dyadic
/// point at t = 0 and t = 1 (tc * unit * w = m w / 2^floor(log2 n)).
inline Q unit(const Q& tc) {
  const mpz_class& n = tc.get_den();
  const std::size_t bits = mpz_sizeinbase(n.get_mpz_t(), 2);
  return canon(Q(n) / pow2(static_cast<int>(bits) - 1));
}

/// Interior contact times: simple fractions, non-dyadic ones (whose TOI is a pair of doubles
/// around t*), and times very close to 0 and to 1.
inline Q interior_time(Rng& r) {
  static const std::vector<std::string> kTimes = {
      "1/2", "1/3",  "2/3",  "1/4", "3/4",    "1/5",          "2/5",
      "3/7", "5/8",  "7/16", "5/6", "1/1024", "1/1073741824", "1048575/1048576",
      "1/7", "9/10", "11/12"};
  return Q(r.pick(kTimes));
}

/// A contact time in [0, 1]: the ends included.
inline Q any_time(Rng& r) {
  const long k = r.uniform(0, 5);
  if (k == 0) return Q(0);
  if (k == 1) return Q(1);
  return interior_time(r);
}

inline P3 random_vector(Rng& r, long den = 8) {
  return P3{r.dyadic(-8, 8, den), r.dyadic(-8, 8, den), r.dyadic(-8, 8, den)};
}

// ---------------------------------------------------------------------------------------------
// Constructions

/// A canonical outward move: coordinate (row, axis) moved by sign * delta.
struct Move {
  int row, axis, sign;
};

struct Construction {
  std::array<P3, 8> rows;
  Q toi;                    // the constructed first contact time (the configuration collides)
  std::vector<Move> moves;  // the near misses' outward moves (all coordinates by one delta)
  std::string kind;
};

/// Vertex `row` (0-3) at position `at_tc` at time tc, moving with velocity v.
inline void set_motion(Construction& c, int row, const P3& at_tc, const P3& v, const Q& tc) {
  c.rows[row] = at_tc - tc * v;
  c.rows[row + 4] = at_tc + canon(1 - tc) * v;
}
inline void set_static(Construction& c, int row, const P3& at) {
  c.rows[row] = c.rows[row + 4] = at;
}

/// Throws std::invalid_argument unless per_family lies in [kMinPerFamily, kMaxPerFamily].
inline void check_per_family(int per_family) {
  if (per_family < kMinPerFamily || per_family > kMaxPerFamily)
    throw std::invalid_argument("per_family must lie in [" + std::to_string(kMinPerFamily) + ", " +
                                std::to_string(kMaxPerFamily) + "]");
}

// ---------------------------------------------------------------------------------------------
// The random frame: exact, verdict- and t*-preserving.

struct Frame {
  std::array<int, 3> axis_from;  // new axis i holds old axis axis_from[i] ...
  std::array<int, 3> sign;       // ... times sign[i]
  std::array<int, 8> row_to;     // old row r goes to new row row_to[r]
  P3 translation, velocity;      // added at both times / added at t = 1
};

inline Frame random_frame(Rng& r, QueryType type) {
  Frame f;
  f.axis_from = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(f.axis_from[i], f.axis_from[r.uniform(0, i)]);
  for (int& s : f.sign) s = r.sign();
  if (type == QueryType::vertex_face) {
    std::array<int, 3> perm = {1, 2, 3};
    for (int i = 2; i > 0; --i) std::swap(perm[i], perm[r.uniform(0, i)]);
    f.row_to = {0, perm[0], perm[1], perm[2], 4, perm[0] + 4, perm[1] + 4, perm[2] + 4};
  } else {
    const bool swap = r.coin(), reverse_a = r.coin(), reverse_b = r.coin();
    const int base_a = swap ? 2 : 0, base_b = swap ? 0 : 2;
    const std::array<int, 4> to = {base_a + (reverse_a ? 1 : 0), base_a + (reverse_a ? 0 : 1),
                                   base_b + (reverse_b ? 1 : 0), base_b + (reverse_b ? 0 : 1)};
    for (int i = 0; i < 4; ++i) f.row_to[i] = to[i], f.row_to[i + 4] = to[i] + 4;
  }
  // A zero translation component now and then, so that some coordinates stay 0 (their
  // one-ulp neighbour is the smallest subnormal).
  for (int i = 0; i < 3; ++i) {
    f.translation[i] = r.uniform(0, 3) == 0 ? Q(0) : r.dyadic(-12, 12, 16);
    f.velocity[i] = r.uniform(0, 3) == 0 ? Q(0) : r.dyadic(-8, 8, 8);
  }
  return f;
}

struct Placed {
  QueryPoints points;
  std::vector<Coordinate> moved;
  std::vector<int> direction;
};

/// The construction in the frame, as doubles; nullopt when a coordinate is not a double.
inline std::optional<Placed> place(const Construction& c, const Frame& f) {
  Placed out;
  std::array<int, 3> axis_to{};
  for (int i = 0; i < 3; ++i) axis_to[f.axis_from[i]] = i;
  for (int r = 0; r < 8; ++r) {
    for (int i = 0; i < 3; ++i) {
      Q v = f.sign[i] * c.rows[r][f.axis_from[i]] + f.translation[i];
      if (r >= 4) v += f.velocity[i];
      v.canonicalize();
      const double d = v.get_d();
      if (Q(d) != v) return std::nullopt;
      out.points[f.row_to[r]][i] = d;
    }
  }
  for (const Move& m : c.moves) {
    const int axis = axis_to[m.axis];
    out.moved.push_back({f.row_to[m.row], axis});
    out.direction.push_back(f.sign[axis] * m.sign);
  }
  return out;
}

/// Moves every listed coordinate by exactly `distance` outward; false if one does not land on
/// a double.
inline bool move_exactly(QueryPoints& p, const std::vector<Coordinate>& moved,
                  const std::vector<int>& direction, double distance) {
  for (std::size_t i = 0; i < moved.size(); ++i) {
    double& x = p[moved[i].row][moved[i].axis];
    const double y = x + direction[i] * distance;
    if (!std::isfinite(y) || Q(y) != Q(x) + direction[i] * Q(distance)) return false;
    x = y;
  }
  return true;
}

/// The near miss of `contact` at requested offset offset_unit * 2^-k (k = 0: one ulp).
inline Member near_miss(const Member& contact, int partner, const Placed& placed, int k,
                         double offset_unit = 1.0) {
  double step = 0;
  for (std::size_t i = 0; i < placed.moved.size(); ++i) {
    const double x = contact.points[placed.moved[i].row][placed.moved[i].axis];
    const double to = placed.direction[i] > 0 ? std::numeric_limits<double>::infinity()
                                              : -std::numeric_limits<double>::infinity();
    step = std::max(step, std::abs(std::nextafter(x, to) - x));
  }
  double distance = k == 0 ? step : std::max(step, std::ldexp(offset_unit, -k));
  Member m;
  for (;;) {
    m.points = contact.points;
    if (move_exactly(m.points, placed.moved, placed.direction, distance)) break;
    distance *= 2;
  }
  m.label = k == 0 ? "1ulp" : "2^-" + std::to_string(k);
  m.kind = contact.kind;
  m.claim_known = true;
  m.collides = false;
  m.partner = partner;
  m.moved = placed.moved;
  m.direction = placed.direction;
  m.distance = distance;
  m.distance_log2 = k;
  return m;
}

}  // namespace exactccd::families::construction
