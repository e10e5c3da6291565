"""exactccd: exact continuous collision detection for linearly moving vertices.

Every vertex moves on a straight line, x(t) = (1 - t) x_t0 + t x_t1. A query collides iff the
closed primitives (closed triangle, closed segments) share a point at some t in [0, t_max]; in
the default mode, "filtered", the answer is exact for every finite input, and [toi_lo, toi_hi]
encloses the exact earliest contact time. With min_separation=delta > 0 a query collides iff
the primitives come within Euclidean distance delta, and the TOI is the earliest such time.

    import exactccd
    r = exactccd.vertex_face_ccd(p0, a0, b0, c0, p1, a1, b1, c1)   # numpy 3-vectors
    r.collides, r.toi_lo, r.toi_hi, r.stage
    batch = exactccd.vertex_face_ccd_batch(queries)                  # (N, 8, 3) float64
    batch.collides, batch.toi_lo, batch.toi_hi, batch.stage          # numpy arrays

Bad input raises ValueError (malformed query files: exactccd.InputError, a ValueError).
"""

import enum
from typing import NamedTuple, Optional

import numpy as np


class QueryType(str, enum.Enum):
    """The kind of a pair of primitives (ScenePair.type): an enum whose members are also the
    strings that name them in query files, so `pair.type == "vertex-face"` holds as well.
    point_edge, point_point and point_plane: the pairs of a Scene's edge meshes, point sets
    and planes (and of 2D scenes)."""

    vertex_face = "vertex-face"
    edge_edge = "edge-edge"
    point_edge = "point-edge"
    point_point = "point-point"
    point_plane = "point-plane"

    def __str__(self):
        return self.value


from . import _exactccd
from ._exactccd import (
    MODE_NAMES,
    STAGE_NAMES,
    CcdResult,
    ContactGeometry,
    __version__,
    EarliestContact,
    InputError,
    RigidCcdResult,
    RigidMotion,
    Scene,
    SceneContact,
    ScenePair,
    SceneResult,
    SceneStats,
    exact_ccd,
    find_query_files,
    query_type_from_path,
    StepResult,
    rigid_edge_edge_ccd,
    rigid_point_plane_ccd,
    rigid_edge_edge_collision_free_step,
    rigid_vertex_face_ccd,
    rigid_vertex_face_collision_free_step,
)
from .inspect import inspect
from .query_files import (
    QueryData,
    read_query_file,
    read_query_file_exact,
    write_query_file,
)

for _type in (CcdResult, ContactGeometry, EarliestContact, InputError, RigidCcdResult, RigidMotion,
              Scene, SceneContact, ScenePair, SceneResult, SceneStats, StepResult):
    _type.__module__ = __name__

# Arguments of the wrong type: one line naming the public function, not pybind11's listing.
from . import _arguments

for _type in (RigidMotion, Scene, ScenePair):
    _arguments.wrap_class(_type)
exact_ccd = _arguments.one_line_type_errors(exact_ccd, "exact_ccd")
find_query_files = _arguments.one_line_type_errors(find_query_files, "find_query_files")
query_type_from_path = _arguments.one_line_type_errors(query_type_from_path,
                                                       "query_type_from_path")
rigid_edge_edge_ccd = _arguments.one_line_type_errors(rigid_edge_edge_ccd, "rigid_edge_edge_ccd")
rigid_point_plane_ccd = _arguments.one_line_type_errors(rigid_point_plane_ccd,
                                                       "rigid_point_plane_ccd")
rigid_vertex_face_ccd = _arguments.one_line_type_errors(rigid_vertex_face_ccd,
                                                        "rigid_vertex_face_ccd")
rigid_edge_edge_collision_free_step = _arguments.one_line_type_errors(
    rigid_edge_edge_collision_free_step, "rigid_edge_edge_collision_free_step")
rigid_vertex_face_collision_free_step = _arguments.one_line_type_errors(
    rigid_vertex_face_collision_free_step, "rigid_vertex_face_collision_free_step")


RigidCcdResult.contact = property(
    lambda self: self.__dict__.get("contact"),
    doc="The contact geometry (ContactGeometry) at s* when asked for with contact=True and the "
        "query collides; None otherwise.")
CcdResult.contact = property(
    lambda self: self.__dict__.get("contact"),
    doc="The contact geometry (ContactGeometry) when asked for with contact=True and the query "
        "collides; None otherwise.")


