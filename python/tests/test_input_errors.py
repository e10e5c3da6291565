"""Bad input to the Python module gets a one-line error that names the value and what is
allowed (issue 28, item 6), and a file of the user's is never touched by a refused call."""

import os
import stat

import numpy as np
import pytest

import exactccd

_TRIANGLE = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])


def _query():
    q = np.zeros((1, 8, 3))
    q[0, 1], q[0, 2], q[0, 5], q[0, 6] = [1, 0, 0], [0, 1, 0], [1, 0, 0], [0, 1, 0]
    return q


def _one_line_naming(error, *parts):
    text = str(error.value)
    assert "\n" not in text, text
    assert "_exactccd" not in text and "Invoked with" not in text, text
    for part in parts:
        assert part in text, (part, text)


@pytest.mark.parametrize("dtype", [np.uint64, np.uint32, np.int64])
def test_face_indices_beyond_int32_are_named_as_given(dtype):
    largest = np.iinfo(dtype).max
    with pytest.raises(ValueError) as error:
        exactccd.Scene().add_static_mesh(_TRIANGLE, np.array([[0, 1, largest]], dtype=dtype))
    _one_line_naming(error, str(largest), "out of range")


def test_negative_face_index_is_named():
    with pytest.raises(ValueError) as error:
        exactccd.Scene().add_static_mesh(_TRIANGLE, np.array([[0, 1, -3]]))
    _one_line_naming(error, "-3", "out of range")


@pytest.mark.parametrize("key", ["pivot", "translation", "cayley"])
@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_rigid_motion_refuses_non_finite_vectors_at_once(key, bad):
    with pytest.raises(ValueError) as error:
        exactccd.RigidMotion(**{key: (bad, 0.0, 0.0)})
    _one_line_naming(error, key, "finite")


def test_turn_about_huge_and_tiny_axes():
    unit = exactccd.RigidMotion.turn((0, 0, 0), (0, 0, 1), 0.5).cayley
    for axis in [(0, 0, 1e308), (0, 0, 1e-320), (0, 0, 5e-324)]:
        assert np.array_equal(exactccd.RigidMotion.turn((0, 0, 0), axis, 0.5).cayley, unit)
    diagonal = exactccd.RigidMotion.turn((0, 0, 0), (1e308, 1e308, 1e308), 0.5).cayley
    assert np.all(np.isfinite(diagonal)) and diagonal[0] == diagonal[1] == diagonal[2] > 0
    with pytest.raises(ValueError, match="non-zero axis"):
        exactccd.RigidMotion.turn((0, 0, 0), (0, 0, 0), 0.5)


@pytest.mark.parametrize("truth", [[2], [0.5], [-1], [np.nan]])
def test_write_query_file_refuses_truth_other_than_0_or_1(tmp_path, truth):
    path = tmp_path / "q.csv"
    with pytest.raises(ValueError) as error:
        exactccd.write_query_file(path, _query(), truth)
    _one_line_naming(error, "truth[0]", "0 (no collision) or 1 (collision)")
    assert os.listdir(tmp_path) == []


def test_write_query_file_on_a_folder_names_the_folder(tmp_path):
    folder = tmp_path / "data"
    folder.mkdir()
    for overwrite in (False, True):
        with pytest.raises(IsADirectoryError, match="is a folder, not a file"):
            exactccd.write_query_file(folder, _query(), [1], overwrite=overwrite)
    assert folder.is_dir() and os.listdir(folder) == []


