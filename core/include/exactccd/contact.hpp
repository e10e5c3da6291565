/// \file
/// Where and which way: the contact geometry of a colliding query at its exact earliest contact
/// time t*, as certified enclosures (\ref contact_geometry "contact geometry").
///
/// A simulator that finds a contact must respond to it, and the configuration is at its most
/// degenerate exactly there (the distance is zero), so recomputing the contact point and normal
/// in plain doubles at toi_lo loses the guarantee at the last step. contact_geometry() encloses
/// them instead, by interval arithmetic with directed rounding over the certified enclosure
/// [toi_lo, toi_hi] of t*: every interval contains the true value at t*.
#pragma once

#include <array>
#include <cstdint>

#include "exactccd/export.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// A closed interval [lo, hi] of doubles that contains a real number.
struct Enclosure {
  double lo = 0.0;  ///< lower end
  double hi = 0.0;  ///< upper end
};

/// What the enclosures of a ContactGeometry say.
enum class ContactKind : std::uint8_t {
  /// The contact set at t* is one point, whose parameters are unique; every enclosure is certified
  /// and the normal is oriented as documented (ContactGeometry::normal).
  point,
  /// The primitives already touch at t = 0 (t* = 0): "just before t*" does not exist, so the
  /// normal is not oriented by the approach; the parameters and the point are as for `point`,
  /// and the normal is the unoriented direction (ContactGeometry::normal).
  at_start,
  /// The enclosures over [toi_lo, toi_hi] do not separate the configuration from a degenerate
  /// one, and it is not one of the degenerate kinds below (a triangle nearly degenerate at t*,
  /// nearly parallel edges, a tangential approach whose side is not certain, a point against
  /// a segment in 3D, whose normal the rules leave undefined). Every enclosure is still
  /// certified, but parameters may be the whole [0, 1] and the normal the whole [-1, 1]^3;
  /// normal_oriented says which.
  unresolved,
  /// Vertex-face: the triangle is degenerate (its normal (b - a) x (c - a) is zero) at every
  /// t, exactly: the barycentric coordinates are not unique ([0, 1] each), the normal is
  /// [-1, 1]^3; the point is the vertex.
  degenerate_triangle,
  /// Edge-edge: the edges are parallel ((ea1 - ea0) x (eb1 - eb0) = 0) at every t, exactly:
  /// the contact set may be a segment; the parameters are [0, 1], the normal [-1, 1]^3, and
  /// `point` a box that holds the whole contact set.
  parallel_edges,
  /// The four points are coplanar at every t, exactly (a vertex sliding in the triangle's
  /// plane, edges moving in one plane): there is no side to come from; the parameters are as
  /// for `point` where resolved, and the normal, where certified, the unoriented direction.
  coplanar,
};

/// The kind's name: "point", "at_start", "unresolved", "degenerate_triangle",
/// "parallel_edges" or "coplanar" (a static string). Never throws.
/// \param kind a contact kind.
/// \return its name.
EXACTCCD_API const char* to_string(ContactKind kind) noexcept;

/// The contact geometry of a colliding query at t*, every field a certified enclosure.
struct ContactGeometry {
  /// See ContactKind.
  ContactKind kind = ContactKind::unresolved;
  /// Vertex-face: the barycentric coordinates of the contact point with respect to (a, b, c)
  /// (3 of them, each in [0, 1]). Edge-edge: the parameter on edge a (0 at ea0, 1 at ea1), then
  /// on edge b (0 at eb0); a zero-length edge (a point) has parameter [0, 0].
  std::array<Enclosure, 3> parameters{};
  /// How many of `parameters` are used: 3 (vertex-face) or 2 (edge-edge).
  int parameter_count = 0;
  /// The contact point in space at t* (vertex-face: the vertex; edge-edge: the point where the
  /// edges meet).
  std::array<Enclosure, 3> point{};
  /// The unit contact normal, pointing from the face (edge b) towards the vertex (edge a) just
  /// before t*: vertex-face the triangle's normal at t*, edge-edge the normalised cross product
  /// of the edges at t*, each oriented towards the side the vertex (edge a) came from; a point
  /// against a point: the direction from q to p just before t* (minus their relative velocity);
  /// a point against a segment in the plane z = 0: the in-plane perpendicular of the segment,
  /// towards the side the point came from. When !normal_oriented it is the unoriented
  /// direction (vertex-face: along (b - a) x (c - a), edge-edge: along (ea1 - ea0) x
  /// (eb1 - eb0)) if that is certified, else [-1, 1]^3.
  std::array<Enclosure, 3> normal{{{-1.0, 1.0}, {-1.0, 1.0}, {-1.0, 1.0}}};
  /// True when `normal` is the oriented normal described above.
  bool normal_oriented = false;
};

