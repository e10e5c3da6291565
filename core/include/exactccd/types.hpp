// Public types of exactccd: queries, options and results.
//
// Motion model (the benchmark's, Wang et al. 2021): every vertex moves on a straight line,
// x(t) = (1 - t) x_t0 + t x_t1. A query collides iff the closed primitives (closed triangle,
// closed segments) share a point at some t in the closed interval [0, t_max].
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace exactccd {

enum class QueryType : std::uint8_t { vertex_face, edge_edge };

const char* to_string(QueryType type) noexcept;

/// Vertex p against triangle (a, b, c); fields named as the benchmark's CSV rows.
struct VertexFaceQuery {
  Eigen::Vector3d p_t0, a_t0, b_t0, c_t0;
  Eigen::Vector3d p_t1, a_t1, b_t1, c_t1;
};

/// Edge (ea0, ea1) against edge (eb0, eb1); fields named as the benchmark's CSV rows.
struct EdgeEdgeQuery {
  Eigen::Vector3d ea0_t0, ea1_t0, eb0_t0, eb1_t0;
  Eigen::Vector3d ea0_t1, ea1_t1, eb0_t1, eb1_t1;
};

/// Which path decides a query.
enum class Mode : std::uint8_t {
  /// Certified: culling, then interval filters, then the exact path where they cannot decide.
  /// Always the exact answer. The default.
  filtered,
  /// Uncertified classic cubic test in plain double arithmetic (Provot 1997; Redon et al.
  /// 2002): for comparison and for the speed-versus-error report only. Can miss contacts and
  /// report false ones, and its TOI is a single double (toi_lo == toi_hi) that may be late.
  float_only,
  /// The exact rational decision procedure only (reference oracle).
  exact,
};

const char* to_string(Mode mode) noexcept;

/// The stage that decided a query (for statistics and tests).
enum class Stage : std::uint8_t {
  culling,           ///< disjoint swept bounding boxes (exact comparisons)
  filter,            ///< interval filters decided the verdict and the TOI
  filter_exact_toi,  ///< filters decided the verdict; exact arithmetic tightened the TOI
  exact_at_double,   ///< filters isolated the deciding root; exact integer arithmetic at that
                     ///< double time decided it
  exact,             ///< exact rational arithmetic and exact root isolation (exact/)
  float_only,        ///< the uncertified double-precision test (Mode::float_only)
};

const char* to_string(Stage stage) noexcept;

struct CcdOptions {
  /// End of the time interval [0, t_max]; must lie in (0, 1].
  double t_max = 1.0;
  /// Largest acceptable toi_hi - toi_lo. 0 (the default) asks for the tightest pair of
  /// doubles around the exact first contact time t*: toi_lo == toi_hi == t* when t* is a
  /// double, otherwise the two consecutive doubles that enclose t*. Must be >= 0 and finite.
  double toi_width = 0.0;
  Mode mode = Mode::filtered;
};

struct CcdResult {
  /// True iff the closed primitives meet at some t in [0, t_max].
  bool collides = false;
  /// When collides: toi_lo <= t* <= toi_hi, t* the exact earliest contact time.
  /// toi_lo is the conservative time a simulator advances to. Both are 0 when !collides.
  double toi_lo = 0.0;
  double toi_hi = 0.0;
  Stage decided_by = Stage::exact;
};

}  // namespace exactccd
