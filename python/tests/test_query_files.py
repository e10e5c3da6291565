"""Reading and writing benchmark CSV files; bad input raises, never crashes."""

import os
from fractions import Fraction as F

import numpy as np
import pytest

import exactccd


def test_write_then_read_is_exact(tmp_path):
    rng = np.random.default_rng(3)
    queries = rng.normal(size=(50, 8, 3)) * np.logspace(-300, 300, 50)[:, None, None]
    queries[0, 0, 0] = -0.0
    queries[1, 1, 1] = 5e-324  # the smallest subnormal
    truth = rng.integers(0, 2, size=50).astype(bool)
    path = tmp_path / "vertex-face" / "data.csv"
    path.parent.mkdir()
    exactccd.write_query_file(path, queries, truth)
    back = exactccd.read_query_file(path)
    assert back.type == "vertex-face"
    assert np.array_equal(back.queries, queries) and np.array_equal(back.truth, truth)
    exact = exactccd.read_query_file_exact(path)
    assert exact.queries[1][1][1] == F(5e-324)
    assert [d for d in os.listdir(path.parent)] == ["data.csv"]  # no temporary file left


def test_writes_the_benchmark_format(tmp_path):
    queries = np.zeros((1, 8, 3))
    queries[0, 0] = [0.5, -3.0, 0.1]
    path = tmp_path / "q.csv"
    exactccd.write_query_file(path, queries, [True])
    lines = path.read_text().splitlines()
    assert len(lines) == 8
    assert lines[0] == f"1,2,-3,1,{F(0.1).numerator},{F(0.1).denominator},1"
    assert lines[1] == "0,1,0,1,0,1,1"


def test_refuses_to_overwrite(tmp_path):
    path = tmp_path / "mine.csv"
    path.write_text("precious\n")
    queries = np.ones((2, 8, 3))
    with pytest.raises(FileExistsError, match="overwrite=True"):
        exactccd.write_query_file(path, queries, [0, 1])
    assert path.read_text() == "precious\n"
    assert os.listdir(tmp_path) == ["mine.csv"]
    exactccd.write_query_file(path, queries, [0, 1], overwrite=True)
    assert np.array_equal(exactccd.read_query_file(path, "vf").queries, queries)


def test_bad_queries_write_nothing(tmp_path):
    path = tmp_path / "q.csv"
    queries = np.ones((3, 8, 3))
    queries[2, 5, 1] = np.inf
    with pytest.raises(ValueError, match="query 2"):
        exactccd.write_query_file(path, queries, [0, 0, 0])
    with pytest.raises(ValueError, match="truth"):
        exactccd.write_query_file(path, np.ones((3, 8, 3)), [0, 0])
    with pytest.raises(ValueError, match="shape"):
        exactccd.write_query_file(path, np.ones((3, 7, 3)), [0, 0, 0])
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("content, message", [
    ("1,2,3\n", "column"),
    ("1,0,0,1,0,1,0\n" * 8, "denominator"),
    ("x,1,0,1,0,1,0\n" + "0,1,0,1,0,1,0\n" * 7, "integer"),
    ("nan,1,0,1,0,1,0\n" + "0,1,0,1,0,1,0\n" * 7, ""),
    ("0,1,0,1,0,1,0\n" * 7, ""),
    ("0,1,0,1,0,1,2\n" * 8, "truth"),
])
def test_malformed_file_raises_input_error(tmp_path, content, message):
    path = tmp_path / "bad.csv"
    path.write_text(content)
    with pytest.raises(exactccd.InputError, match=message) as error:
        exactccd.read_query_file(path, "vf")
    assert isinstance(error.value, ValueError)
    assert "bad.csv" in str(error.value)
    with pytest.raises(exactccd.InputError):
        exactccd.read_query_file_exact(path, "ee")


def test_missing_file_and_unknown_type(tmp_path):
    with pytest.raises(exactccd.InputError, match="No such file"):
        exactccd.read_query_file(tmp_path / "none.csv", "vf")
    (tmp_path / "q.csv").write_text("0,1,0,1,0,1,0\n" * 8)
    with pytest.raises(exactccd.InputError, match="type"):
        exactccd.read_query_file(tmp_path / "q.csv")
    with pytest.raises(ValueError, match="type"):
        exactccd.read_query_file(tmp_path / "q.csv", "triangle")
    with pytest.raises(exactccd.InputError):
        exactccd.find_query_files(str(tmp_path / "none"))


def test_coordinate_not_a_double(tmp_path):
    path = tmp_path / "edge-edge" / "third.csv"
    path.parent.mkdir()
    path.write_text("0,1,0,1,0,1,1\n" * 3 + "1,3,0,1,0,1,1\n" + "0,1,0,1,0,1,1\n" * 4)
    with pytest.raises(exactccd.InputError, match=r"third.csv:4: .*not exactly a double"):
        exactccd.read_query_file(path)
    exact = exactccd.read_query_file_exact(path)
    assert exact.type == "edge-edge" and exact.queries[0][3] == (F(1, 3), 0, 0)
    assert exact.truth.tolist() == [True]


def test_query_type_from_path_and_listing(sample_queries):
    assert exactccd.query_type_from_path("a/vertex-face/b.csv") == "vertex-face"
    assert exactccd.query_type_from_path("a/edge-edge/b.csv") == "edge-edge"
    assert exactccd.query_type_from_path("a/b.csv") is None
    files = exactccd.find_query_files(str(sample_queries))
    assert files == sorted(files) and all(f.endswith(".csv") for f in files)
