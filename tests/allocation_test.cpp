// The culling and filter stages of the default path make no heap allocation (rigid queries
// included): this program
// replaces every global operator new / delete with counting versions and routes GMP's memory
// functions through counters as well, then checks that every query decided by Stage::culling or
// Stage::filter allocated nothing. The exact stages at double times (filter_exact_toi,
// exact_at_double) allocate nothing either when all their computations fit the fixed-size
// integers (exact/stages/integer_query.hpp counts those that needed GMP). The rational exact path
// does allocate (GMP numbers, polynomials): its counts are reported, and a test asserts that it is
// seen allocating, which proves the counters see the library's allocations.
#include <gmp.h>
#include <gtest/gtest.h>

#include <random>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "corpus/random_queries.hpp"
#include "corpus/rigid_queries.hpp"
#include "exact/reference/exact_ccd.hpp"
#include "exact/stages/integer_query.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exact/polynomials/small_polynomial.hpp"
#include "exactccd/query_file.hpp"
#include "exactccd/rigid.hpp"
#include "exact/stages/separation_exact_signs.hpp"
#include "tests/sample_double_queries.hpp"
#include "tests/test_scale.hpp"

// ---------------------------------------------------------------------------------------------
// Counting allocators (per thread: a query's allocations are those of the calling thread)

namespace {
thread_local std::uint64_t g_allocations = 0;

void* counted_malloc(std::size_t size) {
  ++g_allocations;
  if (size == 0) size = 1;
  return std::malloc(size);
}

void* counted_aligned(std::size_t size, std::size_t alignment) {
  ++g_allocations;
  if (alignment < sizeof(void*)) alignment = sizeof(void*);
  void* p = nullptr;
  if (posix_memalign(&p, alignment, size ? size : 1) != 0) return nullptr;
  return p;
}

void* throwing(void* p) {
  if (!p) throw std::bad_alloc();
  return p;
}

// GMP's memory functions (GMP allocates with malloc, not operator new).
void* gmp_allocate(std::size_t size) { return throwing(counted_malloc(size)); }
void* gmp_reallocate(void* p, std::size_t, std::size_t size) {
  ++g_allocations;
  return throwing(std::realloc(p, size));
}
void gmp_free(void* p, std::size_t) { std::free(p); }

// Installed before main (and before any test); GMP numbers made earlier were allocated with
// malloc, which gmp_free releases correctly.
const bool g_gmp_counting_installed = [] {
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
  return true;
}();
}  // namespace

