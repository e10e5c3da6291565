// Tests of the numerical-stability study: the tolerance method (core/float_only/tolerance_ccd.hpp)
// on hand-made queries whose coplanar times and distances are worked out by hand below, and the
// `exactccd study` command on a sample file (expected verdicts from the file's truth column, read
// here independently), on a hand-made suite with a TOI sidecar, and with a minimum separation on a
// hand-made file whose first times within the separation are worked out below.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/float_only/tolerance_ccd.hpp"

namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;
using exactccd::CcdResult;
using exactccd::EdgeEdgeQuery;
using exactccd::VertexFaceQuery;
using exactccd::methods::point_segment_distance;
using exactccd::methods::point_triangle_distance;
using exactccd::methods::segment_segment_distance;
using exactccd::methods::tolerance_edge_edge_ccd;
using exactccd::methods::tolerance_vertex_face_ccd;

// The fixed triangle a = 0, b = s e_x, c = s e_y (plane z = 0, normal +z) and a vertex moving
// straight down from (x, y, s) to (x, y, -s): the coplanarity cubic is s^2 (s - 2 s t), whose
// only root is t = 1/2, where the vertex is at (x, y, 0). For s a power of two every quantity
// below is exact in doubles.
VertexFaceQuery vertex_through_plane(double x, double y, double s = 1.0) {
  const Vector3d a(0, 0, 0), b(s, 0, 0), c(0, s, 0);
  return {Vector3d(x, y, s), a, b, c, Vector3d(x, y, -s), a, b, c};
}

// Edge A fixed on the x axis from 0 to 1; edge B parallel to the y axis at x = x_b, from
// y = -1 to y = 1, moving down from z = 1 to z = -1. The cubic det[A1 - A0, B0 - A0, B1 - A0]
// = -2 z(t) = 4t - 2 has its only root at t = 1/2; the segments are then in the plane z = 0 and
// meet iff 0 <= x_b <= 1; for x_b < 0 their distance is -x_b (from A0 to (x_b, 0, 0)).
EdgeEdgeQuery edge_through_plane(double x_b) {
  const Vector3d a0(0, 0, 0), a1(1, 0, 0);
  return {a0, a1, Vector3d(x_b, -1, 1), Vector3d(x_b, 1, 1),
          a0, a1, Vector3d(x_b, -1, -1), Vector3d(x_b, 1, -1)};
}

// ---- The distances on degenerate inputs (3-4-5 right triangles: exact answers) --------------

TEST(ToleranceDistances, PointTriangleInsideProjectionIsDistanceToPlane) {
  EXPECT_EQ(point_triangle_distance({1, 1, 5}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), 5.0);
}

TEST(ToleranceDistances, PointTriangleOutsideProjectionIsDistanceToNearestSide) {
  // The projection (2, -3, 0) is outside (y < 0); the nearest point is (2, 0, 0) on side ab.
  EXPECT_EQ(point_triangle_distance({2, -3, 4}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), 5.0);
}

TEST(ToleranceDistances, CollinearTriangleIsItsLongestSide) {
  // a, b, c on the x axis from 0 to 2: the nearest point to (1, 3, 4) is (1, 0, 0).
  EXPECT_EQ(point_triangle_distance({1, 3, 4}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}), 5.0);
  // Same set listed with the middle vertex last: the hull is still [0, 2].
  EXPECT_EQ(point_triangle_distance({1.5, 3, 4}, {0, 0, 0}, {2, 0, 0}, {1, 0, 0}), 5.0);
}

TEST(ToleranceDistances, PointTriangleWithThreeEqualVerticesIsPointDistance) {
  EXPECT_EQ(point_triangle_distance({1, 4, 5}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}), 5.0);
}

