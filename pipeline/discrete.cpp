// Discrete collision detection (core/include/exactccd/discrete.hpp): exact triangle-triangle
// tests at instants, and bisection backtracking. PROOF: proofs/discrete.md
#include "exactccd/discrete.hpp"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/fp_environment.hpp"
#include "pipeline/scene/bvh.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exact/reference/triangle_intersection.hpp"

namespace exactccd {

bool operator<(const TrianglePair& a, const TrianglePair& b) {
  return std::tie(a.first_mesh, a.first_triangle, a.second_mesh, a.second_triangle) <
         std::tie(b.first_mesh, b.first_triangle, b.second_mesh, b.second_triangle);
}

namespace {

using scene::Box;
using scene::Bvh;
/// The double nearest to (1 - t) a + t b = a + t (b - a), for 0 <= t <= 1 (ties to even); a at
/// t = 0 and b at t = 1. Needs round-to-nearest. PROOF: proofs/discrete.md#positions
double position_at(double a, double b, double t) {
  if (t == 0.0) return a;
  if (t == 1.0) return b;
  // d = b - a and its rounding error e (TwoSum, exact for doubles below 2^1000 in magnitude:
  // no intermediate overflows). When e == 0, d is b - a exactly and the fused multiply-add
  // rounds a + t d = a + t (b - a) once, to nearest.
  if (std::fabs(a) < 0x1p1000 && std::fabs(b) < 0x1p1000) {
    const double d = b + (-a);
    const double minus_a_virtual = d - b;
    const double b_virtual = d - minus_a_virtual;
    const double e = (b - b_virtual) + (-a - minus_a_virtual);
    if (e == 0.0) return std::fma(t, d, a);
  }
  const exact::Rational ea(a);
  return exact::round_nearest(ea + exact::Rational(t) * (exact::Rational(b) - ea));
}

bool share_vertex(const Triangles& tri, std::uint32_t i, std::uint32_t j) {
  const auto a = static_cast<Eigen::Index>(i), b = static_cast<Eigen::Index>(j);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      if (tri(a, k) == tri(b, l)) return true;
  return false;
}

/// The scene at instants: each mesh's positions at the probed time and a hierarchy over its
/// triangles' boxes at those positions. Static meshes are set up once; moving meshes are
/// recomputed at every probe (their trees refitted, rebuilt when degraded).
class Probe {
 public:
  Probe(const Scene& scene, bool self_collision)
      : scene_(scene), self_(self_collision), meshes_(scene.mesh_count()) {}

