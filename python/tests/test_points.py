"""Point-edge and point-point CCD in Python, in 3D and in the plane: hand-made queries with known
first contacts (exact dyadic times), the 2D form against the same query in z = 0, the batch
against single calls, and bad input."""

import numpy as np
import pytest

import exactccd

INF = float("inf")


def test_point_through_the_middle_of_a_segment_at_one_half():
    # p moves from (0.5, 1, 0) to (0.5, -1, 0) across the segment [(0, 0, 0), (1, 0, 0)].
    r = exactccd.point_edge_ccd((0.5, 1, 0), (0, 0, 0), (1, 0, 0),
                                (0.5, -1, 0), (0, 0, 0), (1, 0, 0))
    assert r.collides and r.toi_lo == r.toi_hi == 0.5
    # Beside the segment's end: never.
    r = exactccd.point_edge_ccd((1.5, 1, 0), (0, 0, 0), (1, 0, 0),
                                (1.5, -1, 0), (0, 0, 0), (1, 0, 0))
    assert not r.collides and r.toi_lo == INF
    # Within 0.5 of the end (1, 0) first when p is at (1.5, 0): t = 1/2 again, from the side.
    r = exactccd.point_edge_ccd((1.5, 1, 0), (0, 0, 0), (1, 0, 0),
                                (1.5, -1, 0), (0, 0, 0), (1, 0, 0), min_separation=0.5)
    assert r.collides and r.toi_lo == r.toi_hi == 0.5


def test_points_meeting_at_one_quarter():
    # p from (0, 0) to (4, 0), q from (1, 0) at rest: they meet at t = 1/4; in 3D and in 2D.
    r3 = exactccd.point_point_ccd((0, 0, 0), (1, 0, 0), (4, 0, 0), (1, 0, 0))
    r2 = exactccd.point_point_ccd((0, 0), (1, 0), (4, 0), (1, 0))
    for r in (r3, r2):
        assert r.collides and r.toi_lo == r.toi_hi == 0.25
    # Passing 2^-60 apart in 2D: no contact, but within 2^-59.
    assert not exactccd.point_point_ccd((0, 2.0 ** -60), (1, 0), (4, 2.0 ** -60), (1, 0)).collides
    assert exactccd.point_point_ccd((0, 2.0 ** -60), (1, 0), (4, 2.0 ** -60), (1, 0),
                                    min_separation=2.0 ** -59).collides


def _random_point_queries(rng, n, k, dim):
    # A coarse dyadic grid: touching, collinear and coincident configurations are common.
    return rng.integers(-4, 5, size=(n, k, dim)).astype(np.float64) / 4


@pytest.mark.parametrize("function, batch, k", [
    (exactccd.point_edge_ccd, exactccd.point_edge_ccd_batch, 6),
    (exactccd.point_point_ccd, exactccd.point_point_ccd_batch, 4),
])
def test_2d_is_the_query_in_z0_and_the_batch_equals_single_calls(function, batch, k):
    rng = np.random.default_rng(11)
    queries = _random_point_queries(rng, 400, k, 2)
    in_z0 = np.concatenate([queries, np.zeros((400, k, 1))], axis=2)
    collided = 0
    for options in ({}, {"min_separation": 0.125}, {"t_max": 0.5}, {"mode": "exact"}):
        got = batch(queries, **options)
        got3 = batch(in_z0, **options)
        assert np.array_equal(got.collides, got3.collides)
        assert np.array_equal(got.toi_lo, got3.toi_lo) and np.array_equal(got.toi_hi, got3.toi_hi)
        for i in range(0, 400, 7):
            single = function(queries[i], **options)
            assert (single.collides, single.toi_lo, single.toi_hi) == \
                (got.collides[i], got.toi_lo[i], got.toi_hi[i])
            assert function(*queries[i], **options).toi_lo == single.toi_lo
        collided += int(got.collides.sum())
    assert 40 < collided < 1500  # both answers well represented