TEST(ToleranceDistances, PointSegmentClampsToTheEnds) {
  EXPECT_EQ(point_segment_distance({5, 4, 0}, {0, 0, 0}, {2, 0, 0}), 5.0);   // past (2, 0, 0)
  EXPECT_EQ(point_segment_distance({-3, 4, 0}, {0, 0, 0}, {2, 0, 0}), 5.0);  // before (0, 0, 0)
  EXPECT_EQ(point_segment_distance({3, 4, 0}, {0, 0, 0}, {0, 0, 0}), 5.0);   // zero length
}

TEST(ToleranceDistances, SkewSegmentsUseTheCommonPerpendicular) {
  // Crossing in projection, 5 apart in z; every endpoint pair is sqrt(26) or more apart.
  EXPECT_EQ(segment_segment_distance({-1, 0, 0}, {1, 0, 0}, {0, -1, 5}, {0, 1, 5}), 5.0);
}

TEST(ToleranceDistances, ParallelOverlappingSegments) {
  EXPECT_EQ(segment_segment_distance({0, 0, 0}, {2, 0, 0}, {1, 3, 4}, {3, 3, 4}), 5.0);
}

TEST(ToleranceDistances, ZeroLengthSegmentAgainstSegment) {
  EXPECT_EQ(segment_segment_distance({0, 0, 0}, {0, 0, 0}, {3, -1, 4}, {3, 1, 4}), 5.0);
  EXPECT_EQ(segment_segment_distance({0, 0, 0}, {0, 0, 0}, {3, 0, 4}, {3, 0, 4}), 5.0);
}

TEST(ToleranceDistances, SkewSegmentsWhosePerpendicularMissesUseEndpoints) {
  // The lines' common perpendicular meets B's line at y = 0, outside B (y in [2, 4]). Over
  // (x, 0, 0) in A and (0, y, 5) in B the squared distance x^2 + y^2 + 25 is least at x = 0,
  // y = 2: sqrt(29), between B's end (0, 2, 5) and (0, 0, 0) in A.
  EXPECT_EQ(segment_segment_distance({-1, 0, 0}, {1, 0, 0}, {0, 2, 5}, {0, 4, 5}),
            std::sqrt(29.0));
}

// ---- The tolerance method ----------------------------------------------------------------------

TEST(ToleranceCcd, VertexFaceNearMissAt1e10IsContactForEps1e9Only) {
  // At t = 1/2 the vertex is at (-1e-10, 1/4, 0): outside the triangle (x < 0), at distance
  // 1e-10 from its side x = 0. No contact; eps = 1e-9 and 1e-6 take it for one.
  const VertexFaceQuery q = vertex_through_plane(-1e-10, 0.25);
  EXPECT_FALSE(tolerance_vertex_face_ccd(q, 0.0).collides);
  EXPECT_FALSE(tolerance_vertex_face_ccd(q, 1e-12).collides);
  for (const double eps : {1e-9, 1e-6}) {
    const CcdResult r = tolerance_vertex_face_ccd(q, eps);
    EXPECT_TRUE(r.collides) << eps;
    EXPECT_EQ(r.toi_lo, 0.5) << eps;
    EXPECT_EQ(r.toi_hi, 0.5) << eps;
    EXPECT_EQ(r.decided_by, exactccd::Stage::float_only);
  }
}

TEST(ToleranceCcd, EdgeEdgeNearMissAt1e10IsContactForEps1e9Only) {
  const EdgeEdgeQuery q = edge_through_plane(-1e-10);
  EXPECT_FALSE(tolerance_edge_edge_ccd(q, 0.0).collides);
  EXPECT_FALSE(tolerance_edge_edge_ccd(q, 1e-12).collides);
  for (const double eps : {1e-9, 1e-6}) {
    const CcdResult r = tolerance_edge_edge_ccd(q, eps);
    EXPECT_TRUE(r.collides) << eps;
    EXPECT_EQ(r.toi_lo, 0.5) << eps;
    EXPECT_EQ(r.decided_by, exactccd::Stage::float_only);
  }
}

