#!/usr/bin/env python3
"""How far whole runs overshoot their time limit: every shipped scene with every planner of its app,
and the heavy mesh robot of the tests (a Franka Panda whose links are exact triangle meshes,
test/data/scenes/panda_*.xml), several short limits and seeds, each run as a process timed from start
to exit (loading the scene, setting up, planning, smoothing or re-simulating, re-checking, writing the
JSON). A run's budget is its time before planning, the limit and 50 ms; its overshoot is its wall time
minus its time before planning minus the limit (a run that solves early has a negative one). The time
before planning is the run's own load and setup phases (the JSON's phases_s), so the process's start
and exit count against the budget. Binaries that do not report their phases (older builds) are given
the wall time of a run that stops before planning (--list-params, the quickest of three, start and
exit included, but not the setup() of the planner nor the opening of the outputs, so their
overshoot comes out higher by those). Prints the largest and the median overshoot per app, scene and
planner for each limit, the largest overshoot of planning alone (the JSON's time_s minus the limit,
the same measure in every build), the runs over budget and the worst runs. Standard library only.

Example:
  benchmarks/time_limit_overshoot.py --seeds 3 --limits 0.01 0.1 1
  benchmarks/time_limit_overshoot.py --apps /tmp/before-apps --only panda   # an older build's binaries
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from run_records import check_binary

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, ".."))
MM_PLANNERS = ["mopl", "rrtconnect", "rrt", "est"]
PHYSICS_PLANNERS = ["rrt", "est", "kpiece", "sycloprrt", "syclopest", "pdst", "sst"]
# a heavy mesh robot: a collision query costs milliseconds, a continuous check up to a tenth of a second
MESH_SCENES = sorted(glob.glob(os.path.join(ROOT, "test", "data", "scenes", "panda_*.xml")))
# slack beyond the limit that a run may take (after its own time before planning)
ALLOWED_OVERSHOOT = 0.05


def runs(apps):
    """(app binary, scene, planner) for every shipped scene and planner, then the mesh robot's scenes."""
    mm = os.path.join(apps, "ompl_mm_plan")
    phys = os.path.join(apps, "ompl_phys_plan")
    for scene in sorted(glob.glob(os.path.join(ROOT, "scenes", "*.xml"))) + MESH_SCENES:
        for planner in MM_PLANNERS:
            yield mm, scene, planner
    for scene in sorted(glob.glob(os.path.join(ROOT, "scenes", "physics", "*.xml"))):
        for planner in PHYSICS_PLANNERS:
            yield phys, scene, planner


def quickest(command, runs):
    """The least wall time of runs of command, seconds."""
    walls = []
    for _ in range(runs):
        start = time.monotonic()
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        walls.append(time.monotonic() - start)
    return min(walls)


def before_planning(binary, scene, planner, cache):
    """Wall time of a run that loads and sets up the scene and stops before planning (--list-params),
    the least of three: the time before planning of a binary that does not report its phases."""
    key = (binary, scene, planner)
    if key not in cache:
        cache[key] = quickest([binary, scene, "--planner", planner, "--list-params"], 3)
    return cache[key]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder with apps/")
    parser.add_argument("--apps", help="folder holding the app binaries (default: BUILD/apps)")
    parser.add_argument("--seeds", type=int, default=3, help="seeds 1..N per limit (default 3)")
    parser.add_argument("--limits", type=float, nargs="+", default=[0.01, 0.1, 1.0],
                        help="time limits in seconds (default 0.01 0.1 1)")
    parser.add_argument("--only", help="only scenes whose file name contains this text")
    parser.add_argument("--worst", type=int, default=5, help="list this many worst runs (default 5)")
    args = parser.parse_args()
    if args.seeds < 1 or any(limit <= 0 for limit in args.limits):
        sys.exit("--seeds must be at least 1 and every limit positive")
    apps = args.apps or os.path.join(args.build, "apps")
    results = []  # (overshoot, name, limit, seed, solved, wall, time before planning, solve time)
    estimates = {}
    with tempfile.TemporaryDirectory() as workdir:
        json_file = os.path.join(workdir, "run.json")
        for binary, scene, planner in runs(apps):
            if args.only and args.only not in os.path.basename(scene):
                continue
            check_binary(binary)
            rejected = False
            for limit in args.limits:
                for seed in range(1, args.seeds + 1):
                    if rejected:
                        break
                    command = [binary, scene, "--planner", planner, "--seed", str(seed), "--time-limit", str(limit),
                               "--json", json_file]
                    if os.path.exists(json_file):
                        os.remove(json_file)
                    start = time.monotonic()
                    status = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                    wall = time.monotonic() - start
                    if status.returncode == 2:  # an older build may not read a newer scene
                        print(f"skipped, the app rejects it: {' '.join(command)}\n  {status.stderr.strip()}",
                              file=sys.stderr)
                        rejected = True
                        continue
                    if status.returncode not in (0, 1):
                        sys.exit(f"exit {status.returncode}: {' '.join(command)}\n{status.stderr}")
                    with open(json_file) as f:
                        record = json.load(f)
                    phases = record.get("phases_s")
                    if phases:
                        before = phases["load"] + phases["setup"]
                    else:
                        before = before_planning(binary, scene, planner, estimates)
                    name = f"{os.path.basename(binary)} {os.path.basename(scene)} {planner}"
                    results.append((wall - before - limit, name, limit, seed, status.returncode == 0, wall, before,
                                    record["time_s"]))
    names = list(dict.fromkeys(r[1] for r in results))
    limits = sorted(set(args.limits))
    print(f"overshoot [ms] of wall time over (time before planning + limit), largest (median) of {args.seeds} "
          f"seed(s) per cell; budget {1000 * ALLOWED_OVERSHOOT:.0f} ms\n")
    print("| app, scene, planner | " + " | ".join(f"limit {limit:g} s" for limit in limits) +
          " | planning alone | over budget |")
    print("|---|" + "---|" * len(limits) + "---|---|")
    for name in names:
        mine = [r for r in results if r[1] == name]
        cells = []
        for limit in limits:
            overshoots = [r[0] for r in mine if r[2] == limit]
            cells.append(f"{1000 * max(overshoots):.0f} ({1000 * statistics.median(overshoots):.0f})")
        over = sum(1 for r in mine if r[0] > ALLOWED_OVERSHOOT)
        planning = max(r[7] - r[2] for r in mine)
        print(f"| {name} | " + " | ".join(cells) + f" | {1000 * planning:.0f} | {over} of {len(mine)} |")
    worst = max(r[0] for r in results)
    over = [r for r in results if r[0] > ALLOWED_OVERSHOOT]
    print(f"\nlargest overshoot over all {len(results)} runs: {1000 * worst:.0f} ms; "
          f"{len(over)} run(s) over the {1000 * ALLOWED_OVERSHOOT:.0f} ms budget")
    print("worst runs (wall = before planning + solve + the rest):")
    for overshoot, name, limit, seed, solved, wall, before, solve in sorted(results, reverse=True)[:args.worst]:
        print(f"  {1000 * overshoot:.0f} ms: {name}, limit {limit:g} s, seed {seed}, "
              f"{'solved' if solved else 'not solved'}; wall {wall:.3f} s = {before:.3f} + {solve:.3f} + "
              f"{wall - before - solve:.3f} s")


if __name__ == "__main__":
    main()
