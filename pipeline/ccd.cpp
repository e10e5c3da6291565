// The public entry points: input validation, then the path the options choose.
#include "exactccd/ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <optional>
#include <tuple>

#include "core/predicates/fp_environment.hpp"
#include "pipeline/ccd_options_check.hpp"
#include "core/float_only/float_only_ccd.hpp"
#include "pipeline/power_of_two_scaling.hpp"
#include "pipeline/separation_outcome.hpp"
#include "exact/stages/algebraic_at_doubles.hpp"
#include "exact/reference/exact_ccd.hpp"
#include "exact/reference/min_separation.hpp"
#include "core/float_only/tolerance_ccd.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "filters/separation_filter.hpp"
#include "exact/stages/contact_exact_stage.hpp"
#include "exact/stages/integer_query.hpp"
#include "filters/ccd_filters.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd {

const char* to_string(Stage stage) noexcept {
  switch (stage) {
    case Stage::culling: return "culling";
    case Stage::filter: return "filter";
    case Stage::filter_exact_toi: return "filter_exact_toi";
    case Stage::exact_at_double: return "exact_at_double";
    case Stage::exact: return "exact";
    case Stage::float_only: return "float_only";
  }
  return "unknown";
}

const char* to_string(Mode mode) noexcept {
  switch (mode) {
    case Mode::filtered: return "default";
    case Mode::float_only: return "float_only";
    case Mode::exact: return "exact";
  }
  return "unknown";
}

const char* to_string(QueryType type) noexcept {
  return type == QueryType::vertex_face ? "vertex-face" : "edge-edge";
}

namespace {

RationalPoint rational(const Eigen::Vector3d& x, const char* name) {
  if (!x.allFinite())
    throw std::invalid_argument(std::string("exactccd: non-finite coordinate in ") + name);
  return {mpq_class(x.x()), mpq_class(x.y()), mpq_class(x.z())};
}

}  // namespace

RationalQuery to_rational(const VertexFaceQuery& q) {
  return {QueryType::vertex_face,
          {rational(q.p_t0, "p_t0"), rational(q.a_t0, "a_t0"), rational(q.b_t0, "b_t0"),
           rational(q.c_t0, "c_t0"), rational(q.p_t1, "p_t1"), rational(q.a_t1, "a_t1"),
           rational(q.b_t1, "b_t1"), rational(q.c_t1, "c_t1")}};
}

RationalQuery to_rational(const EdgeEdgeQuery& q) {
  return {QueryType::edge_edge,
          {rational(q.ea0_t0, "ea0_t0"), rational(q.ea1_t0, "ea1_t0"),
           rational(q.eb0_t0, "eb0_t0"), rational(q.eb1_t0, "eb1_t0"),
           rational(q.ea0_t1, "ea0_t1"), rational(q.ea1_t1, "ea1_t1"),
           rational(q.eb0_t1, "eb0_t1"), rational(q.eb1_t1, "eb1_t1")}};
}

namespace {

/// The exact path with the rational delta (options checked, the FP state set; options'
/// min_separation is not read).
CcdResult exact_with_separation(const RationalQuery& query, const mpq_class& delta,
                                const CcdOptions& options) {
  if (sgn(delta) == 0)
    return query.type == QueryType::vertex_face ? exact::vertex_face_ccd_exact(query, options)
                                                : exact::edge_edge_ccd_exact(query, options);
  return query.type == QueryType::vertex_face
             ? exact::vertex_face_min_separation_exact(query, delta, options)
             : exact::edge_edge_min_separation_exact(query, delta, options);
}

}  // namespace

CcdResult exact_ccd(const RationalQuery& query, const CcdOptions& options) {
  const predicates::RoundToNearestGuard
      nearest;  // the TOI's conversions to doubles compare doubles
  check_ccd_options(options);
  return exact_with_separation(query, mpq_class(options.min_separation), options);
}

