// Tests of the simulation-like query generator (corpus/simulation_queries.hpp) and of `exactccd simulate`.
// The broad phase is checked against an all-pairs enumeration written here, with its own box
// computation and its own exclusion rules; contact / no-contact from the exact path.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "corpus/barrier_steps.hpp"
#include "exactccd/scene.hpp"
#include "corpus/broad_phase.hpp"
#include "corpus/simulation_queries.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"

namespace {

namespace fs = std::filesystem;
using exactccd::QueryType;
using namespace exactccd::sim;

// The bits of a double: equal keys mean bit-identical values (0.0 and -0.0 differ).
std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// A query as comparable data: type, pair kind and the bits of its 24 coordinates.
using QueryKey = std::tuple<int, int, std::array<std::uint64_t, 24>>;

QueryKey key_of(QueryType type, PairKind kind, const std::array<Eigen::Vector3d, 8>& points) {
  std::array<std::uint64_t, 24> coordinates;
  for (int row = 0; row < 8; ++row)
    for (int k = 0; k < 3; ++k) coordinates[3 * row + k] = bits(points[row][k]);
  return {static_cast<int>(type), static_cast<int>(kind), coordinates};
}

QueryKey key_of(const SimulationQuery& q) { return key_of(q.type, q.kind, q.points); }

exactccd::RationalQuery rational_of(const SimulationQuery& q) {
  exactccd::RationalQuery r;
  r.type = q.type;
  for (int row = 0; row < 8; ++row)
    r.points[row] = {mpq_class(q.points[row].x()), mpq_class(q.points[row].y()),
                     mpq_class(q.points[row].z())};
  return r;
}

// The exact verdict of every query, in parallel.
std::vector<std::uint8_t> exact_verdicts(const std::vector<SimulationQuery>& queries) {
  std::vector<std::uint8_t> collides(queries.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        collides[i] = exactccd::exact_ccd(rational_of(queries[i])).collides;
                    });
  return collides;
}

SimulationConfig tiny_config() {
  SimulationConfig config;
  config.sheet_resolution = 6;
  config.steps = 30;  // the sheet reaches the sphere after about 16 steps
  return config;
}

// ---- Determinism ------------------------------------------------------------------------------

TEST(SimulationQueries, SameConfigGivesBitIdenticalQueries) {
  const SimulationConfig config = small_simulation_config();
  const std::vector<SimulationQuery> first = generate_simulation_queries(config);
  const std::vector<SimulationQuery> second = generate_simulation_queries(config);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i)
    ASSERT_TRUE(key_of(first[i]) == key_of(second[i])) << "query " << i;
}

TEST(SimulationQueries, SeedChangesTheQueries) {
  SimulationConfig config = tiny_config();
  const std::vector<SimulationQuery> one = generate_simulation_queries(config);
  config.seed = 2;
  const std::vector<SimulationQuery> two = generate_simulation_queries(config);
  bool differ = one.size() != two.size();
  for (std::size_t i = 0; !differ && i < one.size(); ++i) differ = key_of(one[i]) != key_of(two[i]);
  EXPECT_TRUE(differ);
}

TEST(SimulationQueries, RejectsConfigOutsideItsDomain) {
  for (const auto& [resolution, steps] : {std::pair{1, 10}, {1025, 10}, {8, 0}, {8, -3}}) {
    SimulationConfig config;
    config.sheet_resolution = resolution;
    config.steps = steps;
    EXPECT_THROW(generate_simulation_queries(config), std::invalid_argument)
        << resolution << " " << steps;
  }
}

// ---- The small config --------------------------------------------------------------------------

TEST(SimulationQueries, SmallConfigHasContactsAndNearMissesOfEveryType) {
  const std::vector<SimulationQuery> queries =
      generate_simulation_queries(small_simulation_config());
  // The small config is specified as about 50,000 queries.
  EXPECT_GE(queries.size(), 40000u);
  EXPECT_LE(queries.size(), 70000u);
  for (const SimulationQuery& q : queries)
    for (const Eigen::Vector3d& p : q.points)
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(std::isfinite(p[k]));
        ASSERT_FALSE(p[k] == 0.0 && std::signbit(p[k]));  // no -0.0 (see the round trip)
      }

  const std::vector<std::uint8_t> collides = exact_verdicts(queries);
  std::size_t count[2][2] = {};  // [type][collides]
  std::size_t sheet_sphere_contacts = 0, body_contacts = 0, queries_of_kind[3] = {};
  for (std::size_t i = 0; i < queries.size(); ++i) {
    ++count[static_cast<int>(queries[i].type)][collides[i]];
    ++queries_of_kind[static_cast<int>(queries[i].kind)];
    sheet_sphere_contacts += collides[i] && queries[i].kind == PairKind::sheet_sphere;
    body_contacts += collides[i] && queries[i].kind == PairKind::body_body;
  }
  for (int type = 0; type < 2; ++type) {
    EXPECT_GT(count[type][1], 0u) << "contacts, type " << type;
    EXPECT_GT(count[type][0], 0u) << "near misses, type " << type;
  }
  EXPECT_GT(sheet_sphere_contacts, 0u);  // the sheet touches the sphere
  EXPECT_GT(body_contacts, 0u);
  for (const std::size_t n : queries_of_kind) EXPECT_GT(n, 0u);
}

