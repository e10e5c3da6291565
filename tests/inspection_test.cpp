// What `exactccd inspect` reports (oracle/inspection.hpp), checked against CGAL's exact kernel:
// each root bracket holds a sign change of CGAL's orientation of the four moving points, no
// sign change of it is left without a root, the inclusion test at each rational root is CGAL's
// intersection test, and the root marked earliest is the exact answer's TOI. On the sample
// queries, the degenerate suite, and hand-made queries; and the page that carries the data.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "corpus/point_families.hpp"
#include "corpus/rigid_exact_pose.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/rational_query.hpp"
#include "oracle/inspection.hpp"
#include "oracle/inspector_page.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using exactccd::QueryRecord;
using exactccd::QueryType;
using exactccd::oracle::InspectSettings;
using Kernel = CGAL::Simple_cartesian<CGAL::Gmpq>;
using Point = Kernel::Point_3;

CGAL::Gmpq gmpq(const mpq_class& q) { return CGAL::Gmpq(q.get_str()); }

// The query's point k (0-3) at the rational time t.
Point at(const exactccd::RationalQuery& q, int k, const mpq_class& t) {
  const auto& a = q.points[k];
  const auto& b = q.points[k + 4];
  return Point(gmpq(a.x + t * (b.x - a.x)), gmpq(a.y + t * (b.y - a.y)),
               gmpq(a.z + t * (b.z - a.z)));
}

// CGAL's sign of det[x1 - x0, x2 - x0, x3 - x0] at t: the coplanarity cubic's sign, up to the
// sign convention (only sign changes are compared).
int orientation_at(const exactccd::RationalQuery& q, const mpq_class& t) {
  return static_cast<int>(CGAL::orientation(at(q, 0, t), at(q, 1, t), at(q, 2, t), at(q, 3, t)));
}

// CGAL's contact test at the rational time t (nullopt for a degenerate primitive, which CGAL's
// predicates do not take).
std::optional<bool> contact_at(const exactccd::RationalQuery& q, QueryType type,
                               const mpq_class& t) {
  const Point x0 = at(q, 0, t), x1 = at(q, 1, t), x2 = at(q, 2, t), x3 = at(q, 3, t);
  if (type == QueryType::vertex_face) {
    const Kernel::Triangle_3 triangle(x1, x2, x3);
    if (triangle.is_degenerate()) return std::nullopt;
    return CGAL::do_intersect(triangle, x0);
  }
  if (x0 == x1 || x2 == x3) return std::nullopt;
  return CGAL::do_intersect(Kernel::Segment_3(x0, x1), Kernel::Segment_3(x2, x3));
}

mpq_class exact_of(double d) { return mpq_class(d); }

struct Counts {
  int queries = 0, roots = 0, rational_roots_checked = 0, earliest = 0;
};

