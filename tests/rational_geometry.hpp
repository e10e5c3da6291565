// Exact rational vectors for the contact-geometry tests: the operations, and whether a double
// enclosure holds a rational value or a component of a unit vector (compared through squares,
// no rounding).
#pragma once

#include <gmpxx.h>

#include <type_traits>

#include "core/predicates/query_points.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd::test {

struct RationalVector {
  mpq_class x, y, z;
};

inline RationalVector minus(const RationalPoint& a, const RationalPoint& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline RationalVector cross(const RationalVector& a, const RationalVector& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline mpq_class dot(const RationalVector& a, const RationalVector& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

inline bool contains(const Enclosure& e, const mpq_class& x) {
  return mpq_class(e.lo) <= x && x <= mpq_class(e.hi);
}

inline mpq_class clamp01(const mpq_class& x) {
  return x < 0 ? mpq_class(0) : (x > 1 ? mpq_class(1) : x);
}

/// lo sqrt(N) <= v <= hi sqrt(N), exactly (N > 0): the unit vector's component v / sqrt(N) lies
/// in [lo, hi].
inline bool unit_component_in(const mpq_class& v, const mpq_class& N, const Enclosure& e) {
  const auto at_least = [&](double lo) {  // lo sqrt(N) <= v
    const mpq_class l(lo);
    if (l <= 0 && v >= 0) return true;
    if (l >= 0 && v < 0) return false;
    return l >= 0 ? l * l * N <= v * v : l * l * N >= v * v;
  };
  const auto at_most = [&](double hi) {  // v <= hi sqrt(N)
    const mpq_class h(hi);
    if (h >= 0 && v <= 0) return true;
    if (h <= 0 && v > 0) return false;
    return h >= 0 ? v * v <= h * h * N : v * v >= h * h * N;
  };
  return at_least(e.lo) && at_most(e.hi);
}

/// A double query (VertexFaceQuery or EdgeEdgeQuery) as the rational query of the same doubles.
template <class Query>
RationalQuery rational_query_of(const Query& q) {
  const predicates::QueryPoints rows = predicates::points_of(q);
  RationalQuery r{std::is_same_v<Query, VertexFaceQuery> ? QueryType::vertex_face
                                                         : QueryType::edge_edge,
                  {}};
  for (int i = 0; i < 8; ++i)
    r.points[i] = {mpq_class(rows[i]->x()), mpq_class(rows[i]->y()), mpq_class(rows[i]->z())};
  return r;
}

}  // namespace exactccd::test
