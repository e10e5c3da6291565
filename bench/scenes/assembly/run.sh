#!/usr/bin/env bash
# The assembly demonstration in one command: builds exactccd_assembly (Release, in build/ or
# $EXACTCCD_BUILD_DIR), runs it (at 1280 segments per circle by default: a key of 10,252 and a
# lock of 25,528 triangles; it checks itself), draws its two PNGs and copies them next to this
# script (the README's pictures).
#
#   bash bench/scenes/assembly/run.sh [program options...]     # about a minute
#
# Outputs in bench/scenes/out/assembly/ (summary.json, the PNGs). The plots need Debian's
# python3-matplotlib (`bash .ci/install-deps.sh --with-plots`). Exit status: the program's,
# else the plot's.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
cd "$root"
build=${EXACTCCD_BUILD_DIR:-build}
out=bench/scenes/out/assembly

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target exactccd_assembly -j "$(nproc)"
"$build/bench/scenes/assembly/exactccd_assembly" --out "$out" "$@"
if ! /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  echo "run.sh: python3-matplotlib is missing: run 'bash .ci/install-deps.sh --with-plots'" >&2
  exit 2
fi
/usr/bin/python3 bench/scenes/assembly/plot_assembly.py "$out"
cp "$out/assembly_contact.png" "$out/assembly_chord.png" bench/scenes/assembly/
echo "run.sh: pictures in $out/ and bench/scenes/assembly/" >&2
