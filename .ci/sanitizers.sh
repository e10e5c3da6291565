#!/usr/bin/env bash
# The sanitizer and fuzzing stage of CI (after .ci/test.sh's Release build and full suite):
#  1. clang, Debug at -O1 (NDEBUG unset: CGAL's and the library's assertions on), with
#     AddressSanitizer, UndefinedBehaviorSanitizer (any report aborts) and libFuzzer's coverage
#     instrumentation, in build-san: the library, every test, the fuzz harnesses; then the
#     whole ctest suite at EXACTCCD_TEST_SCALE (default 0.02), the fuzz corpora included;
#  2. each libFuzzer harness for EXACTCCD_FUZZ_SECONDS (default 30) from its committed corpus
#     (tests/fuzz/corpus/<harness>), two at a time; new inputs go to build-san/fuzz/<harness>/,
#     a failing input is saved there as crash-*, leak-*, timeout-* or oom-*;
#  3. ThreadSanitizer in build-tsan: the library and the tests that run it on several threads
#     (scene_test, discrete_test, rounding_mode_test's thread-safety test), whole, at the same
#     scale, with tests/tsan/tbb_tsan_bridge.cpp showing TBB's synchronisation to TSan (no
#     suppressions), after the two self-checks of that setup.
# Stops at the first failure (exit status non-zero). Needs the packages of
# `bash .ci/install-deps.sh --with-sanitizers`, which it installs when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh --with-sanitizers

jobs=$(nproc)
export EXACTCCD_TEST_SCALE="${EXACTCCD_TEST_SCALE:-0.02}"
fuzz_seconds="${EXACTCCD_FUZZ_SECONDS:-30}"
symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
export ASAN_OPTIONS="check_initialization_order=1:detect_leaks=1"
ASAN_OPTIONS+=":external_symbolizer_path=$symbolizer"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:external_symbolizer_path=$symbolizer"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:external_symbolizer_path=$symbolizer"

configure() {  # configure DIR CMAKE-ARGS...
  local dir=$1
  shift
  cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
    "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -gline-tables-only" -DEXACTCCD_BUILD_BENCH=OFF \
    -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE "$@" >/dev/null
}

echo "== AddressSanitizer + UndefinedBehaviorSanitizer (build-san, scale $EXACTCCD_TEST_SCALE)"
configure build-san -DEXACTCCD_SANITIZE=address,undefined -DEXACTCCD_FUZZ=ON
cmake --build build-san -j"$jobs"
ctest --test-dir build-san --output-on-failure -j"$jobs"

echo "== libFuzzer: ${fuzz_seconds} s per harness"
fuzz() {  # fuzz HARNESS: runs it, its log in build-san/fuzz/HARNESS/log.txt
  local out=build-san/fuzz/$1
  mkdir -p "$out/new"
  # -timeout: one input running longer is a failure (every finite query is checked, the widest
  # exponent spreads included: fuzz_support.hpp kMaxExponentSpread).
  if build-san/tests/fuzz/"$1"_fuzz -max_total_time="$fuzz_seconds" -timeout=60 \
      -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$out/" \
      "$out/new" tests/fuzz/corpus/"$1" >"$out/log.txt" 2>&1; then
    echo "$1: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$out/log.txt" |
      grep -o '[0-9]*$') inputs, no failure"
  else
    tail -n 60 "$out/log.txt"
    echo "$1: FAILED; the input is saved in $out/ (log: $out/log.txt)" >&2
    return 1
  fi
}
harnesses=(query_file ccd_api answers_file suite_manifest)
for ((i = 0; i < ${#harnesses[@]}; i += 2)); do
  fuzz "${harnesses[i]}" &
  first=$!
  status=0
  if ((i + 1 < ${#harnesses[@]})); then fuzz "${harnesses[i + 1]}" || status=1; fi
  wait "$first" || status=1
  ((status == 0)) || exit 1
done

echo "== ThreadSanitizer (build-tsan)"
configure build-tsan -DEXACTCCD_SANITIZE=thread
thread_tests=(scene_test discrete_test rounding_mode_test)
cmake --build build-tsan -j"$jobs" --target exactccd_tbb_tsan_bridge tsan_race_is_reported \
  tsan_handoff_is_not_a_race "${thread_tests[@]}"
# The setup's self-checks: a race between TBB bodies is reported, TBB's hand-offs are not.
ctest --test-dir build-tsan -L tsan --output-on-failure
bridge=$PWD/build-tsan/tests/tsan/libexactccd_tbb_tsan_bridge.so  # tests/tsan/tbb_tsan_bridge.cpp
for test in "${thread_tests[@]}"; do
  LD_PRELOAD=$bridge INTEL_LIBITTNOTIFY64=$bridge INTEL_ITTNOTIFY_GROUPS=sync \
    build-tsan/tests/"$test" --gtest_brief=1
done
echo "sanitizers: all passed"