// Every claim of one inspection, checked independently.
void check_inspection(const QueryRecord& record, QueryType type, const std::string& where,
                      double t_max, Counts& counts) {
  InspectSettings settings;
  settings.t_max = t_max;
  settings.mode = exactccd::Mode::exact;  // rational coordinates are fine
  const json doc =
      json::parse(exactccd::oracle::inspection_json(record, type, where, 0, settings));
  SCOPED_TRACE(where);
  ++counts.queries;
  exactccd::RationalQuery q = record.query;
  q.type = type;
  exactccd::CcdOptions options;
  options.t_max = t_max;
  const exactccd::CcdResult exact = exactccd::exact_ccd(q, options);
  ASSERT_EQ(doc["exact"]["collides"].get<bool>(), exact.collides);
  EXPECT_EQ(doc["float_only"]["wrong"].get<bool>(),
            doc["float_only"]["collides"].get<bool>() != exact.collides);

  const json& cubic = doc["polynomials"].at(0);
  const bool coplanar_throughout = cubic["identically_zero"].get<bool>();
  // The cubic vanishes identically exactly when CGAL finds the points coplanar at 4 times.
  bool all_coplanar = true;
  for (int k = 0; k < 4; ++k)
    all_coplanar = all_coplanar && orientation_at(q, mpq_class(k, 3) * exact_of(t_max)) == 0;
  EXPECT_EQ(coplanar_throughout, all_coplanar);

  std::vector<mpq_class> ends;  // root brackets and grid points, for the sign-change count
  int earliest_marks = 0;
  std::optional<std::pair<double, double>> first_inclusion;
  for (const json& poly : doc["polynomials"]) {
    for (const json& root : poly["roots"]) {
      ++counts.roots;
      const double lo = root["lo"], hi = root["hi"];
      ASSERT_LE(lo, hi);
      ASSERT_GE(lo, 0.0);
      ASSERT_LE(hi, t_max);
      if (&poly == &cubic) {
        // CGAL's orientation changes sign across the bracket as often as the roots inside it
        // say: an odd number of simple roots changes it; an even number (two close roots in
        // one tightest pair of doubles) does not, nor does a root of even multiplicity, which
        // for a rational cubic is rational (gcd(P, P') is), so its exact value is given and
        // checked to be a zero below.
        int in_bracket = 0;
        bool rational_inside = false;
        for (const json& other : poly["roots"])
          if (other["lo"] == root["lo"] && other["hi"] == root["hi"]) {
            ++in_bracket;
            rational_inside = rational_inside || other["exact"].is_string();
          }
        const int change = orientation_at(q, exact_of(lo)) * orientation_at(q, exact_of(hi));
        if (change < 0) EXPECT_TRUE(in_bracket % 2 == 1 || rational_inside) << lo << " " << hi;
        if (change > 0) EXPECT_TRUE(in_bracket % 2 == 0 || rational_inside) << lo << " " << hi;
        ends.push_back(exact_of(lo));
        ends.push_back(exact_of(hi));
      }
      const bool inclusion = root["inclusion"];
      if (root["exact"].is_string()) {
        const mpq_class t(root["exact"].get<std::string>());
        if (&poly == &cubic) EXPECT_EQ(orientation_at(q, t), 0);
        if (const auto cgal = contact_at(q, type, t)) {
          EXPECT_EQ(inclusion, *cgal) << "at t = " << t;
          ++counts.rational_roots_checked;
        }
      }
      if (inclusion && (!first_inclusion || hi < first_inclusion->first))
        first_inclusion = std::pair(lo, hi);
      if (root["earliest"].get<bool>()) {
        ++earliest_marks;
        EXPECT_TRUE(inclusion);
        EXPECT_EQ(lo, exact.toi_lo);
        EXPECT_EQ(hi, exact.toi_hi);
      }
    }
  }
  if (!exact.collides) {
    EXPECT_FALSE(first_inclusion.has_value()) << "a root passes inclusion without contact";
    EXPECT_EQ(earliest_marks, 0);
  } else if (doc["contact_at_start_coplanar"].get<bool>()) {
    EXPECT_EQ(exact.toi_lo, 0.0);
    EXPECT_EQ(earliest_marks, 0);
  } else {
    EXPECT_EQ(earliest_marks, 1);
    ++counts.earliest;
    ASSERT_TRUE(first_inclusion.has_value());
    EXPECT_EQ(first_inclusion->first, exact.toi_lo);
  }
  // No sign change of the orientation is missed: between consecutive bracket ends and grid
  // points at k/16 of t_max, CGAL's orientation changes sign only across a reported bracket.
  if (!coplanar_throughout && t_max > 0) {
    std::vector<mpq_class> grid = ends;
    for (int k = 0; k <= 16; ++k) grid.push_back(mpq_class(k, 16) * exact_of(t_max));
    std::sort(grid.begin(), grid.end());
    int previous = 0;
    mpq_class previous_t;
    for (const mpq_class& t : grid) {
      const int s = orientation_at(q, t);
      if (s != 0 && previous != 0 && s != previous) {
        bool covered = false;
        for (const json& root : cubic["roots"])
          covered = covered || (exact_of(root["lo"]) <= t && exact_of(root["hi"]) >= previous_t);
        EXPECT_TRUE(covered) << "sign change in [" << previous_t << ", " << t
                             << "] without a root";
      }
      if (s != 0) {
        previous = s;
        previous_t = t;
      }
    }
  }
}

TEST(Inspection, SampleQueriesAgreeWithCgal) {
  Counts counts;
  for (const std::string& path : exactccd::find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
    const QueryType type = *exactccd::query_type_from_path(path);
    const exactccd::QueryFile file = exactccd::read_query_file(path, type);
    // Every colliding query and every 9th other one: the test stays a few seconds long.
    for (std::size_t i = 0; i < file.queries.size(); ++i)
      if (file.queries[i].truth || i % 9 == 0)
        check_inspection(file.queries[i], type, path + " #" + std::to_string(i), 1.0, counts);
  }
  EXPECT_GT(counts.queries, 500);
  EXPECT_GT(counts.earliest, 100);
  EXPECT_GT(counts.roots, 300);
}