TEST(ToleranceCcd, ExactContactIsReportedByEveryEps) {
  // The vertex passes through (1/4, 1/4, 0), inside the triangle; edge B crosses A at
  // (1/2, 0, 0). Both at t = 1/2, distance exactly 0.
  for (const double eps : {0.0, 1e-12, 1e-9, 1e-6}) {
    const CcdResult vf = tolerance_vertex_face_ccd(vertex_through_plane(0.25, 0.25), eps);
    EXPECT_TRUE(vf.collides) << eps;
    EXPECT_EQ(vf.toi_lo, 0.5) << eps;
    const CcdResult ee = tolerance_edge_edge_ccd(edge_through_plane(0.5), eps);
    EXPECT_TRUE(ee.collides) << eps;
    EXPECT_EQ(ee.toi_lo, 0.5) << eps;
  }
}

TEST(ToleranceCcd, ContactAtTheStartIsTimeZero) {
  // The vertex starts on the triangle, at (1/4, 1/4, 0), and leaves it upwards: the cubic is t.
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const VertexFaceQuery q{Vector3d(0.25, 0.25, 0), a, b, c, Vector3d(0.25, 0.25, 1), a, b, c};
  for (const double eps : {0.0, 1e-12, 1e-9, 1e-6}) {
    const CcdResult r = tolerance_vertex_face_ccd(q, eps);
    EXPECT_TRUE(r.collides) << eps;
    EXPECT_EQ(r.toi_lo, 0.0) << eps;
  }
}

TEST(ToleranceCcd, EpsIsAnAbsoluteDistanceSoItDependsOnTheScale) {
  // The near miss of a triangle of size 2^-30 (about 9.3e-10) with the vertex 2^-31 (about
  // 4.7e-10, half the triangle's size) outside it: eps = 1e-9 calls it a contact, as it would
  // a 1e-10 gap on a unit triangle; eps = 1e-12 does not.
  const double s = std::ldexp(1.0, -30);
  const VertexFaceQuery q = vertex_through_plane(-s / 2, s / 4, s);
  EXPECT_TRUE(tolerance_vertex_face_ccd(q, 1e-9).collides);
  EXPECT_FALSE(tolerance_vertex_face_ccd(q, 1e-12).collides);
  // Scaled up by 2^30 the same configuration is a miss by 1/2, for every eps.
  for (const double eps : {1e-12, 1e-9, 1e-6})
    EXPECT_FALSE(tolerance_vertex_face_ccd(vertex_through_plane(-0.5, 0.25), eps).collides);
}

// ---- The `exactccd study` command --------------------------------------------------------------

struct RunResult {
  int status = -1;
  std::string out;
};

