"""Point-plane CCD in Python (C++: point_plane_ccd, proofs/point_plane.md#reduction): known
times, and moving planes with turning normals against z3's decision of the same formula
(contact: (p(t) - o(t)) . n(t) = 0; within delta: ((p - o) . n)^2 <= delta^2 |n|^2), and bad
input."""

from fractions import Fraction

import numpy as np
import pytest

import exactccd
from z3_support import Z3Tally, needs_z3, seed_from_environment, z3

INF = float("inf")


def test_falling_on_a_floor():
    up, origin = (0, 0, 1), (0, 0, 0)
    r = exactccd.point_plane_ccd((5, 7, 1), origin, up, (-3, 2, -1), origin, up)
    assert r.collides and r.toi_lo == r.toi_hi == 0.5
    r = exactccd.point_plane_ccd((5, 7, 1), origin, up, (-3, 2, -1), origin, up,
                                 min_separation=0.25)
    assert r.toi_lo == r.toi_hi == 0.375
    assert not exactccd.point_plane_ccd((5, 7, 1), origin, up, (-3, 2, 0.5), origin, up).collides
    assert exactccd.point_plane_ccd(np.array([(5, 7, 1), origin, up, (-3, 2, -1), origin, up]),
                                    mode="exact").toi_lo == 0.5


def test_bad_input():
    up, origin = (0, 0, 1), (0, 0, 0)
    with pytest.raises(ValueError, match="normal_t0 is zero"):
        exactccd.point_plane_ccd((1, 1, 1), origin, (0, 0, 0), (1, 1, 1), origin, up)
    with pytest.raises(ValueError, match="non-finite coordinate in p_t1"):
        exactccd.point_plane_ccd((1, 1, 1), origin, up, (np.nan, 1, 1), origin, up)
    with pytest.raises(ValueError, match=r"\(6, 3\)"):
        exactccd.point_plane_ccd(np.zeros((5, 3)))
    with pytest.raises(TypeError, match="expected the 6 points"):
        exactccd.point_plane_ccd((1, 1, 1), origin)


def _z3_decider(rows, delta):
    """decide(lo, hi, hi_strict): is there t in [lo, hi] (or [lo, hi)) with contact (within
    delta)? Exact rationals throughout."""
    q = [[Fraction(v) for v in row] for row in rows]

    def decide(lo=0.0, hi=1.0, hi_strict=False):
        t = z3.Real("t")
        at = lambda i, k: (1 - t) * z3.RealVal(str(q[i][k])) + t * z3.RealVal(str(q[i + 3][k]))
        f = sum((at(0, k) - at(1, k)) * at(2, k) for k in range(3))
        nn = sum(at(2, k) * at(2, k) for k in range(3))
        solver = z3.Solver()
        solver.set("timeout", 20000)
        solver.add(t >= z3.RealVal(str(Fraction(lo))))
        solver.add(t < z3.RealVal(str(Fraction(hi))) if hi_strict
                   else t <= z3.RealVal(str(Fraction(hi))))
        if delta == 0:
            solver.add(f == 0)
        else:
            d = z3.RealVal(str(Fraction(delta)))
            solver.add(f * f <= d * d * nn)
        return solver.check()

    return decide


@needs_z3
def test_turning_planes_against_z3():
    rng = np.random.default_rng(seed_from_environment())
    tally = Z3Tally()
    for n in range(120):
        p0, o0 = rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3)
        n0, n1 = rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3)
        p1 = p0 + rng.uniform(-2, 2, 3)
        o1 = o0 if n % 3 == 0 else o0 + rng.uniform(-1, 1, 3)
        if n % 4 == 0:  # the point grazes the plane: dyadic coordinates, exact touching likely
            p0, o0, n0, n1 = (np.round(v * 8) / 8 for v in (p0, o0, n0, n1))
            p1 = o1 = o0
        rows = [p0, o0, n0, p1, o1, n1]
        delta = 0.0 if n % 2 == 0 else 0.05
        exact = exactccd.point_plane_ccd(*rows, mode="exact", min_separation=delta)
        default = exactccd.point_plane_ccd(*rows, min_separation=delta)
        tally.record(exact, default, f"query {n}")
        tally.ask_about(exact, _z3_decider(rows, delta), f"query {n} delta {delta}")
    tally.check()
    assert tally.contacts > 20


