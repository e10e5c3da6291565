// PROOF: proofs/min_separation.md#theorem-exact-procedure
#include "exact/reference/min_separation.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "core/predicates/rigid_paths.hpp"
#include "core/predicates/separation.hpp"
#include "exact/reference/earliest_contact.hpp"

namespace exactccd::exact {

namespace {

/// The earliest instant at which `separation` (a VertexFaceSeparation or EdgeEdgeSeparation
/// over exact rationals) holds, given the hint: t = 0 (t_from = 0 only) or a root in
/// (t_from, t_to] of one of its non-strict polynomials whose sign the hint does not fix;
/// polynomials certainly without a root in [t_from, t_to] are skipped.
/// PROOF: proofs/min_separation.md#candidate-times
/// Each of `positive_factors` (polynomials with no real root, positive) is divided out of every
/// region polynomial as often as it divides it: the signs stay, the degrees fall.
template <class Separation>
CcdResult earliest_within(const Separation& separation, const CcdOptions& options,
                          const SeparationHint& hint,
                          const std::vector<Polynomial>& positive_factors = {}) {
  const Rational from(hint.t_from), to(hint.t_to > 0 ? hint.t_to : options.t_max);
  std::array<signed char, Separation::kCount> known;
  known.fill(2);
  if (hint.t_to > 0 && hint.known_signs)
    std::copy(hint.known_signs, hint.known_signs + Separation::kCount, known.begin());
  std::vector<Polynomial> all;
  all.reserve(Separation::kCount);
  separation.for_each_polynomial([&all](const auto& g) { all.emplace_back(g); });
  for (Polynomial& g : all)
    for (const Polynomial& f : positive_factors)
      while (!g.is_zero()) {
        Polynomial quotient, remainder;
        divide(g, f, &quotient, &remainder);
        if (!remainder.is_zero()) break;
        g = std::move(quotient);
      }
  std::vector<Polynomial> candidates;
  for (int k = 0; k < Separation::kNonStrictCount; ++k)
    if (known[k] == 2 && all[k].degree() >= 1 && !certainly_root_free(all[k], from, to))
      candidates.push_back(all[k]);
  // The instant predicate at an algebraic time in [t_from, t_to], each polynomial's exact
  // sign read once (the hint's constant signs without computation).
  auto within_at = [&all, &known](AlgebraicTime& t) {
    std::array<signed char, Separation::kCount> memo = known;
    return Separation::within([&](int k) {
      if (memo[k] == 2) memo[k] = static_cast<signed char>(t.sign_of(all[k]));
      return static_cast<int>(memo[k]);
    });
  };
  return make_result(earliest_contact(candidates, hint.t_from == 0.0, to, within_at, from),
                     options);
}

/// The query scaled to integer coordinates by l, delta by the same l (distances scale by l,
/// times do not), and its separation made by `make` over the exact rationals.
template <class Make>
CcdResult min_separation_exact(const RationalQuery& query, const Rational& delta,
                               const CcdOptions& options, const SeparationHint& hint,
                               Make make) {
  Rational scale;
  const RationalQuery q = with_integer_coordinates(query, &scale);
  const Rational d = delta * scale;
  const auto& v = q.points;
  return earliest_within(make(moving(v[0], v[4]), moving(v[1], v[5]), moving(v[2], v[6]),
                              moving(v[3], v[7]), Rational(d * d)),
                         options, hint);
}

}  // namespace

CcdResult vertex_face_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                           const CcdOptions& options,
                                           const SeparationHint& hint) {
  return min_separation_exact(query, delta, options, hint, [](auto... a) {
    return predicates::vertex_face_separation(a...);
  });
}

CcdResult edge_edge_min_separation_exact(const RationalQuery& query, const Rational& delta,
                                         const CcdOptions& options,
                                         const SeparationHint& hint) {
  return min_separation_exact(query, delta, options, hint, [](auto... a) {
    return predicates::edge_edge_separation(a...);
  });
}

CcdResult rigid_min_separation_exact(const RationalRigidQuery& query, const Rational& delta,
                                     const CcdOptions& options, const SeparationHint& hint) {
  const predicates::RigidPaths<Rational> paths = predicates::rigid_paths<Rational>(query);
  const auto W = paths.common_denominator();
  const auto delta2 = predicates::scaled(Rational(delta * delta), W * W);
  std::array<predicates::RigidPoint<Rational>, 4> y;
  for (int i = 0; i < 4; ++i) y[i] = paths.on_common_denominator(i);
  std::vector<Polynomial> denominators;  // w_side = 1 + |q|^2 s^2 of each turning side
  for (const auto& w : paths.denominator)
    if (sgn(w.c[2]) > 0) denominators.emplace_back(w);
  return query.type == QueryType::vertex_face
             ? earliest_within(predicates::vertex_face_separation(y[0], y[1], y[2], y[3], delta2),
                               options, hint, denominators)
             : earliest_within(predicates::edge_edge_separation(y[0], y[1], y[2], y[3], delta2),
                               options, hint, denominators);
}

}  // namespace exactccd::exact
