// `exactccd rigid SCENE.json` (docs/rigid_scene_format.md): the scenes of tests/data/rigid/ (a
// cube turning into a wall at a contact parameter worked out by hand, the same turn clear of
// the wall, the turn in three steps), the answers equal to the library's Scene on the same
// bodies, a deformable body, mode float_only (the uncertified test), a minimum separation
// (--min-separation or the file's "min_separation", and bench --rigid --min-separation), and
// malformed scene and OBJ files (exit status 2, one line on stderr naming the file and the key,
// never a crash).
#include <gmpxx.h>
#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli_fixture.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace {

using namespace cli_test;
using exactccd::MeshId;
using exactccd::Positions;
using exactccd::RigidMotion;
using exactccd::Scene;
using exactccd::Triangles;
using nlohmann::json;

const fs::path kData = fs::path(EXACTCCD_TEST_DATA) / "rigid";

class CliRigid : public CliTest {
 protected:
  RunResult run_bounded(const std::vector<std::string>& args) {
    return CliTest::run_bounded(args, 60);
  }
  /// `exactccd rigid --json` on a scene written from `scene` (in the temporary folder).
  RunResult run_scene(const json& scene, bool as_json = true) {
    const fs::path file = write_file("scene.json", scene.dump(1));
    std::vector<std::string> args = {"rigid", file.string()};
    if (as_json) args.insert(args.begin() + 1, "--json");
    return run_bounded(args);
  }
  void expect_rejected(const json& scene, const std::vector<std::string>& expected) {
    SCOPED_TRACE(scene.dump());
    expect_bad_input(run_scene(scene), expected);
  }
};

/// The cube [0, 5]^3 of cube.obj, its quads split into fans as the reader does.
void cube(Positions& x, Triangles& t) {
  x.resize(8, 3);
  x << 0, 0, 0, 5, 0, 0, 5, 5, 0, 0, 5, 0, 0, 0, 5, 5, 0, 5, 5, 5, 5, 0, 5, 5;
  const int quads[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5},
                           {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}};
  t.resize(12, 3);
  for (int f = 0; f < 6; ++f) {
    t.row(2 * f) << quads[f][0] - 1, quads[f][1] - 1, quads[f][2] - 1;
    t.row(2 * f + 1) << quads[f][0] - 1, quads[f][2] - 1, quads[f][3] - 1;
  }
}

void wall(double x_wall, Positions& x, Triangles& t) {
  x.resize(4, 3);
  x << x_wall, -2, -1, x_wall, 2, -1, x_wall, 2, 2, x_wall, -2, 2;
  t.resize(2, 3);
  t << 0, 1, 2, 0, 2, 3;
}

/// lo <= q <= hi exactly.
bool encloses(double lo, const mpq_class& q, double hi) { return mpq_class(lo) <= q && q <= mpq_class(hi); }

/// The earliest contact of the cube turning past the wall at x = x_wall, from the library's
/// Scene with minimum separation delta (0: contact).
exactccd::EarliestContact library_cube_and_wall(double x_wall, double delta) {
  Scene scene;
  Positions x;
  Triangles t_cube, t_wall;
  cube(x, t_cube);
  const MeshId body = scene.add_rigid_body(x, t_cube);
  RigidMotion m;
  m.cayley = Eigen::Vector3d(0, 0, -0.5);
  scene.set_rigid_motion(body, m);
  wall(x_wall, x, t_wall);
  scene.add_static_mesh(x, t_wall);
  exactccd::SceneOptions o;
  o.min_separation = delta;
  return scene.earliest_contact(o);
}

