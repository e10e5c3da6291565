"""Rigid-body CCD from Python, and its answers checked by z3 (Debian's python3-z3), which shares
no reduction with exactccd. For each query z3 decides over the reals, with exact rationals,

    exists s in [lo, hi], u, v >= 0, u + v <= 1 (vertex-face; u, v in [0, 1] for edge-edge):
        the two closed primitives share a point at parameter s,

with every body point written from the matrix form of the motion,
w(s) x(s) = w(s) (c + s d) + ((1 - s^2 q.q) I + 2 s^2 q q^T + 2 s [q]x) (x0 - c),
w(s) = 1 + s^2 q.q, and the equation multiplied out by the two sides' (positive) denominators.
exactccd's `collides` (filtered and exact modes) must equal z3's answer on [0, 1]; for a contact
there must be no such s < toi_lo (unsat) and one with s <= toi_hi (sat).

Queries: seeded random rigid pairs near contact on a grid of small dyadic numbers (so that z3's
nonlinear arithmetic answers quickly): a triangle (or an edge) turning about a random axis with
a Cayley vector of eighths, a vertex (or an edge) put near its pose at s = 1/2 and then at rest,
turning itself or moving on straight lines; plus the exact constructions of the C++ tests. A
z3 timeout counts as neither agreement nor disagreement; more than a few fail the test. The z3
tests are skipped, saying so, only where z3 cannot be imported.
"""

import math
import os
import random
from fractions import Fraction as F

import numpy as np
import pytest

import exactccd

from z3_support import TIMEOUT_MS, Z3Tally, needs_z3, seed_from_environment, z3


# ------------------------------------------------------------------------------------------
# Motions as exact rationals

class Rigid:
    def __init__(self, pivot, translation, cayley):
        self.pivot, self.translation, self.cayley = pivot, translation, cayley

    def to_exactccd(self):
        return exactccd.RigidMotion(pivot=[float(x) for x in self.pivot],
                                    translation=[float(x) for x in self.translation],
                                    cayley=[float(x) for x in self.cayley])

    def numerator(self, x0, s):
        """w(s) x(s), from the matrix form, for a z3 or Fraction s."""
        c, d, q = self.pivot, self.translation, self.cayley
        qq = sum(x * x for x in q)
        w = 1 + s * s * qq
        r = [x0[k] - c[k] for k in range(3)]
        cross = [[0, -q[2], q[1]], [q[2], 0, -q[0]], [-q[1], q[0], 0]]
        out = []
        for i in range(3):
            rotated = 0
            for j in range(3):
                m = (1 - s * s * qq if i == j else 0) + 2 * s * s * q[i] * q[j] + 2 * s * cross[i][j]
                rotated = rotated + m * r[j]
            out.append(w * (c[i] + s * d[i]) + rotated)
        return out

    def denominator(self, s):
        return 1 + s * s * sum(x * x for x in self.cayley)


class Linear:
    def __init__(self, ends):
        self.ends = ends

    def to_exactccd(self):
        return np.array([[float(x) for x in e] for e in self.ends])

    def numerator_of(self, i, x0, s):
        return [x0[k] + s * (self.ends[i][k] - x0[k]) for k in range(3)]

    def denominator(self, s):
        return 1


def side_numerators(motion, points, s):
    if isinstance(motion, Rigid):
        return [motion.numerator(x, s) for x in points]
    return [motion.numerator_of(i, x, s) for i, x in enumerate(points)]


def value(x):
    return z3.RealVal(f"{x.numerator}/{x.denominator}") if isinstance(x, F) else x


