#include "oracle/inspection.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>
#include <vector>

#include "core/float_only/tolerance_ccd.hpp"
#include "core/predicates/coplanarity_cubic.hpp"
#include "core/predicates/inclusion.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exact/polynomials/root_isolation.hpp"
#include "exact/reference/earliest_contact.hpp"
#include "exact/reference/primitive_contact.hpp"
#include "exact/reference/rigid_ccd.hpp"
#include "exact/stages/rigid_exact_stage.hpp"
#include "corpus/rigid_exact_pose.hpp"
#include "pipeline/rigid_query_check.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/rational_query.hpp"
#include "exactccd/rigid.hpp"
#include "core/predicates/plane_offset.hpp"
#include "oracle/check.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/names.hpp"

namespace exactccd::oracle {
namespace {

using nlohmann::json;
using exact::AlgebraicTime;
using exact::Polynomial;
using exact::Rational;

json time_value(double t) { return std::isfinite(t) ? json(t) : json(nullptr); }

json answer_json(const CcdResult& r) {
  return {{"collides", r.collides},
          {"toi_lo", time_value(r.toi_lo)},
          {"toi_hi", time_value(r.toi_hi)},
          {"decided_by", to_string(r.decided_by)}};
}

std::string exact_text(const Rational& q) { return q.get_str(); }

// The nearest double of each coordinate (+-inf beyond the doubles), for drawing and for the
// double distance samples.
std::array<Eigen::Vector3d, 8> nearest_doubles(const RationalQuery& q) {
  std::array<Eigen::Vector3d, 8> p;
  for (int i = 0; i < 8; ++i)
    p[i] = {exact::round_nearest(q.points[i].x), exact::round_nearest(q.points[i].y),
            exact::round_nearest(q.points[i].z)};
  return p;
}

// The simplest rational in the closed interval [a, b], 0 <= a <= b (the continued fraction of
// the two ends up to where they part): what a reader would write for the root, 2/3 say.
Rational simplest_rational_between(Rational a, Rational b) {
  // Continued-fraction convergents of the answer: h/k = (h1 q + h0) / (k1 q + k0).
  mpz_class h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  for (int guard = 0; guard < 4096; ++guard) {
    mpz_class q;
    mpz_fdiv_q(q.get_mpz_t(), a.get_num_mpz_t(), a.get_den_mpz_t());  // floor(a)
    if (Rational(q) == a || Rational(q + 1) <= b) {  // an integer lies in [a, b]
      const mpz_class n = Rational(q) == a ? q : q + 1;
      return Rational(h1 * n + h0, k1 * n + k0);
    }
    const mpz_class h = h1 * q + h0, k = k1 * q + k0;
    h0 = h1, h1 = h, k0 = k1, k1 = k;
    // [a, b] -> [1 / (b - q), 1 / (a - q)].
    const Rational na = 1 / (b - q), nb = 1 / (a - q);
    a = na, b = nb;
  }
  return Rational(h1, k1);  // not reached for doubles' brackets
}

// The root's exact value when it is rational. A rational root p/q of poly has q dividing the
// leading coefficient L of poly's primitive integer multiple; once t's isolating interval is
// narrower than 1/L^2, the simplest rational inside it (whose denominator is at most q) is
// the root itself, since two rationals of denominators at most L differ by at least 1/L^2.
// So: refine to that width (a bounded number of halvings; beyond it the value is not claimed),
// then test the simplest rational.
std::optional<Rational> rational_root(const Polynomial& poly, AlgebraicTime& t) {
  const mpz_class L = abs(exact::primitive_part(poly).leading().get_num());
  const Rational width_needed(1, L * L);
  for (int halvings = 0; !t.is_rational() && t.hi() - t.lo() >= width_needed; ++halvings) {
    if (halvings == 20000) return std::nullopt;  // coefficients of thousands of digits
    t.refine_once();
  }
  if (t.is_rational()) return t.lo();
  const Rational r = simplest_rational_between(t.lo(), t.hi());
  if (sgn(poly.evaluate(r)) == 0) return r;
  return std::nullopt;
}

// One polynomial of the exact path with its real roots in [0, t_max], each an exact bracket
// and the inclusion test's answer there. `contact_at` is the instant predicate.
// The earliest root passing inclusion so far, and where it is listed: (polynomial, root).
struct Earliest {
  std::optional<AlgebraicTime> time;
  std::size_t polynomial = 0, root = 0;
};

template <class ContactAt>
json polynomial_json(const std::string& name, const Polynomial& poly, const Rational& t_max,
                     ContactAt&& contact_at, Earliest* earliest, std::size_t index) {
  json coefficients_exact = json::array(), coefficients = json::array();
  for (const Rational& c : poly.coefficients()) {
    coefficients_exact.push_back(exact_text(c));
    coefficients.push_back(exact::round_nearest(c));
  }
  json roots = json::array();
  if (poly.degree() >= 1 && sgn(t_max) > 0) {
    for (AlgebraicTime& t : exact::real_roots_in(poly, Rational(0), t_max)) {
      const bool inclusion = contact_at(t);
      if (inclusion && (!earliest->time || exact::compare(t, *earliest->time) < 0))
        *earliest = {t, index, roots.size()};
      const auto [lo, hi] = t.enclosure(0.0);  // refines t's interval: then look for a rational
      std::optional<Rational> value = rational_root(poly, t);
      roots.push_back({{"lo", lo},
                       {"hi", hi},
                       {"exact", value ? json(exact_text(*value)) : json(nullptr)},
                       {"inclusion", inclusion},
                       {"earliest", false}});
    }
  }
  return {{"name", name},
          {"coefficients_exact", coefficients_exact},
          {"coefficients", coefficients},
          {"identically_zero", poly.is_zero()},
          {"roots", roots}};
}

// Marks the earliest root that passes inclusion: the contact, unless it is at t = 0.
void mark_earliest(json& polynomials, const Earliest& earliest) {
  if (earliest.time) polynomials[earliest.polynomial]["roots"][earliest.root]["earliest"] = true;
}

// The polynomials that decide a contact query of four moving points y (any moving-point type
// of the exact path) given its coplanarity polynomial: that polynomial, or, when it vanishes
// identically, the vertex-edge candidates of the coplanar case (and t = 0).
// PROOF: proofs/exact_ccd.md#theorem-1
template <class Point>
json contact_polynomials(QueryType type, const std::array<Point, 4>& y,
                         const Polynomial& coplanarity, const std::string& name,
                         const Rational& t_max, bool* contact_at_start) {
  json polynomials = json::array();
  Earliest earliest;
  *contact_at_start = false;
  auto contact_at = [&](AlgebraicTime& t) {
    return type == QueryType::vertex_face
               ? predicates::point_in_triangle_at(y[0], y[1], y[2], y[3], exact::sign_at(t))
               : predicates::segments_intersect_at(y[0], y[1], y[2], y[3], exact::sign_at(t));
  };
  polynomials.push_back(polynomial_json(name, coplanarity, t_max, contact_at, &earliest, 0));
  if (coplanarity.is_zero()) {
    AlgebraicTime start = AlgebraicTime::rational(Rational(0));
    *contact_at_start = contact_at(start);
    using exact::vertex_edge_candidates;
    if (type == QueryType::vertex_face) {
      const char* names[] = {"p against side ab", "p against side bc", "p against side ca"};
      const Polynomial sides[] = {vertex_edge_candidates(y[0], y[1], y[2]),
                                  vertex_edge_candidates(y[0], y[2], y[3]),
                                  vertex_edge_candidates(y[0], y[3], y[1])};
      for (int k = 0; k < 3; ++k)
        polynomials.push_back(
            polynomial_json(names[k], sides[k], t_max, contact_at, &earliest, polynomials.size()));
    } else {
      const char* names[] = {"ea0 against edge b", "ea1 against edge b", "eb0 against edge a",
                             "eb1 against edge a"};
      const Polynomial ends[] = {
          vertex_edge_candidates(y[0], y[2], y[3]), vertex_edge_candidates(y[1], y[2], y[3]),
          vertex_edge_candidates(y[2], y[0], y[1]), vertex_edge_candidates(y[3], y[0], y[1])};
      for (int k = 0; k < 4; ++k)
        polynomials.push_back(
            polynomial_json(names[k], ends[k], t_max, contact_at, &earliest, polynomials.size()));
    }
  }
  if (!*contact_at_start) mark_earliest(polynomials, earliest);
  return polynomials;
}

// The linear query's polynomials: the coplanarity cubic of its moving points.
json contact_polynomials(const RationalQuery& q, const Rational& t_max, bool* contact_at_start) {
  const auto& v = q.points;
  using exact::moving;
  const std::array<predicates::MovingPoint<Rational>, 4> y = {
      moving(v[0], v[4]), moving(v[1], v[5]), moving(v[2], v[6]), moving(v[3], v[7])};
  const bool vf = q.type == QueryType::vertex_face;
  const Polynomial cubic(vf ? predicates::vertex_face_coplanarity_cubic(y[0], y[1], y[2], y[3])
                            : predicates::edge_edge_coplanarity_cubic(y[0], y[1], y[2], y[3]));
  return contact_polynomials(q.type, y, cubic,
                             vf ? "coplanarity cubic det[b - a, c - a, p - a](t)"
                                : "coplanarity cubic det[ea1 - ea0, eb0 - ea0, eb1 - ea0](t)",
                             t_max, contact_at_start);
}

// The distance between the primitives of four points, computed on the points scaled by a power
// of two to unit size and scaled back (exact scalings: squared norms of points 1e-100 or 1e300
// apart neither underflow nor overflow).
double primitive_distance(QueryType type, std::array<Eigen::Vector3d, 4> p) {
  double m = 0;
  for (const auto& x : p) m = std::max(m, x.cwiseAbs().maxCoeff());
  if (!std::isfinite(m)) return std::numeric_limits<double>::quiet_NaN();
  int e = 0;
  if (m > 0) std::frexp(m, &e);
  for (auto& x : p)
    for (int k = 0; k < 3; ++k) x[k] = std::ldexp(x[k], -e);
  // The tolerance method's distances in double (core/float_only): for display only.
  const double d = type == QueryType::vertex_face
                       ? methods::point_triangle_distance(p[0], p[1], p[2], p[3])
                       : methods::segment_segment_distance(p[0], p[1], p[2], p[3]);
  return std::ldexp(d, e);
}

json distance_samples(const std::array<Eigen::Vector3d, 8>& x, QueryType type, double t_max,
                      double delta) {
  constexpr int kSamples = 400;
  json samples = json::array();
  for (int i = 0; i <= kSamples; ++i) {
    const double t = t_max * i / kSamples;
    std::array<Eigen::Vector3d, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = x[k] + t * (x[k + 4] - x[k]);
    const double d = primitive_distance(type, p);
    if (std::isfinite(d)) samples.push_back({t, d});  // beyond the doubles: no sample
  }
  return {{"delta", delta}, {"samples", samples}};
}

json enclosures_json(const std::array<Enclosure, 3>& e, int count = 3) {
  json out = json::array();
  for (int k = 0; k < count; ++k) out.push_back({e[k].lo, e[k].hi});
  return out;
}

json geometry_json(const ContactGeometry& g) {
  return {{"kind", to_string(g.kind)},
          {"point", enclosures_json(g.point)},
          {"normal", enclosures_json(g.normal)},
          {"normal_oriented", g.normal_oriented},
          {"parameters", enclosures_json(g.parameters, g.parameter_count)}};
}

}  // namespace

std::string inspection_json(const QueryRecord& record, QueryType type, const std::string& source,
                            std::size_t index, const InspectSettings& settings,
                            const GradedAnswer* graded) {
  RationalQuery q = record.query;
  q.type = type;
  CcdOptions options;
  options.t_max = settings.t_max;
  options.min_separation = settings.min_separation;
  const CcdResult exact_answer = exact_ccd(q, options);  // validates the options

  std::size_t bad_row = 0;
  const std::optional<QueryPoints> doubles = exact_doubles(q, &bad_row);
  if (!doubles && settings.mode != Mode::exact)
    throw InputError(source, record.line_of_row(bad_row),
                     std::string("a coordinate is not a double: mode ") + to_string(settings.mode) +
                         " decides double queries; use --mode exact");
  const auto x = nearest_doubles(q);
  const bool vf = type == QueryType::vertex_face;

  CcdResult answer = exact_answer, float_answer;
  bool float_computable = true;
  CcdOptions float_options = options;
  float_options.mode = Mode::float_only;
  json contact = nullptr;
  if (doubles) {
    options.mode = settings.mode;
    const VertexFaceQuery vfq = vertex_face_query(*doubles);
    const EdgeEdgeQuery eeq = edge_edge_query(*doubles);
    answer = vf ? vertex_face_ccd(vfq, options) : edge_edge_ccd(eeq, options);
    float_answer = vf ? vertex_face_ccd(vfq, float_options) : edge_edge_ccd(eeq, float_options);
    if (exact_answer.collides)
      contact = geometry_json(vf ? contact_geometry(vfq, exact_answer, settings.min_separation)
                                 : contact_geometry(eeq, exact_answer, settings.min_separation));
  } else if (std::all_of(x.begin(), x.end(), [](const Eigen::Vector3d& v) { return v.allFinite(); })) {
    const VertexFaceQuery vfq = vertex_face_query(x);
    const EdgeEdgeQuery eeq = edge_edge_query(x);
    float_answer = vf ? vertex_face_ccd(vfq, float_options) : edge_edge_ccd(eeq, float_options);
  } else {
    float_computable = false;  // a coordinate beyond the doubles: no double query to give it
  }

  json points_exact = json::array(), points = json::array();
  for (int i = 0; i < 8; ++i) {
    const RationalPoint& p = q.points[i];
    points_exact.push_back({exact_text(p.x), exact_text(p.y), exact_text(p.z)});
    points.push_back({x[i].x(), x[i].y(), x[i].z()});
  }

  json doc;
  doc["format"] = "exactccd-inspection";
  doc["version"] = 1;
  doc["title"] = std::string(vf ? "vertex-face" : "edge-edge") + " query " +
                 std::to_string(index) + " of " + source;
  doc["source"] = {{"file", source}, {"index", index}, {"first_line", record.first_line}};
  doc["kind"] = vf ? "vertex_face" : "edge_edge";
  doc["motion"] = "linear";
  doc["t_max"] = settings.t_max;
  doc["min_separation"] = settings.min_separation;
  doc["labels"] = vf ? json{"p", "a", "b", "c"} : json{"ea0", "ea1", "eb0", "eb1"};
  doc["points_exact"] = points_exact;
  doc["points"] = points;
  doc["points_are_doubles"] = doubles.has_value();
  doc["truth"] = record.truth;
  doc["result"] = answer_json(answer);
  doc["result"]["mode"] = to_string(settings.mode);
  doc["exact"] = answer_json(exact_answer);
  if (float_computable) {
    doc["float_only"] = answer_json(float_answer);
    doc["float_only"]["wrong"] = float_answer.collides != exact_answer.collides;
    doc["float_only"]["on_rounded_points"] = !doubles.has_value();
  } else {
    doc["float_only"] = nullptr;
  }
  doc["contact"] = contact;
  bool at_start = false;
  if (settings.min_separation == 0.0) {
    doc["polynomials"] = contact_polynomials(q, Rational(settings.t_max), &at_start);
    doc["distance"] = nullptr;
  } else {
    doc["polynomials"] = json::array();
    doc["distance"] = distance_samples(x, type, settings.t_max, settings.min_separation);
  }
  doc["contact_at_start_coplanar"] = at_start;
  if (graded)
    doc["graded"] = {{"finding", graded->finding},
                     {"collides", graded->collides},
                     {"toi_exact", graded->toi ? json(*graded->toi) : json(nullptr)},
                     {"toi", graded->toi ? json(graded->toi_double) : json(nullptr)}};
  return doc.dump(-1, ' ', false, json::error_handler_t::replace);  // file names: any bytes
}

namespace {

json rigid_answer_json(const RigidCcdResult& r) {
  json a = answer_json(r.ccd);
  a["has_time"] = r.has_time;
  a["time_lo"] = r.has_time ? time_value(r.time_lo) : json(nullptr);
  a["time_hi"] = r.has_time ? time_value(r.time_hi) : json(nullptr);
  return a;
}

// The four points of a rigid query at s, exactly: a rigid side by its Cayley motion
// (corpus/rigid_exact_pose.hpp, the matrix form), a linear side on its straight lines.
std::array<rigid_pose::RationalPosition, 4> exact_points_at(const Eigen::Vector3d (&start)[4],
                                                            const SideMotion (&side)[2],
                                                            int first_side_points,
                                                            const mpq_class& s) {
  std::array<rigid_pose::RationalPosition, 4> out;
  for (int i = 0; i < 4; ++i) {
    const bool second = i >= first_side_points;
    const SideMotion& m = side[second ? 1 : 0];
    if (m.kind == PathKind::rigid) {
      out[i] = rigid_pose::exact_position(m.rigid, start[i], s);
    } else {
      const Eigen::Vector3d& end = m.linear_end[second ? i - first_side_points : i];
      for (int k = 0; k < 3; ++k)
        out[i][k] = mpq_class(start[i][k]) + s * (mpq_class(end[k]) - mpq_class(start[i][k]));
    }
  }
  return out;
}

// A query decided in `mode` with the page's t_max and minimum separation (any query type the
// library's overloads take).
template <class Query, class Decide>
auto decided(const Query& q, const InspectSettings& settings, Mode mode, Decide&& decide) {
  CcdOptions options;
  options.t_max = settings.t_max;
  options.min_separation = settings.min_separation;
  options.mode = mode;
  return decide(q, options);
}

// The parameters a rigid page samples: 64 pieces of [0, t_max], and the TOIs' lower ends (where
// the page opens), sorted and distinct.
std::vector<double> sample_parameters(double t_max, std::initializer_list<const RigidCcdResult*> at) {
  std::vector<double> times;
  for (int k = 0; k <= 64; ++k) times.push_back(t_max * k / 64);
  for (const RigidCcdResult* r : at)
    if (r->ccd.collides) times.push_back(r->ccd.toi_lo);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

template <class Query>
std::string rigid_inspection(const Query& query, QueryType type, const Eigen::Vector3d (&start)[4],
                             const SideMotion (&side)[2], const InspectSettings& settings,
                             const std::string& title, const std::string& source,
                             const std::vector<std::string>& labels,
                             std::optional<std::size_t> step) {
  const bool vf = type == QueryType::vertex_face;
  const int first_side_points = vf ? 1 : 2;
  auto decide = [&](Mode mode) {
    return decided(query, settings, mode, [](const Query& q, const CcdOptions& o) {
      if constexpr (std::is_same_v<Query, RigidVertexFaceQuery>)
        return vertex_face_ccd(q, o);
      else
        return edge_edge_ccd(q, o);
    });
  };
  const RigidCcdResult exact_answer = decide(Mode::exact);
  const RigidCcdResult answer = decide(settings.mode);
  const RigidCcdResult float_answer = decide(Mode::float_only);

  // Samples of s: 64 pieces of [0, t_max], and the TOI's lower end, where the page shows the
  // contact: each position exact, then rounded to the nearest double.
  const std::vector<double> times = sample_parameters(settings.t_max, {&exact_answer, &answer});
  json positions = json::array();
  std::vector<std::array<Eigen::Vector3d, 4>> rounded;
  for (double s : times) {
    const auto exact_points = exact_points_at(start, side, first_side_points, mpq_class(s));
    json snapshot = json::array();
    std::array<Eigen::Vector3d, 4> r;
    for (int i = 0; i < 4; ++i) {
      for (int k = 0; k < 3; ++k) r[i][k] = exact::round_nearest(exact_points[i][k]);
      snapshot.push_back({r[i].x(), r[i].y(), r[i].z()});
    }
    positions.push_back(snapshot);
    rounded.push_back(r);
  }
  json points_exact = json::array(), points = json::array();
  for (const mpq_class& s : {mpq_class(0), mpq_class(1)}) {  // as the linear kinds: t = 0, 1
    const auto exact_points = exact_points_at(start, side, first_side_points, s);
    for (const auto& p : exact_points) {
      points_exact.push_back({exact_text(p[0]), exact_text(p[1]), exact_text(p[2])});
      points.push_back({exact::round_nearest(p[0]), exact::round_nearest(p[1]),
                        exact::round_nearest(p[2])});
    }
  }

  json doc;
  doc["format"] = "exactccd-inspection";
  doc["version"] = 1;
  doc["title"] = title;
  doc["source"] = {{"file", source}};
  if (step) doc["source"]["step"] = *step;
  doc["kind"] = vf ? "vertex_face" : "edge_edge";
  doc["motion"] = "samples";
  doc["parameter"] = "s";
  doc["trajectory"] = {{"times", times}, {"positions", positions}};
  doc["t_max"] = settings.t_max;
  doc["min_separation"] = settings.min_separation;
  doc["labels"] = labels;
  doc["points_exact"] = points_exact;
  doc["points"] = points;
  doc["points_are_doubles"] = false;
  doc["truth"] = nullptr;
  doc["result"] = rigid_answer_json(answer);
  doc["result"]["mode"] = to_string(settings.mode);
  doc["exact"] = rigid_answer_json(exact_answer);
  doc["float_only"] = rigid_answer_json(float_answer);
  doc["float_only"]["wrong"] = float_answer.ccd.collides != exact_answer.ccd.collides;
  doc["contact"] = exact_answer.ccd.collides
                       ? geometry_json(contact_geometry(query, exact_answer,
                                                        settings.min_separation))
                       : json(nullptr);
  bool at_start = false;
  if (settings.min_separation == 0.0) {
    const exact::RationalRigidQuery rq = exact::rational_query(pipeline::checked_query(query));
    doc["polynomials"] = contact_polynomials(
        type, exact::common_denominator_points(rq), exact::rigid_coplanarity_polynomial(rq),
        "reduced rigid coplanarity polynomial g(s)", Rational(settings.t_max), &at_start);
    doc["distance"] = nullptr;
  } else {
    json samples = json::array();
    for (std::size_t j = 0; j < times.size(); ++j) {
      const auto& p = rounded[j];
      const double d = primitive_distance(type, p);
      if (std::isfinite(d)) samples.push_back({times[j], d});
    }
    doc["polynomials"] = json::array();
    doc["distance"] = {{"delta", settings.min_separation}, {"samples", samples}};
  }
  doc["contact_at_start_coplanar"] = at_start;
  return doc.dump(-1, ' ', false, json::error_handler_t::replace);  // file names: any bytes
}

}  // namespace

std::string rigid_inspection_json(const RigidVertexFaceQuery& q, const InspectSettings& settings,
                                  const std::string& title, const std::string& source,
                                  const std::vector<std::string>& labels,
                                  std::optional<std::size_t> step) {
  const Eigen::Vector3d start[4] = {q.p, q.a, q.b, q.c};
  const SideMotion side[2] = {q.vertex, q.face};
  return rigid_inspection(q, QueryType::vertex_face, start, side, settings, title, source, labels, step);
}

std::string rigid_inspection_json(const RigidEdgeEdgeQuery& q, const InspectSettings& settings,
                                  const std::string& title, const std::string& source,
                                  const std::vector<std::string>& labels,
                                  std::optional<std::size_t> step) {
  const Eigen::Vector3d start[4] = {q.ea0, q.ea1, q.eb0, q.eb1};
  const SideMotion side[2] = {q.edge_a, q.edge_b};
  return rigid_inspection(q, QueryType::edge_edge, start, side, settings, title, source, labels, step);
}

namespace {

// The plane offset polynomial's page data: its roots (every one a contact: the plane is
// infinite), the earliest marked, unless the point lies in the plane throughout.
json plane_offset_polynomials(const Polynomial& f, const std::string& name, const Rational& t_max,
                              bool* in_plane_throughout) {
  Earliest earliest;
  json polynomials = json::array();
  polynomials.push_back(
      polynomial_json(name, f, t_max, [](AlgebraicTime&) { return true; }, &earliest, 0));
  *in_plane_throughout = f.is_zero();
  mark_earliest(polynomials, earliest);
  return polynomials;
}

// |(p - o) . n| / |n| in double, on vectors scaled to unit size by powers of two (display only).
double plane_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& o, Eigen::Vector3d n) {
  Eigen::Vector3d v = p - o;
  int ev = 0, en = 0;
  const double mv = v.cwiseAbs().maxCoeff(), mn = n.cwiseAbs().maxCoeff();
  if (!std::isfinite(mv) || !(mn > 0) || !std::isfinite(mn))
    return std::numeric_limits<double>::quiet_NaN();
  if (mv > 0) std::frexp(mv, &ev);
  std::frexp(mn, &en);
  for (int k = 0; k < 3; ++k) v[k] = std::ldexp(v[k], -ev), n[k] = std::ldexp(n[k], -en);
  return std::ldexp(std::fabs(v.dot(n)) / n.norm(), ev);
}

json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
json exact_vector_json(const Eigen::Vector3d& v) {
  return {exact_text(Rational(v.x())), exact_text(Rational(v.y())), exact_text(Rational(v.z()))};
}

// The fields every point-plane page has.
json point_plane_document(const PointPlaneSource& source, const InspectSettings& settings) {
  json doc;
  doc["format"] = "exactccd-inspection";
  doc["version"] = 1;
  doc["title"] = source.title;
  doc["source"] = {{"file", source.file}};
  if (source.index) doc["source"]["index"] = *source.index;
  if (source.first_line) doc["source"]["first_line"] = *source.first_line;
  if (source.step) doc["source"]["step"] = *source.step;
  doc["kind"] = "point_plane";
  doc["labels"] = {"p", "o"};
  doc["t_max"] = settings.t_max;
  doc["min_separation"] = settings.min_separation;
  doc["truth"] = source.truth ? json(*source.truth) : json(nullptr);
  doc["points_are_doubles"] = true;
  return doc;
}

}  // namespace

std::string point_plane_inspection_json(const PointPlaneQuery& q, const InspectSettings& settings,
                                        const PointPlaneSource& source) {
  auto decide = [&](Mode mode) {
    return decided(q, settings, mode,
                   [](const PointPlaneQuery& x, const CcdOptions& o) { return point_plane_ccd(x, o); });
  };
  const CcdResult exact_answer = decide(Mode::exact), answer = decide(settings.mode),
                  float_answer = decide(Mode::float_only);
  json doc = point_plane_document(source, settings);
  doc["motion"] = "linear";
  doc["points_exact"] = {exact_vector_json(q.p_t0), exact_vector_json(q.origin_t0),
                         exact_vector_json(q.p_t1), exact_vector_json(q.origin_t1)};
  doc["points"] = {vector_json(q.p_t0), vector_json(q.origin_t0), vector_json(q.p_t1),
                   vector_json(q.origin_t1)};
  doc["plane_normal"] = {{"exact", {exact_vector_json(q.normal_t0), exact_vector_json(q.normal_t1)}},
                         {"double", {vector_json(q.normal_t0), vector_json(q.normal_t1)}}};
  doc["result"] = answer_json(answer);
  doc["result"]["mode"] = to_string(settings.mode);
  doc["exact"] = answer_json(exact_answer);
  doc["float_only"] = answer_json(float_answer);
  doc["float_only"]["wrong"] = float_answer.collides != exact_answer.collides;
  doc["contact"] = exact_answer.collides
                       ? geometry_json(contact_geometry(q, exact_answer, settings.min_separation))
                       : json(nullptr);
  bool in_plane = false;
  if (settings.min_separation == 0.0) {
    doc["polynomials"] = plane_offset_polynomials(
        Polynomial(predicates::linear_plane_offset<Rational>(q)),
        "plane offset f(t) = (p - o) . n", Rational(settings.t_max), &in_plane);
    doc["distance"] = nullptr;
  } else {
    json samples = json::array();
    for (int i = 0; i <= 400; ++i) {
      const double t = settings.t_max * i / 400;
      const double d = plane_distance(q.p_t0 + t * (q.p_t1 - q.p_t0),
                                      q.origin_t0 + t * (q.origin_t1 - q.origin_t0),
                                      q.normal_t0 + t * (q.normal_t1 - q.normal_t0));
      if (std::isfinite(d)) samples.push_back({t, d});
    }
    doc["polynomials"] = json::array();
    doc["distance"] = {{"delta", settings.min_separation}, {"samples", samples}};
  }
  doc["contact_at_start_coplanar"] = in_plane;
  return doc.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string rigid_point_plane_inspection_json(const RigidPointPlaneQuery& q,
                                              const InspectSettings& settings,
                                              const PointPlaneSource& source) {
  auto decide = [&](Mode mode) {
    return decided(q, settings, mode, [](const RigidPointPlaneQuery& x, const CcdOptions& o) {
      return point_plane_ccd(x, o);
    });
  };
  const RigidCcdResult exact_answer = decide(Mode::exact), answer = decide(settings.mode),
                       float_answer = decide(Mode::float_only);
  // Samples of s as for the other rigid pages: the exact pose rounded to nearest.
  const std::vector<double> times = sample_parameters(settings.t_max, {&exact_answer, &answer});
  auto at = [&](const mpq_class& s) {
    const auto x = rigid_pose::exact_position(q.motion, q.p, s);
    return std::pair(Eigen::Vector3d(exact::round_nearest(x[0]), exact::round_nearest(x[1]),
                                     exact::round_nearest(x[2])),
                     json{exact_text(x[0]), exact_text(x[1]), exact_text(x[2])});
  };
  json positions = json::array(), samples = json::array();
  for (double s : times) {
    const Eigen::Vector3d p = at(mpq_class(s)).first;
    positions.push_back({vector_json(p), vector_json(q.origin)});
    const double d = plane_distance(p, q.origin, q.normal);
    if (std::isfinite(d)) samples.push_back({s, d});
  }
  json doc = point_plane_document(source, settings);
  doc["motion"] = "samples";
  doc["parameter"] = "s";
  doc["trajectory"] = {{"times", times}, {"positions", positions}};
  const auto [p1, p1_exact] = at(mpq_class(1));
  doc["points_exact"] = {exact_vector_json(q.p), exact_vector_json(q.origin), p1_exact,
                         exact_vector_json(q.origin)};
  doc["points"] = {vector_json(q.p), vector_json(q.origin), vector_json(p1), vector_json(q.origin)};
  doc["points_are_doubles"] = false;
  doc["plane_normal"] = {{"exact", {exact_vector_json(q.normal), exact_vector_json(q.normal)}},
                         {"double", {vector_json(q.normal), vector_json(q.normal)}}};
  doc["result"] = rigid_answer_json(answer);
  doc["result"]["mode"] = to_string(settings.mode);
  doc["exact"] = rigid_answer_json(exact_answer);
  doc["float_only"] = rigid_answer_json(float_answer);
  doc["float_only"]["wrong"] = float_answer.ccd.collides != exact_answer.ccd.collides;
  doc["contact"] = exact_answer.ccd.collides
                       ? geometry_json(contact_geometry(q, exact_answer, settings.min_separation))
                       : json(nullptr);
  bool in_plane = false;
  if (settings.min_separation == 0.0) {
    doc["polynomials"] = plane_offset_polynomials(
        Polynomial(predicates::rigid_plane_offset<Rational>(q, nullptr)),
        "plane offset numerator F(s) = (X(s) - o w(s)) . n (the offset is F / w, w > 0)",
        Rational(settings.t_max), &in_plane);
    doc["distance"] = nullptr;
  } else {
    doc["polynomials"] = json::array();
    doc["distance"] = {{"delta", settings.min_separation}, {"samples", samples}};
  }
  doc["contact_at_start_coplanar"] = in_plane;
  return doc.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string inspect_file_query(const std::string& path, std::optional<QueryType> type,
                               std::size_t index, const InspectSettings& settings,
                               std::optional<PrimitiveKind> primitive) {
  auto check_index = [&](std::size_t count) {
    if (count == 0) throw InputError(path, 0, "the file holds no query");
    if (index >= count)
      throw InputError(path, 0,
                       "index " + std::to_string(index) + " is past the end: the file has " +
                           std::to_string(count) + " queries (0-based indices 0 to " +
                           std::to_string(count - 1) + ")");
  };
  if (primitive) {
    const PrimitiveQueryFile file = read_primitive_query_file(path, *primitive);
    check_index(file.queries.size());
    if (*primitive != PrimitiveKind::point_plane) {  // the edge-edge query of its segments
      const QueryFile as_segments = as_edge_edge_file(file);
      return inspection_json(as_segments.queries[index], QueryType::edge_edge, path, index,
                             settings);
    }
    const PrimitiveQueryRecord& record = file.queries[index];
    double x[6][3];
    for (int row = 0; row < 6; ++row)
      for (int k = 0; k < 3; ++k) {
        const RationalPoint& p = record.points[row];
        if (!exact::to_double_exactly(k == 0 ? p.x : k == 1 ? p.y : p.z, &x[row][k]))
          throw InputError(path, record.first_line + row,
                           "a coordinate is not a double (point-plane queries take doubles)");
      }
    auto v = [&](int row) { return Eigen::Vector3d(x[row][0], x[row][1], x[row][2]); };
    const PointPlaneQuery q{v(0), v(1), v(2), v(3), v(4), v(5)};
    PointPlaneSource source{path, index, record.first_line, std::nullopt, record.truth,
                            "point-plane query " + std::to_string(index) + " of " + path};
    try {
      return point_plane_inspection_json(q, settings, source);
    } catch (const std::invalid_argument& e) {  // a zero normal: bad input, named
      throw InputError(path, record.first_line, e.what());
    }
  }
  const QueryType resolved = resolve_query_type(path, type);
  const QueryFile file = read_query_file(path, resolved);
  check_index(file.queries.size());
  return inspection_json(file.queries[index], resolved, path, index, settings);
}

std::string inspection_text(const std::string& text) {
  const json doc = json::parse(text);
  std::ostringstream out;
  out.precision(17);
  auto toi = [&](const json& a) {
    std::ostringstream s;
    s.precision(17);
    if (a["toi_lo"].is_null()) return std::string("+infinity (no contact)");
    s << "[" << a["toi_lo"].get<double>() << ", " << a["toi_hi"].get<double>() << "]";
    return s.str();
  };
  const json& r = doc["result"];
  out << doc["title"].get<std::string>() << "\n";
  out << "  " << r["mode"].get<std::string>() << ": "
      << (r["collides"].get<bool>() ? "collides" : "no contact") << ", toi " << toi(r)
      << ", decided by " << r["decided_by"].get<std::string>() << "\n";
  out << "  exact: " << (doc["exact"]["collides"].get<bool>() ? "collides" : "no contact")
      << ", toi " << toi(doc["exact"]);
  if (doc["truth"].is_boolean()) out << "; truth column: " << (doc["truth"].get<bool>() ? "1" : "0");
  out << "\n";
  if (doc["float_only"].is_null())
    out << "  float_only: not run (a coordinate is beyond the doubles)\n";
  else
    out << "  float_only: "
        << (doc["float_only"]["collides"].get<bool>() ? "collides" : "no contact")
        << (doc["float_only"]["wrong"].get<bool>() ? " (WRONG)" : " (right)") << "\n";
  for (const json& p : doc["polynomials"]) {
    out << "  " << p["name"].get<std::string>() << ":";
    if (p["identically_zero"].get<bool>()) out << " identically zero";
    if (!p["identically_zero"].get<bool>() && p["roots"].empty()) out << " no root in [0, t_max]";
    for (const json& root : p["roots"])
      out << " root " << (root["exact"].is_string() ? root["exact"].get<std::string>() + " " : "")
          << "in [" << root["lo"].get<double>() << ", " << root["hi"].get<double>() << "] "
          << (root["inclusion"].get<bool>() ? "inside" : "outside")
          << (root["earliest"].get<bool>() ? " (earliest contact)" : "") << ";";
    out << "\n";
  }
  if (doc["contact_at_start_coplanar"].get<bool>())
    out << "  coplanar throughout, in contact at t = 0\n";
  return out.str();
}

}  // namespace exactccd::oracle
