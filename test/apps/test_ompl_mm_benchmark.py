#!/usr/bin/env python3
"""Tests for the ompl_mm_benchmark contract (docs/benchmarks.md): bad configs exit 2 naming cfg:line;
the logs parse with Debian's ompl_benchmark_statistics without warnings into a database whose columns
and values match the log; a run is planned again by the plan app from its seed alone; three shards
run through GNU parallel give the same runs as one unsharded run; a user's own planner runs from a cfg.

Prints "ok - name" / "not ok - name" per check, then "N passed, M failed"; exits 1 on any failure.
"""
import argparse
import json
import os
import shutil
import sqlite3
import subprocess
import sys

STATISTICS = "/usr/bin/ompl_benchmark_statistics"
RUN_LIMIT_S = 600  # every command is bounded, so a hang fails a check instead of the whole test

# the run properties of the Table I (MOPL) and of the physics paper, as database columns
MOPL_COLUMNS = ["time_sampling_s", "time_nearest_s", "time_propagate_s", "time_connect_s", "time_ik_s",
                "time_smoothing_s", "iterations", "restarts", "clearings", "tree_vertices", "tree_edges",
                "collision_queries", "collision_queries_free", "path_vertices", "path_length_m",
                "push_reversals", "primitives_transit", "primitives_push", "primitives_pickup",
                "primitives_transfer", "seed"]
PHYSICS_COLUMNS = ["action", "power", "smoothness", "substeps", "propagations", "reaches_goal", "seed"]


class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, name, condition, *details):
        if condition:
            print(f"ok - {name}")
            self.passed += 1
        else:
            print(f"not ok - {name}")
            for detail in details:
                for line in str(detail).splitlines():
                    print(f"#   {line}")
            self.failed += 1
        return condition


def run(command, cwd=None):
    """(exit status, stdout, stderr) of a bounded command."""
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=RUN_LIMIT_S, cwd=cwd)
        return done.returncode, done.stdout, done.stderr
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {RUN_LIMIT_S} s"


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def logged_runs(text):
    """The runs of a single-planner log as {property name: value text}, read from the log itself."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.endswith(" properties for each run"))
    count = int(lines[start].split()[0])
    names = ["_".join(line.split()[:-1]) for line in lines[start + 1:start + 1 + count]]
    runs = int(lines[start + 1 + count].split()[0])
    return [dict(zip(names, line.split("; "))) for line in lines[start + 2 + count:start + 2 + count + runs]]


def database(logs, path):
    """Runs ompl_benchmark_statistics on logs into a fresh database: (status, stdout, stderr)."""
    if os.path.exists(path):
        os.remove(path)
    return run([STATISTICS, *logs, "-d", path])


def rows(db, columns):
    """Sorted (planner name, *columns) rows of the runs table."""
    con = sqlite3.connect(db)
    query = (f"SELECT plannerConfigs.name, {', '.join('runs.' + c for c in columns)} FROM runs "
             "JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id")
    result = sorted(con.execute(query).fetchall(), key=repr)
    con.close()
    return result


def columns_of(db, table):
    con = sqlite3.connect(db)
    names = [row[1] for row in con.execute(f"PRAGMA table_info({table})")]
    con.close()
    return names


def quiet_benchmark(benchmark, scratch, name, cfg_text):
    """Runs benchmark --quiet on scratch/NAME.cfg (written from cfg_text) and loads its log into
    scratch/NAME.db; returns the exit status, standard error and the database's path."""
    status, _, err = run([benchmark, write(os.path.join(scratch, f"{name}.cfg"), cfg_text), "--quiet"])
    db = os.path.join(scratch, f"{name}.db")
    database([os.path.join(scratch, f"{name}.log")], db)
    return status, err, db


