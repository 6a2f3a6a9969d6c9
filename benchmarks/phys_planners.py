#!/usr/bin/env python3
"""Runs ompl_phys_plan for every planner on every physics scene over many seeds (one process per
run, sequentially, or --jobs at a time) and reports per scene and planner: success rate, median
planning time, and the median action, power and smoothness of the solved runs' re-simulated
paths. Every solved run's controls are re-simulated by ompl_phys_plan; the table also counts the
runs whose re-simulation does not end in the goal (should be 0). Standard library only.

Example (the protocol of docs/benchmarks.md):
  benchmarks/phys_planners.py --seeds 10 --time-limit 60 --raw out/phys.json --markdown out/phys.md
"""
import argparse
import concurrent.futures
import json
import statistics
import sys
import tempfile

from run_records import check_binary, run_app

PLANNERS = ["kpiece", "rrt", "sycloprrt", "est", "syclopest"]
SCENES = ["scenes/physics/scene1.xml", "scenes/physics/scene2.xml", "scenes/physics/scene3.xml"]


def median(values):
    return statistics.median(values) if values else float("nan")


def table(results, time_limit):
    lines = [f"| scene | planner | solved (≤ {time_limit:g} s) | median time [s] | median action [N·s·m] "
             "| median power [W] | median smoothness [m²/s⁵] | re-simulation misses goal |",
             "|---|---|---|---|---|---|---|---|"]
    keys = sorted({(r["scene"], r["planner"]) for r in results},
                  key=lambda k: (k[0], PLANNERS.index(k[1]) if k[1] in PLANNERS else 99))
    for scene, planner in keys:
        runs = [r for r in results if r["scene"] == scene and r["planner"] == planner]
        solved = [r for r in runs if r["solved"]]
        # unsolved runs count at the time limit, so the median is honest when some fail
        times = [r["time_s"] if r["solved"] else time_limit for r in runs]
        misses = sum(1 for r in solved if not r.get("reaches_goal", False))
        lines.append(f"| {scene} | {planner} | {len(solved)}/{len(runs)} | {median(times):.2f} "
                     f"| {median([r['action'] for r in solved]):.3f} | {median([r['power'] for r in solved]):.2f} "
                     f"| {median([r['smoothness'] for r in solved]):.0f} | {misses} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenes", nargs="+", default=SCENES)
    parser.add_argument("--planners", nargs="+", default=PLANNERS)
    parser.add_argument("--seeds", type=int, default=10, help="number of seeds (1..N), default 10")
    parser.add_argument("--first-seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=60.0, help="seconds per run, default 60")
    parser.add_argument("--jobs", type=int, default=1, help="runs at a time, default 1 (timing is per run)")
    parser.add_argument("--binary", default="build/apps/ompl_phys_plan")
    parser.add_argument("--markdown", help="also write the table to this file")
    parser.add_argument("--raw", help="write all runs' JSON results to this file")
    args = parser.parse_args()
    if args.seeds < 1 or args.jobs < 1 or not args.time_limit > 0:
        sys.exit("--seeds and --jobs must be at least 1, --time-limit positive")
    check_binary(args.binary)

    jobs = [(scene, planner, seed) for scene in args.scenes for planner in args.planners
            for seed in range(args.first_seed, args.first_seed + args.seeds)]
    results = []
    with tempfile.TemporaryDirectory() as workdir, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(run_app, args.binary, scene, seed, workdir,
                               ["--planner", planner, "--time-limit", str(args.time_limit)]): (scene, planner, seed)
                   for scene, planner, seed in jobs}
        for future in concurrent.futures.as_completed(futures):
            r = future.result()
            results.append(r)
            print(f"{r['scene']} {r['planner']} seed {r['seed']}: "
                  f"{'solved' if r['solved'] else 'NOT solved'} in {r['time_s']:.2f} s", file=sys.stderr, flush=True)
            if args.raw:  # keep what has run so far: long experiments may be interrupted
                with open(args.raw, "w") as f:
                    json.dump(results, f, indent=1)
    text = table(results, args.time_limit)
    print(text)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
