"""exactccd.dask on a 2-worker local cluster of processes: the totals and tables equal what
`exactccd check` / `exactccd grade` print for the same files."""

import io
import json

import distributed  # python3-distributed: ctest adds this test only where it is installed
import numpy as np
import pytest

import exactccd
from conftest import run
from exactccd import dask as exactccd_dask


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            yield client


def without_timing(table):
    """The table without its us/query column (found by its header), the only part that depends
    on the run."""
    lines = table.splitlines()
    k = lines[1].split().index("us/query")
    out = [lines[0]]
    for line in lines[1:]:
        fields = line.split()
        out.append(" ".join(fields[:k] + fields[k + 1:]))
    return out


def without_seconds(report):
    report = json.loads(report) if isinstance(report, str) else report
    report.pop("seconds", None)
    for entry in report.get("files", []):
        entry.pop("seconds", None)
    return report


@pytest.mark.parametrize("mode", ["filtered", "exact"])
@pytest.mark.parametrize("shard", [None, 100])
def test_check_equals_command(client, cli, sample_queries, mode, shard):
    table = run([cli, "check", sample_queries, "--mode", mode])
    report_json = run([cli, "check", sample_queries, "--mode", mode, "--json"])
    assert table.returncode == 0 and report_json.returncode == 0, table.stderr

    calls = []
    out = io.StringIO()
    report = exactccd_dask.check([str(sample_queries)], mode=mode, cluster=client, shard=shard,
                                 progress=lambda done, total: calls.append((done, total)), out=out)
    assert without_timing(out.getvalue()) == without_timing(table.stdout)
    assert without_timing(report.table) == without_timing(table.stdout)
    expected = json.loads(report_json.stdout)
    assert without_seconds(report.json) == without_seconds(expected)
    assert report.total["queries"] == expected["queries"]
    assert report.disagreements == 0
    assert calls[-1][0] == calls[-1][1] == len(calls) and len(calls) >= 24

    printed_json = io.StringIO()
    exactccd_dask.check(str(sample_queries), mode=mode, cluster=client, shard=shard,
                        progress=False, json=True, out=printed_json)
    assert without_seconds(printed_json.getvalue()) == without_seconds(expected)


def test_relative_paths_named_as_given(client, cli, sample_queries, monkeypatch):
    monkeypatch.chdir(sample_queries.parent)
    table = run([cli, "check", sample_queries.name, "--mode", "float_only"])
    assert table.returncode in (0, 1), table.stderr  # 1: float_only errs on some queries
    report = exactccd_dask.check(sample_queries.name, mode="float_only", cluster=client,
                                 progress=False, out=None)
    assert without_timing(report.table) == without_timing(table.stdout)
    assert report.files[0]["file"].startswith(sample_queries.name + "/")


def test_check_arrays_equal_files(client, sample_files):
    arrays = []
    for path in sample_files:
        data = exactccd.read_query_file(path)
        arrays.append((path, data.type, data.queries, data.truth))
    by_arrays = exactccd_dask.check_arrays(arrays, cluster=client, shard=50, progress=False,
                                           out=None)
    # "default", the old name of "filtered", is accepted and reported as "filtered".
    by_files = exactccd_dask.check(sample_files, mode="default", cluster=client, progress=False,
                                   out=None)
    assert by_arrays.mode == by_files.mode == "filtered"
    assert without_timing(by_arrays.table) == without_timing(by_files.table)


def test_grade_equals_command(client, cli, sample_files, tmp_path):
    path = next(f for f in sample_files if "vertex-face" in f and "unit-tests" in f)
    data = exactccd.read_query_file(path)
    batch = exactccd.vertex_face_ccd_batch(data.queries)
    # Answers: the exact ones, then some flipped and a late toi, so that every category shows.
    lines = [f"1,{lo!r}" if c else "0" for c, lo in zip(batch.collides, batch.toi_lo)]
    colliding = np.flatnonzero(batch.collides)
    free = np.flatnonzero(~batch.collides)
    lines[colliding[0]] = "0"
    lines[free[0]] = "1"
    lines[colliding[1]] = f"1,{min(1.0, batch.toi_hi[colliding[1]] + 0.25)!r}"
    answers = tmp_path / "answers.txt"
    answers.write_text("\n".join(lines) + "\n")

    for json_flag in (False, True):
        command = run([cli, "grade", "--queries", path, "--answers", answers]
                      + (["--json"] if json_flag else []))
        assert command.returncode == 1, command.stderr
        for shard in (None, 30):
            out = io.StringIO()
            report = exactccd_dask.grade((path, str(answers)), cluster=client, shard=shard,
                                         progress=False, json=json_flag, out=out)
            assert out.getvalue() == command.stdout
            assert not report.all_good
    assert report.findings[0]["false_negatives"] == [int(colliding[0])]


def test_errors_reach_the_caller(client, tmp_path):
    bad = tmp_path / "vertex-face" / "bad.csv"
    bad.parent.mkdir()
    bad.write_text("1,2,3\n")
    with pytest.raises(exactccd.InputError, match="bad.csv:1"):
        exactccd_dask.check([str(bad)], cluster=client, progress=False, out=None)
    untyped = tmp_path / "untyped.csv"
    untyped.write_text("0,1,0,1,0,1,0\n" * 8)
    with pytest.raises(exactccd.InputError, match="query type"):
        exactccd_dask.check([str(untyped)], cluster=client, progress=False, out=None)
    with pytest.raises(ValueError, match="t_max"):
        exactccd_dask.check([str(bad)], t_max=2.0, cluster=client, progress=False, out=None)
    with pytest.raises(ValueError, match='mode must be "float_only", "filtered" or "exact"'):
        exactccd_dask.check([str(bad)], mode="fast", cluster=client, progress=False, out=None)
