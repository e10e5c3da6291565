// Point-plane CCD as an instance of the one pipeline (dispatch.hpp): the polynomial
// f(t) = (p - o) . n of degree <= 2 (contact) or g = f^2 - delta^2 |n|^2 of degree <= 4
// (minimum separation). The filter is interval arithmetic on the polynomial over [0, t_max]:
// it certifies "no contact" when the polynomial keeps a certain sign there; everything else
// goes to the exact path (exact/reference/point_plane.cpp).
// PROOF: proofs/point_plane.md#reduction
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/float_only/float_only_ccd.hpp"
#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/fp_environment.hpp"
#include "core/predicates/interval.hpp"
#include "core/predicates/plane_offset.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exact/arithmetic/stack_dyadic.hpp"
#include "exact/polynomials/polynomial.hpp"
#include "exact/reference/point_plane.hpp"
#include "exactccd/ccd.hpp"
#include "pipeline/ccd_options_check.hpp"
#include "pipeline/dispatch.hpp"

namespace exactccd {

namespace pipeline {

namespace {

exact::PointPlanePoints rows_of(const PointPlaneQuery& q) {
  return {q.p_t0, q.origin_t0, q.normal_t0, q.p_t1, q.origin_t1, q.normal_t1};
}

struct PointPlane : WithoutExactStage<PointPlane, PointPlaneQuery> {
  using Query = PointPlaneQuery;

