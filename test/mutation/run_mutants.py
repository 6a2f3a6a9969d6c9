#!/usr/bin/env python3
"""Mutation testing of the test suite: applies each mutant of mutants.txt (one small deliberate
bug in an important line) to a scratch copy of the sources, one at a time, rebuilds incrementally,
runs the tests that depend on the mutated file and counts the mutant killed when one fails. Prints
the score (killed / total) and lists the survivors: lines no test guards. Not part of CI; run it
before closing any issue that changes core code. See docs/architecture.md.

Fast enough for the whole list at every need: the copy is built with shared libraries whose
dependents are not relinked when a library changes, so a mutant recompiles its file (or the files
including a mutated header) and relinks one library; only the tests that use a rebuilt library,
executable or module run (a test naming no build output always runs), the mutated file's own test
(test_<Name>) first, each test executable stopping at its first failing case and the run at the
first failing test. The test that killed each mutant last time is kept in killers.txt beside the
mutants: a mutant with one is first built only as far as that test needs (its executable, the
libraries and apps it uses) and that test run alone; only when it survives that is everything
rebuilt and every affected test run. A mutated header then recompiles one library and one test
instead of every file including it.

Usage:
  test/mutation/run_mutants.py [--only ID[,ID...]] [--work DIR] [--jobs N] [--report FILE]

A mutant whose build fails is "stillborn" and is not counted; fix its text in mutants.txt.
"""
import argparse
import filecmp
import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
# tests that exercise no planning code (the API docs, the layer table, the installed package) and
# the timed fuzzing of the readers (how many inputs it tries depends on the machine's speed)
EXCLUDED_TESTS = "test_api_docs|test_layering|downstream_package|test_fuzz_"
FIELDS = ("id", "file", "old", "new")
KILLERS = os.path.join(HERE, "killers.txt")


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


def read_killers(path):
    """mutant id -> the test that killed it last time (lines 'id test'; none when there is no file)."""
    if not os.path.isfile(path):
        return {}
    with open(path, encoding="utf-8") as f:
        return dict(line.split() for line in f if line.strip() and not line.startswith("#"))


def write_killers(path, killers):
    with open(path, "w", encoding="utf-8") as f:
        f.write("# The test that killed each mutant of mutants.txt last time (written by run_mutants.py).\n")
        for mutant_id in sorted(killers):
            f.write(f"{mutant_id} {killers[mutant_id]}\n")


def failed_test(build):
    """The test the last failing CTest run stopped at, or None."""
    failed = os.path.join(build, "Testing", "Temporary", "LastTestsFailed.log")
    if not os.path.isfile(failed):
        return None
    with open(failed) as f:
        names = [line.strip().split(":", 1)[1] for line in f if ":" in line]
    return names[0] if names else None


def build_outputs(build):
    """Modification times of the build's executables and shared libraries (ninja rewrites only what
    it rebuilds)."""
    times = {}
    for folder, _, names in os.walk(build):
        if "CMakeFiles" in folder:
            continue
        for name in names:
            path = os.path.join(folder, name)
            if (name.endswith(".so") or (os.access(path, os.X_OK) and "." not in name)) and os.path.isfile(path):
                times[path] = os.stat(path).st_mtime_ns
    return times


def direct_libraries(outputs):
    """For each output, the build's shared libraries it names as NEEDED (one readelf per output)."""
    by_name = {os.path.basename(o): o for o in outputs if o.endswith(".so")}
    direct = {}
    for output in outputs:
        dynamic = subprocess.run(["readelf", "-d", output], capture_output=True, text=True).stdout
        direct[output] = {by_name[n] for n in re.findall(r"\(NEEDED\).*\[(.*)\]", dynamic) if n in by_name}
    return direct


def loaded_libraries(output, direct):
    """The build's shared libraries that output loads, directly or through one another."""
    found, unvisited = set(), [output]
    while unvisited:
        for library in direct[unvisited.pop()] - found:
            found.add(library)
            unvisited.append(library)
    return found


def places(output, build):
    """The paths that name output in a test: itself, and for a shared library or module each
    folder above it inside the build (a module path such as PYTHONPATH names the modules below)."""
    found = [output]
    folder = os.path.dirname(output)
    while output.endswith(".so") and folder.startswith(build + os.sep):
        found.append(folder)
        folder = os.path.dirname(folder)
    return found


def names(path, text):
    """Whether text holds path whole (not as the start of a longer name)."""
    return re.search(re.escape(path) + r"(?![\w.])", text) is not None


