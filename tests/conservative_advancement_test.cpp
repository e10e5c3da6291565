// Conservative advancement in the minimum-separation search (filters/separation_directions.hpp,
// VertexFaceMotion::advance and EdgeEdgeMotion::advance): a piece [lo, end] it returns must be
// never within delta. Checked against the exact path on the same motion restricted to
// [lo, end] (the positions at lo and end as exact rationals, a rational query over that
// piece), on random pairs, on pairs that come within delta at a random time (delta just below
// and just above their distance there; from 0, from a random earlier time and from just before
// it, where the gap left is as small as the rounding errors of the guesses), on sliding pairs
// at distance about delta, these two also moved up to 2^30 times their size away from the
// origin, and on all of these scaled by 2^+-400. It is not vacuous: many calls advance (a
// third of them). PROOF: proofs/min_separation.md#conservative-advancement
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <random>

#include "exactccd/rational_query.hpp"
#include "core/predicates/interval.hpp"
#include "filters/separation_directions.hpp"
#include "test_scale.hpp"

namespace exactccd {
namespace {

using predicates::Interval;
using filters::separation::EdgeEdgeMotion;
using filters::separation::MovingVertex;
using filters::separation::VertexFaceMotion;

struct Pair {
  std::array<Eigen::Vector3d, 4> t0, t1;
};

/// The rational query of the motion restricted to [lo, end], reparameterised to [0, 1].
RationalQuery restricted(const Pair& p, QueryType type, double lo, double end) {
  RationalQuery q;
  q.type = type;
  const mpq_class l(lo), e(end);
  for (int i = 0; i < 4; ++i)
    for (int which = 0; which < 2; ++which) {
      const mpq_class t = which == 0 ? l : e;
      const Eigen::Vector3d& a = p.t0[i];
      const Eigen::Vector3d& b = p.t1[i];
      auto at = [&](int k) {
        mpq_class x = mpq_class(a[k]) + t * (mpq_class(b[k]) - mpq_class(a[k]));
        x.canonicalize();
        return x;
      };
      q.points[4 * which + i] = {at(0), at(1), at(2)};
    }
  return q;
}

template <class Motion>
Motion motion_of(const Pair& p) {
  return Motion{{MovingVertex(p.t0[0], p.t1[0]), MovingVertex(p.t0[1], p.t1[1]),
                 MovingVertex(p.t0[2], p.t1[2]), MovingVertex(p.t0[3], p.t1[3])}};
}

struct Tally {
  long calls = 0, advanced = 0, wrong = 0;
};

/// Advances from lo and checks any piece it claims against the exact path.
template <class Motion>
void check(const Pair& p, QueryType type, double lo, double delta, Tally* tally) {
  double end = lo, estimate = 0;
  {
    const predicates::RoundingGuard upward;
    const Interval delta2 = Interval(delta) * delta;
    end = motion_of<Motion>(p).advance(lo, 1.0, delta2, delta, &estimate);
  }
  ++tally->calls;
  ASSERT_GE(end, lo);
  ASSERT_LE(end, 1.0);
  if (!(end > lo)) return;
  ++tally->advanced;
  const CcdResult exact = exact_ccd(restricted(p, type, lo, end), mpq_class(delta));
  if (exact.collides) {
    ++tally->wrong;
    ADD_FAILURE() << "claimed [" << lo << ", " << end << "] apart, but the exact path finds "
                  << "the pair within " << delta << " at " << exact.toi_lo << " of the piece";
  }
}

Eigen::Vector3d random_point(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return scale * Eigen::Vector3d(u(rng), u(rng), u(rng));
}

/// A pair whose second primitive is the first's mirror moved so that the two meet near time
/// tc: the first primitive's points pass through the second's at tc up to `miss` (so the
/// distance at tc is about |miss|); random shapes, a common drift.
Pair crossing_pair(std::mt19937_64& rng, int first_count, double tc, double miss) {
  Pair p;
  const Eigen::Vector3d drift = random_point(rng, 1.0);
  const Eigen::Vector3d normal = random_point(rng, 1.0).normalized();
  const Eigen::Vector3d speed = normal * (0.5 + std::uniform_real_distribution<double>(0, 1)(rng));
  for (int i = 0; i < 4; ++i) {
    // In the plane through the origin with this normal at tc (the first offset by miss).
    const Eigen::Vector3d at_tc = random_point(rng, 1.0);
    Eigen::Vector3d x = at_tc - normal * normal.dot(at_tc);
    if (i < first_count) x += miss * normal;
    const Eigen::Vector3d v = i < first_count ? Eigen::Vector3d(-speed) : Eigen::Vector3d(speed * 0.25);
    p.t0[i] = x - tc * v + drift;
    p.t1[i] = x + (1 - tc) * v + 1.1 * drift;
  }
  return p;
}

/// Sliding: both primitives translate together along their common plane at distance `gap`.
Pair sliding_pair(std::mt19937_64& rng, int first_count, double gap) {
  Pair p;
  const Eigen::Vector3d slide(0.7, -0.3, 0.0);
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector3d x = random_point(rng, 1.0);
    x[2] = i < first_count ? gap : 0.0;
    p.t0[i] = x;
    p.t1[i] = x + slide + (i < first_count ? Eigen::Vector3d(0.2, 0.1, 0.0) : Eigen::Vector3d::Zero());
  }
  return p;
}

Pair scaled(const Pair& p, int k) {
  Pair s;
  for (int i = 0; i < 4; ++i) {
    s.t0[i] = p.t0[i] * std::ldexp(1.0, k);
    s.t1[i] = p.t1[i] * std::ldexp(1.0, k);
  }
  return s;
}

/// The pair moved far from the origin (each coordinate rounded), so that the rounding errors
/// of the guesses exceed delta: only the certification keeps the claims right.
Pair far(const Pair& p, const Eigen::Vector3d& offset) {
  Pair s;
  for (int i = 0; i < 4; ++i) {
    s.t0[i] = p.t0[i] + offset;
    s.t1[i] = p.t1[i] + offset;
  }
  return s;
}

template <class Motion>
Tally run_family(QueryType type, int first_count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Tally tally;
  const std::uint64_t n = test::scaled_count(300, test::scale_from_environment());
  for (std::uint64_t c = 0; c < n; ++c) {
    const int k = c % 3 == 0 ? 0 : (c % 3 == 1 ? 400 : -400);
    const double unit_scale = std::ldexp(1.0, k);
    // Random pairs, delta up to a tenth of their size.
    {
      const Pair p = scaled(Pair{{random_point(rng, 1), random_point(rng, 1), random_point(rng, 1),
                                  random_point(rng, 1)},
                                 {random_point(rng, 1), random_point(rng, 1), random_point(rng, 1),
                                  random_point(rng, 1)}},
                            k);
      check<Motion>(p, type, 0.0, 0.1 * unit(rng) * unit_scale, &tally);
    }
    // Crossing near tc with a miss of about delta, from 0 and from a time before tc.
    {
      const double tc = 0.1 + 0.8 * unit(rng);
      const double miss = std::ldexp(unit(rng), -static_cast<int>(4 + 40 * unit(rng)));
      const Eigen::Vector3d offset = std::ldexp(1.0, static_cast<int>(30 * unit(rng))) *
                                     random_point(rng, 1.0);
      const Pair p = scaled(far(crossing_pair(rng, first_count, tc, miss), offset), k);
      for (const double factor : {1 - 0x1p-40, 1.0, 1 + 0x1p-40, 0.5, 2.0}) {
        const double delta = miss * factor * unit_scale;
        check<Motion>(p, type, 0.0, delta, &tally);
        check<Motion>(p, type, tc * unit(rng), delta, &tally);
        // Just before tc, where the gap left is as small as the guesses' rounding errors.
        check<Motion>(p, type, tc - std::ldexp(tc, -static_cast<int>(20 + 33 * unit(rng))),
                      delta, &tally);
      }
    }
    // Sliding at distance gap, delta just below and just above it.
    {
      const double gap = std::ldexp(1.0, -static_cast<int>(1 + 30 * unit(rng)));
      const Eigen::Vector3d offset = std::ldexp(1.0, static_cast<int>(30 * unit(rng))) *
                                     random_point(rng, 1.0);
      const Pair p = scaled(far(sliding_pair(rng, first_count, gap), offset), k);
      for (const double factor : {1 - 0x1p-45, 1 + 0x1p-45})
        check<Motion>(p, type, 0.5 * unit(rng), gap * factor * unit_scale, &tally);
    }
  }
  return tally;
}

TEST(ConservativeAdvancement, VertexFaceNeverClaimsAPieceThatComesWithinDelta) {
  const Tally t = run_family<VertexFaceMotion>(QueryType::vertex_face, 1, 12);
  EXPECT_EQ(t.wrong, 0);
  // Not vacuous: many calls advance (the crossings that start well before tc; a third here).
  EXPECT_GT(t.advanced, t.calls / 4) << t.advanced << " of " << t.calls;
}

TEST(ConservativeAdvancement, EdgeEdgeNeverClaimsAPieceThatComesWithinDelta) {
  const Tally t = run_family<EdgeEdgeMotion>(QueryType::edge_edge, 2, 34);
  EXPECT_EQ(t.wrong, 0);
  EXPECT_GT(t.advanced, t.calls / 4) << t.advanced << " of " << t.calls;
}

}  // namespace
}  // namespace exactccd
