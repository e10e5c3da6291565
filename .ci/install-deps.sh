#!/usr/bin/env bash
# Installs the Debian 12 packages exactccd needs, only those missing. Idempotent.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libeigen3-dev libboost-dev
  googletest libgtest-dev libbenchmark-dev libtbb-dev libcli11-dev nlohmann-json3-dev
  # The Python module and its tests, the Dask oracle, the API reference (issue 11); python3 also
  # runs .ci/check_test_times.py.
  python3 pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed doxygen
  # z3: the independent check of minimum-separation and rigid-body CCD (python/tests/test_min_separation.py,
  # python/tests/test_rigid_min_separation_z3.py,
  # python/tests/test_rigid.py) and of the contact geometry (python/tests/test_contact_z3.py).
  python3-z3
  # FCL 0.7: the comparison of rigid-body CCD with FCL's continuous collision
  # (bench/fcl_comparison; built only when CMake finds it, the library never uses it).
  libfcl-dev
  # The inspector pages (issue 29): Debian's three.js, inlined into every page; their browser
  # tests (tests/browser) drive Debian's Chromium headless through ChromeDriver and Selenium,
  # with a font for the pages' text.
  libjs-three chromium chromium-driver python3-selenium fonts-liberation
)
if [[ "${1:-}" == "--with-plots" ]]; then packages+=(python3-matplotlib); fi
# .ci/sanitizers.sh: clang with its sanitizer and libFuzzer runtimes, llvm-symbolizer for traces.
if [[ " $* " == *" --with-sanitizers "* ]]; then packages+=(clang libclang-rt-14-dev libfuzzer-14-dev llvm-14); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "exactccd: installing missing packages: ${missing[*]}" >&2
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
if ! $sudo apt-get install -y --no-install-recommends "${missing[@]}"; then
  $sudo apt-get update
  $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi
