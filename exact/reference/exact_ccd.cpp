// PROOF: proofs/exact_ccd.md (theorems 1 and 2 and the lemmas they cite).
#include "exact/reference/exact_ccd.hpp"

#include <optional>
#include <tuple>

#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/inclusion.hpp"
#include "exact/reference/earliest_contact.hpp"
#include "exact/reference/primitive_contact.hpp"

namespace exactccd::exact {

RationalQuery with_integer_coordinates(const RationalQuery& q, Rational* scale) {
  mpz_class l = 1;
  for (const auto& p : q.points)
    for (const Rational* x : {&p.x, &p.y, &p.z})
      mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x->get_den_mpz_t());
  if (scale) *scale = l;
  if (l == 1) return q;
  RationalQuery scaled = q;
  for (auto& p : scaled.points)
    for (Rational* x : {&p.x, &p.y, &p.z}) *x *= l;
  return scaled;
}

CcdResult make_result(std::optional<AlgebraicTime> toi, const CcdOptions& options) {
  CcdResult r;
  r.decided_by = Stage::exact;
  if (!toi) return r;
  r.collides = true;
  std::tie(r.toi_lo, r.toi_hi) = toi->enclosure(options.toi_width);
  return r;
}


CcdResult vertex_face_ccd_exact(const RationalQuery& query, const CcdOptions& options) {
  const RationalQuery q = with_integer_coordinates(query);
  const auto& v = q.points;
  const auto p = moving(v[0], v[4]), a = moving(v[1], v[5]), b = moving(v[2], v[6]),
             c = moving(v[3], v[7]);
  const Polynomial cubic(predicates::vertex_face_coplanarity_cubic(p, a, b, c));
  return make_result(earliest_vertex_face_contact(p, a, b, c, cubic, Rational(options.t_max)),
                     options);
}

CcdResult edge_edge_ccd_exact(const RationalQuery& query, const CcdOptions& options) {
  const RationalQuery q = with_integer_coordinates(query);
  const auto& v = q.points;
  const auto a0 = moving(v[0], v[4]), a1 = moving(v[1], v[5]), b0 = moving(v[2], v[6]),
             b1 = moving(v[3], v[7]);
  const Polynomial cubic(predicates::edge_edge_coplanarity_cubic(a0, a1, b0, b1));
  return make_result(earliest_edge_edge_contact(a0, a1, b0, b1, cubic, Rational(options.t_max)),
                     options);
}

}  // namespace exactccd::exact
