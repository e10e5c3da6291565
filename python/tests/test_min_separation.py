"""Minimum-separation CCD from Python: the min_separation keyword of every entry point, and the
answers checked by z3 (Debian's python3-z3), which shares no reduction with exactccd: for each
query and delta, z3 decides over the reals, with exact rationals,

    exists t in [0, 1], u, v >= 0, u + v <= 1 (vertex-face; s, r in [0, 1] for edge-edge):
        |p(t) - (a(t) + u (b(t) - a(t)) + v (c(t) - a(t)))|^2 <= delta^2

and that must equal exactccd's `collides` (exact_ccd with the rational delta, and the default
path with the double delta). For a contact, there must be no such t < toi_lo (unsat) and one
with t <= toi_hi (sat): toi_lo <= t* <= toi_hi. Queries: the minimum-separation families of
`exactccd generate --min-separation` (boundary configurations and their near misses) for a
short and a 53-bit delta, and seeded random queries with deltas just below and just above
their threshold. A z3 timeout counts as neither agreement nor disagreement; more than a few
fail the test. The z3 tests are skipped, saying so, only where z3 cannot be imported.
"""

import json
import math
import os
import random
from fractions import Fraction as F

import numpy as np
import pytest

import exactccd
from conftest import run

from z3_support import TIMEOUT_MS, Z3Tally, needs_z3, seed_from_environment, z3


def within_delta(points, type, delta, t_lo=0, t_hi=1, t_hi_strict=False):
    """z3's answer (z3.sat, z3.unsat or z3.unknown) to: some t in [t_lo, t_hi] (t < t_hi when
    t_hi_strict) with the closed primitives within distance delta. Every number is an exact
    Fraction (z3.RealVal of a Fraction is exact)."""
    solver = z3.Solver()
    solver.set("timeout", TIMEOUT_MS)
    t = z3.Real("t")

    def at(vertex):
        x0, x1 = points[vertex], points[vertex + 4]
        return [z3.RealVal(x0[k]) + t * z3.RealVal(x1[k] - x0[k]) for k in range(3)]

    x = [at(i) for i in range(4)]
    if type == "vertex-face":
        u, v = z3.Reals("u v")
        solver.add(u >= 0, v >= 0, u + v <= 1)
        p = x[0]
        q = [x[1][k] + u * (x[2][k] - x[1][k]) + v * (x[3][k] - x[1][k]) for k in range(3)]
    else:
        s, r = z3.Reals("s r")
        solver.add(s >= 0, s <= 1, r >= 0, r <= 1)
        p = [x[0][k] + s * (x[1][k] - x[0][k]) for k in range(3)]
        q = [x[2][k] + r * (x[3][k] - x[2][k]) for k in range(3)]
    if delta == 0:
        # The same statement as |p - q|^2 <= 0; z3 4.8.12 answers that sum-of-squares form
        # wrongly (unsat) where the only solutions are irrational algebraic points (a contact
        # at a root of the coplanarity cubic), and the equations correctly.
        solver.add(*[p[k] == q[k] for k in range(3)])
    else:
        squared = sum((p[k] - q[k]) * (p[k] - q[k]) for k in range(3))
        solver.add(squared <= z3.RealVal(delta * delta))
    solver.add(t >= z3.RealVal(t_lo))
    solver.add(t < z3.RealVal(t_hi) if t_hi_strict else t <= z3.RealVal(t_hi))
    return solver.check()


def decide_double(points, type, delta):
    array = np.array([[float(c) for c in p] for p in points], dtype=np.float64)
    decide = exactccd.vertex_face_ccd if type == "vertex-face" else exactccd.edge_edge_ccd
    return decide(array, min_separation=float(delta))


def check_query(tally, points, type, delta, where):
    """exactccd (exact and default paths) against z3 on one query with the rational delta (a
    double, so that the default path gets the same delta)."""
    assert F(float(delta)) == delta
    exact = exactccd.exact_ccd(points, type, min_separation=delta)
    tally.record(exact, decide_double(points, type, delta), where)
    tally.ask_about(
        exact,
        lambda lo=0, hi=1, hi_strict=False: within_delta(points, type, delta, t_lo=F(lo),
                                                         t_hi=F(hi), t_hi_strict=hi_strict),
        where)


@pytest.fixture(scope="module")
def families(cli, tmp_path_factory):
    """The minimum-separation families for a short delta (5 * 2^-12: Pythagorean offsets) and a
    53-bit one (0.3): [(delta, family, type, points)]."""
    out = []
    for delta in ("0x1.4p-10", "0.3"):
        folder = tmp_path_factory.mktemp("families")
        done = run([cli, "generate", "--out", folder, "--seed", "3", "--per-family", "14",
                    "--min-separation", delta])
        assert done.returncode == 0, done.stderr
        manifest = json.loads((folder / "manifest.json").read_text())
        exact_delta = F(manifest["min_separation_exact"])
        assert exact_delta == F(float.fromhex(delta) if delta.startswith("0x") else float(delta))
        for family in manifest["families"]:
            data = exactccd.read_query_file_exact(
                folder / family["name"] / family["type"] / "data_0.csv", family["type"])
            out += [(exact_delta, family["name"], family["type"], q) for q in data.queries]
    return out


