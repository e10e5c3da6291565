"""The batch oracle on Dask (python3-distributed): `exactccd check` and `exactccd grade` over many
benchmark CSV files or arrays, one task per shard, on any Dask cluster.

    from exactccd.dask import check, grade
    report = check(["tests/data/sample-queries"])              # a LocalCluster on this machine
    report = check(paths, cluster="tcp://scheduler:8786", shard=100_000)

A multi-machine cluster: `dask scheduler` on one machine, `dask worker tcp://host:8786` on each
worker machine (every worker needs exactccd importable and the files at the same paths), then
check(..., cluster="tcp://host:8786").

The tables and JSON are exactly the command's (the same printers): per file and TOTAL. The
us/query column and "seconds" are the decision time summed over the workers.
"""

import os
import sys
from typing import Callable, List, NamedTuple, Optional, Sequence, Tuple, Union

from . import _exactccd
from ._exactccd import InputError, query_type_from_path

__all__ = ["CheckReport", "GradeReport", "check", "check_arrays", "grade"]


# ---- Tasks (run on the workers) -----------------------------------------------------------------

def _check_file_task(path, type, begin, end, mode, t_max):
    return _exactccd._check_file_shard(path, type, begin, end, mode, t_max)


def _check_array_task(name, type, queries, truth, mode, t_max):
    return _exactccd._check_array_shard(name, type, queries, truth, mode, t_max)


def _grade_file_task(queries_path, answers_path, type, begin, end, t_max):
    return _exactccd._grade_file_shard(queries_path, answers_path, type, begin, end, t_max)


# ---- Reports ------------------------------------------------------------------------------------

class CheckReport(NamedTuple):
    """The merged tallies: files (one dict per file, in order) and total; table and json are the
    command's printed forms."""
    mode: str
    t_max: float
    files: List[dict]
    total: dict
    table: str
    json: str

    @property
    def disagreements(self) -> int:
        return self.total["false_positives"] + self.total["false_negatives"]


class GradeReport(NamedTuple):
    """Per (queries, answers) pair, its findings (false_positives, false_negatives,
    non_conservative: 0-based query indices) and the command's text and JSON for it."""
    files: List[Tuple[str, str]]
    findings: List[dict]
    texts: List[str]
    jsons: List[str]

    @property
    def all_good(self) -> bool:
        return all(not (f["false_positives"] or f["false_negatives"] or f["non_conservative"])
                   for f in self.findings)


# ---- Running tasks on a cluster -----------------------------------------------------------------

class _Client:
    """A distributed.Client for `cluster`: None (a LocalCluster on this machine, closed after
    use), a scheduler address, a Cluster object, or a Client (used as it is)."""

    def __init__(self, cluster):
        import distributed
        self._owned = []
        if cluster is None:
            local = distributed.LocalCluster(processes=True, threads_per_worker=1)
            self._owned.append(local)
            self.client = distributed.Client(local)
            self._owned.insert(0, self.client)
        elif isinstance(cluster, distributed.Client):
            self.client = cluster
        else:
            self.client = distributed.Client(cluster)  # an address or a Cluster
            self._owned.append(self.client)

    def __enter__(self):
        return self.client

    def __exit__(self, *exc):
        for owned in self._owned:
            owned.close()


def _stderr_progress(done, total):
    """A one-line progress report on stderr, when it is a terminal (as the command's)."""
    if not sys.stderr.isatty():
        return
    sys.stderr.write(f"\rexactccd: {done}/{total} shards" + ("\n" if done == total else ""))
    sys.stderr.flush()


def _run(cluster, calls, progress):
    """Runs calls [(function, args)] as one task each; results in the order of the calls."""
    import distributed
    if progress is True:
        progress = _stderr_progress
    with _Client(cluster) as client:
        futures = [client.submit(function, *args, pure=False) for function, args in calls]
        index = {future.key: k for k, future in enumerate(futures)}
        results = [None] * len(futures)
        try:
            for done, future in enumerate(distributed.as_completed(futures), start=1):
                results[index[future.key]] = future.result()  # raises the task's exception
                if progress:
                    progress(done, len(futures))
        finally:
            for future in futures:
                future.cancel()
        return results


