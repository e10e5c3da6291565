// exact::IntegerQuery::bisect_root (guided probes) against the plain bit-order bisection it
// replaced, written here from its definition: one exact sign (IntegerQuery::cubic_sign_at) at
// the middle double, in bit order, of what is left, until no double is left strictly inside or
// hi - lo <= width exactly. Every bracket meets the contract (f(lo), f(hi) non-zero of
// opposite signs and one root in [lo, hi]), checked with rational arithmetic independently of
// IntegerQuery; the two must return identical pairs for every width, and for width 0 the pair
// is also checked against the root itself (known by construction, or isolated by the exact
// path's Sturm sequences).
#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/predicates/coplanarity_cubic.hpp"
#include "corpus/random_queries.hpp"
#include "exact/stages/integer_query.hpp"
#include "exact/polynomials/root_isolation.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

namespace {

using exact::IntegerQuery;
using exact::Polynomial;
constexpr double kInf = std::numeric_limits<double>::infinity();

double up(double x, int n = 1) {
  for (int i = 0; i < n; ++i) x = std::nextafter(x, kInf);
  return x;
}
double down(double x, int n = 1) {
  for (int i = 0; i < n; ++i) x = std::nextafter(x, -kInf);
  return x;
}

/// The reference: bit-order bisection with one exact sign per step (the pre-guided code).
std::pair<double, double> reference_bisection(const IntegerQuery& q, double lo, double hi,
                                              double width) {
  const int sign_lo = q.cubic_sign_at(lo);
  for (;;) {
    const double first = up(lo), last = down(hi);
    if (first > last) return {lo, hi};
    if (width > 0 && mpq_class(hi) - mpq_class(lo) <= mpq_class(width)) return {lo, hi};
    std::uint64_t a, b;
    std::memcpy(&a, &first, sizeof a);
    std::memcpy(&b, &last, sizeof b);
    const std::uint64_t mid_bits = a + (b - a) / 2;
    double mid;
    std::memcpy(&mid, &mid_bits, sizeof mid);
    const int s = q.cubic_sign_at(mid);
    if (s == 0) return {mid, mid};
    (s == sign_lo ? lo : hi) = mid;
  }
}

/// Widths from below one ulp to above the whole bracket, and ones derived from the bracket.
std::vector<double> widths_for(double lo, double hi) {
  std::vector<double> w = {0.0,  std::numeric_limits<double>::denorm_min(), 0x1p-60, 1e-12,
                           1e-9, 1e-6, 1e-3, 0.1, 0.5, 1.0};
  const double d = hi - lo;
  for (double x : {d, d / 2, d / 3, d / 1000, down(d), up(d)})
    if (x > 0 && std::isfinite(x)) w.push_back(x);
  return w;
}

std::string hexpair(std::pair<double, double> p) {
  return "[" + hex(p.first) + ", " + hex(p.second) + "]";
}

/// bisect_root equals the reference on [lo, hi] for every width; returns the width-0 pair.
std::pair<double, double> expect_same_as_reference(const IntegerQuery& q, double lo, double hi,
                                                   const std::string& where) {
  std::pair<double, double> tight;
  for (const double w : widths_for(lo, hi)) {
    const auto expected = reference_bisection(q, lo, hi, w);
    const auto got = q.bisect_root(lo, hi, w);
    EXPECT_EQ(got, expected) << where << " bracket " << hexpair({lo, hi}) << " width " << hex(w)
                             << ": got " << hexpair(got) << ", reference "
                             << hexpair(expected);
    if (w == 0) tight = got;
  }
  return tight;
}

// ---------------------------------------------------------------------------------------------
// Constructed cubics with known roots.
//
// An edge-edge query whose coplanarity determinant is s (n1 - t d1)(n2 - t d2)(n3 - t d3),
// s > 0, with all coordinates doubles: a0 moves from 0 to (d1, d2, d3); a1 = (n1, a0y, a0z),
// b0 = (a0x, n2, a0z) and b1 = (k, k', n3), where a1, b0 share a0's moving coordinates (same
// start and end). Then a1 - a0 = (n1 - t d1, 0, 0), b0 - a0 = (0, n2 - t d2, 0) and
// b1 - a0 = (., ., n3 - t d3): a triangular matrix, det = product of the diagonal.
struct Factor {
  double num, den;  // the root num / den, den > 0
  mpq_class root() const { return mpq_class(num) / mpq_class(den); }
};

EdgeEdgeQuery product_query(const Factor& f1, const Factor& f2, const Factor& f3) {
  const Eigen::Vector3d a0_t0(0, 0, 0), a0_t1(f1.den, f2.den, f3.den);
  EdgeEdgeQuery q;
  q.ea0_t0 = a0_t0;
  q.ea0_t1 = a0_t1;
  q.ea1_t0 = {f1.num, a0_t0.y(), a0_t0.z()};
  q.ea1_t1 = {f1.num, a0_t1.y(), a0_t1.z()};
  q.eb0_t0 = {a0_t0.x(), f2.num, a0_t0.z()};
  q.eb0_t1 = {a0_t1.x(), f2.num, a0_t1.z()};
  q.eb1_t0 = {0.375, -1.25, f3.num};
  q.eb1_t1 = {-2.5, 0.75, f3.num};
  return q;
}

/// Sign of (n1 - t d1)(n2 - t d2)(n3 - t d3) at t, in rationals.
int product_sign(const Factor (&f)[3], double t) {
  int s = 1;
  for (const Factor& x : f) s *= sgn(mpq_class(x.num) - mpq_class(t) * mpq_class(x.den));
  return s;
}

struct ConstructedCase {
  std::string name;
  Factor factors[3];
  int target;  // which factor's root the brackets isolate
};

/// Brackets [lo, hi] around `root` (double or not) at various distances, clamped at 0, that
/// leave every other distinct root outside and satisfy the contract.
std::vector<std::pair<double, double>> brackets_around(const ConstructedCase& c,
                                                       const IntegerQuery& q) {
  const mpq_class root = c.factors[c.target].root();
  const double below = exact::round_down(root), above = exact::round_up(root);
  std::vector<std::pair<double, double>> candidates;
  for (int k_lo : {1, 2, 3, 17, 1000})
    for (int k_hi : {1, 2, 5, 64}) candidates.push_back({down(below, k_lo), up(above, k_hi)});
  if (below != above) candidates.push_back({below, above});  // already tight
  for (double d : {1e-300, 1e-30, 1e-12, 1e-6, 1e-3, 0.25})
    for (double e : {1e-15, 1e-9, 1e-6, 1e-3}) candidates.push_back({below - d, above + e});
  candidates.push_back({0.0, above + 1e-6});
  candidates.push_back({0.0, up(above)});
  candidates.push_back({0.0, 1.0});
  std::vector<std::pair<double, double>> out;
  for (auto [lo, hi] : candidates) {
    lo = std::max(lo, 0.0);
    if (!(lo < hi) || !(mpq_class(lo) < root && root < mpq_class(hi))) continue;
    bool alone = true;
    for (int i = 0; i < 3; ++i) {
      const mpq_class other = c.factors[i].root();
      if (other != root && mpq_class(lo) <= other && other <= mpq_class(hi)) alone = false;
    }
    const Factor(&f)[3] = c.factors;
    const int s_lo = product_sign(f, lo), s_hi = product_sign(f, hi);
    if (!alone || s_lo == 0 || s_hi != -s_lo) continue;
    // The query's cubic is this product times a positive constant (construction check).
    EXPECT_EQ(q.cubic_sign_at(lo), s_lo) << c.name;
    EXPECT_EQ(q.cubic_sign_at(hi), s_hi) << c.name;
    out.push_back({lo, hi});
  }
  return out;
}

/// For width 0 the pair must be [root, root] for a double root, else the two consecutive
/// doubles around it; checked against the known rational root.
void expect_tightest_around(std::pair<double, double> got, const mpq_class& root,
                            const std::string& where) {
  double as_double;
  if (exact::to_double_exactly(root, &as_double)) {
    EXPECT_EQ(got.first, as_double) << where;
    EXPECT_EQ(got.second, as_double) << where;
  } else {
    EXPECT_EQ(up(got.first), got.second) << where << ": not consecutive " << hexpair(got);
    EXPECT_LT(mpq_class(got.first), root) << where;
    EXPECT_LT(root, mpq_class(got.second)) << where;
  }
}

void run_constructed(const std::vector<ConstructedCase>& cases, std::size_t min_brackets) {
  std::size_t brackets = 0;
  for (const ConstructedCase& c : cases) {
    const IntegerQuery q(product_query(c.factors[0], c.factors[1], c.factors[2]));
    const auto list = brackets_around(c, q);
    EXPECT_FALSE(list.empty()) << c.name << ": no bracket meets the contract";
    for (const auto& [lo, hi] : list) {
      const std::string where = c.name + " " + hexpair({lo, hi});
      const auto tight = expect_same_as_reference(q, lo, hi, where);
      expect_tightest_around(tight, c.factors[c.target].root(), where);
      ++brackets;
    }
  }
  EXPECT_GE(brackets, min_brackets);
}

TEST(BisectRoot, RootsThatAreDoubles) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double min_normal = std::numeric_limits<double>::min();
  std::vector<ConstructedCase> cases;
  // Roots n / 2^k (dyadic, exact doubles) with the other roots far away; scales 2^k of the
  // factors move the integer coefficients' sizes.
  for (double r : {0.5, 0.25, 0.75, 0.375, 0x1p-20, 0x1.8p-40, 1.0 - 0x1p-53, 1.0, 0.1, 1.0 / 3,
                   0.9999999, 1e-300, min_normal, down(min_normal), 3 * tiny, tiny})
    for (double scale : {1.0, 0x1p-500, 0x1p300}) {
      if (mpq_class(r * scale) != mpq_class(r) * mpq_class(scale)) continue;  // underflow
      cases.push_back({"double root " + hex(r) + " scale " + hex(scale),
                       {{r * scale, scale}, {-1.0, 1.0}, {7.0, 2.0}},
                       0});
      cases.push_back({"double root " + hex(r) + ", other roots close",
                       {{2.0, 3.0}, {r * scale, scale}, {up(r, 3), 1.0}},
                       1});
    }
  run_constructed(cases, 500);
}

