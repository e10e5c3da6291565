#!/usr/bin/env python3
"""Batch throughput of the Python module: queries per second of vertex_face_ccd_batch and
edge_edge_ccd_batch on the simulation-like query set, for each thread count.

    PYTHONPATH=build/python python3 python/bench_batch.py --cli build/tools/exactccd

The set is written once by `exactccd simulate --out DIR` (reused when DIR already holds it).
Each figure is the best of --repeat runs over the whole set (reading the files is not timed).
"""

import argparse
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

# The module comes from PYTHONPATH (the build tree or an installation), not from the sources
# next to this script, which lack the compiled extension.
HERE = pathlib.Path(__file__).resolve().parent
sys.path = [p for p in sys.path if pathlib.Path(p or ".").resolve() != HERE]
import exactccd  # noqa: E402


def simulation_set(cli, folder):
    """The simulation-like queries by type: {type: (N, 8, 3) array}."""
    root = pathlib.Path(folder) / "simulation"
    if not root.is_dir():
        if cli is None:
            sys.exit(f"bench_batch: no query set in {root}: pass --cli to write it")
        subprocess.run([str(cli), "simulate", "--out", str(folder), "--truth", "none"], check=True)
    by_type = {}
    for path in exactccd.find_query_files(str(root)):
        data = exactccd.read_query_file(path)
        by_type.setdefault(data.type, []).append(data.queries)
    return {t: np.concatenate(parts) for t, parts in by_type.items()}


def best_seconds(function, repeat):
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", help="the exactccd command (to write the query set)")
    parser.add_argument("--data", help="folder of the query set (default: a temporary folder)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--mode", default="filtered", choices=exactccd.MODE_NAMES + ["default"],
                        help='"default": the old name of "filtered"')
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as temporary:
        queries = simulation_set(args.cli, args.data or temporary)
    batch = {"vertex-face": exactccd.vertex_face_ccd_batch,
             "edge-edge": exactccd.edge_edge_ccd_batch}
    total = sum(len(q) for q in queries.values())
    print(f"simulation-like set: {', '.join(f'{len(q)} {t}' for t, q in queries.items())} "
          f"queries; mode {args.mode}; best of {args.repeat}; {os.cpu_count()} cores")
    print(f"{'threads':>7} {'vertex-face q/s':>16} {'edge-edge q/s':>14} {'all q/s':>12}")
    for threads in args.threads:
        seconds = {t: best_seconds(lambda: batch[t](q, threads=threads, mode=args.mode),
                                   args.repeat)
                   for t, q in queries.items()}
        rate = {t: len(queries[t]) / s for t, s in seconds.items()}
        print(f"{threads:>7} {rate.get('vertex-face', 0):>16,.0f} "
              f"{rate.get('edge-edge', 0):>14,.0f} {total / sum(seconds.values()):>12,.0f}")


if __name__ == "__main__":
    main()
