// PROOF: proofs/min_separation.md#theorem-exact-procedure
#include "exact/min_separation.hpp"

#include <vector>

#include "core/predicates/separation.hpp"
#include "exact/earliest_contact.hpp"

namespace exactccd::exact {

namespace {

/// The earliest instant at which `separation` (a VertexFaceSeparation or EdgeEdgeSeparation
/// over exact rationals) holds: t = 0 or a root of one of its non-strict polynomials.
/// PROOF: proofs/min_separation.md#candidate-times
template <class Separation>
CcdResult earliest_within(const Separation& separation, const CcdOptions& options) {
  std::vector<Polynomial> candidates;
  candidates.reserve(24);
  separation.for_each_polynomial([&candidates](const auto& g) {
    Polynomial q(g);
    if (q.degree() >= 1) candidates.push_back(std::move(q));
  });
  return make_result(earliest_contact(candidates, true, Rational(options.t_max),
                                      [&separation](AlgebraicTime& t) {
                                        return separation.within_at(sign_at(t));
                                      }),
                     options);
}

}  // namespace

CcdResult vertex_face_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                           const CcdOptions& options) {
  Rational scale;
  const RationalQuery q = with_integer_coordinates(query, &scale);
  const Rational d = delta * scale;
  const auto& v = q.points;
  return earliest_within(
      predicates::vertex_face_separation(moving(v[0], v[4]), moving(v[1], v[5]),
                                         moving(v[2], v[6]), moving(v[3], v[7]), Rational(d * d)),
      options);
}

CcdResult edge_edge_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                         const CcdOptions& options) {
  Rational scale;
  const RationalQuery q = with_integer_coordinates(query, &scale);
  const Rational d = delta * scale;
  const auto& v = q.points;
  return earliest_within(
      predicates::edge_edge_separation(moving(v[0], v[4]), moving(v[1], v[5]),
                                       moving(v[2], v[6]), moving(v[3], v[7]), Rational(d * d)),
      options);
}

}  // namespace exactccd::exact
