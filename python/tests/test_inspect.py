"""exactccd.inspect: the command's inspection from Python, checked with fractions (the
coplanarity determinant's sign across each root bracket) and against the pair functions."""

import glob
import os
from fractions import Fraction

import pytest

import exactccd

SAMPLES = os.environ.get("EXACTCCD_SAMPLE_QUERIES",
                         os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data",
                                      "sample-queries"))


def _det(x, t):
    """det[x1 - x0, x2 - x0, x3 - x0] of the four moving points at the rational time t."""
    p = [[x[i][k] + t * (x[i + 4][k] - x[i][k]) for k in range(3)] for i in range(4)]
    u, v, w = ([p[i][k] - p[0][k] for k in range(3)] for i in (1, 2, 3))
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def _sign(x):
    return (x > 0) - (x < 0)


def _files():
    files = sorted(glob.glob(os.path.join(SAMPLES, "*", "*", "*.csv")))
    assert files, SAMPLES
    return files[:6]


def test_inspection_matches_fractions_and_the_pair_functions():
    checked = 0
    for path in _files():
        data = exactccd.read_query_file(path)
        for index in range(0, len(data.truth), 11):
            d = exactccd.inspect(path, index)
            x = [[Fraction(c) for c in p] for p in d["points_exact"]]
            pair = (exactccd.vertex_face_ccd if d["kind"] == "vertex_face"
                    else exactccd.edge_edge_ccd)
            r = pair(*data.queries[index])
            assert d["result"]["collides"] == r.collides
            if r.collides:
                assert (d["result"]["toi_lo"], d["result"]["toi_hi"]) == (r.toi_lo, r.toi_hi)
            else:
                assert d["result"]["toi_lo"] is None
            cubic = d["polynomials"][0]
            for root in cubic["roots"]:
                lo, hi = Fraction(root["lo"]), Fraction(root["hi"])
                same = [o for o in cubic["roots"] if (o["lo"], o["hi"]) == (root["lo"], root["hi"])]
                change = _sign(_det(x, lo)) * _sign(_det(x, hi))
                if not any(o["exact"] for o in same):
                    assert change <= 0 if len(same) % 2 else change >= 0
                if root["exact"]:
                    assert _det(x, Fraction(root["exact"])) == 0
                checked += 1
    assert checked > 20


def test_html_page_is_written_whole_and_never_overwritten(tmp_path):
    path = _files()[0]
    page = tmp_path / "page.html"
    d = exactccd.inspect(path, 0, html=page)
    text = page.read_text()
    assert "exactccd-inspection" in text and "<script src=" not in text
    with pytest.raises(FileExistsError):
        exactccd.inspect(path, 0, html=page)
    assert page.read_text() == text
    exactccd.inspect(path, 1, html=page, force=True)
    assert page.read_text() != text
    assert d["source"]["index"] == 0
    assert [p.name for p in tmp_path.iterdir()] == ["page.html"]  # no temporary left


def test_bad_input(tmp_path):
    path = _files()[0]
    n = len(exactccd.read_query_file(path).truth)
    with pytest.raises(exactccd.InputError, match="past the end"):
        exactccd.inspect(path, n)
    for bad in (-1, 1.5, True, "0"):
        with pytest.raises(ValueError):
            exactccd.inspect(path, bad)
    with pytest.raises(ValueError):
        exactccd.inspect(path, 0, mode="fast")
    with pytest.raises(ValueError):
        exactccd.inspect(path, 0, min_separation=-1.0)
    with pytest.raises(exactccd.InputError):
        exactccd.inspect(tmp_path / "missing.csv", 0, type="vertex-face")


def test_minimum_separation_gives_distance_samples():
    path = _files()[0]
    d = exactccd.inspect(path, 0, min_separation=1e-3)
    assert d["polynomials"] == []
    assert d["distance"]["delta"] == 1e-3
    assert len(d["distance"]["samples"]) > 100
