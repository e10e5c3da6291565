// The certified path of rigid-body CCD (filters/rigid_filter.cpp): the reduced coplanarity
// polynomial against the determinant on the common denominator (an exact identity, for every
// kind of side) and its interval enclosures; the default path against the exact path, bit for
// bit, on random pairs near contact (every kind of second body, pure rotations, offsets down to
// zero, t_max < 1, coarse TOI widths), on adversarial constructions that touch exactly (at
// s = 1/2, at 0, at t_max, tangentially, on the rotation axis, coplanar throughout) under exact
// rigid transforms, and at extreme magnitudes. The stages reached are counted, so that no check
// passes vacuously. PROOF: proofs/rigid_ccd.md#filter-tests
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/predicates/rigid_coplanarity.hpp"
#include "corpus/rigid_queries.hpp"
#include "exact/reference/rigid_ccd.hpp"
#include "exact/arithmetic/stack_dyadic.hpp"
#include "exactccd/rigid.hpp"
#include "core/predicates/x87_interval.hpp"
#include "core/predicates/interval.hpp"
#include "filters/rigid_filter.hpp"
#include "test_scale.hpp"
#include "test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;
using predicates::Vec3;

CcdOptions with_mode(Mode m, double t_max = 1.0, double toi_width = 0.0) {
  CcdOptions o;
  o.mode = m;
  o.t_max = t_max;
  o.toi_width = toi_width;
  return o;
}

/// Queries decided by each stage of the default path.
struct StageTally {
  int count[6] = {};
  int contacts = 0, queries = 0;
  void add(const CcdResult& r) {
    ++count[static_cast<int>(r.decided_by)];
    contacts += r.collides;
    ++queries;
  }
  int of(Stage s) const { return count[static_cast<int>(s)]; }
  std::string summary() const {
    std::string out;
    for (Stage s : {Stage::culling, Stage::filter, Stage::filter_exact_toi, Stage::exact_at_double,
                    Stage::exact})
      out += std::string(to_string(s)) + " " + std::to_string(of(s)) + ", ";
    return out + std::to_string(contacts) + " contacts of " + std::to_string(queries);
  }
};

// ---------------------------------------------------------------------------------------------
// The reduced polynomial (proofs/rigid_ccd.md#reduced-polynomial)

Vec3<double> vec(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Vec3<mpq_class> rational(const Vec3<double>& v) { return {v.x, v.y, v.z}; }

/// A random query of the given type with each side rigid or linear (any data: the identity
/// holds for all of them); a rigid side sometimes has q = 0 or d = 0.
predicates::DoubleRigidQuery random_query(std::mt19937_64& rng, QueryType type, bool rigid0,
                                       bool rigid1) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto point = [&] { return Vec3<double>{u(rng), u(rng), u(rng)}; };
  predicates::DoubleRigidQuery q;
  q.type = type;
  for (auto& x : q.start) x = point();
  const bool rigid[2] = {rigid0, rigid1};
  for (int k = 0; k < 2; ++k) {
    predicates::DoubleSide& s = q.side[k];
    s.rigid = rigid[k];
    if (s.rigid) {
      s.motion.pivot = point();
      s.motion.translation = rng() % 5 == 0 ? Vec3<double>{0, 0, 0} : point();
      const Vec3<double> c = point();
      const double scale = rng() % 6 == 0 ? 0.0 : std::tan(u(rng) * 1.4);
      s.motion.cayley = {c.x * scale, c.y * scale, c.z * scale};
    }
    for (auto& e : s.end) e = point();
  }
  return q;
}

exact::RationalRigidQuery rational_query(const predicates::DoubleRigidQuery& d) {
  exact::RationalRigidQuery q;
  q.type = d.type;
  for (int i = 0; i < 4; ++i) q.start[i] = rational(d.start[i]);
  for (int k = 0; k < 2; ++k) {
    q.side[k].rigid = d.side[k].rigid;
    q.side[k].motion = {rational(d.side[k].motion.pivot), rational(d.side[k].motion.translation),
                        rational(d.side[k].motion.cayley)};
    for (int i = 0; i < 3; ++i) q.side[k].end[i] = rational(d.side[k].end[i]);
  }
  return q;
}

