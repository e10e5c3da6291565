"""The collision-free step of barrier methods in Python (C++: exactccd/step.hpp): points whose
distance is a closed form (exact with fractions), the rational exact path as the independent
check of [0, step], every kind (vertex-face, edge-edge, point-edge and point-point in 3D and
2D, rigid), and bad options."""

from fractions import Fraction

import numpy as np
import pytest

import exactccd


def _point_point_distance2(p0, q0, p1, q1, t):
    """|p(t) - q(t)|^2 at the rational t, exactly."""
    t = Fraction(t)
    return sum(((1 - t) * Fraction(a) + t * Fraction(c) - (1 - t) * Fraction(b) - t * Fraction(d))
               ** 2 for a, b, c, d in zip(p0, q0, p1, q1))


@pytest.mark.parametrize("delta", [0.0, 1e-3, 0.25])
@pytest.mark.parametrize("s", [0.8, 0.5, 1.0])
def test_point_point_step_keeps_the_effective_separation(delta, s):
    rng = np.random.default_rng(7)
    limited = 0
    for n in range(60):
        # Dyadic coordinates: p1 = 2 q0 - p0 is exact, p passes through q at t = 1/2 (n even),
        # or near it (n odd).
        p0, q0 = rng.integers(-8, 9, 3) / 8, rng.integers(-8, 9, 3) / 8
        p1 = 2 * q0 - p0 + (rng.uniform(-0.1, 0.1, 3) if n % 2 else 0)
        r = exactccd.point_point_collision_free_step(p0, q0, p1, q0, min_separation=delta,
                                                     conservative_rescaling=s)
        assert 0.0 <= r.step <= 1.0
        d0 = _point_point_distance2(p0, q0, p1, q0, 0)
        assert r.starts_within == (d0 <= Fraction(delta) ** 2)
        if r.starts_within:
            assert r.step == 0.0 and r.limited
            continue
        limited += r.limited
        assert r.effective_separation >= delta
        if s == 1.0:
            assert r.effective_separation == delta
        # The distance at rational instants of [0, step], its end included (the distance of a
        # moving point pair is convex in t, so the ends bound it; the midpoint is checked too).
        for k in range(5):
            d2 = _point_point_distance2(p0, q0, p1, q0, Fraction(r.step) * k / 4)
            assert d2 >= Fraction(r.effective_separation) ** 2
            assert d2 > Fraction(delta) ** 2
        # And the rational exact path: never within delta on [0, step].
        assert not exactccd.point_point_ccd(p0, q0, p1, q0, t_max=r.step, mode="exact",
                                            min_separation=delta).collides
    assert limited >= 30


def test_every_kind_is_certified_by_the_exact_path():
    rng = np.random.default_rng(11)
    checks = [
        (exactccd.vertex_face_collision_free_step, exactccd.vertex_face_ccd, 8, 3),
        (exactccd.edge_edge_collision_free_step, exactccd.edge_edge_ccd, 8, 3),
        (exactccd.point_edge_collision_free_step, exactccd.point_edge_ccd, 6, 3),
        (exactccd.point_edge_collision_free_step, exactccd.point_edge_ccd, 6, 2),
        (exactccd.point_point_collision_free_step, exactccd.point_point_ccd, 4, 2),
    ]
    for step, ccd, rows, dim in checks:
        limited = 0
        for n in range(40):
            x0 = rng.uniform(-1, 1, (rows // 2, dim))
            x1 = x0 + rng.uniform(-0.1, 0.1, (rows // 2, dim))
            # The first point heads through the middle of the other primitive.
            other = x0[2:] if step is exactccd.edge_edge_collision_free_step else x0[1:]
            x1[0] = 2 * other.mean(axis=0) - x0[0]
            if step is exactccd.edge_edge_collision_free_step:
                x1[1] = x0[1] + (x1[0] - x0[0])
            points = np.concatenate([x0, x1])
            delta = 0.05 if n % 2 else 0.0
            r = step(points, min_separation=delta)
            if r.starts_within:
                assert r.step == 0.0
                assert ccd(points, t_max=0.0, mode="exact", min_separation=delta).collides
                continue
            limited += r.limited
            assert not ccd(points, t_max=r.step, mode="exact", min_separation=delta).collides
            whole = ccd(points, mode="exact", min_separation=r.effective_separation)
            assert whole.collides == r.limited
            if r.limited:
                assert whole.toi_hi >= r.step
            else:
                assert r.step == 1.0
        assert limited > 15, step.__name__


def test_rigid_steps():
    turn = exactccd.RigidMotion(pivot=(0, 0, 0), cayley=(0, 0, 0.3), translation=(0, 0, -1))
    still = exactccd.RigidMotion()
    r = exactccd.rigid_vertex_face_collision_free_step(
        np.array([[0.25, 0.25, 0.5], [-1, -1, 0], [2, -1, 0], [-1, 2, 0]]), turn, still,
        min_separation=1e-3)
    assert r.limited and 0 < r.step < 1 and r.effective_separation > 1e-3
    r = exactccd.rigid_edge_edge_collision_free_step(
        np.array([[-1, 0, 0.5], [1, 0, 0.5], [0, -1, 0], [0, 1, 0]]), turn, still)
    assert r.limited and 0 < r.step < 1
    assert repr(r).startswith("StepResult(step=")


def test_bad_options_and_points_are_clear_errors():
    points = np.zeros((8, 3))
    points[0] = points[4] = (0.25, 0.25, 1)
    points[2] = points[6] = (1, 0, 0)
    points[3] = points[7] = (0, 1, 0)
    with pytest.raises(ValueError, match=r"conservative_rescaling must lie in \(0, 1\], got 0"):
        exactccd.vertex_face_collision_free_step(points, conservative_rescaling=0.0)
    with pytest.raises(ValueError, match=r"t_max must lie in \[0, 1\], got 2"):
        exactccd.vertex_face_collision_free_step(points, t_max=2)
    with pytest.raises(TypeError, match="min_separation"):
        exactccd.vertex_face_collision_free_step(points, min_separation="big")
    points[1, 0] = np.nan
    with pytest.raises(ValueError, match="non-finite coordinate in a_t0"):
        exactccd.vertex_face_collision_free_step(points)


def test_max_margin_caps_the_margin_as_tight_inclusion_does():
    # Points 1 apart meeting at t = 1/2: 0.4 by the rule, just before 0.5 - 5e-5 with the cap.
    args = ((0, 0, 0), (1, 0, 0), (2, 0, 0), (1, 0, 0))
    assert exactccd.point_point_collision_free_step(*args).step == pytest.approx(0.4, abs=1e-12)
    r = exactccd.point_point_collision_free_step(*args, max_margin=1e-4)
    assert r.effective_separation == 1e-4
    assert r.step == pytest.approx(0.5 - 0.5e-4, abs=1e-12) and r.step < 0.5 - 0.5e-4
    with pytest.raises(ValueError, match="max_margin must be >= 0"):
        exactccd.point_point_collision_free_step(*args, max_margin=-1.0)
