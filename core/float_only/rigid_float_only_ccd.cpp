// Mode::float_only for rigid queries (see rigid_float_only_ccd.hpp): the rigid coplanarity
// polynomial, its roots and the inclusion test, all in plain doubles. Nothing here is
// certified; it exists to be measured against the exact path.
#include "core/float_only/rigid_float_only_ccd.hpp"

#include <array>

#include "core/float_only/sign_change_bisection.hpp"
#include "core/predicates/inclusion.hpp"
#include "core/predicates/rigid_coplanarity.hpp"
#include "core/predicates/rigid_paths.hpp"
#include "core/predicates/separation.hpp"

namespace exactccd::float_only {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;

int sign(double x) { return (x > 0) - (x < 0); }

template <int D>
bool is_zero(const FixedPoly<double, D>& f) {
  for (const double c : f.c)
    if (c != 0) return false;
  return true;
}

/// The roots of f in [lo, hi], ascending, at most D (see polynomial_roots). f is not the zero
/// polynomial.
template <int D>
int roots_on(const FixedPoly<double, D>& f, double lo, double hi, double* roots) {
  static_assert(D >= 1, "a constant has no isolated roots");
  // [lo, hi] split at the derivative's roots into pieces on which f is (numerically) monotone.
  double breaks[D + 1];
  int nb = 0;
  breaks[nb++] = lo;
  if constexpr (D >= 2) {
    const auto df = predicates::derivative(f);
    if (!is_zero(df)) {
      double critical[D - 1];
      const int nc = roots_on(df, lo, hi, critical);
      for (int i = 0; i < nc; ++i)
        if (critical[i] > breaks[nb - 1] && critical[i] < hi) breaks[nb++] = critical[i];
    }
  }
  breaks[nb++] = hi;

  int n = 0;
  double last = 0.0;  // roots[n - 1] when n > 0
  const auto add = [&](double t) {
    if (n < D && (n == 0 || last != t)) roots[n++] = last = t;
  };
  for (int i = 0; i + 1 < nb; ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    const double fa = predicates::evaluate(f, a);
    if (fa == 0) {
      add(a);
      continue;
    }
    const int sa = sign(fa);  // 0 for NaN: no root is looked for
    if (sa == 0 || sign(predicates::evaluate(f, b)) != -sa) continue;  // a zero at b: next piece
    add(bisect_sign_change(f, a, b, sa));
  }
  if (predicates::evaluate(f, hi) == 0) add(hi);
  return n;
}

using predicates::DoubleSide;

using Paths = predicates::RigidPaths<double>;

/// The contact test at one parameter: the inclusion test on the positions there, signs of
/// doubles (given that the four points are coplanar there, which only g's root says).
bool contact_at(QueryType type, const Paths& paths, double s) {
  const std::array<Vec3<double>, 4> x = paths.positions_at(s);
  const auto sign_at = [](double v) { return sign(v); };
  return type == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

/// Within delta at s: the region polynomials' signs on the positions there, all in doubles.
template <class Separation>
bool within_at(const Paths& paths, double delta2, double s) {
  using Point = Vec3<FixedPoly<double, 0>>;
  const std::array<Vec3<double>, 4> x = paths.positions_at(s);
  auto point = [&x](int i) { return Point{{{x[i].x}}, {{x[i].y}}, {{x[i].z}}}; };
  double value[Separation::kCount];
  int n = 0;
  Separation{point(0), point(1), point(2), point(3), delta2}.for_each_polynomial(
      [&](const auto& g) { value[n++] = g.c[0]; });
  return Separation::within([&value](int k) { return sign(value[k]); });
}

/// Samples of the coplanar-throughout case and of minimum separation.
constexpr int kSamples = 64;

/// The first s in [0, t_max] at which holds(s): the first of kSamples + 1 equally spaced
/// parameters at which it holds, then bisection between it and the sample before (which fails).
template <class Holds>
CcdResult first_sampled(Holds&& holds, double t_max) {
  CcdResult r;
  r.decided_by = Stage::float_only;
  double before = 0.0;
  for (int j = 0; j <= kSamples; ++j) {
    const double s = j == kSamples ? t_max : t_max * (static_cast<double>(j) / kSamples);
    if (!holds(s)) {
      before = s;
      continue;
    }
    double lo = before, hi = s;
    for (int it = 0; j > 0 && it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (holds(mid) ? hi : lo) = mid;
    }
    r.collides = true;
    r.toi_lo = r.toi_hi = hi;
    return r;
  }
  return r;
}

}  // namespace

int polynomial_roots(const FixedPoly<double, 5>& g, double t_max, double roots[5]) {
  if (is_zero(g)) return 0;
  return roots_on(g, 0.0, t_max, roots);
}

CcdResult rigid_ccd(const predicates::DoubleRigidQuery& q, const CcdOptions& options) {
  const QueryType type = q.type;
  const std::array<Vec3<double>, 4>& start = q.start;
  const DoubleSide &first = q.side[0], &second = q.side[1];
  const double t_max = options.t_max;
  CcdResult r;
  r.decided_by = Stage::float_only;
  const Paths paths = predicates::rigid_paths<double>(q);
  if (options.min_separation > 0) {  // the distance sampled: the common practice
    using predicates::EdgeEdgeSeparation;
    using predicates::VertexFaceSeparation;
    using Point = Vec3<FixedPoly<double, 0>>;
    const double delta2 = options.min_separation * options.min_separation;
    return type == QueryType::vertex_face
               ? first_sampled(
                     [&](double s) {
                       return within_at<VertexFaceSeparation<Point, double>>(paths, delta2, s);
                     },
                     t_max)
               : first_sampled(
                     [&](double s) {
                       return within_at<EdgeEdgeSeparation<Point, double>>(paths, delta2, s);
                     },
                     t_max);
  }
  const FixedPoly<double, 5> g =
      type == QueryType::vertex_face
          ? predicates::vertex_face_rigid_coplanarity<double>(start[0], start[1], start[2],
                                                              start[3], first, second)
          : predicates::edge_edge_rigid_coplanarity<double>(start[0], start[1], start[2],
                                                            start[3], first, second);
  const auto found = [&r](double s) {
    r.collides = true;
    r.toi_lo = r.toi_hi = s;
    return r;
  };
  if (is_zero(g))  // coplanar throughout: contact wherever the inclusion test passes
    return first_sampled([&](double s) { return contact_at(type, paths, s); }, t_max);
  double roots[5];
  const int n = polynomial_roots(g, t_max, roots);
  for (int i = 0; i < n; ++i)
    if (contact_at(type, paths, roots[i])) return found(roots[i]);
  return r;
}

}  // namespace exactccd::float_only