CcdResult exact_ccd(const RationalQuery& query, const mpq_class& min_separation,
                    const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  if (options.min_separation != 0.0)
    throw std::invalid_argument(
        "exactccd: give the minimum separation once: options.min_separation or the rational "
        "argument, not both");
  if (sgn(min_separation) < 0)
    throw std::invalid_argument("exactccd: min_separation must be >= 0");
  return exact_with_separation(query, min_separation, options);
}

namespace {

/// The exact path of a double query: the exact stage at double brackets, and the rational path
/// (the reference) past the stage's step caps (never reached on any test or benchmark set).
/// PROOF: proofs/exact_ccd.md#exact-at-double-brackets
CcdResult exact_path_of(const VertexFaceQuery& q, const CcdOptions& options,
                        const exact::IntegerQuery* known = nullptr) {
  if (std::optional<CcdResult> r = exact::vertex_face_ccd_at_doubles(q, options, known)) return *r;
  return exact::vertex_face_ccd_exact(to_rational(q), options);
}

CcdResult exact_path_of(const EdgeEdgeQuery& q, const CcdOptions& options,
                        const exact::IntegerQuery* known = nullptr) {
  if (std::optional<CcdResult> r = exact::edge_edge_ccd_at_doubles(q, options, known)) return *r;
  return exact::edge_edge_ccd_exact(to_rational(q), options);
}

/// The default pipeline after culling: filters, exact path.
template <class Query, class Filter, class Exact>
CcdResult filters_then_exact(const Query& q, const CcdOptions& options, Filter filter,
                             Exact exact_path) {
  CcdResult r;
  exact::ContactExactStageAtDoubles<Query> exact_at_doubles(q);
  const filters::FilterOutcome f = filter(q, options, exact_at_doubles);
  switch (f.verdict) {
    case filters::FilterOutcome::Verdict::no_contact:
      r.decided_by = f.exact_used ? Stage::exact_at_double : Stage::filter;
      return r;
    case filters::FilterOutcome::Verdict::contact:
      r.collides = true;
      r.decided_by = f.exact_used ? Stage::exact_at_double : Stage::filter;
      r.toi_lo = f.toi_lo;
      r.toi_hi = f.toi_hi;
      if (!f.toi_final) {
        if (r.decided_by == Stage::filter) r.decided_by = Stage::filter_exact_toi;
        std::tie(r.toi_lo, r.toi_hi) =
            exact_at_doubles.integer().bisect_root(r.toi_lo, r.toi_hi, options.toi_width);
      }
      return r;
    case filters::FilterOutcome::Verdict::uncertain: break;
  }
  return exact_path(q, options, exact_at_doubles.built());
}

/// The default pipeline: culling, filters, exact path. The culling and filter stages make no
/// heap allocation, nor do the exact stages at double times within their fixed-size bounds;
/// the rational exact path does. A query far from unit scale is first scaled by a power of two
/// when that is exact (the same verdict and TOI; culling, exact, is unaffected by it).
/// PROOF: proofs/filters.md#power-of-two-normalisation
template <class Query, class Culled, class Filter, class Exact>
CcdResult filtered_ccd(const Query& q, const CcdOptions& options, Culled culled, Filter filter,
                       Exact exact_path) {
  if (culled(q)) {
    CcdResult r;
    r.decided_by = Stage::culling;
    return r;
  }
  if (const int s = detail::normalising_exponent(q); s != 0)
    return filters_then_exact(detail::scaled_by_power_of_two(q, s), options, filter, exact_path);
  return filters_then_exact(q, options, filter, exact_path);
}

/// The exact stage of minimum separation at double times for a query (no work until asked).
exact::separation::ExactSignsAtDoubles separation_exact_stage(const VertexFaceQuery& q,
                                                              double delta) {
  return {{&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0},
          {&q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1},
          delta,
          predicates::SeparationPair::vertex_face};
}
exact::separation::ExactSignsAtDoubles separation_exact_stage(const EdgeEdgeQuery& q,
                                                              double delta) {
  return {{&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0},
          {&q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1},
          delta,
          predicates::SeparationPair::edge_edge};
}

/// Minimum-separation CCD, delta = options.min_separation > 0: culling and filters with delta,
/// then the exact procedure; or the common practice (uncertified) in Mode::float_only.
/// PROOF: proofs/min_separation.md#pipeline
template <class Query, class Culled, class Filter, class Exact, class Tolerance>
CcdResult min_separation_ccd(const Query& q, const CcdOptions& options, Culled culled,
                             Filter filter, Exact exact_path, Tolerance tolerance) {
  const double delta = options.min_separation;
  CcdResult r;
  switch (options.mode) {
    case Mode::float_only: return tolerance(q, delta, options.t_max);
    case Mode::exact: return exact_path(to_rational(q), mpq_class(delta), options, {});
    case Mode::filtered: break;
  }
  if (culled(q, delta)) {
    r.decided_by = Stage::culling;
    return r;
  }
  // The exact stage at double times, for the filter to ask where intervals cannot tell (its
  // integer query formed only then).
  const exact::separation::ExactSignsAtDoubles exact_signs = separation_exact_stage(q, delta);
  return separation_result(filter(q, options, exact_signs), [&](const exact::SeparationHint& hint) {
    return exact_path(to_rational(q), mpq_class(delta), options, hint);
  });
}

bool all_finite(const VertexFaceQuery& q) {
  return q.p_t0.allFinite() && q.a_t0.allFinite() && q.b_t0.allFinite() && q.c_t0.allFinite() &&
         q.p_t1.allFinite() && q.a_t1.allFinite() && q.b_t1.allFinite() && q.c_t1.allFinite();
}

bool all_finite(const EdgeEdgeQuery& q) {
  return q.ea0_t0.allFinite() && q.ea1_t0.allFinite() && q.eb0_t0.allFinite() &&
         q.eb1_t0.allFinite() && q.ea0_t1.allFinite() && q.ea1_t1.allFinite() &&
         q.eb0_t1.allFinite() && q.eb1_t1.allFinite();
}

}  // namespace

