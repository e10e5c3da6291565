// The reduced coplanarity polynomial of rigid-body CCD against the determinant on the common
// denominator (an exact identity, for every kind of side) and its interval enclosures.
// PROOF: proofs/rigid_ccd.md#reduced-polynomial
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/predicates/rigid_coplanarity.hpp"
#include "corpus/rigid_queries.hpp"
#include "exact/rigid_ccd.hpp"
#include "exactccd/rigid.hpp"
#include "filters/interval.hpp"
#include "filters/rigid_filter.hpp"
#include "test_scale.hpp"
#include "test_support.hpp"

namespace exactccd::test {
namespace {

using Eigen::Vector3d;
using predicates::Vec3;

std::string describe_result(const CcdResult& r) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "collides %d [%a, %a] by %s", r.collides ? 1 : 0, r.toi_lo,
                r.toi_hi, to_string(r.decided_by));
  return buffer;
}

bool same_answer(const CcdResult& a, const CcdResult& b) {
  return a.collides == b.collides && a.toi_lo == b.toi_lo && a.toi_hi == b.toi_hi;
}

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
filters::DoubleRigidQuery random_query(std::mt19937_64& rng, QueryType type, bool rigid0,
                                       bool rigid1) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto point = [&] { return Vec3<double>{u(rng), u(rng), u(rng)}; };
  filters::DoubleRigidQuery q;
  q.type = type;
  for (auto& x : q.start) x = point();
  const bool rigid[2] = {rigid0, rigid1};
  for (int k = 0; k < 2; ++k) {
    filters::DoubleSide& s = q.side[k];
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

exact::RationalRigidQuery rational_query(const filters::DoubleRigidQuery& d) {
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


TEST(RigidFilter, ReducedPolynomialTimesTheDenominatorsIsTheDeterminant) {
  std::mt19937_64 rng(test_seed("RigidFilter.ReducedPolynomial"));
  const int per_kind = static_cast<int>(at_least(scaled_count(40), 8));
  int checked = 0, degree_five = 0;
  for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge})
    for (int kinds = 0; kinds < 4; ++kinds)
      for (int i = 0; i < per_kind; ++i) {
        const filters::DoubleRigidQuery d = random_query(rng, type, kinds & 1, kinds & 2);
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
          const filters::RoundingGuard upward;
          const auto& x = d.start;
          const auto gi =
              type == QueryType::vertex_face
                  ? predicates::vertex_face_rigid_coplanarity<filters::Interval>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1])
                  : predicates::edge_edge_rigid_coplanarity<filters::Interval>(
                        x[0], x[1], x[2], x[3], d.side[0], d.side[1]);
          for (int k = 0; k <= 5; ++k) {
            ASSERT_LE(mpq_class(gi.c[k].inf()), c[k]) << k;
            ASSERT_GE(mpq_class(gi.c[k].sup()), c[k]) << k;
          }
        }
        ++checked;
      }
  EXPECT_EQ(checked, 8 * per_kind);
  EXPECT_GT(degree_five, per_kind);  // generic rigid/rigid and rigid-vertex queries reach 5
}

}  // namespace
}  // namespace exactccd::test