// ---- Broad phase -------------------------------------------------------------------------------

struct TestBox {
  double lo[3], hi[3];
};

// The box of the given vertices' start and end positions.
TestBox box_of(const MovingMesh& m, std::initializer_list<std::uint32_t> vertices) {
  TestBox b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = INFINITY;
    b.hi[k] = -INFINITY;
  }
  for (const std::uint32_t v : vertices)
    for (const Eigen::Vector3d& p : {m.start.at(v), m.end.at(v)})
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], p[k]);
        b.hi[k] = std::max(b.hi[k], p[k]);
      }
  return b;
}

bool touch(const TestBox& a, const TestBox& b) {
  for (int k = 0; k < 3; ++k)
    if (!(a.lo[k] <= b.hi[k] && b.lo[k] <= a.hi[k])) return false;
  return true;
}

// Every vertex-face and edge-edge pair of the step whose boxes meet, by trying all pairs.
std::multiset<QueryKey> all_pairs(const SimulationStep& step) {
  std::multiset<QueryKey> keys;
  for (const MeshPair& pair : step.pairs) {
    const MovingMesh& a = step.meshes.at(pair.first);
    const MovingMesh& b = step.meshes.at(pair.second);
    const bool self = pair.first == pair.second;
    auto vertex_face = [&](const MovingMesh& vm, const MovingMesh& tm) {
      for (std::uint32_t v = 0; v < vm.topology->vertex_count; ++v)
        for (const auto& t : tm.topology->triangles) {
          if (self && std::find(t.begin(), t.end(), v) != t.end()) continue;
          if (!touch(box_of(vm, {v}), box_of(tm, {t[0], t[1], t[2]}))) continue;
          keys.insert(key_of(QueryType::vertex_face, pair.kind,
                             {vm.start[v], tm.start[t[0]], tm.start[t[1]], tm.start[t[2]],
                              vm.end[v], tm.end[t[0]], tm.end[t[1]], tm.end[t[2]]}));
        }
    };
    vertex_face(a, b);
    if (!self) vertex_face(b, a);
    const auto& ea = a.topology->edges;
    const auto& eb = b.topology->edges;
    for (std::size_t i = 0; i < ea.size(); ++i)
      for (std::size_t j = self ? i + 1 : 0; j < eb.size(); ++j) {
        const auto& e = ea[i];
        const auto& f = eb[j];
        if (self && (e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1])) continue;
        if (!touch(box_of(a, {e[0], e[1]}), box_of(b, {f[0], f[1]}))) continue;
        keys.insert(key_of(QueryType::edge_edge, pair.kind,
                           {a.start[e[0]], a.start[e[1]], b.start[f[0]], b.start[f[1]],
                            a.end[e[0]], a.end[e[1]], b.end[f[0]], b.end[f[1]]}));
      }
  }
  return keys;
}

TEST(SimulationQueries, BroadPhaseFindsExactlyTheOverlappingPairs) {
  std::size_t steps = 0, of_kind[3] = {};
  simulate(tiny_config(), [&](const SimulationStep& step) {
    ++steps;
    std::vector<SimulationQuery> found;
    append_step_queries(step, found);
    std::multiset<QueryKey> found_keys;
    for (const SimulationQuery& q : found) {
      found_keys.insert(key_of(q));
      ++of_kind[static_cast<int>(q.kind)];
    }
    EXPECT_EQ(found_keys.size(), found.size());
    EXPECT_TRUE(found_keys == all_pairs(step)) << "step " << step.index;
  });
  EXPECT_EQ(steps, 30u);
  for (const std::size_t n : of_kind) EXPECT_GT(n, 0u);  // every kind of pair was exercised
}

TEST(SimulationQueries, GridBroadPhaseOnTouchingAndFlatBoxes) {
  // Boxes with corners on a coarse lattice: many touch exactly on a face, an edge or a corner,
  // and some are flat or points.
  std::mt19937 random(7);
  std::uniform_int_distribution<int> corner(0, 12), size(0, 3);
  auto make = [&](std::size_t n) {
    std::vector<Box> boxes(n);
    for (Box& b : boxes)
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = 0.5 * corner(random);
        b.hi[k] = b.lo[k] + 0.5 * size(random);
      }
    return boxes;
  };
  const std::vector<Box> first = make(400), second = make(300);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < first.size(); ++i)
    for (std::uint32_t j = 0; j < second.size(); ++j) {
      bool meet = true;
      for (int k = 0; k < 3; ++k)
        meet = meet && first[i].lo[k] <= second[j].hi[k] && second[j].lo[k] <= first[i].hi[k];
      if (meet) expected.emplace_back(i, j);
    }
  ASSERT_GT(expected.size(), 1000u);
  EXPECT_EQ(overlapping_pairs(first, second), expected);
}

