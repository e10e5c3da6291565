// PROOF: proofs/min_separation.md#theorem-exact-procedure
#include "exact/reference/min_separation.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "core/predicates/separation.hpp"
#include "exact/reference/earliest_contact.hpp"

namespace exactccd::exact {

namespace {

/// The earliest instant at which `separation` (a VertexFaceSeparation or EdgeEdgeSeparation
/// over exact rationals) holds, given the hint: t = 0 (t_from = 0 only) or a root in
/// (t_from, t_to] of one of its non-strict polynomials whose sign the hint does not fix;
/// polynomials certainly without a root in [t_from, t_to] are skipped.
/// PROOF: proofs/min_separation.md#candidate-times
template <class Separation>
CcdResult earliest_within(const Separation& separation, const CcdOptions& options,
                          const SeparationHint& hint) {
  const Rational from(hint.t_from), to(hint.t_to > 0 ? hint.t_to : options.t_max);
  std::array<signed char, Separation::kCount> known;
  known.fill(2);
  if (hint.t_to > 0 && hint.known_signs)
    std::copy(hint.known_signs, hint.known_signs + Separation::kCount, known.begin());
  std::vector<Polynomial> all;
  all.reserve(Separation::kCount);
  separation.for_each_polynomial([&all](const auto& g) { all.emplace_back(g); });
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

}  // namespace exactccd::exact