def points_on_both(solver, kind, points, motions, lo=F(0), hi=F(1), hi_strict=False):
    """A point of each primitive at a parameter s in [lo, hi] (or [lo, hi)), cleared of
    denominators: (on_first, on_second, w0, w1) with the point of side i at on_i / w_i, the
    parameters s, u, v declared and bounded in the solver."""
    s, u, v = z3.Reals("s u v")
    solver.add(s >= value(lo), s < value(hi) if hi_strict else s <= value(hi))
    first, second = (points[:1], points[1:]) if kind == "vf" else (points[:2], points[2:])
    n0 = side_numerators(motions[0], [[value(x) for x in p] for p in first], s)
    n1 = side_numerators(motions[1], [[value(x) for x in p] for p in second], s)
    w0, w1 = motions[0].denominator(s), motions[1].denominator(s)
    if kind == "vf":
        solver.add(u >= 0, v >= 0, u + v <= 1)
        on_first = n0[0]
        on_second = [n1[0][k] + u * (n1[1][k] - n1[0][k]) + v * (n1[2][k] - n1[0][k])
                     for k in range(3)]
    else:
        solver.add(u >= 0, u <= 1, v >= 0, v <= 1)
        on_first = [n0[0][k] + u * (n0[1][k] - n0[0][k]) for k in range(3)]
        on_second = [n1[0][k] + v * (n1[1][k] - n1[0][k]) for k in range(3)]
    return on_first, on_second, w0, w1


def shares_a_point(kind, points, motions, lo=F(0), hi=F(1), hi_strict=False):
    """z3's answer: some s in [lo, hi] (or [lo, hi)) at which the primitives share a point."""
    solver = z3.Solver()
    solver.set("timeout", TIMEOUT_MS)
    on_first, on_second, w0, w1 = points_on_both(solver, kind, points, motions, lo, hi,
                                                 hi_strict)
    solver.add(*[on_first[k] * w1 == on_second[k] * w0 for k in range(3)])
    return solver.check()


def decide(kind, points, motions, mode="filtered"):
    array = np.array([[float(x) for x in p] for p in points])
    ccd = exactccd.rigid_vertex_face_ccd if kind == "vf" else exactccd.rigid_edge_edge_ccd
    return ccd(array, motions[0].to_exactccd(), motions[1].to_exactccd(), mode=mode)


# ------------------------------------------------------------------------------------------
# Queries

def grid(rng, scale=64, size=64):
    return F(rng.randint(-size, size), scale)


def random_query(rng, kind, styles=("rest", "linear")):
    """A turning triangle / edge, and a vertex / edge near its pose at s = 1/2 (rounded to the
    grid of 1/64), at rest, moving on straight lines, or ("turn") turning itself."""
    turn = Rigid([grid(rng) for _ in range(3)], [grid(rng, 16, 8) for _ in range(3)],
                 [F(rng.randint(-8, 8), 8) for _ in range(3)])
    count = 3 if kind == "vf" else 2
    first = [[grid(rng) for _ in range(3)] for _ in range(count)]
    half = F(1, 2)
    posed = [[x / turn.denominator(half) for x in turn.numerator(p, half)] for p in first]
    if kind == "vf":
        u = F(rng.randint(0, 8), 8)
        v = F(rng.randint(0, 8), 8) * (1 - u)
        target = [[posed[0][k] + u * (posed[1][k] - posed[0][k]) + v * (posed[2][k] - posed[0][k])
                   for k in range(3)]]
    else:
        mid = [(posed[0][k] + posed[1][k]) / 2 for k in range(3)]
        direction = [grid(rng, 16, 16) for _ in range(3)]
        target = [[mid[k] - direction[k] for k in range(3)], [mid[k] + direction[k] for k in range(3)]]
    other = [[F(round(x * 64), 64) for x in p] for p in target]  # near the pose, on the grid
    style = rng.choice(styles)
    if style == "rest":
        motion = Rigid([F(0)] * 3, [F(0)] * 3, [F(0)] * 3)
    elif style == "turn":
        motion = Rigid([grid(rng) for _ in range(3)], [F(0)] * 3,
                       [F(rng.randint(-2, 2), 8) for _ in range(3)])
    else:
        velocity = [grid(rng, 64, 16) for _ in range(3)]
        motion = Linear([[p[k] + velocity[k] for k in range(3)] for p in other])
    # The second primitive is the vertex (vf) or edge b; the turning body is the face / edge a.
    if kind == "vf":
        return other + first, [motion, turn]
    return first + other, [turn, motion]


