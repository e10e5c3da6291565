#!/usr/bin/env bash
# The main job on a fresh machine: install what is missing, build in Release, and decide every
# shipped sample query of the CCD benchmark exactly, printing the summary table.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_BUILD_TESTS=OFF -DEXACTCCD_BUILD_BENCH=OFF
cmake --build build -j"$(nproc)" --target exactccd_cli
./build/tools/exactccd check tests/data/sample-queries