  static CcdResult exact(const Query& q, const CcdOptions& o) {
    return exact::point_plane_ccd_exact(rows_of(q), o);
  }
  /// The float polynomial's roots in doubles (min_separation: its roots compared with delta in
  /// doubles, the common practice). Uncertified.
  static CcdResult float_only(const Query& q, const CcdOptions& o) {
    const auto f = predicates::linear_plane_offset<double>(q);
    CcdResult r;
    r.decided_by = Stage::float_only;
    const auto distance_at = [&](double t) {
      const Eigen::Vector3d nt = (1 - t) * q.normal_t0 + t * q.normal_t1;
      const Eigen::Vector3d d = (1 - t) * (q.p_t0 - q.origin_t0) + t * (q.p_t1 - q.origin_t1);
      return std::abs(d.dot(nt)) / nt.norm();
    };
    double roots[3];
    const int count = float_only::cubic_roots({{f.c[0], f.c[1], f.c[2], 0.0}}, o.t_max, roots);
    for (int i = 0; i < count; ++i)
      if (o.min_separation == 0.0 || distance_at(roots[i]) <= o.min_separation) {
        r.collides = true;
        r.toi_lo = r.toi_hi = roots[i];
        break;
      }
    if (o.min_separation > 0.0 && distance_at(0.0) <= o.min_separation) {
      r.collides = true;
      r.toi_lo = r.toi_hi = 0.0;
    }
    return r;
  }
  /// No contact when the polynomial keeps a certain sign on [0, t_max] (contact: f != 0;
  /// within delta: g > 0), by interval arithmetic with upward rounding.
  static FilterOutcome filter(const Query& q, const CcdOptions& o, NoStage&) {
    const predicates::RoundingGuard upward;
    using predicates::Interval;
    const auto n = predicates::moving_point<Interval>(q.normal_t0, q.normal_t1);
    const auto f = predicates::linear_plane_offset<Interval>(q);
    FilterOutcome out;
    bool apart;
    if (o.min_separation == 0.0) {
      apart = predicates::certain_strict_sign(predicates::enclosure_over(f, 0.0, o.t_max)) != 0;
    } else {
      const Interval delta(o.min_separation);
      const predicates::FixedPoly<Interval, 0> delta2{{delta * delta}};
      apart = predicates::enclosure_over(f * f - delta2 * predicates::dot(n, n), 0.0, o.t_max)
                  .inf() > 0;
    }
    if (apart) {
      out.verdict = FilterOutcome::Verdict::no_contact;
      return out;
    }
    if (o.min_separation == 0.0) certify_single_crossing(q, f, o, &out);
    return out;
  }
  /// Contact, certified with its TOI, when f is certainly monotone on [0, t_max] (f' = c1 +
  /// 2 c2 t away from 0 there) and certainly of opposite signs at the two ends: its only root
  /// there is the earliest contact, bracketed by bisection on doubles down to the tightest pair
  /// (or toi_width). f's sign at each midpoint comes from intervals, or, where they cannot tell
  /// (within a few units in the last place of the root), from f's rational coefficients
  /// evaluated exactly at that double. PROOF: proofs/point_plane.md#filter
  static void certify_single_crossing(const Query& q,
                                      const predicates::FixedPoly<predicates::Interval, 2>& f,
                                      const CcdOptions& o, FilterOutcome* out) {
    using predicates::Interval;
    const auto value_at = [&](double t) { return f.c[0] + t * (f.c[1] + t * f.c[2]); };
    const Interval slope = f.c[1] + Interval(0.0, 2 * o.t_max) * f.c[2];
    const int s0 = predicates::certain_strict_sign(f.c[0]);
    if (s0 == 0 || predicates::certain_strict_sign(slope) == 0 ||
        predicates::certain_strict_sign(value_at(o.t_max)) != -s0)
      return;
    // Built on the first uncertain sign: f's exact coefficients on the stack (StackDyadic: no
    // heap), over the rationals only if those overflow.
    std::optional<predicates::FixedPoly<exact::StackDyadic, 2>> dyadic_f;
    std::optional<exact::Polynomial> exact_f;
    // f's sign at the double t: intervals first, f's exact coefficients where they cannot tell.
    const auto sign_at = [&](double t) {
      const int s = predicates::certain_strict_sign(value_at(t));
      if (s != 0) return s;
      out->exact_used = true;
      if (!dyadic_f) dyadic_f = predicates::linear_plane_offset<exact::StackDyadic>(q);
      const exact::StackDyadic T(t);
      const exact::StackDyadic v = dyadic_f->c[0] + T * (dyadic_f->c[1] + T * dyadic_f->c[2]);
      if (!v.overflow()) return v.sign();
      if (!exact_f) exact_f = exact_polynomial(q);
      return exact_f->sign_at(exact::Rational(t));
    };
    double lo = 0.0, hi = o.t_max;  // f has sign s0 at lo, -s0 at hi
    // A guess of the root (the coefficients' midpoints: a secant step, then Newton steps), and
    // a few units in the last place around it: when f's certified signs bracket the root there,
    // bisection starts from that bracket instead of [0, t_max] (a speed-up only: every bracket
    // is certified as in the bisection). PROOF: proofs/point_plane.md#filter
    {
      const auto mid = [](const Interval& x) { return 0.5 * (x.inf() + x.sup()); };
      const double m0 = mid(f.c[0]), m1 = mid(f.c[1]), m2 = mid(f.c[2]);
      const auto g_at = [&](double t) { return m0 + t * (m1 + t * m2); };
      double g = lo - g_at(lo) * (hi - lo) / (g_at(hi) - g_at(lo));
      for (int k = 0; k < 3; ++k) g -= g_at(g) / (m1 + 2 * m2 * g);
      double d = std::max(std::abs(g) * 0x1p-50, 0x1p-1060);
      for (int tries = 0; tries < 3 && std::isfinite(g); ++tries, d *= 0x1p12) {
        const double a = g - d, b = g + d;
        if (!(a > lo && b < hi)) break;
        const int sa = sign_at(a);
        if (sa == 0) {  // t* is this double
          lo = hi = a;
          break;
        }
        if (sa != s0) {  // the root is below a
          hi = a;
          continue;
        }
        lo = a;
        const int sb = sign_at(b);
        if (sb == 0) {
          lo = hi = b;
          break;
        }
        if (sb != s0) {
          hi = b;
          break;
        }
        lo = b;  // the root is above b
      }
    }
    while (lo < hi) {
      if (o.toi_width > 0.0 && hi - lo <= o.toi_width) break;
      double mid = lo + (hi - lo) / 2;  // upward rounding: in [lo, hi]
      if (mid <= lo || mid >= hi) {
        // Rounded onto an end: where the spacing of the doubles changes inside [lo, hi] (a
        // power of two) the midpoint can round onto hi with doubles still between them. Then
        // the double just above lo, unless lo and hi are consecutive (the tightest pair).
        mid = std::nextafter(lo, hi);
        if (mid >= hi) break;
      }
      const int s = sign_at(mid);
      if (s == 0) {  // t* is this double
        lo = hi = mid;
        break;
      }
      (s == s0 ? lo : hi) = mid;
    }
    out->verdict = FilterOutcome::Verdict::contact;
    out->toi_lo = lo;
    out->toi_hi = hi;
    out->toi_final = true;
  }
  /// f with the doubles' exact rational coefficients.
  static exact::Polynomial exact_polynomial(const Query& q) {
    return exact::Polynomial(predicates::linear_plane_offset<exact::Rational>(q));
  }
};

void require_finite(const Eigen::Vector3d& x, const char* name) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + name);
}

}  // namespace

}  // namespace pipeline

CcdResult point_plane_ccd(const PointPlaneQuery& q, const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  pipeline::require_finite(q.p_t0, "p_t0");
  pipeline::require_finite(q.origin_t0, "origin_t0");
  pipeline::require_finite(q.normal_t0, "normal_t0");
  pipeline::require_finite(q.p_t1, "p_t1");
  pipeline::require_finite(q.origin_t1, "origin_t1");
  pipeline::require_finite(q.normal_t1, "normal_t1");
  if (q.normal_t0.isZero(0.0))
    throw std::invalid_argument("exactccd: point_plane_ccd: normal_t0 is zero: no plane");
  if (q.normal_t1.isZero(0.0))
    throw std::invalid_argument("exactccd: point_plane_ccd: normal_t1 is zero: no plane");
  return pipeline::certified_ccd<pipeline::PointPlane>(q, options);
}

}  // namespace exactccd