void* operator new(std::size_t size) { return throwing(counted_malloc(size)); }
void* operator new[](std::size_t size) { return throwing(counted_malloc(size)); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void* operator new(std::size_t size, std::align_val_t a) {
  return throwing(counted_aligned(size, static_cast<std::size_t>(a)));
}
void* operator new[](std::size_t size, std::align_val_t a) {
  return throwing(counted_aligned(size, static_cast<std::size_t>(a)));
}
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_aligned(size, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_aligned(size, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

constexpr std::uint64_t kDefaultSeed = 0xa110c;

/// Allocations per stage of the default path.
struct StageAllocations {
  std::uint64_t queries[kStageCount] = {};
  std::uint64_t allocating_queries[kStageCount] = {};
  std::uint64_t allocations[kStageCount] = {};
  std::vector<std::string> offenders;  // culling / filter queries that allocated (first few)

  void record(const DoubleQuery& q, const CcdResult& r, std::uint64_t n) {
    const int s = static_cast<int>(r.decided_by);
    ++queries[s];
    allocations[s] += n;
    if (n == 0) return;
    ++allocating_queries[s];
    if ((r.decided_by == Stage::culling || r.decided_by == Stage::filter) && offenders.size() < 5)
      offenders.push_back(std::to_string(n) + " allocation(s), " + describe(r) + ", " +
                          describe(q));
  }
  std::uint64_t of(Stage s) const { return queries[static_cast<int>(s)]; }
  std::uint64_t allocating(Stage s) const { return allocating_queries[static_cast<int>(s)]; }

  void print(const char* what) const {
    std::printf("%s\n", what);
    for (Stage s : default_path_stages()) {
      const int i = static_cast<int>(s);
      std::printf("  %-17s %7llu queries, %7llu allocating, %8.1f allocations/query\n", to_string(s),
                  static_cast<unsigned long long>(queries[i]),
                  static_cast<unsigned long long>(allocating_queries[i]),
                  queries[i] ? double(allocations[i]) / double(queries[i]) : 0.0);
    }
  }
};

/// Runs the default path on q and counts its allocations. The query and the options are built
/// before the counter is read, so only the call itself is measured.
CcdResult decide_counting(const DoubleQuery& q, const CcdOptions& options, std::uint64_t* n) {
  const VertexFaceQuery vf = q.vertex_face();
  const EdgeEdgeQuery ee = q.edge_edge();
  const std::uint64_t before = g_allocations;
  const CcdResult r = q.type == QueryType::vertex_face ? vertex_face_ccd(vf, options)
                                                       : edge_edge_ccd(ee, options);
  *n = g_allocations - before;
  return r;
}

void expect_no_allocation_in_float_stages(const StageAllocations& a, const char* what) {
  a.print(what);
  EXPECT_EQ(a.allocating(Stage::culling), 0u) << what;
  EXPECT_EQ(a.allocating(Stage::filter), 0u) << what;
  for (const auto& o : a.offenders) ADD_FAILURE() << what << ": " << o;
}

// ---------------------------------------------------------------------------------------------

/// The counters see allocations made by the library: the exact path (Mode::exact) on a
/// colliding query builds GMP rationals and polynomials.
TEST(Allocation, CounterSeesLibraryAllocations) {
  ASSERT_TRUE(g_gmp_counting_installed);
  // p falls through the unit triangle in the plane z = 0 at t = 1/2.
  DoubleQuery q;
  q.type = QueryType::vertex_face;
  q.v = {Eigen::Vector3d(0.25, 0.25, 1), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
         Eigen::Vector3d(0, 1, 0),       Eigen::Vector3d(0.25, 0.25, -1), Eigen::Vector3d(0, 0, 0),
         Eigen::Vector3d(1, 0, 0),       Eigen::Vector3d(0, 1, 0)};
  // The rational path (the reference) builds GMP rationals and polynomials.
  const RationalQuery rq = to_rational(q.vertex_face());
  const CcdOptions options;
  const std::uint64_t start = g_allocations;
  const CcdResult r = exact::vertex_face_ccd_exact(rq, options);
  const std::uint64_t n = g_allocations - start;
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.5);
  EXPECT_GT(n, 0u) << "the counting allocators missed the rational path's allocations";

  // And a plain operator new in this thread is counted.
  const std::uint64_t before = g_allocations;
  auto* volatile probe = new int(1);
  delete probe;
  EXPECT_EQ(g_allocations - before, 1u);
}

TEST(Allocation, CullingAndFilterStagesDoNotAllocateOnRandomQueries) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  std::printf("[ seed     ] EXACTCCD_TEST_SEED=%llu\n", static_cast<unsigned long long>(seed));
  const std::uint64_t n = scaled_count(1500, scale_from_environment());
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
    StageAllocations a;
    for (Family family : kAllFamilies) {
      const Generator g{family, type};
      for (std::uint64_t i = 0; i < affordable_count(g, n); ++i) {
        std::mt19937_64 rng;
        const DoubleQuery q = generate(g, seed, i, rng);
        // Over [0, 1] (semi-static stage enabled) and over [0, t_max < 1] with a coarse width.
        for (const CcdOptions& options : {CcdOptions{}, CcdOptions{0.75, 1e-6, Mode::filtered}}) {
          std::uint64_t count = 0;
          const CcdResult r = decide_counting(q, options, &count);
          a.record(q, r, count);
        }
      }
    }
    const char* what = type == QueryType::vertex_face ? "vertex-face" : "edge-edge";
    expect_no_allocation_in_float_stages(a, what);
    // The generators must reach the stages under test, or this test proves nothing.
    EXPECT_GT(a.of(Stage::culling), scaled_count(1000)) << what;
    EXPECT_GT(a.of(Stage::filter), scaled_count(1000)) << what;
  }
}

