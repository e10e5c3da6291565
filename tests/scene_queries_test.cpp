// The scene data set (tests/data/scene-queries): vertex-face and edge-edge queries sampled from
// the demonstration scenes (bench/scenes/export_queries.py). Their truth column was written by
// the scenes from Scene::find_contacts (default, filtered path), so it is checked here against
// deciders that do not share the filters: the exact rational path alone, and CGAL's exact kernel
// for contacts whose exact time is a double.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace exactccd::test {
namespace {

std::vector<SampleQuery> scene_queries() {
  std::vector<SampleQuery> out;
  for (const std::string& path : find_query_files(EXACTCCD_TEST_DATA "/scene-queries")) {
    const auto type = query_type_from_path(path);
    if (!type) throw std::runtime_error(path + ": neither vertex-face nor edge-edge");
    for (const QueryRecord& r : read_query_file(path, *type).queries)
      out.push_back({path, r.first_line, r.query, r.truth});
  }
  return out;
}

TEST(SceneQueries, EveryScenePresentWithContactsAndMisses) {
  const auto queries = scene_queries();
  std::map<std::string, std::pair<std::size_t, std::size_t>> per_scene;  // hits, misses
  for (const auto& q : queries) {
    for (const char* scene : {"thin_sheet", "cloth", "peg_in_hole"})
      if (q.file.find(std::string("/") + scene + "/") != std::string::npos)
        (q.truth ? per_scene[scene].first : per_scene[scene].second)++;
    EXPECT_TRUE(all_coordinates_are_doubles(q.query)) << q.where();
  }
  EXPECT_EQ(per_scene.size(), 3u);
  for (const auto& [scene, counts] : per_scene) {
    EXPECT_GT(counts.first, 0u) << scene;
    EXPECT_GT(counts.second, 0u) << scene;
  }
}

// The exact path alone (no filter) must reproduce the recorded verdicts, and the double API
// (filters first) must return the same verdict and the same TOI enclosure.
TEST(SceneQueries, ExactPathAndDoubleApiAgreeWithRecordedVerdicts) {
  std::size_t disagreements = 0, checked = 0;
  for (const auto& q : scene_queries()) {
    const CcdResult exact = exact_ccd(q.query);
    const CcdResult filtered = double_api_ccd(q.query);
    ++checked;
    if (exact.collides != q.truth || filtered.collides != q.truth ||
        (exact.collides && (exact.toi_lo != filtered.toi_lo || exact.toi_hi != filtered.toi_hi))) {
      ++disagreements;
      ADD_FAILURE() << q.where() << ": truth " << q.truth << ", exact " << exact.collides
                    << " [" << exact.toi_lo << ", " << exact.toi_hi << "], default "
                    << filtered.collides << " [" << filtered.toi_lo << ", " << filtered.toi_hi
                    << "]";
    }
  }
  EXPECT_EQ(disagreements, 0u);
  EXPECT_EQ(checked, 6000u);
}

// Colliding queries whose exact first contact time is a double (toi_lo == toi_hi): CGAL's exact
// kernel confirms contact at that time. (Other contact times are algebraic numbers; the exact
// path's Sturm isolation, tested elsewhere, covers them.)
TEST(SceneQueries, ContactsAtDoubleTimesConfirmedByCgal) {
  std::size_t confirmed = 0;
  for (const auto& q : scene_queries()) {
    if (!q.truth) continue;
    const CcdResult r = exact_ccd(q.query);
    if (r.toi_lo != r.toi_hi) continue;
    EXPECT_TRUE(cgal_contact_at(q.query, mpq_class(r.toi_lo))) << q.where();
    ++confirmed;
  }
  std::printf("contacts at a double time confirmed by CGAL: %zu\n", confirmed);
}

}  // namespace
}  // namespace exactccd::test
