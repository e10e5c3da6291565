// Tests of the degenerate-query families (corpus/families.hpp) and of `exactccd generate`.
//
// Every base-family member carries the answer its construction proves (families.cpp, the
// comment above each builder): a verdict and, when it collides, the exact first contact time
// t*. Here the exact path (exact_ccd), the double API in Mode::exact and the default path must
// reproduce that answer, with the tightest TOI pair around the constructed t*. The
// constructions are also confirmed with CGAL's exact kernel at rational times (contact at t*,
// none at sampled earlier times, none for a near miss at its partner's t*), which shares no
// code with the library. Near misses are checked to differ from their colliding partner in
// exactly the listed coordinates, by exactly the stated distance (one ulp, or 2^-k).
#include "corpus/families.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus/corpus_writer.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rational_query.hpp"
#include "tests/family_expectations.hpp"
#include "tests/generate_command_fixture.hpp"
#include "tests/test_support.hpp"

namespace {

namespace fs = std::filesystem;
namespace fam = exactccd::families;
using exactccd::CcdOptions;
using exactccd::CcdResult;
using exactccd::Mode;
using exactccd::QueryType;
using exactccd::test::expect_answer;
using exactccd::test::expect_tightest_enclosure;
using exactccd::test::GenerateCommand;
using exactccd::RationalQuery;

// Four groups per family: every sub-kind of every builder (at most four) appears.
constexpr int kPerFamily = 28;

RationalQuery rational(QueryType type, const fam::QueryPoints& p) {
  RationalQuery q;
  q.type = type;
  for (int i = 0; i < 8; ++i)
    q.points[i] = {mpq_class(p[i].x()), mpq_class(p[i].y()), mpq_class(p[i].z())};
  return q;
}

/// The base families for the seeds under test (the default seed of the suite, 1, and the test
/// seed, EXACTCCD_TEST_SEED when set), generated once.
const std::vector<fam::Family>& base_families() {
  static const std::vector<fam::Family> all = [] {
    std::vector<fam::Family> out;
    const std::uint64_t seeds[] = {1, exactccd::test::test_seed("families")};
    for (const std::uint64_t seed : seeds)
      for (const std::string& name : fam::base_family_names())
        out.push_back(fam::generate_base_family(name, seed, kPerFamily));
    return out;
  }();
  return all;
}

std::string where(const fam::Family& f, std::size_t i) {
  return f.name + " member " + std::to_string(i) + " (" + f.members[i].label + ", " +
         f.members[i].kind + ")";
}


TEST(Families, NamesVariantsAndArguments) {
  const auto& bases = fam::base_family_names();
  EXPECT_EQ(bases.size(), 29u);
  const auto& randoms = fam::random_family_names();
  EXPECT_EQ(randoms.size(), 8u);
  EXPECT_EQ(fam::variants().size(), 12u);
  const std::vector<std::string> all = fam::all_family_names();
  EXPECT_EQ(all.size(), bases.size() * 13 + randoms.size());
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), all.size());
  for (const std::string& name : all) EXPECT_TRUE(fam::is_family_name(name)) << name;
  EXPECT_EQ(fam::base_of("vf_interior@s1e-12"), "vf_interior");
  EXPECT_EQ(fam::base_of("ee_crossing@t1e8"), "ee_crossing");
  EXPECT_EQ(fam::base_of("ee_crossing"), "ee_crossing");
  EXPECT_EQ(fam::base_of("vf_resting@p2^-1000"), "vf_resting");
  EXPECT_EQ(fam::base_of("ee_stacked@p2^1000"), "ee_stacked");
  EXPECT_EQ(fam::base_of("vf_wide_exponent_1000"), "vf_wide_exponent_1000");
  EXPECT_TRUE(fam::is_random_family("ee_huge_triangle_subnormal_motion"));
  EXPECT_FALSE(fam::is_random_family("ee_resting"));
  EXPECT_EQ(fam::base_of("vf_wide_exponent_1000@p2^100"), "");  // random families: no variants
  EXPECT_EQ(fam::base_of("ee_crossing@s2"), "");
  EXPECT_EQ(fam::base_of("ee_crossing@p2^7"), "");
  EXPECT_EQ(fam::base_of("nope"), "");
  EXPECT_THROW(fam::generate_base_family("nope", 1, 14), std::invalid_argument);
  EXPECT_THROW(fam::generate_base_family("vf_t0", 1, 1), std::invalid_argument);
  EXPECT_THROW(fam::generate_base_family("vf_wide_exponent_100", 1, 14), std::invalid_argument);
  EXPECT_THROW(fam::generate_random_family("vf_t0", 1, 14), std::invalid_argument);
  EXPECT_THROW(fam::generate_random_family("vf_wide_exponent_100", 1, 1), std::invalid_argument);
  EXPECT_THROW(fam::generate_families(1, 14, {"vf_t0@s3"}), std::invalid_argument);
  // Variants: the rounded ones first (their index is part of the suite's naming), then the
  // powers of two, each 2^k exactly.
  EXPECT_STREQ(fam::variants()[4].suffix, "@t1e4");
  for (const fam::Variant& v : fam::variants())
    if (v.power_of_two != 0) EXPECT_EQ(v.scale, std::ldexp(1.0, v.power_of_two)) << v.suffix;
}

