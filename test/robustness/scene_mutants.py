#!/usr/bin/env python3
"""Runs a planning app on mutants of a shipped scene (and of the robot's URDF) and fails on any
crash, sanitizer report, hang past the time limit, or exit code other than 0, 1 or 2.

The mutants are derived deterministically (a fixed seed) from the scene's text: numbers replaced by
0, -1, huge, tiny, NaN, infinity, hex or very long values; elements dropped or duplicated;
attribute names misspelt; values emptied or made very long; the file cut short. With --urdf, a
share of the mutants change the robot's URDF instead (the scene is copied beside a mutated copy).
Each mutant runs once with a short time limit; its exit code, time and stderr are judged.

Usage:
  scene_mutants.py APP SCENE... --count N [--seed S] [--time-limit T] [--urdf REL] [--work DIR] [--jobs J]
                   [--extra ARGS...]

N mutants in all, shared evenly by the scenes.

Prints a summary (mutants per exit code, the mutants that solved) and exits 1 on any failure.
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import time

NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")
ATTRIBUTE = re.compile(r'(\s)([a-z_0-9]+)="([^"]*)"')
ELEMENT_LINE = re.compile(r"^\s*<[a-z_]+[^>]*/>\s*$")
REPLACEMENTS = ["0", "-1", "1e308", "-1e308", "1e-308", "nan", "inf", "-inf", "0x10", "1e20", "2.5",
                "99999999999999999999", "9" * 400, "", "abc", "1,5"]
SANITIZER_MARKS = ("AddressSanitizer", "LeakSanitizer", "UndefinedBehaviorSanitizer", "runtime error:")
# a run may exceed its time limit by loading, writing and the sanitizer's slowness, not by this much
HANG_MARGIN_S = 5.0


def mutate(text, rng):
    """One mutant of text and a short description of what changed."""
    lines = text.split("\n")
    kind = rng.choice(["number", "number", "number", "drop", "duplicate", "misspell", "value", "cut"])
    if kind == "number":
        spots = [(i, m) for i, line in enumerate(lines) for m in NUMBER.finditer(line)]
        if spots:
            i, m = rng.choice(spots)
            new = rng.choice(REPLACEMENTS)
            lines[i] = lines[i][:m.start()] + new + lines[i][m.end():]
            return "\n".join(lines), f"line {i + 1}: number '{m.group()}' -> '{new[:20]}'"
    if kind in ("drop", "duplicate"):
        candidates = [i for i, line in enumerate(lines) if ELEMENT_LINE.match(line)]
        if candidates:
            i = rng.choice(candidates)
            if kind == "drop":
                del lines[i]
            else:
                lines.insert(i, lines[i])
            return "\n".join(lines), f"line {i + 1}: element {'dropped' if kind == 'drop' else 'duplicated'}"
    if kind in ("misspell", "value"):
        spots = [(i, m) for i, line in enumerate(lines) for m in ATTRIBUTE.finditer(line)]
        if spots:
            i, m = rng.choice(spots)
            if kind == "misspell":
                new = f'{m.group(1)}{m.group(2)}x="{m.group(3)}"'
            else:
                new = f'{m.group(1)}{m.group(2)}="{rng.choice(["", "x" * 5000, m.group(3) + " " + m.group(3)])}"'
            lines[i] = lines[i][:m.start()] + new + lines[i][m.end():]
            return "\n".join(lines), f"line {i + 1}: attribute '{m.group(2)}' {kind}"
    cut = rng.randrange(len(text))
    return text[:cut], f"cut at byte {cut}"


def judge(command, time_limit, env):
    """Runs command; returns (exit code, seconds, failure or None, stderr)."""
    start = time.monotonic()
    try:
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                              errors="replace", timeout=time_limit + HANG_MARGIN_S, env=env)
    except subprocess.TimeoutExpired:
        return None, time.monotonic() - start, f"hang: still running {time_limit + HANG_MARGIN_S:.0f} s after start", ""
    seconds = time.monotonic() - start
    if done.returncode < 0:
        return done.returncode, seconds, f"killed by signal {-done.returncode}", done.stderr
    if any(mark in done.stderr for mark in SANITIZER_MARKS):
        return done.returncode, seconds, "sanitizer report", done.stderr
    if done.returncode not in (0, 1, 2):
        return done.returncode, seconds, f"exit code {done.returncode}", done.stderr
    return done.returncode, seconds, None, done.stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("app")
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--count", type=int, default=300, help="mutants in all (default 300)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=0.5)
    parser.add_argument("--urdf", help="the robot's URDF, relative to the scene's folder: some mutants change it")
    parser.add_argument("--work", default="scene_mutants_scratch")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--extra", nargs=argparse.REMAINDER, default=[], help="further options for every run")
    args = parser.parse_args()

    shutil.rmtree(args.work, ignore_errors=True)
    rng = random.Random(args.seed)
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1", UBSAN_OPTIONS="print_stacktrace=1")
    jobs = []
    for k in range(args.count):
        scene = args.scenes[k % len(args.scenes)]
        scene_text = open(scene, encoding="utf-8").read()
        folder = os.path.join(args.work, f"m{k:04d}")
        scene_path = os.path.join(folder, os.path.basename(scene))
        os.makedirs(folder, exist_ok=True)
        what_prefix = os.path.basename(scene)
        if args.urdf:
            # the scene names its URDF relative to itself: keep that layout
            urdf_text = open(os.path.join(os.path.dirname(os.path.abspath(scene)), args.urdf), encoding="utf-8").read()
            urdf_path = os.path.join(folder, args.urdf)
            os.makedirs(os.path.dirname(urdf_path), exist_ok=True)
            if k % 4 == 3:
                urdf_text, what = mutate(urdf_text, rng)
                what_prefix = args.urdf
            open(urdf_path, "w", encoding="utf-8").write(urdf_text)
            if k % 4 == 3:
                open(scene_path, "w", encoding="utf-8").write(scene_text)
                jobs.append((k, f"{what_prefix} {what}", scene_path))
                continue
        mutant, what = mutate(scene_text, rng)
        open(scene_path, "w", encoding="utf-8").write(mutant)
        jobs.append((k, f"{what_prefix} {what}", scene_path))

    def run(job):
        k, what, scene_path = job
        command = [args.app, scene_path, "--time-limit", str(args.time_limit), "--seed", "1", *args.extra]
        return (k, what) + judge(command, args.time_limit, env)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = sorted(pool.map(run, jobs))

    by_code, failures, solved = {}, [], []
    for k, what, code, seconds, failure, stderr in results:
        by_code[code] = by_code.get(code, 0) + 1
        if failure:
            failures.append(f"mutant {k} ({what}): {failure} after {seconds:.1f} s\n    {stderr.strip()[:600]}")
        elif code == 0:
            solved.append(f"mutant {k}: {what}")
    app = os.path.basename(args.app)
    print(f"{app} on {len(results)} mutants of {', '.join(os.path.basename(s) for s in args.scenes)} "
          f"(seed {args.seed}): " +
          ", ".join(f"exit {code}: {n}" for code, n in sorted(by_code.items(), key=lambda i: str(i[0]))))
    print(f"solved (exit 0): {len(solved)}")
    for line in solved:
        print(f"  {line}")
    if failures:
        print(f"{len(failures)} FAILED:")
        for line in failures:
            print(f"  {line}")
        sys.exit(1)
    print("no crash, sanitizer report, hang or stray exit code")


if __name__ == "__main__":
    main()
