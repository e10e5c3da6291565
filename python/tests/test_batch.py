"""The batch functions equal the one-by-one loop, serially and on 2 threads."""

import numpy as np
import pytest

import exactccd

SINGLE = {"vertex-face": exactccd.vertex_face_ccd, "edge-edge": exactccd.edge_edge_ccd}
BATCH = {"vertex-face": exactccd.vertex_face_ccd_batch, "edge-edge": exactccd.edge_edge_ccd_batch}


def loop(kind, queries, **options):
    results = [SINGLE[kind](q, **options) for q in queries]
    return exactccd.BatchResult(
        np.array([r.collides for r in results], dtype=bool),
        np.array([r.toi_lo for r in results], dtype=np.float64),
        np.array([r.toi_hi for r in results], dtype=np.float64),
        np.array([r.stage_code for r in results], dtype=np.uint8))


def assert_same(batch, expected):
    assert batch.collides.dtype == np.bool_ and batch.toi_lo.dtype == np.float64
    assert batch.toi_hi.dtype == np.float64 and batch.stage.dtype == np.uint8
    for got, want in zip(batch, expected):
        assert got.shape == want.shape
        assert np.array_equal(got, want)


def random_queries(rng, n):
    """Random motions, plus families that reach the filters' and the exact path's cases:
    coplanar, small, and sharing coordinates."""
    q = rng.uniform(-1, 1, size=(n, 8, 3))
    q[n // 4: n // 2, :, 2] = 0.0                         # everything in the plane z = 0
    q[n // 2: 3 * n // 4] *= 1e-9                         # tiny and crowded
    q[3 * n // 4:, 4:] = q[3 * n // 4:, :4]               # at rest
    q[3 * n // 4::2, 0, :] = q[3 * n // 4::2, 1, :]       # a vertex on another
    return q


@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge"])
@pytest.mark.parametrize("threads", [1, 2, None])
@pytest.mark.parametrize("mode", ["filtered", "float_only"])
def test_batch_equals_loop_on_random_queries(kind, threads, mode):
    queries = random_queries(np.random.default_rng(11), 400)
    assert_same(BATCH[kind](queries, threads=threads, mode=mode), loop(kind, queries, mode=mode))


@pytest.mark.parametrize("threads", [1, 2])
def test_batch_equals_loop_on_sample_queries(sample_files, threads):
    for path in sample_files:
        data = exactccd.read_query_file(path)
        for options in ({}, {"t_max": 0.5, "toi_width": 1e-6}):
            assert_same(BATCH[data.type](data.queries, threads=threads, **options),
                        loop(data.type, data.queries, **options))


def test_batch_converts_its_input(sample_files):
    data = exactccd.read_query_file(sample_files[0])
    reference = BATCH[data.type](data.queries)
    fortran = np.asfortranarray(data.queries)
    strided = np.repeat(data.queries, 2, axis=0)[::2]
    assert not fortran.flags.c_contiguous and not strided.flags.c_contiguous
    for converted in (fortran, strided, data.queries.tolist()):
        assert_same(BATCH[data.type](converted), reference)


@pytest.mark.parametrize("threads", [0, -1, 65537])
def test_batch_refuses_a_bad_thread_count(threads):
    # 65537 crashed the process inside TBB's task arena before it was refused.
    with pytest.raises(ValueError, match="threads"):
        exactccd.vertex_face_ccd_batch(np.zeros((1, 8, 3)), threads=threads)


def test_empty_batch():
    result = exactccd.vertex_face_ccd_batch(np.zeros((0, 8, 3)))
    assert all(len(a) == 0 for a in result)
