/// \file
/// Public types of exactccd: queries, options and results. The collision semantics they follow
/// (motion model, closed primitives, closed interval, TOI enclosure, the no-contact convention)
/// are stated once, on the \ref semantics "main page".
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>

#include "exactccd/export.hpp"

namespace exactccd {

/// The two primitive pairs of the benchmark's files (Wang et al. 2021).
enum class QueryType : std::uint8_t {
  vertex_face,  ///< a vertex against a triangle
  edge_edge,    ///< a segment against a segment
  point_edge,   ///< a point against a segment (scene pairs of edge meshes, point sets, 2D)
  point_point,  ///< a point against a point (scene pairs of point sets)
  point_plane,  ///< a point against a plane (scene pairs with Scene::add_plane)
};

/// The type's name, as the benchmark's folder names. Never throws.
/// \param type a query type.
/// \return "vertex-face", "edge-edge", "point-edge", "point-point" or "point-plane" (a static
///         string).
EXACTCCD_API const char* to_string(QueryType type) noexcept;

/// Vertex p against the closed triangle (a, b, c); fields named as the benchmark's CSV rows.
/// Each vertex moves on a straight line from its `_t0` to its `_t1` position (\ref semantics).
/// Any finite coordinates; a degenerate triangle (a segment, a point) is the point set it is.
struct VertexFaceQuery {
  Eigen::Vector3d p_t0;  ///< the vertex at t = 0
  Eigen::Vector3d a_t0;  ///< triangle corner a at t = 0
  Eigen::Vector3d b_t0;  ///< triangle corner b at t = 0
  Eigen::Vector3d c_t0;  ///< triangle corner c at t = 0
  Eigen::Vector3d p_t1;  ///< the vertex at t = 1
  Eigen::Vector3d a_t1;  ///< triangle corner a at t = 1
  Eigen::Vector3d b_t1;  ///< triangle corner b at t = 1
  Eigen::Vector3d c_t1;  ///< triangle corner c at t = 1
};

/// Closed segment [ea0, ea1] against closed segment [eb0, eb1]; fields named as the
/// benchmark's CSV rows. Any finite coordinates; a zero-length segment is the point it is.
struct EdgeEdgeQuery {
  Eigen::Vector3d ea0_t0;  ///< first endpoint of edge a at t = 0
  Eigen::Vector3d ea1_t0;  ///< second endpoint of edge a at t = 0
  Eigen::Vector3d eb0_t0;  ///< first endpoint of edge b at t = 0
  Eigen::Vector3d eb1_t0;  ///< second endpoint of edge b at t = 0
  Eigen::Vector3d ea0_t1;  ///< first endpoint of edge a at t = 1
  Eigen::Vector3d ea1_t1;  ///< second endpoint of edge a at t = 1
  Eigen::Vector3d eb0_t1;  ///< first endpoint of edge b at t = 1
  Eigen::Vector3d eb1_t1;  ///< second endpoint of edge b at t = 1
};

/// Point p against the closed segment [e0, e1] in 3D (point_edge_ccd). Any finite
/// coordinates; a zero-length segment is the point it is.
struct PointEdgeQuery {
  Eigen::Vector3d p_t0;   ///< the point at t = 0
  Eigen::Vector3d e0_t0;  ///< first endpoint of the segment at t = 0
  Eigen::Vector3d e1_t0;  ///< second endpoint of the segment at t = 0
  Eigen::Vector3d p_t1;   ///< the point at t = 1
  Eigen::Vector3d e0_t1;  ///< first endpoint of the segment at t = 1
  Eigen::Vector3d e1_t1;  ///< second endpoint of the segment at t = 1
};

/// Point p against point q in 3D (point_point_ccd). Any finite coordinates.
struct PointPointQuery {
  Eigen::Vector3d p_t0;  ///< point p at t = 0
  Eigen::Vector3d q_t0;  ///< point q at t = 0
  Eigen::Vector3d p_t1;  ///< point p at t = 1
  Eigen::Vector3d q_t1;  ///< point q at t = 1
};

/// Points p and q in the plane (point_point_ccd_2d). Any finite coordinates.
struct PointPointQuery2d {
  Eigen::Vector2d p_t0;  ///< point p at t = 0
  Eigen::Vector2d q_t0;  ///< point q at t = 0
  Eigen::Vector2d p_t1;  ///< point p at t = 1
  Eigen::Vector2d q_t1;  ///< point q at t = 1
};

/// Point p against the closed segment [e0, e1] in the plane (point_edge_ccd_2d). Any finite
/// coordinates; a zero-length segment is the point it is.
struct PointEdgeQuery2d {
  Eigen::Vector2d p_t0;   ///< the point at t = 0
  Eigen::Vector2d e0_t0;  ///< first endpoint of the segment at t = 0
  Eigen::Vector2d e1_t0;  ///< second endpoint of the segment at t = 0
  Eigen::Vector2d p_t1;   ///< the point at t = 1
  Eigen::Vector2d e0_t1;  ///< first endpoint of the segment at t = 1
  Eigen::Vector2d e1_t1;  ///< second endpoint of the segment at t = 1
};

/// Point p against the plane through `origin` with normal `normal` (not necessarily unit),
/// both of which may move linearly too: the plane at t is {x : (x - origin(t)) . normal(t) = 0}
/// (point_plane_ccd). A static plane repeats origin and normal at t1. Any finite coordinates
/// and a non-zero normal at t = 0 and at t = 1.
struct PointPlaneQuery {
  Eigen::Vector3d p_t0;       ///< the point at t = 0
  Eigen::Vector3d origin_t0;  ///< a point of the plane at t = 0
  Eigen::Vector3d normal_t0;  ///< the plane's normal at t = 0
  Eigen::Vector3d p_t1;       ///< the point at t = 1
  Eigen::Vector3d origin_t1;  ///< a point of the plane at t = 1
  Eigen::Vector3d normal_t1;  ///< the plane's normal at t = 1
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

/// The mode's name, as the command's --mode option spells it. Never throws.
/// \param mode a mode.
/// \return "filtered", "float_only" or "exact" (a static string). Mode::filtered was named
///         "default" before; the command and the Python module still accept that name.
EXACTCCD_API const char* to_string(Mode mode) noexcept;

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

/// The stage's name. Never throws.
/// \param stage a stage.
/// \return its enumerator's name, e.g. "filter_exact_toi" (a static string).
EXACTCCD_API const char* to_string(Stage stage) noexcept;

/// The time of impact of a query without contact: +infinity, so that the minimum of toi_lo over
/// many pairs needs no check of `collides` (\ref no_contact_toi "convention").
inline constexpr double kNoContactToi = std::numeric_limits<double>::infinity();

/// Options of one query's test. Every CCD function throws std::invalid_argument when they lie
/// outside their domain.
struct CcdOptions {
  /// End of the time interval [0, t_max]; must lie in [0, 1]. 0 asks for the state at t = 0
  /// alone: a contact (or within min_separation) there, with TOI [0, 0], or none.
  double t_max = 1.0;
  /// Largest acceptable toi_hi - toi_lo. 0 (the default) asks for the tightest pair of
  /// doubles around the exact first contact time t*: toi_lo == toi_hi == t* when t* is a
  /// double, otherwise the two consecutive doubles that enclose t*. Must be >= 0 and finite.
  double toi_width = 0.0;
  /// The path that decides (Mode::filtered, the certified default, unless comparing methods).
  Mode mode = Mode::filtered;
  /// Minimum separation delta >= 0 (\ref min_separation "minimum-separation CCD"): contact
  /// means the closed primitives come within Euclidean distance delta, and the TOI is the
  /// earliest such time. 0 (the default) is contact itself, decided exactly as without this
  /// field. Must be finite and >= 0. Mode::float_only with delta > 0 runs the common practice
  /// (the float cubic's roots, the distance at each compared with delta): uncertified.
  double min_separation = 0.0;
};

/// The answer to one query (\ref semantics).
struct CcdResult {
  /// True iff the closed primitives meet at some t in [0, t_max].
  bool collides = false;
  /// When collides: 0 <= toi_lo <= t* <= toi_hi, t* the exact earliest contact time.
  /// toi_lo is the conservative time a simulator advances to.
  /// When !collides: +infinity (kNoContactToi).
  double toi_lo = kNoContactToi;
  /// Upper end of the TOI enclosure (see toi_lo); +infinity when !collides.
  double toi_hi = kNoContactToi;
  /// The stage that decided (statistics only: the answer does not depend on it).
  Stage decided_by = Stage::exact;
  /// True iff the primitives already meet (with min_separation > 0: are within it) at t = 0,
  /// i.e. t* = 0: exact in the certified modes, whatever toi_width (a barrier method treats
  /// such a pair as already in contact, not as a contact within the step).
  bool starts_within = false;
};

}  // namespace exactccd
