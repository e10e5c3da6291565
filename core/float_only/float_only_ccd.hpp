// The classic, uncertified cubic CCD test in plain double arithmetic (Mode::float_only).
#pragma once

#include "core/predicates/motion.hpp"
#include "exactccd/types.hpp"

namespace exactccd::float_only {

CcdResult vertex_face_ccd(const VertexFaceQuery& q, const CcdOptions& options);
CcdResult edge_edge_ccd(const EdgeEdgeQuery& q, const CcdOptions& options);

/// The roots in [0, t_max] of the cubic f, found in double arithmetic (bisection on monotone
/// pieces), ascending, at most 3, written to roots; returns their count. Uncertified. Also
/// used by the tolerance method of core/float_only/tolerance_ccd.hpp, so that both find the
/// same roots.
int cubic_roots(const predicates::FixedPoly<double, 3>& f, double t_max, double roots[3]);

}  // namespace exactccd::float_only