def check_bad_configs(checks, args, scratch):
    """Each kind of bad config: exit 2 and a message naming the cfg file and line."""
    mm = os.path.join(args.scenes, "mobile_blocked.xml")

    def config(problem="", benchmark="time_limit = 1\nrun_count = 1\n", planner="mopl =\n", scene=mm):
        return f"[problem]\nname = p\nscene = {scene}\n{problem}[benchmark]\n{benchmark}[planner]\n{planner}"

    cases = [
        ("unknown section", config() + "[planners]\n", 9, "unknown section [planners]"),
        ("unknown key", config(benchmark="time_limit = 1\nruns = 3\n"), 6, "unknown key 'runs' in [benchmark]"),
        ("unknown planner", config(planner="rrtt =\n"), 8, "unknown planner 'rrtt'"),
        ("unknown parameter", config(planner="mopl =\nmopl.conect_step = 0.1\n"), 9,
         "unknown parameter 'conect_step'"),
        ("parameter out of range", config(planner="mopl =\nmopl.connect_step = 2\n"), 9,
         "bad value '2' for parameter 'connect_step'"),
        ("missing scene", config(scene="nowhere.xml"), 3, "not found"),
        ("non-numeric value", config(benchmark="time_limit = ten\n"), 5, "'time_limit' must be a number"),
        ("physics planner on a geometric scene", config(planner="sycloprrt =\n"), 8,
         "planner 'sycloprrt' plans a physics scene; problem 'p' is an ompl_mm scene"),
        ("problem key no planner declares", config(problem="goal_bias = 0.1\n"), 4, "unknown key 'goal_bias'"),
        ("run count not a whole number", config(benchmark="run_count = 2.5\n"), 5, "whole number"),
    ]
    for name, text, line, message in cases:
        cfg = write(os.path.join(scratch, "bad.cfg"), text)
        status, _, err = run([args.benchmark, cfg, "--quiet"])
        checks.check(f"bad config, {name}: exit 2 naming {cfg}:{line}",
                     status == 2 and err.startswith(f"ompl_mm_benchmark: {cfg}:{line}: ") and message in err,
                     f"exit {status}", f"stderr: {err}", f"expected '{cfg}:{line}: ...{message}...'")
    status, _, err = run([args.benchmark, os.path.join(scratch, "missing.cfg")])
    checks.check("missing cfg file: exit 2 naming it", status == 2 and "missing.cfg: benchmark config not found" in err,
                 f"exit {status}", err)
    cfg = write(os.path.join(scratch, "good.cfg"), config())
    for shard in ["0/3", "4/3", "x"]:
        status, _, err = run([args.benchmark, cfg, "--shard", shard])
        checks.check(f"bad --shard {shard}: exit 2 naming the option",
                     status == 2 and "command line option --shard" in err, f"exit {status}", err)


