#!/usr/bin/env python3
"""Throughput of exactccd.dask.check on a query set: queries per second end to end (reading,
deciding, merging), on a LocalCluster of this machine or on a given scheduler.

    PYTHONPATH=build/python python3 python/bench_dask.py DIR [--workers 2] [--shard 100000]
    PYTHONPATH=build/python python3 python/bench_dask.py DIR --cluster tcp://host:8786
"""

import argparse
import pathlib
import sys
import time

# The module comes from PYTHONPATH, not from the sources next to this script.
HERE = pathlib.Path(__file__).resolve().parent
sys.path = [p for p in sys.path if pathlib.Path(p or ".").resolve() != HERE]
import distributed  # noqa: E402

from exactccd import dask as exactccd_dask  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("paths", nargs="+", help="query files or folders (exactccd check's)")
    parser.add_argument("--cluster", help="scheduler address (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    parser.add_argument("--shard", type=int, default=100_000, help="queries per task")
    parser.add_argument("--mode", default="filtered",
                        help='filtered, exact or float_only ("default": filtered)')
    args = parser.parse_args()

    if args.cluster:
        client = distributed.Client(args.cluster)
    else:
        client = distributed.Client(distributed.LocalCluster(
            n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None))
    with client:
        start = time.perf_counter()
        report = exactccd_dask.check(args.paths, mode=args.mode, cluster=client, shard=args.shard,
                                     out=None)
        seconds = time.perf_counter() - start
    workers = args.cluster or f"LocalCluster of {args.workers} processes"
    print(f"{report.total['queries']} queries, {report.disagreements} disagreements, "
          f"{seconds:.1f} s on {workers} (shard {args.shard}): "
          f"{report.total['queries'] / seconds:,.0f} queries/s")


if __name__ == "__main__":
    main()