TEST(Families, EachFamilyHasCollidingAndNonCollidingMembers) {
  for (const fam::Family& f : base_families()) {
    SCOPED_TRACE(f.name);
    ASSERT_EQ(f.members.size(), static_cast<std::size_t>(kPerFamily));
    EXPECT_FALSE(f.is_variant());
    std::size_t colliding = 0, contacts = 0, one_ulp = 0;
    std::set<std::string> kinds;
    for (const fam::Member& m : f.members) {
      EXPECT_TRUE(m.claim_known);
      colliding += m.collides;
      contacts += m.label == "contact";
      one_ulp += m.label == "1ulp";
      kinds.insert(m.kind);
      EXPECT_EQ(m.collides, m.label == "contact");
    }
    EXPECT_GT(colliding, 0u);
    EXPECT_LT(colliding, f.members.size());
    EXPECT_TRUE(f.members[0].collides);
    EXPECT_FALSE(f.members[1].collides);
    // Every contact member but possibly the last (cut by per_family) has its one-ulp near miss.
    EXPECT_GE(one_ulp + 1, contacts);
    EXPECT_EQ(f.parameters.at("kinds").size(), kinds.size());
  }
}

// The exact path, the double API in Mode::exact and the default path against the
// construction, for every member.
TEST(Families, EveryPathReproducesTheConstruction) {
  CcdOptions exact_mode;
  exact_mode.mode = Mode::exact;
  for (const fam::Family& f : base_families())
    for (std::size_t i = 0; i < f.members.size(); ++i) {
      const fam::Member& m = f.members[i];
      const RationalQuery q = rational(f.type, m.points);
      expect_answer(m, exactccd::exact_ccd(q), where(f, i) + ", exact_ccd");
      expect_answer(m, exactccd::test::double_api_ccd(q, exact_mode), where(f, i) + ", exact");
      expect_answer(m, exactccd::test::double_api_ccd(q), where(f, i) + ", default");
    }
}

