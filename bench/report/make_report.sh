#!/usr/bin/env bash
# The speed-versus-error report, in one command (from anywhere in the repository):
#
#   bash bench/report/make_report.sh
#
# Builds the `exactccd` command if needed (Release, in build/ or $EXACTCCD_BUILD_DIR), runs
# `exactccd study` on the shipped sample queries, the generated degenerate suite
# (tests/data/degenerate-suite, when present), the scene queries (tests/data/scene-queries), the
# hard families of `exactccd generate` (resting, stacked, wide exponents, 2^+-1000 scalings), the
# sample queries scaled by 2^+-1000, and the simulation-like set, and writes
# bench/report/REPORT.md, bench/report/speed_vs_error_<dataset>.png and bench/report/toi_error.png
# (the study's raw JSON too when $EXACTCCD_STUDY_JSON names a file), and a minimum-separation
# section (issue 12: `exactccd bench --min-separation` on the sample queries, the
# simulation-like set and the generated minimum-separation families, with
# bench/report/min_separation.png). Plots need Debian's
# python3-matplotlib (.ci/install-deps.sh --with-plots installs it). About 4 minutes on a
# 2-core machine (measured 2026-11-24), mostly the exact path timed on the 1.2 million
# simulation-like queries and the minimum-separation runs.
# Exit status: the worst of the study's and the benches' (0: the certified methods showed no
# false positive, false negative or late TOI); 2 when matplotlib is missing or the study could not run.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
build=${EXACTCCD_BUILD_DIR:-build}
out=bench/report
# The simulation-like set: the full default configuration (README: about 1.2 million queries).
simulation_args=(--simulation --resolution 36 --steps 120 --seed 1)

if ! /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  echo "make_report: python3-matplotlib is missing: run 'bash .ci/install-deps.sh --with-plots'" >&2
  exit 2
fi

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target exactccd_cli -j "$(nproc)"
exactccd="$build/tools/exactccd"

paths=(tests/data/sample-queries)
if [[ -f tests/data/degenerate-suite/manifest.json ]]; then
  paths+=(tests/data/degenerate-suite)
fi
# The queries of the demonstration scenes (bench/scenes/export_queries.py).
if [[ -d tests/data/scene-queries ]]; then
  paths+=(tests/data/scene-queries)
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The hard families of issue 10, generated here (exact truth from the constructions or the exact
# path): resting and stacked contact, each also scaled by 2^-1000 and 2^1000, and the wide
# exponent spreads +-100/300/1000 and a huge primitive against subnormal motion.
hard_families=()
for base in vf_resting ee_resting vf_stacked ee_stacked; do
  hard_families+=("$base" "$base@p2^-1000" "$base@p2^1000")
done
for kind in vf ee; do
  hard_families+=("${kind}_wide_exponent_100" "${kind}_wide_exponent_300" "${kind}_wide_exponent_1000"
    "${kind}_huge_triangle_subnormal_motion")
done
"$exactccd" generate --out "$tmp/hard-families" --per-family 28 \
  --families "$(IFS=,; echo "${hard_families[*]}")" > /dev/null
paths+=("$tmp/hard-families")
# The sample queries scaled by 2^-1000 and 2^1000 (queries not exactly doubles after scaling
# left out): a power-of-two scale changes no answer, and should change no cost.
for k in -1000 1000; do
  /usr/bin/python3 bench/report/scale_queries.py "$k" tests/data/sample-queries \
    "$tmp/sample-queries-2pow$k"
  paths+=("$tmp/sample-queries-2pow$k")
done
command=("$exactccd" study --json --out-md "$tmp/tables.md" "${simulation_args[@]}" "${paths[@]}")
echo "make_report: ${command[*]}" >&2
status=0
"${command[@]}" > "$tmp/study.json" || status=$?
if [[ $status -gt 1 ]]; then
  echo "make_report: exactccd study failed (exit status $status)" >&2
  exit "$status"
fi

# Minimum separation (issue 12): exactccd at delta against the common practice (float_only at
# delta > 0), on the sample queries and the simulation-like set at delta = 1e-8, 1e-6, 1e-4 of
# each set's size (0 too: the same run's contact path, for the ratio), and on the
# minimum-separation families generated for each delta (absolute: the families are built around
# their delta, so their box is no scene size; their truth column holds for that delta only).
separation_specs=()
separation_commands=()
bench_separation() {  # NAME OUT ARGS...: one `exactccd bench --json` run
  local name=$1 out=$2
  shift 2
  local run=("$exactccd" bench --json --repetitions 3 "$@")
  echo "make_report: ${run[*]}" >&2
  local code=0
  "${run[@]}" > "$out" || code=$?
  if [[ $code -gt 1 ]]; then
    echo "make_report: exactccd bench failed (exit status $code)" >&2
    exit "$code"
  fi
  if [[ $code -gt $status ]]; then status=$code; fi
  separation_specs+=("$name=$out")
  separation_commands+=("exactccd bench --json --repetitions 3 $(sed "s|$tmp|TMP|g" <<< "$*")")
}
bench_separation sample-queries "$tmp/separation-sample.json" \
  --modes float_only,default,exact --min-separation 0,1e-8,1e-6,1e-4 --relative-separation \
  tests/data/sample-queries
bench_separation simulation "$tmp/separation-simulation.json" \
  --modes float_only,default --min-separation 0,1e-8,1e-6,1e-4 --relative-separation \
  --simulation --steps 24 --seed 1
for delta in 1e-8 1e-6 1e-4; do
  "$exactccd" generate --out "$tmp/separation-families-$delta" --min-separation "$delta" \
    > /dev/null
  bench_separation "min-separation families" "$tmp/separation-families-$delta.json" \
    --modes float_only,default,exact --min-separation "$delta" \
    "$tmp/separation-families-$delta"
done
separation_command=$(printf '%s; ' "${separation_commands[@]}")
separation_command="for delta in 1e-8 1e-6 1e-4: exactccd generate --out TMP/separation-families-\$delta --min-separation \$delta; then ${separation_command%; }"

compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
compiler_version=$("${compiler:-c++}" --version | head -n 1)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
# Changes other than this report's own outputs (from an earlier run) mark the source as modified.
if [[ -n $(git status --porcelain -- . ':!bench/report/REPORT.md' ':!bench/report/*.png' \
  2>/dev/null) ]]; then
  commit="$commit (with uncommitted changes)"
fi

if [[ -n ${EXACTCCD_STUDY_JSON:-} ]]; then cp "$tmp/study.json" "$EXACTCCD_STUDY_JSON"; fi
/usr/bin/python3 "$out/plot_report.py" --json "$tmp/study.json" --tables "$tmp/tables.md" \
  --out-dir "$out" --command "bash bench/report/make_report.sh" \
  --study-command "exactccd study --json --out-md TABLES ${simulation_args[*]} ${paths[*]}" \
  --compiler "$compiler_version" --commit "$commit" --study-status "$status" \
  --min-separation "${separation_specs[@]}" --min-separation-command "$separation_command"
echo "make_report: wrote $out/REPORT.md and its plots" >&2
exit "$status"
