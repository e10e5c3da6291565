#!/usr/bin/env bash
# The README's table of exactccd's rigid CCD against FCL's continuous collision, in one command:
# builds exactccd_fcl_comparison (Release, in build/ or $EXACTCCD_BUILD_DIR; needs Debian's
# libfcl-dev, which .ci/install-deps.sh installs) and prints the Markdown table on stdout
# (progress on stderr). Single thread; about ten minutes with the defaults.
#
#   bash bench/fcl_comparison/make_table.sh [--pairs N] [--segments N] [--json FILE] ...
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
build=${EXACTCCD_BUILD_DIR:-build}

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >&2
fi
if ! cmake --build "$build" --target exactccd_fcl_comparison -j "$(nproc)" >&2; then
  echo "make_table.sh: could not build exactccd_fcl_comparison (is libfcl-dev installed? run" \
       "'bash .ci/install-deps.sh', then reconfigure $build)" >&2
  exit 2
fi
"$build/bench/fcl_comparison/exactccd_fcl_comparison" "$@"