def check_mopl_log(checks, args, scratch):
    """A MOPL benchmark: the log parses without warnings, the columns are there, values match the log,
    and each run is planned again by ompl_mm_plan from its seed alone."""
    scene = os.path.join(args.scenes, "mobile_blocked.xml")
    cfg = write(os.path.join(scratch, "mopl.cfg"),
                f"[problem]\nname = mobile_blocked\nscene = {scene}\n[benchmark]\ntime_limit = 30\nrun_count = 3\n"
                "simplify = 0\nsave_paths = all\n[planner]\nmopl =\n")
    status, out, err = run([args.benchmark, cfg])
    log = os.path.join(scratch, "mopl.log")
    checks.check("MOPL benchmark: exit 0, writes the log and a path per solved run",
                 status == 0 and log in out.split() and os.path.isfile(log), f"exit {status}", out, err)
    checks.check("progress names planner, run k of n, successes and time left",
                 "mobile_blocked mopl run 3 of 3: solved; 3 solved so far" in err and "s left" in err, err)
    with open(log, encoding="utf-8") as f:
        text = f.read()
    checks.check("the log names the OMPL version", text.startswith(f"OMPL version {args.ompl_version}\n"), text[:40])
    db = os.path.join(scratch, "mopl.db")
    status, out, err = database([log], db)
    checks.check("ompl_benchmark_statistics parses the log without warnings",
                 status == 0 and err == "" and "arning" not in out, f"exit {status}", out, err)
    columns = columns_of(db, "runs")
    missing = [c for c in MOPL_COLUMNS if c not in columns]
    checks.check("every MOPL metric is a column of runs", not missing, f"missing: {missing}")
    experiment = columns_of(db, "experiments")
    checks.check("the experiment names the scene and its hash",
                 "scene" in experiment and "scene_hash" in experiment, experiment)
    con = sqlite3.connect(db)
    scene_logged, version = con.execute("SELECT scene, version FROM experiments").fetchone()
    con.close()
    checks.check("experiment columns hold the scene file and the version",
                 scene_logged == os.path.normpath(scene) and version == f"OMPL {args.ompl_version}", scene_logged, version)
    runs = rows(db, ["seed", "solved", "path_length_m", "iterations", "path_vertices"])
    checks.check("three runs, all solved, with distinct seeds",
                 len(runs) == 3 and all(r[2] == 1 for r in runs) and len({r[1] for r in runs}) == 3, runs)
    logged = sorted((int(r["seed"]), float(r["path_length_m"]), int(r["iterations"]), int(r["tree_vertices"]))
                    for r in logged_runs(text))
    con = sqlite3.connect(db)
    stored = sorted(con.execute("SELECT seed, path_length_m, iterations, tree_vertices FROM runs").fetchall())
    con.close()
    checks.check("the database holds the log's values (seed, path length, iterations, tree vertices)",
                 logged == stored and len(logged) == 3, f"log: {logged}", f"database: {stored}")
    for name, seed, _, length, iterations, vertices in runs:
        json_path = os.path.join(scratch, f"seed{seed}.json")
        status, _, err = run([args.mm_plan, scene, "--seed", str(seed), "--json", json_path])
        again = json.load(open(json_path)) if os.path.isfile(json_path) else {}
        checks.check(f"ompl_mm_plan --seed {seed} plans run {name} again (iterations, path length, vertices)",
                     status == 0 and again.get("stats", {}).get("iterations") == iterations
                     and abs(again.get("path_length_m", -1) - length) <= 1e-9 * length
                     and again.get("path_vertices") == vertices,
                     f"exit {status}", err, f"log: {iterations} iterations, {length} m, {vertices} vertices",
                     f"app: {again}")
    paths = sorted(p for p in os.listdir(scratch) if p.startswith("mopl.mopl.run") and p.endswith(".path"))
    checks.check("save_paths = all writes one path file per solved run",
                 paths == ["mopl.mopl.run1.path", "mopl.mopl.run2.path", "mopl.mopl.run3.path"], paths)


def check_physics_log(checks, args, scratch):
    """A physics benchmark: the physics metrics are columns, and a solved run re-simulates to the same
    action in ompl_phys_plan with the run's seed."""
    scene = os.path.join(args.scenes, "physics", "scene1.xml")
    cfg = write(os.path.join(scratch, "physics.cfg"),
                f"[problem]\nname = scene1\nscene = {scene}\n[benchmark]\ntime_limit = 20\nrun_count = 1\nseed = 3\n"
                "[planner]\nrrt =\n")
    status, _, err = run([args.benchmark, cfg, "--quiet"])
    checks.check("physics benchmark: exit 0, quiet", status == 0 and err == "", f"exit {status}", err)
    db = os.path.join(scratch, "physics.db")
    status, out, err = database([os.path.join(scratch, "physics.log")], db)
    checks.check("its log parses without warnings", status == 0 and err == "", f"exit {status}", out, err)
    missing = [c for c in PHYSICS_COLUMNS if c not in columns_of(db, "runs")]
    checks.check("every physics metric is a column of runs", not missing, f"missing: {missing}")
    runs = rows(db, ["seed", "solved", "action", "smoothness", "reaches_goal"])
    checks.check("the run solved and its re-simulation reached the goal",
                 len(runs) == 1 and runs[0][2] == 1 and runs[0][5] == 1, runs)
    if runs and runs[0][2] == 1:
        _, seed, _, action, smoothness, _ = runs[0]
        json_path = os.path.join(scratch, "physics_again.json")
        status, _, err = run([args.phys_plan, scene, "--planner", "rrt", "--seed", str(seed), "--json", json_path])
        again = json.load(open(json_path)) if os.path.isfile(json_path) else {}
        checks.check(f"ompl_phys_plan --seed {seed} plans the run again (action and smoothness)",
                     status == 0 and abs(again.get("action", -1) - action) <= 1e-9 * action
                     and abs(again.get("smoothness", -1) - smoothness) <= 1e-9 * smoothness,
                     f"exit {status}", err, f"log: {action}, {smoothness}", f"app: {again}")