std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (const char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

RunResult run_cli(const std::vector<std::string>& args, const fs::path& dir) {
  std::string command = shell_quote(EXACTCCD_CLI);
  for (const std::string& a : args) command += " " + shell_quote(a);
  const fs::path out = dir / "stdout.txt";
  command += " > " + shell_quote(out.string()) + " 2> " +
             shell_quote((dir / "stderr.txt").string());
  const int raw = std::system(command.c_str());
  RunResult r;
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  std::ifstream in(out);
  std::ostringstream text;
  text << in.rdbuf();
  r.out = text.str();
  return r;
}

class StudyCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("exactccd_study_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The truth column, one value per query (8 rows each), read without exactccd's reader.
std::vector<bool> truth_column(const fs::path& path) {
  std::ifstream in(path);
  std::vector<bool> truth;
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (rows++ % 8 == 0) truth.push_back(std::stoi(line.substr(line.rfind(',') + 1)) == 1);
  }
  return truth;
}

const nlohmann::json& method_row(const nlohmann::json& methods, const std::string& label) {
  for (const nlohmann::json& m : methods)
    if (m["label"] == label) return m;
  static const nlohmann::json none;
  ADD_FAILURE() << "no method " << label;
  return none;
}

const std::vector<std::string> kCertified = {"filtered width=0", "filtered width=1e-6",
                                             "filtered width=1e-3", "exact"};

TEST_F(StudyCommand, SampleFileCertifiedMethodsShowNoErrors) {
  const fs::path file =
      fs::path(EXACTCCD_SAMPLE_QUERIES) / "unit-tests" / "edge-edge" / "data_0_1.csv";
  const std::vector<bool> truth = truth_column(file);
  std::size_t contacts = 0;
  for (const bool t : truth) contacts += t;
  ASSERT_GT(contacts, 0u);

  const RunResult r = run_cli({"study", "--json", "--repetitions", "1", file.string()}, dir_);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["datasets"].size(), 1u);
  const nlohmann::json& d = j["datasets"][0];
  EXPECT_EQ(d["queries"], truth.size());
  EXPECT_EQ(d["contacts"], contacts);
  // float_only, three tolerances, three widths, exact.
  EXPECT_EQ(d["methods"].size(), 8u);
  for (const std::string& label : kCertified) {
    const nlohmann::json& m = method_row(d["methods"], label);
    EXPECT_EQ(m["certified"], true) << label;
    EXPECT_EQ(m["queries"], truth.size()) << label;
    EXPECT_EQ(m["false_positives"], 0) << label;
    EXPECT_EQ(m["false_negatives"], 0) << label;
    EXPECT_EQ(m["late_tois"], 0) << label;
    EXPECT_EQ(m["collisions"], contacts) << label;
    EXPECT_GT(m["mean_ns"].get<double>(), 0.0) << label;
  }
  // An enclosure of width w starts within w of t* (the API's contract).
  for (const double w : {0.0, 1e-6, 1e-3}) {
    const std::string label = w == 0.0    ? "filtered width=0"
                              : w == 1e-6 ? "filtered width=1e-6"
                                          : "filtered width=1e-3";
    EXPECT_LE(method_row(d["methods"], label)["max_abs_toi_error"].get<double>(), w) << label;
  }
  for (const std::string label : {"float_only", "tolerance eps=1e-12", "tolerance eps=1e-9",
                                  "tolerance eps=1e-6"})
    EXPECT_EQ(method_row(d["methods"], label)["certified"], false) << label;
}

TEST_F(StudyCommand, WrongTruthColumnMakesTheCertifiedMethodsDisagreeAndExitOne) {
  // The sample file with the first colliding query's truth flipped to 0: the certified methods
  // now report a contact the truth column denies.
  const fs::path source =
      fs::path(EXACTCCD_SAMPLE_QUERIES) / "unit-tests" / "edge-edge" / "data_0_1.csv";
  const std::vector<bool> truth = truth_column(source);
  std::size_t flipped = 0;
  while (!truth[flipped]) ++flipped;
  fs::create_directories(dir_ / "edge-edge");
  const fs::path file = dir_ / "edge-edge" / "data_0.csv";
  {
    std::ifstream in(source);
    std::ofstream out(file);
    std::size_t row = 0;
    for (std::string line; std::getline(in, line); ++row) {
      if (row / 8 == flipped) line = line.substr(0, line.rfind(',') + 1) + "0";
      out << line << '\n';
    }
  }
  const RunResult r = run_cli({"study", "--json", "--repetitions", "1", file.string()}, dir_);
  EXPECT_EQ(r.status, 1);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const std::string& label : kCertified) {
    const nlohmann::json& m = method_row(j["datasets"][0]["methods"], label);
    EXPECT_EQ(m["false_positives"], 1) << label;
    EXPECT_EQ(m["false_negatives"], 0) << label;
    EXPECT_EQ(m["examples"]["false_positives"][0],
              file.string() + ":" + std::to_string(flipped))
        << label;
  }
}

