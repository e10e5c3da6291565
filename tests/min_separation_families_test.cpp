// Tests of the minimum-separation families (corpus/min_separation_families.hpp) and of
// `exactccd generate --min-separation`.
//
// Every member carries the answer its construction proves for its delta (the comments above
// the builders): within delta or not, and the exact earliest time t*. The exact path
// (exact_ccd with the rational delta), the double API in Mode::exact and the default path must
// reproduce it, with the tightest TOI pair around t*, for deltas that exercise every kind of
// offset (powers of two, 5 * 2^-k and 13 * 2^-k for the Pythagorean directions, 53-bit deltas
// such as 0.3 and 1e-4, 0, and far exponents). The constructions are also confirmed with
// CGAL's exact squared distances at rational times (distance exactly delta at t*, more at
// sampled earlier times, more for a near miss at its partner's t*), which share no code with
// the library; scaling a query and its delta by the same power of two keeps the claim.
#include "corpus/min_separation_families.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus/corpus_writer.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"
#include "tests/test_support.hpp"
#include "tests/family_expectations.hpp"
#include "tests/generate_command_fixture.hpp"

namespace {

namespace fs = std::filesystem;
namespace fam = exactccd::families;
using exactccd::CcdOptions;
using exactccd::CcdResult;
using exactccd::Mode;
using exactccd::QueryType;
using exactccd::RationalQuery;
using exactccd::test::expect_answer;
using exactccd::test::cgal_squared_distance_at;

// Four groups per family: every sub-kind of every builder (at most three) appears, and a
// contact at t = 0 or 1 now and then.
constexpr int kPerFamily = 28;

/// 2^-10; 5 * 2^-12 and 13 * 2^-20 (Pythagorean offsets (3, 4, 0) / 5, (5, 12, 0) / 13 ...);
/// 3 * 2^-8 ((1, 2, 2) / 3); 53-bit deltas; 0 (contact); the ends of the domain's exponents.
std::vector<double> deltas() {
  return {std::ldexp(1.0, -10), std::ldexp(5.0, -12), std::ldexp(13.0, -20), std::ldexp(3.0, -8),
          0.3, 1e-4, 0.0, std::ldexp(1.0, -800), 3e250};
}

RationalQuery rational(QueryType type, const fam::QueryPoints& p) {
  RationalQuery q;
  q.type = type;
  for (int i = 0; i < 8; ++i)
    q.points[i] = {mpq_class(p[i].x()), mpq_class(p[i].y()), mpq_class(p[i].z())};
  return q;
}

struct DeltaFamily {
  double delta;
  fam::Family family;
};

/// Every family for every delta, for the default seed 1 and the test seed.
const std::vector<DeltaFamily>& all_families() {
  static const std::vector<DeltaFamily> all = [] {
    std::vector<DeltaFamily> out;
    const std::uint64_t seeds[] = {1, exactccd::test::test_seed("min-separation families")};
    for (const std::uint64_t seed : seeds)
      for (const double delta : deltas())
        for (const std::string& name : fam::min_separation_family_names())
          out.push_back({delta, fam::generate_min_separation_family(name, delta, seed,
                                                                     kPerFamily)});
    return out;
  }();
  return all;
}

std::string where(const DeltaFamily& f, std::size_t i) {
  char delta[40];
  std::snprintf(delta, sizeof delta, "%.17g", f.delta);
  return f.family.name + " delta " + delta + " member " + std::to_string(i) + " (" +
         f.family.members[i].label + ", " + f.family.members[i].kind + ")";
}


CcdOptions options(double delta, Mode mode) {
  CcdOptions o;
  o.min_separation = delta;
  o.mode = mode;
  return o;
}

// ------------------------------------------------------------------------------------ tests

TEST(MinSeparationFamilies, NamesAndArguments) {
  const auto& names = fam::min_separation_family_names();
  EXPECT_EQ(names.size(), 10u);
  for (const std::string& name : names) {
    EXPECT_TRUE(fam::is_min_separation_family(name));
    EXPECT_FALSE(fam::is_family_name(name)) << name << " is also a degenerate family";
  }
  EXPECT_FALSE(fam::is_min_separation_family("vf_t0"));
  EXPECT_THROW(fam::generate_min_separation_family("vf_t0", 0.25, 1, 14), std::invalid_argument);
  EXPECT_THROW(fam::generate_min_separation_family("ms_vf_vertex", 0.25, 1, 1),
               std::invalid_argument);
  EXPECT_THROW(fam::generate_min_separation_families(0.25, 1, 14, {"ms_vf_vertex", "nope"}),
               std::invalid_argument);
  for (const double bad : {-0.25, std::nan(""), std::numeric_limits<double>::infinity(),
                           std::ldexp(1.0, -901), std::ldexp(1.0, 901)}) {
    EXPECT_FALSE(fam::min_separation_delta_problem(bad).empty()) << bad;
    EXPECT_THROW(fam::generate_min_separation_family("ms_vf_vertex", bad, 1, 14),
                 std::invalid_argument)
        << bad;
  }
  for (const double good : {0.0, std::ldexp(1.0, -900), std::ldexp(1.0, 900), 0.3})
    EXPECT_EQ(fam::min_separation_delta_problem(good), "") << good;
}

TEST(MinSeparationFamilies, EachFamilyHasContactsAndNearMissesOfEveryKind) {
  for (const DeltaFamily& f : all_families()) {
    SCOPED_TRACE(f.family.name);
    ASSERT_EQ(f.family.members.size(), static_cast<std::size_t>(kPerFamily));
    EXPECT_TRUE(f.family.members[0].collides);
    EXPECT_FALSE(f.family.members[1].collides);
    std::set<std::string> kinds;
    for (const fam::Member& m : f.family.members) {
      EXPECT_TRUE(m.claim_known);
      kinds.insert(m.kind);
    }
    // Every builder has two or three sub-kinds (vertex and endpoint spheres: one).
    const bool single = f.family.name == "ms_vf_vertex" || f.family.name == "ms_ee_endpoints";
    EXPECT_GE(kinds.size(), single ? 1u : 2u);
    EXPECT_EQ(f.family.parameters.at("min_separation").get<double>(), f.delta);
    EXPECT_EQ(mpq_class(f.family.parameters.at("min_separation_exact").get<std::string>()),
              mpq_class(f.delta));
  }
}

TEST(MinSeparationFamilies, EveryPathReproducesTheConstruction) {
  std::size_t contacts = 0, misses = 0;
  for (const DeltaFamily& f : all_families())
    for (std::size_t i = 0; i < f.family.members.size(); ++i) {
      const fam::Member& m = f.family.members[i];
      const RationalQuery q = rational(f.family.type, m.points);
      expect_answer(m, exactccd::exact_ccd(q, mpq_class(f.delta)), where(f, i) + ", exact_ccd");
      expect_answer(m, exactccd::test::double_api_ccd(q, options(f.delta, Mode::exact)),
                    where(f, i) + ", exact");
      expect_answer(m, exactccd::test::double_api_ccd(q, options(f.delta, Mode::filtered)),
                    where(f, i) + ", default");
      (m.collides ? contacts : misses) += 1;
    }
  EXPECT_GT(contacts, 0u);
  EXPECT_GT(misses, contacts);
}

// The constructions against CGAL, independently of the library: a contact is at squared
// distance exactly delta^2 at t* and farther at the sampled earlier times t* j / 16; a near
// miss is farther than delta at its partner's t* and at 0 and 1.
TEST(MinSeparationFamilies, ConstructionsConfirmedWithCgalAtRationalTimes) {
  for (const DeltaFamily& f : all_families()) {
    const mpq_class delta2 = mpq_class(f.delta) * mpq_class(f.delta);
    for (std::size_t i = 0; i < f.family.members.size(); ++i) {
      SCOPED_TRACE(where(f, i));
      const fam::Member& m = f.family.members[i];
      const RationalQuery q = rational(f.family.type, m.points);
      if (m.collides) {
        EXPECT_EQ(cgal_squared_distance_at(q, m.toi), delta2);
        for (int j = 0; j < 16 && sgn(m.toi) > 0; ++j)
          EXPECT_GT(cgal_squared_distance_at(q, mpq_class(m.toi * j / 16)), delta2)
              << "within delta at t* " << j << "/16 < t* = " << m.toi;
      } else {
        ASSERT_GE(m.partner, 0);
        const mpq_class& tc = f.family.members[static_cast<std::size_t>(m.partner)].toi;
        for (const mpq_class& t : {tc, mpq_class(0), mpq_class(1)})
          EXPECT_GT(cgal_squared_distance_at(q, t), delta2) << "within delta at " << t;
      }
    }
  }
}

// A near miss differs from its contact in exactly the listed coordinates, each moved by
// `distance`: the largest one-ulp step of the moved coordinates ("1ulp"), or 2^-k times
// delta's leading power of two ("2^-k"; that step when larger, doubled while not exact).
TEST(MinSeparationFamilies, NearMissesLieAtTheStatedDistanceFromTheirContact) {
  std::size_t near_misses = 0, requested = 0;
  for (const DeltaFamily& f : all_families()) {
    const double unit = f.delta > 0 ? std::ldexp(1.0, std::ilogb(f.delta)) : 1.0;
    for (std::size_t i = 0; i < f.family.members.size(); ++i) {
      SCOPED_TRACE(where(f, i));
      const fam::Member& m = f.family.members[i];
      if (m.collides) continue;
      ++near_misses;
      ASSERT_GE(m.partner, 0);
      const fam::Member& partner = f.family.members[static_cast<std::size_t>(m.partner)];
      ASSERT_EQ(partner.label, "contact");
      ASSERT_FALSE(m.moved.empty());
      ASSERT_EQ(m.moved.size(), m.direction.size());
      std::set<std::pair<int, int>> moved;
      double step = 0;
      for (std::size_t k = 0; k < m.moved.size(); ++k) {
        const int row = m.moved[k].row, axis = m.moved[k].axis;
        moved.insert({row, axis});
        const double x = partner.points[row][axis];
        EXPECT_EQ(mpq_class(m.points[row][axis]) - mpq_class(x),
                  m.direction[k] * mpq_class(m.distance));
        const double toward = m.direction[k] * std::numeric_limits<double>::infinity();
        step = std::max(step, std::abs(std::nextafter(x, toward) - x));
      }
      for (int row = 0; row < 8; ++row)
        for (int axis = 0; axis < 3; ++axis)
          if (moved.count({row, axis}) == 0)
            EXPECT_EQ(m.points[row][axis], partner.points[row][axis]);
      if (m.label == "1ulp") {
        EXPECT_EQ(m.distance, step);
      } else {
        ASSERT_EQ(m.label, "2^-" + std::to_string(m.distance_log2));
        const double asked = std::max(std::ldexp(unit, -m.distance_log2), step);
        EXPECT_GE(m.distance, asked);
        requested += m.distance == asked;
      }
    }
  }
  EXPECT_GT(near_misses, 0u);
  EXPECT_GT(requested, near_misses / 4);  // most 2^-k moves land where asked
}

// Scaling space by 2^j scales every distance by 2^j: the query scaled by 2^j (where exact)
// with delta * 2^j keeps the member's claim, on the default path.
TEST(MinSeparationFamilies, PowerOfTwoScalingOfQueryAndDeltaKeepsTheClaim) {
  std::mt19937_64 rng(exactccd::test::test_seed("min-separation scaling"));
  std::size_t scaled = 0;
  for (const DeltaFamily& f : all_families())
    for (std::size_t i = 0; i < f.family.members.size(); ++i) {
      const int j = static_cast<int>(rng() % 121) - 60;
      const double delta = std::ldexp(f.delta, j);
      if (mpq_class(delta) != mpq_class(f.delta) * exactccd::test::pow2(j)) continue;
      RationalQuery q = rational(f.family.type, f.family.members[i].points);
      bool exact = true;
      for (exactccd::RationalPoint& p : q.points)
        for (mpq_class* c : {&p.x, &p.y, &p.z}) {
          const mpq_class x = *c * exactccd::test::pow2(j);
          exact = exact && mpq_class(x.get_d()) == x;
          *c = x;
        }
      if (!exact) continue;
      ++scaled;
      expect_answer(f.family.members[i],
                    exactccd::test::double_api_ccd(q, options(delta, Mode::filtered)),
                    where(f, i) + " scaled by 2^" + std::to_string(j));
    }
  EXPECT_GT(scaled, all_families().size() * kPerFamily / 2);
}

TEST(MinSeparationFamilies, GenerationIsDeterministicBySeed) {
  const double delta = std::ldexp(5.0, -12);
  const auto a = fam::generate_min_separation_families(delta, 7, 14);
  const auto b = fam::generate_min_separation_families(delta, 7, 14);
  const auto c = fam::generate_min_separation_families(delta, 8, 14);
  ASSERT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t f = 0; f < a.size(); ++f) {
    ASSERT_EQ(a[f].members.size(), b[f].members.size());
    EXPECT_EQ(a[f].parameters, b[f].parameters);
    for (std::size_t m = 0; m < a[f].members.size(); ++m) {
      EXPECT_EQ(a[f].members[m].points, b[f].members[m].points);
      EXPECT_EQ(a[f].members[m].label, b[f].members[m].label);
      EXPECT_EQ(a[f].members[m].toi, b[f].members[m].toi);
      differ += a[f].members[m].points != c[f].members[m].points;
    }
  }
  EXPECT_GT(differ, 0u);
  // A family does not depend on which others are generated.
  const auto alone = fam::generate_min_separation_families(delta, 7, 14, {"ms_ee_parallel"});
  ASSERT_EQ(alone.size(), 1u);
  for (const fam::Family& f : a)
    if (f.name == "ms_ee_parallel")
      for (std::size_t m = 0; m < f.members.size(); ++m)
        EXPECT_EQ(f.members[m].points, alone[0].members[m].points);
}