exact::Polynomial power(const exact::Polynomial& p, int n) {
  exact::Polynomial r(std::vector<mpq_class>{1});
  for (int i = 0; i < n; ++i) r = r * p;
  return r;
}

#if EXACTCCD_X87_INTERVAL
/// A long double as the exact rational it is (64-bit significand).
mpq_class exact_value(long double x) {
  if (x == 0) return 0;
  int e;
  const long double m = std::frexp(std::fabs(x), &e);  // in [1/2, 1)
  const auto integer = static_cast<unsigned long long>(std::ldexp(m, 64));
  mpz_class z;
  mpz_import(z.get_mpz_t(), 1, 1, sizeof integer, 0, 0, &integer);
  mpq_class r(z);
  r *= pow2(e - 64);
  return x < 0 ? mpq_class(-r) : r;
}
#endif

TEST(RigidFilter, ReducedPolynomialTimesTheDenominatorsIsTheDeterminant) {
  std::mt19937_64 rng(test_seed("RigidFilter.ReducedPolynomial"));
  const int per_kind = static_cast<int>(at_least(scaled_count(40), 8));
  int checked = 0, degree_five = 0;
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge})
    for (int kinds = 0; kinds < 4; ++kinds)
      for (int i = 0; i < per_kind; ++i) {
        const predicates::DoubleRigidQuery d = random_query(rng, type, kinds & 1, kinds & 2);
        const exact::RationalRigidQuery q = rational_query(d);
        // The reference: the determinant on the common denominator, as the exact path formed it
        // before the closed form (vertex-face det[b - a, c - a, p - a]; edge-edge
        // det[a1 - a0, b0 - a0, b1 - a0]).
        const auto y = exact::common_denominator_points(q);
        const exact::Polynomial f(type == QueryType::vertex_face
                                      ? predicates::coplanarity_determinant(y[0], y[1], y[2], y[3])
                                      : predicates::coplanarity_determinant(y[3], y[0], y[1], y[2]));
        // The factor w0^2 w1^2 of the rigid sides: positive for every real s.
        exact::Polynomial factor(std::vector<mpq_class>{1});
        for (int k = 0; k < 2; ++k)
          if (q.side[k].rigid)
            factor = factor * power(exact::Polynomial(predicates::rigid_path_denominator(
                                        q.side[k].motion)),
                                    2);
        const exact::Polynomial g = exact::rigid_coplanarity_polynomial(q);
        ASSERT_LE(g.degree(), 5);
        degree_five += g.degree() == 5;
        const exact::Polynomial product = factor * g;
        ASSERT_EQ(product.coefficients(), f.coefficients())
            << to_string(type) << " sides " << kinds << " query " << i;
        std::vector<mpq_class> c = g.coefficients();
        c.resize(6, mpq_class(0));
        {  // The interval instantiation encloses the exact coefficients.
          const predicates::RoundingGuard upward;
          const auto& x = d.start;
          const auto gi =
              type == QueryType::vertex_face
                  ? predicates::vertex_face_rigid_coplanarity<predicates::Interval>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1])
                  : predicates::edge_edge_rigid_coplanarity<predicates::Interval>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1]);
          for (int k = 0; k <= 5; ++k) {
            ASSERT_LE(mpq_class(gi.c[k].inf()), c[k]) << k;
            ASSERT_GE(mpq_class(gi.c[k].sup()), c[k]) << k;
          }
        }
        {  // The exact stack dyadics give the exact coefficients.
          const auto& x = d.start;
          const auto gd =
              type == QueryType::vertex_face
                  ? predicates::vertex_face_rigid_coplanarity<exact::StackDyadic>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1])
                  : predicates::edge_edge_rigid_coplanarity<exact::StackDyadic>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1]);
          for (int k = 0; k <= 5; ++k) {
            ASSERT_FALSE(gd.c[k].overflow()) << k;
            ASSERT_EQ(gd.c[k].to_rational(), c[k]) << k;
          }
        }