// ---- exactccd simulate -----------------------------------------------------------------------

class SimulateCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device random;
    for (int attempt = 0; dir_.empty() && attempt < 100; ++attempt) {
      const fs::path candidate =
          fs::temp_directory_path() /
          ("exactccd-sim-test-" + std::to_string(getpid()) + "-" + std::to_string(random()));
      if (fs::create_directory(candidate)) dir_ = candidate;
    }
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    std::error_code ignored;
    if (!dir_.empty()) fs::remove_all(dir_, ignored);
  }

  // Runs `exactccd simulate --out DIR` with `args`; returns the exit status.
  int simulate_command(const std::vector<std::string>& args) {
    std::string command = std::string("'") + EXACTCCD_CLI + "' simulate --out '" +
                          dir_.string() + "'";
    for (const std::string& a : args) command += " " + a;
    command += " >'" + (dir_ / "stdout.txt").string() + "' 2>&1";
    const int raw = std::system(command.c_str());
    return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }

  // The files of one type, data_0.csv, data_1.csv, ... (all there are, in order).
  std::vector<fs::path> data_files(const char* type) {
    std::vector<fs::path> files;
    for (int k = 0;; ++k) {
      const fs::path p = dir_ / "simulation" / type / ("data_" + std::to_string(k) + ".csv");
      if (!fs::exists(p)) break;
      files.push_back(p);
    }
    std::size_t all = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "simulation" / type))
      all += entry.path().extension() == ".csv";
    EXPECT_EQ(all, files.size()) << "files not numbered 0, 1, ... in " << type;
    return files;
  }

  fs::path dir_;
};

TEST_F(SimulateCommand, CsvRoundTripGivesIdenticalDoublesAndSplitsFiles) {
  SimulationConfig config;
  config.sheet_resolution = 18;
  config.steps = 60;  // more than 100,000 edge-edge queries: two edge-edge files
  ASSERT_EQ(simulate_command({"--resolution 18", "--steps 60", "--truth none"}), 0);
  const std::vector<SimulationQuery> queries = generate_simulation_queries(config);

  for (const QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    SCOPED_TRACE(exactccd::to_string(type));
    std::vector<const SimulationQuery*> expected;
    for (const SimulationQuery& q : queries)
      if (q.type == type) expected.push_back(&q);
    const std::vector<fs::path> files = data_files(exactccd::to_string(type));
    ASSERT_EQ(files.size(), (expected.size() + 99999) / 100000);
    std::size_t next = 0;
    for (const fs::path& file : files) {
      const exactccd::QueryFile input = exactccd::read_query_file(file.string(), type);
      if (&file != &files.back()) EXPECT_EQ(input.queries.size(), 100000u) << file;
      for (const exactccd::QueryRecord& record : input.queries) {
        ASSERT_LT(next, expected.size());
        const SimulationQuery& want = *expected[next++];
        EXPECT_FALSE(record.truth);  // --truth none
        for (int row = 0; row < 8; ++row) {
          const exactccd::RationalPoint& got = record.query.points[row];
          for (int k = 0; k < 3; ++k) {
            const mpq_class& value = k == 0 ? got.x : k == 1 ? got.y : got.z;
            // Exactly the double: the rational equals it and converts back to its bits (the
            // generator writes no -0.0, which a fraction cannot keep).
            ASSERT_EQ(value, mpq_class(want.points[row][k])) << file << " row " << row;
            ASSERT_EQ(bits(value.get_d()), bits(want.points[row][k])) << file << " row " << row;
          }
        }
      }
    }
    EXPECT_EQ(next, expected.size());
  }
}

TEST_F(SimulateCommand, TruthColumnIsTheExactVerdictOfEachQuery) {
  SimulationConfig config;
  config.sheet_resolution = 4;
  config.steps = 8;  // few queries, the bodies' contacts among them
  ASSERT_EQ(simulate_command({"--resolution 4", "--steps 8"}), 0);
  const std::vector<SimulationQuery> queries = generate_simulation_queries(config);
  const std::vector<std::uint8_t> collides = exact_verdicts(queries);
  ASSERT_NE(std::count(collides.begin(), collides.end(), 1), 0);
  ASSERT_NE(std::count(collides.begin(), collides.end(), 0), 0);
  for (const QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    std::vector<bool> expected;
    for (std::size_t i = 0; i < queries.size(); ++i)
      if (queries[i].type == type) expected.push_back(collides[i]);
    std::vector<bool> got;
    for (const fs::path& file : data_files(exactccd::to_string(type)))
      for (const auto& record : exactccd::read_query_file(file.string(), type).queries)
        got.push_back(record.truth);
    EXPECT_EQ(got, expected) << exactccd::to_string(type);
  }
}