// A suite in the generator's layout, by hand: family "hit" (the vertex through the unit
// triangle's interior at t = 1/2, see vertex_through_plane) and family "hit@s0.5" (the same
// scaled by 1/2: t* = 1/2 too), each one query with its toi sidecar; `late_toi` makes the first
// family's sidecar claim t* = 1/4, so that every method finding 1/2 is late.
void write_suite(const fs::path& root, bool late_toi) {
  // Benchmark rows p, a, b, c at t = 0 then at t = 1, as exact fractions, truth 1.
  auto write_family = [&](const std::string& name, int den, const std::string& toi) {
    const fs::path folder = root / name / "vertex-face";
    fs::create_directories(folder);
    std::ofstream data(folder / "data_0.csv");
    const std::string d = std::to_string(den), d4 = std::to_string(4 * den);
    const std::string p0 = "1," + d4 + ",1," + d4 + ",1," + d;
    const std::string p1 = "1," + d4 + ",1," + d4 + ",-1," + d;
    const std::string a = "0,1,0,1,0,1", b = "1," + d + ",0,1,0,1", c = "0,1,1," + d + ",0,1";
    for (const std::string& row : {p0, a, b, c, p1, a, b, c}) data << row << ",1\n";
    std::ofstream sidecar(folder / "toi_0.csv");
    sidecar << "0,1," << toi << "," << toi << "\n";
  };
  write_family("hit", 1, late_toi ? "0.25" : "0.5");
  write_family("hit@s0.5", 2, "0.5");
  std::ofstream manifest(root / "manifest.json");
  manifest << R"({"generator": "hand-written", "seed": 0, "families": [
    {"name": "hit", "base": "hit", "type": "vertex-face", "scale": 1, "offset": 0,
     "parameters": {}, "queries": 1, "collisions": 1, "description": "interior hit"},
    {"name": "hit@s0.5", "base": "hit", "type": "vertex-face", "scale": 0.5, "offset": 0,
     "parameters": {}, "queries": 1, "collisions": 1, "description": "interior hit, scaled"}]})";
}

TEST_F(StudyCommand, SuiteIsBrokenDownPerFamilyAndScaleWithSidecarTois) {
  write_suite(dir_ / "suite", false);
  const RunResult r =
      run_cli({"study", "--json", "--repetitions", "1", (dir_ / "suite").string()}, dir_);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json d = nlohmann::json::parse(r.out)["datasets"][0];
  EXPECT_EQ(d["exact_toi"], "sidecar (exact path, at generation)");
  ASSERT_EQ(d["families"].size(), 2u);
  EXPECT_EQ(d["families"][0]["name"], "hit");
  EXPECT_EQ(d["families"][1]["name"], "hit@s0.5");
  // Both families have the base "hit": one row for the two together.
  ASSERT_EQ(d["bases"].size(), 1u);
  EXPECT_EQ(d["bases"][0]["base"], "hit");
  EXPECT_EQ(d["bases"][0]["queries"], 2);
  EXPECT_EQ(d["bases"][0]["contacts"], 2);
  ASSERT_EQ(d["scales"].size(), 2u);
  EXPECT_EQ(d["scales"][0]["scale"], 0.5);
  EXPECT_EQ(d["scales"][1]["scale"], 1.0);
  for (const nlohmann::json& group : {d["families"][0], d["families"][1], d["scales"][0]}) {
    EXPECT_EQ(group["queries"], 1);
    EXPECT_EQ(group["contacts"], 1);
    // Every method, the uncertified ones included, finds the contact at exactly 1/2.
    for (const nlohmann::json& m : group["methods"]) {
      EXPECT_EQ(m["collisions"], 1) << m["label"];
      EXPECT_EQ(m["late_tois"], 0) << m["label"];
      // A positive width allows an earlier toi_lo.
      if (m["method"] != "filtered" || m["parameter"] == 0.0)
        EXPECT_EQ(m["max_abs_toi_error"], 0.0) << m["label"];
    }
  }
}

