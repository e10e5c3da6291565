// The public entry points of rigid-body CCD: input validation, the filters, the exact path, and
// the contact time of pure rotations. PROOF: proofs/rigid_ccd.md
#include "exactccd/rigid.hpp"

#include <mpfr.h>

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/predicates/fp_environment.hpp"
#include "core/src/ccd_options_check.hpp"
#include "exact/rigid_ccd.hpp"
#include "filters/rigid_filter.hpp"

namespace exactccd {

namespace {

using predicates::Vec3;

class RoundToNearest : predicates::FpEnvironmentGuard {
 public:
  RoundToNearest() noexcept : FpEnvironmentGuard(predicates::Rounding::to_nearest) {}
};

Vec3<double> checked(const Eigen::Vector3d& x, const char* name) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + name);
  return {x.x(), x.y(), x.z()};
}

Vec3<exact::Rational> rational(const Vec3<double>& x) {
  return {exact::Rational(x.x), exact::Rational(x.y), exact::Rational(x.z)};
}

/// Both forms of one query: doubles for the filters, rationals (the same values) for the exact
/// path; built once, after every input was checked to be finite.
struct CheckedQuery {
  filters::DoubleRigidQuery doubles;
  exact::RationalRigidQuery rationals;
};

void add_side(const SideMotion& side, int vertices, const char* name, CheckedQuery* q,
              int index) {
  filters::DoubleSide& d = q->doubles.side[index];
  exact::RationalSide& r = q->rationals.side[index];
  d.rigid = r.rigid = side.kind == PathKind::rigid;
  const std::string n(name);
  if (d.rigid) {
    d.motion = {checked(side.rigid.pivot, (n + ".rigid.pivot").c_str()),
                checked(side.rigid.translation, (n + ".rigid.translation").c_str()),
                checked(side.rigid.cayley, (n + ".rigid.cayley").c_str())};
    r.motion = {rational(d.motion.pivot), rational(d.motion.translation),
                rational(d.motion.cayley)};
  } else {
    if (side.kind != PathKind::linear)
      throw std::invalid_argument("exactccd: unknown PathKind in " + n);
    for (int i = 0; i < vertices; ++i) {
      d.end[i] = checked(side.linear_end[i], (n + ".linear_end").c_str());
      r.end[i] = rational(d.end[i]);
    }
  }
}

void set_start(CheckedQuery* q, int i, const Eigen::Vector3d& x, const char* name) {
  q->doubles.start[i] = checked(x, name);
  q->rationals.start[i] = rational(q->doubles.start[i]);
}

CheckedQuery checked_query(const RigidVertexFaceQuery& query) {
  CheckedQuery q;
  q.doubles.type = q.rationals.type = QueryType::vertex_face;
  set_start(&q, 0, query.p, "p");
  set_start(&q, 1, query.a, "a");
  set_start(&q, 2, query.b, "b");
  set_start(&q, 3, query.c, "c");
  add_side(query.vertex, 1, "vertex", &q, 0);
  add_side(query.face, 3, "face", &q, 1);
  return q;
}

CheckedQuery checked_query(const RigidEdgeEdgeQuery& query) {
  CheckedQuery q;
  q.doubles.type = q.rationals.type = QueryType::edge_edge;
  set_start(&q, 0, query.ea0, "ea0");
  set_start(&q, 1, query.ea1, "ea1");
  set_start(&q, 2, query.eb0, "eb0");
  set_start(&q, 3, query.eb1, "eb1");
  add_side(query.edge_a, 2, "edge_a", &q, 0);
  add_side(query.edge_b, 2, "edge_b", &q, 1);
  return q;
}

/// |q|^2 of a side when it turns about a fixed axis or stands still (0), -1 when it moves
/// otherwise (a translating pivot or a moving linear vertex).
exact::Rational rotation_rate_squared(const exact::RationalRigidQuery& q, int index) {
  const exact::RationalSide& side = q.side[index];
  const int begin = index == 0 ? 0 : (q.type == QueryType::vertex_face ? 1 : 2);
  const int end = index == 0 ? begin + (q.type == QueryType::vertex_face ? 1 : 2) : 4;
  if (!side.rigid) {
    for (int i = begin; i < end; ++i)
      for (int k = 0; k < 3; ++k)
        if (side.end[i - begin][k] != q.start[i][k]) return -1;
    return 0;
  }
  for (int k = 0; k < 3; ++k)
    if (sgn(side.motion.translation[k]) != 0) return -1;
  return predicates::squared_norm(side.motion.cayley);
}