def test_batch_equals_single_calls():
    rng = np.random.default_rng(4)
    n = 300
    queries = np.zeros((n, 6, 3))
    queries[:, 0] = rng.uniform(-1, 1, (n, 3))
    queries[:, 1] = rng.uniform(-0.5, 0.5, (n, 3))
    queries[:, 2] = rng.uniform(-1, 1, (n, 3))
    queries[:, 3] = queries[:, 0] + rng.uniform(-2, 2, (n, 3))
    queries[:, 4] = queries[:, 1]
    queries[:, 5] = np.where(rng.uniform(size=(n, 1)) < 0.5, queries[:, 2],
                             rng.uniform(-1, 1, (n, 3)))
    for delta in (0.0, 0.01):
        batch = exactccd.point_plane_ccd_batch(queries, threads=2, min_separation=delta)
        for i in range(n):
            r = exactccd.point_plane_ccd(queries[i], min_separation=delta)
            assert (batch.collides[i], batch.toi_lo[i], batch.toi_hi[i]) == \
                (r.collides, r.toi_lo, r.toi_hi)
        assert 30 < batch.collides.sum() < n
    with pytest.raises(ValueError, match="query 1"):
        bad = queries[:3].copy()
        bad[1, 2] = 0
        bad[1, 5] = 0
        exactccd.point_plane_ccd_batch(bad)


def test_contact_geometry_on_request():
    # A point falling from above onto the floor z = 0 (normal 3z): the point at t* = 1/2 and the
    # unit normal +z; from below, -z; float_only refuses contact=True.
    r = exactccd.point_plane_ccd([0.25, 0.5, 1.0], [0, 0, 0], [0, 0, 3],
                                 [0.25, 0.5, -1.0], [0, 0, 0], [0, 0, 3], contact=True)
    assert r.collides and r.toi_lo == 0.5
    g = r.contact
    assert g.kind == "point" and g.normal_oriented
    assert g.parameters.shape == (0, 2)
    assert np.array_equal(g.normal[2], [1.0, 1.0])
    assert (g.point[:, 0] <= [0.25, 0.5, 0.0]).all() and ([0.25, 0.5, 0.0] <= g.point[:, 1]).all()
    up = exactccd.point_plane_ccd([0, 0, -1.0], [0, 0, 0], [0, 0, 3],
                                  [0, 0, 1.0], [0, 0, 0], [0, 0, 3], contact=True)
    assert np.array_equal(up.contact.normal[2], [-1.0, -1.0])
    assert exactccd.point_plane_ccd([0, 0, 1.0], [0, 0, 0], [0, 0, 3],
                                    [0, 0, 2.0], [0, 0, 0], [0, 0, 3], contact=True).contact is None
    with pytest.raises(ValueError, match="certified mode"):
        exactccd.point_plane_ccd([0, 0, -1.0], [0, 0, 0], [0, 0, 3],
                                 [0, 0, 1.0], [0, 0, 0], [0, 0, 3], contact=True, mode="float_only")


def test_batch_contact_geometry_equals_single_calls():
    rng = np.random.default_rng(7)
    n = 200
    queries = np.zeros((n, 6, 3))
    queries[:, 0] = rng.uniform(-1, 1, (n, 3)) + [0, 0, 0.5]      # p at t0, above
    queries[:, 1] = rng.uniform(-0.1, 0.1, (n, 3))               # origin
    queries[:, 2] = rng.uniform(-0.2, 0.2, (n, 3)) + [0, 0, 1]   # normal
    queries[:, 3] = rng.uniform(-1, 1, (n, 3)) - [0, 0, 0.5]     # p at t1, below
    queries[:, 4:] = queries[:, 1:3]
    for delta in (0.0, 0.05):
        batch = exactccd.point_plane_ccd_batch(queries, contact=True, min_separation=delta)
        assert batch.contact.parameters.shape == (n, 0, 2)
        assert batch.collides.sum() > n // 2
        for i in range(n):
            single = exactccd.point_plane_ccd(queries[i], contact=True, min_separation=delta)
            assert single.collides == batch.collides[i]
            if single.collides:
                assert np.array_equal(single.contact.normal, batch.contact.normal[i])
                assert np.array_equal(single.contact.point, batch.contact.point[i])
                assert exactccd.CONTACT_KIND_NAMES[batch.contact.kind[i]] == single.contact.kind
            else:
                assert batch.contact.kind[i] == -1
    with pytest.raises(ValueError, match="certified mode"):
        exactccd.point_plane_ccd_batch(queries, contact=True, mode="float_only")