TEST_F(StudyCommand, SidecarToiIsTheReference) {
  // A sidecar claiming t* = 1/4 where every method finds 1/2: the exact path now reports a late
  // TOI, late by 1/4, so the study exits 1.
  write_suite(dir_ / "suite", true);
  const RunResult r =
      run_cli({"study", "--json", "--repetitions", "1", (dir_ / "suite").string()}, dir_);
  EXPECT_EQ(r.status, 1);
  const nlohmann::json d = nlohmann::json::parse(r.out)["datasets"][0];
  const nlohmann::json& exact = method_row(d["families"][0]["methods"], "exact");
  EXPECT_EQ(exact["late_tois"], 1);
  EXPECT_EQ(exact["max_late_by"], 0.25);
  EXPECT_EQ(method_row(d["families"][1]["methods"], "exact")["late_tois"], 0);
}

// ---- `exactccd study --min-separation D` -------------------------------------------------------

// D = 2^-10 and the fixed triangle a = 0, b = e_x, c = e_y (plane z = 0). Query 0 (truth 0: no
// contact): the vertex p(t) = (s, -s, D/2) with s = 2t - 1 passes over the vertex a at height
// D/2 without crossing the plane; its distance to the triangle is sqrt(s^2 + D^2/4) (nearest
// point (s, 0, 0) for s >= 0, (0, -s, 0) for s < 0), within D from s = -D sqrt(3)/2 on. The
// coplanarity cubic is the constant D/2: the common practice finds no root and misses it.
// Query 1 (truth 1): the vertex (1/4, 1/4, 1 - 2t) through the interior: within D from
// t* = (1 - D)/2 on, a double; the common practice reports the root 1/2, late by D/2.
constexpr double kSeparation = 1.0 / 1024;

fs::path write_separation_file(const fs::path& dir) {
  fs::create_directories(dir / "vertex-face");
  const fs::path file = dir / "vertex-face" / "data_0.csv";
  std::ofstream out(file);
  const std::string a = "0,1,0,1,0,1", b = "1,1,0,1,0,1", c = "0,1,1,1,0,1";
  for (const std::string& p0 : {"-1,1,1,1,1,2048", "1,4,1,4,1,1"}) {
    const bool passing = p0[0] == '-';
    const std::string p1 = passing ? "1,1,-1,1,1,2048" : "1,4,1,4,-1,1";
    const std::string truth = passing ? ",0\n" : ",1\n";
    for (const std::string& row : {p0, a, b, c, p1, a, b, c}) out << row << truth;
  }
  return file;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The document without its timings, which differ from run to run.
void drop_timings(nlohmann::json& j) {
  if (j.is_object()) {
    j.erase("mean_ns");
    for (auto& [key, value] : j.items()) drop_timings(value);
  } else if (j.is_array()) {
    for (nlohmann::json& value : j) drop_timings(value);
  }
}

TEST_F(StudyCommand, MinSeparationCommonPracticeMissesAPassingVertexExactDoesNot) {
  const fs::path file = write_separation_file(dir_ / "data");
  const RunResult r = run_cli({"study", "--json", "--repetitions", "1", "--min-separation",
                               "0.0009765625", file.string()},
                              dir_);
  ASSERT_EQ(r.status, 0) << r.out << read_text(dir_ / "stderr.txt");
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["min_separation"], kSeparation);
  const nlohmann::json& d = j["datasets"][0];
  // Both queries come within D (the truth column, for contact, says only query 1).
  EXPECT_EQ(d["queries"], 2);
  EXPECT_EQ(d["contacts"], 2);
  EXPECT_NE(d["truth"].get<std::string>().find("minimum separation"), std::string::npos);
  for (const std::string& label : kCertified) {
    const nlohmann::json& m = method_row(d["methods"], label);
    EXPECT_EQ(m["collisions"], 2) << label;
    EXPECT_EQ(m["false_positives"], 0) << label;
    EXPECT_EQ(m["false_negatives"], 0) << label;
    EXPECT_EQ(m["late_tois"], 0) << label;
    EXPECT_EQ(m["toi_errors_measured"], 2) << label;
  }
  // The filtered path's TOIs are the exact path's tightest pairs.
  EXPECT_EQ(method_row(d["methods"], "filtered width=0")["max_abs_toi_error"], 0.0);
  // The common practice, at eps = D and at D + eps: query 0 missed, query 1 late by D/2.
  for (const std::string label : {"float_only", "tolerance eps=1e-12", "tolerance eps=1e-9",
                                  "tolerance eps=1e-6"}) {
    const nlohmann::json& m = method_row(d["methods"], label);
    EXPECT_EQ(m["false_positives"], 0) << label;
    EXPECT_EQ(m["false_negatives"], 1) << label;
    EXPECT_EQ(m["examples"]["false_negatives"][0], file.string() + ":0") << label;
    EXPECT_EQ(m["late_tois"], 1) << label;
    EXPECT_EQ(m["max_late_by"], kSeparation / 2) << label;
  }

  const RunResult markdown = run_cli(
      {"study", "--repetitions", "1", "--min-separation", "0.0009765625", file.string()}, dir_);
  ASSERT_EQ(markdown.status, 0);
  EXPECT_NE(markdown.out.find("minimum separation: 0.0009765625"), std::string::npos)
      << markdown.out;
}