@needs_z3
def test_families_agree_with_z3(families):
    tally = Z3Tally()
    for k, (delta, name, type, points) in enumerate(families):
        check_query(tally, points, type, delta, f"{name} delta {float(delta)!r} query {k}")
    assert tally.contacts > 0 and tally.contacts < tally.queries
    tally.check()


def random_query(rng, type):
    """8 points with coordinates k / 64 in [-1, 1]. Vertex-face: a rigid triangle and a vertex
    moving on its own; edge-edge: a rigid edge and an edge whose endpoints move on their own
    (turning and stretching). Then a common velocity for all. (z3 4.8.12's nonlinear arithmetic
    times out on most deforming triangles near their threshold; the families' tilting triangle
    is exact tangency on a turning plane.)"""
    def point():
        return tuple(F(rng.randint(-64, 64), 64) for _ in range(3))

    points = [point() for _ in range(8)]
    rigid = (1, 2, 3) if type == "vertex-face" else (2, 3)
    for i in rigid:
        points[i + 4] = points[i]
    common = point()
    for i in range(4, 8):
        points[i] = tuple(x + w for x, w in zip(points[i], common))
    return points


def threshold_deltas(rng, points, type):
    """Deltas around the query's threshold (the least delta it comes within), found by bisection
    on the default path among multiples of 2^-12 in [0, 4]: the largest one it does not come
    within, the smallest one it does, and a 53-bit double between them."""
    lo, hi = F(0), F(4)  # within 4 always (coordinates in [-1, 1]^3)
    if decide_double(points, type, lo).collides:
        return [F(0), F(1, 4096)]
    while hi - lo > F(1, 4096):
        mid = (lo + hi) / 2
        if decide_double(points, type, mid).collides:
            hi = mid
        else:
            lo = mid
    between = F(float(lo + (hi - lo) * F(rng.randint(1, 2**52 - 1), 2**52)))
    return [lo, hi, between]


@needs_z3
def test_random_queries_near_their_threshold_agree_with_z3():
    rng = random.Random(seed_from_environment())
    tally = Z3Tally()
    for k in range(24):
        type = "vertex-face" if k % 2 == 0 else "edge-edge"
        points = random_query(rng, type)
        for delta in threshold_deltas(rng, points, type):
            check_query(tally, points, type, delta, f"random {type} {k} delta {float(delta)!r}")
    assert tally.contacts > 0 and tally.contacts < tally.queries
    tally.check()


def test_min_separation_keyword():
    """The keyword through every entry point: the default 0 is contact; a negative or
    non-finite delta raises ValueError (the library's check); exact_ccd takes Fractions."""
    # p passes over the unit triangle at height 1/4, entering it at t = 1/4.
    points = [(-1, F(1, 4), F(1, 4)), (0, 0, 0), (1, 0, 0), (0, 1, 0),
              (3, F(1, 4), F(1, 4)), (0, 0, 0), (1, 0, 0), (0, 1, 0)]
    array = np.array([[float(c) for c in p] for p in points])
    assert not exactccd.vertex_face_ccd(array).collides
    r = exactccd.vertex_face_ccd(array, min_separation=0.25)
    assert r.collides and r.toi_lo == r.toi_hi == 0.25
    assert not exactccd.vertex_face_ccd(array, min_separation=math.nextafter(0.25, 0)).collides
    exact = exactccd.exact_ccd(points, "vf", min_separation=F(1, 4))
    assert (exact.collides, exact.toi_lo, exact.toi_hi) == (True, 0.25, 0.25)
    assert not exactccd.exact_ccd(points, "vf").collides
    batch = exactccd.vertex_face_ccd_batch(np.stack([array, array]), min_separation=0.25)
    assert batch.collides.all() and (batch.toi_lo == 0.25).all()
    edges = np.array([[-1, 0, 1], [1, 0, 1], [0, -1, 0], [0, 1, 0]] * 2, dtype=np.float64)
    assert exactccd.edge_edge_ccd(edges, min_separation=1.0).collides
    assert not exactccd.edge_edge_ccd(edges, min_separation=0.5).collides
    assert exactccd.edge_edge_ccd_batch(edges[None], min_separation=1.0).collides[0]
    for bad in (-0.25, math.inf, math.nan):
        with pytest.raises(ValueError):
            exactccd.vertex_face_ccd(array, min_separation=bad)
        with pytest.raises(ValueError):
            exactccd.edge_edge_ccd_batch(edges[None], min_separation=bad)
    with pytest.raises(ValueError):
        exactccd.exact_ccd(points, "vf", min_separation=F(-1, 3))
    with pytest.raises(TypeError):
        exactccd.exact_ccd(points, "vf", min_separation=0.25)  # a float: Fraction(0.25) is exact
