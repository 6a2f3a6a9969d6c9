#!/usr/bin/env python3
"""Runs ompl_mm_plan on one scene for many seeds (one process per run, sequentially) and reports
success rate, planning time and its breakdown, search effort and path quality next to the MOPL
paper's Table I row for the scene. Standard library only.

Example:
  benchmarks/mopl_seeds.py scenes/mobile_blocked.xml --seeds 50 --markdown out/mobile_blocked.md
"""
import argparse
import json
import statistics
import sys
import tempfile

from run_records import check_binary, run_app

# MOPL paper, Table I (200 runs, 3.1 GHz desktop, 2015): mean values.
PAPER = {
    "mobile_blocked": {"timeout_s": 60, "success": 97.5, "time_mean_s": 10.966, "time_std_s": 9.676,
                       "nn_share": 83.0, "ik_share": 0.0, "iterations": 4132, "path_vertices": 63.7,
                       "length_m": 17.389, "transit": 6.462, "push": 5.462, "transfer": 0.0},
    "kuka_table": {"timeout_s": 60, "success": 100.0, "time_mean_s": 4.96, "time_std_s": 2.33,
                   "nn_share": 12.0, "ik_share": 63.0, "iterations": 225, "path_vertices": 75,
                   "length_m": 8.112, "transit": 4.5, "push": 0.3, "transfer": 3.5},
    "kuka_cabinet": {"timeout_s": 180, "success": 96.5, "time_mean_s": 59.8, "time_std_s": 40.0,
                     "nn_share": 47.0, "ik_share": 45.0, "iterations": 1693, "path_vertices": 143,
                     "length_m": 11.07, "transit": 12.2, "push": 7.2, "transfer": 4.4},
    "meka_cleanup": {"timeout_s": 600, "success": 100.0, "time_mean_s": 152.4, "time_std_s": 81.1,
                     "nn_share": 49.0, "ik_share": 38.0, "iterations": 3505, "path_vertices": 104,
                     "length_m": 6.17, "transit": 5.9, "push": 1.7, "transfer": 4.2},
}


def summary(values):
    if not values:
        return float("nan"), float("nan"), float("nan")
    return statistics.median(values), statistics.mean(values), statistics.pstdev(values)


def report(name, results):
    solved = [r for r in results if r["solved"]]
    times = [r["time_s"] for r in solved]
    share = lambda key: 100.0 * sum(r["stats"][key] for r in solved) / max(sum(times), 1e-12)
    per_run_nn = [100.0 * r["stats"]["time_nearest_s"] / r["time_s"] for r in solved if r["time_s"] > 0]
    med, mean, std = summary(times)
    rows = [
        ("runs", f"{len(results)}", ""),
        ("success [%]", f"{100.0 * len(solved) / len(results):.1f}", "success"),
        ("time median [s]", f"{med:.3f}", ""),
        ("time mean ± std [s]", f"{mean:.3f} ± {std:.3f}", "time_mean_s"),
        ("time 90th percentile / max [s]",
         f"{statistics.quantiles(times, n=10)[-1]:.3f} / {max(times):.3f}" if len(times) > 1 else "-", ""),
        ("nearest-neighbour share [%] (of total time; median per run)",
         f"{share('time_nearest_s'):.1f} ({statistics.median(per_run_nn):.1f})" if per_run_nn else "-", "nn_share"),
        ("propagate share [%]", f"{share('time_propagate_s'):.1f}", ""),
        ("connect share [%]", f"{share('time_connect_s'):.1f}", ""),
        ("sampling share [%]", f"{share('time_sampling_s'):.1f}", ""),
        ("smoothing share [%]", f"{share('time_smoothing_s'):.1f}", ""),
        ("IK share [%] (inside the parts above)", f"{share('time_ik_s'):.1f}", "ik_share"),
        ("iterations (mean)", f"{statistics.mean(r['stats']['iterations'] for r in solved):.0f}", "iterations"),
        ("tree vertices (mean)", f"{statistics.mean(r['tree_vertices'] for r in solved):.0f}", ""),
        ("collision queries (mean)", f"{statistics.mean(r['stats']['collision_queries'] for r in solved):.0f}", ""),
        ("path vertices (mean)", f"{statistics.mean(r['path_vertices'] for r in solved):.1f}", "path_vertices"),
        ("Cartesian path length [m] (mean)", f"{statistics.mean(r['path_length_m'] for r in solved):.2f}", "length_m"),
        ("solutions passing PathGeometric::check()", f"{sum(r['path_valid'] for r in solved)}/{len(solved)}", ""),
    ]
    for kind, plural in (("transit", "transits"), ("push", "pushes"), ("transfer", "transfers")):
        rows.append((f"{plural} in path (mean)", f"{statistics.mean(r['primitives'][kind] for r in solved):.2f}", kind))
    paper = PAPER.get(name, {})
    lines = [f"| metric | ompl_mm | MOPL paper |", "|---|---|---|"]
    for label, ours, key in rows:
        theirs = paper.get(key, "")
        if key == "time_mean_s" and paper:
            theirs = f"{paper['time_mean_s']} ± {paper['time_std_s']}"
        lines.append(f"| {label} | {ours} | {theirs} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--seeds", type=int, default=50, help="number of seeds (1..N), default 50")
    parser.add_argument("--first-seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, help="seconds per run (default: the scene's)")
    parser.add_argument("--binary", default="build/apps/ompl_mm_plan")
    parser.add_argument("--markdown", help="also write the table to this file")
    parser.add_argument("--raw", help="write all runs' JSON results to this file")
    args = parser.parse_args()
    if args.seeds < 1:
        sys.exit("--seeds must be at least 1")
    check_binary(args.binary)

    with tempfile.TemporaryDirectory() as workdir:
        results = []
        for seed in range(args.first_seed, args.first_seed + args.seeds):
            limit = ["--time-limit", str(args.time_limit)] if args.time_limit else []
            results.append(run_app(args.binary, args.scene, seed, workdir, limit))
            print(f"seed {seed}: {'solved' if results[-1]['solved'] else 'NOT solved'} in {results[-1]['time_s']:.3f} s",
                  file=sys.stderr)
    name = results[0]["scene"]
    table = report(name, results)
    print(table)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(table + "\n")
    if args.raw:
        with open(args.raw, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
