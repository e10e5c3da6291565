// Families of minimum-separation queries with a known answer for a given delta, for
// `exactccd generate --min-separation D` and the tests (proofs/min_separation.md for the
// semantics: a query comes within delta at the earliest t in [0, 1] where the Euclidean
// distance between the closed primitives is <= delta).
//
// Every member is built exactly in doubles, and its claim (within delta or not; the exact
// earliest time t*, a rational) follows from its construction (the proof is the comment above
// each builder in min_separation_families.cpp). Members come in groups: one boundary
// configuration, at distance exactly delta at t* (tangent to a vertex sphere, an edge capsule
// or the face's plane inside the triangle at an interior time; sliding at distance exactly
// delta over a face or along an edge; parallel edges at distance delta; degenerate primitives)
// and its near misses, the same query with the coordinates that realise the distance moved
// outward by one ulp and by 2^-k * 2^floor(log2 delta) (k in kNearMissExponents; 2^-k when
// delta = 0, the geometry's scale being 1 then); each construction proves that a move outward
// by ANY positive distance keeps the distance above delta at every time.
//
// Exactness: delta enters the coordinates only as delta * n / h for an integer vector n of
// integer length h (a coordinate axis, h = 1, for every delta; a Pythagorean direction such as
// (3, 4, 0) / 5 or (1, 2, 2) / 3 where delta / h is a dyadic number), added to coordinates that
// are 0 on the axes where n is non-zero, so any delta in the domain works, also one with 53
// significant bits. The geometry's size is 2^r times delta (r in 2..30, a random power of two
// per group); then the random frame of families.hpp (signed axis permutation, relabelled
// vertices or swapped and reversed edges, dyadic translation and common velocity: a rigid
// motion and a Galilean change of frame, which change no distance) where it lands on doubles,
// else the signed permutation alone.
//
// Deterministic: the members depend only on (seed, family name, per_family, delta).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "corpus/families.hpp"

namespace exactccd::families {

/// The smallest and largest positive delta the families accept (0 is accepted too): the
/// geometry spans 2^2 to 2^36 times delta and must stay within the normal doubles.
constexpr int kMinSeparationMinExponent = -900;
constexpr int kMinSeparationMaxExponent = 900;

/// The minimum-separation families, vertex-face then edge-edge ("ms_vf_vertex", ...).
const std::vector<std::string>& min_separation_family_names();
bool is_min_separation_family(const std::string& name);

/// Why `delta` cannot be the families' minimum separation (non-finite, negative, or a positive
/// value outside [2^kMinSeparationMinExponent, 2^kMinSeparationMaxExponent]); empty when it can.
std::string min_separation_delta_problem(double delta);

/// Family `name` for minimum separation `delta`: per_family members, claims for all of them;
/// the family's parameters record delta ("min_separation", and "min_separation_exact" as
/// "num/den"). Throws std::invalid_argument for an unknown name, a per_family outside
/// [kMinPerFamily, kMaxPerFamily] or a delta with a problem. Its first member is within delta
/// and its second is not.
Family generate_min_separation_family(const std::string& name, double delta, std::uint64_t seed,
                                      int per_family);
/// The named families (all of them when `names` is empty), in min_separation_family_names()
/// order; the same errors.
std::vector<Family> generate_min_separation_families(double delta, std::uint64_t seed,
                                                     int per_family,
                                                     const std::vector<std::string>& names = {});

}  // namespace exactccd::families