TEST_F(StudyCommand, ZeroMinSeparationIsContactAsWithoutTheOption) {
  const fs::path file = write_separation_file(dir_ / "data");
  const RunResult plain = run_cli({"study", "--json", "--repetitions", "1", file.string()}, dir_);
  const RunResult zero = run_cli(
      {"study", "--json", "--repetitions", "1", "--min-separation", "0", file.string()}, dir_);
  ASSERT_EQ(plain.status, 0) << plain.out;
  ASSERT_EQ(zero.status, 0) << zero.out;
  nlohmann::json a = nlohmann::json::parse(plain.out), b = nlohmann::json::parse(zero.out);
  EXPECT_EQ(a["min_separation"], 0.0);
  drop_timings(a);
  drop_timings(b);
  EXPECT_EQ(a, b);
  // Contact: query 0 never touches, query 1 touches at 1/2, found by every method.
  const nlohmann::json& d = a["datasets"][0];
  EXPECT_EQ(d["contacts"], 1);
  EXPECT_EQ(d["truth"], "truth column");
  for (const nlohmann::json& m : d["methods"]) {
    EXPECT_EQ(m["collisions"], 1) << m["label"];
    EXPECT_EQ(m["false_negatives"], 0) << m["label"];
    EXPECT_EQ(m["late_tois"], 0) << m["label"];
  }
  const RunResult markdown = run_cli({"study", "--repetitions", "1", file.string()}, dir_);
  EXPECT_EQ(markdown.out.find("minimum separation"), std::string::npos) << markdown.out;
}

TEST_F(StudyCommand, MinSeparationIgnoresTheContactSidecars) {
  // The suite whose sidecar claims t* = 1/4 (late for every method at contact, see
  // SidecarToiIsTheReference): at D > 0 the reference is the exact path at D, t* = (1 - D)/2.
  write_suite(dir_ / "suite", true);
  const RunResult r = run_cli({"study", "--json", "--repetitions", "1", "--min-separation",
                               "0.0009765625", (dir_ / "suite").string()},
                              dir_);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json d = nlohmann::json::parse(r.out)["datasets"][0];
  for (const nlohmann::json& family : d["families"]) {
    const nlohmann::json& exact = method_row(family["methods"], "exact");
    EXPECT_EQ(exact["collisions"], 1);
    EXPECT_EQ(exact["late_tois"], 0);
    EXPECT_EQ(method_row(family["methods"], "float_only")["late_tois"], 1);
  }
}

TEST_F(StudyCommand, BadMinSeparationIsRefused) {
  const fs::path file = write_separation_file(dir_ / "data");
  for (const std::string bad : {"-1", "-1e-300", "inf", "nan", "1e999"}) {
    const RunResult r =
        run_cli({"study", "--repetitions", "1", "--min-separation", bad, file.string()}, dir_);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(read_text(dir_ / "stderr.txt").find("min-separation"), std::string::npos) << bad;
  }
}

}  // namespace
