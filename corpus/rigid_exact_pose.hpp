// Exact positions under a rigid motion, from the matrix form of the Cayley rotation (not from
// the polynomial expansion the library decides with): the independent reference of the tests,
// the demonstration's checks, and the exact end pose of `exactccd rigid`'s steps.
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <array>

#include "exactccd/rigid.hpp"

namespace exactccd::rigid_pose {

using RationalPosition = std::array<mpq_class, 3>;

inline RationalPosition exactly(const Eigen::Vector3d& v) {
  return {mpq_class(v.x()), mpq_class(v.y()), mpq_class(v.z())};
}

/// x(s) = c + s d + C(s q) (x0 - c) over the rationals, with
/// C(v) = ((1 - v.v) I + 2 v v^T + 2 [v]x) / (1 + v.v).
inline RationalPosition exact_position(const RigidMotion& m, const Eigen::Vector3d& x0,
                                       const mpq_class& s) {
  const RationalPosition c = exactly(m.pivot), d = exactly(m.translation), q = exactly(m.cayley),
                         x = exactly(x0);
  const RationalPosition v = {s * q[0], s * q[1], s * q[2]};
  const RationalPosition r = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  const mpq_class vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  mpq_class a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = (i == j ? 1 - vv : mpq_class(0)) + 2 * v[i] * v[j];
  // 2 [v]x, the cross-product matrix.
  a[0][1] -= 2 * v[2], a[0][2] += 2 * v[1];
  a[1][0] += 2 * v[2], a[1][2] -= 2 * v[0];
  a[2][0] -= 2 * v[1], a[2][1] += 2 * v[0];
  RationalPosition out;
  for (int i = 0; i < 3; ++i) {
    mpq_class rotated = 0;
    for (int j = 0; j < 3; ++j) rotated += a[i][j] * r[j];
    out[i] = c[i] + s * d[i] + rotated / (1 + vv);
  }
  return out;
}

}  // namespace exactccd::rigid_pose