TEST(Allocation, CullingAndFilterStagesDoNotAllocateOnSampleQueries) {
  StageAllocations a;
  for (const DoubleQuery& q : sample_double_queries()) {
    for (const CcdOptions& options : {CcdOptions{}, CcdOptions{1.0, 1e-3, Mode::filtered}}) {
      std::uint64_t count = 0;
      const CcdResult res = decide_counting(q, options, &count);
      a.record(q, res, count);
    }
  }
  expect_no_allocation_in_float_stages(a, "sample");
  EXPECT_GT(a.of(Stage::culling) + a.of(Stage::filter), 1000u);
}

/// Queries decided at double times whose exact computations all stayed within the fixed widths
/// (no GMP computation counted during the call) make no allocation; GMP computations are seen
/// allocating.
struct AtDoubleTimes {
  std::uint64_t fixed = 0, gmp = 0, gmp_allocating = 0;
  std::vector<std::string> offenders;

  void record(const DoubleQuery& q, const CcdResult& r, std::uint64_t allocations,
              bool used_gmp) {
    if (r.decided_by != Stage::exact_at_double && r.decided_by != Stage::filter_exact_toi) return;
    if (used_gmp) {
      ++gmp;
      gmp_allocating += allocations > 0;
      return;
    }
    ++fixed;
    if (allocations > 0 && offenders.size() < 5)
      offenders.push_back(std::to_string(allocations) + " allocation(s), " + describe(r) + ", " +
                          describe(q));
  }
};

void decide_at_double_times(const DoubleQuery& q, const CcdOptions& options, AtDoubleTimes* a) {
  const std::uint64_t gmp_before = exact::gmp_computations_in_this_thread();
  std::uint64_t count = 0;
  const CcdResult r = decide_counting(q, options, &count);
  a->record(q, r, count, exact::gmp_computations_in_this_thread() != gmp_before);
}

