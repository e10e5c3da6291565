// PROOF: proofs/rigid_ccd.md#filters
#include "filters/rigid_filter.hpp"

#include "filters/interval.hpp"

namespace exactccd::filters {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;

/// The number of equal pieces [0, t_max] is cut into: boxes of a turning arc over a piece are
/// much tighter than over the whole motion, and 16 keeps the filter cheap.
constexpr int kPieces = 16;

Vec3<Interval> exact_interval(const Vec3<double>& x) { return {x.x, x.y, x.z}; }

predicates::RigidMotionOver<Interval> interval_motion(const predicates::RigidMotionOver<double>& m) {
  return {exact_interval(m.pivot), exact_interval(m.translation), exact_interval(m.cayley)};
}

struct IntervalPaths {
  std::array<Vec3<FixedPoly<Interval, 3>>, 4> numerator;
  std::array<FixedPoly<Interval, 2>, 2> denominator;
  int first_side_count;
};

IntervalPaths interval_paths(const DoubleRigidQuery& q) {
  IntervalPaths paths;
  paths.first_side_count = q.type == QueryType::vertex_face ? 1 : 2;
  for (int side = 0; side < 2; ++side) {
    const DoubleSide& s = q.side[side];
    const auto motion = interval_motion(s.motion);
    paths.denominator[side] =
        s.rigid ? predicates::rigid_path_denominator(motion)
                : FixedPoly<Interval, 2>{{Interval(1), Interval(0), Interval(0)}};
    const int begin = side == 0 ? 0 : paths.first_side_count;
    const int end = side == 0 ? paths.first_side_count : 4;
    for (int i = begin; i < end; ++i) {
      const Vec3<Interval> x0 = exact_interval(q.start[i]);
      paths.numerator[i] = s.rigid ? predicates::rigid_path_numerator(motion, x0)
                                   : predicates::linear_path_numerator(
                                         x0, exact_interval(s.end[i - begin]));
    }
  }
  return paths;
}

/// Encloses the box of x(s) = X(s) / w(s) over s in `piece` (w >= 1 there).
Vec3<Interval> box_over(const Vec3<FixedPoly<Interval, 3>>& X, const FixedPoly<Interval, 2>& w,
                        const Interval& piece) {
  const Interval den = predicates::evaluate(w, piece);
  return {predicates::evaluate(X.x, piece) / den, predicates::evaluate(X.y, piece) / den,
          predicates::evaluate(X.z, piece) / den};
}

bool boxes_apart(const Vec3<Interval>* a, int na, const Vec3<Interval>* b, int nb) {
  for (int k = 0; k < 3; ++k) {
    double a_lo = a[0][k].inf(), a_hi = a[0][k].sup();
    for (int i = 1; i < na; ++i) a_lo = std::min(a_lo, a[i][k].inf()), a_hi = std::max(a_hi, a[i][k].sup());
    double b_lo = b[0][k].inf(), b_hi = b[0][k].sup();
    for (int i = 1; i < nb; ++i) b_lo = std::min(b_lo, b[i][k].inf()), b_hi = std::max(b_hi, b[i][k].sup());
    if (a_hi < b_lo || b_hi < a_lo) return true;
  }
  return false;
}

}  // namespace

std::optional<CcdResult> rigid_no_contact_filter(const DoubleRigidQuery& q,
                                                 const CcdOptions& options) {
  const RoundingGuard upward;
  const IntervalPaths paths = interval_paths(q);
  const int n0 = paths.first_side_count;
  // Points on the common denominator W = w_0 w_1 > 0 (rigid_motion.hpp): the coplanarity
  // determinant has the sign of the true one at every s.
  std::array<predicates::RigidPoint<Interval>, 4> y;
  for (int i = 0; i < 4; ++i)
    y[i] = predicates::on_common_denominator(paths.numerator[i],
                                             paths.denominator[i < n0 ? 1 : 0]);
  const auto f = q.type == QueryType::vertex_face
                     ? predicates::coplanarity_determinant(y[0], y[1], y[2], y[3])
                     : predicates::coplanarity_determinant(y[3], y[0], y[1], y[2]);
  bool only_culled = true;
  // Piece ends k t_max / kPieces rounded outwards (upward rounding: -((-x)) rounds down).
  for (int k = 0; k < kPieces; ++k) {
    const double lo = k == 0 ? 0.0 : -((-options.t_max * k) / kPieces);
    const double hi = k + 1 == kPieces ? options.t_max : (options.t_max * (k + 1)) / kPieces;
    const Interval piece(lo, hi);
    std::array<Vec3<Interval>, 4> box;
    for (int i = 0; i < 4; ++i)
      box[i] = box_over(paths.numerator[i], paths.denominator[i < n0 ? 0 : 1], piece);
    if (boxes_apart(&box[0], n0, &box[n0], 4 - n0)) continue;
    only_culled = false;
    const Interval value = predicates::evaluate(f, piece);
    if (certified_sign(value) == CertifiedSign::positive ||
        certified_sign(value) == CertifiedSign::negative)
      continue;
    return std::nullopt;
  }
  CcdResult r;
  r.decided_by = only_culled ? Stage::culling : Stage::filter;
  return r;
}

}  // namespace exactccd::filters