def test_write_query_file_never_replaces_a_fifo(tmp_path):
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    with pytest.raises(FileExistsError, match="not a regular file"):
        exactccd.write_query_file(fifo, _query(), [1], overwrite=True)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_paths_with_a_nul_are_refused_not_cut(tmp_path):
    # Cut at the NUL, the path would name "q.csv": it exists, and must be neither read nor
    # replaced.
    existing = tmp_path / "q.csv"
    exactccd.write_query_file(existing, _query(), [1])
    before = existing.read_bytes()
    bad = str(existing) + "\0.extra"
    with pytest.raises(ValueError, match="NUL"):
        exactccd.write_query_file(bad, _query(), [0], overwrite=True)
    with pytest.raises(ValueError, match="NUL"):
        exactccd.read_query_file(bad, "vf")
    with pytest.raises(ValueError, match="NUL"):
        exactccd.read_query_file_exact(bad, "vf")
    assert existing.read_bytes() == before


@pytest.mark.parametrize("call, parts", [
    (lambda: exactccd.vertex_face_ccd(_query()[0], mode=5), ["vertex_face_ccd()", "mode", "int"]),
    (lambda: exactccd.edge_edge_ccd(_query()[0], t_max="1"), ["edge_edge_ccd()", "t_max", "str"]),
    (lambda: exactccd.vertex_face_ccd(_query()[0], min_separation=None),
     ["vertex_face_ccd()", "min_separation", "NoneType"]),
    (lambda: exactccd.vertex_face_ccd_batch(np.zeros((100, 8, 3)), t_max="x"),
     ["vertex_face_ccd_batch()", "t_max", "str"]),
    (lambda: exactccd.edge_edge_ccd_batch(np.zeros((100, 8, 3)), threads=1.5),
     ["edge_edge_ccd_batch()", "threads", "float"]),
    (lambda: exactccd.vertex_face_ccd_batch(np.zeros((100, 8, 3)), threads=True),
     ["vertex_face_ccd_batch()", "threads", "bool"]),
    (lambda: exactccd.Scene(threads=2), ["Scene()", "threads=int", "no arguments"]),
    (lambda: exactccd.Scene().earliest_contact(5), ["Scene.earliest_contact()", "(int)", "t_max"]),
    (lambda: exactccd.Scene().find_contacts(t_max="late"),
     ["Scene.find_contacts()", "t_max=str", "t_max: float"]),
    (lambda: exactccd.RigidMotion.turn("a", 1, 2), ["RigidMotion.turn()", "(str, int, int)"]),
    (lambda: exactccd.rigid_vertex_face_ccd(np.zeros((4, 3)), 1, 2, mode=3),
     ["rigid_vertex_face_ccd()", "mode=int"]),
])
def test_wrong_argument_types_get_one_line_naming_the_public_function(call, parts):
    with pytest.raises(TypeError) as error:
        call()
    _one_line_naming(error, *parts)


def test_wrapped_methods_still_work():
    scene = exactccd.Scene()
    mesh = scene.add_mesh(_TRIANGLE, np.array([[0, 1, 2]]))
    scene.set_motion(mesh, _TRIANGLE, _TRIANGLE + [0, 0, 1])
    scene.add_static_mesh(_TRIANGLE + [0.2, 0.2, 0.5], np.array([[0, 1, 2]]))
    assert scene.earliest_contact(t_max=1.0).collides
    assert exactccd.Scene.earliest_contact.__name__ == "earliest_contact"
    assert "t_max" in exactccd.Scene.earliest_contact.__doc__


@pytest.mark.parametrize("options, shown", [
    (dict(t_max=1e308), "t_max must lie in [0, 1], got 1e+308"),
    (dict(t_max=-1e-300), "t_max must lie in [0, 1], got -1e-300"),
    (dict(toi_width=-1e-300), "toi_width must be finite and >= 0, got -1e-300"),
    (dict(min_separation=float("inf")), "min_separation must be finite and >= 0, got inf"),
])
def test_options_outside_their_domain_are_shown_as_given(options, shown):
    query = _query()[0]
    for call in (lambda: exactccd.vertex_face_ccd(query, **options),
                 lambda: exactccd.vertex_face_ccd_batch(query[None], **options),
                 lambda: exactccd.Scene().earliest_contact(**options)):
        with pytest.raises(ValueError) as error:
            call()
        _one_line_naming(error, shown)
