// The shipped degenerate suite (tests/data/degenerate-suite, written by `exactccd generate`
// with the seed and per-family count its manifest records): every query through the default
// path and through the exact path (double API in Mode::exact, and exact_ccd on the file's
// rationals) must reproduce the file's truth column and the TOI sidecar's tightest pair bit
// for bit; the manifest's counts must be the files'; and regenerating the suite in memory
// from the manifest's seed, parameters and family list must give the shipped files byte for
// byte, so the suite cannot drift from the generator. (The generator may offer families the
// suite was not written with: the manifest lists the suite's own.)
//
// The suite's truth and TOIs were computed by the exact path when it was generated; what makes
// them trustworthy is tests/families_test.cpp, which checks every base-family member against
// its construction (and CGAL). Here they pin down both paths on the shipped bytes.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus/corpus_writer.hpp"
#include "corpus/families.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"
#include "test_scale.hpp"

namespace {

namespace fs = std::filesystem;
namespace fam = exactccd::families;
using exactccd::CcdOptions;
using exactccd::CcdResult;
using exactccd::QueryType;

const fs::path kSuite = fs::path(EXACTCCD_TEST_DATA) / "degenerate-suite";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in) << p;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const nlohmann::json& manifest() {
  static const nlohmann::json m = nlohmann::json::parse(read_text(kSuite / "manifest.json"));
  return m;
}

/// The suite's families, as its manifest lists them.
std::vector<std::string> suite_family_names() {
  std::vector<std::string> names;
  for (const auto& f : manifest().at("families")) names.push_back(f.at("name"));
  return names;
}

/// One sidecar line: index,collides,toi_lo,toi_hi.
struct SidecarLine {
  bool collides = false;
  double lo = 0, hi = 0;
};

double parse_double(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  EXPECT_TRUE(errno == 0 && end == text.c_str() + text.size() && !text.empty()) << text;
  return v;
}

std::vector<SidecarLine> read_sidecar(const fs::path& p) {
  std::vector<SidecarLine> out;
  std::istringstream in(read_text(p));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    if (!line.empty() && line.back() == ',') f.emplace_back();
    EXPECT_EQ(f.size(), 4u) << p << ": " << line;
    if (f.size() != 4) continue;
    EXPECT_EQ(f[0], std::to_string(out.size())) << p;
    EXPECT_TRUE(f[1] == "0" || f[1] == "1") << p << ": " << line;
    SidecarLine s;
    s.collides = f[1] == "1";
    if (s.collides) {
      s.lo = parse_double(f[2]);
      s.hi = parse_double(f[3]);
    } else {
      EXPECT_TRUE(f[2].empty() && f[3].empty()) << p << ": " << line;
    }
    out.push_back(s);
  }
  return out;
}

QueryType type_named(const std::string& name) {
  EXPECT_TRUE(name == "vertex-face" || name == "edge-edge") << name;
  return name == "vertex-face" ? QueryType::vertex_face : QueryType::edge_edge;
}

Eigen::Vector3d as_doubles(const exactccd::RationalPoint& p) {
  const Eigen::Vector3d v(p.x.get_d(), p.y.get_d(), p.z.get_d());
  EXPECT_TRUE(mpq_class(v.x()) == p.x && mpq_class(v.y()) == p.y && mpq_class(v.z()) == p.z)
      << "a coordinate is not a double";
  return v;
}

