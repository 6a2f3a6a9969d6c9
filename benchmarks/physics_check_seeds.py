#!/usr/bin/env python3
"""Plans a scene with ompl_mm_plan --simulate for many seeds (one process per run) and reports how
many plans hold in physics: solved and confirmed shares, the end errors, what went wrong in the
plans not confirmed, and the planning and simulation times. Standard library only.

Examples:
  benchmarks/physics_check_seeds.py scenes/mobile_blocked.xml --seeds 100
  benchmarks/physics_check_seeds.py scenes/mobile_blocked.xml --seeds 100 --push-models kinematic,physics
"""
import argparse
import collections
import os
import statistics
import sys
import tempfile

from run_records import check_binary, run_app


def failure(check):
    """What kept a plan from being confirmed, in a few words."""
    objects = check["objects"]
    worst = max(objects, key=lambda name: objects[name]["position_error_m"])
    if any(o["tipped"] for o in objects.values()):
        return "an object tipped over"
    if any(o["off_surface"] for o in objects.values()):
        return "an object fell off its surface"
    if check["max_position_error_m"] > 0.02:
        return f"{worst} ends {objects[worst]['position_error_m']:.2f} m from its planned pose" \
            if len(objects) == 1 else "an object ends off its planned pose"
    return "the goal does not hold"


def report(scene, model, runs):
    """Prints what the runs of one push model came to."""
    solved = [r for r in runs if r["solved"]]
    checks = [r["physics_check"] for r in solved]
    confirmed = [c for c in checks if c["confirmed"]]
    print(f"{scene}, {model} pushes: {len(solved)} of {len(runs)} solved, {len(confirmed)} of {len(solved)} "
          f"confirmed in physics ({100.0 * len(confirmed) / max(1, len(solved)):.1f} %)")
    times = [r["time_s"] for r in runs]
    print(f"  planning time: median {statistics.median(times):.3f} s, mean {statistics.mean(times):.3f} s, "
          f"max {max(times):.3f} s")
    if not checks:
        return
    errors = [c["max_position_error_m"] for c in checks]
    print(f"  largest end error per plan: median {statistics.median(errors):.3f} m, max {max(errors):.3f} m")
    print(f"  goal holds in {sum(c['goal_holds'] for c in checks)} of {len(checks)} simulated end states")
    reasons = collections.Counter(failure(c) for c in checks if not c["confirmed"])
    for reason, count in reasons.most_common():
        print(f"  not confirmed, {count}x: {reason}")
    walls = [c["time_s"] for c in checks]
    simulated = [c["simulated_s"] for c in checks]
    print(f"  simulation: median {statistics.median(walls):.3f} s of wall time for a median "
          f"{statistics.median(simulated):.1f} s simulated")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--seeds", type=int, default=100, help="number of seeds, default 100")
    parser.add_argument("--first-seed", type=int, default=1,
                        help="the first seed (seeds FIRST..FIRST+N-1), default 1: shards of one run")
    parser.add_argument("--push-models", default="scene",
                        help="comma-separated push models to compare, each seed run with each in turn: "
                             "scene (the scene's own), kinematic, physics; default scene")
    parser.add_argument("--binary", default="build/apps/ompl_mm_plan")
    parser.add_argument("--records", help="folder that keeps every run's JSON record (default: a temporary one)")
    args = parser.parse_args()
    check_binary(args.binary)
    models = args.push_models.split(",")
    for model in models:
        if model not in ("scene", "kinematic", "physics"):
            sys.exit(f"unknown push model '{model}' (scene, kinematic, physics)")
    runs = {model: [] for model in models}
    with tempfile.TemporaryDirectory() as temporary:
        workdir = args.records or temporary
        os.makedirs(workdir, exist_ok=True)
        for seed in range(args.first_seed, args.first_seed + args.seeds):
            for model in models:
                extra = ("--simulate",) if model == "scene" else ("--simulate", "--push-model", model)
                runs[model].append(run_app(args.binary, args.scene, seed, workdir, extra=extra))
    for model in models:
        report(args.scene, model, runs[model])
    if not any(r["solved"] for model in models for r in runs[model]):
        sys.exit(1)


if __name__ == "__main__":
    main()