def _with_contact(function, result, rows, type, contact, mode, min_separation, keep=None):
    """result, with its contact geometry attached when asked for (contact=True) and it collides.
    keep: the rows of the edge-edge parameters that the point kinds report."""
    if not contact:
        return result
    if _exactccd._mode_name(mode) == "float_only":
        raise ValueError(f"{function}(): contact=True needs a certified mode (\"filtered\" or "
                         f"\"exact\"): float_only's time of impact is not an enclosure")
    if result.collides:
        geometry = _exactccd._contact_geometry(rows, type, result, min_separation)
        result.__dict__["contact"] = geometry if keep is None else _PointContact(geometry, keep)
    return result


class _PointContact:
    """The contact geometry of a point query: the edge-edge geometry with only the segment's
    parameter (point-edge) or none (point-point)."""

    def __init__(self, geometry, keep):
        self._geometry, self._keep = geometry, keep

    parameters = property(lambda self: self._geometry.parameters[self._keep])
    normal = property(lambda self: self._geometry.normal)
    point = property(lambda self: self._geometry.point)
    kind = property(lambda self: self._geometry.kind)
    normal_oriented = property(lambda self: self._geometry.normal_oriented)

    def __repr__(self):
        return repr(self._geometry)


def _options(function, t_max, toi_width, mode, min_separation):
    """The options, type-checked (their domains are checked by the library)."""
    return (_arguments.real(function, "t_max", t_max),
            _arguments.real(function, "toi_width", toi_width),
            _arguments.text(function, "mode", mode),
            _arguments.real(function, "min_separation", min_separation))

__all__ = [
    "BatchContact", "BatchResult", "CONTACT_KIND_NAMES", "CcdResult", "ContactGeometry",
    "EarliestContact", "InputError", "MODE_NAMES", "QueryData", "QueryType", "RigidCcdResult",
    "RigidMotion", "STAGE_NAMES", "Scene", "SceneContact", "ScenePair", "SceneResult",
    "SceneStats", "StepResult", "__version__", "edge_edge_ccd", "edge_edge_ccd_batch", "inspect",
    "edge_edge_collision_free_step", "exact_ccd", "find_query_files", "point_edge_ccd",
    "point_edge_ccd_batch", "point_edge_collision_free_step", "point_plane_ccd",
    "point_plane_ccd_batch", "point_point_ccd", "point_point_ccd_batch",
    "point_point_collision_free_step", "query_type_from_path", "read_query_file",
    "read_query_file_exact", "rigid_edge_edge_ccd", "rigid_edge_edge_collision_free_step",
    "rigid_point_plane_ccd",
    "rigid_vertex_face_ccd", "rigid_vertex_face_collision_free_step", "vertex_face_ccd",
    "vertex_face_ccd_batch", "vertex_face_collision_free_step", "write_query_file",
]


def _points(points, names):
    """The 8 points as one (8, 3) array: either 8 3-vectors or one (8, 3) array."""
    if len(points) == 1:
        return points[0]
    if len(points) == 8:
        return [np.asarray(p, dtype=np.float64) for p in points]
    raise TypeError(f"expected the 8 points {', '.join(names)} or one (8, 3) array, "
                    f"got {len(points)} arguments")


_VERTEX_FACE_ROWS = ("p_t0", "a_t0", "b_t0", "c_t0", "p_t1", "a_t1", "b_t1", "c_t1")
_EDGE_EDGE_ROWS = ("ea0_t0", "ea1_t0", "eb0_t0", "eb1_t0", "ea0_t1", "ea1_t1", "eb0_t1", "eb1_t1")


def vertex_face_ccd(*points, t_max: float = 1.0, toi_width: float = 0.0,
                    mode: str = "filtered", min_separation: float = 0.0,
                    contact: bool = False) -> CcdResult:
    """Vertex p against the closed triangle (a, b, c), over [0, t_max].

    vertex_face_ccd(p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1) with 3-vectors, or
    vertex_face_ccd(points) with one (8, 3) array in that row order.
    t_max in [0, 1] (0: the state at t = 0 alone, a contact there at [0, 0]); toi_width >= 0
    (0: the tightest pair of doubles around the exact time); mode "filtered" (certified;
    "default", its old name, is accepted too), "exact" (the rational path only) or "float_only"
    (uncertified, for comparison). min_separation: delta >= 0,
    finite; collides iff the vertex comes within Euclidean distance delta of the triangle, the
    TOI the earliest such time (0: contact). contact=True: a colliding result's `contact` is the
    certified contact geometry at the exact time of impact (ContactGeometry: barycentric
    coordinates as `parameters`, `normal`, `point`, `kind`; with min_separation > 0, those of
    the closest points); certified modes only.
    Raises ValueError for non-finite coordinates or options outside their domain.
    """
    rows = _points(points, _VERTEX_FACE_ROWS)
    options = _options("vertex_face_ccd", t_max, toi_width, mode, min_separation)
    return _with_contact("vertex_face_ccd", _exactccd._vertex_face_ccd(rows, *options), rows,
                         "vf", contact, options[2], options[3])


