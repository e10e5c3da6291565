// Families of hard and degenerate CCD queries with a known answer, for `exactccd generate`, the
// shipped degenerate suite (tests/data/degenerate-suite) and the numerical-stability study.
//
// Every base family builds exact configurations from small dyadic numbers, so that the
// degeneracy (a contact on an edge, a double root, coplanar motion, a collinear triangle...)
// holds exactly in doubles, and knows each member's answer from the construction: the verdict
// and, when it collides, the exact first contact time t* (a rational such as 1/3, 2^-30 or 1).
// Members come in groups: one boundary configuration (it collides, at the constructed t*) and
// its near misses, the same query with a few coordinates moved outward by one ulp and by 2^-k
// for k in {10, 20, 30, 40, 52}; each family's construction proves (comment at its builder)
// that a move outward by ANY positive distance misses, so no near miss depends on luck.
// A random frame (signed permutation of the axes, relabelled vertices or swapped and reversed
// edges, a small dyadic translation and a common velocity) is applied before the moves; it is
// exact and changes neither verdict nor t*.
//
// Variant families `<base>@s<scale>` and `<base>@t<offset>` multiply every coordinate of the
// base members by scale (1e-12, 1e-6, 1e6, 1e12) or add offset (1e4, 1e8) to it, in double
// arithmetic: the input rounding is part of the case and their truth is whatever the exact
// path says about the rounded doubles (members carry no claim).
//
// Variant families `<base>@p2^<k>` multiply every coordinate by 2^k, k in {-1000, -300, -100,
// 100, 300, 1000}. Scaling space by 2^k > 0 maps every trajectory onto the scaled one at the
// same times, so it changes neither the verdict nor t*; where every product is a double (no
// overflow, no bit lost below 2^-1074) the member is exactly that scaled query and keeps its
// base member's claim. A member with an inexact product carries no claim (an overflowing
// product is replaced by +-DBL_MAX, an underflowing one rounded to nearest).
//
// Random families (`vf_wide_exponent_100`, ..., `ee_huge_triangle_subnormal_motion`) are
// seeded random queries with widely spread exponents, without a construction and without a
// claim: their truth is the exact path's. They have no variants (their coordinates already span
// the exponent range; scaling them would overflow or round).
//
// Deterministic: the members of a family depend only on (seed, family name, per_family), not on
// which other families are generated, and only IEEE operations and mt19937_64 are used.
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::families {

/// Benchmark row order: vertex-face p, a, b, c at t = 0, then at t = 1; edge-edge ea0, ea1,
/// eb0, eb1 at t = 0, then at t = 1.
using QueryPoints = std::array<Eigen::Vector3d, 8>;

/// One coordinate of a query: row 0-7 (benchmark order), axis 0-2 (x, y, z).
struct Coordinate {
  int row = 0;
  int axis = 0;
};

struct Member {
  QueryPoints points;
  /// "contact" (the boundary configuration), "1ulp" or "2^-k" (its near misses); in a variant
  /// family, the label of the base member it rounds.
  std::string label;
  /// The construction's sub-kind (e.g. "edge", "vertex", "face", "coplanar-touch").
  std::string kind;

  /// The construction's claim; base families make one (claim_known), and power-of-two variants
  /// keep it where the scaling is exact.
  bool claim_known = false;
  bool collides = false;
  mpq_class toi;  ///< the exact first contact time t*, when collides

  /// Near misses: the index in the family of the colliding member this one was moved from; the
  /// coordinates that differ from it, each moved by exactly `distance` in `direction` (+1/-1).
  int partner = -1;
  std::vector<Coordinate> moved;
  std::vector<int> direction;
  /// The distance each moved coordinate moved: for "1ulp" the largest of the moved
  /// coordinates' one-ulp steps outward; for "2^-k" max(2^-k, that step), doubled while some
  /// moved coordinate would not land on a double (it never needs to in the shipped suite).
  double distance = 0.0;
  int distance_log2 = 0;  ///< k of a "2^-k" member; 0 for "1ulp" and the others

  /// Variant families: the index of the base family's member this one rounds (or scales).
  int source = -1;
  /// Power-of-two variants: every coordinate is the base member's times 2^k exactly.
  bool exact_scaling = false;
};

struct Family {
  std::string name;  ///< e.g. "vf_interior", "vf_interior@s1e-12", "vf_interior@p2^-1000"
  std::string base;  ///< the base family's name (== name for a base or random family)
  QueryType type = QueryType::vertex_face;
  double scale = 1.0;   ///< variants: every coordinate multiplied by scale (2^k: exactly) ...
  double offset = 0.0;  ///< ... or offset added to it
  std::string description;
  nlohmann::json parameters = nlohmann::json::object();
  std::vector<Member> members;

  bool is_variant() const { return name != base; }
};

/// A scaled or translated copy of a base family.
struct Variant {
  const char* suffix;  ///< "@s1e-12", ..., "@t1e8", "@p2^-1000", ..., "@p2^1000"
  double scale;
  double offset;
  /// scale is 2^power_of_two exactly (power-of-two variants keep exact members' claims); 0 for
  /// the rounded scalings and translations.
  int power_of_two = 0;
};

/// The near misses' requested offsets 2^-k (besides the one-ulp move).
constexpr std::array<int, 5> kNearMissExponents = {10, 20, 30, 40, 52};

/// Members per family of `exactccd generate` and of the shipped suite.
constexpr int kDefaultPerFamily = 14;
/// Bounds of --per-family.
constexpr int kMinPerFamily = 2;
constexpr int kMaxPerFamily = 100000;

/// The base families (constructions with claims), vertex-face then edge-edge.
const std::vector<std::string>& base_family_names();
/// The random families (no claims, no variants), vertex-face then edge-edge.
const std::vector<std::string>& random_family_names();
bool is_random_family(const std::string& name);
/// The variants applied to every base family (scales 1e-12, 1e-6, 1e6, 1e12; offsets 1e4, 1e8;
/// then the powers of two 2^-1000, 2^-300, 2^-100, 2^100, 2^300, 2^1000).
const std::vector<Variant>& variants();
/// Every family: the base families, the random families, then for each variant every base
/// family with it.
std::vector<std::string> all_family_names();
bool is_family_name(const std::string& name);
/// The base of a family name ("vf_interior@s1e-6" -> "vf_interior"; a base or random family
/// is its own); empty if not a family.
std::string base_of(const std::string& name);

/// Base family `base` (throws std::invalid_argument for an unknown name or a per_family out of
/// [kMinPerFamily, kMaxPerFamily]). Its first member collides and its second does not.
Family generate_base_family(const std::string& base, std::uint64_t seed, int per_family);
/// Random family `name` (same errors): per_family seeded random queries, no claims.
Family generate_random_family(const std::string& name, std::uint64_t seed, int per_family);
/// The variant of a base family: rounded members without claims, or (power of two) members
/// scaled by 2^k that keep their claims where the scaling is exact.
Family make_variant(const Family& base, const Variant& variant);
/// The named families (all of them when `names` is empty), in all_family_names() order.
std::vector<Family> generate_families(std::uint64_t seed, int per_family,
                                      const std::vector<std::string>& names = {});

}  // namespace exactccd::families
