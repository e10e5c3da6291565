// The contact geometry of rigid queries (exactccd/contact.hpp): the query as the pipeline reads
// it (checked_query), the positions over the enclosure S of s* from its paths in interval
// arithmetic (predicates::rigid_paths, as the rigid filters use them), then the enclosures of
// contact_enclosures.hpp. The side just before s* is minus the sign of the rigid coplanarity
// polynomial's derivative over S: g = w0 w1 det[...] with w0 w1 > 0, so g and the positions'
// coplanarity determinant vanish together and change sign together at s*.
// PROOF: proofs/contact_geometry.md#rigid
#include "core/predicates/interval.hpp"
#include "core/predicates/rigid_coplanarity.hpp"
#include "core/predicates/rigid_paths.hpp"
#include "exactccd/contact.hpp"
#include "pipeline/contact_enclosures.hpp"
#include "pipeline/rigid_query_check.hpp"

namespace exactccd {

namespace {

using predicates::Interval;
namespace contact = pipeline::contact;

/// Whether edge `side` of an edge-edge query is a point throughout: equal start rows, moved by
/// one rigid motion or to equal end rows.
bool is_point(const predicates::DoubleRigidQuery& q, int side) {
  const int i = 2 * side;
  const auto same = [](const predicates::Vec3<double>& a, const predicates::Vec3<double>& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  };
  const predicates::DoubleSide& m = q.side[side];
  return same(q.start[i], q.start[i + 1]) && (m.rigid || same(m.end[0], m.end[1]));
}

/// The enclosures of a rigid query (vertex-face or edge-edge by q.type).
ContactGeometry rigid_geometry(const predicates::DoubleRigidQuery& q, const CcdResult& r,
                               double min_separation) {
  contact::check_separation(min_separation);
  contact::check_result(r);
  const predicates::RoundingGuard upward;
  const Interval S = contact::parameter_enclosure(r);
  const auto x = predicates::rigid_paths<Interval>(q).positions_at(S);
  const bool vertex_face = q.type == QueryType::vertex_face;
  if (min_separation > 0.0)
    return vertex_face ? contact::vertex_face_separation_from(x[0], x[1], x[2], x[3],
                                                              r.starts_within, 0)
                       : contact::edge_edge_separation_from(x[0], x[1], x[2], x[3],
                                                            r.starts_within, 0, is_point(q, 0),
                                                            is_point(q, 1));
  const auto side_before = [&] {
    const auto& p = q.start;
    const auto g =
        vertex_face
            ? predicates::vertex_face_rigid_coplanarity<Interval>(p[0], p[1], p[2], p[3],
                                                                  q.side[0], q.side[1])
            : predicates::edge_edge_rigid_coplanarity<Interval>(p[0], p[1], p[2], p[3],
                                                                q.side[0], q.side[1]);
    return contact::side_just_before(contact::derivative_over(g, S));
  };
  return vertex_face
             ? contact::vertex_face_from(x[0], x[1], x[2], x[3], r.starts_within, 0, side_before)
             : contact::edge_edge_from(x[0], x[1], x[2], x[3], r.starts_within, 0, side_before);
}

}  // namespace

ContactGeometry contact_geometry(const RigidVertexFaceQuery& q, const RigidCcdResult& result,
                                 double min_separation) {
  return rigid_geometry(pipeline::checked_query(q), result.ccd, min_separation);
}

ContactGeometry contact_geometry(const RigidEdgeEdgeQuery& q, const RigidCcdResult& result,
                                 double min_separation) {
  return rigid_geometry(pipeline::checked_query(q), result.ccd, min_separation);
}

}  // namespace exactccd
