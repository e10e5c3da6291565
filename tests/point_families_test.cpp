// The point kinds' degenerate families (corpus/point_families.hpp, `exactccd generate --type`):
// every member of every family holds its construction under the exact path and under the
// filtered path (the construction is the independent truth: built exactly in doubles to touch,
// or to miss by one ulp or 2^-30); each family's file reads back (read_primitive_query_file) as
// exactly its doubles with the exact verdicts as truth; the same seed gives the same files; and
// the families are hard: float_only gets some of them wrong.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "corpus/point_families.hpp"
#include "exact/arithmetic/rational.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

constexpr PrimitiveKind kKinds[] = {PrimitiveKind::point_edge, PrimitiveKind::point_edge_2d,
                                    PrimitiveKind::point_point, PrimitiveKind::point_point_2d,
                                    PrimitiveKind::point_plane};

TEST(PointFamilies, EveryMemberHoldsItsConstructionInTheCertifiedModes) {
  std::size_t float_wrong = 0, members = 0;
  for (const PrimitiveKind kind : kKinds) {
    const auto families = families::generate_point_families(kind, 7, 25);
    ASSERT_GE(families.size(), 4u) << to_string(kind);
    bool some_collide = false, some_miss = false;
    for (const families::PointFamily& f : families) {
      EXPECT_TRUE(families::point_claim_mismatches(f).empty()) << f.name;
      some_collide |= f.collides;
      some_miss |= !f.collides;
      for (std::size_t i = 0; i < f.members.size(); ++i) {
        const CcdResult filtered = families::decide_point_query(kind, f.members[i], {});
        EXPECT_EQ(filtered.collides, f.collides) << f.name << " member " << i;
        if (filtered.collides) {
          EXPECT_EQ(filtered.toi_lo, f.exact[i].toi_lo) << f.name << " member " << i;
          EXPECT_EQ(filtered.toi_hi, f.exact[i].toi_hi) << f.name << " member " << i;
        }
        CcdOptions fo;
        fo.mode = Mode::float_only;
        float_wrong += families::decide_point_query(kind, f.members[i], fo).collides != f.collides;
        ++members;
      }
    }
    EXPECT_TRUE(some_collide && some_miss) << to_string(kind);
  }
  EXPECT_GT(float_wrong, members / 20) << "the families should trip the uncertified test";
}

TEST(PointFamilies, FilesReadBackExactlyAndTheSeedFixesThem) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("exactccd_point_families_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const PrimitiveKind kind : kKinds) {
    const auto a = families::generate_point_families(kind, 3, 6);
    const auto b = families::generate_point_families(kind, 3, 6);
    const auto c = families::generate_point_families(kind, 4, 6);
    ASSERT_EQ(a.size(), b.size());
    bool differs = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(families::point_family_csv(a[k]), families::point_family_csv(b[k]));
      differs |= families::point_family_csv(a[k]) != families::point_family_csv(c[k]);
      const std::filesystem::path path = dir / (a[k].name + ".csv");
      std::ofstream(path) << families::point_family_csv(a[k]);
      const PrimitiveQueryFile file = read_primitive_query_file(path.string(), kind);
      ASSERT_EQ(file.queries.size(), a[k].members.size()) << a[k].name;
      for (std::size_t i = 0; i < file.queries.size(); ++i) {
        EXPECT_EQ(file.queries[i].truth, a[k].exact[i].collides);
        ASSERT_EQ(file.queries[i].points.size(), a[k].members[i].size());
        for (std::size_t r = 0; r < a[k].members[i].size(); ++r) {
          EXPECT_EQ(file.queries[i].points[r].x, exact::Rational(a[k].members[i][r].x()));
          EXPECT_EQ(file.queries[i].points[r].y, exact::Rational(a[k].members[i][r].y()));
          EXPECT_EQ(file.queries[i].points[r].z, exact::Rational(a[k].members[i][r].z()));
        }
      }
    }
    EXPECT_TRUE(differs) << "another seed gives other members";
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace exactccd::test