CcdResult double_api(const exactccd::RationalQuery& q, const CcdOptions& options) {
  std::array<Eigen::Vector3d, 8> v;
  for (int i = 0; i < 8; ++i) v[i] = as_doubles(q.points[i]);
  if (q.type == QueryType::vertex_face)
    return exactccd::vertex_face_ccd({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, options);
  return exactccd::edge_edge_ccd({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, options);
}

void expect_reproduces(const CcdResult& r, bool truth, const SidecarLine& s,
                       const std::string& what) {
  EXPECT_EQ(r.collides, truth) << what;
  if (truth && r.collides) {
    EXPECT_EQ(r.toi_lo, s.lo) << what;
    EXPECT_EQ(r.toi_hi, s.hi) << what;
  }
}

TEST(DegenerateSuite, ManifestListsEveryFamilyWithTheFilesCounts) {
  const nlohmann::json& m = manifest();
  EXPECT_EQ(m.at("generator"), "exactccd generate");
  const auto& families = m.at("families");
  std::set<std::string> names;
  std::size_t total = 0;
  for (const auto& f : families) {
    const std::string name = f.at("name");
    SCOPED_TRACE(name);
    names.insert(name);
    const std::string type = f.at("type");
    const fs::path folder = kSuite / name / type;
    const exactccd::QueryFile file =
        exactccd::read_query_file((folder / "data_0.csv").string(), type_named(type));
    std::size_t collisions = 0;
    for (const auto& q : file.queries) collisions += q.truth;
    EXPECT_EQ(f.at("queries").get<std::size_t>(), file.queries.size());
    EXPECT_EQ(f.at("collisions").get<std::size_t>(), collisions);
    const std::vector<SidecarLine> sidecar = read_sidecar(folder / "toi_0.csv");
    ASSERT_EQ(sidecar.size(), file.queries.size());
    for (std::size_t i = 0; i < sidecar.size(); ++i)
      EXPECT_EQ(sidecar[i].collides, file.queries[i].truth) << "query " << i;
    EXPECT_TRUE(fam::is_family_name(name));
    EXPECT_EQ(f.at("base"), fam::base_of(name));
    EXPECT_EQ(f.at("type"),
              to_string(type == "vertex-face" ? QueryType::vertex_face : QueryType::edge_edge));
    // Each base family (a construction; random families have none) has both verdicts.
    if (f.at("base") == name && !fam::is_random_family(name)) {
      EXPECT_GT(collisions, 0u);
      EXPECT_LT(collisions, file.queries.size());
    }
    total += file.queries.size();
  }
  EXPECT_EQ(names.size(), families.size());  // no family twice
  // Every base family of the suite comes with all the variants the suite has of any of them.
  std::set<std::string> bases, suffixes;
  for (const std::string& name : names) {
    const std::size_t at = name.find('@');
    if (at == std::string::npos)
      bases.insert(name);
    else
      suffixes.insert(name.substr(at));
  }
  for (const std::string& base : bases)
    for (const std::string& suffix : suffixes)
      if (!fam::is_random_family(base)) EXPECT_EQ(names.count(base + suffix), 1u) << base + suffix;
  EXPECT_GE(bases.size(), 25u);
  EXPECT_GE(total, 2000u);
  // The folder holds nothing else that `check` would read: one data_0.csv per family (the
  // toi_0.csv sidecars are not query files).
  const std::vector<std::string> files = exactccd::find_query_files(kSuite.string());
  EXPECT_EQ(files.size(), families.size());
  for (const std::string& f : files) EXPECT_EQ(fs::path(f).filename(), "data_0.csv") << f;
}

TEST(DegenerateSuite, DefaultAndExactPathsReproduceTruthAndToi) {
  CcdOptions exact_mode;
  exact_mode.mode = exactccd::Mode::exact;
  std::size_t queries = 0, collisions = 0;
  std::size_t index = 0;  // over the whole suite: EXACTCCD_TEST_SCALE < 1 checks a subset
  for (const auto& f : manifest().at("families")) {
    const std::string name = f.at("name"), type = f.at("type");
    const fs::path folder = kSuite / name / type;
    const exactccd::QueryFile file =
        exactccd::read_query_file((folder / "data_0.csv").string(), type_named(type));
    const std::vector<SidecarLine> sidecar = read_sidecar(folder / "toi_0.csv");
    ASSERT_EQ(sidecar.size(), file.queries.size()) << name;
    for (std::size_t i = 0; i < file.queries.size(); ++i) {
      if (index++ % exactccd::test::subset_stride() != 0) continue;
      const exactccd::QueryRecord& q = file.queries[i];
      const std::string what = name + " query " + std::to_string(i);
      expect_reproduces(double_api(q.query, CcdOptions{}), q.truth, sidecar[i], what + " default");
      expect_reproduces(double_api(q.query, exact_mode), q.truth, sidecar[i], what + " exact");
      expect_reproduces(exactccd::exact_ccd(q.query), q.truth, sidecar[i], what + " exact_ccd");
      ++queries;
      collisions += q.truth;
    }
  }
  std::cout << "[ suite    ] " << queries << " queries, " << collisions << " collisions\n";
}

// The shipped files are what the generator writes today for the manifest's seed, per-family
// count and families.
TEST(DegenerateSuite, RegeneratingGivesTheShippedFilesByteForByte) {
  const std::uint64_t seed = manifest().at("seed");
  const int per_family = manifest().at("per_family");
  const fam::Corpus corpus = fam::generate_corpus(seed, per_family, suite_family_names());
  EXPECT_EQ(fam::manifest_text(corpus), read_text(kSuite / "manifest.json"));
  for (const fam::GeneratedFamily& g : corpus.families) {
    const fs::path folder = kSuite / fam::family_folder(g.family);
    EXPECT_EQ(fam::data_csv_text(g), read_text(folder / "data_0.csv")) << folder;
    EXPECT_EQ(fam::toi_csv_text(g), read_text(folder / "toi_0.csv")) << folder;
    EXPECT_TRUE(fam::claim_mismatches(g).empty()) << g.family.name;
  }
}

}  // namespace
