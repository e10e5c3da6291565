/// \file
/// The collision-free step of barrier methods (IPC and its descendants): how far along a trial
/// step a pair can move while staying strictly apart, with a margin, so that stepping there and
/// asking again from the new positions never sees the same contact again at once.
///
/// The exact first time the distance reaches delta (the CCD functions' toi_lo) is the wrong
/// answer for these methods: the distance there is delta itself, and the next query, started
/// there, is already at contact. collision_free_step answers instead with a step at which the
/// distance is still at least an *effective separation* delta' > delta, chosen as ipc-toolkit
/// chooses it, delta' = delta + (1 - s) (d0 - delta) with d0 the distance at t = 0 and s the
/// conservative rescaling (\ref collision_free_step "the step").
#pragma once

#include <limits>

#include "exactccd/export.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// Options of collision_free_step. Every function throws std::invalid_argument when they lie
/// outside their domain (the message names the value).
struct StepOptions {
  /// End of the trial step [0, t_max], in [0, 1].
  double t_max = 1.0;
  /// delta >= 0, finite: the distance the primitives must keep (0: they must not touch).
  double min_separation = 0.0;
  /// s in (0, 1]: the step keeps the fraction 1 - s of the start's gap d0 - delta as a margin
  /// (ipc-toolkit's conservative_rescaling; its default 0.8 keeps 20 %). 1 keeps no margin: the
  /// step is then before the first time within delta.
  double conservative_rescaling = 0.8;
  /// The largest margin kept, an absolute distance >= 0 (+infinity, the default: no cap, as
  /// ipc-toolkit's interface states the rule; its Tight Inclusion narrow phase caps the margin
  /// at 1e-4, which gives longer steps when the start's gap is large).
  double max_margin = std::numeric_limits<double>::infinity();
};

/// The answer of collision_free_step. Certified in every field.
struct StepResult {
  /// A time in [0, t_max] up to which the motion is safe: the distance between the closed
  /// primitives is > min_separation, and >= effective_separation, at every t in [0, step]
  /// (step = 0 when starts_within). When limited, for linear queries, it is moreover >=
  /// effective_separation + eta there (unless the start itself is within that), eta = 2^-46
  /// times the largest |coordinate| of the query plus 2^-1070: the caller's rounding of the
  /// positions at `step` (x0 + step (x1 - x0) or (1 - step) x0 + step x1 in doubles) moves the
  /// distance by less than eta / 2, so the straight motion from the start to the rounded
  /// positions stays beyond effective_separation, and asking again over it is not limited
  /// (ipc-toolkit's "Repeated CCD").
  double step = 1.0;
  /// True iff the primitives come within effective_separation at some t in [0, t_max] (then
  /// step is before the first such time); false: step = t_max.
  bool limited = false;
  /// True iff the distance at t = 0 is <= min_separation (exact): the pair is already in
  /// contact, step = 0 and limited = true.
  bool starts_within = false;
  /// delta' in [min_separation, d0): delta + min((1 - s)(d0 - delta), max_margin) for d0 the
  /// distance at t = 0 estimated in doubles, lowered towards delta until the primitives
  /// certifiably do not start within it. Equal to min_separation when s = 1, when no double
  /// between delta and d0 was found, or when starts_within; then the distance is still
  /// > delta on [0, step].
  double effective_separation = 0.0;
};

/// The collision-free step of vertex p against the closed triangle (a, b, c) over
/// [0, options.t_max] (\ref collision_free_step).
/// \param query any finite coordinates.
/// \param options t_max in [0, 1], min_separation finite and >= 0, conservative_rescaling in
///        (0, 1].
/// \return the step, certified.
/// \throws std::invalid_argument for a non-finite coordinate or options outside their domain.
EXACTCCD_API StepResult collision_free_step(const VertexFaceQuery& query,
                                            const StepOptions& options = {});

/// The collision-free step of the closed segments [ea0, ea1] and [eb0, eb1]; as for
/// vertex-face.
/// \param query any finite coordinates.
/// \param options as for vertex-face.
/// \return the step, certified.
/// \throws std::invalid_argument as for vertex-face.
EXACTCCD_API StepResult collision_free_step(const EdgeEdgeQuery& query,
                                            const StepOptions& options = {});

/// The collision-free step of point p against the closed segment [e0, e1] in 3D: that of the
/// edge-edge query [p, p], [e0, e1] (the same distance at every t).
/// \param query any finite coordinates.
/// \param options as for vertex-face.
/// \return the step, certified.
/// \throws std::invalid_argument as for vertex-face.
EXACTCCD_API StepResult collision_free_step(const PointEdgeQuery& query,
                                            const StepOptions& options = {});

/// The collision-free step of points p and q in 3D: that of the edge-edge query [p, p], [q, q].
/// \param query any finite coordinates.
/// \param options as for vertex-face.
/// \return the step, certified.
/// \throws std::invalid_argument as for vertex-face.
EXACTCCD_API StepResult collision_free_step(const PointPointQuery& query,
                                            const StepOptions& options = {});

/// The collision-free step of point p against the segment [e0, e1] in the plane: that of the
/// query embedded in z = 0 (exactly).
/// \param query any finite coordinates.
/// \param options as for vertex-face.
/// \return the step, certified.
/// \throws std::invalid_argument as for vertex-face.
EXACTCCD_API StepResult collision_free_step(const PointEdgeQuery2d& query,
                                            const StepOptions& options = {});

/// The collision-free step of points p and q in the plane: that of the query embedded in z = 0.
/// \param query any finite coordinates.
/// \param options as for vertex-face.
/// \return the step, certified.
/// \throws std::invalid_argument as for vertex-face.
EXACTCCD_API StepResult collision_free_step(const PointPointQuery2d& query,
                                            const StepOptions& options = {});

/// The collision-free step of a rigid vertex-face query, in the motion parameter s.
/// \param query finite positions and motions.
/// \param options as for vertex-face (t_max bounds s).
/// \return the step in s, certified.
/// \throws std::invalid_argument as the rigid vertex_face_ccd.
EXACTCCD_API StepResult collision_free_step(const RigidVertexFaceQuery& query,
                                            const StepOptions& options = {});

/// The collision-free step of a rigid edge-edge query, in the motion parameter s.
/// \param query finite positions and motions.
/// \param options as for vertex-face (t_max bounds s).
/// \return the step in s, certified.
/// \throws std::invalid_argument as the rigid edge_edge_ccd.
EXACTCCD_API StepResult collision_free_step(const RigidEdgeEdgeQuery& query,
                                            const StepOptions& options = {});

}  // namespace exactccd
