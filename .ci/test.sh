#!/usr/bin/env bash
# The whole test suite, as CI runs it: installs what is missing, builds in Release and runs every
# test (ctest), then the sanitizer and fuzzing stage (.ci/sanitizers.sh: ASan+UBSan suite at a
# reduced scale, each libFuzzer harness for a fixed time, ThreadSanitizer on the threaded tests).
# Fails when any stage fails. The fast loop for development: ctest --test-dir build -L fast -j2.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_BUILD_TESTS=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" | tee build/ctest-output.log
# Every test well inside its timeout (a third at most), so a loaded machine does not time it out.
python3 .ci/check_test_times.py build --log build/ctest-output.log
bash .ci/sanitizers.sh
