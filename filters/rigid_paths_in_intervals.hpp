// A rigid query's paths in interval arithmetic, for the rigid filters (contact and minimum
// separation): the power-of-two normalisation of its positions, the paths' coefficients, boxes
// enclosing the positions over a parameter interval, and the simplest separation of two
// primitives' boxes. Everything needs upward rounding (a RoundingGuard).
// PROOF: proofs/rigid_ccd.md#filters
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/predicates/rigid_paths.hpp"
#include "core/predicates/rigid_query.hpp"
#include "filters/certified_numbers.hpp"

namespace exactccd::filters::rigid {

using predicates::DoubleRigidQuery;
using predicates::DoubleSide;
using predicates::FixedPoly;
using predicates::Vec3;
using Boxes = std::array<Vec3<Interval>, 4>;

// ---------------------------------------------------------------------------------------------
// Power-of-two normalisation (PROOF: proofs/rigid_ccd.md#filters, step 0)

/// A largest |coordinate| in [2^-64, 2^65) is left as it is.
constexpr int kComfortableExponent = 64;

/// Calls f on every position-like vector of the query: the points at s = 0, the pivots and
/// translations of rigid sides, the end positions of linear ones. Scaling all of them by 2^k
/// scales every position x(s) by 2^k (the Cayley vectors are angles and stay).
template <class Query, class F>
void for_each_position(Query& q, F&& f) {
  for (auto& x : q.start) f(x);
  const int first = q.type == QueryType::vertex_face ? 1 : 2;
  for (int side = 0; side < 2; ++side) {
    auto& s = q.side[side];
    if (s.rigid) {
      f(s.motion.pivot);
      f(s.motion.translation);
    } else {
      for (int i = 0; i < (side == 0 ? first : 4 - first); ++i) f(s.end[i]);
    }
  }
}

/// The exponent k that brings the largest |coordinate| into [1/2, 1) when it lies outside the
/// comfortable range and every coordinate times 2^k is again a double (no bit lost); else 0.
inline int normalising_exponent(const DoubleRigidQuery& q) {
  double largest = 0;
  int lowest_bit = 1 << 20;  // the exponent of the lowest set bit of any coordinate
  for_each_position(q, [&](const Vec3<double>& x) {
    for (int k = 0; k < 3; ++k) {
      const double m = std::fabs(x[k]);
      if (m == 0) continue;
      largest = std::max(largest, m);
      int e;
      const double mantissa = std::frexp(m, &e);  // m = mantissa 2^e, mantissa in [1/2, 1)
      // mantissa 2^53 is an integer (exact); its trailing zeros lift the lowest bit.
      const auto integer = static_cast<std::uint64_t>(std::ldexp(mantissa, 53));
      lowest_bit = std::min(lowest_bit, e - 53 + __builtin_ctzll(integer));
    }
  });
  if (largest == 0) return 0;
  int e;
  std::frexp(largest, &e);
  if (std::abs(e - 1) <= kComfortableExponent) return 0;
  const int k = -e;
  return k > 0 || lowest_bit + k >= -1074 ? k : 0;
}

inline DoubleRigidQuery scaled(DoubleRigidQuery q, int k) {
  for_each_position(q, [k](Vec3<double>& x) {
    x = {std::ldexp(x.x, k), std::ldexp(x.y, k), std::ldexp(x.z, k)};
  });
  return q;
}

using IntervalPaths = predicates::RigidPaths<Interval>;

inline IntervalPaths interval_paths(const DoubleRigidQuery& q) {
  return predicates::rigid_paths<Interval>(q);
}

/// Boxes enclosing every position x(s) = X(s) / w(s), s in T (w >= 1 there).
inline Boxes positions_over(const IntervalPaths& paths, const Interval& T) {
  return paths.positions_at(T);
}

/// Lower bounds of the gap between the hulls of the two primitives' boxes on each axis
/// (negative where they overlap), the differences rounded down; false for a NaN bound
/// (overflow), which bounds nothing.
inline bool axis_gaps(const Boxes& x, int first, double (&gap)[3]) {
  for (int k = 0; k < 3; ++k) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 4; ++i) {
      const int side = i < first ? 0 : 1;
      const double l = x[i][k].inf(), h = x[i][k].sup();
      if (!(l <= h)) return false;
      lo[side] = std::min(lo[side], l);
      hi[side] = std::max(hi[side], h);
    }
    // Rounded down: the negated upward difference (the callers round upwards). Infinite bounds
    // give -infinity or NaN, which bound nothing (every comparison with NaN is false).
    gap[k] = std::max(-(hi[0] - lo[1]), -(hi[1] - lo[0]));
  }
  return true;
}

/// On some axis the hulls of the two primitives' boxes are more than delta apart (delta = 0:
/// disjoint; a difference of doubles rounded down is positive exactly when it is).
inline bool boxes_apart(const Boxes& x, int first, double delta = 0.0) {
  double gap[3];
  return axis_gaps(x, first, gap) && (gap[0] > delta || gap[1] > delta || gap[2] > delta);
}

}  // namespace exactccd::filters::rigid
