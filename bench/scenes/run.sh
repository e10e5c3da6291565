#!/usr/bin/env bash
# One demonstration scene in one command: builds its program (Release, in build/ or
# $EXACTCCD_BUILD_DIR), runs it (it prints its summary and checks itself), then draws its PNGs.
#
#   bash bench/scenes/run.sh thin_sheet|cloth|peg_in_hole [program options...]
#
# Outputs go to bench/scenes/out/<scene>/ (summary.json, the PNGs, and the scene's CCD queries in
# the benchmark's CSV format under queries/). Plots need Debian's python3-matplotlib
# (`bash .ci/install-deps.sh --with-plots`). Exit status: the program's, else the plot's.
set -euo pipefail

scene=${1:-}
case "$scene" in
  thin_sheet | cloth | peg_in_hole) shift ;;
  *)
    echo "usage: bash bench/scenes/run.sh thin_sheet|cloth|peg_in_hole [options...]" >&2
    exit 2
    ;;
esac
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
build=${EXACTCCD_BUILD_DIR:-build}
out=bench/scenes/out/$scene

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target "exactccd_$scene" -j "$(nproc)"
"$build/bench/scenes/exactccd_$scene" --out "$out" "$@"
if ! /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  echo "run.sh: python3-matplotlib is missing: run 'bash .ci/install-deps.sh --with-plots'" >&2
  exit 2
fi
/usr/bin/python3 "bench/scenes/plot_$scene.py" "$out"
echo "run.sh: pictures in $out/" >&2