#if EXACTCCD_X87_INTERVAL
        {
          const predicates::X87EnvironmentGuard upward(predicates::Rounding::upward);
          const auto& x = d.start;
          const auto ge =
              type == QueryType::vertex_face
                  ? predicates::vertex_face_rigid_coplanarity<predicates::X87Interval>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1])
                  : predicates::edge_edge_rigid_coplanarity<predicates::X87Interval>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1]);
          for (int k = 0; k <= 5; ++k) {
            ASSERT_LE(exact_value(ge.c[k].lo), c[k]) << k;
            ASSERT_GE(exact_value(ge.c[k].hi), c[k]) << k;
          }
        }
#endif
        ++checked;
      }
  EXPECT_EQ(checked, 8 * per_kind);
  EXPECT_GT(degree_five, per_kind);  // generic rigid/rigid and rigid-vertex queries reach 5
}

TEST(RigidFilter, StackDyadicRingOperationsAreExact) {
  std::mt19937_64 rng(test_seed("RigidFilter.StackDyadic"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  int checked = 0, overflows = 0;
  for (int round = 0; round < static_cast<int>(at_least(scaled_count(2000), 200)); ++round) {
    // A random expression tree over random doubles (some subnormal, zero or huge), evaluated
    // in both number types.
    std::vector<exact::StackDyadic> d;
    std::vector<mpq_class> q;
    for (int i = 0; i < 6; ++i) {
      double x = std::ldexp(u(rng), exponent(rng));
      if (rng() % 16 == 0) x = 0;
      if (rng() % 32 == 0) x = std::ldexp(u(rng), rng() % 2 ? -1070 : 1000);
      d.emplace_back(x);
      q.emplace_back(x);
    }
    for (int step = 0; step < 12; ++step) {
      const std::size_t i = rng() % d.size(), j = rng() % d.size();
      switch (rng() % 4) {
        case 0: d.push_back(d[i] + d[j]), q.push_back(q[i] + q[j]); break;
        case 1: d.push_back(d[i] - d[j]), q.push_back(q[i] - q[j]); break;
        case 2: d.push_back(d[i] * d[j]), q.push_back(q[i] * q[j]); break;
        default: d.push_back(-d[i]), q.push_back(-q[i]); break;
      }
    }
    for (std::size_t k = 0; k < d.size(); ++k) {
      if (d[k].overflow()) {
        ++overflows;
        continue;
      }
      ASSERT_EQ(d[k].to_rational(), q[k]) << round << " " << k;
      ASSERT_EQ(d[k].sign(), sgn(q[k])) << round << " " << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
  // Sums of far-apart magnitudes need more limbs than the stack holds: flagged, never wrong.
  EXPECT_GT(overflows, 0);
  const exact::StackDyadic far = exact::StackDyadic(1e300) + exact::StackDyadic(1e-300);
  EXPECT_TRUE(far.overflow());
  EXPECT_TRUE((far * exact::StackDyadic(0.0)).overflow());  // an overflow taints every result
}

// ---------------------------------------------------------------------------------------------
// Random pairs near contact

RigidCcdResult ccd(const RigidVertexFaceQuery& q, const CcdOptions& o) {
  return vertex_face_ccd(q, o);
}
RigidCcdResult ccd(const RigidEdgeEdgeQuery& q, const CcdOptions& o) {
  return edge_edge_ccd(q, o);
}

/// The default path against the exact path on one query: bit for bit at toi_width = 0; with a
/// coarse width, the same verdict and an enclosure of the exact tightest pair no wider than asked
/// (or the tightest pair itself).
template <class Query>
void compare(const Query& q, const CcdOptions& options, StageTally* tally, const std::string& what) {
  CcdOptions exact_options = options;
  exact_options.mode = Mode::exact;
  exact_options.toi_width = 0;
  const CcdResult e = ccd(q, exact_options).ccd;
  CcdOptions filtered_options = options;
  filtered_options.mode = Mode::filtered;
  const CcdResult f = ccd(q, filtered_options).ccd;
  tally->add(f);
  if (options.toi_width == 0) {
    ASSERT_TRUE(same_answer(e, f)) << what << ": exact " << describe_result(e) << ", filtered "
                                   << describe_result(f);
    return;
  }
  ASSERT_EQ(e.collides, f.collides) << what;
  if (!f.collides) return;
  ASSERT_LE(f.toi_lo, e.toi_lo) << what << ": " << describe_result(f);
  ASSERT_GE(f.toi_hi, e.toi_hi) << what << ": " << describe_result(f);
  const bool narrow = mpq_class(f.toi_hi) - mpq_class(f.toi_lo) <= mpq_class(options.toi_width);
  ASSERT_TRUE(narrow || same_answer(e, f)) << what << ": " << describe_result(f);
}

TEST(RigidFilter, FilteredEqualsExactOnRandomPairsNearContact) {
  const std::uint64_t seed = test_seed("RigidFilter.RandomPairs");
  const std::size_t n = at_least(scaled_count(80), 12);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  StageTally tally;
  int configuration = 0;
  for (rigid_queries::OtherMotion other :
       {rigid_queries::OtherMotion::rigid, rigid_queries::OtherMotion::linear,
        rigid_queries::OtherMotion::rest})
    for (bool pure : {false, true})
      for (double offset : {1.0, 0x1p-30, 0.0}) {
        rigid_queries::RigidQueryOptions o;
        o.other = other;
        o.pure_rotation = pure;
        o.offset_scale = offset;
        const std::uint64_t s = seed + static_cast<std::uint64_t>(++configuration);
        const auto vf = rigid_queries::random_rigid_vertex_face(s, n, o);
        const auto ee = rigid_queries::random_rigid_edge_edge(s, n, o);
        for (std::size_t i = 0; i < n; ++i) {
          // One query in four with t_max < 1, one in four with a coarse TOI width.
          CcdOptions options;
          if (i % 4 == 1) options.t_max = 0.25 + 0.75 * u(rng);
          if (i % 4 == 2) options.toi_width = std::ldexp(1.0, -10 - static_cast<int>(rng() % 30));
          const std::string what = "configuration " + std::to_string(configuration) + " query " +
                                   std::to_string(i);
          compare(vf[i], options, &tally, "vertex-face " + what);
          compare(ee[i], options, &tally, "edge-edge " + what);
          if (HasFatalFailure()) return;
        }
      }
  std::printf("random pairs: %s\n", tally.summary().c_str());
  // Most are decided in floating point; exact signs at doubles and the exact path are reached.
  EXPECT_GT(tally.of(Stage::filter), tally.queries / 2);
  EXPECT_GT(tally.of(Stage::filter_exact_toi) + tally.of(Stage::exact_at_double), 0);
  EXPECT_LT(tally.of(Stage::exact), tally.queries / 20);
  EXPECT_GT(tally.contacts, tally.queries / 4);
  EXPECT_LT(tally.contacts, tally.queries);
}

// ---------------------------------------------------------------------------------------------
// Adversarial constructions, under exact rigid transforms of the whole query

/// x -> 2^k M x with M a signed permutation: a rotation's Cayley vector maps to det(M) M q.
struct ExactTransform {
  int order[3];
  double sign[3];
  int k;
  double det() const {
    const int parity = (order[0] > order[1]) + (order[0] > order[2]) + (order[1] > order[2]);
    return (parity % 2 ? -1.0 : 1.0) * sign[0] * sign[1] * sign[2];
  }
  Vector3d linear(const Vector3d& x) const {
    Vector3d y;
    for (int i = 0; i < 3; ++i) y[i] = sign[i] * x[order[i]];
    return y;
  }
  Vector3d point(const Vector3d& x) const { return std::ldexp(1.0, k) * linear(x); }
  SideMotion side(const SideMotion& s) const {
    SideMotion out = s;
    out.rigid.pivot = point(s.rigid.pivot);
    out.rigid.translation = point(s.rigid.translation);
    out.rigid.cayley = det() * linear(s.rigid.cayley);
    for (auto& e : out.linear_end) e = point(e);
    return out;
  }
  RigidVertexFaceQuery operator()(const RigidVertexFaceQuery& q) const {
    return {point(q.p), point(q.a), point(q.b), point(q.c), side(q.vertex), side(q.face)};
  }
  RigidEdgeEdgeQuery operator()(const RigidEdgeEdgeQuery& q) const {
    return {point(q.ea0), point(q.ea1), point(q.eb0), point(q.eb1), side(q.edge_a), side(q.edge_b)};
  }
};

std::vector<ExactTransform> exact_transforms(int count, std::mt19937_64& rng) {
  std::vector<ExactTransform> out = {{{0, 1, 2}, {1, 1, 1}, 0}};
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int scales[4] = {0, -40, 30, -3};
  while (static_cast<int>(out.size()) < count) {
    ExactTransform t;
    const int* o = orders[rng() % 6];
    for (int i = 0; i < 3; ++i) t.order[i] = o[i], t.sign[i] = rng() % 2 ? 1.0 : -1.0;
    t.k = scales[rng() % 4];
    out.push_back(t);
  }
  return out;
}

SideMotion at_rest() { return SideMotion::of(RigidMotion{}); }

SideMotion turning(const Vector3d& cayley, const Vector3d& pivot = Vector3d::Zero(),
                   const Vector3d& translation = Vector3d::Zero()) {
  RigidMotion m;
  m.pivot = pivot;
  m.cayley = cayley;
  m.translation = translation;
  return SideMotion::of(m);
}

/// (5, 0, 0) turned about z by q = (0, 0, 1) is at (3, 4, 0) at s = 1/2 exactly, with y(s)
/// increasing: a wall in the plane y = 4 is first met at s = 1/2.
RigidVertexFaceQuery pythagorean_vertex_face() {
  return {Vector3d(5, 0, 0), Vector3d(2, 4, -1), Vector3d(4, 4, -1), Vector3d(3, 4, 1),
          turning(Vector3d(0, 0, 1)), at_rest()};
}

/// A vertical segment at (5, 0) turned the same way meets the static segment from (2, 4, 0) to
/// (4, 4, 0) at s = 1/2 in (3, 4, 0).
RigidEdgeEdgeQuery pythagorean_edge_edge() {
  return {Vector3d(5, 0, -1), Vector3d(5, 0, 1), Vector3d(2, 4, 0), Vector3d(4, 4, 0),
          turning(Vector3d(0, 0, 1)), at_rest()};
}

struct Expected {
  bool collides;
  double toi;  // toi_lo == toi_hi == toi when it collides (a double)
};

/// Every position-like field times m (pivots, translations, linear ends; the Cayley vectors are
/// angles): a similarity, exact when every product is a double, which the caller ensures. An
/// odd m of 33 bits makes the filters' interval arithmetic round (products of three coordinates
/// need 100 bits), so that a root at a double is no longer seen exactly there.
SideMotion scaled(SideMotion s, double m) {
  s.rigid.pivot *= m;
  s.rigid.translation *= m;
  for (auto& e : s.linear_end) e *= m;
  return s;
}
RigidVertexFaceQuery scaled(const RigidVertexFaceQuery& q, double m) {
  return {q.p * m, q.a * m, q.b * m, q.c * m, scaled(q.vertex, m), scaled(q.face, m)};
}
RigidEdgeEdgeQuery scaled(const RigidEdgeEdgeQuery& q, double m) {
  return {q.ea0 * m, q.ea1 * m, q.eb0 * m, q.eb1 * m, scaled(q.edge_a, m), scaled(q.edge_b, m)};
}

/// Small integers times this stay exact doubles (below 2^40).
constexpr double kManyBits = 4886718345.0;  // 0x123456789

template <class Query>
void check_adversarial(const Query& base, const Expected& expected, const CcdOptions& options,
                       const std::vector<ExactTransform>& transforms, StageTally* tally,
                       const char* name) {
  for (std::size_t k = 0; k < 2 * transforms.size(); ++k) {
    const Query q = k < transforms.size() ? transforms[k](base)
                                          : transforms[k - transforms.size()](
                                                scaled(base, kManyBits));
    const std::string what = std::string(name) + " transform " + std::to_string(k);
    compare(q, options, tally, what);
    const CcdResult f = ccd(q, options).ccd;
    ASSERT_EQ(f.collides, expected.collides) << what;
    if (expected.collides) {
      ASSERT_EQ(f.toi_lo, expected.toi) << what << ": " << describe_result(f);
      ASSERT_EQ(f.toi_hi, expected.toi) << what << ": " << describe_result(f);
    }
  }
}

TEST(RigidFilter, AdversarialTouchingUnderExactTransforms) {
  std::mt19937_64 rng(test_seed("RigidFilter.Adversarial"));
  const auto transforms = exact_transforms(static_cast<int>(at_least(scaled_count(24), 6)), rng);
  StageTally tally;
  const CcdOptions filtered;

  // A root at the double 1/2, its sign zero exactly there (the filter's own brackets cannot show
  // it: exact signs at doubles decide).
  check_adversarial(pythagorean_vertex_face(), {true, 0.5}, filtered, transforms, &tally,
                    "pythagorean vertex-face");
  check_adversarial(pythagorean_edge_edge(), {true, 0.5}, filtered, transforms, &tally,
                    "pythagorean edge-edge");
  // The same contact exactly at t_max, and just out of reach.
  check_adversarial(pythagorean_vertex_face(), {true, 0.5}, with_mode(Mode::filtered, 0.5),
                    transforms, &tally, "pythagorean at t_max");
  check_adversarial(pythagorean_edge_edge(), {false, 0}, with_mode(Mode::filtered, 0.4375),
                    transforms, &tally, "pythagorean before t_max");
  // Touching at s = 0: the vertex in the triangle at the start, turning away.
  {
    RigidVertexFaceQuery q = pythagorean_vertex_face();
    q.p = Vector3d(3, 4, 0);
    check_adversarial(q, {true, 0.0}, filtered, transforms, &tally, "touching at 0");
  }
  // The vertex on its own rotation axis (it stays) and the face translating onto it at 1/2.
  {
    const RigidVertexFaceQuery q{Vector3d(1, 2, 3),
                                 Vector3d(0, 1, 4),
                                 Vector3d(3, 2, 4),
                                 Vector3d(1, 4, 4),
                                 turning(Vector3d(0.25, -0.5, 1), Vector3d(1, 2, 3)),
                                 turning(Vector3d::Zero(), Vector3d::Zero(), Vector3d(0, 0, -2))};
    check_adversarial(q, {true, 0.5}, filtered, transforms, &tally, "vertex on its axis");
  }
  // Coplanar throughout: a triangle in z = 0 turning about z through its corner, a vertex in
  // that plane (g is identically zero: the exact path decides).
  {
    const RigidVertexFaceQuery q{Vector3d(0.6, 0.8, 0), Vector3d(0, 0, 0), Vector3d(2, 0, 0),
                                 Vector3d(2, -1, 0),   at_rest(),         turning(Vector3d(0, 0, 1))};
    for (const ExactTransform& t : transforms) {
      compare(t(q), filtered, &tally, "coplanar");
      compare(t(scaled(q, kManyBits)), filtered, &tally, "coplanar scaled");
    }
  }
  // Tangent: (5, 0, 0) turned by q = (0, 0, 2) reaches angle 90 degrees, the point (0, 5, 0),
  // at s = 1/2, where its circle touches the plane y = 5 (a double root of g): inside the
  // triangle a contact, beside it none.
  {
    RigidVertexFaceQuery q{Vector3d(5, 0, 0), Vector3d(-1, 5, -1), Vector3d(1, 5, -1),
                           Vector3d(0, 5, 1), turning(Vector3d(0, 0, 2)), at_rest()};
    check_adversarial(q, {true, 0.5}, filtered, transforms, &tally, "tangent inside");
    q.a.x() += 3, q.b.x() += 3, q.c.x() += 3;
    check_adversarial(q, {false, 0}, filtered, transforms, &tally, "tangent beside");
  }
  std::printf("adversarial: %s\n", tally.summary().c_str());
  EXPECT_GT(tally.of(Stage::exact_at_double), 0);  // the roots at doubles
  EXPECT_GT(tally.of(Stage::exact), 0);            // coplanar throughout, tangents
}

// ---------------------------------------------------------------------------------------------
// Extreme magnitudes

TEST(RigidFilter, ExtremeMagnitudes) {
  const std::uint64_t seed = test_seed("RigidFilter.Extreme");
  const std::size_t n = at_least(scaled_count(40), 8);
  rigid_queries::RigidQueryOptions o;
  o.other = rigid_queries::OtherMotion::linear;
  const auto vf = rigid_queries::random_rigid_vertex_face(seed, n, o);
  const auto ee = rigid_queries::random_rigid_edge_edge(seed, n);
  StageTally scaled_tally, cayley_tally;
  for (std::size_t i = 0; i < n; ++i) {
    // Coordinates times 2^+-500 (exact): the exact answer is that of the unscaled query.
    const CcdResult e_vf = vertex_face_ccd(vf[i], with_mode(Mode::exact)).ccd;
    const CcdResult e_ee = edge_edge_ccd(ee[i], with_mode(Mode::exact)).ccd;
    for (int k : {500, -500}) {
      const ExactTransform t{{0, 1, 2}, {1, 1, 1}, k};
      const CcdResult f_vf = vertex_face_ccd(t(vf[i])).ccd;
      const CcdResult f_ee = edge_edge_ccd(t(ee[i])).ccd;
      scaled_tally.add(f_vf);
      scaled_tally.add(f_ee);
      ASSERT_TRUE(same_answer(e_vf, f_vf)) << i << " 2^" << k << ": " << describe_result(f_vf);
      ASSERT_TRUE(same_answer(e_ee, f_ee)) << i << " 2^" << k << ": " << describe_result(f_ee);
    }
  }
  // Cayley vectors of 1e-150 (a turn by 2e-150 radians) and 1e150 (a half turn reached at once):
  // both paths on the same doubles (the exact path is slow on the huge ones: fewer of them).
  for (double size : {1e-150, 1e150}) {
    const std::size_t m = size > 1 ? std::max<std::size_t>(n / 4, 2) : n;
    for (std::size_t i = 0; i < m; ++i) {
      RigidVertexFaceQuery q = vf[i];
      q.face.rigid.cayley = q.face.rigid.cayley.normalized() * size;
      compare(q, CcdOptions{}, &cayley_tally, "vertex-face cayley " + std::to_string(i));
      if (i == 0 || size < 1) {
        RigidEdgeEdgeQuery r = ee[i];
        r.edge_a.rigid.cayley = r.edge_a.rigid.cayley.normalized() * size;
        r.edge_b.rigid.cayley = r.edge_b.rigid.cayley.normalized() * (size * 3);
        compare(r, CcdOptions{}, &cayley_tally, "edge-edge cayley " + std::to_string(i));
      }
      if (HasFatalFailure()) return;
    }
  }
  std::printf("scaled by 2^+-500: %s\ncayley 1e-150 and 1e150: %s\n", scaled_tally.summary().c_str(),
              cayley_tally.summary().c_str());
  // Normalised by a power of two, far coordinates are decided as near ones.
  EXPECT_GT(scaled_tally.of(Stage::filter), scaled_tally.queries / 2);
  EXPECT_GT(cayley_tally.contacts, 0);
}

}  // namespace
}  // namespace exactccd::test