/// RAII for one MPFR number at 64 bits.
struct Mpfr {
  mpfr_t x;
  Mpfr() { mpfr_init2(x, 64); }
  ~Mpfr() { mpfr_clear(x); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
};

/// A certified enclosure of t(s) = atan(s r) / atan(r) over s in [s_lo, s_hi], r = sqrt(rr) > 0:
/// every operation rounded outwards by MPFR. PROOF: proofs/rigid_ccd.md#time-of-rotation
std::pair<double, double> rotation_time(const exact::Rational& rr, double s_lo, double s_hi) {
  Mpfr r_lo, r_hi, num, den;
  mpfr_set_q(r_lo.x, rr.get_mpq_t(), MPFR_RNDD);
  mpfr_sqrt(r_lo.x, r_lo.x, MPFR_RNDD);
  mpfr_set_q(r_hi.x, rr.get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(r_hi.x, r_hi.x, MPFR_RNDU);
  // Lower end: the smaller numerator over the larger denominator (both >= 0).
  mpfr_mul_d(num.x, r_lo.x, s_lo, MPFR_RNDD);
  mpfr_atan(num.x, num.x, MPFR_RNDD);
  mpfr_atan(den.x, r_hi.x, MPFR_RNDU);
  mpfr_div(num.x, num.x, den.x, MPFR_RNDD);
  const double lo = mpfr_get_d(num.x, MPFR_RNDD);
  mpfr_mul_d(num.x, r_hi.x, s_hi, MPFR_RNDU);
  mpfr_atan(num.x, num.x, MPFR_RNDU);
  mpfr_atan(den.x, r_lo.x, MPFR_RNDD);
  mpfr_div(num.x, num.x, den.x, MPFR_RNDU);
  const double hi = std::min(mpfr_get_d(num.x, MPFR_RNDU), 1.0);  // t(s) <= 1 for s <= 1
  return {std::max(lo, 0.0), hi};
}

RigidCcdResult with_time(const CcdResult& ccd, const exact::RationalRigidQuery& q) {
  RigidCcdResult r;
  r.ccd = ccd;
  const exact::Rational r0 = rotation_rate_squared(q, 0), r1 = rotation_rate_squared(q, 1);
  const bool no_rotation = (q.side[0].rigid ? sgn(predicates::squared_norm(q.side[0].motion.cayley)) == 0
                                             : true) &&
                           (q.side[1].rigid ? sgn(predicates::squared_norm(q.side[1].motion.cayley)) == 0
                                             : true);
  if (no_rotation) {
    r.has_time = true;
    r.time_lo = ccd.toi_lo;
    r.time_hi = ccd.toi_hi;
    return r;
  }
  if (sgn(r0) < 0 || sgn(r1) < 0) return r;
  if (sgn(r0) > 0 && sgn(r1) > 0 && r0 != r1) return r;
  r.has_time = true;
  if (!ccd.collides) return r;  // both stay +infinity
  std::tie(r.time_lo, r.time_hi) = rotation_time(sgn(r0) > 0 ? r0 : r1, ccd.toi_lo, ccd.toi_hi);
  return r;
}

template <class Query>
RigidCcdResult rigid_ccd(const Query& query, const CcdOptions& options) {
  const RoundToNearest nearest;
  check_ccd_options(options);
  if (options.min_separation != 0.0)
    throw std::invalid_argument(
        "exactccd: min_separation is not supported for rigid motion (it must be 0)");
  if (options.mode == Mode::float_only)
    throw std::invalid_argument(
        "exactccd: Mode::float_only has no rigid-motion test (use Mode::filtered or exact)");
  const CheckedQuery q = checked_query(query);
  if (options.mode == Mode::filtered)
    if (std::optional<CcdResult> r = filters::rigid_no_contact_filter(q.doubles, options))
      return with_time(*r, q.rationals);
  return with_time(exact::rigid_ccd_exact(q.rationals, options), q.rationals);
}

}  // namespace

RigidMotion RigidMotion::turn(const Eigen::Vector3d& pivot, const Eigen::Vector3d& axis,
                              double angle, const Eigen::Vector3d& translation) {
  if (!pivot.allFinite() || !axis.allFinite() || !translation.allFinite() ||
      !std::isfinite(angle))
    throw std::invalid_argument("exactccd: RigidMotion::turn needs finite inputs");
  if (!(std::abs(angle) < M_PI))
    throw std::invalid_argument("exactccd: RigidMotion::turn needs |angle| < pi");
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("exactccd: RigidMotion::turn needs a non-zero finite axis");
  RigidMotion m;
  m.pivot = pivot;
  m.translation = translation;
  m.cayley = axis * (std::tan(angle / 2) / length);
  return m;
}

Eigen::Vector3d position_at(const RigidMotion& m, const Eigen::Vector3d& x0, double s) {
  const Eigen::Vector3d v = s * m.cayley;
  const Eigen::Vector3d r = x0 - m.pivot;
  const double vv = v.squaredNorm();
  const Eigen::Vector3d rotated = ((1 - vv) * r + 2 * v * v.dot(r) + 2 * v.cross(r)) / (1 + vv);
  return m.pivot + s * m.translation + rotated;
}

RigidCcdResult vertex_face_ccd(const RigidVertexFaceQuery& query, const CcdOptions& options) {
  return rigid_ccd(query, options);
}

RigidCcdResult edge_edge_ccd(const RigidEdgeEdgeQuery& query, const CcdOptions& options) {
  return rigid_ccd(query, options);
}

}  // namespace exactccd
