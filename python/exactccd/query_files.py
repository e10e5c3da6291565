"""The CCD benchmark's CSV files (Wang et al. 2021): 8 rows per query, columns
x_num,x_den,y_num,y_den,z_num,z_den,truth; coordinates exact rationals."""

import errno
import os
import secrets
import stat
from typing import NamedTuple, Optional

import numpy as np

from . import _exactccd


class QueryData(NamedTuple):
    """A query file's content: queries (N, 8, 3) (float64 from read_query_file; lists of 8
    (x, y, z) tuples of fractions.Fraction from read_query_file_exact), truth (N,) bool, and
    type ("vertex-face" or "edge-edge")."""
    queries: object
    truth: np.ndarray
    type: str


def _checked_path(path) -> str:
    """The path as a str; a NUL character is refused (the C library would cut the path there and
    name another file)."""
    path = os.fsdecode(os.fspath(path))
    if "\0" in path:
        raise ValueError(f"a path must not contain a NUL character: {path!r}")
    return path


def read_query_file(path, type: Optional[str] = None) -> QueryData:
    """Reads a benchmark CSV file into an (N, 8, 3) float64 array and its truth column.

    type: "vertex-face" or "edge-edge"; None takes it from a folder of that name in the path.
    The point kinds and the plane ("pe", "pe2d", "pp", "pp2d", "pl": README.md, their rows
    per query) give an (N, rows, 3) or, in 2D, (N, rows, 2) array, as the point functions and
    their batch forms take them.
    Raises exactccd.InputError (naming the file and line) for a malformed file, an unknown type,
    or a coordinate that is not exactly a double (read_query_file_exact reads those of the
    benchmark's kinds).
    """
    if type in _PRIMITIVE_KINDS:
        return QueryData(*_exactccd._read_primitive_query_file(_checked_path(path), type))
    return QueryData(*_exactccd._read_query_file(_checked_path(path), type))


_PRIMITIVE_KINDS = ("pe", "pe2d", "pp", "pp2d", "pl")


def read_query_file_exact(path, type: Optional[str] = None) -> QueryData:
    """Reads a benchmark CSV file with every coordinate as an exact fractions.Fraction:
    queries is a list of N lists of 8 (x, y, z) tuples, for exactccd.exact_ccd."""
    return QueryData(*_exactccd._read_query_file_exact(_checked_path(path), type))


def _temporary_file(folder, name):
    """A new file next to the target (so that the rename stays in one file system), created
    with the usual permissions (0666 minus the umask)."""
    while True:
        temporary = os.path.join(folder, f".{name}.{secrets.token_hex(6)}.tmp")
        try:
            return temporary, os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        except FileExistsError:
            continue


def write_query_file(path, queries, truth, *, overwrite: bool = False,
                     kind: Optional[str] = None) -> None:
    """Writes queries (N, 8, 3) with their truth values (N,) as a benchmark CSV file, each
    coordinate as the exact fraction of its double (so the file reads back as exactly these
    doubles). Rows in the benchmark's order (vertex-face: p, a, b, c at t0 then t1; edge-edge:
    ea0, ea1, eb0, eb1 at t0 then t1). kind "pe", "pe2d", "pp", "pp2d" or "pl": queries of
    that point kind or the plane, (N, rows, 3) or in 2D (N, rows, 2), as read_query_file reads
    them.

    The file appears whole or not at all: written to a temporary file in the same folder, then
    renamed into place. An existing file is never replaced unless overwrite=True
    (FileExistsError), nor a folder (IsADirectoryError) or another kind of file. Raises
    ValueError for a wrong shape, a non-finite coordinate, a truth value other than 0 or 1, or a
    NUL character in the path, before anything is written.
    """
    if kind is None:
        text = _exactccd._format_query_rows(queries, truth)
    elif kind in _PRIMITIVE_KINDS:
        text = _exactccd._format_primitive_rows(queries, truth, kind)
    else:
        raise ValueError(f"write_query_file(): kind must be one of {', '.join(_PRIMITIVE_KINDS)} "
                         f"(or None for the benchmark's queries), not {kind!r}")
    path = _checked_path(path)
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        mode = None
    if mode is not None and stat.S_ISDIR(mode):
        raise IsADirectoryError(errno.EISDIR, "is a folder, not a file: write_query_file needs "
                                "the path of the file to write", path)
    if mode is not None and not stat.S_ISREG(mode):
        raise FileExistsError(errno.EEXIST, "is not a regular file (a device, FIFO or socket): "
                              "write_query_file never replaces one", path)
    folder, name = os.path.split(os.path.abspath(path))
    if not overwrite and os.path.lexists(path):
        raise FileExistsError(errno.EEXIST, "refusing to replace an existing file "
                              "(write_query_file(..., overwrite=True) replaces it)", path)
    temporary, fd = _temporary_file(folder, name)
    try:
        with os.fdopen(fd, "wb") as out:
            out.write(text)
            out.flush()
            os.fsync(out.fileno())
        if overwrite:
            os.replace(temporary, path)
        else:
            # link() fails if the name exists, even if it appeared since the check above.
            try:
                os.link(temporary, path)
            except FileExistsError:
                raise FileExistsError(errno.EEXIST, "refusing to replace an existing file "
                                      "(write_query_file(..., overwrite=True) replaces it)",
                                      path) from None
            except OSError as error:
                # A file system without hard links: rename, after checking again.
                if error.errno not in (errno.EPERM, errno.EOPNOTSUPP, errno.ENOSYS):
                    raise
                if os.path.lexists(path):
                    raise FileExistsError(errno.EEXIST, "refusing to replace an existing file "
                                          "(write_query_file(..., overwrite=True) replaces it)",
                                          path) from None
                os.rename(temporary, path)
                return
            os.unlink(temporary)
    except BaseException:
        if os.path.lexists(temporary):
            os.unlink(temporary)
        raise