TEST(MinSeparationFamilies, CorpusDecidesWithDeltaAndRecordsItInTheManifest) {
  const double delta = std::ldexp(5.0, -12);
  const fam::Corpus corpus =
      fam::generate_min_separation_corpus(delta, 3, 14, {"ms_vf_face_tilt", "ms_ee_capsule"});
  ASSERT_EQ(corpus.families.size(), 2u);
  for (const fam::GeneratedFamily& g : corpus.families) {
    EXPECT_TRUE(fam::claim_mismatches(g).empty());
    EXPECT_GT(g.collisions(), 0u);
    EXPECT_LT(g.collisions(), g.family.members.size());
  }
  const nlohmann::json manifest = nlohmann::json::parse(fam::manifest_text(corpus));
  EXPECT_EQ(manifest.at("min_separation").get<double>(), delta);
  EXPECT_EQ(manifest.at("min_separation_exact"), "5/4096");
  EXPECT_EQ(manifest.at("families").size(), 2u);
  EXPECT_EQ(manifest.at("families")[0].at("parameters").at("min_separation").get<double>(), delta);
  // The degenerate families' manifest has no delta.
  const nlohmann::json plain =
      nlohmann::json::parse(fam::manifest_text(fam::generate_corpus(3, 7, {"vf_t0"})));
  EXPECT_FALSE(plain.contains("min_separation"));
}

