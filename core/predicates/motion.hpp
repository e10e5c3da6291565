// Polynomials in t of fixed degree over any number type, and 3-vectors of them.
//
// Every CCD predicate of exactccd is written once over these templates. Instantiated with
// a field NT (double, an interval type, exact rationals) a vertex's linear motion
// x(t) = x_t0 + t (x_t1 - x_t0) is a FixedPoly<NT, 1>, and products of coordinates give the
// coefficients of the coplanarity cubic and of the inclusion polynomials exactly as written.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds

namespace exactccd::predicates {

/// c[i] is the coefficient of t^i.
template <class NT, int D>
struct FixedPoly {
  static_assert(D >= 0, "degree must be non-negative");
  static constexpr int degree = D;
  std::array<NT, D + 1> c;
};

template <class NT, int D1, int D2>
EXACTCCD_CERTIFIED auto operator+(const FixedPoly<NT, D1>& a, const FixedPoly<NT, D2>& b) {
  constexpr int D = D1 > D2 ? D1 : D2;
  FixedPoly<NT, D> r{};
  for (int i = 0; i <= D; ++i) {
    if (i <= D1 && i <= D2) r.c[i] = a.c[i] + b.c[i];
    else if (i <= D1) r.c[i] = a.c[i];
    else r.c[i] = b.c[i];
  }
  return r;
}

template <class NT, int D1, int D2>
EXACTCCD_CERTIFIED auto operator-(const FixedPoly<NT, D1>& a, const FixedPoly<NT, D2>& b) {
  constexpr int D = D1 > D2 ? D1 : D2;
  FixedPoly<NT, D> r{};
  for (int i = 0; i <= D; ++i) {
    if (i <= D1 && i <= D2) r.c[i] = a.c[i] - b.c[i];
    else if (i <= D1) r.c[i] = a.c[i];
    else r.c[i] = -b.c[i];
  }
  return r;
}

template <class NT, int D1, int D2>
EXACTCCD_CERTIFIED
FixedPoly<NT, D1 + D2> operator*(const FixedPoly<NT, D1>& a, const FixedPoly<NT, D2>& b) {
  FixedPoly<NT, D1 + D2> r{};
  for (int k = 0; k <= D1 + D2; ++k) {
    // Sum the products in a fixed order: the filters' error analysis counts these terms.
    bool first = true;
    for (int i = 0; i <= D1; ++i) {
      const int j = k - i;
      if (j < 0 || j > D2) continue;
      if (first) {
        r.c[k] = a.c[i] * b.c[j];
        first = false;
      } else {
        r.c[k] = r.c[k] + a.c[i] * b.c[j];
      }
    }
  }
  return r;
}

/// Constants (degree 0: a number at one instant or over an interval, as the factored forms
/// of the minimum-separation search evaluate them): always inlined, where a call costs more
/// than the product itself.
template <class NT>
[[gnu::always_inline]] EXACTCCD_CERTIFIED FixedPoly<NT, 0> operator*(
    const FixedPoly<NT, 0>& a, const FixedPoly<NT, 0>& b) {
  return {{a.c[0] * b.c[0]}};
}

/// Horner evaluation at t (for an interval t: an enclosure of the range over t).
template <class NT, int D, class T>
EXACTCCD_CERTIFIED NT evaluate(const FixedPoly<NT, D>& p, const T& t) {
  NT r = p.c[D];
  for (int i = D - 1; i >= 0; --i) r = r * t + p.c[i];
  return r;
}

/// p'(t).
template <class NT, int D>
EXACTCCD_CERTIFIED FixedPoly<NT, (D > 0 ? D - 1 : 0)> derivative(const FixedPoly<NT, D>& p) {
  FixedPoly<NT, (D > 0 ? D - 1 : 0)> r{};
  if constexpr (D == 0) {
    r.c[0] = NT(0);
  } else {
    for (int i = 1; i <= D; ++i) r.c[i - 1] = p.c[i] * NT(i);
  }
  return r;
}

template <class T>
struct Vec3 {
  T x, y, z;
  const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <class A, class B>
EXACTCCD_CERTIFIED auto operator-(const Vec3<A>& a, const Vec3<B>& b) {
  return Vec3<decltype(a.x - b.x)>{a.x - b.x, a.y - b.y, a.z - b.z};
}

template <class A, class B>
EXACTCCD_CERTIFIED auto cross(const Vec3<A>& a, const Vec3<B>& b) {
  return Vec3<decltype(a.y * b.z - a.z * b.y)>{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                                              a.x * b.y - a.y * b.x};
}

template <class A, class B>
EXACTCCD_CERTIFIED auto dot(const Vec3<A>& a, const Vec3<B>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// The k-th component of cross(b - a, c - a): the orientation of (a, b, c) projected along
/// axis k, with the cyclic axis order (k+1, k+2) so that it equals the k-th normal component.
template <class T>
EXACTCCD_CERTIFIED
auto orient2d_along_axis(int k, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  return (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
}

/// x(t) = x0 + t (x1 - x0), coordinate-wise.
template <class NT>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 1>> linear_motion(const Vec3<NT>& x0, const Vec3<NT>& x1) {
  return {FixedPoly<NT, 1>{{x0.x, x1.x - x0.x}}, FixedPoly<NT, 1>{{x0.y, x1.y - x0.y}},
          FixedPoly<NT, 1>{{x0.z, x1.z - x0.z}}};
}

/// The linear path of a vertex given by its positions at t = 0 and t = 1 (any vector type with
/// operator[], e.g. Eigen::Vector3d), each coordinate converted to NT (exactly: double, an
/// interval of a double, an exact number).
template <class NT, class Vector>
EXACTCCD_CERTIFIED Vec3<FixedPoly<NT, 1>> moving_point(const Vector& x0, const Vector& x1) {
  return linear_motion(Vec3<NT>{NT(x0[0]), NT(x0[1]), NT(x0[2])},
                       Vec3<NT>{NT(x1[0]), NT(x1[1]), NT(x1[2])});
}

}  // namespace exactccd::predicates