def test_bad_point_input_is_named():
    with pytest.raises(ValueError, match=r"non-finite coordinate in e1_t1"):
        exactccd.point_edge_ccd((0, 0), (0, 0), (1, 0), (0, 0), (0, 0), (np.nan, 0))
    q = np.zeros((3, 4, 3))
    q[2, 1, 0] = np.inf
    with pytest.raises(ValueError, match=r"query 2: exactccd: non-finite coordinate in q_t0"):
        exactccd.point_point_ccd_batch(q)
    with pytest.raises(ValueError, match=r"shape \(6, 3\) or \(6, 2\), not \(6, 4\)"):
        exactccd.point_edge_ccd(np.zeros((6, 4)))
    with pytest.raises(ValueError, match="must all be 3-vectors or all 2-vectors"):
        exactccd.point_point_ccd((0, 0), (1, 0, 0), (0, 0), (1, 0))
    with pytest.raises(TypeError, match="the 4 points"):
        exactccd.point_point_ccd((0, 0), (1, 0))
    with pytest.raises(TypeError, match="point_edge_ccd_batch.*t_max"):
        exactccd.point_edge_ccd_batch(np.zeros((2, 6, 2)), t_max="1")


def test_query_files_of_the_point_kinds(tmp_path):
    # A point-edge file in the plane (5 columns) and a point-plane file, read into the arrays the
    # point functions take; every query decided as its truth says.
    pe2d = tmp_path / "pe2d.csv"
    pe2d.write_text("1,2,1,1,1\n0,1,0,1,1\n1,1,0,1,1\n1,2,-1,1,1\n0,1,0,1,1\n1,1,0,1,1\n"
                    "3,2,1,1,0\n0,1,0,1,0\n1,1,0,1,0\n3,2,-1,1,0\n0,1,0,1,0\n1,1,0,1,0\n")
    data = exactccd.read_query_file(pe2d, "pe2d")
    assert data.queries.shape == (2, 6, 2) and data.truth.tolist() == [True, False]
    assert data.type == "pe2d"
    batch = exactccd.point_edge_ccd_batch(data.queries)
    assert batch.collides.tolist() == [True, False] and batch.toi_lo[0] == 0.5
    pl = tmp_path / "pl.csv"
    pl.write_text("5,1,7,1,1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n"
                  "-3,1,2,1,-1,1,1\n0,1,0,1,0,1,1\n0,1,0,1,1,1,1\n")
    data = exactccd.read_query_file(pl, "pl")
    assert data.queries.shape == (1, 6, 3)
    assert exactccd.point_plane_ccd(data.queries[0]).toi_lo == 0.5
    with pytest.raises(exactccd.InputError, match="expected 7 comma-separated columns"):
        exactccd.read_query_file(pe2d, "pe")


def test_point_kind_files_round_trip(tmp_path):
    # Random queries of each kind written exactly and read back bit for bit; the decisions on
    # the file equal those on the arrays (exactccd check reads the same files).
    rng = np.random.default_rng(9)
    for kind, shape in (("pe", (20, 6, 3)), ("pe2d", (20, 6, 2)), ("pp", (20, 4, 3)),
                        ("pp2d", (20, 4, 2)), ("pl", (20, 6, 3))):
        queries = rng.uniform(-1, 1, shape) * 10.0 ** rng.integers(-5, 5, (shape[0], 1, 1))
        truth = rng.integers(0, 2, shape[0])
        path = tmp_path / f"{kind}.csv"
        exactccd.write_query_file(path, queries, truth, kind=kind)
        data = exactccd.read_query_file(path, kind)
        assert (data.queries == queries).all() and (data.truth == truth.astype(bool)).all()
    with pytest.raises(ValueError, match="kind must be one of"):
        exactccd.write_query_file(tmp_path / "x.csv", queries, truth, kind="vf")
    with pytest.raises(ValueError, match="queries"):
        exactccd.write_query_file(tmp_path / "y.csv", np.zeros((2, 6, 3)), [0, 0], kind="pp")
