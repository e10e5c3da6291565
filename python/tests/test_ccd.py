"""One query at a time, on the sample queries: the module's answers equal the truth column and
the C++ command's own per-query answers (exactccd check --out), and its stage tallies."""

import collections
import inspect
import json

import numpy as np
import pytest

import exactccd
from conftest import run

MODES = ["filtered", "exact", "float_only"]


def decide_file(data, mode, t_max=1.0):
    decide = exactccd.vertex_face_ccd if data.type == "vertex-face" else exactccd.edge_edge_ccd
    return [decide(q, mode=mode, t_max=t_max) for q in data.queries]


@pytest.fixture(scope="module")
def sample_data(sample_files):
    return {f: exactccd.read_query_file(f) for f in sample_files}


@pytest.mark.parametrize("mode", ["filtered", "exact"])
def test_certified_modes_equal_truth_column(sample_data, mode):
    for path, data in sample_data.items():
        results = decide_file(data, mode)
        collides = np.array([r.collides for r in results], dtype=bool)
        assert np.array_equal(collides, data.truth), path
        for r in results:
            if r.collides:
                assert 0.0 <= r.toi_lo <= r.toi_hi <= 1.0
            else:
                assert r.toi_lo == r.toi_hi  # the library's no-contact value


def check_out(cli, sample_queries, tmp_path, mode, t_max):
    """Per query (file, index) -> (collides, toi_lo, toi_hi or None), and the JSON report."""
    out = tmp_path / f"out-{mode}-{t_max}.csv"
    args = [cli, "check", sample_queries, "--mode", mode, "--t-max", repr(t_max)]
    done = run(args + ["--out", out, "--json"])
    assert done.returncode in (0, 1), done.stderr
    answers = {}
    for line in out.read_text().splitlines():
        file, index, collides, lo, hi = line.split(",")
        answers[(file, int(index))] = (collides == "1", float(lo) if lo else None,
                                       float(hi) if hi else None)
    return answers, json.loads(done.stdout)


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("t_max", [1.0, 0.5])
def test_equal_to_command_per_query(cli, sample_queries, sample_data, tmp_path, mode, t_max):
    answers, report = check_out(cli, sample_queries, tmp_path, mode, t_max)
    assert len(answers) == sum(len(d.truth) for d in sample_data.values())
    stages_by_file = {entry["file"]: entry["stage_counts"] for entry in report["files"]}
    for path, data in sample_data.items():
        results = decide_file(data, mode, t_max)
        for i, r in enumerate(results):
            collides, lo, hi = answers[(path, i)]
            assert r.collides == collides, (path, i)
            if lo is not None:  # written for every contact (and without one, when it has TOIs)
                # %.17g round-trips, so the TOIs compare exactly.
                assert (r.toi_lo, r.toi_hi) == (lo, hi), (path, i)
            else:
                assert not collides
        stages = collections.Counter(r.stage for r in results)
        expected = {name: count for name, count in stages_by_file[path].items() if count}
        assert dict(stages) == expected, path


def test_arguments_forms_agree(sample_data):
    data = next(d for d in sample_data.values() if d.type == "edge-edge")
    for q in data.queries[:20]:
        as_array = exactccd.edge_edge_ccd(q)
        as_points = exactccd.edge_edge_ccd(*q)
        as_lists = exactccd.edge_edge_ccd(*[list(map(float, p)) for p in q])
        assert as_array == as_points == as_lists
        assert repr(as_array).startswith("CcdResult(collides=")
        assert as_array.stage in exactccd.STAGE_NAMES
        assert exactccd.STAGE_NAMES[as_array.stage_code] == as_array.stage


def test_hand_derived_vertex_face():
    # p falls through the middle of the unit triangle in z = 0: z(t) = 1 - 4t, contact at 1/4.
    tri = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    r = exactccd.vertex_face_ccd([0.25, 0.25, 1], *tri, [0.25, 0.25, -3], *tri)
    assert r.collides and r.toi_lo == r.toi_hi == 0.25
    # Over [0, 0.2] it has not arrived yet.
    assert not exactccd.vertex_face_ccd([0.25, 0.25, 1], *tri, [0.25, 0.25, -3], *tri,
                                        t_max=0.2).collides
    # Passing outside the triangle (x + y > 1): no contact.
    assert not exactccd.vertex_face_ccd([0.75, 0.75, 1], *tri, [0.75, 0.75, -3], *tri).collides


def test_toi_width_is_honoured(sample_data):
    for data in sample_data.values():
        decide = exactccd.vertex_face_ccd if data.type == "vertex-face" else exactccd.edge_edge_ccd
        for q in data.queries[:30]:
            tight = decide(q)
            wide = decide(q, toi_width=1e-3)
            assert wide.collides == tight.collides
            if tight.collides:
                assert wide.toi_lo <= tight.toi_lo <= tight.toi_hi <= wide.toi_hi
                assert wide.toi_hi - wide.toi_lo <= 1e-3


