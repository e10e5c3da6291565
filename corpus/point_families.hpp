// Degenerate families of the point kinds (point-edge in 3D and 2D, point-point in 3D and 2D,
// point-plane), for `exactccd generate --type`: each family is built exactly in doubles so that
// every member collides, or misses, by construction (a point through a segment's endpoint or
// one unit in the last place beyond it, points meeting at a dyadic time or missing by an ulp, a
// point sliding in a plane, a plane grazed by a double root of the offset...), and its truth is
// the exact path's (Mode::exact); a member whose exact verdict contradicts its construction is
// reported, never rewritten. PROOF: proofs/api_reductions.md#point-families
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "exactccd/types.hpp"

namespace exactccd::families {

/// One query of a point kind: rows_per_query(kind) points (those at t0, then at t1; z = 0 in
/// 2D), as in the kind's files.
using PointRows = std::vector<Eigen::Vector3d>;

/// The query's answer by the kind's public function (point_edge_ccd, point_edge_ccd_2d,
/// point_point_ccd, point_point_ccd_2d, point_plane_ccd).
CcdResult decide_point_query(PrimitiveKind kind, const PointRows& rows, const CcdOptions& options);

struct PointFamily {
  std::string name;        ///< e.g. "pe2d_through_endpoint"
  PrimitiveKind kind = PrimitiveKind::point_edge;
  bool collides = false;   ///< what the construction claims for every member
  std::string what;        ///< one line: the construction
  std::vector<PointRows> members;
  std::vector<CcdResult> exact;  ///< each member decided by Mode::exact
};

/// The families of `kind`, `per_family` members each, from `seed` (the same on every machine).
std::vector<PointFamily> generate_point_families(PrimitiveKind kind, std::uint64_t seed,
                                                 int per_family);

/// The family as a file of its kind (exact fractions, truth = the exact verdict).
std::string point_family_csv(const PointFamily& family);

/// "member i: ..." for each member whose exact verdict contradicts the construction.
std::vector<std::string> point_claim_mismatches(const PointFamily& family);

}  // namespace exactccd::families