# ---- Planning shards ----------------------------------------------------------------------------

def _as_list(paths) -> List[str]:
    if isinstance(paths, (str, bytes, os.PathLike)):
        paths = [paths]
    return [os.fspath(p) for p in paths]


def _resolve_type(file, type):
    if type is not None or query_type_from_path(file) is not None:
        return
    raise InputError(f"{file}: cannot tell the query type: no folder named vertex-face or "
                     f"edge-edge in the path (pass type=\"vertex-face\" or type=\"edge-edge\")")


def _count_queries(path):
    """Queries in a benchmark file: its non-blank lines / 8 (for planning shards only; the task
    reading the file checks it)."""
    with open(path, "rb") as f:
        return (sum(1 for line in f if line.strip()) + 7) // 8


def _ranges(path, shard):
    """[begin, end) ranges of `shard` queries covering the file; one (0, None) when unsharded."""
    if shard is None:
        return [(0, None)]
    if shard < 1:
        raise ValueError(f"shard must be >= 1 queries (or None: one task per file), not {shard}")
    count = _count_queries(path)
    return [(begin, begin + shard) for begin in range(0, max(count, 1), shard)]


def _print(text, out):
    if out is not None:
        out.write(text)
        out.flush()


# ---- check --------------------------------------------------------------------------------------

def _check_report(mode, t_max, names, shard_names, tallies, json, out):
    """Merges the shards' tallies per file (in file order), then prints as `exactccd check`."""
    files = []
    for name in names:
        parts = [t for n, t in zip(shard_names, tallies) if n == name]
        files.append(_exactccd._merge_tallies(parts, name))
    total = _exactccd._merge_tallies(files, "TOTAL")
    empty = [f["file"] for f in files if f["queries"] == 0]
    _exactccd._require_some_queries(empty, len(files), total["queries"])
    table = _exactccd._check_table(mode, files, total)
    json_text = _exactccd._check_json(mode, files, total, t_max)
    _print(json_text if json else table, out)
    return CheckReport(mode, t_max, files, total, table, json_text)


def check(paths, *, mode: str = "filtered", t_max: float = 1.0, type: Optional[str] = None,
          cluster=None, shard: Optional[int] = None,
          progress: Union[bool, Callable[[int, int], None]] = True, json: bool = False,
          out=sys.stdout) -> CheckReport:
    """`exactccd check` on a Dask cluster: decides every query of the benchmark CSV files
    (files, or folders searched for vertex-face/*.csv and edge-edge/*.csv) and compares with
    their truth column.

    mode: "filtered", "exact" or "float_only" ("default": the old name of filtered); t_max in
    (0, 1]; type: "vertex-face" or "edge-edge" for every file (None: from the folder names).
    cluster: None (a LocalCluster of processes, one thread each), a scheduler address
    "tcp://host:8786", a Cluster or a Client.
    shard: queries per task (None: one task per file). progress: True (a line on stderr when it
    is a terminal), False, or a callback progress(done, total) called as shards finish.
    Prints the command's table (or JSON) to `out` (None: nothing); returns a CheckReport.
    Raises InputError / ValueError as the command exits with status 2.
    """
    mode = _exactccd._mode_name(mode)  # canonical; ValueError listing the names
    if not 0.0 < t_max <= 1.0:
        raise ValueError(f"t_max must lie in (0, 1], got {t_max}")
    files = [f for p in _as_list(paths) for f in _exactccd.find_query_files(p)]
    for f in files:
        _resolve_type(f, type)
    calls, shard_names = [], []
    for f in files:
        for begin, end in _ranges(f, shard):
            # Workers read the absolute path (their working folder is not the caller's); the
            # tables name the file as given, as the command does.
            calls.append((_check_file_task, (os.path.abspath(f), type, begin, end, mode, t_max)))
            shard_names.append(f)
    tallies = _run(cluster, calls, progress)
    return _check_report(mode, t_max, files, shard_names, tallies, json, out)