TEST(Allocation, MinimumSeparationCullingAndFilterDoNotAllocate) {
  // Minimum separation: culling with delta and the interval search (stage filter: never within
  // delta, or a first contact whose every sign intervals or double-double with an error bound
  // certified) allocate nothing; so do exact signs at doubles (exact_at_double) that all ran in
  // the fixed widths (proofs/min_separation.md#fixed-width-signs); GMP evaluations and the
  // exact stage may.
  StageAllocations a;
  AtDoubleTimes at_doubles;
  const auto& all = sample_double_queries();
  for (std::size_t i = 0; i < all.size(); i += subset_stride()) {
    for (const double delta : {1.5e-7, 1.5e-5, 1.5e-3}) {
      CcdOptions options;
      options.min_separation = delta;
      const std::uint64_t gmp_before = exact::separation::gmp_evaluations_in_this_thread();
      std::uint64_t count = 0;
      const CcdResult res = decide_counting(all[i], options, &count);
      a.record(all[i], res, count);
      at_doubles.record(
          all[i], res, count,
          exact::separation::gmp_evaluations_in_this_thread() != gmp_before);
    }
  }
  expect_no_allocation_in_float_stages(a, "sample, minimum separation");
  EXPECT_GT(a.of(Stage::culling), 100u);
  EXPECT_GT(a.of(Stage::filter), 100u);
  // The double-double signs with an error bound decide the sample queries' signs at doubles
  // (stage filter, checked above). Exact signs in the fixed widths are needed where a region
  // polynomial vanishes at a double: a vertex reaching delta over a face's interior, and an
  // edge reaching delta over another, at a dyadic t* (the heights short dyadics, so the
  // polynomial is exactly 0 there; the other coordinates full doubles, so that no interval
  // is exactly [0, 0]).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(0.0, 0.1);
  auto in_plane = [&](double x, double y) { return Eigen::Vector3d(x + jitter(rng), y + jitter(rng), 0); };
  for (int i = 0; i < 200; ++i) {
    const double delta = std::ldexp(1.0, -static_cast<int>(4 + rng() % 20));
    const double t_star = static_cast<double>(1 + 2 * (rng() % 127)) / 256;
    const double speed = std::ldexp(static_cast<double>(1 + rng() % 15), -3);
    const double z0 = delta + speed * t_star, z1 = delta - speed * (1 - t_star);
    const Eigen::Vector3d up0(0, 0, z0), up1(0, 0, z1);
    DoubleQuery q;
    q.type = i % 2 == 0 ? QueryType::vertex_face : QueryType::edge_edge;
    if (q.type == QueryType::vertex_face) {  // p over (a, b, c) in z = 0, near its centroid
      const Eigen::Vector3d a = in_plane(-1, -1), b = in_plane(1, -1), c = in_plane(0, 1);
      const Eigen::Vector3d p = in_plane(0, -0.3);
      q.v = {p + up0, a, b, c, p + up1, a, b, c};
    } else {  // edge b (along y, at height z) over edge a (along x)
      const Eigen::Vector3d a0 = in_plane(-1, 0), a1 = in_plane(1, 0);
      const Eigen::Vector3d b0 = in_plane(0, -1), b1 = in_plane(0, 1);
      q.v = {a0, a1, b0 + up0, b1 + up0, a0, a1, b0 + up1, b1 + up1};
    }
    CcdOptions options;
    options.min_separation = delta;
    const std::uint64_t gmp_before = exact::separation::gmp_evaluations_in_this_thread();
    std::uint64_t count = 0;
    const CcdResult res = decide_counting(q, options, &count);
    EXPECT_TRUE(res.collides && res.toi_lo == t_star && res.toi_hi == t_star)
        << describe(res) << ", " << describe(q);
    at_doubles.record(q, res, count,
                      exact::separation::gmp_evaluations_in_this_thread() != gmp_before);
  }
  std::printf("minimum separation at double times: %llu queries within the fixed widths, %llu "
              "with GMP evaluations (%llu of them allocating)\n",
              static_cast<unsigned long long>(at_doubles.fixed),
              static_cast<unsigned long long>(at_doubles.gmp),
              static_cast<unsigned long long>(at_doubles.gmp_allocating));
  for (const auto& o : at_doubles.offenders) ADD_FAILURE() << o;
  EXPECT_GT(at_doubles.fixed, 100u);
}

TEST(Allocation, ExactStagesAtDoubleTimesDoNotAllocateWithinTheFixedWidths) {
  AtDoubleTimes a;
  // The sample queries, also scaled far from unit scale (normalised before the filters).
  for (const DoubleQuery& q : sample_double_queries()) {
    for (int k : {0, 700, -700}) {
      DoubleQuery scaled = q;
      if (!scale_if_exact(&scaled, k)) continue;
      for (const CcdOptions& options : {CcdOptions{}, CcdOptions{0.75, 1e-3, Mode::filtered}})
        decide_at_double_times(scaled, options, &a);
    }
  }
  // Random families: planted and near-degenerate contacts.
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const std::uint64_t n = scaled_count(1500, scale_from_environment());
  for (const Generator& g : all_generators())
    for (std::uint64_t i = 0; i < affordable_count(g, n); ++i)
      decide_at_double_times(generate(g, seed, i), CcdOptions{}, &a);
  std::printf("at double times: %llu queries within the fixed widths, %llu with GMP "
              "computations (%llu of them allocating)\n",
              static_cast<unsigned long long>(a.fixed), static_cast<unsigned long long>(a.gmp),
              static_cast<unsigned long long>(a.gmp_allocating));
  for (const auto& o : a.offenders) ADD_FAILURE() << o;
  EXPECT_GT(a.fixed, 1000u);  // the stages under test are reached
}

