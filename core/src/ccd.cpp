// The public entry points: input validation, then the path the options choose.
#include "exactccd/ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "exact/exact_ccd.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd {

const char* to_string(Stage stage) noexcept {
  switch (stage) {
    case Stage::exact: return "exact";
  }
  return "unknown";
}

const char* to_string(QueryType type) noexcept {
  return type == QueryType::vertex_face ? "vertex-face" : "edge-edge";
}

namespace {

void validate(const CcdOptions& o) {
  if (!(o.t_max > 0.0 && o.t_max <= 1.0))
    throw std::invalid_argument("exactccd: t_max must lie in (0, 1], got " +
                                std::to_string(o.t_max));
  if (!(o.toi_width >= 0.0) || !std::isfinite(o.toi_width))
    throw std::invalid_argument("exactccd: toi_width must be finite and >= 0");
}

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

CcdResult exact_ccd(const RationalQuery& query, const CcdOptions& options) {
  validate(options);
  return query.type == QueryType::vertex_face ? exact::vertex_face_ccd_exact(query, options)
                                              : exact::edge_edge_ccd_exact(query, options);
}

CcdResult vertex_face_ccd(const VertexFaceQuery& query, const CcdOptions& options) {
  validate(options);
  return exact::vertex_face_ccd_exact(to_rational(query), options);
}

CcdResult edge_edge_ccd(const EdgeEdgeQuery& query, const CcdOptions& options) {
  validate(options);
  return exact::edge_edge_ccd_exact(to_rational(query), options);
}

}  // namespace exactccd