// The constructions checked with CGAL's exact kernel at rational times, independently of the
// library: a colliding member touches at t* and at none of the sampled earlier times
// t* j / 16; a near miss does not touch at its partner's t* (nor at the ends 0 and 1).
TEST(Families, ConstructionsConfirmedWithCgalAtRationalTimes) {
  for (const fam::Family& f : base_families())
    for (std::size_t i = 0; i < f.members.size(); ++i) {
      SCOPED_TRACE(where(f, i));
      const fam::Member& m = f.members[i];
      const RationalQuery q = rational(f.type, m.points);
      if (m.collides) {
        EXPECT_TRUE(exactccd::test::cgal_contact_at(q, m.toi));
        for (int j = 0; j < 16 && sgn(m.toi) > 0; ++j)
          EXPECT_FALSE(exactccd::test::cgal_contact_at(q, mpq_class(m.toi * j / 16)))
              << "contact at t* " << j << "/16 < t* = " << m.toi;
      } else {
        ASSERT_GE(m.partner, 0);
        const mpq_class& tc = f.members[static_cast<std::size_t>(m.partner)].toi;
        EXPECT_FALSE(exactccd::test::cgal_contact_at(q, tc));
        EXPECT_FALSE(exactccd::test::cgal_contact_at(q, 0));
        EXPECT_FALSE(exactccd::test::cgal_contact_at(q, 1));
      }
    }
}

// A near miss differs from its colliding partner in exactly the listed coordinates, each
// moved by exactly `distance` in its direction; the distance is the stated one: the largest
// one-ulp step of the moved coordinates ("1ulp"), or 2^-k ("2^-k", or that step when larger).
TEST(Families, NearMissesLieAtTheStatedDistanceFromACollidingMember) {
  std::size_t near_misses = 0, subnormal_steps = 0;
  for (const fam::Family& f : base_families())
    for (std::size_t i = 0; i < f.members.size(); ++i) {
      SCOPED_TRACE(where(f, i));
      const fam::Member& m = f.members[i];
      if (m.collides) continue;
      ++near_misses;
      ASSERT_GE(m.partner, 0);
      ASSERT_LT(static_cast<std::size_t>(m.partner), i);
      const fam::Member& partner = f.members[static_cast<std::size_t>(m.partner)];
      ASSERT_TRUE(partner.collides);
      EXPECT_EQ(partner.label, "contact");
      ASSERT_FALSE(m.moved.empty());
      ASSERT_EQ(m.moved.size(), m.direction.size());
      ASSERT_GT(m.distance, 0.0);
      std::set<std::pair<int, int>> moved;
      double step = 0;
      for (std::size_t k = 0; k < m.moved.size(); ++k) {
        const int row = m.moved[k].row, axis = m.moved[k].axis;
        ASSERT_TRUE(row >= 0 && row < 8 && axis >= 0 && axis < 3);
        ASSERT_TRUE(m.direction[k] == 1 || m.direction[k] == -1);
        moved.insert({row, axis});
        const double x = partner.points[row][axis];
        EXPECT_EQ(mpq_class(m.points[row][axis]) - mpq_class(x),
                  m.direction[k] * mpq_class(m.distance))
            << "row " << row << " axis " << axis;
        const double toward = m.direction[k] * std::numeric_limits<double>::infinity();
        step = std::max(step, std::abs(std::nextafter(x, toward) - x));
      }
      for (int row = 0; row < 8; ++row)
        for (int axis = 0; axis < 3; ++axis)
          if (moved.count({row, axis}) == 0)
            EXPECT_EQ(m.points[row][axis], partner.points[row][axis])
                << "row " << row << " axis " << axis << " moved but not listed";
      if (m.label == "1ulp") {
        EXPECT_EQ(m.distance_log2, 0);
        EXPECT_EQ(m.distance, step);
        subnormal_steps += m.distance < std::numeric_limits<double>::min();
      } else {
        ASSERT_EQ(m.label, "2^-" + std::to_string(m.distance_log2));
        EXPECT_EQ(m.distance, std::max(std::ldexp(1.0, -m.distance_log2), step));
      }
    }
  EXPECT_GT(near_misses, 0u);
  // Coordinates 0 moved by one ulp land on the smallest subnormal: some members do that.
  EXPECT_GT(subnormal_steps, 0u);
}

