"""Shared fixtures: where the sample queries, the exactccd command and the C++ scene helper are
(set by ctest; see CMakeLists.txt)."""

import os
import pathlib
import subprocess

import pytest

HERE = pathlib.Path(__file__).resolve().parent


def _env_path(name, default=None):
    value = os.environ.get(name, default)
    return pathlib.Path(value) if value else None


@pytest.fixture(scope="session")
def sample_queries():
    path = _env_path("EXACTCCD_SAMPLE_QUERIES", str(HERE.parent.parent / "tests/data/sample-queries"))
    assert path.is_dir(), f"no sample queries at {path}"
    return path


@pytest.fixture(scope="session")
def sample_files(sample_queries):
    import exactccd
    files = exactccd.find_query_files(str(sample_queries))
    assert len(files) > 0
    return files


@pytest.fixture(scope="session")
def cli():
    """The exactccd command (its independent C++ answers)."""
    path = _env_path("EXACTCCD_CLI")
    if path is None:
        pytest.skip("EXACTCCD_CLI not set (the command is not built)")
    assert path.is_file(), f"EXACTCCD_CLI={path} does not exist"
    return path


@pytest.fixture(scope="session")
def scene_reference():
    path = _env_path("EXACTCCD_SCENE_REFERENCE")
    if path is None:
        pytest.skip("EXACTCCD_SCENE_REFERENCE not set")
    assert path.is_file(), f"EXACTCCD_SCENE_REFERENCE={path} does not exist"
    return path


def run(command, **kwargs):
    return subprocess.run([str(c) for c in command], capture_output=True, text=True, **kwargs)
