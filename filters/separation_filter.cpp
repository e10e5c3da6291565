// PROOF: proofs/min_separation.md#filters
#include "filters/separation_filter.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>

#include "core/predicates/separation.hpp"
#include "exact/earliest_contact.hpp"
#include "exact/polynomial.hpp"
#include "exactccd/rational_query.hpp"
#include "filters/interval.hpp"
#include "filters/separation_directions.hpp"
#include "filters/separation_search.hpp"

namespace exactccd::filters {

namespace {

using predicates::Vec3;

/// hi1 + delta < lo2 or hi2 + delta < lo1 on some axis, the sums rounded upwards: a certain
/// gap wider than delta. PROOF: proofs/min_separation.md#culling-with-delta
template <std::size_t N1, std::size_t N2>
bool boxes_apart(const std::array<const Eigen::Vector3d*, N1>& first,
                 const std::array<const Eigen::Vector3d*, N2>& second, double delta) {
  const RoundingGuard upward;
  for (int k = 0; k < 3; ++k) {
    double lo1 = first[0]->coeff(k), hi1 = lo1, lo2 = second[0]->coeff(k), hi2 = lo2;
    for (const auto* v : first) {
      lo1 = std::min(lo1, v->coeff(k));
      hi1 = std::max(hi1, v->coeff(k));
    }
    for (const auto* v : second) {
      lo2 = std::min(lo2, v->coeff(k));
      hi2 = std::max(hi2, v->coeff(k));
    }
    if (hi1 + delta < lo2 || hi2 + delta < lo1) return true;
  }
  return false;
}

predicates::MovingPoint<Interval> moving(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  return predicates::linear_motion(Vec3<Interval>{x0.x(), x0.y(), x0.z()},
                                   Vec3<Interval>{x1.x(), x1.y(), x1.z()});
}

/// Polynomial k of a separation over the exact rationals.
template <class Separation>
exact::Polynomial polynomial_number(const Separation& s, int k) {
  exact::Polynomial found;
  int index = 0;
  s.for_each_polynomial([&](const auto& g) {
    if (index++ == k) found = exact::Polynomial(g);
  });
  return found;
}

/// Polynomial k of the query's separation over the exact rationals, for the query scaled to
/// integer coordinates by a power of two l (delta by l too): each region polynomial is
/// homogeneous in the coordinates and delta, so it is scaled by a positive power of l and
/// keeps its signs, and integers keep GMP's normalisation cheap.
exact::Polynomial exact_polynomial_number(const RationalQuery& query, double delta, int k) {
  exact::Rational l;
  const RationalQuery q = exact::with_integer_coordinates(query, &l);
  const exact::Rational d = exact::Rational(delta) * l;
  const auto& v = q.points;
  using exact::moving;
  if (q.type == QueryType::vertex_face)
    return polynomial_number(
        predicates::vertex_face_separation(moving(v[0], v[4]), moving(v[1], v[5]),
                                           moving(v[2], v[6]), moving(v[3], v[7]),
                                           exact::Rational(d * d)),
        k);
  return polynomial_number(
      predicates::edge_edge_separation(moving(v[0], v[4]), moving(v[1], v[5]), moving(v[2], v[6]),
                                       moving(v[3], v[7]), exact::Rational(d * d)),
      k);
}

template <class Motion, class Separation>
SeparationOutcome first_within(const Motion& m, const Separation& s,
                               const separation::ExactPolynomial& exact_polynomial,
                               const CcdOptions& options) {
  return separation::FirstWithinSearch<Motion, Separation>(m, s, exact_polynomial, options).run();
}

}  // namespace

bool vertex_face_separation_culling(const VertexFaceQuery& q, double delta) {
  return boxes_apart<2, 6>({&q.p_t0, &q.p_t1},
                           {&q.a_t0, &q.b_t0, &q.c_t0, &q.a_t1, &q.b_t1, &q.c_t1}, delta);
}

bool edge_edge_separation_culling(const EdgeEdgeQuery& q, double delta) {
  return boxes_apart<4, 4>({&q.ea0_t0, &q.ea1_t0, &q.ea0_t1, &q.ea1_t1},
                           {&q.eb0_t0, &q.eb1_t0, &q.eb0_t1, &q.eb1_t1}, delta);
}

SeparationOutcome vertex_face_separation_filter(const VertexFaceQuery& q,
                                                const CcdOptions& options) {
  using separation::MovingVertex;
  const RoundingGuard upward;
  const separation::VertexFaceMotion m{
      {MovingVertex(q.p_t0, q.p_t1), MovingVertex(q.a_t0, q.a_t1), MovingVertex(q.b_t0, q.b_t1),
       MovingVertex(q.c_t0, q.c_t1)}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto s = predicates::vertex_face_separation(moving(q.p_t0, q.p_t1),
                                                    moving(q.a_t0, q.a_t1),
                                                    moving(q.b_t0, q.b_t1),
                                                    moving(q.c_t0, q.c_t1), delta2);
  const separation::ExactPolynomial exact_polynomial = [&q, &options](int k) {
    return exact_polynomial_number(to_rational(q), options.min_separation, k);
  };
  return first_within(m, s, exact_polynomial, options);
}

SeparationOutcome edge_edge_separation_filter(const EdgeEdgeQuery& q, const CcdOptions& options) {
  using separation::MovingVertex;
  const RoundingGuard upward;
  const separation::EdgeEdgeMotion m{
      {MovingVertex(q.ea0_t0, q.ea0_t1), MovingVertex(q.ea1_t0, q.ea1_t1),
       MovingVertex(q.eb0_t0, q.eb0_t1), MovingVertex(q.eb1_t0, q.eb1_t1)}};
  const Interval delta2 = Interval(options.min_separation) * options.min_separation;
  const auto s = predicates::edge_edge_separation(moving(q.ea0_t0, q.ea0_t1),
                                                  moving(q.ea1_t0, q.ea1_t1),
                                                  moving(q.eb0_t0, q.eb0_t1),
                                                  moving(q.eb1_t0, q.eb1_t1), delta2);
  const separation::ExactPolynomial exact_polynomial = [&q, &options](int k) {
    return exact_polynomial_number(to_rational(q), options.min_separation, k);
  };
  return first_within(m, s, exact_polynomial, options);
}

}  // namespace exactccd::filters