def edge_edge_ccd(*points, t_max: float = 1.0, toi_width: float = 0.0,
                  mode: str = "filtered", min_separation: float = 0.0,
                  contact: bool = False) -> CcdResult:
    """Closed segment [ea0, ea1] against the closed segment [eb0, eb1], over [0, t_max].

    edge_edge_ccd(ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1) or
    edge_edge_ccd(points) with one (8, 3) array; options as vertex_face_ccd (contact=True: the
    parameter on each edge as `parameters`, the normal from edge b towards edge a).
    """
    rows = _points(points, _EDGE_EDGE_ROWS)
    options = _options("edge_edge_ccd", t_max, toi_width, mode, min_separation)
    return _with_contact("edge_edge_ccd", _exactccd._edge_edge_ccd(rows, *options), rows, "ee",
                         contact, options[2], options[3])


_POINT_EDGE_ROWS = ("p_t0", "e0_t0", "e1_t0", "p_t1", "e0_t1", "e1_t1")
_POINT_POINT_ROWS = ("p_t0", "q_t0", "p_t1", "q_t1")
# The edge-edge query each point query is (proofs/api_reductions.md#point-primitives): a point
# is the zero-length segment [p, p]; rows copied, never computed.
_POINT_EDGE_AS_EDGE_EDGE = [0, 0, 1, 2, 3, 3, 4, 5]
_POINT_POINT_AS_EDGE_EDGE = [0, 0, 1, 1, 2, 2, 3, 3]


def _in_space(function, array, names, leading):
    """The points as float64 in 3D: (..., k, 3) as given, (..., k, 2) embedded in z = 0
    (appending the double 0 rounds nothing); non-finite coordinates named."""
    k = len(names)
    if array.ndim != leading + 2 or array.shape[-2] != k or array.shape[-1] not in (2, 3):
        want = "(N, " if leading else "("
        raise ValueError(f"{function}(): the points {', '.join(names)} must have shape "
                         f"{want}{k}, 3) or {want}{k}, 2), not {array.shape}")
    finite = np.isfinite(array).all(axis=-1)
    if not finite.all():
        where = np.argwhere(~finite)[0]
        query = f"query {where[0]}: " if leading else ""
        raise ValueError(f"{query}exactccd: non-finite coordinate in {names[where[-1]]}")
    if array.shape[-1] == 2:
        array = np.concatenate([array, np.zeros(array.shape[:-1] + (1,))], axis=-1)
    return array


def _point_query(function, points, names):
    if len(points) == 1:
        array = np.asarray(points[0], dtype=np.float64)
    elif len(points) == len(names):
        shapes = {np.shape(p) for p in points}
        if len(shapes) != 1:
            raise ValueError(f"{function}(): the points {', '.join(names)} must all be 3-vectors "
                             f"or all 2-vectors")
        array = np.array([np.asarray(p, dtype=np.float64) for p in points])
    else:
        raise TypeError(f"{function}(): expected the {len(names)} points {', '.join(names)} or "
                        f"one ({len(names)}, 3) or ({len(names)}, 2) array, got {len(points)} "
                        f"arguments")
    return _in_space(function, array, names, 0)


def point_edge_ccd(*points, t_max: float = 1.0, toi_width: float = 0.0,
                   mode: str = "filtered", min_separation: float = 0.0,
                   contact: bool = False) -> CcdResult:
    """Point p against the closed segment [e0, e1], in 3D or in the plane, over [0, t_max].

    point_edge_ccd(p_t0, e0_t0, e1_t0, p_t1, e0_t1, e1_t1) with 3-vectors or 2-vectors, or one
    (6, 3) or (6, 2) array in that row order; a 2D query is decided in the plane z = 0. Options
    as vertex_face_ccd. The edge-edge query of the segment [p, p] against [e0, e1], which has
    the same contact set (C++: point_edge_ccd, point_edge_ccd_2d).
    """
    rows = _point_query("point_edge_ccd", points, _POINT_EDGE_ROWS)[_POINT_EDGE_AS_EDGE_EDGE]
    options = _options("point_edge_ccd", t_max, toi_width, mode, min_separation)
    return _with_contact("point_edge_ccd", _exactccd._edge_edge_ccd(rows, *options), rows, "ee",
                         contact, options[2], options[3], keep=slice(1, 2))


