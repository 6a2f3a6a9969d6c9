#!/usr/bin/env bash
# Line and branch coverage of the project's code by the whole test suite (the Release suite's tests,
# Python's included, but the downstream project's): builds in build-coverage/ with gcc's --coverage (-O1: the suite's planning
# tests take too long unoptimised), runs the suite, writes out/coverage/index.html (per file, lines
# and branches) and out/coverage/summary.txt (per library and app folder). Branches exclude those
# only exceptions take (every call that may throw has one).
#   scripts/coverage.sh [CTEST ARGUMENTS...]     e.g. -R test_RobotModel for one test
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh gcovr
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build-coverage -G Ninja -DCMAKE_BUILD_TYPE=Coverage -DCMAKE_CXX_FLAGS_COVERAGE="--coverage -O1 -g" \
  -DCMAKE_EXE_LINKER_FLAGS_COVERAGE=--coverage -DCMAKE_SHARED_LINKER_FLAGS_COVERAGE=--coverage \
  -DCMAKE_MODULE_LINKER_FLAGS_COVERAGE=--coverage -DOMPL_MM_UNITY_BUILD=ON > /dev/null
cmake --build build-coverage -j "$jobs"
find build-coverage -name '*.gcda' -delete
# downstream_package builds a project of its own against the installed libraries, without --coverage
(cd build-coverage && ctest -j "$jobs" -E downstream_package "$@") ||
  echo "coverage.sh: some tests failed; the report covers what ran" >&2

mkdir -p out/coverage
gcovr --root . --object-directory build-coverage --filter 'ompl_[a-z]+/' --filter 'apps/' --filter 'python/src/' \
  --exclude-throw-branches --exclude-unreachable-branches --gcov-ignore-parse-errors \
  --html-details out/coverage/index.html --json-summary out/coverage/summary.json --json-summary-pretty \
  -j "$jobs" > /dev/null
python3 - out/coverage/summary.json > out/coverage/summary.txt <<'PYEOF'
import collections, json, sys
files = json.load(open(sys.argv[1]))["files"]
totals = collections.defaultdict(lambda: [0, 0, 0, 0])
for f in files:
    part = f["filename"].split("/")[0] if not f["filename"].startswith("python/") else "python"
    t = totals[part]
    t[0] += f["line_covered"]; t[1] += f["line_total"]; t[2] += f["branch_covered"]; t[3] += f["branch_total"]
def pct(a, b):
    return "%5.1f %%" % (100.0 * a / b) if b else "    -  "
print("%-12s %15s %8s %17s %8s" % ("part", "lines", "", "branches", ""))
for part in sorted(totals):
    l, lt, b, bt = totals[part]
    print("%-12s %7d / %6d %s %8d / %6d %s" % (part, l, lt, pct(l, lt), b, bt, pct(b, bt)))
PYEOF
cat out/coverage/summary.txt
echo "coverage.sh: out/coverage/index.html, out/coverage/summary.txt"
