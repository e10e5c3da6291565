"""The contact geometry's point against z3 (proofs/contact_geometry.md): for edges, z3 is asked
whether some contact point at some t of the TOI enclosure [toi_lo, toi_hi] lies outside the
reported `point` box (it must be unsat: the box holds every contact point of the enclosure, the
representative one at t* included) and whether one lies inside (sat). Parallel edges sliding
onto each other (kind parallel_edges: the contact set is a segment), a vertex sliding into a
triangle in its plane (coplanar), a degenerate triangle (a segment), random crossing edges
(point), and a point against a segment."""

from fractions import Fraction

import numpy as np
import pytest

import exactccd
from z3_support import needs_z3, seed_from_environment, z3


def _real(x):
    return z3.RealVal(str(Fraction(x)))


def _moving(rows, i, n, t):
    """Point i of a query of n points per instant (rows at t0 then at t1) at z3's t."""
    return [(1 - t) * _real(rows[i][k]) + t * _real(rows[i + n][k]) for k in range(3)]


def _ask(constraints):
    solver = z3.Solver()
    solver.set("timeout", 20000)
    solver.add(*constraints)
    return solver.check()


def _outside(point, box):
    return z3.Or(*[z3.Or(point[k] < _real(box[k][0]), point[k] > _real(box[k][1]))
                   for k in range(3)])


def _inside(point, box):
    return z3.And(*[z3.And(point[k] >= _real(box[k][0]), point[k] <= _real(box[k][1]))
                    for k in range(3)])


def _check_edges(rows, result):
    """z3: every common point of the two segments at some t of the enclosure is in the box
    (unsat outside), and some is (sat inside). Returns the kind."""
    g = result.contact
    t, s, u = z3.Reals("t s u")
    a0, a1 = _moving(rows, 0, 4, t), _moving(rows, 1, 4, t)
    b0, b1 = _moving(rows, 2, 4, t), _moving(rows, 3, 4, t)
    on_a = [a0[k] + s * (a1[k] - a0[k]) for k in range(3)]
    on_b = [b0[k] + u * (b1[k] - b0[k]) for k in range(3)]
    common = [t >= _real(result.toi_lo), t <= _real(result.toi_hi), s >= 0, s <= 1, u >= 0,
              u <= 1] + [on_a[k] == on_b[k] for k in range(3)]
    assert _ask(common + [_outside(on_a, g.point)]) == z3.unsat, (rows, g)
    assert _ask(common + [_inside(on_a, g.point)]) == z3.sat, (rows, g)
    return g.kind


@needs_z3
def test_parallel_edges_sliding_onto_each_other():
    rng = np.random.default_rng(seed_from_environment())
    kinds = set()
    for _ in range(8):
        # Edge a parallel to edge b (the same direction d), above it, falling onto it.
        d = rng.integers(1, 4, size=3).astype(float)
        b0 = rng.integers(-2, 3, size=3).astype(float)
        shift = rng.integers(-1, 2) * 0.5
        a0 = b0 + shift * d + np.array([0.0, 0.0, 1.0])
        drop = np.array([0.0, 0.0, -2.0])
        rows = [a0, a0 + d, b0, b0 + d, a0 + drop, a0 + d + drop, b0, b0 + d]
        r = exactccd.edge_edge_ccd(*rows, contact=True)
        assert r.collides
        kinds.add(_check_edges([list(x) for x in rows], r))
    assert "parallel_edges" in kinds


@needs_z3
def test_crossing_edges_and_a_point_against_a_segment():
    rng = np.random.default_rng(seed_from_environment() + 1)
    checked = 0
    for _ in range(12):
        # Edge a along x above edge b along y (both jittered), falling through it.
        j = lambda: rng.uniform(-0.2, 0.2, 3)
        a0, a1 = np.array([-1.0, 0, 1]) + j(), np.array([1.0, 0, 1]) + j()
        b0, b1 = np.array([0, -1.0, 0]) + j(), np.array([0, 1.0, 0]) + j()
        v = np.array([0, 0, -2.0]) + j()
        rows = [a0, a1, b0, b1, a0 + v, a1 + v, b0, b1]
        r = exactccd.edge_edge_ccd(*rows, contact=True)
        if not r.collides:
            continue
        _check_edges([list(x) for x in rows], r)
        checked += 1
    # A point (a zero-length edge a) falling through a segment: the point box holds it.
    rows = [[0.25, 0.5, 1], [0.25, 0.5, 1], [0, 0, 0], [1, 1, 0],
            [0.25, 0.5, -1], [0.25, 0.5, -1], [0, 0, 0], [1, 1, 0]]
    r = exactccd.edge_edge_ccd(*[np.array(x, dtype=float) for x in rows], contact=True)
    assert not r.collides  # (0.25, 0.5) is off the segment's line x = y
    rows[0] = rows[1] = [0.5, 0.5, 1]
    rows[4] = rows[5] = [0.5, 0.5, -1]
    r = exactccd.edge_edge_ccd(*[np.array(x, dtype=float) for x in rows], contact=True)
    assert r.collides
    _check_edges(rows, r)
    assert checked >= 8


def _check_vertex_face(rows, result):
    """z3: at every t of the enclosure where the vertex lies in the closed triangle (barycentric
    coordinates, the plane included), it lies in the point box (unsat outside), and at some such
    t it does (sat)."""
    g = result.contact
    t, beta, gamma = z3.Reals("t beta gamma")
    p, a, b, c = (_moving(rows, i, 4, t) for i in range(4))
    in_triangle = [t >= _real(result.toi_lo), t <= _real(result.toi_hi), beta >= 0, gamma >= 0,
                   beta + gamma <= 1] + [
        p[k] == a[k] + beta * (b[k] - a[k]) + gamma * (c[k] - a[k]) for k in range(3)]
    assert _ask(in_triangle + [_outside(p, g.point)]) == z3.unsat, (rows, g)
    assert _ask(in_triangle + [_inside(p, g.point)]) == z3.sat, (rows, g)
    return g.kind


@needs_z3
def test_vertex_sliding_in_the_plane_and_a_degenerate_triangle():
    # The vertex slides in the triangle's plane z = 0 into the triangle: coplanar throughout.
    rows = [[-1, 0.25, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0],
            [1, 0.25, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0]]
    r = exactccd.vertex_face_ccd(*[np.array(x, dtype=float) for x in rows], contact=True)
    assert r.collides and r.contact.kind == "coplanar"
    _check_vertex_face(rows, r)
    # A triangle that is a segment (c on ab) crossed by a falling vertex.
    rows = [[0.5, 0, 1], [0, 0, 0], [1, 0, 0], [0.25, 0, 0],
            [0.5, 0, -1], [0, 0, 0], [1, 0, 0], [0.25, 0, 0]]
    r = exactccd.vertex_face_ccd(*[np.array(x, dtype=float) for x in rows], contact=True)
    assert r.collides and r.contact.kind == "degenerate_triangle"
    _check_vertex_face(rows, r)