def point_point_ccd(*points, t_max: float = 1.0, toi_width: float = 0.0,
                    mode: str = "filtered", min_separation: float = 0.0,
                    contact: bool = False) -> CcdResult:
    """Points p and q, in 3D or in the plane, over [0, t_max]: they meet (or come within
    min_separation) at some t.

    point_point_ccd(p_t0, q_t0, p_t1, q_t1) with 3-vectors or 2-vectors, or one (4, 3) or (4, 2)
    array. Options as vertex_face_ccd (C++: point_point_ccd, point_point_ccd_2d).
    """
    rows = _point_query("point_point_ccd", points, _POINT_POINT_ROWS)[_POINT_POINT_AS_EDGE_EDGE]
    options = _options("point_point_ccd", t_max, toi_width, mode, min_separation)
    return _with_contact("point_point_ccd", _exactccd._edge_edge_ccd(rows, *options), rows, "ee",
                         contact, options[2], options[3], keep=slice(0, 0))


def _step_options(function, t_max, min_separation, conservative_rescaling, max_margin):
    """The step's options, type-checked (their domains are checked by the library)."""
    return (_arguments.real(function, "t_max", t_max),
            _arguments.real(function, "min_separation", min_separation),
            _arguments.real(function, "conservative_rescaling", conservative_rescaling),
            _arguments.real(function, "max_margin", max_margin))


def vertex_face_collision_free_step(*points, t_max: float = 1.0, min_separation: float = 0.0,
                                    conservative_rescaling: float = 0.8,
                                    max_margin: float = float("inf")) -> StepResult:
    """The collision-free step of a barrier method: a certified time `step` in [0, t_max] such
    that the vertex stays farther than min_separation from the triangle, and at least
    `effective_separation` = delta + (1 - s)(d0 - delta) from it, on all of [0, step] (d0 the
    distance at t = 0, s = conservative_rescaling in (0, 1], as ipc-toolkit's; max_margin caps
    the margin (1 - s)(d0 - delta), as ipc-toolkit's Tight Inclusion does at 1e-4). Points as
    vertex_face_ccd. `limited`: the pair comes within effective_separation before t_max;
    `starts_within` (exact): within min_separation at t = 0, step 0.
    """
    function = "vertex_face_collision_free_step"
    return _exactccd._collision_free_step(
        _points(points, _VERTEX_FACE_ROWS), "vf",
        *_step_options(function, t_max, min_separation, conservative_rescaling, max_margin))


def edge_edge_collision_free_step(*points, t_max: float = 1.0, min_separation: float = 0.0,
                                  conservative_rescaling: float = 0.8,
                                  max_margin: float = float("inf")) -> StepResult:
    """The collision-free step of two segments; points as edge_edge_ccd, the rest as
    vertex_face_collision_free_step."""
    function = "edge_edge_collision_free_step"
    return _exactccd._collision_free_step(
        _points(points, _EDGE_EDGE_ROWS), "ee",
        *_step_options(function, t_max, min_separation, conservative_rescaling, max_margin))


def point_edge_collision_free_step(*points, t_max: float = 1.0, min_separation: float = 0.0,
                                   conservative_rescaling: float = 0.8,
                                  max_margin: float = float("inf")) -> StepResult:
    """The collision-free step of a point and a segment, in 3D or in the plane; points as
    point_edge_ccd, the rest as vertex_face_collision_free_step."""
    function = "point_edge_collision_free_step"
    rows = _point_query(function, points, _POINT_EDGE_ROWS)
    return _exactccd._collision_free_step(
        rows[_POINT_EDGE_AS_EDGE_EDGE], "ee",
        *_step_options(function, t_max, min_separation, conservative_rescaling, max_margin))


def point_point_collision_free_step(*points, t_max: float = 1.0, min_separation: float = 0.0,
                                    conservative_rescaling: float = 0.8,
                                    max_margin: float = float("inf")) -> StepResult:
    """The collision-free step of two points, in 3D or in the plane; points as
    point_point_ccd, the rest as vertex_face_collision_free_step."""
    function = "point_point_collision_free_step"
    rows = _point_query(function, points, _POINT_POINT_ROWS)
    return _exactccd._collision_free_step(
        rows[_POINT_POINT_AS_EDGE_EDGE], "ee",
        *_step_options(function, t_max, min_separation, conservative_rescaling, max_margin))


