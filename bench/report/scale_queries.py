#!/usr/bin/env python3
"""Copies benchmark CSV files with every coordinate multiplied by 2^k, exactly.

    python3 bench/report/scale_queries.py K SOURCE_DIR OUT_DIR

Each query (8 rows x_num,x_den,y_num,y_den,z_num,z_den,truth) is scaled in exact rational
arithmetic; a query with a scaled coordinate that is not exactly a finite double (overflow, or
bits lost below the subnormals) is left out, so `exactccd bench` (which times the double API)
takes every file. A scale by a power of two changes no verdict and no time of impact, so the
truth column is kept. Paths under SOURCE_DIR are kept under OUT_DIR (folder names such as
vertex-face/edge-edge tell the query type). Never overwrites: OUT_DIR must not exist yet.
"""
import sys
from fractions import Fraction
from pathlib import Path


def exactly_double(q: Fraction) -> bool:
    try:
        return Fraction(float(q)) == q
    except OverflowError:
        return False


def scale_file(k: int, source: Path, out: Path) -> tuple[int, int]:
    factor = Fraction(2) ** k
    rows = [line.strip() for line in source.read_text().splitlines() if line.strip()]
    kept, dropped, written = 0, 0, []
    for start in range(0, len(rows) - len(rows) % 8, 8):
        query, ok = [], True
        for row in rows[start:start + 8]:
            f = row.split(",")
            coords = [Fraction(int(f[2 * i]), int(f[2 * i + 1])) * factor for i in range(3)]
            ok = ok and all(exactly_double(c) for c in coords)
            query.append(",".join(f"{c.numerator},{c.denominator}" for c in coords) + "," + f[6])
        if ok:
            written.extend(query)
            kept += 1
        else:
            dropped += 1
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("".join(line + "\n" for line in written))
    return kept, dropped


def main() -> int:
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    k, source, out = int(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    if out.exists():
        print(f"scale_queries: {out} exists; refusing to overwrite", file=sys.stderr)
        return 2
    kept = dropped = 0
    for csv in sorted(source.rglob("*.csv")):
        if not csv.name.startswith("data"):
            continue  # TOI sidecars and the like
        a, b = scale_file(k, csv, out / csv.relative_to(source))
        kept, dropped = kept + a, dropped + b
    print(f"scale_queries: 2^{k}: {kept} queries written, {dropped} not exactly doubles left out",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