TEST(Families, VariantsAreTheBaseMembersScaledOrTranslated) {
  const std::vector<fam::Family> families = fam::generate_families(3, 14);
  std::map<std::string, const fam::Family*> by_name;
  for (const fam::Family& f : families) by_name[f.name] = &f;
  ASSERT_EQ(families.size(), fam::all_family_names().size());
  std::size_t exact_members = 0, inexact_members = 0;
  for (const fam::Family& f : families) {
    if (!f.is_variant()) continue;
    SCOPED_TRACE(f.name);
    const fam::Family& base = *by_name.at(f.base);
    const bool power_of_two = f.parameters.at("transform") == "power_of_two";
    EXPECT_EQ(f.type, base.type);
    ASSERT_EQ(f.members.size(), base.members.size());
    EXPECT_TRUE((f.scale != 1.0) != (f.offset != 0.0));
    for (std::size_t i = 0; i < f.members.size(); ++i) {
      const fam::Member& m = f.members[i];
      EXPECT_EQ(m.source, static_cast<int>(i));
      bool exact = true;  // every product x 2^k a double
      for (int row = 0; row < 8; ++row)
        for (int axis = 0; axis < 3; ++axis) {
          const double x = base.members[i].points[row][axis], y = m.points[row][axis];
          if (f.offset != 0.0) {
            EXPECT_EQ(y, x + f.offset);
          } else if (!power_of_two || std::isfinite(x * f.scale)) {
            EXPECT_EQ(y, x * f.scale);  // a power of two: exact unless it underflows
            exact = exact && mpq_class(y) == mpq_class(x) * mpq_class(f.scale);
          } else {
            EXPECT_EQ(y, std::copysign(std::numeric_limits<double>::max(), x));
            exact = false;
          }
        }
      if (power_of_two) {
        // Exactly scaled members keep their base member's claim; the others carry none.
        EXPECT_EQ(m.exact_scaling, exact);
        EXPECT_EQ(m.claim_known, exact);
        exact_members += exact;
        inexact_members += !exact;
        if (exact) {
          EXPECT_EQ(m.collides, base.members[i].collides);
          EXPECT_EQ(m.toi, base.members[i].toi);
          EXPECT_EQ(m.partner, base.members[i].partner);
        }
      } else {
        EXPECT_FALSE(m.claim_known);
      }
    }
  }
  // Both occur: +-100 and +-300 are exact on these magnitudes, 2^1000 overflows the
  // tunneling families' 2^40, 2^-1000 loses one-ulp moves of subnormal size.
  EXPECT_GT(exact_members, 0u);
  EXPECT_GT(inexact_members, 0u);
}

// The power-of-two variants' claims hold: the exact path on the rational query and the default
// path reproduce the verdict and the tightest TOI pair of every member that keeps its claim,
// and a near miss still lies at its (scaled) distance from its colliding partner.
TEST(Families, PowerOfTwoVariantsKeepTheirClaimsWhereExact) {
  std::size_t claims = 0, dropped = 0;
  for (const fam::Family& base : base_families()) {
    for (const fam::Variant& v : fam::variants()) {
      if (v.power_of_two == 0) continue;
      const fam::Family f = fam::make_variant(base, v);
      for (std::size_t i = 0; i < f.members.size(); ++i) {
        const fam::Member& m = f.members[i];
        if (!m.claim_known) {
          ++dropped;
          continue;
        }
        ++claims;
        const RationalQuery q = rational(f.type, m.points);
        expect_answer(m, exactccd::exact_ccd(q), where(f, i) + ", exact_ccd");
        expect_answer(m, exactccd::test::double_api_ccd(q), where(f, i) + ", default");
        if (m.collides) continue;
        const fam::Member& partner = f.members[static_cast<std::size_t>(m.partner)];
        if (!partner.exact_scaling) continue;
        for (std::size_t k = 0; k < m.moved.size(); ++k) {
          const int row = m.moved[k].row, axis = m.moved[k].axis;
          EXPECT_EQ(mpq_class(m.points[row][axis]) - mpq_class(partner.points[row][axis]),
                    m.direction[k] * mpq_class(m.distance))
              << where(f, i) << " row " << row << " axis " << axis;
        }
      }
    }
  }
  std::cout << "[ claims   ] " << claims << " power-of-two members keep their claim, " << dropped
            << " do not\n";
  EXPECT_GT(claims, dropped);
  EXPECT_GT(dropped, 0u);
}

