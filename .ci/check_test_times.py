#!/usr/bin/env python3
"""Fails when a test of the last ctest run took more than a third of its timeout.

    python3 .ci/check_test_times.py BUILD_DIR --log CTEST_OUTPUT [--factor 3]

Reads each test's timeout from `ctest --show-only=json-v1` and its time from ctest's printed
output (lines "N/M Test #K: NAME ....   Passed   T sec"), so that a test which passes today but
would time out on a loaded machine is found before it does. Prints the tests with the least
margin."""
import argparse
import json
import re
import subprocess
import sys
from pathlib import Path


def timeouts(build):
    out = subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1"],
                         check=True, capture_output=True, text=True).stdout
    result = {}
    for test in json.loads(out)["tests"]:
        for prop in test.get("properties", []):
            if prop["name"] == "TIMEOUT":
                # ctest prints a parameterised GoogleTest's name without its "  # GetParam()".
                result[test["name"].split("  # ")[0]] = float(prop["value"])
    return result


def elapsed(log):
    pattern = re.compile(r"Test +#\d+: (\S+) .*?([0-9.]+) sec\s*$")
    result = {}
    for line in log.read_text(errors="replace").splitlines():
        m = pattern.search(line)
        if m:
            result[m.group(1)] = float(m.group(2))
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--factor", type=float, default=3.0)
    parser.add_argument("--log", required=True, help="what ctest printed")
    parser.add_argument("--timeouts", help="JSON {name: seconds} instead of asking ctest")
    args = parser.parse_args()
    log = Path(args.log)
    limits = json.loads(Path(args.timeouts).read_text()) if args.timeouts else timeouts(args.build)
    times = elapsed(log)
    if not times:
        sys.exit(f"check_test_times: no test times in {log}")
    margins = sorted((limits[n] / max(t, 0.01), n, t, limits[n]) for n, t in times.items()
                     if n in limits and limits[n] > 0)
    for ratio, name, t, limit in margins[:5]:
        print(f"check_test_times: {name}: {t:g} s of {limit:g} s ({ratio:.1f}x margin)")
    slow = [(n, t, limit) for ratio, n, t, limit in margins if t * args.factor > limit]
    for name, t, limit in slow:
        print(f"check_test_times: {name} took {t:g} s, more than 1/{args.factor:g} of its "
              f"timeout {limit:g} s", file=sys.stderr)
    print(f"check_test_times: {len(margins)} tests, {len(slow)} within {args.factor:g}x of "
          "their timeout")
    return 1 if slow else 0


if __name__ == "__main__":
    sys.exit(main())
