// The public entry points of rigid-body CCD: input validation, the filters, the exact path, the
// uncertified float_only test, and the contact time of pure rotations. PROOF: proofs/rigid_ccd.md
#include "exactccd/rigid.hpp"

#include <mpfr.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/predicates/fp_environment.hpp"
#include "core/predicates/interval.hpp"
#include "core/predicates/rigid_query.hpp"
#include "exact/arithmetic/rational.hpp"
#include "pipeline/ccd_options_check.hpp"
#include "pipeline/dispatch.hpp"
#include "pipeline/rigid_problems.hpp"
#include "pipeline/rigid_query_check.hpp"
#include "pipeline/rotation_time.hpp"

namespace exactccd {

namespace {

using predicates::Vec3;

/// x as doubles; throws naming "<side>.<field>" (the message is built only then).
Vec3<double> checked(const Eigen::Vector3d& x, const char* side, const char* field = nullptr) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + side +
                                (field ? std::string(".") + field : std::string()));
  return {x.x(), x.y(), x.z()};
}

Vec3<exact::Rational> rational(const Vec3<double>& x) {
  return {exact::Rational(x.x), exact::Rational(x.y), exact::Rational(x.z)};
}

void add_side(const SideMotion& side, int vertices, const char* name,
              predicates::DoubleSide* out) {
  out->rigid = side.kind == PathKind::rigid;
  if (out->rigid) {
    out->motion = {checked(side.rigid.pivot, name, "rigid.pivot"),
                   checked(side.rigid.translation, name, "rigid.translation"),
                   checked(side.rigid.cayley, name, "rigid.cayley")};
  } else {
    if (side.kind != PathKind::linear)
      throw std::invalid_argument(std::string("exactccd: unknown PathKind in ") + name);
    for (int i = 0; i < vertices; ++i) out->end[i] = checked(side.linear_end[i], name, "linear_end");
  }
}