TEST(Inspection, DegenerateSuiteAgreesWithCgal) {
  Counts counts;
  const fs::path suite = fs::path(EXACTCCD_TEST_DATA) / "degenerate-suite";
  for (const std::string& path : exactccd::find_query_files(suite.string())) {
    const QueryType type = *exactccd::query_type_from_path(path);
    const exactccd::QueryFile file = exactccd::read_query_file(path, type);
    for (std::size_t i = 0; i < file.queries.size(); i += 3)
      check_inspection(file.queries[i], type, path + " #" + std::to_string(i), 1.0, counts);
  }
  EXPECT_GT(counts.queries, 500);
  EXPECT_GT(counts.rational_roots_checked, 100);  // constructed contact times are rational
}

// p falls through the static triangle z = 0 at t = 1/2 (the command tests' hand-made query).
QueryRecord falling_vertex(int z1) {
  QueryRecord r;
  auto set = [&](int row, mpq_class x, mpq_class y, mpq_class z) {
    r.query.points[row] = {x, y, z};
  };
  for (int t = 0; t < 2; ++t) {
    set(4 * t, mpq_class(1, 4), mpq_class(1, 4), t == 0 ? mpq_class(1) : mpq_class(z1));
    set(4 * t + 1, 0, 0, 0);
    set(4 * t + 2, 1, 0, 0);
    set(4 * t + 3, 0, 1, 0);
  }
  r.truth = z1 < 0;
  r.first_line = 1;
  return r;
}

TEST(Inspection, HandMadeQueryAndTimeWindow) {
  Counts counts;
  check_inspection(falling_vertex(-1), QueryType::vertex_face, "falling", 1.0, counts);
  check_inspection(falling_vertex(-1), QueryType::vertex_face, "falling, t_max 1/4", 0.25, counts);
  check_inspection(falling_vertex(1), QueryType::vertex_face, "resting above", 1.0, counts);
  const json doc = json::parse(exactccd::oracle::inspection_json(
      falling_vertex(-1), QueryType::vertex_face, "f.csv", 7, InspectSettings{}));
  EXPECT_EQ(doc["result"]["toi_lo"].get<double>(), 0.5);
  EXPECT_EQ(doc["polynomials"][0]["roots"][0]["exact"], "1/2");
  EXPECT_EQ(doc["polynomials"][0]["coefficients_exact"], json({"1", "-2"}));  // degree 1
  EXPECT_EQ(doc["source"]["index"], 7);
  EXPECT_EQ(doc["contact"]["kind"], "point");
  EXPECT_EQ(doc["points_exact"][0], json({"1/4", "1/4", "1"}));
}

// Rational roots whose denominators are too large for the simplest rational of a one-ulp
// bracket: found once the isolating interval is refined below 1 / L^2.
TEST(Inspection, RationalRootsWithLargeDenominators) {
  QueryRecord r;
  const mpq_class rows[8][3] = {{mpq_class(1, 8), mpq_class(1, 8), mpq_class("35184372088839")},
                                {0, 0, 0},
                                {mpq_class("1099511627777"), 0, 0},
                                {0, 1, 0},
                                {mpq_class(1, 8), mpq_class(1, 8), mpq_class("-35184372088833")},
                                {0, 0, 0},
                                {mpq_class("-1099511627779"), 0, 0},
                                {0, 1, 0}};
  for (int i = 0; i < 8; ++i) r.query.points[i] = {rows[i][0], rows[i][1], rows[i][2]};
  r.first_line = 1;
  const json doc = json::parse(exactccd::oracle::inspection_json(
      r, QueryType::vertex_face, "quad.csv", 0, InspectSettings{}));
  const json& roots = doc["polynomials"][0]["roots"];
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_EQ(roots[0]["exact"], "1099511627777/2199023255556");
  EXPECT_EQ(roots[1]["exact"], "11728124029613/23456248059224");
  Counts counts;
  check_inspection(r, QueryType::vertex_face, "quad.csv", 1.0, counts);  // zeros, per CGAL
  EXPECT_EQ(counts.roots, 2);
}