def check_simulated_log(checks, args, scratch):
    """simulate = 1: each solved run's physics check is a run property, the same the plan app reports for
    the run's seed."""
    scene = os.path.join(args.scenes, "mobile_blocked.xml")
    status, err, db = quiet_benchmark(args.benchmark, scratch, "simulated",
                                      f"[problem]\nname = mobile_blocked\nscene = {scene}\n[benchmark]\n"
                                      "time_limit = 30\nrun_count = 2\nsimplify = 0\nsimulate = 1\n"
                                      "[planner]\nmopl =\n")
    columns = columns_of(db, "runs") if os.path.isfile(db) else []
    wanted = ["physics_check_confirmed", "physics_check_max_position_error_m", "physics_check_action",
              "physics_check_power", "physics_check_smoothness"]
    checks.check("simulate = 1: the physics check's values are columns of runs",
                 status == 0 and all(c in columns for c in wanted), f"exit {status}", err, columns)
    if not all(c in columns for c in wanted):
        return
    for _, seed, confirmed, error in rows(db, ["seed", "physics_check_confirmed",
                                               "physics_check_max_position_error_m"]):
        json_path = os.path.join(scratch, f"simulated{seed}.json")
        status, _, err = run([args.mm_plan, scene, "--seed", str(seed), "--simulate", "--json", json_path])
        again = json.load(open(json_path)).get("physics_check", {}) if os.path.isfile(json_path) else {}
        checks.check(f"ompl_mm_plan --seed {seed} --simulate reports the run's physics check again",
                     status == 0 and again.get("confirmed") == bool(confirmed)
                     and abs(again.get("max_position_error_m", -1) - error) <= 1e-9 * max(error, 1e-9),
                     f"exit {status}", err, f"log: {confirmed}, {error}", f"app: {again}")


