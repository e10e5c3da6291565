// Linear motion as instances of the one pipeline (pipeline/dispatch.hpp): contact and minimum
// separation, each for both pair kinds, which differ only in the functions LinearPair names.
// PROOF: proofs/pipeline.md#one-pipeline
#pragma once

#include <optional>
#include <utility>

#include "core/float_only/float_only_ccd.hpp"
#include "core/float_only/tolerance_ccd.hpp"
#include "core/predicates/query_points.hpp"
#include "exact/reference/exact_ccd.hpp"
#include "exact/reference/min_separation.hpp"
#include "exact/stages/algebraic_at_doubles.hpp"
#include "exact/stages/contact_exact_stage.hpp"
#include "exact/stages/integer_query.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "exactccd/rational_query.hpp"
#include "filters/ccd_filters.hpp"
#include "filters/separation_filter.hpp"
#include "pipeline/power_of_two_scaling.hpp"
#include "pipeline/separation_hint.hpp"

namespace exactccd::pipeline {

/// What tells the two linear pair kinds apart: their filters, exact procedures and points.
template <class Query>
struct LinearPair;

template <>
struct LinearPair<VertexFaceQuery> {
  static constexpr auto contact_culling = &filters::vertex_face_ccd_culling;
  static constexpr auto contact_filter = &filters::vertex_face_ccd_filter;
  static constexpr auto contact_at_doubles = &exact::vertex_face_ccd_at_doubles;
  static constexpr auto contact_rational = &exact::vertex_face_ccd_exact;
  static constexpr auto separation_culling = &filters::vertex_face_separation_culling;
  static constexpr auto separation_filter = &filters::vertex_face_separation_filter;
  static constexpr auto separation_rational = &exact::vertex_face_min_separation_exact;
  static constexpr auto tolerance = &methods::tolerance_vertex_face_ccd;
  static constexpr predicates::SeparationPair separation_pair = predicates::SeparationPair::vertex_face;
  static CcdResult float_contact(const VertexFaceQuery& q, const CcdOptions& o) {
    return float_only::vertex_face_ccd(q, o);
  }
};

template <>
struct LinearPair<EdgeEdgeQuery> {
  static constexpr auto contact_culling = &filters::edge_edge_ccd_culling;
  static constexpr auto contact_filter = &filters::edge_edge_ccd_filter;
  static constexpr auto contact_at_doubles = &exact::edge_edge_ccd_at_doubles;
  static constexpr auto contact_rational = &exact::edge_edge_ccd_exact;
  static constexpr auto separation_culling = &filters::edge_edge_separation_culling;
  static constexpr auto separation_filter = &filters::edge_edge_separation_filter;
  static constexpr auto separation_rational = &exact::edge_edge_min_separation_exact;
  static constexpr auto tolerance = &methods::tolerance_edge_edge_ccd;
  static constexpr predicates::SeparationPair separation_pair = predicates::SeparationPair::edge_edge;
  static CcdResult float_contact(const EdgeEdgeQuery& q, const CcdOptions& o) {
    return float_only::edge_edge_ccd(q, o);
  }
};

/// Contact under linear motion: the coplanarity cubic and the inclusion test.
/// PROOF: proofs/filters.md#power-of-two-normalisation
template <class Q>
struct LinearContact {
  using Query = Q;
  using Pair = LinearPair<Q>;
  using ExactStage = exact::ContactExactStageAtDoubles<Q>;

  /// The exact stage at double brackets, and the rational path (the reference) past its step
  /// caps (never reached on any test or benchmark set). `known`: the integer query if built.
  /// PROOF: proofs/exact_ccd.md#exact-at-double-brackets
  static CcdResult exact_path(const Q& q, const CcdOptions& o,
                              const exact::IntegerQuery* known = nullptr) {
    if (std::optional<CcdResult> r = Pair::contact_at_doubles(q, o, known)) return *r;
    return Pair::contact_rational(to_rational(q), o);
  }
  static CcdResult float_only(const Q& q, const CcdOptions& o) { return Pair::float_contact(q, o); }
  static CcdResult exact(const Q& q, const CcdOptions& o) { return exact_path(q, o); }
  static bool culled(const Q& q, const CcdOptions&) { return Pair::contact_culling(q); }
  static int normalising_exponent(const Q& q) { return detail::normalising_exponent(q); }
  static Q scaled(const Q& q, int s) { return detail::scaled_by_power_of_two(q, s); }
  static ExactStage exact_stage(const Q& q, const CcdOptions&) { return ExactStage(q); }
  static FilterOutcome filter(const Q& q, const CcdOptions& o, ExactStage& stage) {
    return Pair::contact_filter(q, o, stage);
  }
  static std::pair<double, double> tighten(ExactStage& stage, double lo, double hi,
                                           const CcdOptions& o) {
    return stage.integer().bisect_root(lo, hi, o.toi_width);
  }
  static CcdResult after_filter(const Q& q, const CcdOptions& o, const FilterOutcome&,
                                ExactStage& stage) {
    return exact_path(q, o, stage.built());
  }
};

/// Minimum separation delta = options.min_separation > 0 under linear motion: the region
/// polynomials and `within`. PROOF: proofs/min_separation.md#pipeline
template <class Q>
struct LinearSeparation {
  using Query = Q;
  using Pair = LinearPair<Q>;
  using ExactStage = exact::separation::ExactSignsAtDoubles;

  static CcdResult rational(const Q& q, const CcdOptions& o, const exact::SeparationHint& hint) {
    return Pair::separation_rational(to_rational(q), mpq_class(o.min_separation), o, hint);
  }
  /// The common practice (a distance tolerance on a float test), uncertified.
  static CcdResult float_only(const Q& q, const CcdOptions& o) {
    return Pair::tolerance(q, o.min_separation, o.t_max);
  }
  static CcdResult exact(const Q& q, const CcdOptions& o) { return rational(q, o, {}); }
  static bool culled(const Q& q, const CcdOptions& o) {
    return Pair::separation_culling(q, o.min_separation);
  }
  static constexpr int normalising_exponent(const Q&) { return 0; }
  static Q scaled(const Q& q, int) { return q; }
  /// No work until the filter asks (its integer query formed only then).
  static ExactStage exact_stage(const Q& q, const CcdOptions& o) {
    return ExactStage(predicates::points_at(q, false), predicates::points_at(q, true),
                      o.min_separation, Pair::separation_pair);
  }
  static FilterOutcome filter(const Q& q, const CcdOptions& o, const ExactStage& stage) {
    return Pair::separation_filter(q, o, stage);
  }
  static std::pair<double, double> tighten(const ExactStage&, double lo, double hi,
                                           const CcdOptions&) {
    return {lo, hi};  // the separation filters report final TOIs
  }
  static CcdResult after_filter(const Q& q, const CcdOptions& o, const FilterOutcome& f,
                                const ExactStage&) {
    return rational(q, o, separation_hint(f));
  }
};

}  // namespace exactccd::pipeline