TEST(BisectRoot, RootsBetweenDoubles) {
  std::vector<ConstructedCase> cases;
  std::mt19937_64 rng(20240617);
  std::uniform_int_distribution<std::int64_t> numerator(1, (std::int64_t{1} << 53) - 1);
  // Random rationals p / q in (0, 1).
  for (int i = 0; i < 40; ++i) {
    double p = static_cast<double>(numerator(rng)), q = static_cast<double>(numerator(rng));
    if (p > q) std::swap(p, q);
    if (p == q) continue;
    cases.push_back({"random p/q #" + std::to_string(i), {{p, q}, {-3.0, 1.0}, {2.0, 1.0}}, 0});
  }
  // Near 0 (subnormal and normal), near 1, and thirds at several exponents.
  for (int e : {0, -1, -30, -300, -1000, -1022, -1050, -1073})
    cases.push_back({"1/3 * 2^" + std::to_string(e), {{std::ldexp(1.0, e), 3.0}, {5.0, 1.0},
                                                      {-1.0, 4.0}}, 0});
  cases.push_back({"1 - 1/(3 2^51)", {{0x3p51 - 1, 0x3p51}, {2.0, 1.0}, {-1.0, 1.0}}, 0});
  cases.push_back({"2/3 with 1/3 and 5/6 near", {{1.0, 3.0}, {2.0, 3.0}, {5.0, 6.0}}, 1});
  // The example of proofs/exact_ccd.md (width test): a root in (2^-54, 1/2 + 2^-53).
  cases.push_back({"width example", {{1.0, 5.0}, {-1.0, 1.0}, {4.0, 1.0}}, 0});
  run_constructed(cases, 300);

  // That bracket and width 1/2: hi - lo = 1/2 + 2^-54 rounds to 1/2 but exceeds it.
  const Factor f[3] = {{1.0, 5.0}, {-1.0, 1.0}, {4.0, 1.0}};
  const IntegerQuery q(product_query(f[0], f[1], f[2]));
  const double lo = 0x1p-54, hi = 0.5 + 0x1p-53;
  EXPECT_EQ(q.bisect_root(lo, hi, 0.5), reference_bisection(q, lo, hi, 0.5));
  EXPECT_NE(q.bisect_root(lo, hi, 0.5), std::make_pair(lo, hi));  // not already met
}

