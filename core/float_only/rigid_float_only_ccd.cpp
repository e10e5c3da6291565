// Mode::float_only for rigid queries (see rigid_float_only_ccd.hpp): the rigid coplanarity
// polynomial, its roots and the inclusion test, all in plain doubles. Nothing here is
// certified; it exists to be measured against the exact path.
#include "core/float_only/rigid_float_only_ccd.hpp"

#include <array>

#include "core/float_only/sign_change_bisection.hpp"
#include "core/predicates/inclusion.hpp"
#include "core/predicates/rigid_coplanarity.hpp"

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

/// The four points' paths x(s) = X(s) / w(s) in doubles (w = 1 on a linear side).
class Paths {
 public:
  Paths(const std::array<Vec3<double>, 4>& start, const DoubleSide& first,
        const DoubleSide& second, int first_count)
      : first_count_(first_count) {
    for (int i = 0; i < 4; ++i) {
      const bool on_first = i < first_count;
      const DoubleSide& side = on_first ? first : second;
      const int index = on_first ? i : i - first_count;
      numerator_[i] = side.rigid ? predicates::rigid_path_numerator(side.motion, start[i])
                                 : predicates::linear_path_numerator(start[i], side.end[index]);
    }
    denominator_[0] = denominator_of(first);
    denominator_[1] = denominator_of(second);
  }

  /// The four positions at s, rounded.
  std::array<Vec3<double>, 4> at(double s) const {
    const double w[2] = {predicates::evaluate(denominator_[0], s),
                         predicates::evaluate(denominator_[1], s)};
    std::array<Vec3<double>, 4> x;
    for (int i = 0; i < 4; ++i) {
      const double d = w[i < first_count_ ? 0 : 1];
      const auto& X = numerator_[i];
      x[i] = {predicates::evaluate(X.x, s) / d, predicates::evaluate(X.y, s) / d,
              predicates::evaluate(X.z, s) / d};
    }
    return x;
  }

 private:
  static FixedPoly<double, 2> denominator_of(const DoubleSide& side) {
    return side.rigid ? predicates::rigid_path_denominator(side.motion)
                      : FixedPoly<double, 2>{{1.0, 0.0, 0.0}};
  }

  int first_count_;
  std::array<Vec3<FixedPoly<double, 3>>, 4> numerator_;
  std::array<FixedPoly<double, 2>, 2> denominator_;
};

/// The contact test at one parameter: the inclusion test on the positions there, signs of
/// doubles (given that the four points are coplanar there, which only g's root says).
bool contact_at(QueryType type, const Paths& paths, double s) {
  const std::array<Vec3<double>, 4> x = paths.at(s);
  const auto sign_at = [](double v) { return sign(v); };
  return type == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

/// Samples of the coplanar-throughout case (g identically zero in doubles).
constexpr int kSamples = 64;

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
  const int first_count = type == QueryType::vertex_face ? 1 : 2;
  const Paths paths(start, first, second, first_count);
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
  if (is_zero(g)) {
    // Coplanar throughout: contact wherever the inclusion test passes. The first sample that
    // passes, then bisection between it and the sample before (which fails).
    double before = 0.0;
    for (int j = 0; j <= kSamples; ++j) {
      const double s = j == kSamples ? t_max : t_max * (static_cast<double>(j) / kSamples);
      if (!contact_at(type, paths, s)) {
        before = s;
        continue;
      }
      if (j == 0) return found(s);
      double lo = before, hi = s;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (contact_at(type, paths, mid) ? hi : lo) = mid;
      }
      return found(hi);
    }
    return r;
  }
  double roots[5];
  const int n = polynomial_roots(g, t_max, roots);
  for (int i = 0; i < n; ++i)
    if (contact_at(type, paths, roots[i])) return found(roots[i]);
  return r;
}

}  // namespace exactccd::float_only