TEST(Allocation, GmpComputationsAtDoubleTimesAreSeen) {
  // A query whose integers have about 2,000 bits decided at a double time: its coefficients
  // need GMP, which allocates, and the computation is counted.
  const double big = std::ldexp(1.0, 1000), tiny = std::ldexp(1.0, -1000);
  DoubleQuery q;  // p rests on the triangle's plane z = 0 at t = 0 and leaves it
  q.type = QueryType::vertex_face;
  q.v = {Eigen::Vector3d(tiny, tiny, 0),   Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(big, 0, 0),
         Eigen::Vector3d(0, big, 0),       Eigen::Vector3d(tiny, tiny, big),
         Eigen::Vector3d(0, 0, 0),         Eigen::Vector3d(big, 0, 0), Eigen::Vector3d(0, big, 0)};
  const std::uint64_t gmp_before = exact::gmp_computations_in_this_thread();
  std::uint64_t count = 0;
  const CcdResult r = decide_counting(q, CcdOptions{}, &count);
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.0);
  EXPECT_EQ(r.decided_by, Stage::exact_at_double);
  EXPECT_GT(exact::gmp_computations_in_this_thread(), gmp_before);
  EXPECT_GT(count, 0u);
}

/// The exact stage at double brackets (Mode::exact, and the default path's last stage)
/// allocates nothing for a query it decides without a GMP step (no common factor, square-free
/// part or bracket finer than the doubles, and every width within the fixed ones); its GMP
/// steps are seen allocating.
/// PROOF: proofs/exact_ccd.md#exact-at-double-brackets
TEST(Allocation, ExactStageAtBracketsDoesNotAllocateWithoutGmpSteps) {
  std::uint64_t fixed = 0, gmp = 0, gmp_allocating = 0;
  std::vector<std::string> offenders;
  auto decide = [&](const DoubleQuery& q, CcdOptions options) {
    const std::uint64_t steps = exact::gmp_polynomial_steps_in_this_thread();
    const std::uint64_t integer_gmp = exact::gmp_computations_in_this_thread();
    std::uint64_t count = 0;
    const CcdResult r = decide_counting(q, options, &count);
    if (r.decided_by != Stage::exact) return;
    if (exact::gmp_polynomial_steps_in_this_thread() != steps ||
        exact::gmp_computations_in_this_thread() != integer_gmp) {
      ++gmp;
      gmp_allocating += count > 0;
      return;
    }
    ++fixed;
    if (count > 0 && offenders.size() < 5)
      offenders.push_back(std::to_string(count) + " allocation(s), " + describe(r) + ", " +
                          describe(q));
  };
  CcdOptions exact_mode;
  exact_mode.mode = Mode::exact;
  for (const DoubleQuery& q : sample_double_queries()) {
    decide(q, exact_mode);
    decide(q, CcdOptions{});
  }
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const std::uint64_t n = scaled_count(600, scale_from_environment());
  for (const Generator& g : all_generators())
    for (std::uint64_t i = 0; i < affordable_count(g, n); ++i) {
      const DoubleQuery q = generate(g, seed, i);
      decide(q, exact_mode);
      decide(q, CcdOptions{});
    }
  std::printf("exact stage: %llu decisions without GMP steps, %llu with (%llu allocating)\n",
              static_cast<unsigned long long>(fixed), static_cast<unsigned long long>(gmp),
              static_cast<unsigned long long>(gmp_allocating));
  for (const std::string& o : offenders) ADD_FAILURE() << o;
  EXPECT_GT(fixed, scaled_count(5000));
  EXPECT_GT(gmp_allocating, 0u) << "GMP steps must be seen allocating, or the counter is blind";
}