def test_plan(build):
    """Each test of the suite (in declared order) with the build outputs it uses: those its command
    or environment names (a module's folder names the modules in it), and the libraries they load."""
    listing = json.loads(subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True,
                                        text=True, check=True).stdout)
    outputs = build_outputs(build)
    direct = direct_libraries(outputs)
    loads = {o: loaded_libraries(o, direct) for o in outputs}
    plan = []
    for test in listing["tests"]:
        words = list(test.get("command", []))
        for prop in test.get("properties", []):
            if prop["name"] == "ENVIRONMENT":
                words += prop["value"]
        text = "\n".join(words)
        used = {o for o in outputs if any(names(place, text) for place in places(o, build))}
        for o in list(used):
            used |= loads[o]
        plan.append((test["name"], used))
    return plan


def affected_tests(plan, changed):
    """The tests that use a changed output or name none, in declared order."""
    return [name for name, used in plan if not used or used & changed]


def run_tests(names, build, log, jobs, first=None):
    """Runs the named tests, the one called first (when among them) before the others, which CTest
    runs in declared order (without its record of earlier run times: unit tests first); stops at the
    first failure. 0 when all pass."""
    order = [[first]] if first in names else []
    order.append([n for n in names if n != first])
    cost_data = os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    env = dict(os.environ, GTEST_FAIL_FAST="1")
    for group in order:
        if not group:
            continue
        if os.path.exists(cost_data):
            os.remove(cost_data)
        regex = "^(" + "|".join(re.escape(n) for n in group) + ")$"
        status = run(["ctest", "-j", str(jobs), "-R", regex, "-E", EXCLUDED_TESTS, "--stop-on-failure",
                      "--timeout", "600"], build, log, env=env)
        if status != 0:
            return status
    return 0


def run(command, cwd, log, timeout=None, env=None):
    with open(log, "a") as out:
        out.write(f"$ {' '.join(command)}\n")
        out.flush()
        try:
            return subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout,
                                  env=env).returncode
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
    started = time.monotonic()
    # shared libraries, their dependents not relinked when one changes: a mutant relinks one library
    configure = ["cmake", "-S", src, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                 "-DBUILD_SHARED_LIBS=ON", "-DCMAKE_LINK_DEPENDS_NO_SHARED=ON"]
    if run(configure, src, log) != 0 or run(["cmake", "--build", build, "-j", str(args.jobs)], src, log) != 0:
        sys.exit(f"the unmutated copy does not build: see {log}")
    plan = test_plan(build)
    uses = {name: used for name, used in plan}
    killers = read_killers(KILLERS)
    if run_tests([name for name, _ in plan], build, log, args.jobs) != 0:
        sys.exit(f"the suite fails without any mutant: see {log}")
    print(f"built and passed in {time.monotonic() - started:.0f} s", flush=True)

    results = []
    for k, mutant in enumerate(mutants, 1):
        path = os.path.join(src, mutant["file"])
        original = check_applies(mutant, src)
        start = time.monotonic()
        before = build_outputs(build)
        with open(path, "w", encoding="utf-8") as f:
            f.write(original.replace(mutant["old"], mutant["new"]))
        tests, outcome = [], None
        try:
            # the test that killed it last time, built only as far as it needs
            killer = killers.get(mutant["id"])
            needs = uses.get(killer)
            if needs:
                targets = sorted(os.path.relpath(o, build) for o in needs)
                if run(["ninja", "-C", build, "-j", str(args.jobs)] + targets, src, log) != 0:
                    outcome = "stillborn"
                elif run_tests([killer], build, log, args.jobs) != 0:
                    tests, outcome = [killer], "killed"
            if outcome is None:
                if run(["cmake", "--build", build, "-j", str(args.jobs)], src, log) != 0:
                    outcome = "stillborn"
                else:
                    after = build_outputs(build)
                    changed = {o for o, t in after.items() if before.get(o) != t}
                    tests = affected_tests(plan, changed)
                    own = "test_" + os.path.splitext(os.path.basename(mutant["file"]))[0]
                    if run_tests(tests, build, log, args.jobs, own) != 0:
                        outcome = "killed"
                        killers[mutant["id"]] = failed_test(build) or killers.get(mutant["id"])
                    else:
                        outcome = "survived"
        finally:
            with open(path, "w", encoding="utf-8") as f:
                f.write(original)
        results.append((mutant, outcome))
        print(f"[{k}/{len(mutants)}] {outcome:9} {mutant['id']} ({time.monotonic() - start:.0f} s, "
              f"{len(tests)} tests chosen)", flush=True)
        if args.report:  # as it goes: a long run may be interrupted
            with open(args.report, "a") as f:
                f.write(f"{outcome} {mutant['id']}\n")
        if outcome == "killed":
            write_killers(KILLERS, {k: v for k, v in killers.items() if v})
    # leave the build matching the sources
    run(["cmake", "--build", build, "-j", str(args.jobs)], src, log)
    print(f"whole run: {time.monotonic() - started:.0f} s")

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