TEST(BisectRoot, RootsNextToDoubleAndTripleRoots) {
  std::vector<ConstructedCase> cases;
  // f = (t - a)^2 (t - b) with b within a few ulps to 1e-3 of the double root a: f' is small
  // near b and Newton's method on the rounded cubic is poor.
  for (double a : {0.5, 0.3, 1.0 / 3, 1e-200})
    for (double gap : {0x1p-50, 0x1p-45, 1e-12, 1e-9, 1e-6, 1e-3}) {
      const double b = a * (1 + gap);
      cases.push_back({"double root " + hex(a) + ", simple root " + hex(b),
                       {{a, 1.0}, {a, 1.0}, {b, 1.0}}, 2});
      cases.push_back({"double root " + hex(a) + ", simple root " + hex(b) + " / 3",
                       {{a, 1.0}, {a, 1.0}, {b, 3.0}}, 2});
      const double c = a * (1 - gap);
      cases.push_back({"double root " + hex(a) + ", simple root below " + hex(c),
                       {{a, 1.0}, {a, 1.0}, {c, 1.0}}, 2});
    }
  // f = (t - a)^3: not simple, but f still has one sign below a and the other above it, which
  // is all the replay relies on (Newton converges only linearly here).
  for (double a : {0.5, 0.1, 1.0 / 3, 1e-200})
    cases.push_back({"triple root " + hex(a), {{a, 1.0}, {a, 1.0}, {a, 1.0}}, 0});
  cases.push_back({"triple root 2/3", {{2.0, 3.0}, {2.0, 3.0}, {2.0, 3.0}}, 0});
  run_constructed(cases, 300);
}