TEST(Inspection, NonDoubleCoordinatesNeedExactMode) {
  QueryRecord r = falling_vertex(-1);
  r.query.points[0].x = mpq_class(1, 3);
  EXPECT_THROW(exactccd::oracle::inspection_json(r, QueryType::vertex_face, "f.csv", 0,
                                                 InspectSettings{}),
               exactccd::InputError);
  InspectSettings exact;
  exact.mode = exactccd::Mode::exact;
  const json doc =
      json::parse(exactccd::oracle::inspection_json(r, QueryType::vertex_face, "f.csv", 0, exact));
  EXPECT_TRUE(doc["result"]["collides"].get<bool>());
  EXPECT_FALSE(doc["points_are_doubles"].get<bool>());
  EXPECT_EQ(doc["points_exact"][0][0], "1/3");
}

TEST(Inspection, MinimumSeparationDistanceSamples) {
  InspectSettings settings;
  settings.min_separation = 0.25;
  // Resting 1 above the face: never within 0.25; the samples say distance 1.
  const json apart = json::parse(exactccd::oracle::inspection_json(
      falling_vertex(1), QueryType::vertex_face, "f.csv", 0, settings));
  EXPECT_FALSE(apart["exact"]["collides"].get<bool>());
  for (const json& s : apart["distance"]["samples"]) EXPECT_EQ(s[1].get<double>(), 1.0);
  // Falling: within 0.25 first at t = 3/8 (height 1 - 2t = 1/4).
  const json within = json::parse(exactccd::oracle::inspection_json(
      falling_vertex(-1), QueryType::vertex_face, "f.csv", 0, settings));
  EXPECT_EQ(within["result"]["toi_lo"].get<double>(), 0.375);
  EXPECT_EQ(within["distance"]["delta"].get<double>(), 0.25);
  EXPECT_TRUE(within["polynomials"].empty());
}

TEST(Inspection, FileQueryIndexPastTheEnd) {
  const std::string path =
      (fs::path(EXACTCCD_SAMPLE_QUERIES) / "unit-tests" / "vertex-face" / "data_0_1.csv").string();
  const auto file = exactccd::read_query_file(path, QueryType::vertex_face);
  EXPECT_NO_THROW(exactccd::oracle::inspect_file_query(path, std::nullopt,
                                                       file.queries.size() - 1, {}));
  try {
    exactccd::oracle::inspect_file_query(path, std::nullopt, file.queries.size(), {});
    FAIL() << "no error";
  } catch (const exactccd::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("past the end"), std::string::npos) << e.what();
  }
}

// The corner (5, 5, 0) of a cube turning about the z axis (cayley (0, 0, -1/2)) against the
// static wall x = 7: contact at s = 2/3 (tests/data/rigid/cube_turns_into_wall.json).
exactccd::RigidVertexFaceQuery turning_corner() {
  exactccd::RigidVertexFaceQuery q;
  q.p = {5, 5, 0};
  q.a = {7, -2, -1};
  q.b = {7, 2, -1};
  q.c = {7, 2, 2};
  exactccd::RigidMotion turn;
  turn.cayley = {0, 0, -0.5};
  q.vertex = exactccd::SideMotion::of(turn);
  q.face = exactccd::SideMotion::of(exactccd::RigidMotion{});
  return q;
}

// d is a double nearest to x: no neighbour of d is closer (checked exactly).
bool is_nearest(double d, const CGAL::Gmpq& x) {
  const mpq_class e(x.mpq());
  const mpq_class off = abs(e - mpq_class(d));
  for (double n : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)})
    if (abs(e - mpq_class(n)) < off) return false;
  return true;
}

Point rigid_at(const exactccd::RigidVertexFaceQuery& q, int k, const mpq_class& s) {
  const Eigen::Vector3d x0 = k == 0 ? q.p : k == 1 ? q.a : k == 2 ? q.b : q.c;
  const auto& m = k == 0 ? q.vertex.rigid : q.face.rigid;
  const auto x = exactccd::rigid_pose::exact_position(m, x0, s);
  return Point(gmpq(x[0]), gmpq(x[1]), gmpq(x[2]));
}

