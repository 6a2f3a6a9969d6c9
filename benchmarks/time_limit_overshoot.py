#!/usr/bin/env python3
"""How far whole runs overshoot their time limit: every shipped scene with every planner of its app,
several short limits and seeds, each run as a process timed from start to exit (loading the scene,
planning, smoothing or re-simulating, writing the JSON). The overshoot of a run is its wall time
minus its limit; a run that solves early has a negative one. Prints the maximum per app and planner
and the worst runs. Standard library only.

Example:
  benchmarks/time_limit_overshoot.py --seeds 5 --limits 0.05 0.2 1
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

from run_records import check_binary

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, ".."))
PHYSICS_PLANNERS = ["rrt", "est", "kpiece", "sycloprrt", "syclopest", "pdst", "sst"]


def runs(build):
    """(app binary, scene, planner) for every shipped scene and planner."""
    mm = os.path.join(build, "apps", "ompl_mm_plan")
    phys = os.path.join(build, "apps", "ompl_phys_plan")
    yield mm, os.path.join(ROOT, "scenes", "mobile_blocked.xml"), "mopl"
    for n in (1, 2, 3):
        for planner in PHYSICS_PLANNERS:
            yield phys, os.path.join(ROOT, "scenes", "physics", f"scene{n}.xml"), planner


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder with apps/")
    parser.add_argument("--seeds", type=int, default=3, help="seeds 1..N per limit (default 3)")
    parser.add_argument("--limits", type=float, nargs="+", default=[0.05, 0.2, 1.0],
                        help="time limits in seconds (default 0.05 0.2 1)")
    parser.add_argument("--worst", type=int, default=5, help="list this many worst runs (default 5)")
    args = parser.parse_args()
    if args.seeds < 1 or any(limit <= 0 for limit in args.limits):
        sys.exit("--seeds must be at least 1 and every limit positive")
    results = []
    with tempfile.TemporaryDirectory() as workdir:
        json_file = os.path.join(workdir, "run.json")
        for binary, scene, planner in runs(args.build):
            check_binary(binary)
            for limit in args.limits:
                for seed in range(1, args.seeds + 1):
                    command = [binary, scene, "--planner", planner, "--seed", str(seed), "--time-limit", str(limit),
                               "--json", json_file]
                    start = time.monotonic()
                    status = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                    wall = time.monotonic() - start
                    if status.returncode not in (0, 1):
                        sys.exit(f"exit {status.returncode}: {' '.join(command)}\n{status.stderr}")
                    name = f"{os.path.basename(binary)} {os.path.basename(scene)} {planner}"
                    results.append((wall - limit, name, limit, seed, status.returncode == 0))
    by_planner = {}
    for overshoot, name, *_ in results:
        by_planner[name] = max(by_planner.get(name, overshoot), overshoot)
    print("| app, scene, planner | runs | largest overshoot [ms] |")
    print("|---|---|---|")
    for name, worst in by_planner.items():
        count = sum(1 for r in results if r[1] == name)
        print(f"| {name} | {count} | {1000 * worst:.0f} |")
    print(f"\nlargest overshoot over all {len(results)} runs: {1000 * max(r[0] for r in results):.0f} ms")
    print("worst runs:")
    for overshoot, name, limit, seed, solved in sorted(results, reverse=True)[:args.worst]:
        print(f"  {1000 * overshoot:.0f} ms: {name}, limit {limit} s, seed {seed}, {'solved' if solved else 'not solved'}")


if __name__ == "__main__":
    main()
