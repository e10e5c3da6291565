"""exactccd.inspect: one query of a benchmark CSV file, as `exactccd inspect` shows it."""

import json
import os
from typing import Optional

from . import _exactccd
from .query_files import _checked_path


def inspect(path, index: int = 0, *, type: Optional[str] = None, mode: str = "filtered",
            t_max: float = 1.0, min_separation: float = 0.0, html=None,
            force: bool = False) -> dict:
    """The inspection of query `index` (0-based) of the benchmark CSV file `path`: a dict with
    the points (exact "num/den" strings and nearest doubles), the answer of `mode` ("result"),
    the exact and float_only answers, the polynomials that decide the query with their roots
    in [0, t_max] as exact brackets and the inclusion test at each, and the contact geometry
    (the same JSON as `exactccd inspect --json`; TOIs of no contact are None there, JSON having
    no infinity).

    html: also write the self-contained inspector page there (a 3D view with a time slider, a
    plot, a panel); an existing file is refused (FileExistsError) unless force=True, and a page
    is written whole or not at all.
    Raises exactccd.InputError for a malformed file or an index past its end, ValueError for a
    bad mode, t_max or min_separation."""
    if isinstance(index, bool) or not isinstance(index, int) or index < 0:
        raise ValueError(f"exactccd.inspect: index must be an int >= 0, got {index!r}")
    path = _checked_path(path)
    if html is not None:
        html = _checked_path(html)
        if not force and os.path.lexists(html):
            raise FileExistsError(f"exactccd.inspect: {html} exists (force=True replaces it)")
    text = _exactccd._inspect(path, index, type, str(mode), float(t_max), float(min_separation))
    if html is not None:
        _exactccd._write_inspector_page(text, html, bool(force))
    return json.loads(text)