def test_bad_input_raises():
    tri = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    good = [[0.25, 0.25, 1], *tri, [0.25, 0.25, -3], *tri]
    with pytest.raises(ValueError, match="non-finite"):
        exactccd.vertex_face_ccd([np.nan, 0, 1], *good[1:])
    with pytest.raises(ValueError, match="non-finite"):
        exactccd.edge_edge_ccd(*good[:7], [0, np.inf, 0])
    with pytest.raises(ValueError, match="shape"):
        exactccd.vertex_face_ccd(np.zeros((7, 3)))
    with pytest.raises(ValueError):
        exactccd.vertex_face_ccd(*good[:7], [0, 1])
    with pytest.raises(TypeError, match="8 points"):
        exactccd.vertex_face_ccd(*good[:5])
    with pytest.raises(ValueError, match="t_max"):
        exactccd.vertex_face_ccd(good, t_max=-0.5)
    with pytest.raises(ValueError, match="t_max"):
        exactccd.vertex_face_ccd(good, t_max=1.5)
    with pytest.raises(ValueError, match="toi_width"):
        exactccd.vertex_face_ccd(good, toi_width=-1.0)
    with pytest.raises(ValueError, match="mode"):
        exactccd.vertex_face_ccd(good, mode="fast")
    with pytest.raises(ValueError):
        exactccd.vertex_face_ccd([["a", "b", "c"]] + good[1:])


def test_bad_batch_input_names_the_first_bad_query():
    rng = np.random.default_rng(5)
    queries = rng.uniform(-1, 1, size=(5000, 8, 3))
    queries[4321, 6, 2] = np.nan
    queries[1234, 0, 0] = -np.inf
    queries[4999, 7, 1] = np.inf
    for threads in (1, 2, None):
        with pytest.raises(ValueError, match="^query 1234: .*non-finite"):
            exactccd.vertex_face_ccd_batch(queries, threads=threads)
        with pytest.raises(ValueError, match="^query 1234: "):
            exactccd.edge_edge_ccd_batch(queries, threads=threads)
    with pytest.raises(ValueError, match=r"shape \(N, 8, 3\)"):
        exactccd.vertex_face_ccd_batch(np.zeros((4, 3, 8)))
    with pytest.raises(ValueError, match="shape"):
        exactccd.vertex_face_ccd_batch(np.zeros((8, 3)))
    with pytest.raises(ValueError, match="threads"):
        exactccd.vertex_face_ccd_batch(np.zeros((4, 8, 3)), threads=0)
    with pytest.raises(ValueError, match="t_max"):
        exactccd.vertex_face_ccd_batch(np.zeros((4, 8, 3)), t_max=-1.0)
    with pytest.raises(ValueError, match="mode"):
        exactccd.edge_edge_ccd_batch(np.zeros((4, 8, 3)), mode="quick")


def test_mode_names_and_the_old_name_default(sample_data):
    # The canonical names are the command's; "filtered" is the default argument everywhere.
    assert exactccd.MODE_NAMES == ["filtered", "float_only", "exact"]
    for function in (exactccd.vertex_face_ccd, exactccd.edge_edge_ccd,
                     exactccd.vertex_face_ccd_batch, exactccd.edge_edge_ccd_batch):
        assert inspect.signature(function).parameters["mode"].default == "filtered", function
    # "default", the old name of "filtered", is still accepted: the same answers and stages.
    for path, data in sample_data.items():
        named = decide_file(data, "filtered")
        aliased = decide_file(data, "default")
        unnamed = [exactccd.vertex_face_ccd(q) if data.type == "vertex-face"
                   else exactccd.edge_edge_ccd(q) for q in data.queries]
        for a, b, c in zip(named, aliased, unnamed):
            assert (a.collides, a.toi_lo, a.toi_hi, a.stage) == \
                (b.collides, b.toi_lo, b.toi_hi, b.stage) == \
                (c.collides, c.toi_lo, c.toi_hi, c.stage), path
        batch = (exactccd.vertex_face_ccd_batch if data.type == "vertex-face"
                 else exactccd.edge_edge_ccd_batch)
        x, y = batch(data.queries, mode="filtered"), batch(data.queries, mode="default")
        for field in ("collides", "toi_lo", "toi_hi", "stage"):
            assert np.array_equal(getattr(x, field), getattr(y, field)), (path, field)
    # An unknown name: a ValueError listing the valid ones.
    good = np.zeros((8, 3))
    for bad in ("fast", "Filtered", ""):
        with pytest.raises(ValueError) as error:
            exactccd.vertex_face_ccd(good, mode=bad)
        message = str(error.value)
        for name in ("float_only", "filtered", "exact", "default"):
            assert f'"{name}"' in message, message


def test_t_max_zero_is_the_state_at_the_start():
    # A vertex on the triangle at t = 0 leaving it, one 2^-80 above it arriving later, and the
    # same in a batch and with a minimum separation that reaches across the gap.
    touching = np.array([[0.25, 0.25, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0],
                         [0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
    above = touching.copy()
    above[0, 2], above[4, 2] = 2.0 ** -80, -1.0
    r = exactccd.vertex_face_ccd(touching, t_max=0.0)
    assert r.collides and r.toi_lo == 0.0 and r.toi_hi == 0.0 and r.starts_within
    assert exactccd.vertex_face_ccd(touching, toi_width=0.5).starts_within
    late = exactccd.vertex_face_ccd(above, toi_width=1.0)  # [0, w] encloses a later contact
    assert late.collides and not late.starts_within
    assert not exactccd.vertex_face_ccd(above, t_max=0.0).collides
    assert exactccd.vertex_face_ccd(above).collides  # it does arrive within the step
    assert exactccd.vertex_face_ccd(above, t_max=0.0, min_separation=2.0 ** -80).collides
    batch = exactccd.vertex_face_ccd_batch(np.stack([touching, above]), t_max=0.0)
    assert list(batch.collides) == [True, False] and batch.toi_hi[0] == 0.0