CcdResult vertex_face_ccd(const VertexFaceQuery& query, const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  if (!all_finite(query)) to_rational(query);  // throws, naming the coordinate
  if (options.min_separation > 0)
    return min_separation_ccd(query, options, filters::vertex_face_separation_culling,
                              filters::vertex_face_separation_filter,
                              exact::vertex_face_min_separation_exact,
                              methods::tolerance_vertex_face_ccd);
  switch (options.mode) {
    case Mode::float_only: return float_only::vertex_face_ccd(query, options);
    case Mode::exact: return exact_path_of(query, options);
    case Mode::filtered: break;
  }
  return filtered_ccd(query, options, filters::vertex_face_ccd_culling,
                      filters::vertex_face_ccd_filter,
                      [](const VertexFaceQuery& q, const CcdOptions& o,
                         const exact::IntegerQuery* known) { return exact_path_of(q, o, known); });
}

CcdResult edge_edge_ccd(const EdgeEdgeQuery& query, const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  if (!all_finite(query)) to_rational(query);  // throws, naming the coordinate
  if (options.min_separation > 0)
    return min_separation_ccd(query, options, filters::edge_edge_separation_culling,
                              filters::edge_edge_separation_filter,
                              exact::edge_edge_min_separation_exact,
                              methods::tolerance_edge_edge_ccd);
  switch (options.mode) {
    case Mode::float_only: return float_only::edge_edge_ccd(query, options);
    case Mode::exact: return exact_path_of(query, options);
    case Mode::filtered: break;
  }
  return filtered_ccd(query, options, filters::edge_edge_ccd_culling, filters::edge_edge_ccd_filter,
                      [](const EdgeEdgeQuery& q, const CcdOptions& o,
                         const exact::IntegerQuery* known) { return exact_path_of(q, o, known); });
}

}  // namespace exactccd