TEST(Inspection, RigidQueryAgreesWithExactPoses) {
  const exactccd::RigidVertexFaceQuery q = turning_corner();
  const json doc = json::parse(exactccd::oracle::rigid_inspection_json(
      q, InspectSettings{}, "turning corner", "test", {"p", "a", "b", "c"}));
  EXPECT_EQ(doc["motion"], "samples");
  const double lo = doc["result"]["toi_lo"], hi = doc["result"]["toi_hi"];
  EXPECT_LE(exact_of(lo), mpq_class(2, 3));
  EXPECT_GE(exact_of(hi), mpq_class(2, 3));
  EXPECT_TRUE(doc["result"]["has_time"].get<bool>());
  // Every sample: the exact pose (matrix form of the Cayley rotation) rounded to nearest.
  const json& times = doc["trajectory"]["times"];
  ASSERT_GE(times.size(), 65u);
  for (std::size_t j = 0; j < times.size(); ++j)
    for (int k = 0; k < 4; ++k) {
      const Point x = rigid_at(q, k, exact_of(times[j]));
      const json& drawn = doc["trajectory"]["positions"][j][k];
      EXPECT_TRUE(is_nearest(drawn[0].get<double>(), x.x()));
      EXPECT_TRUE(is_nearest(drawn[1].get<double>(), x.y()));
      EXPECT_TRUE(is_nearest(drawn[2].get<double>(), x.z()));
    }
  // Each root bracket of g(s) holds a sign change of CGAL's orientation of the exact poses, and
  // the root marked earliest is the contact (the other root of g lies outside the triangle).
  int earliest = 0;
  for (const json& root : doc["polynomials"][0]["roots"]) {
    const mpq_class a = exact_of(root["lo"]), b = exact_of(root["hi"]);
    const int change =
        static_cast<int>(CGAL::orientation(rigid_at(q, 0, a), rigid_at(q, 1, a), rigid_at(q, 2, a),
                                           rigid_at(q, 3, a))) *
        static_cast<int>(CGAL::orientation(rigid_at(q, 0, b), rigid_at(q, 1, b), rigid_at(q, 2, b),
                                           rigid_at(q, 3, b)));
    EXPECT_LE(change, 0) << a << " " << b;
    if (root["earliest"].get<bool>()) {
      ++earliest;
      EXPECT_EQ(root["lo"].get<double>(), lo);
      EXPECT_EQ(root["hi"].get<double>(), hi);
    }
  }
  EXPECT_EQ(earliest, 1);
  // g(s) = -12 (3 s - 2) (s - 1): both roots found rational.
  EXPECT_EQ(doc["polynomials"][0]["roots"][0]["exact"], "2/3");
  EXPECT_EQ(doc["polynomials"][0]["roots"][1]["exact"], "1");
  EXPECT_EQ(doc["contact"]["kind"], "point");
  // With a minimum separation: the distance samples instead, the TOI earlier.
  InspectSettings within;
  within.min_separation = 0.5;
  const json near = json::parse(exactccd::oracle::rigid_inspection_json(
      q, within, "turning corner", "test", {"p", "a", "b", "c"}));
  EXPECT_LT(near["result"]["toi_hi"].get<double>(), lo);
  EXPECT_FALSE(near["distance"]["samples"].empty());
}

// f(t) = (p(t) - o(t)) . n(t) of a point-plane query, over the rationals (independent of the
// library's polynomial code).
mpq_class plane_offset_at(const exactccd::PointPlaneQuery& q, const mpq_class& t) {
  // mpq_class, not auto: gmpxx's expression templates would outlive their temporaries.
  auto lerp = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, int k) -> mpq_class {
    return mpq_class(a[k]) + t * (mpq_class(b[k]) - mpq_class(a[k]));
  };
  mpq_class f = 0;
  for (int k = 0; k < 3; ++k)
    f += (lerp(q.p_t0, q.p_t1, k) - lerp(q.origin_t0, q.origin_t1, k)) *
         lerp(q.normal_t0, q.normal_t1, k);
  return f;
}

