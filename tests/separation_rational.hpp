// A minimum-separation query over the rationals for the tests: its region polynomials
// (core/predicates/separation.hpp instantiated in mpq_class) evaluated exactly at a double
// time, the independent reference of the signs at doubles.
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <array>

#include "core/predicates/separation.hpp"

namespace exactccd::test {

/// Four moving vertices (vertex-face p, a, b, c or edge-edge a0, a1, b0, b1) and delta.
struct SeparationCase {
  std::array<Eigen::Vector3d, 4> t0, t1;
  double delta = 0;
};

/// Region polynomial `poly` at t over the rationals, from the separation predicates.
inline mpq_class rational_value(const SeparationCase& c, bool vertex_face, int poly, double t) {
  using P = predicates::FixedPoly<mpq_class, 0>;
  using Point = predicates::Vec3<P>;
  const mpq_class tq(t);
  Point x[4];
  for (int i = 0; i < 4; ++i) {
    P p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = P{{mpq_class(c.t0[i][k]) + tq * (mpq_class(c.t1[i][k]) - mpq_class(c.t0[i][k]))}};
    x[i] = Point{p[0], p[1], p[2]};
  }
  const mpq_class d2 = mpq_class(c.delta) * mpq_class(c.delta);
  mpq_class v;
  auto take = [&v](const auto& g) { v = g.c[0]; };
  if (vertex_face)
    predicates::vertex_face_separation(x[0], x[1], x[2], x[3], d2).for_each_polynomial(take, poly);
  else
    predicates::edge_edge_separation(x[0], x[1], x[2], x[3], d2).for_each_polynomial(take, poly);
  return v;
}

}  // namespace exactccd::test
