#!/usr/bin/env python3
"""Compares two builds of a planning app on the same scene and seeds, in one run: for each seed
it runs the old binary and then the new one (alternating, so both see the same machine load)
and reports each one's median and mean planning time, success, the median of the per-seed time
ratios (robust to seeds of very different length), and how many seeds gave an identical result
(every value both write, but the times). Standard library only.

Example (before/after figures of a change):
  benchmarks/ab_seeds.py /tmp/old/ompl_mm_plan build/apps/ompl_mm_plan scenes/mobile_blocked.xml --seeds 50
"""
import argparse
import statistics
import sys
import tempfile

from run_records import check_binary, run_app


def same_values(a, b):
    """True when the two records agree on every key both have, timing values aside (they differ
    between any two runs; a key only one build writes is a format change, not a result)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return all(same_values(a[k], b[k]) for k in a.keys() & b.keys() if not k.startswith("time"))
    return a == b


def describe(name, records):
    times = [r["time_s"] for r in records]
    solved = sum(1 for r in records if r["solved"])
    return (f"{name}: solved {solved}/{len(records)}, time median {statistics.median(times):.4f} s, "
            f"mean {statistics.mean(times):.4f} s")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("scene")
    parser.add_argument("--seeds", type=int, default=50, help="number of seeds (1..N), default 50")
    parser.add_argument("--first-seed", type=int, default=1)
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
            old.append(run_app(args.old, args.scene, seed, workdir, args.args))
            new.append(run_app(args.new, args.scene, seed, workdir, args.args))
            same += same_values(old[-1], new[-1])
    print(describe("old", old))
    print(describe("new", new))
    print(f"identical results (all values both write, but times): {same}/{args.seeds} seeds")
    ratio = statistics.median(r["time_s"] for r in new) / statistics.median(r["time_s"] for r in old)
    paired = statistics.median(n["time_s"] / o["time_s"] for o, n in zip(old, new) if o["time_s"] > 0)
    print(f"median time new/old: {ratio:.3f}; median of the per-seed ratios new/old: {paired:.3f}")


if __name__ == "__main__":
    main()