// The random families: claim-less, deterministic, every coordinate finite, the exponents
// spread as named (wide: every coordinate a normal double with exponent in [-E, E], spread over
// most of that range in each family; huge: coordinates at 2^900 .. 2^1001 next to subnormal
// ones), and the exact path decides every member (the corpus writes its answers).
TEST(Families, RandomFamiliesSpreadTheirExponentsWithoutClaims) {
  for (const std::string& name : fam::random_family_names()) {
    SCOPED_TRACE(name);
    const fam::Family f = fam::generate_random_family(name, 7, 20);
    EXPECT_FALSE(f.is_variant());
    EXPECT_EQ(f.base, name);
    EXPECT_EQ(f.type, name.rfind("vf_", 0) == 0 ? QueryType::vertex_face : QueryType::edge_edge);
    ASSERT_EQ(f.members.size(), 20u);
    const fam::Family again = fam::generate_random_family(name, 7, 20);
    const fam::Family other = fam::generate_random_family(name, 8, 20);
    int lowest = INT_MAX, highest = INT_MIN;
    std::size_t subnormal = 0, same = 0, same_other = 0;
    for (std::size_t i = 0; i < f.members.size(); ++i) {
      const fam::Member& m = f.members[i];
      EXPECT_FALSE(m.claim_known);
      EXPECT_EQ(m.label, "random");
      same += m.points == again.members[i].points;
      same_other += m.points == other.members[i].points;
      for (const Eigen::Vector3d& p : m.points)
        for (int k = 0; k < 3; ++k) {
          ASSERT_TRUE(std::isfinite(p[k]));
          if (p[k] == 0) continue;
          lowest = std::min(lowest, std::ilogb(p[k]));
          highest = std::max(highest, std::ilogb(p[k]));
          subnormal += std::fpclassify(p[k]) == FP_SUBNORMAL;
        }
    }
    EXPECT_EQ(same, f.members.size());  // deterministic
    EXPECT_EQ(same_other, 0u);          // and the seed matters
    const std::size_t at = name.rfind('_');
    if (name.find("wide_exponent") != std::string::npos) {
      const int spread = std::stoi(name.substr(at + 1));
      EXPECT_EQ(subnormal, 0u);
      EXPECT_GE(lowest, -spread);
      EXPECT_LE(highest, spread);
      EXPECT_GT(highest - lowest, spread);  // 480 exponents drawn: far more than half the range
    } else {
      EXPECT_GT(subnormal, 0u);
      EXPECT_GE(highest, 900);
      EXPECT_LE(highest, 1002);
      EXPECT_LT(lowest, -1022);
    }
  }
  // The exact path decides them (no construction to contradict), and the corpus has both
  // verdicts over the random families.
  const fam::Corpus corpus = fam::generate_corpus(7, 6, fam::random_family_names());
  ASSERT_EQ(corpus.families.size(), fam::random_family_names().size());
  std::size_t collisions = 0, queries = 0;
  for (const fam::GeneratedFamily& g : corpus.families) {
    EXPECT_TRUE(fam::claim_mismatches(g).empty());
    EXPECT_EQ(g.exact.size(), 6u);
    collisions += g.collisions();
    queries += g.exact.size();
  }
  EXPECT_GT(collisions, 0u);
  EXPECT_LT(collisions, queries);
}

