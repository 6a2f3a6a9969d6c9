#!/usr/bin/env python3
"""Mesh robots with exact meshes (the default) against convex hulls: runs ompl_mm_plan on scenes
whose robot has mesh links (the Panda scenes by default) for many seeds, each seed once with the
scene as it is and once with meshes="convex_hull" on its robot, alternating in one run, and reports
per scene and mode: solved share, median and mean planning time, median whole-process wall time,
median tool path, and the median over seeds of the exact/hull time ratio. Standard library only.

Example:
  benchmarks/mesh_collision.py --seeds 50 --markdown out/mesh_collision.md
"""
import argparse
import os
import re
import statistics
import sys
import tempfile
import time

from run_records import check_binary, run_app

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PANDA_SCENES = ["panda_reach", "panda_table", "panda_push", "panda_tall"]


def hull_copy(scene, workdir):
    """The scene with meshes="convex_hull" on its robot element, its file paths made absolute, in
    workdir."""
    text = open(scene).read()
    folder = os.path.dirname(os.path.abspath(scene))
    text = re.sub(r'(urdf|srdf)="([^"/][^"]*)"', lambda m: f'{m.group(1)}="{os.path.join(folder, m.group(2))}"',
                  text)
    text, count = re.subn(r"<robot ", '<robot meshes="convex_hull" ', text, count=1)
    if count != 1 or 'meshes="' in text.split("<robot ", 1)[1].split(">", 1)[0].replace('meshes="convex_hull"', "", 1):
        sys.exit(f"{scene}: cannot set meshes on its robot element")
    out = os.path.join(workdir, os.path.basename(scene))
    with open(out, "w") as f:
        f.write(text)
    return out


def timed_run(binary, scene, seed, workdir, time_limit):
    started = time.monotonic()
    record = run_app(binary, scene, seed, workdir, ["--time-limit", str(time_limit)])
    record["wall_s"] = time.monotonic() - started
    return record


def summary_row(name, mode, runs):
    solved = [r for r in runs if r["solved"]]
    times = [r["time_s"] for r in runs]
    walls = [r["wall_s"] for r in runs]
    lengths = [r["path_length_m"] for r in solved]
    return (f"| {name} | {mode} | {len(solved)}/{len(runs)} | {statistics.median(times):.3f} | "
            f"{statistics.mean(times):.3f} | {statistics.median(walls):.3f} | "
            f"{statistics.median(lengths) if lengths else float('nan'):.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenes", nargs="*", help="scene files (default: the Panda scenes)")
    parser.add_argument("--seeds", type=int, default=50)
    parser.add_argument("--first-seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=60.0)
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "apps", "ompl_mm_plan"))
    parser.add_argument("--markdown", help="also write the table to this file")
    args = parser.parse_args()
    check_binary(args.binary)
    scenes = args.scenes or [os.path.join(ROOT, "scenes", f"{name}.xml") for name in PANDA_SCENES]
    lines = ["| scene | meshes | solved | median time s | mean time s | median wall s | median tool path m |",
             "|---|---|---|---|---|---|---|"]
    ratios_lines = []
    with tempfile.TemporaryDirectory() as workdir:
        for scene in scenes:
            name = os.path.splitext(os.path.basename(scene))[0]
            hull = hull_copy(scene, workdir)
            exact_runs, hull_runs = [], []
            for seed in range(args.first_seed, args.first_seed + args.seeds):
                exact_runs.append(timed_run(args.binary, scene, seed, workdir, args.time_limit))
                hull_runs.append(timed_run(args.binary, hull, seed, workdir, args.time_limit))
            lines.append(summary_row(name, "exact", exact_runs))
            lines.append(summary_row(name, "convex_hull", hull_runs))
            ratios = [e["time_s"] / h["time_s"] for e, h in zip(exact_runs, hull_runs) if h["time_s"] > 0]
            ratios_lines.append(f"{name}: exact/hull time per seed, median {statistics.median(ratios):.2f} "
                                f"(quartiles {statistics.quantiles(ratios, n=4)[0]:.2f}, "
                                f"{statistics.quantiles(ratios, n=4)[2]:.2f})")
            print(lines[-2], lines[-1], ratios_lines[-1], sep="\n", flush=True)
    text = "\n".join(lines + [""] + ratios_lines) + "\n"
    print(text)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