  void move_to(double t) {
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      const auto id = static_cast<MeshId>(m);
      MeshAt& mesh = meshes_[m];
      const bool moving = !scene_.is_static(id);
      if (!moving && mesh.built) continue;
      const Positions& start = scene_.start_positions(id);
      const Positions* at = &start;
      if (moving) {
        const Positions& end = scene_.end_positions(id);
        if (t == 1.0) {
          at = &end;
        } else if (t != 0.0) {
          mesh.own.resize(start.rows(), 3);
          tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, start.rows(), 1024),
                            [&](const tbb::blocked_range<Eigen::Index>& r) {
                              // position_at's fast path needs round-to-nearest, whatever
                              // mode the caller (or this worker thread) runs in.
                              const predicates::RoundToNearestGuard nearest;
                              for (Eigen::Index v = r.begin(); v != r.end(); ++v)
                                for (int k = 0; k < 3; ++k)
                                  mesh.own(v, k) = position_at(start(v, k), end(v, k), t);
                            });
          at = &mesh.own;
        }
      }
      mesh.x = at;
      const Triangles& tri = scene_.triangles(id);
      std::vector<Box> boxes(static_cast<std::size_t>(tri.rows()));
      tbb::parallel_for(
          tbb::blocked_range<Eigen::Index>(0, tri.rows(), 4096),
          [&](const tbb::blocked_range<Eigen::Index>& r) {
            const predicates::RoundToNearestGuard nearest;  // comparisons: no denormals-are-zero
            for (Eigen::Index f = r.begin(); f != r.end(); ++f) {
              Box box = scene::point_box(at->row(tri(f, 0)));
              scene::grow(box, at->row(tri(f, 1)));
              scene::grow(box, at->row(tri(f, 2)));
              boxes[static_cast<std::size_t>(f)] = box;
            }
          });
      if (mesh.built) {
        mesh.bvh.refit_or_rebuild(boxes);
      } else {
        mesh.bvh.build(boxes);
        mesh.built = true;
      }
    }
  }

  /// The intersecting pairs at the current positions, sorted; with `first_only`, stops testing
  /// once one is found (then the list holds at least one pair iff any intersects).
  /// PROOF: proofs/discrete.md#pairs
  std::vector<TrianglePair> intersecting(bool first_only) const {
    tbb::enumerable_thread_specific<std::vector<TrianglePair>> found;
    std::atomic<bool> any{false};
    const auto test = [&](MeshId ma, std::uint32_t fa, MeshId mb, std::uint32_t fb) {
      if (first_only && any.load(std::memory_order_relaxed)) return;
      const Positions& xa = *meshes_[ma].x;
      const Positions& xb = *meshes_[mb].x;
      const Triangles& ta = scene_.triangles(ma);
      const Triangles& tb = scene_.triangles(mb);
      const auto vertex = [](const Positions& x, const Triangles& t, std::uint32_t f, int k) {
        return Eigen::Vector3d(x.row(t(static_cast<Eigen::Index>(f), k)).transpose());
      };
      if (exact::triangles_intersect(vertex(xa, ta, fa, 0), vertex(xa, ta, fa, 1),
                                     vertex(xa, ta, fa, 2), vertex(xb, tb, fb, 0),
                                     vertex(xb, tb, fb, 1), vertex(xb, tb, fb, 2))) {
        found.local().push_back({ma, fa, mb, fb});
        any.store(true, std::memory_order_relaxed);
      }
    };
    for (std::size_t a = 0; a < meshes_.size(); ++a) {
      const auto ma = static_cast<MeshId>(a);
      const bool a_static = scene_.is_static(ma);
      if (self_ && !a_static) {
        const Triangles& tri = scene_.triangles(ma);
        meshes_[a].bvh.parallel_for_each_self_overlap([&](std::uint32_t i, std::uint32_t j) {
          if (share_vertex(tri, i, j)) return;
          test(ma, std::min(i, j), ma, std::max(i, j));
        });
      }
      for (std::size_t b = a + 1; b < meshes_.size(); ++b) {
        const auto mb = static_cast<MeshId>(b);
        if (a_static && scene_.is_static(mb)) continue;
        meshes_[a].bvh.parallel_for_each_overlap(
            meshes_[b].bvh, [&](std::uint32_t i, std::uint32_t j) { test(ma, i, mb, j); });
      }
    }
    std::vector<TrianglePair> pairs;
    for (const auto& local : found) pairs.insert(pairs.end(), local.begin(), local.end());
    tbb::parallel_sort(pairs.begin(), pairs.end());
    return pairs;
  }

 private:
  struct MeshAt {
    const Positions* x = nullptr;  ///< the positions at the probed time
    Positions own;                 ///< storage when they are neither the start nor the end
    Bvh bvh;
    bool built = false;
  };

  const Scene& scene_;
  bool self_;
  std::vector<MeshAt> meshes_;
};

}  // namespace

std::vector<TrianglePair> intersecting_triangle_pairs(const Scene& scene, double t,
                                                      bool self_collision) {
  const predicates::RoundToNearestGuard nearest;
  if (!(t >= 0.0 && t <= 1.0))
    throw std::invalid_argument("exactccd: intersecting_triangle_pairs needs 0 <= t <= 1");
  Probe probe(scene, self_collision);
  probe.move_to(t);
  return probe.intersecting(false);
}

DiscreteResult discrete_collision(const Scene& scene, const DiscreteOptions& options) {
  const predicates::RoundToNearestGuard nearest;
  if (options.bisection_steps < 0 || options.bisection_steps > 60)
    throw std::invalid_argument("exactccd: bisection_steps must lie in [0, 60]");
  DiscreteResult result;
  Probe probe(scene, options.self_collision);
  probe.move_to(1.0);
  result.pairs_at_end = probe.intersecting(false);
  if (result.pairs_at_end.empty()) return result;
  result.collides = true;
  // Invariant: the positions at hi intersect; those at lo do not, unless lo == 0 (never probed).
  // PROOF: proofs/discrete.md#bisection
  double lo = 0.0, hi = 1.0;
  for (int step = 0; step < options.bisection_steps; ++step) {
    // lo and hi are multiples of 2^-step; their midpoint is exact unless no double lies strictly
    // between them (possible only from step 53 on), and then bisection is done.
    const double mid = 0.5 * (lo + hi);
    if (!(lo < mid && mid < hi)) break;
    probe.move_to(mid);
    if (probe.intersecting(true).empty())
      lo = mid;
    else
      hi = mid;
  }
  result.toi_lo = lo;
  result.toi_hi = hi;
  return result;
}

}  // namespace exactccd