TEST(Families, GenerationIsDeterministic) {
  const auto same = [](const std::vector<fam::Family>& a, const std::vector<fam::Family>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t f = 0; f < a.size(); ++f) {
      if (a[f].name != b[f].name || a[f].members.size() != b[f].members.size()) return false;
      for (std::size_t i = 0; i < a[f].members.size(); ++i)
        if (a[f].members[i].points != b[f].members[i].points ||
            a[f].members[i].label != b[f].members[i].label)
          return false;
    }
    return true;
  };
  EXPECT_TRUE(same(fam::generate_families(5, 14), fam::generate_families(5, 14)));
  EXPECT_FALSE(same(fam::generate_families(5, 14), fam::generate_families(6, 14)));
  // A family does not depend on which other families are generated with it.
  // (generate_families lists base families first, then the variants.)
  EXPECT_TRUE(same(
      fam::generate_families(5, 14, {"vf_grazing@t1e4", "ee_parallel"}),
      {fam::generate_base_family("ee_parallel", 5, 14),
       fam::make_variant(fam::generate_base_family("vf_grazing", 5, 14), fam::variants()[4])}));

  // The written texts: identical bytes with one thread and with all of them.
  const auto texts = [] {
    const fam::Corpus c = fam::generate_corpus(5, 14);
    std::string all = fam::manifest_text(c);
    for (const fam::GeneratedFamily& g : c.families)
      all += fam::data_csv_text(g) + fam::toi_csv_text(g);
    return all;
  };
  std::string one_thread;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one_thread = texts();
  }
  EXPECT_EQ(texts(), one_thread);
}

TEST(Families, ExactFractionsAreLowestTermsAndExact) {
  EXPECT_EQ(fam::exact_fraction(0.0), "0,1");
  EXPECT_EQ(fam::exact_fraction(-0.0), "0,1");
  EXPECT_EQ(fam::exact_fraction(0.375), "3,8");
  EXPECT_EQ(fam::exact_fraction(-3.0), "-3,1");
  EXPECT_EQ(fam::exact_fraction(std::ldexp(1.0, 60)), "1152921504606846976,1");
  // The smallest subnormal, 2^-1074: the denominator has 324 digits.
  const std::string tiny = fam::exact_fraction(std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(tiny.substr(0, 2), "1,");
  EXPECT_EQ(mpq_class(1, mpz_class(tiny.substr(2))),
            mpq_class(std::numeric_limits<double>::denorm_min()));
  EXPECT_THROW(fam::exact_fraction(std::nan("")), std::invalid_argument);
}

// ------------------------------------------------------------------ the `generate` command


TEST_F(GenerateCommand, BadArgumentsExitWithStatusTwo) {
  const std::string out = "--out '" + (dir_ / "suite").string() + "'";
  expect_usage_error("generate", "--out");
  expect_usage_error("generate " + out + " --per-family 1", "--per-family");
  expect_usage_error("generate " + out + " --per-family abc", "--per-family");
  expect_usage_error("generate " + out + " --seed -3", "--seed");
  expect_usage_error("generate " + out + " --families vf_t0,no_such_family", "no_such_family");
  expect_usage_error("generate " + out + " --families vf_t0@s7", "vf_t0@s7");
  std::ofstream(dir_ / "a-file") << "x";
  expect_usage_error("generate --out '" + (dir_ / "a-file").string() + "'", "a-file");
}

// A small corpus: the layout, the manifest's counts, and `check` on it (which must not take
// the toi_0.csv sidecars for query files).
TEST_F(GenerateCommand, WritesTheLayoutAndCheckAgrees) {
  const fs::path suite = dir_ / "suite";
  const Run r = run("generate --out '" + suite.string() +
                    "' --seed 9 --per-family 7 --families vf_interior,ee_crossing@t1e8");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("vf_interior"), std::string::npos);
  EXPECT_NE(r.out.find("ee_crossing@t1e8"), std::string::npos);
  const nlohmann::json manifest = nlohmann::json::parse(read(suite / "manifest.json"));
  EXPECT_EQ(manifest.at("generator"), "exactccd generate");
  EXPECT_EQ(manifest.at("seed"), 9);
  ASSERT_EQ(manifest.at("families").size(), 2u);
  for (const auto& f : manifest.at("families")) {
    const std::string type = f.at("type");
    const fs::path folder = suite / f.at("name").get<std::string>() / type;
    EXPECT_EQ(f.at("queries"), 7);
    const exactccd::QueryFile file = exactccd::read_query_file(
        (folder / "data_0.csv").string(),
        type == "vertex-face" ? QueryType::vertex_face : QueryType::edge_edge);
    ASSERT_EQ(file.queries.size(), 7u);
    std::size_t collisions = 0;
    for (const auto& q : file.queries) collisions += q.truth;
    EXPECT_EQ(f.at("collisions"), collisions);
    std::istringstream toi(read(folder / "toi_0.csv"));
    std::size_t lines = 0;
    for (std::string line; std::getline(toi, line); ++lines)
      EXPECT_EQ(line.rfind(std::to_string(lines) + (file.queries[lines].truth ? ",1," : ",0,,"), 0),
                0u)
          << line;
    EXPECT_EQ(lines, 7u);
  }
  const std::vector<std::string> found = exactccd::find_query_files(suite.string());
  ASSERT_EQ(found.size(), 2u);
  for (const std::string& f : found) EXPECT_EQ(fs::path(f).filename(), "data_0.csv");
  const Run check = run("check '" + suite.string() + "'");
  EXPECT_EQ(check.status, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("TOTAL"), std::string::npos);
  // A second run into the same folder replaces the files with --force only (same seed: same
  // bytes), and deletes none: the family it does not write stays.
  const std::string before = read(suite / "vf_interior/vertex-face/data_0.csv");
  const std::string again =
      "generate --out '" + suite.string() + "' --seed 9 --per-family 7 --families vf_interior";
  EXPECT_EQ(run(again).status, 2);
  ASSERT_EQ(run(again + " --force").status, 0);
  EXPECT_EQ(read(suite / "vf_interior/vertex-face/data_0.csv"), before);
  EXPECT_TRUE(fs::exists(suite / "ee_crossing@t1e8/edge-edge/data_0.csv"));
}