_POINT_PLANE_ROWS = ("p_t0", "origin_t0", "normal_t0", "p_t1", "origin_t1", "normal_t1")


def point_plane_ccd(*points, t_max: float = 1.0, toi_width: float = 0.0,
                    mode: str = "filtered", min_separation: float = 0.0,
                    contact: bool = False) -> CcdResult:
    """Point p against the plane through `origin` with normal `normal`, each moving linearly,
    over [0, t_max]: contact when p(t) is on the plane {x : (x - origin(t)) . normal(t) = 0}
    (with min_separation delta: within distance delta of it).

    point_plane_ccd(p_t0, origin_t0, normal_t0, p_t1, origin_t1, normal_t1) with 3-vectors, or
    one (6, 3) array; a static plane repeats origin and normal. Options as vertex_face_ccd.
    contact=True: a colliding result's `contact` is the certified contact geometry at t*
    (no parameters; `point` the point at t*, with min_separation its closest point on the plane;
    `normal` the plane's unit normal towards the side the point came from).
    Raises ValueError for non-finite coordinates, a zero normal, or options outside their
    domain.
    """
    if len(points) == 1:
        rows = points[0]
    elif len(points) == 6:
        rows = [np.asarray(p, dtype=np.float64) for p in points]
    else:
        raise TypeError(f"point_plane_ccd(): expected the 6 points {', '.join(_POINT_PLANE_ROWS)} "
                        f"or one (6, 3) array, got {len(points)} arguments")
    options = _options("point_plane_ccd", t_max, toi_width, mode, min_separation)
    result = _exactccd._point_plane_ccd(rows, *options)
    if contact:
        if _exactccd._mode_name(options[2]) == "float_only":
            raise ValueError("point_plane_ccd(): contact=True needs a certified mode "
                             "(\"filtered\" or \"exact\"): float_only's time of impact is not an "
                             "enclosure")
        if result.collides:
            result.__dict__["contact"] = _exactccd._point_plane_contact_geometry(
                rows, result, options[3])
    return result


def point_plane_ccd_batch(queries, *, t_max: float = 1.0, toi_width: float = 0.0,
                          mode: str = "filtered", threads: Optional[int] = None,
                          min_separation: float = 0.0, contact: bool = False) -> "BatchResult":
    """Decides N point-plane queries: an (N, 6, 3) array, rows p, origin, normal at t0 then at
    t1. As vertex_face_ccd_batch; results equal one point_plane_ccd call per query (contact=True:
    the BatchContact of every query, no parameters: (N, 0, 2))."""
    function = "point_plane_ccd_batch"
    t_max, toi_width, mode, min_separation = _options(function, t_max, toi_width, mode,
                                                      min_separation)
    threads = _arguments.count_or_none(function, "threads", threads)
    if not isinstance(contact, (bool, np.bool_)):
        raise TypeError(f"{function}(): contact must be True or False, not "
                        f"{contact.__class__.__name__}")
    fields = _exactccd._point_plane_batch(queries, t_max, toi_width, mode, threads,
                                          min_separation, bool(contact))
    if not contact:
        return BatchResult(*fields)
    result = _BatchResultWithContact(*fields[:4])
    result.__dict__["contact"] = BatchContact(*fields[4])
    return result


class BatchResult(NamedTuple):
    """Results of a batch, one entry per query: stage holds codes into STAGE_NAMES."""
    collides: np.ndarray  # bool
    toi_lo: np.ndarray    # float64
    toi_hi: np.ndarray    # float64
    stage: np.ndarray     # uint8

    def stage_names(self):
        """The stage of each query by name."""
        return [STAGE_NAMES[code] for code in self.stage]

    @property
    def contact(self):
        """The contact geometry of every query (BatchContact) when asked for with contact=True;
        None otherwise."""
        return getattr(self, "__dict__", {}).get("contact")


CONTACT_KIND_NAMES = ("point", "at_start", "unresolved", "degenerate_triangle", "parallel_edges",
                      "coplanar")