TEST(Inspection, PointPlaneFamiliesAgreeWithTheOffset) {
  // The point-plane degenerate families (exactccd generate --type pl): crossing at dyadic times,
  // grazing a turning plane (a double root), stopping one ulp short, sliding in the plane.
  int roots = 0, contacts = 0;
  for (const auto& family :
       exactccd::families::generate_point_families(exactccd::PrimitiveKind::point_plane, 1, 8)) {
    const std::string& f = family.name;
    for (std::size_t i = 0; i < family.members.size(); ++i) {
      const auto& x = family.members[i];
      const exactccd::PointPlaneQuery q{x[0], x[1], x[2], x[3], x[4], x[5]};
      SCOPED_TRACE(f + " #" + std::to_string(i));
      const json doc = json::parse(exactccd::oracle::point_plane_inspection_json(
          q, InspectSettings{}, {"test", std::nullopt, std::nullopt, std::nullopt, std::nullopt, f}));
      const exactccd::CcdResult exact = [&] {
        exactccd::CcdOptions o;
        o.mode = exactccd::Mode::exact;
        return exactccd::point_plane_ccd(q, o);
      }();
      EXPECT_EQ(doc["exact"]["collides"].get<bool>(), exact.collides);
      const json& poly = doc["polynomials"][0];
      EXPECT_EQ(poly["identically_zero"].get<bool>(),
                plane_offset_at(q, 0) == 0 && plane_offset_at(q, 1) == 0 &&
                    plane_offset_at(q, mpq_class(1, 3)) == 0);
      int earliest = 0;
      for (const json& root : poly["roots"]) {
        ++roots;
        const mpq_class lo = exact_of(root["lo"]), hi = exact_of(root["hi"]);
        const int a = sgn(plane_offset_at(q, lo)), b = sgn(plane_offset_at(q, hi));
        if (root["exact"].is_string())
          EXPECT_EQ(plane_offset_at(q, mpq_class(root["exact"].get<std::string>())), 0);
        else
          EXPECT_LE(a * b, 0) << "[" << lo << ", " << hi << "]";  // a double root is rational
        if (root["earliest"].get<bool>()) {
          ++earliest;
          EXPECT_EQ(root["lo"].get<double>(), exact.toi_lo);
          EXPECT_EQ(root["hi"].get<double>(), exact.toi_hi);
        }
      }
      if (exact.collides && !poly["identically_zero"].get<bool>()) {
        EXPECT_EQ(earliest, 1);
        ++contacts;
      }
    }
  }
  EXPECT_GT(roots, 20);
  EXPECT_GT(contacts, 10);
}

TEST(Inspection, RigidPointPlaneAgreesWithExactPoses) {
  // The corner (5, 5, 0) of a cube turning about the z axis (cayley (0, 0, -1/2)) against the
  // static floor x = 7 seen as a plane: the same contact as the wall, at s = 2/3.
  exactccd::RigidMotion turn;
  turn.cayley = {0, 0, -0.5};
  const exactccd::RigidPointPlaneQuery q({5, 5, 0}, turn, {7, 0, 0}, {-1, 0, 0});
  const json doc = json::parse(exactccd::oracle::rigid_point_plane_inspection_json(
      q, InspectSettings{}, {"test", std::nullopt, std::nullopt, 1, std::nullopt, "corner"}));
  EXPECT_EQ(doc["kind"], "point_plane");
  EXPECT_EQ(doc["polynomials"][0]["roots"][0]["exact"], "2/3");
  EXPECT_TRUE(doc["polynomials"][0]["roots"][0]["earliest"].get<bool>());
  const json& times = doc["trajectory"]["times"];
  for (std::size_t j = 0; j < times.size(); ++j) {
    const auto x = exactccd::rigid_pose::exact_position(turn, q.p, exact_of(times[j]));
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(is_nearest(doc["trajectory"]["positions"][j][0][k].get<double>(),
                             CGAL::Gmpq(x[k].get_str())));
  }
}

TEST(InspectorPage, CarriesTheDataAndEveryScript) {
  if (!exactccd::oracle::inspector_available()) GTEST_SKIP() << "built without libjs-three";
  // A source name that would end the data's <script> element if it were not escaped.
  const std::string json_text = exactccd::oracle::inspection_json(
      falling_vertex(-1), QueryType::vertex_face, "</script><b>x.csv", 0, InspectSettings{});
  const std::string page = exactccd::oracle::inspector_page(json_text);
  EXPECT_EQ(page.find("@DATA_JSON@"), std::string::npos);
  EXPECT_EQ(page.find("/*@THREE_JS@*/"), std::string::npos);
  EXPECT_EQ(page.find("</script><b>x.csv"), std::string::npos);
  EXPECT_NE(page.find("\\u003c/script>\\u003cb>x.csv"), std::string::npos);
  EXPECT_NE(page.find("REVISION"), std::string::npos);  // three.js inline
  EXPECT_EQ(page.find("<script src="), std::string::npos);
  // The data element parses back to the inspection.
  const std::string open = "<script type=\"application/json\" id=\"exactccd-data\">";
  const std::size_t from = page.find(open);
  ASSERT_NE(from, std::string::npos);
  const std::size_t begin = from + open.size(), end = page.find("</script>", begin);
  EXPECT_EQ(json::parse(page.substr(begin, end - begin)), json::parse(json_text));
  // Linked: the page loads the folder's scripts instead.
  const std::string linked = exactccd::oracle::inspector_page(json_text, "scripts");
  EXPECT_NE(linked.find("<script src=\"scripts/three.min.js\"></script>"), std::string::npos);
  EXPECT_LT(linked.size(), page.size() / 4);
}

}  // namespace
