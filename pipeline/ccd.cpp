// The public entry points: input validation, then the path the options choose.
#include "exactccd/ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <optional>
#include <tuple>

#include "core/predicates/fp_environment.hpp"
#include "core/predicates/query_points.hpp"
#include "exact/reference/exact_ccd.hpp"
#include "exact/reference/min_separation.hpp"
#include "exactccd/rational_query.hpp"
#include "pipeline/ccd_options_check.hpp"
#include "pipeline/dispatch.hpp"
#include "pipeline/held_at_start.hpp"
#include "pipeline/linear_problems.hpp"

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
    case Mode::filtered: return "filtered";
    case Mode::float_only: return "float_only";
    case Mode::exact: return "exact";
  }
  return "unknown";
}

const char* to_string(QueryType type) noexcept {
  switch (type) {
    case QueryType::vertex_face: return "vertex-face";
    case QueryType::edge_edge: return "edge-edge";
    case QueryType::point_edge: return "point-edge";
    case QueryType::point_point: return "point-point";
    case QueryType::point_plane: return "point-plane";
  }
  return "unknown";
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
  const mpq_class delta(options.min_separation);
  const auto decide = [&](const RationalQuery& q, const CcdOptions& o) {
    return exact_with_separation(q, delta, o);
  };
  if (options.t_max == 0.0) return pipeline::decided_at_start(query, options, decide);
  return pipeline::with_start_flag(decide(query, options), query, options, decide);
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
  const auto decide = [&](const RationalQuery& q, const CcdOptions& o) {
    return exact_with_separation(q, min_separation, o);
  };
  if (options.t_max == 0.0) return pipeline::decided_at_start(query, options, decide);
  return pipeline::with_start_flag(decide(query, options), query, options, decide);
}

namespace {

/// Validation and the FP state, then the one pipeline's instance the options name.
template <class Query>
CcdResult linear_ccd(const Query& query, const CcdOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  check_ccd_options(options);
  if (!predicates::all_finite(query)) to_rational(query);  // throws, naming the coordinate
  if (options.min_separation > 0)
    return pipeline::certified_ccd<pipeline::LinearSeparation<Query>>(query, options);
  return pipeline::certified_ccd<pipeline::LinearContact<Query>>(query, options);
}

}  // namespace

CcdResult vertex_face_ccd(const VertexFaceQuery& query, const CcdOptions& options) {
  return linear_ccd(query, options);
}

CcdResult edge_edge_ccd(const EdgeEdgeQuery& query, const CcdOptions& options) {
  return linear_ccd(query, options);
}

}  // namespace exactccd
