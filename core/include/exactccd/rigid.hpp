/// \file
/// CCD for rigid bodies that rotate (\ref rigid "rigid-body CCD"): each side of a query moves
/// either with a rational rigid motion of its body or, for a deformable mesh, each vertex on a
/// straight line. Decided exactly, as the linear queries of ccd.hpp are.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "exactccd/export.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// A rigid motion exact over the rationals that passes through both poses (\ref rigid): at the
/// motion parameter s in [0, 1] a point x0 (its position at s = 0) is at
///
///   x(s) = pivot + s translation + C(s cayley) (x0 - pivot),
///   C(v) = ((1 - v.v) I + 2 v v^T + 2 [v]x) / (1 + v.v),
///
/// a rotation about the axis k by 2 atan(s tan(theta/2)) (from 0 to theta) when
/// cayley = tan(theta/2) k, |theta| < pi, composed with a translation of the pivot by
/// s translation. Every field is used exactly as the doubles it holds. cayley = 0 is a pure
/// translation: every point moves on the straight line from x0 to x0 + translation, and the
/// queries give the answers of vertex_face_ccd / edge_edge_ccd on those lines.
struct RigidMotion {
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();        ///< c: the point the rotation fixes
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< d: the pivot moves to c + d
  Eigen::Vector3d cayley = Eigen::Vector3d::Zero();       ///< q = tan(theta / 2) k

  /// The motion that turns by `angle` radians about the line through `pivot` along `axis`,
  /// moving the pivot by `translation`: cayley = tan(angle / 2) axis / |axis|, rounded to
  /// doubles (the motion is then exactly the one those doubles define; its angle may differ
  /// from `angle` by rounding). Throws std::invalid_argument unless |angle| < pi, axis is
  /// non-zero and every input is finite.
  /// \param pivot a point on the rotation axis.
  /// \param axis the axis direction (any non-zero length).
  /// \param angle the total turn in radians, |angle| < pi.
  /// \param translation the pivot's displacement over the motion.
  /// \return the motion.
  EXACTCCD_API static RigidMotion turn(const Eigen::Vector3d& pivot, const Eigen::Vector3d& axis,
                                       double angle,
                                       const Eigen::Vector3d& translation = Eigen::Vector3d::Zero());
};

/// How the vertices of one side of a query move over s in [0, 1].
enum class PathKind : std::uint8_t {
  rigid,   ///< with the side's RigidMotion (a rigid body)
  linear,  ///< each vertex on a straight line to its end position (a deformable mesh)
};

/// The motion of one side of a query: the primitive's rigid body motion, or a straight line per
/// vertex.
struct SideMotion {
  PathKind kind = PathKind::rigid;  ///< which of the two fields below applies
  RigidMotion rigid;                ///< the body's motion, when kind == rigid
  /// When kind == linear: each vertex's position at s = 1, in the side's vertex order
  /// (vertex-face: the vertex uses [0], the face [0], [1], [2]; edge-edge: [0], [1]).
  std::array<Eigen::Vector3d, 3> linear_end{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                            Eigen::Vector3d::Zero()};

  /// A side moved rigidly by `motion`.
  /// \param motion the body's motion.
  /// \return the side motion.
  static SideMotion of(const RigidMotion& motion) {
    SideMotion side;  // linear_end zero (an explicit {} would leave the Eigen vectors unset)
    side.rigid = motion;
    return side;
  }
};

/// Vertex p against the closed triangle (a, b, c), positions at s = 0, each side with its motion.
struct RigidVertexFaceQuery {
  Eigen::Vector3d p;      ///< the vertex at s = 0
  Eigen::Vector3d a;      ///< triangle corner a at s = 0
  Eigen::Vector3d b;      ///< triangle corner b at s = 0
  Eigen::Vector3d c;      ///< triangle corner c at s = 0
  SideMotion vertex;      ///< the vertex's motion
  SideMotion face;        ///< the triangle's motion
};

/// Closed segment [ea0, ea1] against the closed segment [eb0, eb1], positions at s = 0.
struct RigidEdgeEdgeQuery {
  Eigen::Vector3d ea0;  ///< first endpoint of edge a at s = 0
  Eigen::Vector3d ea1;  ///< second endpoint of edge a at s = 0
  Eigen::Vector3d eb0;  ///< first endpoint of edge b at s = 0
  Eigen::Vector3d eb1;  ///< second endpoint of edge b at s = 0
  SideMotion edge_a;    ///< edge a's motion
  SideMotion edge_b;    ///< edge b's motion
};

