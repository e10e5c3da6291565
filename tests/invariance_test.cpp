// Geometric invariances of the verdict and of the exact TOI enclosure.
//
// Relabelling the primitives' vertices, moving every point by the same (possibly time-varying)
// translation, scaling by a power of two, permuting or mirroring axes: none changes the set of
// contact times, so the verdict and the tight enclosure of t* must not change. Reversing time
// maps the contact set C to 1 - C: the verdict is unchanged, and the reversed query's first
// contact is the original's last one.
//
// Inputs: the sample queries and seeded random queries (exact doubles with few mantissa bits,
// planted degeneracies, tiny grids, planted contacts). Transforms act on exact rationals; where
// the transformed coordinates of a random input are all doubles, the double API must agree with
// the rational one.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace exactccd::test {
namespace {

struct Input {
  std::string where;
  RationalQuery query;
  bool random = false;
};

/// The sample queries followed by random queries.
const std::vector<Input>& inputs() {
  static const std::vector<Input> all = [] {
    std::vector<Input> out;
    for (const auto& s : scaled_sample_queries()) out.push_back({s.where(), s.query, false});
    QueryGenerator gen(test_seed("invariance inputs"));
    const int per_type = static_cast<int>(scaled_count(1500));
    for (const QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
      for (int i = 0; i < per_type; ++i) {
        RationalQuery q;
        mpq_class tc;
        switch (i % 4) {
          case 0: q = gen.uniform(type, gen.uniform_int(3, 12)); break;
          case 1: q = gen.degenerate(type); break;
          case 2: q = gen.tiny_grid(type); break;
          default: q = gen.colliding(type, &tc); break;
        }
        out.push_back(
            {std::string("random ") + to_string(type) + " #" + std::to_string(i), q, true});
      }
    }
    return out;
  }();
  return all;
}

/// exact_ccd(inputs()[i]) at t_max = 1, computed on first use and kept for the other properties
/// (ctest runs each property in its own process, which then computes only what it needs).
const CcdResult& original_result(std::size_t i) {
  static std::vector<std::optional<CcdResult>> cache(inputs().size());
  if (!cache[i]) cache[i] = exact_ccd(inputs()[i].query);
  return *cache[i];
}

using Transform = std::function<RationalQuery(const RationalQuery&, std::mt19937_64&)>;

enum class Compare { verdict, verdict_and_toi };

/// Applies `transform` to every input of the given types and compares the results.
void expect_invariant(const char* name, const std::vector<QueryType>& types,
                      const Transform& transform, Compare compare) {
  std::mt19937_64 rng(test_seed(name));
  std::size_t checked = 0, colliding = 0, double_api = 0, failures = 0;
  for (std::size_t i = 0; i < inputs().size(); ++i) {
    const Input& in = inputs()[i];
    if (std::find(types.begin(), types.end(), in.query.type) == types.end()) continue;
    const CcdResult& original = original_result(i);
    const RationalQuery tq = transform(in.query, rng);
    const CcdResult r = exact_ccd(tq);
    ++checked;
    colliding += r.collides;
    bool ok = r.collides == original.collides;
    if (ok && compare == Compare::verdict_and_toi)
      ok = r.toi_lo == original.toi_lo && r.toi_hi == original.toi_hi;
    // The double API on the transformed random inputs (sample_queries_test covers it on the
    // sample queries themselves).
    if (in.random && all_coordinates_are_doubles(tq)) {
      ++double_api;
      const CcdResult d = double_api_ccd(tq);
      if (d.collides != r.collides || d.toi_lo != r.toi_lo || d.toi_hi != r.toi_hi) {
        ADD_FAILURE() << name << ": double and rational API differ on transformed " << in.where
                      << describe(tq);
        ++failures;
      }
    }
    if (!ok) {
      ADD_FAILURE() << name << " changes the result of " << in.where << ": collides "
                    << original.collides << " [" << original.toi_lo << ", " << original.toi_hi
                    << "] -> collides " << r.collides << " [" << r.toi_lo << ", " << r.toi_hi
                    << "]" << describe(in.query) << "\ntransformed:" << describe(tq);
      ++failures;
    }
    if (failures >= 10) {
      ADD_FAILURE() << name << ": stopping after 10 failures";
      return;
    }
  }
  std::cout << "[ checked  ] " << name << ": " << checked << " queries (" << colliding
            << " colliding), " << double_api << " also through the double API\n";
  EXPECT_GT(checked, scaled_count(2000));
  EXPECT_GT(colliding, scaled_count(100));
}

const std::vector<QueryType> kVertexFace{QueryType::vertex_face};
const std::vector<QueryType> kEdgeEdge{QueryType::edge_edge};
const std::vector<QueryType> kBoth{QueryType::vertex_face, QueryType::edge_edge};

/// Reorders the four points of each time step: new point k is old point order[k].
RationalQuery relabel(const RationalQuery& q, const std::array<int, 4>& order) {
  RationalQuery r = q;
  for (int k = 0; k < 4; ++k) {
    r.points[k] = q.points[order[k]];
    r.points[k + 4] = q.points[order[k] + 4];
  }
  return r;
}

/// Applies f to every point at time 0 (f0) and time 1 (f1).
template <class F0, class F1>
RationalQuery map_points(const RationalQuery& q, F0&& f0, F1&& f1) {
  RationalQuery r = q;
  for (int i = 0; i < 4; ++i) {
    f0(&r.points[i]);
    f1(&r.points[i + 4]);
  }
  return r;
}

RationalPoint add(const RationalPoint& a, const RationalPoint& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}

/// A dyadic offset with few bits: exact-double sums with every random input.
RationalPoint dyadic_offset(std::mt19937_64& rng) {
  QueryGenerator g(rng());
  RationalPoint p = g.point(8);
  const mpq_class scale = pow2(g.uniform_int(-4, 4));
  return {p.x * scale, p.y * scale, p.z * scale};
}

/// An offset with denominators 3, 5 and 7: never a double, exercises the rational API only.
RationalPoint odd_offset(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> n(-100, 100);
  return {mpq_class(n(rng), 3), mpq_class(n(rng), 5), mpq_class(n(rng), 7)};
}

TEST(Invariance, CyclicPermutationOfTriangle) {
  expect_invariant("cyclic permutation (a, b, c) -> (b, c, a)", kVertexFace,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     return relabel(q, {0, 2, 3, 1});
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, OddPermutationOfTriangle) {
  expect_invariant("odd permutation (a, b, c) -> (a, c, b)", kVertexFace,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     return relabel(q, {0, 1, 3, 2});
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, SwapEndpointsOfFirstEdge) {
  expect_invariant("swap ea0, ea1", kEdgeEdge,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     return relabel(q, {1, 0, 2, 3});
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, SwapEndpointsOfSecondEdge) {
  expect_invariant("swap eb0, eb1", kEdgeEdge,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     return relabel(q, {0, 1, 3, 2});
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, SwapEdges) {
  expect_invariant("swap edge a and edge b", kEdgeEdge,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     return relabel(q, {2, 3, 0, 1});
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, DyadicTranslation) {
  expect_invariant("translation by a dyadic offset", kBoth,
                   [](const RationalQuery& q, std::mt19937_64& rng) {
                     const RationalPoint d = dyadic_offset(rng);
                     const auto f = [&d](RationalPoint* p) { *p = add(*p, d); };
                     return map_points(q, f, f);
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, RationalTranslation) {
  expect_invariant("translation by a non-dyadic rational offset", kBoth,
                   [](const RationalQuery& q, std::mt19937_64& rng) {
                     const RationalPoint d = odd_offset(rng);
                     const auto f = [&d](RationalPoint* p) { *p = add(*p, d); };
                     return map_points(q, f, f);
                   },
                   Compare::verdict_and_toi);
}

// Every point moved by the same offset (1 - t) d0 + t d1 at each time t: the relative
// configuration at every instant is unchanged.
TEST(Invariance, TimeVaryingTranslation) {
  expect_invariant("time-varying translation", kBoth,
                   [](const RationalQuery& q, std::mt19937_64& rng) {
                     const RationalPoint d0 = dyadic_offset(rng), d1 = dyadic_offset(rng);
                     return map_points(q, [&d0](RationalPoint* p) { *p = add(*p, d0); },
                                       [&d1](RationalPoint* p) { *p = add(*p, d1); });
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, ScalingByPowersOfTwo) {
  expect_invariant("scaling by 2^k, k in [-40, 40]", kBoth,
                   [](const RationalQuery& q, std::mt19937_64& rng) {
                     const mpq_class s = pow2(std::uniform_int_distribution<int>(-40, 40)(rng));
                     const auto f = [&s](RationalPoint* p) {
                       *p = {p->x * s, p->y * s, p->z * s};
                     };
                     return map_points(q, f, f);
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, CyclicPermutationOfAxes) {
  expect_invariant("axes (x, y, z) -> (y, z, x)", kBoth,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     const auto f = [](RationalPoint* p) { *p = {p->y, p->z, p->x}; };
                     return map_points(q, f, f);
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, SwapOfTwoAxes) {
  expect_invariant("axes (x, y, z) -> (y, x, z)", kBoth,
                   [](const RationalQuery& q, std::mt19937_64&) {
                     const auto f = [](RationalPoint* p) { *p = {p->y, p->x, p->z}; };
                     return map_points(q, f, f);
                   },
                   Compare::verdict_and_toi);
}

TEST(Invariance, MirrorOfOneAxis) {
  expect_invariant("mirror of a random axis", kBoth,
                   [](const RationalQuery& q, std::mt19937_64& rng) {
                     const int axis = std::uniform_int_distribution<int>(0, 2)(rng);
                     const auto f = [axis](RationalPoint* p) {
                       mpq_class& c = axis == 0 ? p->x : (axis == 1 ? p->y : p->z);
                       c = -c;
                     };
                     return map_points(q, f, f);
                   },
                   Compare::verdict_and_toi);
}

RationalQuery reverse_time(const RationalQuery& q) {
  RationalQuery r = q;
  for (int i = 0; i < 4; ++i) std::swap(r.points[i], r.points[i + 4]);
  return r;
}

TEST(Invariance, TimeReversalKeepsVerdict) {
  expect_invariant("time reversal", kBoth,
                   [](const RationalQuery& q, std::mt19937_64&) { return reverse_time(q); },
                   Compare::verdict);
}

// The reversed query's first contact t_r is the original's last contact 1 - t_r: where t_r is a
// double, CGAL must find the original in contact at 1 - t_r and free at sampled times after it.
TEST(Invariance, TimeReversalGivesLastContact) {
  std::size_t checked = 0;
  for (std::size_t i = 0; i < inputs().size(); ++i) {
    const Input& in = inputs()[i];
    if (!original_result(i).collides) continue;
    const CcdResult r = exact_ccd(reverse_time(in.query));
    ASSERT_TRUE(r.collides) << in.where;
    if (r.toi_lo != r.toi_hi) continue;
    ++checked;
    const mpq_class last = 1 - mpq_class(r.toi_lo);
    EXPECT_TRUE(cgal_contact_at(in.query, last))
        << in.where << ": no contact at the last contact time 1 - " << r.toi_lo;
    if (r.toi_lo > 0) {
      const mpq_class gap = 1 - last;
      for (const mpq_class& t : {mpq_class(1), mpq_class(last + gap / 2),
                                 mpq_class(last + gap / (1 << 20))})
        EXPECT_FALSE(cgal_contact_at(in.query, t))
            << in.where << ": contact at t = " << t.get_str() << " after the last contact";
    }
  }
  std::cout << "[ checked  ] " << checked << " last contact times\n";
  EXPECT_GT(checked, scaled_count(500));
}

}  // namespace
}  // namespace exactccd::test
