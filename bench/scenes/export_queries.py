#!/usr/bin/env python3
"""Samples the demonstration scenes' CCD queries into the shipped scene data set.

    bash bench/scenes/run.sh thin_sheet && bash bench/scenes/run.sh cloth && \
        bash bench/scenes/run.sh peg_in_hole
    python3 bench/scenes/export_queries.py [--per-scene 2000] [--out tests/data/scene-queries]

Reads bench/scenes/out/<scene>/queries/{vertex-face,edge-edge}/data_K.csv (benchmark CSV, 8 rows
per query, truth from the scene's exact contacts) and writes, per scene and type, one file
<out>/<scene>/<type>/data_0.csv with every colliding query up to half the budget and evenly
spaced non-colliding ones for the rest: the queries a simulator's narrow phase really gets,
small enough to ship. Deterministic (no randomness): the same inputs give the same files.
"""
import argparse
import os
import re
import sys

SCENES = ("thin_sheet", "cloth", "peg_in_hole")
TYPES = ("vertex-face", "edge-edge")


def read_queries(folder):
    files = sorted((f for f in os.listdir(folder) if re.fullmatch(r"data_[0-9]+\.csv", f)),
                   key=lambda f: int(f[5:-4]))
    queries = []
    for name in files:
        with open(os.path.join(folder, name)) as handle:
            rows = [line for line in handle.read().splitlines() if line.strip()]
        if len(rows) % 8:
            sys.exit(f"export_queries: {folder}/{name}: {len(rows)} rows, not a multiple of 8")
        for k in range(0, len(rows), 8):
            block = rows[k:k + 8]
            truth = {row.rsplit(",", 1)[1] for row in block}
            if len(truth) != 1 or truth - {"0", "1"}:
                sys.exit(f"export_queries: {folder}/{name}: bad truth column near row {k + 1}")
            queries.append((block, truth.pop() == "1"))
    return queries


def evenly(items, count):
    if count >= len(items):
        return list(items)
    return [items[(i * len(items)) // count] for i in range(count)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--per-scene", type=int, default=2000, help="queries per scene and type")
    parser.add_argument("--source", default="bench/scenes/out")
    parser.add_argument("--out", default="tests/data/scene-queries")
    args = parser.parse_args()
    total = 0
    for scene in SCENES:
        for query_type in TYPES:
            source = os.path.join(args.source, scene, "queries", query_type)
            if not os.path.isdir(source):
                sys.exit(f"export_queries: {source} missing: run bench/scenes/run.sh {scene}")
            queries = read_queries(source)
            hits = [q for q in queries if q[1]]
            misses = [q for q in queries if not q[1]]
            chosen_hits = evenly(hits, args.per_scene // 2)
            chosen = chosen_hits + evenly(misses, args.per_scene - len(chosen_hits))
            folder = os.path.join(args.out, scene, query_type)
            os.makedirs(folder, exist_ok=True)
            with open(os.path.join(folder, "data_0.csv"), "w") as handle:
                for block, _ in chosen:
                    handle.write("\n".join(block) + "\n")
            total += len(chosen)
            print(f"{scene} {query_type}: {len(chosen)} of {len(queries)} queries "
                  f"({len(chosen_hits)} colliding of {len(hits)})")
    print(f"export_queries: {total} queries in {args.out}")


if __name__ == "__main__":
    main()