/// Rigid queries (exactccd/rigid.hpp): those decided by culling, the interval filters (double
/// and extended intervals) and exact signs at doubles (stack dyadics) allocate nothing; the
/// exact path does (GMP rationals). The contact time of a pure rotation is computed with MPFR,
/// which allocates: those queries are counted apart, and must be seen allocating.
/// PROOF: proofs/rigid_ccd.md#filter-tests
TEST(Allocation, RigidFilterStagesAllocateNothing) {
  const std::uint64_t seed = seed_from_environment(kDefaultSeed);
  const std::size_t n = scaled_count(120, scale_from_environment());
  std::uint64_t queries[kStageCount] = {}, allocating[kStageCount] = {}, rotation_times = 0,
                rotation_times_allocating = 0;
  std::vector<std::string> offenders;
  auto turns = [](const SideMotion& m) {
    return m.kind == PathKind::rigid && !m.rigid.cayley.isZero(0);
  };
  auto record = [&](const RigidCcdResult& r, bool rotates, std::uint64_t count,
                    const std::string& what) {
    const int s = static_cast<int>(r.ccd.decided_by);
    if (r.ccd.collides && r.has_time && rotates) {
      ++rotation_times;  // the time of a rotation: MPFR
      rotation_times_allocating += count > 0;
      return;
    }
    ++queries[s];
    allocating[s] += count > 0;
    if (count > 0 && r.ccd.decided_by != Stage::exact && offenders.size() < 5)
      offenders.push_back(std::to_string(count) + " allocation(s), " + what);
  };
  int group = 0;
  for (rigid_queries::OtherMotion other :
       {rigid_queries::OtherMotion::rigid, rigid_queries::OtherMotion::linear,
        rigid_queries::OtherMotion::rest})
    for (bool pure : {false, true}) {
      rigid_queries::RigidQueryOptions o;
      o.other = other;
      o.pure_rotation = pure;
      ++group;
      const auto vf = rigid_queries::random_rigid_vertex_face(seed + group, n, o);
      const auto ee = rigid_queries::random_rigid_edge_edge(seed + group, n, o);
      for (std::size_t i = 0; i < n; ++i) {
        RigidVertexFaceQuery far = vf[i];  // moved away: culled
        far.p += Eigen::Vector3d(0, 0, 100);
        if (far.vertex.kind == PathKind::linear)
          far.vertex.linear_end[0] += Eigen::Vector3d(0, 0, 100);
        else
          far.vertex.rigid.pivot += Eigen::Vector3d(0, 0, 100);
        const RigidVertexFaceQuery* both[2] = {&vf[i], &far};
        for (const RigidVertexFaceQuery* q : both) {
          const std::uint64_t before = g_allocations;
          const RigidCcdResult r = vertex_face_ccd(*q);
          const std::uint64_t count = g_allocations - before;
          record(r, turns(q->vertex) || turns(q->face), count,
                 "vertex-face group " + std::to_string(group) + " " + std::to_string(i));
        }
        const std::uint64_t before = g_allocations;
        const RigidCcdResult r = edge_edge_ccd(ee[i]);
        const std::uint64_t count = g_allocations - before;
        record(r, turns(ee[i].edge_a) || turns(ee[i].edge_b), count,
               "edge-edge group " + std::to_string(group) + " " + std::to_string(i));
      }
    }
  std::printf("rigid queries (%llu with the time of a rotation, MPFR, not counted; %llu of them "
              "allocating):\n",
              static_cast<unsigned long long>(rotation_times),
              static_cast<unsigned long long>(rotation_times_allocating));
  for (Stage s : default_path_stages())
    std::printf("  %-17s %7llu queries, %7llu allocating\n", to_string(s),
                static_cast<unsigned long long>(queries[static_cast<int>(s)]),
                static_cast<unsigned long long>(allocating[static_cast<int>(s)]));
  for (const std::string& o : offenders) ADD_FAILURE() << o;
  for (Stage s : {Stage::culling, Stage::filter, Stage::filter_exact_toi, Stage::exact_at_double})
    EXPECT_EQ(allocating[static_cast<int>(s)], 0u) << to_string(s);
  // The stages under test are reached, and MPFR's allocations are seen (the counter is not
  // blind to the library's).
  EXPECT_GT(queries[static_cast<int>(Stage::culling)], n);
  EXPECT_GT(queries[static_cast<int>(Stage::filter)], n);
  EXPECT_GT(queries[static_cast<int>(Stage::filter_exact_toi)], n / 10);
  EXPECT_GT(rotation_times_allocating, 0u);
}

}  // namespace
}  // namespace exactccd::test