def check_arrays(arrays: Sequence[Tuple[str, str, object, object]], *, mode: str = "filtered",
                 t_max: float = 1.0, cluster=None, shard: Optional[int] = None,
                 progress: Union[bool, Callable[[int, int], None]] = True, json: bool = False,
                 out=sys.stdout) -> CheckReport:
    """check() over arrays instead of files: `arrays` holds (name, type, queries, truth), queries
    (N, 8, 3) float64 in the benchmark's row order and truth (N,) bool; each is one row of the
    table, sharded into tasks of `shard` queries (None: one task per array)."""
    import numpy as np
    mode = _exactccd._mode_name(mode)  # canonical; ValueError listing the names
    if shard is not None and shard < 1:
        raise ValueError(f"shard must be >= 1 queries (or None: one task per array), not {shard}")
    calls, names, shard_names = [], [], []
    for name, type, queries, truth in arrays:
        queries, truth = np.asarray(queries), np.asarray(truth)
        if len(queries) != len(truth):
            raise ValueError(f"{name}: {len(queries)} queries but {len(truth)} truth values")
        names.append(name)
        step = shard or max(len(queries), 1)
        for begin in range(0, max(len(queries), 1), step):
            calls.append((_check_array_task, (name, type, queries[begin:begin + step],
                                              truth[begin:begin + step], mode, t_max)))
            shard_names.append(name)
    tallies = _run(cluster, calls, progress)
    return _check_report(mode, t_max, names, shard_names, tallies, json, out)


# ---- grade --------------------------------------------------------------------------------------

def grade(pairs, *, type: Optional[str] = None, t_max: float = 1.0, cluster=None,
          shard: Optional[int] = None,
          progress: Union[bool, Callable[[int, int], None]] = True, json: bool = False,
          out=sys.stdout) -> GradeReport:
    """`exactccd grade` on a Dask cluster: judges another code's answers against the exact
    decision. pairs: one (queries_csv, answers_file) pair or a list of them (answers file as the
    command's: one line per query, 0, 1 or 1,toi). Other arguments as check().

    Prints, per pair, the command's text (or JSON) for it; with several pairs each is preceded
    by a line "== QUERIES_FILE ==". Returns a GradeReport.
    """
    if not 0.0 < t_max <= 1.0:
        raise ValueError(f"t_max must lie in (0, 1], got {t_max}")
    if len(pairs) == 2 and all(isinstance(p, (str, os.PathLike)) for p in pairs):
        pairs = [pairs]
    pairs = [(os.fspath(q), os.fspath(a)) for q, a in pairs]
    calls, owners = [], []
    for k, (queries, answers) in enumerate(pairs):
        _resolve_type(queries, type)
        for begin, end in _ranges(queries, shard):
            calls.append((_grade_file_task, (os.path.abspath(queries), os.path.abspath(answers),
                                             type, begin, end, t_max)))
            owners.append(k)
    parts = _run(cluster, calls, progress)
    findings, texts, jsons = [], [], []
    for k, (queries, _) in enumerate(pairs):
        mine = [p for owner, p in zip(owners, parts) if owner == k]
        merged = {key: sum((p[key] for p in mine), [] if isinstance(mine[0][key], list) else 0)
                  for key in mine[0]}
        findings.append(merged)
        texts.append(_exactccd._grade_text(merged))
        jsons.append(_exactccd._grade_json(merged, t_max))
        if len(pairs) > 1:
            _print(f"== {queries} ==\n", out)
        _print(jsons[-1] if json else texts[-1], out)
    return GradeReport(pairs, findings, texts, jsons)
