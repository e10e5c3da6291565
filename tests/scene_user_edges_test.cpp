// Scene::set_edges: a mesh with the simulator's own edge numbering (libigl's (j, i) order, a
// shuffle, reversed orientations) gives the same contacts as the default numbering, edge-edge
// pairs mapped through their vertices, with the same TOIs, in find_contacts and
// earliest_contact; Scene::edges returns the numbering as given; bad edge lists are refused with
// a message naming the row or the side.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

#include "tests/scene_support.hpp"
#include "tests/test_support.hpp"

namespace exactccd::test {
namespace {

/// A wrinkled grid falling through a static grid (vertex-face and edge-edge contacts, with
/// self-collision pairs in the falling one).
SceneSpec falling_sheet() {
  MeshSpec floor = grid(9, 9, Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, 0, 0),
                        Eigen::Vector3d(0, 2, 0));
  floor.is_static = true;
  MeshSpec sheet = grid(9, 9, Eigen::Vector3d(-0.8, -0.8, 0.3), Eigen::Vector3d(1.5, 0.1, 0),
                        Eigen::Vector3d(0.1, 1.5, 0.05));
  sheet.end = sheet.start;
  for (Eigen::Index v = 0; v < sheet.start.rows(); ++v)
    sheet.end(v, 2) -= 0.5 + 0.01 * static_cast<double>(v % 7);
  return {floor, sheet};
}

/// An edge's vertices, smaller first.
std::pair<std::int32_t, std::int32_t> ends(const Edges& e, std::uint32_t row) {
  return {std::min(e(row, 0), e(row, 1)), std::max(e(row, 0), e(row, 1))};
}

/// The contacts with every edge index replaced by its vertex pair, comparable across numberings.
std::map<std::tuple<int, MeshId, std::pair<int, int>, MeshId, std::pair<int, int>>,
         std::pair<double, double>>
by_vertices(const Scene& scene, const std::vector<SceneContact>& contacts) {
  std::map<std::tuple<int, MeshId, std::pair<int, int>, MeshId, std::pair<int, int>>,
           std::pair<double, double>>
      out;
  for (const SceneContact& c : contacts) {
    const ScenePair& p = c.pair;
    std::pair<int, int> a{static_cast<int>(p.first_index), -1};
    std::pair<int, int> b{static_cast<int>(p.second_index), -1};
    if (p.type == QueryType::edge_edge) {
      a = ends(scene.edges(p.first_mesh), p.first_index);
      b = ends(scene.edges(p.second_mesh), p.second_index);
      if (std::make_pair(p.first_mesh, a) > std::make_pair(p.second_mesh, b)) std::swap(a, b);
    }
    out[{static_cast<int>(p.type), p.first_mesh, a, p.second_mesh, b}] = {c.toi_lo, c.toi_hi};
  }
  return out;
}

TEST(SceneUserEdges, OwnNumberingGivesTheSameContacts) {
  const SceneSpec spec = falling_sheet();
  Scene plain = make_scene(spec);
  const SceneResult want = plain.find_contacts();
  ASSERT_GT(want.contacts.size(), 20u);
  std::size_t edge_edge = 0;
  for (const SceneContact& c : want.contacts) edge_edge += c.pair.type == QueryType::edge_edge;
  ASSERT_GT(edge_edge, 5u);

  std::mt19937_64 rng(test_seed("scene_user_edges"));
  for (int variant = 0; variant < 3; ++variant) {
    Scene own = make_scene(spec);
    for (MeshId mesh = 0; mesh < 2; ++mesh) {
      Edges edges = plain.edges(mesh);
      std::vector<Eigen::Index> order(static_cast<std::size_t>(edges.rows()));
      std::iota(order.begin(), order.end(), 0);
      if (variant == 0) {  // libigl's order: sorted by (j, i)
        std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
          return std::make_pair(edges(a, 1), edges(a, 0)) <
                 std::make_pair(edges(b, 1), edges(b, 0));
        });
      } else {
        std::shuffle(order.begin(), order.end(), rng);
      }
      Edges numbered(edges.rows(), 2);
      for (std::size_t k = 0; k < order.size(); ++k) {
        const auto e = order[k];
        const bool flip = variant == 2 && rng() % 2;
        numbered(static_cast<Eigen::Index>(k), 0) = edges(e, flip ? 1 : 0);
        numbered(static_cast<Eigen::Index>(k), 1) = edges(e, flip ? 0 : 1);
      }
      own.set_edges(mesh, numbered);
      EXPECT_EQ(own.edges(mesh), numbered);
    }
    const SceneResult got = own.find_contacts();
    SCOPED_TRACE("variant " + std::to_string(variant));
    EXPECT_EQ(got.contacts.size(), want.contacts.size());
    EXPECT_EQ(by_vertices(own, got.contacts), by_vertices(plain, want.contacts));
    const EarliestContact first = own.earliest_contact();
    EXPECT_EQ(first.contact.toi_lo, want.earliest.toi_lo);
    EXPECT_EQ(first.contact.toi_hi, want.earliest.toi_hi);
    // Every edge-edge contact's pair indexes the numbering as given.
    for (const SceneContact& c : got.contacts)
      if (c.pair.type == QueryType::edge_edge) {
        const EdgeEdgeQuery q = own.edge_edge_query(c.pair);
        const Edges& e = own.edges(c.pair.first_mesh);
        const auto first = e(c.pair.first_index, 0);
        EXPECT_EQ(q.ea0_t0, spec[c.pair.first_mesh].start.row(first).transpose());
      }
  }
}

TEST(SceneUserEdges, BadEdgeListsAreRefused) {
  Scene scene;
  Positions x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  Triangles two(2, 3);
  two << 0, 1, 2, 0, 2, 3;
  const MeshId mesh = scene.add_mesh(x, two);
  const auto message = [&](const Edges& e) -> std::string {
    try {
      scene.set_edges(mesh, e);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  Edges good(5, 2);
  good << 2, 0, 1, 0, 3, 2, 2, 1, 0, 3;
  EXPECT_EQ(message(good), "");
  Edges missing = good.topRows(4);
  EXPECT_EQ(message(missing), "exactccd: set_edges: the side (0, 3) of mesh 0 is missing");
  Edges twice = good;
  twice.row(4) << 1, 2;
  EXPECT_EQ(message(twice), "exactccd: set_edges: edge 4 repeats edge 3");
  Edges diagonal = good;
  diagonal.row(1) << 1, 3;
  EXPECT_EQ(message(diagonal),
            "exactccd: set_edges: edge 1 (1, 3) is no side of a triangle of mesh 0");
  Edges outside = good;
  outside.row(2) << 3, 4;
  EXPECT_EQ(message(outside), "exactccd: set_edges: edge 2 has a vertex index out of range");
  Edges loop = good;
  loop.row(0) << 2, 2;
  EXPECT_EQ(message(loop), "exactccd: set_edges: edge 0 repeats a vertex");
  EXPECT_THROW(scene.set_edges(7, good), std::invalid_argument);
  // A refused list leaves the numbering as it was.
  EXPECT_EQ(scene.edges(mesh), good);
}

}  // namespace
}  // namespace exactccd::test