// ------------------------------------------------------------------ the `generate` command

class GenerateMinSeparationCommand : public exactccd::test::GenerateCommand {};

TEST_F(GenerateMinSeparationCommand, WritesTheLayoutWithDeltaInTheManifest) {
  const fs::path suite = dir_ / "suite";
  const Run r = run("generate --out '" + suite.string() +
                    "' --seed 5 --per-family 7 --min-separation 0x1.4p-10 "
                    "--families ms_vf_face_tilt,ms_ee_interior");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("ms_ee_interior"), std::string::npos);
  const nlohmann::json manifest = nlohmann::json::parse(read(suite / "manifest.json"));
  EXPECT_EQ(manifest.at("min_separation").get<double>(), std::ldexp(5.0, -12));
  EXPECT_EQ(manifest.at("seed"), 5);
  ASSERT_EQ(manifest.at("families").size(), 2u);
  for (const auto& f : manifest.at("families")) {
    const std::string type = f.at("type");
    const fs::path folder = suite / f.at("name").get<std::string>() / type;
    const exactccd::QueryFile file = exactccd::read_query_file(
        (folder / "data_0.csv").string(),
        type == "vertex-face" ? QueryType::vertex_face : QueryType::edge_edge);
    ASSERT_EQ(file.queries.size(), 7u);
    std::size_t collisions = 0;
    for (const auto& q : file.queries) collisions += q.truth;
    EXPECT_EQ(f.at("collisions"), collisions);
    EXPECT_GT(collisions, 0u);
    EXPECT_TRUE(fs::exists(folder / "toi_0.csv"));
  }
}

TEST_F(GenerateMinSeparationCommand, BadDeltasAndFamiliesExitWithStatusTwo) {
  const std::string out = "generate --out '" + (dir_ / "suite").string() + "' ";
  for (const std::string& args :
       {out + "--min-separation -1", out + "--min-separation nan", out + "--min-separation inf",
        out + "--min-separation abc", out + "--min-separation 1e-300",
        out + "--min-separation 0.25 --families vf_t0"}) {
    SCOPED_TRACE(args);
    const Run r = run(args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("exactccd: ", 0), 0u) << r.err;
    const bool names_it = r.err.find("--min-separation") != std::string::npos ||
                          r.err.find("vf_t0") != std::string::npos;
    EXPECT_TRUE(names_it) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "suite" / "manifest.json"));
}

}  // namespace