TEST(BisectRoot, BracketsWithoutRoomAreReturnedAsGiven) {
  // No double strictly inside: the reference loop returns the bracket without evaluating.
  const Factor f[3] = {{1.0, 3.0}, {-1.0, 1.0}, {4.0, 1.0}};
  const IntegerQuery q(product_query(f[0], f[1], f[2]));
  const double lo = exact::round_down(mpq_class(1, 3)), hi = up(lo);
  EXPECT_EQ(q.bisect_root(lo, hi, 0.0), std::make_pair(lo, hi));
  EXPECT_EQ(q.bisect_root(lo, hi, 1.0), std::make_pair(lo, hi));
  // One double inside, not the root: the bracket shrinks to one side of it.
  EXPECT_EQ(q.bisect_root(lo, up(hi), 0.0), reference_bisection(q, lo, up(hi), 0.0));
  EXPECT_EQ(q.bisect_root(down(lo), hi, 0.0), reference_bisection(q, down(lo), hi, 0.0));
  // Width already met: returned as given.
  EXPECT_EQ(q.bisect_root(0.25, 0.5, 0.25), std::make_pair(0.25, 0.5));
}

// ---------------------------------------------------------------------------------------------
// Random queries: the roots in [0, 1] of the rational cubic, isolated by the exact path.

Polynomial rational_cubic(const DoubleQuery& dq) {
  const RationalQuery rq = dq.type == QueryType::vertex_face ? to_rational(dq.vertex_face())
                                                             : to_rational(dq.edge_edge());
  auto mv = [&](int k) {
    const auto& a = rq.points[k];
    const auto& b = rq.points[k + 4];
    return predicates::linear_motion(predicates::Vec3<mpq_class>{a.x, a.y, a.z},
                                     predicates::Vec3<mpq_class>{b.x, b.y, b.z});
  };
  return Polynomial(dq.type == QueryType::vertex_face
                        ? predicates::vertex_face_coplanarity_cubic(mv(0), mv(1), mv(2), mv(3))
                        : predicates::edge_edge_coplanarity_cubic(mv(0), mv(1), mv(2), mv(3)));
}