def check_query(tally, kind, points, motions, where):
    """exactccd (exact and filtered modes) against z3 on one query."""
    exact = decide(kind, points, motions, mode="exact")
    tally.record(exact, decide(kind, points, motions), where)
    tally.ask_about(
        exact,
        lambda lo=0, hi=1, hi_strict=False: shares_a_point(kind, points, motions, lo=F(lo),
                                                           hi=F(hi), hi_strict=hi_strict),
        where)


@needs_z3
@pytest.mark.parametrize("kind", ["vf", "ee"])
def test_random_rigid_pairs_near_contact_agree_with_z3(kind):
    rng = random.Random(seed_from_environment() + (0 if kind == "vf" else 1))
    tally = Z3Tally()
    count = int(os.environ.get("EXACTCCD_RIGID_Z3_QUERIES", "150"))
    for k in range(count):
        points, motions = random_query(rng, kind)
        check_query(tally, kind, points, motions, f"{kind} query {k}")
    assert 0 < tally.contacts < tally.queries, tally.summary()
    tally.check()


@needs_z3
def test_exact_constructions_agree_with_z3():
    tally = Z3Tally()
    quarter = Rigid([F(0)] * 3, [F(0)] * 3, [F(0), F(0), F(1)])
    rest = Rigid([F(0)] * 3, [F(0)] * 3, [F(0)] * 3)
    # (5, 0, 0) turned a quarter reaches (3, 4, 0) at s = 1/2, on the plane y = 4.
    wall = [[F(2), F(4), F(-1)], [F(4), F(4), F(-1)], [F(3), F(4), F(1)]]
    check_query(tally, "vf", [[F(5), F(0), F(0)]] + wall, [quarter, rest], "pythagorean")
    # The chord of the same turn misses a wall on the arc.
    check_query(tally, "vf", [[F(5), F(0), F(0)]] + wall, [Linear([[F(0), F(5), F(0)]]), rest],
                      "chord")
    # An edge swept about z across a vertical edge at radius 2 (the angle of (3/5, 4/5)).
    check_query(tally, "ee", [[F(1), F(0), F(0)], [F(3), F(0), F(0)],
                             [F(6, 5), F(8, 5), F(-1)], [F(6, 5), F(8, 5), F(1)]],
                      [quarter, rest], "sweep")
    tally.check()


def test_rigid_float_only_from_python():
    # The uncertified double test (mode="float_only") on a clear crossing: the point (5, 0, 0)
    # turned a quarter about z crosses the wall y = 4 transversally at s = 1/2 (at (3, 4, 0)).
    quarter = exactccd.RigidMotion(cayley=(0, 0, 1))
    wall = [[2, 4, -1], [4, 4, -1], [3, 4, 1]]
    exact = exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + wall, quarter, exactccd.RigidMotion())
    r = exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + wall, quarter, exactccd.RigidMotion(),
                                       mode="float_only")
    assert r.collides and r.stage == "float_only" and r.toi_lo == r.toi_hi
    assert abs(r.toi_lo - exact.toi_lo) <= 1e-12 * exact.toi_lo
    t = math.atan(r.toi_lo) / math.atan(1.0)  # the time of the constant-speed turn
    assert r.has_time and r.time_lo - 1e-15 <= t <= r.time_hi + 1e-15
    # Clear of the wall (the arc stays within radius 5 < 6): no contact, +infinity TOIs.
    far = [[2, 6, -1], [4, 6, -1], [3, 6, 1]]
    miss = exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + far, quarter, exactccd.RigidMotion(),
                                          mode="float_only")
    assert not miss.collides and miss.toi_lo == miss.toi_hi == math.inf
    assert miss.stage == "float_only"


def test_rigid_mode_filtered_and_its_old_name_default():
    # "filtered" is the default argument; "default", its old name, gives the same answer.
    quarter = exactccd.RigidMotion(cayley=(0, 0, 1))
    wall = [[2, 4, -1], [4, 4, -1], [3, 4, 1]]
    results = [exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + wall, quarter, exactccd.RigidMotion(),
                                              **options)
               for options in ({}, {"mode": "filtered"}, {"mode": "default"})]
    assert results[0].collides
    assert len({(r.collides, r.toi_lo, r.toi_hi, r.stage) for r in results}) == 1
    edge = [[5, 0, -1], [5, 0, 1], [2, 4, 0], [4, 4, 0]]
    ee = [exactccd.rigid_edge_edge_ccd(edge, quarter, exactccd.RigidMotion(), mode=mode)
          for mode in ("filtered", "default")]
    assert (ee[0].collides, ee[0].toi_lo, ee[0].toi_hi) == (ee[1].collides, ee[1].toi_lo,
                                                            ee[1].toi_hi)
    with pytest.raises(ValueError, match='"filtered"'):
        exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + wall, quarter, exactccd.RigidMotion(),
                                       mode="fast")


