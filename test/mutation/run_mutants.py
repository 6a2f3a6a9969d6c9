#!/usr/bin/env python3
"""Mutation testing of the test suite: applies each mutant of mutants.txt (one small deliberate
bug in an important line) to a scratch copy of the sources, one at a time, rebuilds incrementally,
runs the suite and counts the mutant killed when a test fails. Prints the score (killed / total)
and lists the survivors: lines no test guards. Not part of CI (a mutant takes from seconds to a
minute and a half); run it before closing any issue that changes core code. See docs/architecture.md.

Usage:
  test/mutation/run_mutants.py [--only ID[,ID...]] [--work DIR] [--jobs N] [--report FILE]

A mutant whose build fails is "stillborn" and is not counted; fix its text in mutants.txt.
"""
import argparse
import filecmp
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
# tests that exercise no planning code (the API docs, the layer table, the installed package) and
# the timed fuzzing of the loaders, which their unit tests cover
EXCLUDED_TESTS = "test_api_docs|test_layering|downstream_package|test_scene_fuzz"
FIELDS = ("id", "file", "old", "new")


def read_mutants(path):
    """The mutants of the file, each a dict with id, file, old, new and the comment above it."""
    mutants, block, comment = [], {}, ""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines() + [""]
    for number, line in enumerate(lines, 1):
        if not line.strip():
            if block:
                missing = [k for k in FIELDS if k not in block]
                if missing:
                    sys.exit(f"{path}:{number}: mutant ends without {', '.join(missing)}")
                block["comment"] = comment
                mutants.append(block)
            block, comment = {}, ""
        elif line.startswith("#"):
            comment = line[1:].strip()
        else:
            key, sep, value = line.partition(": ")
            if not sep or key not in FIELDS or key in block:
                sys.exit(f"{path}:{number}: expected one of {', '.join(f + ':' for f in FIELDS)} once per mutant")
            block[key] = value
    ids = [m["id"] for m in mutants]
    duplicates = {i for i in ids if ids.count(i) > 1}
    if duplicates:
        sys.exit(f"{path}: ids used twice: {', '.join(sorted(duplicates))}")
    return mutants


def check_applies(mutant, src):
    text = open(os.path.join(src, mutant["file"]), encoding="utf-8").read()
    count = text.count(mutant["old"])
    if count != 1 or mutant["old"] == mutant["new"]:
        sys.exit(f"mutant {mutant['id']}: 'old' occurs {count} times in {mutant['file']} (must be once), "
                 "or equals 'new'")
    return text


def run_suite(command, build, log):
    """Runs the suite in the order the tests are declared, unit tests first: without its record of
    earlier run times, CTest does not start the slowest (end-to-end) tests first, and a mutant is
    mostly killed by a unit test within seconds."""
    cost_data = os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    if os.path.exists(cost_data):
        os.remove(cost_data)
    return run(command, build, log)


def run(command, cwd, log, timeout=None):
    with open(log, "a") as out:
        out.write(f"$ {' '.join(command)}\n")
        out.flush()
        try:
            return subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            out.write("timed out\n")
            return 124


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--only", help="comma-separated ids to run (default: all)")
    parser.add_argument("--work", default=os.path.join(ROOT, "build-mutation"), help="scratch folder")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--report", help="also append each result, then the score, to this file")
    args = parser.parse_args()

    mutants = read_mutants(os.path.join(HERE, "mutants.txt"))
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - {m["id"] for m in mutants}
        if unknown:
            sys.exit(f"unknown mutant ids: {', '.join(sorted(unknown))}")
        mutants = [m for m in mutants if m["id"] in wanted]

    src, build, log = (os.path.join(args.work, d) for d in ("src", "build", "log.txt"))
    os.makedirs(args.work, exist_ok=True)
    # the tracked sources (the working tree's, with uncommitted changes); a file whose copy differs
    # gets a new timestamp, so the build redoes whatever an interrupted run compiled from a mutant
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout.split()
    for name in files:
        source, copy = os.path.join(ROOT, name), os.path.join(src, name)
        if os.path.isfile(source) and not (os.path.isfile(copy) and filecmp.cmp(source, copy, shallow=False)):
            os.makedirs(os.path.dirname(copy), exist_ok=True)
            shutil.copyfile(source, copy)
            shutil.copymode(source, copy)
    for mutant in mutants:
        check_applies(mutant, src)

    print(f"building the unmutated copy in {build} (log: {log})", flush=True)
    if run(["cmake", "-S", src, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"], src, log) != 0 or \
            run(["cmake", "--build", build, "-j", str(args.jobs)], src, log) != 0:
        sys.exit(f"the unmutated copy does not build: see {log}")
    ctest = ["ctest", "-j", str(args.jobs), "-E", EXCLUDED_TESTS, "--stop-on-failure", "--timeout", "600"]
    if run_suite(ctest, build, log) != 0:
        sys.exit(f"the suite fails without any mutant: see {log}")

    results = []
    for k, mutant in enumerate(mutants, 1):
        path = os.path.join(src, mutant["file"])
        original = check_applies(mutant, src)
        start = time.monotonic()
        with open(path, "w", encoding="utf-8") as f:
            f.write(original.replace(mutant["old"], mutant["new"]))
        try:
            if run(["cmake", "--build", build, "-j", str(args.jobs)], src, log) != 0:
                outcome = "stillborn"
            else:
                outcome = "killed" if run_suite(ctest, build, log) != 0 else "survived"
        finally:
            with open(path, "w", encoding="utf-8") as f:
                f.write(original)
        results.append((mutant, outcome))
        print(f"[{k}/{len(mutants)}] {outcome:9} {mutant['id']} ({time.monotonic() - start:.0f} s)", flush=True)
        if args.report:  # as it goes: a long run may be interrupted
            with open(args.report, "a") as f:
                f.write(f"{outcome} {mutant['id']}\n")
    # leave the build matching the sources
    run(["cmake", "--build", build, "-j", str(args.jobs)], src, log)

    counted = [(m, o) for m, o in results if o != "stillborn"]
    killed = sum(1 for _, o in counted if o == "killed")
    lines = [f"mutation score: {killed} killed / {len(counted)} mutants"
             + (f" ({100.0 * killed / len(counted):.1f} %)" if counted else "")]
    for mutant, outcome in results:
        if outcome != "killed":
            lines.append(f"  {outcome}: {mutant['id']} {mutant['file']}: {mutant['comment']}")
    print("\n".join(lines))
    if args.report:
        with open(args.report, "a") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