TEST(BisectRoot, MatchesReferenceOnRandomQueries) {
  const std::uint64_t seed = seed_from_environment(20240617);
  std::mt19937_64 pick(seed);
  std::size_t brackets = 0, roots = 0;
  for (const Generator& g : all_generators()) {
    std::size_t roots_of_generator = 0;
    for (std::uint64_t i = 0; i < affordable_count(g, 60); ++i) {
      const DoubleQuery dq = generate(g, seed, i);
      const Polynomial f = rational_cubic(dq);
      if (f.is_zero()) continue;
      const IntegerQuery q = dq.type == QueryType::vertex_face ? IntegerQuery(dq.vertex_face())
                                                               : IntegerQuery(dq.edge_edge());
      const exact::SturmSequence sturm(exact::square_free_part(f));
      for (exact::AlgebraicTime& root : exact::real_roots_in(f, 0, 1)) {
        const auto [L, H] = root.enclosure(0.0);  // the exact path's tightest pair
        ++roots;
        ++roots_of_generator;
        const double offsets[] = {0.0, 0x1p-1074, 1e-300, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 0.1};
        std::uniform_int_distribution<int> which(0, static_cast<int>(std::size(offsets)) - 1);
        std::uniform_int_distribution<int> ulps(1, 40);
        for (int trial = 0; trial < 6; ++trial) {
          double lo = trial == 0 ? down(L, ulps(pick)) : L - offsets[which(pick)];
          double hi = trial == 0 ? up(H, ulps(pick)) : H + offsets[which(pick)];
          if (L == H) lo = std::min(lo, down(L)), hi = std::max(hi, up(H));
          lo = std::max(lo, 0.0);
          if (!(lo < hi)) continue;
          // The contract, in rationals: opposite non-zero signs and one distinct root.
          const int s_lo = f.sign_at(lo), s_hi = f.sign_at(hi);
          if (s_lo == 0 || s_hi != -s_lo || sturm.count_roots(lo, hi) != 1) continue;
          const std::string where = g.name() + " #" + std::to_string(i) + describe(dq);
          const auto tight = expect_same_as_reference(q, lo, hi, where);
          EXPECT_EQ(tight, std::make_pair(L, H)) << where;
          ++brackets;
        }
      }
    }
    RecordProperty(g.name(), static_cast<int>(roots_of_generator));
  }
  std::cout << "[ stats    ] " << roots << " roots, " << brackets << " brackets\n";
  EXPECT_GE(brackets, 500u);
}

// The filter calls bisect_root under upward rounding: the guidance's floating point changes
// with the mode, the result must not.
TEST(BisectRoot, IndependentOfRoundingMode) {
  std::vector<ConstructedCase> cases;
  for (double r : {1.0 / 3, 0.1, 1e-300, 0.5})
    cases.push_back({"root " + hex(r), {{r, 1.0}, {-1.0, 1.0}, {2.0, 1.0}}, 0});
  cases.push_back({"2/3", {{2.0, 3.0}, {0.5, 1.0}, {5.0, 6.0}}, 0});
  cases.push_back({"next to a double root", {{0.5, 1.0}, {0.5, 1.0}, {0.5 + 1e-9, 1.0}}, 2});
  std::size_t compared = 0;
  for (const ConstructedCase& c : cases) {
    const IntegerQuery q(product_query(c.factors[0], c.factors[1], c.factors[2]));
    for (const auto& [lo, hi] : brackets_around(c, q))
      for (const double w : widths_for(lo, hi)) {
        const auto nearest = q.bisect_root(lo, hi, w);
        for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
          ASSERT_EQ(std::fesetround(mode), 0);
          const auto got = q.bisect_root(lo, hi, w);
          std::fesetround(FE_TONEAREST);
          EXPECT_EQ(got, nearest) << c.name << " " << hexpair({lo, hi}) << " width " << hex(w)
                                  << " mode " << mode;
          ++compared;
        }
      }
  }
  EXPECT_GE(compared, 1000u);
}

}  // namespace
}  // namespace exactccd::test