def check_shards(checks, args, scratch):
    """Three shards through GNU parallel, merged, hold the same runs as one unsharded run."""
    scene = os.path.join(args.scenes, "mobile_blocked.xml")
    folder = os.path.join(scratch, "shards")
    os.makedirs(folder, exist_ok=True)
    cfg = write(os.path.join(folder, "split.cfg"),
                f"[problem]\nname = mobile_blocked\nscene = {scene}\n[benchmark]\ntime_limit = 30\nrun_count = 4\n"
                "seed = 11\n[planner]\nmopl =\nmopl =\nmopl.name = mopl_vertex\nmopl.vertex_step = 0.5\n")
    status, _, err = run([args.benchmark, cfg, "--quiet"])
    checks.check("unsharded run: exit 0", status == 0, f"exit {status}", err)
    whole = os.path.join(folder, "whole.db")
    database([os.path.join(folder, "split.log")], whole)
    parallel = shutil.which("parallel")
    if not checks.check("GNU parallel is installed", parallel is not None):
        return
    status, out, err = run([parallel, "-j", "2", "--halt", "now,fail=1", args.benchmark, cfg, "--quiet",
                            "--shard", "{}/3", ":::", "1", "2", "3"])
    logs = [os.path.join(folder, f"split.shard-{k}-of-3.log") for k in (1, 2, 3)]
    checks.check("three shards through GNU parallel: exit 0, one log each",
                 status == 0 and all(os.path.isfile(log) for log in logs), f"exit {status}", out, err)
    merged = os.path.join(folder, "merged.db")
    database(logs[:1], merged)
    for log in logs[1:]:
        status, out, err = run([STATISTICS, log, "-a", "-d", merged])
        checks.check(f"ompl_benchmark_statistics -a merges {os.path.basename(log)} without warnings",
                     status == 0 and err == "", f"exit {status}", out, err)
    # the Slurm array script, its task variables set by hand (no controller here), makes the same shard
    slurm = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "benchmarks", "slurm_shard.sh")
    slurm_out = os.path.join(folder, "slurm")
    env = dict(os.environ, SLURM_ARRAY_TASK_ID="2", SLURM_ARRAY_TASK_COUNT="3",
               BUILD=os.path.dirname(os.path.dirname(args.benchmark)))
    done = subprocess.run(["bash", slurm, cfg, "--output", slurm_out], env=env, capture_output=True, text=True,
                          timeout=RUN_LIMIT_S)
    slurm_log = os.path.join(slurm_out, "split.shard-2-of-3.log")
    slurm_db = os.path.join(folder, "slurm.db")
    database([slurm_log], slurm_db)
    shard_db = os.path.join(folder, "shard2.db")
    database([logs[1]], shard_db)
    columns = ["seed", "solved", "path_length_m", "iterations", "primitives_push", "tree_vertices"]
    checks.check("the Slurm array script makes shard 2 of 3 like GNU parallel did",
                 done.returncode == 0 and os.path.isfile(slurm_log)
                 and rows(slurm_db, columns) == rows(shard_db, columns),
                 f"exit {done.returncode}", done.stderr)
    checks.check("merged shards hold the same (planner, seed, solved, length, metrics) rows as one run",
                 rows(merged, columns) == rows(whole, columns) and len(rows(whole, columns)) == 8,
                 f"whole:  {rows(whole, columns)}", f"shards: {rows(merged, columns)}")


def check_user_planner(checks, args, scratch):
    """A planner defined outside the libraries, registered by the user's own main, runs from a cfg."""
    scene = os.path.join(args.scenes, "physics", "scene1.xml")
    status, err, db = quiet_benchmark(args.user_benchmark, scratch, "user",
                                      f"[problem]\nname = scene1\nscene = {scene}\n[benchmark]\ntime_limit = 0.5\n"
                                      "run_count = 2\n[planner]\nrandom_tree =\nrandom_tree.max_steps = 5\nrrt =\n")
    planners = sorted({r[0] for r in rows(db, ["seed"])}) if status == 0 else []
    checks.check("a user's planner runs from a cfg beside a shipped one",
                 status == 0 and planners == ["control_random_tree", "control_rrt"] and len(rows(db, ["seed"])) == 4,
                 f"exit {status}", err, planners)
    con = sqlite3.connect(db)
    settings = [s for (s,) in con.execute("SELECT settings FROM plannerConfigs WHERE name = 'control_random_tree'")]
    con.close()
    checks.check("its declared parameter is set from the cfg and logged", any("max_steps = 5" in s for s in settings),
                 settings)
    cfg = os.path.join(scratch, "user.cfg")
    status, _, err = run([args.benchmark, cfg, "--quiet"])
    checks.check("without the user's program the planner is unknown, at its line",
                 status == 2 and f"{cfg}:8: unknown planner 'random_tree'" in err, f"exit {status}", err)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for option in ["--benchmark", "--user-benchmark", "--mm-plan", "--phys-plan", "--scenes", "--scratch",
                   "--ompl-version"]:
        parser.add_argument(option, required=True)
    args = parser.parse_args()
    shutil.rmtree(args.scratch, ignore_errors=True)
    os.makedirs(args.scratch)
    checks = Checks()
    check_bad_configs(checks, args, args.scratch)
    check_mopl_log(checks, args, args.scratch)
    check_physics_log(checks, args, args.scratch)
    check_simulated_log(checks, args, args.scratch)
    check_shards(checks, args, args.scratch)
    check_user_planner(checks, args, args.scratch)
    print(f"{checks.passed} passed, {checks.failed} failed")
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main())