class BatchContact(NamedTuple):
    """The contact geometry of a batch, one entry per query (C++: exactccd::contact_geometry):
    NaN and kind -1 for a query without contact."""
    parameters: np.ndarray       # (N, k, 2) float64: [lo, hi] of each parameter
    normal: np.ndarray           # (N, 3, 2) float64: [lo, hi] of each normal component
    point: np.ndarray            # (N, 3, 2) float64: [lo, hi] of each coordinate
    kind: np.ndarray             # (N,) int8: index into CONTACT_KIND_NAMES, -1 without contact
    normal_oriented: np.ndarray  # (N,) bool


class _BatchResultWithContact(BatchResult):
    """A BatchResult (still a 4-tuple) that carries its BatchContact."""


def vertex_face_ccd_batch(queries, *, t_max: float = 1.0, toi_width: float = 0.0,
                          mode: str = "filtered", threads: Optional[int] = None,
                          min_separation: float = 0.0, contact: bool = False) -> BatchResult:
    """Decides N vertex-face queries: an (N, 8, 3) array, rows p, a, b, c at t0 then at t1.

    Runs without the GIL, in parallel over `threads` threads (None: every core; 1: serially on
    the calling thread). Results equal one vertex_face_ccd call per query. contact=True: the
    result's `contact` is the BatchContact of every query (numpy arrays; certified modes; with
    min_separation > 0, the closest points'). Raises ValueError for a wrong shape, bad options, or a bad query (the
    message names the first one's index).
    """
    return _batch("vertex_face_ccd_batch", "vertex-face", queries, t_max, toi_width, mode,
                  threads, min_separation, contact)


def edge_edge_ccd_batch(queries, *, t_max: float = 1.0, toi_width: float = 0.0,
                        mode: str = "filtered", threads: Optional[int] = None,
                        min_separation: float = 0.0, contact: bool = False) -> BatchResult:
    """Decides N edge-edge queries: an (N, 8, 3) array, rows ea0, ea1, eb0, eb1 at t0 then at
    t1. As vertex_face_ccd_batch."""
    return _batch("edge_edge_ccd_batch", "edge-edge", queries, t_max, toi_width, mode, threads,
                  min_separation, contact)


def _batch(function, type, queries, t_max, toi_width, mode, threads, min_separation,
           contact=False, keep=None):
    t_max, toi_width, mode, min_separation = _options(function, t_max, toi_width, mode,
                                                      min_separation)
    threads = _arguments.count_or_none(function, "threads", threads)
    if not isinstance(contact, (bool, np.bool_)):
        raise TypeError(f"{function}(): contact must be True or False, not "
                        f"{contact.__class__.__name__}")
    fields = _exactccd._ccd_batch(type, queries, t_max, toi_width, mode, threads,
                                  min_separation, bool(contact))
    if not contact:
        return BatchResult(*fields)
    result = _BatchResultWithContact(*fields[:4])
    parameters, normal, point, kind, oriented = fields[4]
    if keep is not None:
        parameters = parameters[:, keep]
    result.__dict__["contact"] = BatchContact(parameters, normal, point, kind, oriented)
    return result


def point_edge_ccd_batch(queries, *, t_max: float = 1.0, toi_width: float = 0.0,
                         mode: str = "filtered", threads: Optional[int] = None,
                         min_separation: float = 0.0, contact: bool = False) -> BatchResult:
    """Decides N point-edge queries: an (N, 6, 3) or (N, 6, 2) array, rows p, e0, e1 at t0 then
    at t1. As vertex_face_ccd_batch; results equal one point_edge_ccd call per query."""
    array = _in_space("point_edge_ccd_batch", np.asarray(queries, dtype=np.float64),
                      _POINT_EDGE_ROWS, 1)
    return _batch("point_edge_ccd_batch", "edge-edge", array[:, _POINT_EDGE_AS_EDGE_EDGE], t_max,
                  toi_width, mode, threads, min_separation, contact, keep=slice(1, 2))


def point_point_ccd_batch(queries, *, t_max: float = 1.0, toi_width: float = 0.0,
                          mode: str = "filtered", threads: Optional[int] = None,
                          min_separation: float = 0.0, contact: bool = False) -> BatchResult:
    """Decides N point-point queries: an (N, 4, 3) or (N, 4, 2) array, rows p, q at t0 then at
    t1. As vertex_face_ccd_batch."""
    array = _in_space("point_point_ccd_batch", np.asarray(queries, dtype=np.float64),
                      _POINT_POINT_ROWS, 1)
    return _batch("point_point_ccd_batch", "edge-edge", array[:, _POINT_POINT_AS_EDGE_EDGE],
                  t_max, toi_width, mode, threads, min_separation, contact, keep=slice(0, 0))