bool is_zero(const Vec3<double>& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

/// How a side moves, for the time of pure rotations: at rest, turning about a fixed axis
/// (pivot fixed, q != 0), or otherwise (a translating pivot or a moving linear vertex).
enum class SideTurn : std::uint8_t { rest, turning, moving };

SideTurn side_turn(const predicates::DoubleRigidQuery& q, int index) {
  const predicates::DoubleSide& side = q.side[index];
  const int begin = index == 0 ? 0 : (q.type == QueryType::vertex_face ? 1 : 2);
  const int end = index == 0 ? begin + (q.type == QueryType::vertex_face ? 1 : 2) : 4;
  if (!side.rigid) {
    for (int i = begin; i < end; ++i)
      for (int k = 0; k < 3; ++k)
        if (side.end[i - begin][k] != q.start[i][k]) return SideTurn::moving;
    return SideTurn::rest;
  }
  if (!is_zero(side.motion.translation)) return SideTurn::moving;
  return is_zero(side.motion.cayley) ? SideTurn::rest : SideTurn::turning;
}

/// |a|^2 == |b|^2 exactly: told apart by interval enclosures when they differ by more than
/// their rounding, else compared over the rationals.
bool equal_squared_norms(const Vec3<double>& a, const Vec3<double>& b) {
  {
    const predicates::RoundingGuard upward;
    using predicates::Interval;
    const Interval na = predicates::squared_norm(Vec3<Interval>{a.x, a.y, a.z});
    const Interval nb = predicates::squared_norm(Vec3<Interval>{b.x, b.y, b.z});
    if (na.sup() < nb.inf() || nb.sup() < na.inf()) return false;
  }
  return predicates::squared_norm(rational(a)) == predicates::squared_norm(rational(b));
}

/// RAII for one MPFR number at 64 bits.
struct Mpfr {
  mpfr_t x;
  Mpfr() { mpfr_init2(x, 64); }
  ~Mpfr() { mpfr_clear(x); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
};

}  // namespace

namespace pipeline {

std::pair<double, double> rotation_time(const Vec3<double>& q, double s_lo, double s_hi) {
  Mpfr r_lo, r_hi, num, den;
  // |q|^2 rounded down and up (each square and sum), then its square root likewise.
  for (const mpfr_rnd_t rounding : {MPFR_RNDD, MPFR_RNDU}) {
    mpfr_t& r = rounding == MPFR_RNDD ? r_lo.x : r_hi.x;
    mpfr_set_d(r, q.x, rounding);
    mpfr_sqr(r, r, rounding);
    for (const double c : {q.y, q.z}) {
      mpfr_set_d(num.x, c, rounding);
      mpfr_sqr(num.x, num.x, rounding);
      mpfr_add(r, r, num.x, rounding);
    }
    mpfr_sqrt(r, r, rounding);
  }
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

}  // namespace pipeline

namespace {

using pipeline::rotation_time;

RigidCcdResult with_time(const CcdResult& ccd, const predicates::DoubleRigidQuery& q) {
  RigidCcdResult r;
  r.ccd = ccd;
  const SideTurn turn[2] = {side_turn(q, 0), side_turn(q, 1)};
  const bool rotates[2] = {q.side[0].rigid && !is_zero(q.side[0].motion.cayley),
                           q.side[1].rigid && !is_zero(q.side[1].motion.cayley)};
  if (!rotates[0] && !rotates[1]) {
    r.has_time = true;
    r.time_lo = ccd.toi_lo;
    r.time_hi = ccd.toi_hi;
    return r;
  }
  if (turn[0] == SideTurn::moving || turn[1] == SideTurn::moving) return r;
  if (turn[0] == SideTurn::turning && turn[1] == SideTurn::turning &&
      !equal_squared_norms(q.side[0].motion.cayley, q.side[1].motion.cayley))
    return r;
  r.has_time = true;
  if (!ccd.collides) return r;  // both stay +infinity
  const int turning = turn[0] == SideTurn::turning ? 0 : 1;
  std::tie(r.time_lo, r.time_hi) =
      rotation_time(q.side[turning].motion.cayley, ccd.toi_lo, ccd.toi_hi);
  return r;
}

/// Validation and the FP state, then the one pipeline's instance the options name.
template <class Query>
RigidCcdResult rigid_ccd(const Query& query, const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  const predicates::DoubleRigidQuery q = pipeline::checked_query(query);
  if (options.min_separation > 0)
    return with_time(pipeline::certified_ccd<pipeline::RigidSeparation>(q, options), q);
  return with_time(pipeline::certified_ccd<pipeline::RigidContact>(q, options), q);
}

}  // namespace

namespace pipeline {

/// The query in doubles, every input checked to be finite (no heap allocation unless it throws).
predicates::DoubleRigidQuery checked_query(const RigidVertexFaceQuery& query) {
  predicates::DoubleRigidQuery q;
  q.type = QueryType::vertex_face;
  q.start = {checked(query.p, "p"), checked(query.a, "a"), checked(query.b, "b"),
             checked(query.c, "c")};
  add_side(query.vertex, 1, "vertex", &q.side[0]);
  add_side(query.face, 3, "face", &q.side[1]);
  return q;
}

predicates::DoubleRigidQuery checked_query(const RigidEdgeEdgeQuery& query) {
  predicates::DoubleRigidQuery q;
  q.type = QueryType::edge_edge;
  q.start = {checked(query.ea0, "ea0"), checked(query.ea1, "ea1"), checked(query.eb0, "eb0"),
             checked(query.eb1, "eb1")};
  add_side(query.edge_a, 2, "edge_a", &q.side[0]);
  add_side(query.edge_b, 2, "edge_b", &q.side[1]);
  return q;
}

}  // namespace pipeline

RigidMotion RigidMotion::turn(const Eigen::Vector3d& pivot, const Eigen::Vector3d& axis,
                              double angle, const Eigen::Vector3d& translation) {
  if (!pivot.allFinite() || !axis.allFinite() || !translation.allFinite() ||
      !std::isfinite(angle))
    throw std::invalid_argument("exactccd: RigidMotion::turn needs finite inputs");
  if (!(std::abs(angle) < M_PI))
    throw std::invalid_argument("exactccd: RigidMotion::turn needs |angle| < pi");
  // Scaled by its largest |component| first: the norm of [1e308, 1e308, 1e308] overflows and
  // that of [0, 0, 1e-320] underflows, although both are good directions.
  const double largest = axis.cwiseAbs().maxCoeff();
  if (!(largest > 0.0))
    throw std::invalid_argument("exactccd: RigidMotion::turn needs a non-zero axis");
  const Eigen::Vector3d direction = axis / largest;
  RigidMotion m;
  m.pivot = pivot;
  m.translation = translation;
  m.cayley = direction * (std::tan(angle / 2) / direction.norm());
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
