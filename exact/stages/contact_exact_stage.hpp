// The exact stage of the contact filter (predicates::ContactExactStage): exact answers at double
// times from the query's integer form, which the exact path reuses.
#pragma once

#include <optional>
#include <utility>

#include "core/predicates/contact_exact_stage.hpp"
#include "exact/stages/integer_query.hpp"

namespace exactccd::exact {

/// Exact answers at double times in integer arithmetic (exact/stages/integer_query.hpp), built
/// lazily (queries the float stages decide never build it): fixed-size stack integers within
/// the proven bounds, GMP beyond them.
/// PROOF: proofs/filters.md#exact-at-double-times
/// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
template <class Query>
class ContactExactStageAtDoubles final : public predicates::ContactExactStage {
 public:
  explicit ContactExactStageAtDoubles(const Query& q) : query_(q) {}
  int cubic_sign_at(double t) override { return integer().cubic_sign_at(t); }
  bool contact_at(double t) override { return integer().contact_at(t); }
  std::pair<double, double> bisect_root(double lo, double hi) override {
    return integer().bisect_root(lo, hi, 0.0);
  }
  void cubic_coefficient_bounds(double (&lo)[4], double (&hi)[4]) override {
    integer().scaled_coefficient_bounds(lo, hi);
  }
  const exact::IntegerQuery& integer() {
    if (!integer_) integer_.emplace(query_);
    return *integer_;
  }
  /// The integer query if a stage built it, else nullptr (the exact path then reuses it).
  const exact::IntegerQuery* built() const { return integer_ ? &*integer_ : nullptr; }

 private:
  const Query& query_;
  std::optional<exact::IntegerQuery> integer_;
};

}  // namespace exactccd::exact
