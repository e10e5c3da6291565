// The classic algorithm (Provot 1997; Redon, Kheddar and Coquillart 2002) in plain doubles:
// the coplanarity cubic's coefficients, its roots in [0, t_max] by bisection on monotone
// pieces, and the inclusion test at each root, earliest first. Nothing here is certified:
// rounding can move, create or lose roots and flip inclusion signs. It exists to be measured.
#include "core/float_only/float_only_ccd.hpp"

#include <algorithm>
#include <cmath>

#include "core/float_only/sign_change_bisection.hpp"
#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/inclusion.hpp"

namespace exactccd::float_only {

namespace {

using predicates::moving_point;
using predicates::FixedPoly;

int sign(double x) { return (x > 0) - (x < 0); }

}  // namespace

/// Roots of the cubic in [0, t_max], ascending (at most 3; an identically zero cubic gives
/// the two ends, the classic codes' usual answer).
int cubic_roots(const FixedPoly<double, 3>& f, double t_max, double roots[3]) {
  if (f.c[0] == 0 && f.c[1] == 0 && f.c[2] == 0 && f.c[3] == 0) {
    roots[0] = 0;
    roots[1] = t_max;
    return 2;
  }
  // Split [0, t_max] at the derivative's roots into monotone pieces.
  double breaks[4] = {0, 0, 0, 0};
  int nb = 0;
  breaks[nb++] = 0;
  const double a = 3 * f.c[3], b = 2 * f.c[2], c = f.c[1];
  double crit[2];
  int nc = 0;
  if (a != 0) {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q != 0) crit[nc++] = c / q;
      crit[nc++] = q / a;
    }
  } else if (b != 0) {
    crit[nc++] = -c / b;
  }
  std::sort(crit, crit + nc);
  for (int i = 0; i < nc; ++i)
    if (crit[i] > 0 && crit[i] < t_max) breaks[nb++] = crit[i];
  breaks[nb++] = t_max;

  int n = 0;
  for (int i = 0; i + 1 < nb; ++i) {
    const double lo = breaks[i], hi = breaks[i + 1];
    const double flo = predicates::evaluate(f, lo), fhi = predicates::evaluate(f, hi);
    if (flo == 0) {
      if (n == 0 || roots[n - 1] != lo) roots[n++] = lo;
      continue;
    }
    if (sign(flo) * sign(fhi) > 0 || fhi == 0) continue;  // a zero at hi is the next piece's lo
    if (n < 3) roots[n++] = bisect_sign_change(f, lo, hi, sign(flo));
  }
  if (n < 3 && predicates::evaluate(f, t_max) == 0 && (n == 0 || roots[n - 1] != t_max))
    roots[n++] = t_max;
  return n;
}

namespace {

template <class ContactAt>
CcdResult first_contact(const FixedPoly<double, 3>& f, double t_max, ContactAt&& contact_at) {
  CcdResult r;
  r.decided_by = Stage::float_only;
  double roots[3];
  const int n = cubic_roots(f, t_max, roots);
  for (int i = 0; i < n; ++i) {
    const double t = roots[i];
    if (contact_at([t](const auto& q) { return sign(predicates::evaluate(q, t)); })) {
      r.collides = true;
      r.toi_lo = r.toi_hi = t;
      return r;
    }
  }
  return r;
}

}  // namespace

CcdResult vertex_face_ccd(const VertexFaceQuery& q, const CcdOptions& options) {
  const auto p = moving_point<double>(q.p_t0, q.p_t1), a = moving_point<double>(q.a_t0, q.a_t1),
             b = moving_point<double>(q.b_t0, q.b_t1), c = moving_point<double>(q.c_t0, q.c_t1);
  return first_contact(predicates::vertex_face_coplanarity_cubic(p, a, b, c), options.t_max,
                       [&](auto&& sign_at) {
                         return predicates::point_in_triangle_at(p, a, b, c, sign_at);
                       });
}

CcdResult edge_edge_ccd(const EdgeEdgeQuery& q, const CcdOptions& options) {
  const auto a0 = moving_point<double>(q.ea0_t0, q.ea0_t1),
             a1 = moving_point<double>(q.ea1_t0, q.ea1_t1),
             b0 = moving_point<double>(q.eb0_t0, q.eb0_t1),
             b1 = moving_point<double>(q.eb1_t0, q.eb1_t1);
  return first_contact(
      predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1), options.t_max,
      [&](auto&& sign_at) { return predicates::segments_intersect_at(a0, a1, b0, b1, sign_at); });
}

}  // namespace exactccd::float_only