// The new kinds of family through the command: a random family (truth from the exact path),
// a power-of-two variant (its exact members' claims checked: exit status 0) and a base family.
TEST_F(GenerateCommand, WritesRandomAndPowerOfTwoFamilies) {
  const fs::path suite = dir_ / "suite";
  const Run r = run("generate --out '" + suite.string() +
                    "' --seed 4 --per-family 7 --families "
                    "vf_wide_exponent_1000,ee_resting@p2^-1000,vf_stacked");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const nlohmann::json manifest = nlohmann::json::parse(read(suite / "manifest.json"));
  ASSERT_EQ(manifest.at("families").size(), 3u);
  std::set<std::string> names;
  for (const auto& f : manifest.at("families")) {
    const std::string name = f.at("name"), type = f.at("type");
    names.insert(name);
    EXPECT_EQ(f.at("queries"), 7);
    const exactccd::QueryFile file = exactccd::read_query_file(
        (suite / name / type / "data_0.csv").string(),
        type == "vertex-face" ? QueryType::vertex_face : QueryType::edge_edge);
    EXPECT_EQ(file.queries.size(), 7u) << name;
    if (name == "ee_resting@p2^-1000") {
      EXPECT_EQ(f.at("parameters").at("transform"), "power_of_two");
      EXPECT_EQ(f.at("parameters").at("exponent"), -1000);
    }
  }
  EXPECT_EQ(names, (std::set<std::string>{"vf_wide_exponent_1000", "ee_resting@p2^-1000",
                                          "vf_stacked"}));
  const Run check = run("check '" + suite.string() + "'");
  EXPECT_EQ(check.status, 0) << check.out << check.err;
}

}  // namespace