TEST_F(SimulateCommand, KeepsEarlierDataFilesAndRejectsBadConfig) {
  ASSERT_EQ(simulate_command({"--resolution 18", "--steps 60", "--truth none"}), 0);
  ASSERT_TRUE(fs::exists(dir_ / "simulation" / "edge-edge" / "data_1.csv"));
  // An earlier run's files: refused without --force; with it, replaced, and the data_1.csv
  // that this smaller run does not write is kept (never deleted).
  EXPECT_EQ(simulate_command({"--resolution 4", "--steps 8", "--truth none"}), 2);
  ASSERT_EQ(simulate_command({"--resolution 4", "--steps 8", "--truth none", "--force"}), 0);
  EXPECT_TRUE(fs::exists(dir_ / "simulation" / "edge-edge" / "data_1.csv"));
  EXPECT_EQ(data_files("edge-edge").size(), 2u);
  EXPECT_EQ(simulate_command({"--resolution 1"}), 2);
  EXPECT_EQ(simulate_command({"--steps 0"}), 2);
  EXPECT_EQ(simulate_command({"--truth maybe"}), 2);
}

TEST_F(SimulateCommand, BarrierStepWritesTheScenesCandidatesWithExactTruth) {
  ASSERT_EQ(simulate_command({"--barrier-step rollers", "--barrier-scale 0.02"}), 0);
  // The scene's own candidates and contacts, in pair order: the files hold the candidates, and
  // the exact path's truth of each equals the scene's (filtered) verdict.
  exactccd::Scene scene =
      exactccd::corpus::make_scene(exactccd::corpus::barrier_step("rollers", 0.02));
  exactccd::SceneOptions options;
  options.record_candidates = true;
  const exactccd::SceneResult result = scene.find_contacts(options);
  std::set<exactccd::ScenePair> contacts;
  for (const auto& c : result.contacts) contacts.insert(c.pair);
  ASSERT_GT(contacts.size(), 10u);
  std::size_t next[2] = {}, collisions = 0;
  std::vector<exactccd::ScenePair> of_type[2];
  for (const exactccd::ScenePair& p : result.candidates)
    of_type[static_cast<int>(p.type)].push_back(p);
  for (const QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    const int t = static_cast<int>(type);
    const fs::path file = dir_ / "barrier" / "rollers" / exactccd::to_string(type) / "data_0.csv";
    for (const exactccd::QueryRecord& record : exactccd::read_query_file(file.string(), type).queries) {
      ASSERT_LT(next[t], of_type[t].size());
      const exactccd::ScenePair& pair = of_type[t][next[t]++];
      EXPECT_EQ(record.truth, contacts.count(pair) == 1);
      collisions += record.truth;
      // The rows are the pair's query, exactly.
      const std::array<Eigen::Vector3d, 8> rows =
          type == QueryType::vertex_face
              ? [&] { const auto q = scene.vertex_face_query(pair);
                      return std::array<Eigen::Vector3d, 8>{q.p_t0, q.a_t0, q.b_t0, q.c_t0,
                                                             q.p_t1, q.a_t1, q.b_t1, q.c_t1}; }()
              : [&] { const auto q = scene.edge_edge_query(pair);
                      return std::array<Eigen::Vector3d, 8>{q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0,
                                                             q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1}; }();
      for (int row = 0; row < 8; ++row) {
        const exactccd::RationalPoint& got = record.query.points[row];
        ASSERT_EQ(got.x, mpq_class(rows[row].x()));
        ASSERT_EQ(got.y, mpq_class(rows[row].y()));
        ASSERT_EQ(got.z, mpq_class(rows[row].z()));
      }
    }
    EXPECT_EQ(next[t], of_type[t].size());
  }
  EXPECT_EQ(collisions, contacts.size());
  EXPECT_EQ(simulate_command({"--barrier-step rollers", "--barrier-scale 0.02"}), 2);  // exists
  EXPECT_EQ(simulate_command({"--barrier-step nope"}), 2);
  EXPECT_EQ(simulate_command({"--barrier-step rollers", "--barrier-scale 0"}), 2);
  EXPECT_EQ(simulate_command({"--barrier-step rollers", "--barrier-scale 2"}), 2);
  EXPECT_EQ(simulate_command({"--barrier-scale 0.1"}), 2);
  EXPECT_EQ(simulate_command({"--barrier-step rollers", "--resolution 4"}), 2);
}

}  // namespace
