"""The rational oracle API: exact on Fractions, equal to the double API on doubles."""

import math
from fractions import Fraction as F

import pytest

import exactccd

TRIANGLE = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]


def vertex_face(p0, p1, triangle0, triangle1=None):
    triangle1 = triangle0 if triangle1 is None else triangle1
    return [p0, *triangle0, p1, *triangle1]


def test_agrees_with_double_api_on_sample_queries(sample_files):
    for path in sample_files:
        doubles = exactccd.read_query_file(path)
        exact = exactccd.read_query_file_exact(path)
        assert exact.type == doubles.type and (exact.truth == doubles.truth).all()
        decide = exactccd.vertex_face_ccd if doubles.type == "vertex-face" else exactccd.edge_edge_ccd
        for k, (q, points) in enumerate(zip(doubles.queries, exact.queries)):
            # The Fractions are exactly the doubles read.
            assert [[F(float(x)) for x in p] for p in q] == [list(p) for p in points]
            for options in ({}, {"t_max": 0.5}):
                rational = exactccd.exact_ccd(points, doubles.type, **options)
                double = decide(q, mode="exact", **options)
                assert rational == double, (path, k)
                assert rational.collides == decide(q, **options).collides
                assert rational.stage == "exact"


def test_one_third_is_exact():
    # p = (1/3, 1/3, z) inside the unit triangle, z(t) = 1 - 3t: contact exactly at t* = 1/3,
    # which is no double, so [toi_lo, toi_hi] are the two consecutive doubles around it.
    third = F(1, 3)
    r = exactccd.exact_ccd(vertex_face([third, third, 1], [third, third, -2], TRIANGLE), "vf")
    assert r.collides
    assert F(r.toi_lo) < third < F(r.toi_hi)
    assert math.nextafter(r.toi_lo, 1.0) == r.toi_hi
    # Over [0, t_max] with t_max just below 1/3: no contact yet.
    below = 1 / 3  # rounds down: the double just below 1/3
    assert F(below) < third
    assert not exactccd.exact_ccd(vertex_face([third, third, 1], [third, third, -2], TRIANGLE),
                                  "vertex-face", t_max=below).collides


def test_rational_boundary_differs_from_rounded_doubles():
    # p = (1/10, 2/10) lies exactly on the hypotenuse x + y = 3/10 of the triangle
    # (0,0), (3/10,0), (0,3/10): the closed triangle is hit when z(t) = 1 - 3t reaches 0.
    # Rounded to doubles, 0.1 + 0.2 > 0.3 exactly (0.3000000000000000166... > 0.2999999999999999888...):
    # the rounded vertex passes just outside, and no contact is the exact answer there.
    tri = [[0, 0, 0], [F(3, 10), 0, 0], [0, F(3, 10), 0]]
    exact = exactccd.exact_ccd(vertex_face([F(1, 10), F(2, 10), 1], [F(1, 10), F(2, 10), -2], tri), "vf")
    assert exact.collides and F(exact.toi_lo) < F(1, 3) < F(exact.toi_hi)

    assert F(0.1) + F(0.2) > F(0.3)
    rounded = [[0.0, 0.0, 0.0], [0.3, 0.0, 0.0], [0.0, 0.3, 0.0]]
    double = exactccd.vertex_face_ccd([0.1, 0.2, 1.0], *rounded, [0.1, 0.2, -2.0], *rounded)
    as_fractions = exactccd.exact_ccd(
        vertex_face([F(0.1), F(0.2), 1], [F(0.1), F(0.2), -2], [[F(x) for x in p] for p in rounded]),
        "vf")
    assert not double.collides and not as_fractions.collides


def test_edge_edge_fractions():
    # Edge a along x at y = 0, z = 0; edge b along y at x = 1/3 (inside a), z from 1 to -1/2:
    # they cross when z(t) = 1 - 3t/2 = 0, t* = 2/3 (no double).
    points = [[0, 0, 0], [1, 0, 0], [F(1, 3), -1, 1], [F(1, 3), 1, 1],
              [0, 0, 0], [1, 0, 0], [F(1, 3), -1, F(-1, 2)], [F(1, 3), 1, F(-1, 2)]]
    r = exactccd.exact_ccd(points, "edge-edge")
    assert r.collides and F(r.toi_lo) < F(2, 3) < F(r.toi_hi)
    # Edge b beyond the end of edge a (x = 4/3 > 1): no contact.
    beyond = [[F(4, 3) if x == F(1, 3) else x for x in p] for p in points]
    assert not exactccd.exact_ccd(beyond, "ee").collides


def test_bad_rational_input():
    third = F(1, 3)
    good = vertex_face([third, third, 1], [third, third, -2], TRIANGLE)
    with pytest.raises(TypeError, match="float"):
        exactccd.exact_ccd(vertex_face([0.5, third, 1], [third, third, -2], TRIANGLE), "vf")
    with pytest.raises(ValueError, match="8 points"):
        exactccd.exact_ccd(good[:7], "vf")
    with pytest.raises(ValueError, match="3 coordinates"):
        exactccd.exact_ccd([[0, 0]] + good[1:], "vf")
    with pytest.raises(ValueError, match="type"):
        exactccd.exact_ccd(good, "triangle")
    with pytest.raises(ValueError, match="t_max"):
        exactccd.exact_ccd(good, "vf", t_max=-1.0)
    with pytest.raises(ValueError, match="toi_width"):
        exactccd.exact_ccd(good, "vf", toi_width=float("nan"))
    # Huge integers convert exactly (no float on the way, no limit on decimal digits).
    big = 10 ** 5000
    far = vertex_face([big, big, big], [big, big, big + 1], TRIANGLE)
    assert not exactccd.exact_ccd(far, "vf").collides
