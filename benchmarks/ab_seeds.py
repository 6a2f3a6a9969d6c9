#!/usr/bin/env python3
"""Compares two builds of a planning app on the same scene and seeds, in one run: for each seed
it runs the old binary and then the new one (alternating, so both see the same machine load)
and reports each one's median and mean planning time, success, the median of the per-seed time
ratios (robust to seeds of very different length), and how many seeds gave an identical result
(every value both write, but the times). With --quality (ompl_mm_plan only) it also reports
plan quality from the JSON and the path files: mean tool-path length, pushes per plan, round-trip pushes (an
object pushed back to where it stood before), push reversals (a push moving an object back against
the push before, ManipulationPath::pushReversals) and the smoothing time. Standard library only.

Example (before/after figures of a change; of a scene's settings: one binary twice, --new-scene):
  benchmarks/ab_seeds.py /tmp/old/ompl_mm_plan build/apps/ompl_mm_plan scenes/mobile_blocked.xml --seeds 50
"""
import argparse
import statistics
import sys
import tempfile

from run_records import check_binary, push_reversals, read_path_file, round_trip_pushes, run_app


def same_values(a, b):
    """True when the two records agree on every key both have, timing and memory values aside (they
    differ between any two runs; a key only one build writes is a format change, not a result)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return all(same_values(a[k], b[k]) for k in a.keys() & b.keys()
                   if not k.startswith("time") and k not in ("peak_memory_mb", "phases_s"))
    return a == b


def describe(name, records):
    times = [r["time_s"] for r in records]
    solved = sum(1 for r in records if r["solved"])
    return (f"{name}: solved {solved}/{len(records)}, time median {statistics.median(times):.4f} s, "
            f"mean {statistics.mean(times):.4f} s")


def describe_quality(name, records):
    solved = [r for r in records if r["solved"]]
    if not solved:
        return f"{name}: no solved run"
    trips = [r["round_trips"] for r in solved]
    reversals = [r["reversals"] for r in solved]
    pushes = [sum(n for kind, n in r.get("primitives", {}).items() if kind.startswith("push")) for r in solved]
    return (f"{name}: tool path mean {statistics.mean(r['path_length_m'] for r in solved):.3f} m, "
            f"pushes per plan {statistics.mean(pushes):.2f} (in {sum(1 for p in pushes if p)} plans), "
            f"round-trip pushes {sum(trips)} in {sum(1 for t in trips if t)}/{len(solved)} plans, "
            f"push reversals {sum(reversals)} in {sum(1 for r in reversals if r)}/{len(solved)} plans, "
            f"smoothing time median {statistics.median(r['stats']['time_smoothing_s'] for r in solved):.4f} s")


def run_with_quality(binary, scene, seed, workdir, extra, quality):
    """One run; with quality, its record gets the round trips and push reversals counted in its path
    file (an older build's record may not count them)."""
    if not quality:
        return run_app(binary, scene, seed, workdir, extra)
    path_file = f"{workdir}/path.txt"
    record = run_app(binary, scene, seed, workdir, extra, path_file=path_file)
    rows = read_path_file(path_file) if record["solved"] else []
    record["round_trips"] = round_trip_pushes(rows)
    record["reversals"] = push_reversals(rows)
    return record


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("scene")
    parser.add_argument("--new-scene", help="the scene the new binary plans (default: the same scene; "
                        "compare a scene's settings with one binary given twice)")
    parser.add_argument("--seeds", type=int, default=50, help="number of seeds (1..N), default 50")
    parser.add_argument("--first-seed", type=int, default=1)
    parser.add_argument("--quality", action="store_true",
                        help="also report tool-path length, round-trip pushes, push reversals and smoothing "
                        "time (ompl_mm_plan)")
    parser.add_argument("--args", nargs=argparse.REMAINDER, default=[],
                        help="further options for both apps (e.g. --planner rrt --time-limit 60)")
    args = parser.parse_args()
    if args.seeds < 1:
        sys.exit("--seeds must be at least 1")
    check_binary(args.old)
    check_binary(args.new)
    old, new, same = [], [], 0
    with tempfile.TemporaryDirectory() as workdir:
        for seed in range(args.first_seed, args.first_seed + args.seeds):
            old.append(run_with_quality(args.old, args.scene, seed, workdir, args.args, args.quality))
            new.append(run_with_quality(args.new, args.new_scene or args.scene, seed, workdir, args.args,
                                        args.quality))
            same += same_values(old[-1], new[-1])
    print(describe("old", old))
    print(describe("new", new))
    if args.quality:
        print(describe_quality("old", old))
        print(describe_quality("new", new))
    print(f"identical results (all values both write, but times): {same}/{args.seeds} seeds")
    ratio = statistics.median(r["time_s"] for r in new) / statistics.median(r["time_s"] for r in old)
    paired = statistics.median(n["time_s"] / o["time_s"] for o, n in zip(old, new) if o["time_s"] > 0)
    print(f"median time new/old: {ratio:.3f}; median of the per-seed ratios new/old: {paired:.3f}")


if __name__ == "__main__":
    main()
