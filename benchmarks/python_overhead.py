#!/usr/bin/env python3
"""What planning from Python costs over the app: ompl_mm.plan() and ompl_mm_plan on the same seeds
(interleaved, one app process per run), their median planning times (the records' time_s) and
whether every record is the same; then how long turning a 1000-state path into numpy arrays
(ompl_mm.Path) takes.

Example (from the project root, after scripts/build.sh):
  PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_overhead.py --seeds 50
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import ompl_mm
from ompl_core import without_times

HERE = os.path.dirname(os.path.abspath(__file__))


def app_record(app, scene, seed, folder):
    """The JSON record of ompl_mm_plan on scene with seed."""
    file = os.path.join(folder, "run.json")
    subprocess.run([app, scene, "--seed", str(seed), "--json", file], check=False, capture_output=True)
    with open(file, encoding="utf-8") as f:
        return json.load(f)


def compare_planning_times(app, scene_file, seeds):
    """Median planning times of the app and of plan() over seeds, and how many records agree."""
    scene = ompl_mm.load_scene(scene_file)
    app_times, python_times, same = [], [], 0
    with tempfile.TemporaryDirectory() as folder:
        for seed in seeds:
            theirs = app_record(app, scene_file, seed, folder)
            ours = ompl_mm.plan(scene, seed=seed).record
            app_times.append(theirs["time_s"])
            python_times.append(ours["time_s"])
            same += without_times(theirs) == without_times(ours)
    return statistics.median(app_times), statistics.median(python_times), same


def path_conversion_ms(scene_file, states, repeats):
    """Median milliseconds ompl_mm.Path takes for a solution of scene_file interpolated to `states`
    states (its labels found once before timing, as after any change of the states)."""
    path = ompl_mm.plan(scene_file, seed=1).run.path()
    path.interpolate(states)
    ompl_mm.Path(path)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        ompl_mm.Path(path)
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times), len(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=os.path.join(HERE, "..", "scenes", "mobile_blocked.xml"))
    parser.add_argument("--seeds", type=int, default=50, help="seeds 1 … N (default 50)")
    parser.add_argument("--app", default=os.path.join(HERE, "..", "build", "apps", "ompl_mm_plan"))
    parser.add_argument("--path-scenes", nargs="+", default=[os.path.join(HERE, "..", "scenes", name + ".xml")
                                                             for name in ("mobile_blocked", "kuka_table")])
    args = parser.parse_args()
    if not os.access(args.app, os.X_OK):
        sys.exit(f"python_overhead: no app {args.app} (build first or pass --app)")
    app_median, python_median, same = compare_planning_times(args.app, args.scene, range(1, args.seeds + 1))
    print(f"{os.path.basename(args.scene)}, {args.seeds} seeds: median planning time app {app_median:.4f} s, "
          f"ompl_mm.plan {python_median:.4f} s (ratio {python_median / app_median:.3f}); "
          f"{same} of {args.seeds} records the same")
    for scene in args.path_scenes:
        ms, states = path_conversion_ms(scene, 1000, 200)
        print(f"{os.path.basename(scene)}: {states}-state path to numpy in {ms:.3f} ms (median of 200)")


if __name__ == "__main__":
    main()
