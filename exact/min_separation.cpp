// PROOF: proofs/min_separation.md#theorem-exact-procedure
#include "exact/min_separation.hpp"

#include <vector>

#include "core/predicates/separation.hpp"
#include "exact/earliest_contact.hpp"

namespace exactccd::exact {

namespace {

/// The earliest instant at which `separation` (a VertexFaceSeparation or EdgeEdgeSeparation
/// over exact rationals) holds, given that it holds nowhere in [0, t_from] when t_from > 0:
/// t = 0 (t_from = 0 only) or a root in (t_from, t_max] of one of its non-strict polynomials;
/// polynomials certainly without a root in [t_from, t_max] are skipped.
/// PROOF: proofs/min_separation.md#candidate-times
template <class Separation>
CcdResult earliest_within(const Separation& separation, const CcdOptions& options,
                          double t_from) {
  const Rational from(t_from), t_max(options.t_max);
  std::vector<Polynomial> candidates;
  candidates.reserve(24);
  separation.for_each_polynomial([&](const auto& g) {
    Polynomial q(g);
    if (q.degree() >= 1 && !certainly_root_free(q, from, t_max))
      candidates.push_back(std::move(q));
  });
  return make_result(earliest_contact(
                         candidates, t_from == 0.0, t_max,
                         [&separation](AlgebraicTime& t) { return separation.within_at(sign_at(t)); },
                         from),
                     options);
}

}  // namespace

CcdResult vertex_face_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                           const CcdOptions& options, double t_from) {
  Rational scale;
  const RationalQuery q = with_integer_coordinates(query, &scale);
  const Rational d = delta * scale;
  const auto& v = q.points;
  return earliest_within(
      predicates::vertex_face_separation(moving(v[0], v[4]), moving(v[1], v[5]),
                                         moving(v[2], v[6]), moving(v[3], v[7]), Rational(d * d)),
      options, t_from);
}

CcdResult edge_edge_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                         const CcdOptions& options, double t_from) {
  Rational scale;
  const RationalQuery q = with_integer_coordinates(query, &scale);
  const Rational d = delta * scale;
  const auto& v = q.points;
  return earliest_within(
      predicates::edge_edge_separation(moving(v[0], v[4]), moving(v[1], v[5]),
                                       moving(v[2], v[6]), moving(v[3], v[7]), Rational(d * d)),
      options, t_from);
}

}  // namespace exactccd::exact