/// A point of a rigid body against a static plane {x : (x - origin) . normal = 0} (the floor a
/// body falls on): the point is at position_at(motion, p, s) for s in [0, 1].
struct RigidPointPlaneQuery {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();       ///< the point at s = 0
  RigidMotion motion;                                ///< its body's motion
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< a point of the plane
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< the plane's normal (non-zero)

  /// All zero (set the fields before use).
  RigidPointPlaneQuery() = default;
  /// The query {p, motion, origin, normal}. A constructor, not an aggregate: six vectors in
  /// braces, point_plane_ccd({p_t0, ..., normal_t1}), stay the linear PointPlaneQuery.
  /// \param p the point at s = 0.
  /// \param motion its body's motion.
  /// \param origin a point of the plane.
  /// \param normal the plane's normal.
  RigidPointPlaneQuery(const Eigen::Vector3d& p, const RigidMotion& motion,
                       const Eigen::Vector3d& origin, const Eigen::Vector3d& normal)
      : p(p), motion(motion), origin(origin), normal(normal) {}
};

/// The answer to a rigid query: the verdict and the TOI enclosure in the motion parameter s
/// (`ccd`, with options.t_max bounding s), and, when the query's time is defined, the same
/// contact in time.
struct RigidCcdResult {
  /// collides, and toi_lo <= s* <= toi_hi for the exact earliest contact parameter s*.
  CcdResult ccd;
  /// True when every moving side turns about a fixed axis at constant speed with one common
  /// rate, t = atan(s |q|) / atan(|q|) (pure rotations, d = 0, of equal |cayley|; static sides
  /// allowed), or when nothing rotates (t = s). Then time_lo <= t(s*) <= time_hi.
  bool has_time = false;
  double time_lo = kNoContactToi;  ///< lower end of the contact time (see has_time)
  double time_hi = kNoContactToi;  ///< upper end of the contact time (see has_time)
};

/// Vertex-face CCD under rigid (or per-vertex linear) motion, over s in [0, options.t_max].
/// Exact for every finite input: rotation axes through the primitives, zero rotation,
/// coplanar-throughout and degenerate primitives included.
/// \param query finite positions and motions.
/// \param options t_max in [0, 1] (0: the state at t = 0), toi_width finite and >= 0;
///        Mode::filtered (culling and interval filters, then the exact path), Mode::exact, or
///        Mode::float_only (the uncertified double test, for comparison only: the rigid
///        coplanarity polynomial's
///        roots in [0, t_max] found in double arithmetic, the inclusion test at each in doubles;
///        it misses contacts and reports false ones; toi_lo == toi_hi, the root, and
///        decided_by == Stage::float_only); min_separation delta >= 0 (the first s at which the
///        primitives come within Euclidean distance delta, exactly).
/// \return the verdict, the TOI enclosure in s, and in time when defined.
/// \throws std::invalid_argument for non-finite input or options outside their domain.
EXACTCCD_API RigidCcdResult vertex_face_ccd(const RigidVertexFaceQuery& query,
                                            const CcdOptions& options = {});

/// Edge-edge CCD under rigid (or per-vertex linear) motion; as the vertex-face function.
/// \param query finite positions and motions.
/// \param options as for the vertex-face function.
/// \return the verdict, the TOI enclosure in s, and in time when defined.
/// \throws std::invalid_argument as the vertex-face function.
EXACTCCD_API RigidCcdResult edge_edge_ccd(const RigidEdgeEdgeQuery& query,
                                          const CcdOptions& options = {});

/// A point of a rigid body against a static plane, over s in [0, options.t_max]: contact when
/// the point is on the plane; with min_separation delta > 0, when its distance to the plane is
/// at most delta. Exact: the signed offset times the path's denominator 1 + s^2 |q|^2 is a
/// polynomial of degree <= 3 in s (proofs/point_plane.md, the rigid section). Mode::float_only
/// finds that cubic's roots in doubles (uncertified). The time is defined as for the other rigid
/// queries (no rotation, or a pure rotation about a fixed axis).
/// \param query finite values, a non-zero normal.
/// \param options as for the vertex-face function.
/// \return the verdict, the TOI enclosure in s, and in time when defined.
/// \throws std::invalid_argument for non-finite input, a zero normal or options outside their
///         domain.
EXACTCCD_API RigidCcdResult point_plane_ccd(const RigidPointPlaneQuery& query,
                                           const CcdOptions& options = {});

/// The position at parameter s of the point that is at x0 at s = 0, in double arithmetic
/// (for display and for the chord approximation; not certified).
/// \param motion the body's motion.
/// \param x0 the point at s = 0.
/// \param s the parameter.
/// \return x(s), rounded.
EXACTCCD_API Eigen::Vector3d position_at(const RigidMotion& motion, const Eigen::Vector3d& x0,
                                         double s);

}  // namespace exactccd