TEST_F(CliRigid, CubeTurnsIntoTheWallAtTwoThirds) {
  const RunResult r = run_bounded({"rigid", "--json", (kData / "cube_turns_into_wall.json").string()});
  // A contact is an answer, not a disagreement: exit status 0, as check and grade when they agree.
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const json j = parse_json(r);
  ASSERT_EQ(j["steps"].size(), 1u);
  EXPECT_EQ(j["first_contact_step"], 1);
  const json& c = j["steps"][0]["contact"];
  // The corner (5, 5, 0) meets the wall x = 7 at s = 2/3 (Cayley parameter s/2 = 1/3), the
  // tightest pair of doubles; the time of the constant-speed turn is atan(1/3) / atan(1/2).
  const double lo = c["s_lo"], hi = c["s_hi"];
  EXPECT_TRUE(encloses(lo, mpq_class(2, 3), hi)) << lo << " " << hi;
  EXPECT_EQ(std::nextafter(lo, 1.0), hi);
  const long double t = std::atan(1.0L / 3) / std::atan(0.5L);
  EXPECT_LE(c["time_lo"].get<double>(), t + 1e-15L);
  EXPECT_GE(c["time_hi"].get<double>(), t - 1e-15L);
  EXPECT_LT(c["time_hi"].get<double>() - c["time_lo"].get<double>(), 1e-15);
  EXPECT_EQ(c["type"], "vertex-face");
  EXPECT_EQ(c["first"]["body"], 0);
  EXPECT_EQ(c["first"]["name"], "cube");
  EXPECT_EQ(c["first"]["vertex"], 2);  // (5, 5, 0): cube.obj's third vertex
  EXPECT_EQ(c["second"]["body"], 1);
  EXPECT_EQ(c["second"]["name"], "wall");
  EXPECT_EQ(c["second"]["triangle"], 0);
  EXPECT_EQ(c["second"]["vertices"], json::array({0, 1, 2}));

  // The library's Scene on the same bodies gives the same contact.
  const exactccd::EarliestContact e = library_cube_and_wall(7, 0.0);
  ASSERT_TRUE(e.collides);
  EXPECT_EQ(e.contact.toi_lo, lo);
  EXPECT_EQ(e.contact.toi_hi, hi);
  EXPECT_EQ(e.contact.time_lo, c["time_lo"].get<double>());
  EXPECT_EQ(e.contact.pair.first_index, 2u);

  // The text form says the same.
  const RunResult text = run_bounded({"rigid", (kData / "cube_turns_into_wall.json").string()});
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("step 1: contact at s in [0.66666666666666663, 0.66666666666666674]"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("vertex-face, vertex 2 of body 0 'cube' against triangle 0 (vertices "
                          "0 1 2) of body 1 'wall'"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("first contact in step 1"), std::string::npos);
}

TEST_F(CliRigid, CubeTipsOntoAFloorPlaneAtTwoThirds) {
  const RunResult r =
      run_bounded({"rigid", "--json", (kData / "cube_tips_onto_floor.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  EXPECT_EQ(j["bodies"][1]["kind"], "plane");
  const json& c = j["steps"][0]["contact"];
  // The corners (5, 0, 0) and (5, 5, 0) reach z = -3 at s = 2/3 (tan(theta / 2) = 1/3): the
  // tightest pair of doubles, the earlier vertex of the two in pair order.
  const double lo = c["s_lo"], hi = c["s_hi"];
  EXPECT_TRUE(encloses(lo, mpq_class(2, 3), hi)) << lo << " " << hi;
  EXPECT_EQ(std::nextafter(lo, 1.0), hi);
  const long double t = std::atan(1.0L / 3) / std::atan(0.5L);
  EXPECT_LE(c["time_lo"].get<double>(), t + 1e-15L);
  EXPECT_GE(c["time_hi"].get<double>(), t - 1e-15L);
  EXPECT_EQ(c["type"], "point-plane");
  EXPECT_EQ(c["first"]["body"], 0);
  EXPECT_EQ(c["second"]["body"], 1);
  EXPECT_EQ(c["second"]["name"], "floor");
  EXPECT_EQ(c["second"]["plane"], 0);
  const int vertex = c["first"]["vertex"];
  Positions x;
  Triangles triangles;
  cube(x, triangles);
  EXPECT_EQ(x(vertex, 0), 5.0);  // (5, 0, 0) or (5, 5, 0)
  EXPECT_EQ(x(vertex, 2), 0.0);
  const RunResult text = run_bounded({"rigid", (kData / "cube_tips_onto_floor.json").string()});
  EXPECT_NE(text.out.find("point-plane, vertex " + std::to_string(vertex) +
                          " of body 0 'cube' against the plane of body 1 'floor'"),
            std::string::npos)
      << text.out;
  // A plane is an origin and a non-zero normal, nothing else.
  json s = json::parse(std::ifstream(kData / "cube_tips_onto_floor.json"));
  s["bodies"][0]["obj"] = (kData / "cube.obj").string();
  json bad = s;
  bad["bodies"][1]["normal"] = {0, 0, 0};
  expect_rejected(bad, {"bodies[1].normal", "zero"});
  bad = s;
  bad["bodies"][1]["positions"] = {{0, 0, 0}};
  expect_rejected(bad, {"bodies[1].positions", "only \"origin\" and \"normal\""});
  bad = s;
  bad["bodies"][1].erase("origin");
  expect_rejected(bad, {"bodies[1]", "missing key \"origin\""});
  bad = s;
  bad["bodies"][0]["normal"] = {0, 0, 1};
  expect_rejected(bad, {"bodies[0].normal", "only a plane"});
}

TEST_F(CliRigid, TheSameTurnClearOfTheWall) {
  const RunResult r = run_bounded({"rigid", (kData / "cube_turns_clear_of_wall.json").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("step 1: collision-free"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("collision-free in every step"), std::string::npos) << r.out;
  const RunResult j = run_bounded({"rigid", "--json", (kData / "cube_turns_clear_of_wall.json").string()});
  EXPECT_EQ(j.status, 0);
  const json out = parse_json(j);
  EXPECT_TRUE(out["first_contact_step"].is_null());
  EXPECT_EQ(out["steps"][0]["collides"], false);
  EXPECT_TRUE(out["steps"][0]["contact"].is_null());
}

TEST_F(CliRigid, StepsStartFromTheRoundedEndPose) {
  const RunResult r = run_bounded({"rigid", "--json", (kData / "cube_turns_in_steps.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  ASSERT_EQ(j["steps"].size(), 3u);
  EXPECT_EQ(j["steps"][0]["collides"], false);
  EXPECT_EQ(j["steps"][0]["start_rounding"], 0.0);
  EXPECT_EQ(j["steps"][1]["collides"], true);
  EXPECT_EQ(j["steps"][2]["collides"], false);  // already past the wall's plane
  EXPECT_EQ(j["first_contact_step"], 2);
  // 30-degree turns have irrational end poses: rounded, by less than an ulp of 5.
  for (int k : {1, 2}) {
    const double rounding = j["steps"][k]["start_rounding"];
    EXPECT_GT(rounding, 0.0);
    EXPECT_LE(rounding, 8.9e-16);
  }
  // The corner reaches x = 7 after atan2(3, 4) = 36.87 degrees, 6.87 degrees into step 2: time
  // (atan2(3, 4) - 30 degrees) / 30 degrees (up to the rounding of the start pose and of the
  // Cayley vector of a 30-degree turn).
  const json& c = j["steps"][1]["contact"];
  const double expected = (std::atan2(3.0, 4.0) - M_PI / 6) / (M_PI / 6);
  EXPECT_NEAR(c["time_lo"].get<double>(), expected, 1e-12);
  EXPECT_EQ(c["first"]["vertex"], 2);

  // The library with the same steps: step 2 starts from the exact end pose of step 1, each
  // coordinate rounded to the nearest double (computed here independently: the exact position
  // from the matrix form, rounded by comparing the two doubles around it).
  Positions x;
  Triangles t;
  cube(x, t);
  const RigidMotion turn = RigidMotion::turn(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1),
                                             -30 * (M_PI / 180));
  Positions start2(x.rows(), 3);
  mpq_class largest(0);
  const mpq_class qz(turn.cayley.z()), qq = qz * qz;
  for (Eigen::Index v = 0; v < x.rows(); ++v) {
    // A turn about the z axis through the origin: C(q) = ((1 - q.q) I + 2 q q^T + 2 [q]x) /
    // (1 + q.q) with q = (0, 0, qz).
    const mpq_class px(x(v, 0)), py(x(v, 1));
    const mpq_class exact[3] = {((1 - qq) * px - 2 * qz * py) / (1 + qq),
                                (2 * qz * px + (1 - qq) * py) / (1 + qq), mpq_class(x(v, 2))};
    for (int k = 0; k < 3; ++k) {
      const double down = exact[k].get_d();  // truncated towards zero
      const double up = std::nextafter(down, sgn(exact[k]) < 0 ? -HUGE_VAL : HUGE_VAL);
      const mpq_class e_down = abs(exact[k] - down), e_up = abs(exact[k] - up);
      start2(v, k) = e_up < e_down ? up : down;  // no ties here (checked below)
      EXPECT_NE(e_up, e_down);
      largest = std::max(largest, std::min(e_up, e_down));
    }
  }
  const double rounding = j["steps"][1]["start_rounding"];
  EXPECT_LE(largest, mpq_class(rounding));
  EXPECT_LE(mpq_class(rounding), largest * (1 + mpq_class(1, 1 << 20)));  // tight
  Scene scene;
  const MeshId body = scene.add_rigid_body(x, t);
  Triangles t_wall;
  Positions x_wall;
  wall(7, x_wall, t_wall);
  scene.add_static_mesh(x_wall, t_wall);
  scene.set_rigid_motion(body, start2, turn);
  const exactccd::EarliestContact e = scene.earliest_contact();
  ASSERT_TRUE(e.collides);
  EXPECT_EQ(e.contact.toi_lo, c["s_lo"].get<double>());
  EXPECT_EQ(e.contact.toi_hi, c["s_hi"].get<double>());
  EXPECT_EQ(e.contact.time_lo, c["time_lo"].get<double>());
  EXPECT_EQ(e.contact.time_hi, c["time_hi"].get<double>());
}

TEST_F(CliRigid, DeformableBodyAgainstARigidOneAtRest) {
  // A triangle falling through the cube's top face (z = 5) at t = 1/2, the cube at rest (no
  // motion: a rigid body with the zero motion).
  json scene = {{"bodies",
                 {{{"name", "cube"}, {"kind", "rigid"}, {"obj", (kData / "cube.obj").string()}},
                  {{"name", "leaf"},
                   {"kind", "deformable"},
                   {"positions", {{1, 1, 6}, {3, 1, 6}, {1, 3, 6}}},
                   {"end_positions", {{1, 1, 4}, {3, 1, 4}, {1, 3, 4}}},
                   {"triangles", {{0, 1, 2}}}}}}};
  const RunResult r = run_scene(scene);
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  const json& c = j["steps"][0]["contact"];
  EXPECT_EQ(c["s_lo"], 0.5);
  EXPECT_EQ(c["s_hi"], 0.5);
  EXPECT_EQ(c["time_lo"], 0.5);  // nothing rotates: time = s
  EXPECT_EQ(c["first"]["name"], "leaf");
  EXPECT_EQ(c["second"]["name"], "cube");
  // With t_max below the contact: collision-free.
  scene["t_max"] = 0.25;
  EXPECT_EQ(run_scene(scene).status, 0);
  scene["mode"] = "exact";
  scene["t_max"] = 1;
  EXPECT_EQ(parse_json(run_scene(scene))["steps"][0]["contact"]["s_lo"], 0.5);
}

TEST_F(CliRigid, HelpListsTheExitStatuses) {
  const RunResult r = run({"rigid", "--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("a contact\n     is an answer, not a disagreement"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("SCENE"), std::string::npos);
}

TEST_F(CliRigid, FloatOnlyModeRunsTheUncertifiedTest) {
  // The cube turning into the wall with "mode": "float_only": the uncertified double test finds
  // the same first contact (a clear, transversal one) with one double near s = 2/3.
  std::ifstream in(kData / "cube_turns_into_wall.json");
  json scene = json::parse(in);
  scene["bodies"][0]["obj"] = (kData / "cube.obj").string();
  scene["mode"] = "float_only";
  const RunResult r = run_scene(scene);
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  EXPECT_EQ(j["mode"], "float_only");
  EXPECT_EQ(j["first_contact_step"], 1);
  const json& c = j["steps"][0]["contact"];
  const double lo = c["s_lo"], hi = c["s_hi"];
  EXPECT_EQ(lo, hi);
  EXPECT_NEAR(lo, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(c["type"], "vertex-face");
  EXPECT_EQ(c["first"]["vertex"], 2);
  EXPECT_EQ(c["second"]["triangle"], 0);
  const RunResult text = run_scene(scene, false);
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("mode float_only"), std::string::npos) << text.out;
}

TEST_F(CliRigid, ModeFilteredAndItsOldNameDefault) {
  // "filtered" (the certified default) and "default", its name before, still accepted: the
  // same contact, printed "filtered" (cube_turns_in_steps.json itself still says "default").
  std::ifstream in(kData / "cube_turns_into_wall.json");
  json scene = json::parse(in);
  scene["bodies"][0]["obj"] = (kData / "cube.obj").string();
  std::map<std::string, json> contact;
  for (const std::string mode : {"filtered", "default"}) {
    SCOPED_TRACE(mode);
    scene["mode"] = mode;
    const RunResult r = run_scene(scene);
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = parse_json(r);
    EXPECT_EQ(j["mode"], "filtered");
    EXPECT_EQ(j["first_contact_step"], 1);
    contact[mode] = j["steps"][0]["contact"];
    const RunResult text = run_scene(scene, false);
    EXPECT_NE(text.out.find("mode filtered"), std::string::npos) << text.out;
  }
  EXPECT_EQ(contact["filtered"], contact["default"]);
  scene.erase("mode");
  EXPECT_EQ(parse_json(run_scene(scene))["mode"], "filtered");
}

// ---------------------------------------------------------------------------------------------
// Minimum separation: --min-separation D, or "min_separation" in the file

TEST_F(CliRigid, MinSeparationFindsTheCloseApproach) {
  // The turn clear of the wall passes it 0.0039 short (5 sqrt(2) = 7.0711 against 7.075):
  // within 0.01, not within 0.001. The command's contact equals the library's.
  const std::string clear = (kData / "cube_turns_clear_of_wall.json").string();
  const RunResult r = run_bounded({"rigid", "--json", "--min-separation", "0.01", clear});
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  EXPECT_EQ(j["min_separation"], 0.01);
  EXPECT_EQ(j["first_contact_step"], 1);
  const json& c = j["steps"][0]["contact"];
  const exactccd::EarliestContact e = library_cube_and_wall(7.075, 0.01);
  ASSERT_TRUE(e.collides);
  EXPECT_EQ(c["s_lo"].get<double>(), e.contact.toi_lo);
  EXPECT_EQ(c["s_hi"].get<double>(), e.contact.toi_hi);
  EXPECT_EQ(c["type"], e.contact.pair.type == exactccd::QueryType::vertex_face ? "vertex-face"
                                                                                : "edge-edge");
  // Near 45 degrees of the 53.13-degree turn: s a little below tan(22.5 degrees) / (1/2).
  EXPECT_GT(e.contact.toi_lo, 0.5);
  EXPECT_LT(e.contact.toi_hi, 2 * std::tan(M_PI / 8));
  const RunResult text = run_bounded({"rigid", "--min-separation", "0.01", clear});
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("min_separation 0.01"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("step 1: contact at s in"), std::string::npos) << text.out;
  // Within 0.001: still clear; without delta the header does not name one.
  const RunResult far = run_bounded({"rigid", "--min-separation", "0.001", clear});
  EXPECT_EQ(far.status, 0) << far.err;
  EXPECT_NE(far.out.find("collision-free in every step"), std::string::npos) << far.out;
  EXPECT_FALSE(library_cube_and_wall(7.075, 0.001).collides);
  const RunResult plain = run_bounded({"rigid", clear});
  EXPECT_EQ(plain.out.find("min_separation"), std::string::npos) << plain.out;
}

TEST_F(CliRigid, MinSeparationFromTheSceneFile) {
  // "min_separation" in the file does the same; --min-separation replaces it (0: contact).
  std::ifstream in(kData / "cube_turns_clear_of_wall.json");
  json scene = json::parse(in);
  scene["bodies"][0]["obj"] = (kData / "cube.obj").string();
  scene["min_separation"] = 0.01;
  const RunResult r = run_scene(scene);
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  EXPECT_EQ(j["min_separation"], 0.01);
  EXPECT_EQ(j["steps"][0]["contact"]["s_lo"].get<double>(),
            library_cube_and_wall(7.075, 0.01).contact.toi_lo);
  const fs::path file = write_file("scene.json", scene.dump(1));
  const RunResult replaced = run_bounded({"rigid", "--json", "--min-separation", "0", file.string()});
  EXPECT_EQ(replaced.status, 0) << replaced.err;
  EXPECT_EQ(parse_json(replaced)["min_separation"], 0.0);
  // The float_only mode runs with a minimum separation too (uncertified: any verdict).
  scene["mode"] = "float_only";
  const RunResult rough = run_scene(scene);
  EXPECT_TRUE(rough.status == 0 || rough.status == 1) << rough.err;
  EXPECT_EQ(parse_json(rough)["mode"], "float_only");
}

TEST_F(CliRigid, BenchRigidWithMinSeparation) {
  // Each delta is a run of every mode, graded at that delta: the certified modes agree bit for
  // bit (exit status 0), float_only is graded against the first certified mode; a delta turns
  // near misses into contacts.
  const RunResult r = run_bounded({"bench", "--rigid", "--rigid-count", "6", "--seed", "3",
                                   "--repetitions", "1", "--modes", "filtered,exact,float_only",
                                   "--min-separation", "0,0.001", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r);
  EXPECT_EQ(j.value("disagreements", 1u), 0u);
  const json& modes = j.at("modes");
  ASSERT_EQ(modes.size(), 6u) << r.out;
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(modes[k]["min_separation"].get<double>(), k < 3 ? 0.0 : 0.001);
    EXPECT_FALSE(modes[k].contains("min_separation_factor"));
  }
  EXPECT_EQ(modes[4]["mode"], "exact");
  EXPECT_EQ(modes[3]["contacts"], modes[4]["contacts"]);
  EXPECT_GE(modes[3]["contacts"].get<int>(), modes[0]["contacts"].get<int>());
  EXPECT_EQ(modes[5]["graded_against"], "filtered");
  EXPECT_TRUE(modes[5].at("false_negatives").is_number());
  // Relative: factors of the set's size.
  const RunResult rel = run_bounded({"bench", "--rigid", "--rigid-count", "6", "--repetitions",
                                     "1", "--modes", "filtered", "--min-separation", "0.01",
                                     "--relative-separation", "--json"});
  ASSERT_EQ(rel.status, 0) << rel.err;
  const json jr = parse_json(rel);
  const double size = jr["size"];
  EXPECT_GT(size, 0.0);
  EXPECT_EQ(jr["modes"][0]["min_separation_factor"], 0.01);
  EXPECT_DOUBLE_EQ(jr["modes"][0]["min_separation"].get<double>(), 0.01 * size);
  // The text table gains a delta column and names the delta of each grading.
  const RunResult text = run_bounded({"bench", "--rigid", "--rigid-count", "6", "--repetitions",
                                      "1", "--modes", "filtered,float_only", "--min-separation",
                                      "0.001"});
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("float_only against filtered at delta 0.001"), std::string::npos)
      << text.out;
  for (const char* delta : {"-1", "nan"}) {
    SCOPED_TRACE(delta);
    expect_bad_input(run_bounded({"bench", "--rigid", "--rigid-count", "6", "--min-separation",
                                  delta}),
                     {"--min-separation"});
  }
}

// ---------------------------------------------------------------------------------------------
// Malformed input: exit status 2, one line on stderr naming the file and the key

json good_scene() {
  return {{"bodies",
           {{{"name", "cube"},
             {"kind", "rigid"},
             {"positions", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
             {"triangles", {{0, 1, 2}, {0, 1, 3}}},
             {"motion", {{"pivot", {0, 0, 0}}, {"axis", {0, 0, 1}}, {"angle_degrees", 45}}}},
            {{"kind", "static"},
             {"positions", {{2, -1, -1}, {2, 1, -1}, {2, 0, 2}}},
             {"triangles", {{0, 1, 2}}}}}}};
}

TEST_F(CliRigid, GoodSceneRuns) {
  const RunResult r = run_scene(good_scene());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r)["bodies"][1]["name"], "body 1");  // the default name
}

// Axes whose norm overflows or underflows in doubles are good directions all the same: the same
// turn as the unit axis, and the library's message is printed with one "exactccd: ".
TEST_F(CliRigid, HugeAndTinyAxesTurnAsTheUnitAxis) {
  json unit = good_scene();
  const RunResult reference = run_scene(unit, true);
  ASSERT_EQ(reference.status, 0) << reference.err;
  for (const json& axis : {json{0, 0, 1e308}, json{0, 0, 1e-320}, json{0, 0, 4.9e-324}}) {
    SCOPED_TRACE(axis.dump());
    json s = good_scene();
    s["bodies"][0]["motion"]["axis"] = axis;
    const RunResult r = run_scene(s, true);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(parse_json(r)["steps"], parse_json(reference)["steps"]);
  }
  json s = good_scene();
  s["bodies"][0]["motion"]["axis"] = {1e308, 1e308, 1e308};
  EXPECT_EQ(run_scene(s).status, 0);
}

TEST_F(CliRigid, MalformedScenesAreRejectedWithTheKey) {
  json s;
  s = good_scene(); s.erase("bodies");
  expect_rejected(s, {"missing key \"bodies\""});
  s = good_scene(); s["bodies"] = 3;
  expect_rejected(s, {"bodies", "non-empty array"});
  s = good_scene(); s["bodies"] = json::array();
  expect_rejected(s, {"bodies", "non-empty array"});
  s = good_scene(); s["bodies"][0].erase("kind");
  expect_rejected(s, {"bodies[0]", "missing key \"kind\""});
  s = good_scene(); s["bodies"][0]["kind"] = "wobbly";
  expect_rejected(s, {"bodies[0].kind", "'wobbly'"});
  s = good_scene(); s["bodies"][1]["positon"] = 1;
  expect_rejected(s, {"bodies[1]", "unknown key 'positon'"});
  s = good_scene(); s["extra"] = 1;
  expect_rejected(s, {"unknown key 'extra'"});
  s = good_scene(); s["bodies"][0]["positions"][1] = {1, 0};
  expect_rejected(s, {"bodies[0].positions[1]", "3 numbers"});
  s = good_scene(); s["bodies"][0]["positions"][1][2] = "x";
  expect_rejected(s, {"bodies[0].positions[1][2]", "a number", "string"});
  s = good_scene(); s["bodies"][0]["triangles"][1][2] = 9;
  expect_rejected(s, {"bodies[0].triangles[1][2]", "out of range", "4 vertices"});
  s = good_scene(); s["bodies"][0]["triangles"][1][2] = -1;
  expect_rejected(s, {"bodies[0].triangles[1][2]", "out of range"});
  s = good_scene(); s["bodies"][0]["triangles"][1][2] = 1.5;
  expect_rejected(s, {"bodies[0].triangles[1][2]", "integer"});
  s = good_scene(); s["bodies"][0]["triangles"][1] = {0, 1, 1};
  expect_rejected(s, {"bodies[0].triangles[1]", "repeats a vertex"});
  s = good_scene(); s["bodies"][0].erase("triangles");
  expect_rejected(s, {"bodies[0]", "missing key \"triangles\""});
  s = good_scene(); s["bodies"][0].erase("positions");
  expect_rejected(s, {"bodies[0]", "\"obj\" or \"positions\""});
  s = good_scene(); s["bodies"][0]["obj"] = "cube.obj";
  expect_rejected(s, {"bodies[0]", "not both"});
  s = good_scene(); s["bodies"][0]["motion"]["cayley"] = {0, 0, 1};
  expect_rejected(s, {"bodies[0].motion", "not both"});
  s = good_scene(); s["bodies"][0]["motion"]["angle_degrees"] = 180;
  expect_rejected(s, {"bodies[0].motion.angle_degrees", "180"});
  s = good_scene(); s["bodies"][0]["motion"]["axis"] = {0, 0, 0};
  expect_rejected(s, {"bodies[0].motion.axis", "zero"});
  s = good_scene(); s["bodies"][0]["motion"].erase("axis");
  expect_rejected(s, {"bodies[0].motion", "missing key \"axis\""});
  s = good_scene(); s["bodies"][0]["motion"]["spin"] = 1;
  expect_rejected(s, {"bodies[0].motion", "unknown key 'spin'"});
  s = good_scene(); s["bodies"][0]["steps"] = json::array();
  expect_rejected(s, {"bodies[0]", "\"motion\" or \"steps\""});
  s = good_scene(); s["bodies"][0].erase("motion"); s["bodies"][0]["steps"] = {1};
  expect_rejected(s, {"bodies[0].steps[0]", "motion object"});
  s = good_scene(); s["bodies"][1]["motion"] = {{"cayley", {0, 0, 1}}};
  expect_rejected(s, {"bodies[1].motion", "only a rigid body"});
  s = good_scene(); s["bodies"][0]["end_positions"] = s["bodies"][0]["positions"];
  expect_rejected(s, {"bodies[0].end_positions", "only a deformable body"});
  s = good_scene(); s["bodies"][1]["kind"] = "deformable";
  s["bodies"][1]["end_positions"] = {{0, 0, 0}};
  expect_rejected(s, {"bodies[1].end_positions", "1 rows", "3 vertices"});
  s = good_scene(); s["bodies"][0]["name"] = 7;
  expect_rejected(s, {"bodies[0].name", "a string"});
  s = good_scene(); s["mode"] = "fast";
  expect_rejected(s, {"mode", "'fast'", "\"filtered\"", "\"float_only\"", "\"exact\""});
  s = good_scene(); s["mode"] = 1;
  expect_rejected(s, {"mode", "\"filtered\""});
  for (double bad : {0.0, -1.0, 1.5}) {
    s = good_scene(); s["t_max"] = bad;
    expect_rejected(s, {"t_max", "(0, 1]"});
  }
  s = good_scene(); s["toi_width"] = -1;
  expect_rejected(s, {"toi_width", ">= 0"});
}

TEST_F(CliRigid, BadMinSeparationIsRejected) {
  const std::string scene = (kData / "cube_turns_into_wall.json").string();
  for (const char* delta : {"-1", "-1e-300", "nan", "inf", "", "abc"}) {
    SCOPED_TRACE(delta);
    expect_bad_input(run_bounded({"rigid", "--min-separation", delta, scene}),
                     {"--min-separation"});
  }
  expect_bad_input(run_bounded({"rigid", "--min-separation", "-1", scene}),
                   {"--min-separation", ">= 0", "-1"});
  // Beyond the doubles either way: named, not rounded to 0 or infinity.
  expect_bad_input(run_bounded({"rigid", "--min-separation", "1e-400", scene}),
                   {"--min-separation", "'1e-400'", "round to 0"});
  expect_bad_input(run_bounded({"rigid", "--min-separation", "1e400", scene}),
                   {"--min-separation", "'1e400'", "beyond the largest double"});
  json s = good_scene();
  s["min_separation"] = -0.5;
  expect_rejected(s, {"min_separation", ">= 0"});
  s["min_separation"] = "small";
  expect_rejected(s, {"min_separation", "a number"});
}

TEST_F(CliRigid, MalformedFilesAreRejected) {
  // Not JSON, numbers beyond the doubles, an empty file, deep nesting.
  const auto rejects = [&](const std::string& name, const std::string& text,
                           const std::vector<std::string>& expected) {
    SCOPED_TRACE(name);
    const fs::path file = write_file(name, text);
    std::vector<std::string> wanted = expected;
    wanted.push_back(file.string());
    expect_bad_input(run_bounded({"rigid", file.string()}), wanted);
  };
  rejects("syntax.json", "{\"bodies\": [}", {"invalid JSON", "line 1"});
  rejects("empty.json", "", {"invalid JSON"});
  rejects("nan.json", "{\"bodies\": NaN}", {"invalid JSON"});
  std::string huge = good_scene().dump();
  huge.replace(huge.find("[0,0,0]"), 7, "[1e999,0,0]");
  rejects("huge.json", huge, {"1e999"});
  rejects("deep.json", std::string(100000, '[') + std::string(100000, ']'), {"the scene"});
  // nlohmann would keep the last of two keys, and stop reading at a NUL byte.
  std::string twice = good_scene().dump();
  twice.insert(1, "\"t_max\":1,\"t_max\":0.5,");
  rejects("twice.json", twice, {"'t_max'", "appears twice"});
  std::string inner = good_scene().dump();
  inner.replace(inner.find("\"kind\":\"static\""), 15, "\"kind\":\"static\",\"kind\":\"rigid\"");
  rejects("twice_inner.json", inner, {"'kind'", "appears twice"});
  rejects("nul.json", good_scene().dump() + std::string(1, '\0') + "{\"more\": 1}",
          {"NUL byte"});
  rejects("array.json", "[1, 2]", {"the scene", "an object"});
  // Files that are not regular files, or missing.
  expect_bad_input(run_bounded({"rigid", (dir_ / "missing.json").string()}),
                   {"missing.json", "No such file"});
  expect_bad_input(run_bounded({"rigid", dir_.string()}), {"is a directory"});
  const fs::path fifo = dir_ / "pipe.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_bad_input(run_bounded({"rigid", fifo.string()}), {"pipe.json", "FIFO"});
  // The command line.
  const RunResult no_scene = run({"rigid"});
  EXPECT_EQ(no_scene.status, 2);
  EXPECT_NE(no_scene.err.find("SCENE"), std::string::npos) << no_scene.err;
}

TEST_F(CliRigid, MalformedObjFilesAreRejectedWithTheLine) {
  const auto scene_with = [&](const std::string& obj_text) {
    write_file("body.obj", obj_text);
    json s = good_scene();
    s["bodies"][0].erase("positions");
    s["bodies"][0].erase("triangles");
    s["bodies"][0]["obj"] = "body.obj";  // relative to the scene file's folder
    return s;
  };
  const std::string obj = (dir_ / "body.obj").string();
  EXPECT_EQ(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf -4 -3 -1\n"))
                .status,
            0);
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0\n")), {obj + ":2:", "x y z"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 nan\n")), {obj + ":2:", "'nan'"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n")),
                   {obj + ":4:", "at least 3"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")),
                   {obj + ":4:", "vertex 7", "3 vertices"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n")),
                   {obj + ":4:", "out of range"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n")),
                   {obj + ":4:", "'0'"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/2 x/3\n")),
                   {obj + ":4:", "'x/3'"});
  expect_bad_input(run_scene(scene_with("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1\n")),
                   {obj + ":4:", "repeats vertex 1"});
  expect_bad_input(run_scene(scene_with("# nothing\n")), {obj, "no vertex"});
  json s = good_scene();
  s["bodies"][0].erase("positions");
  s["bodies"][0].erase("triangles");
  s["bodies"][0]["obj"] = "missing.obj";
  expect_bad_input(run_scene(s), {"missing.obj", "No such file"});
  s["bodies"][0]["obj"] = ".";
  expect_bad_input(run_scene(s), {"is a directory"});
}

}  // namespace