def test_rigid_api_from_python():
    quarter = exactccd.RigidMotion(cayley=(0, 0, 1))
    wall = [[2, 4, -1], [4, 4, -1], [3, 4, 1]]
    r = exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + wall, quarter, exactccd.RigidMotion())
    assert r.collides and r.toi_lo == r.toi_hi == 0.5 and r.has_time
    assert r.time_lo <= math.atan(0.5) / math.atan(1.0) <= r.time_hi
    # A straight line per vertex: an (n, 3) array of end positions.
    chord = exactccd.rigid_vertex_face_ccd([[5, 0, 0]] + wall, [[0, 5, 0]], exactccd.RigidMotion())
    assert not chord.collides and chord.toi_lo == math.inf
    turned = exactccd.RigidMotion.turn((0, 0, 0), (0, 0, 2), math.pi / 2)
    assert np.allclose(turned.cayley, [0, 0, 1])
    assert np.allclose(turned.position_at((5, 0, 0), 0.5), [3, 4, 0])
    with pytest.raises(ValueError):
        exactccd.rigid_vertex_face_ccd([[5, 0, math.nan]] + wall, quarter, exactccd.RigidMotion())
    with pytest.raises(ValueError):
        exactccd.rigid_edge_edge_ccd(np.zeros((3, 3)), quarter, quarter)
    with pytest.raises(ValueError):
        exactccd.RigidMotion.turn((0, 0, 0), (0, 0, 0), 1.0)


def test_rigid_min_separation_keyword():
    # The corner (5, 0, 0) turning a quarter about z passes (3, 4, 0) at s = 1/2, beside a static
    # triangle in the plane through the axis and (3, 4, 0) that starts at radius 5 + gap: the
    # closest distance is gap. min_separation=delta: within delta iff gap <= delta; the default
    # (0) is contact, which never happens here. The same for an edge of the body along z passing
    # the triangle's inner edge (the static side given as straight lines, at rest).
    quarter = exactccd.RigidMotion(cayley=(0, 0, 1))
    rest = exactccd.RigidMotion()
    radial, up = np.array([0.6, 0.8, 0.0]), np.array([0.0, 0.0, 1.0])
    delta = 1e-3
    for gap, within in ((delta / 2, True), (2 * delta, False)):
        inner = [(5 + gap) * radial - up, (5 + gap) * radial + up]
        points = np.array([[5, 0, 0], *inner, 7 * radial])
        r = exactccd.rigid_vertex_face_ccd(points, quarter, rest, min_separation=delta)
        assert r.collides == within, gap
        assert not exactccd.rigid_vertex_face_ccd(points, quarter, rest).collides
        if within:
            assert 0 <= r.toi_lo <= r.toi_hi <= 0.5 and r.stage != "float_only"
        else:
            assert r.toi_lo == r.toi_hi == math.inf
        rough = exactccd.rigid_vertex_face_ccd(points, quarter, rest, mode="float_only",
                                               min_separation=delta)
        assert rough.collides == within and rough.stage == "float_only"
        edges = np.array([[5, 0, -0.5], [5, 0, 0.5], *inner])
        e = exactccd.rigid_edge_edge_ccd(edges, quarter, np.array(inner), min_separation=delta)
        assert e.collides == within, gap
        assert not exactccd.rigid_edge_edge_ccd(edges, quarter, np.array(inner)).collides
    with pytest.raises(ValueError):
        exactccd.rigid_vertex_face_ccd(points, quarter, rest, min_separation=-1e-3)
    with pytest.raises(ValueError):
        exactccd.rigid_edge_edge_ccd(edges, quarter, rest, min_separation=math.nan)