/// The contact geometry of vertex p against the triangle (a, b, c) at the exact earliest
/// contact time t* that `result` encloses (\ref contact_geometry).
/// With min_separation delta > 0 (the delta `result` was decided with) it encloses the closest
/// points at t*, where the distance is delta: `parameters` the barycentric coordinates of the
/// closest point on the triangle, `point` that point, `normal` the unit direction from it
/// towards the vertex (inside the triangle: its normal towards the vertex's side); resolved
/// (`point`) when the closest point's region (inside, on a side, at a corner) is certain over
/// the TOI enclosure, otherwise `unresolved`.
/// \param query the query that was decided.
/// \param result its certified answer (vertex_face_ccd, any toi_width).
/// \param min_separation the delta of that answer (0: contact).
/// \return the enclosures at t*.
/// \throws std::invalid_argument for a non-finite coordinate, a negative or non-finite delta,
///         or when `result` does not collide or its enclosure is not in [0, 1].
EXACTCCD_API ContactGeometry contact_geometry(const VertexFaceQuery& query,
                                              const CcdResult& result,
                                              double min_separation = 0.0);

/// The contact geometry of the segments [ea0, ea1] and [eb0, eb1] at t* (zero-length segments
/// are points: point-edge and point-point contact); as for vertex-face.
/// With min_separation delta > 0: the closest points' parameters on each edge, `point` the
/// closest point on edge b, `normal` the unit direction from it towards edge a (along the edges'
/// cross product when both are inside their edges); resolved when the closest pair (inside both,
/// an end against an edge, two ends, a point against a segment or a point) is certain over the
/// TOI enclosure; `parallel_edges` for edges parallel at every t (closest points not unique,
/// the trivial enclosures), otherwise `unresolved`.
/// \param query the query that was decided.
/// \param result its certified answer (edge_edge_ccd, point_edge_ccd, point_point_ccd or their 2D
///        forms embedded in z = 0).
/// \param min_separation the delta of that answer (0: contact).
/// \return the enclosures at t*.
/// \throws std::invalid_argument as for vertex-face.
EXACTCCD_API ContactGeometry contact_geometry(const EdgeEdgeQuery& query,
                                              const CcdResult& result,
                                              double min_separation = 0.0);

/// The contact geometry of a point against a plane at t* (point_plane_ccd): no parameters
/// (parameter_count 0); `point` the point at t* (with min_separation delta > 0: its closest
/// point on the plane); `normal` the plane's unit normal at t*, pointing towards the side the
/// point came from (the sign of (p - origin) . normal at t = 0, exact: the point is off the
/// plane, or more than delta from it, on all of [0, t*)). Kind `point`; `at_start` when
/// t* = 0 (the unoriented normal along `normal`); `unresolved` when the normal's length is not
/// certainly positive over the enclosure (a turning normal through zero). No scaling: extreme
/// magnitudes may leave enclosures wide.
/// \param query the query that was decided.
/// \param result its certified answer (point_plane_ccd).
/// \param min_separation the delta of that answer (0: contact).
/// \return the enclosures at t*.
/// \throws std::invalid_argument for a non-finite coordinate, a negative or non-finite delta, or
///         when `result` does not collide or its enclosure is not in [0, 1].
EXACTCCD_API ContactGeometry contact_geometry(const PointPlaneQuery& query,
                                              const CcdResult& result,
                                              double min_separation = 0.0);

/// The contact geometry of a rigid body's point against a static plane at s* (as for the linear
/// point-plane query, with the point on its rigid path).
/// \param query the rigid query that was decided.
/// \param result its certified answer (point_plane_ccd of the rigid query).
/// \param min_separation the delta of that answer (0: contact).
/// \return the enclosures at s*.
/// \throws std::invalid_argument as for the linear point-plane query.
EXACTCCD_API ContactGeometry contact_geometry(const RigidPointPlaneQuery& query,
                                              const RigidCcdResult& result,
                                              double min_separation = 0.0);

/// The contact geometry of a rigid vertex-face query at the exact earliest contact parameter s*
/// that `result` encloses (in s, result.ccd): as for linear motion, with the positions of the
/// rigid motion (or a side's straight lines) at s*; the normal points to the side the vertex
/// came from just before s*. No scaling: extreme magnitudes may leave it `unresolved`.
/// With min_separation delta > 0: the closest points at s*, as for linear motion.
/// \param query the rigid query that was decided.
/// \param result its certified answer (vertex_face_ccd of the rigid query).
/// \param min_separation the delta of that answer (0: contact).
/// \return the enclosures at s*.
/// \throws std::invalid_argument for a non-finite position or motion, a negative or non-finite
///         delta, or when the result does not collide or its enclosure is not in [0, 1].
EXACTCCD_API ContactGeometry contact_geometry(const RigidVertexFaceQuery& query,
                                              const RigidCcdResult& result,
                                              double min_separation = 0.0);

/// The contact geometry of a rigid edge-edge query at s*; as for the rigid vertex-face query.
/// \param query the rigid query that was decided.
/// \param result its certified answer (edge_edge_ccd of the rigid query).
/// \param min_separation the delta of that answer (0: contact).
/// \return the enclosures at s*.
/// \throws std::invalid_argument as for the rigid vertex-face query.
EXACTCCD_API ContactGeometry contact_geometry(const RigidEdgeEdgeQuery& query,
                                              const RigidCcdResult& result,
                                              double min_separation = 0.0);

}  // namespace exactccd
