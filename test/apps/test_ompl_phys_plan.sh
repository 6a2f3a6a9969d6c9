#!/usr/bin/env bash
# Tests for the ompl_phys_plan command-line contract: exit 0 solved, 1 not solved, 2 bad input naming
# file:line; the JSON and SVG outputs; the same seed gives the same plan.
# Usage: test_ompl_phys_plan.sh PATH/TO/ompl_phys_plan PHYSICS_SCENES_DIR SCRATCH_DIR
# Prints "ok - name" / "not ok - name" per check and ends with "N passed, M failed".
set -u

if [ $# -ne 3 ]; then
    echo "usage: $0 OMPL_PHYS_PLAN PHYSICS_SCENES_DIR SCRATCH_DIR" >&2
    exit 2
fi
# absolute paths: the checks run from the scratch directory
plan=$(realpath -- "$1")
scenes=$(realpath -- "$2")
scratch=$(realpath -m -- "$3")
base=scene1.xml

# the shared harness: run, ok/not_ok, make_scene, edit, expect_bad, ...
source "$(dirname "${BASH_SOURCE[0]}")/app_contract_lib.sh"

rm -rf "$scratch"
mkdir -p "$scratch/scenes" || exit 2
cd "$scratch" || exit 2
scene=$scenes/$base

# --- 1. help and usage -----------------------------------------------------------------------------
check_help_and_usage --planner --seed --time-limit --param --json --svg --path rrt est kpiece sycloprrt syclopest pdst sst

# --- 2. a solved run and its outputs ------------------------------------------------------------
json1=$scratch/solved1.json
svg=$scratch/solved.svg
path1=$scratch/solved1.txt
run solve1 "$scene" --planner kpiece --seed 1 --time-limit 60 --json "$json1" --svg "$svg" --path "$path1"
if [ $status -eq 0 ]; then
    ok "solves $base with kpiece, --seed 1: exit 0"
else
    not_ok "solves $base with kpiece, --seed 1: exit 0" \
        "command: $plan $scene --planner kpiece --seed 1 --time-limit 60 --json $json1 --svg $svg --path $path1" \
        "expected exit 0, got $status" "$(outputs)"
fi

if report=$(python3 - "$json1" 2>&1 <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
for key in ["scene", "planner", "seed", "solved", "time_s", "stats", "action", "power", "smoothness", "reaches_goal"]:
    assert key in d, f"key '{key}' missing"
assert d["scene"] == "scene1", f"scene is {d['scene']!r}"
assert d["planner"] == "kpiece", f"planner is {d['planner']!r}"
assert d["seed"] == 1, f"seed is {d['seed']!r}"
assert d["solved"] is True, f"solved is {d['solved']!r}"
assert d["reaches_goal"] is True, f"reaches_goal is {d['reaches_goal']!r}"
assert isinstance(d["time_s"], (int, float)) and 0 <= d["time_s"] < math.inf, f"time_s is {d['time_s']!r}"
stats = d["stats"]
assert isinstance(stats, dict), "stats is not an object"
for key in ["propagations", "substeps"]:
    assert isinstance(stats.get(key), int) and stats[key] > 0, f"stats.{key} is {stats.get(key)!r}"
assert stats["substeps"] >= stats["propagations"], "fewer ODE sub-steps than propagations"
for key in ["action", "power", "smoothness"]:
    assert isinstance(d[key], (int, float)) and math.isfinite(d[key]), f"{key} is {d[key]!r}"
assert d["action"] > 0 and d["smoothness"] >= 0, f"action {d['action']}, smoothness {d['smoothness']}"
PY
); then
    ok "JSON result is valid and complete"
else
    not_ok "JSON result is valid and complete" "$report" "json: $(head -c 800 "$json1" 2>/dev/null)"
fi

check_svg "$svg"

# the JSON's values, recomputed without ODE from the re-simulated path file (docs/metrics.md)
if report=$(python3 - "$path1" "$json1" 2>&1 <<'PY'
import json, math, sys
lines = open(sys.argv[1]).read().splitlines()
head = lines[0][1:].split()
params = {head[k]: float(head[k + 1]) for k in range(0, len(head), 2)}
columns = lines[1][1:].split()
rows = [[float(v) for v in line.split()] for line in lines[2:]]
h = params["step_s"]
col = {name: k for k, name in enumerate(columns)}
robot = [[row[col[f"robot.{c}"]] for c in "xyz"] for row in rows]
n = len(rows) - 1
d = json.load(open(sys.argv[2]))
assert d["steps"] == n, f"steps {d['steps']}, path file {n}"
assert abs(d["duration_s"] - n * h) < 1e-9, f"duration_s {d['duration_s']}, path file {n * h}"
# moves: runs of equal move indices, each with one force
moves = []
for k in range(n):
    index, force = int(rows[k][col["move"]]), [rows[k][col[f"f{c}"]] for c in "xyz"]
    if moves and moves[-1][0] == index:
        assert moves[-1][2] == force, f"move {index} changes its force at sample {k}"
        moves[-1][1] += 1
    else:
        moves.append([index, 1, force, k])
assert d["moves"] == len(moves), f"moves {d['moves']}, path file {len(moves)}"
action = power = 0.0
for index, steps, force, a in moves:
    b = a + steps
    covered = sum(math.dist(robot[k], robot[k + 1]) for k in range(a, b))
    action += math.hypot(*force) * steps * h * covered
    power += sum(f * (robot[b][c] - robot[a][c]) for c, f in enumerate(force)) / (steps * h)
jerks = [sum(((robot[k + 3][c] - 3 * robot[k + 2][c] + 3 * robot[k + 1][c] - robot[k][c]) / h ** 3) ** 2
             for c in range(3)) for k in range(n - 2)]
smoothness = n * h * sum(jerks) / (n - 2) if n >= 3 else 0.0
for key, value in (("action", action), ("power", power), ("smoothness", smoothness)):
    assert abs(d[key] - value) <= 1e-6 * max(1.0, abs(value)), f"{key} {d[key]}, recomputed {value}"
end = math.dist(robot[-1][:2], (params["goal_x"], params["goal_y"]))
assert d["reaches_goal"] == (end <= params["goal_radius"]), f"reaches_goal {d['reaches_goal']}, end {end:.4f} m from the goal"
PY
); then
    ok "JSON values recomputed from the re-simulated path file: steps, duration, moves, action, power, smoothness, goal"
else
    not_ok "JSON values recomputed from the re-simulated path file: steps, duration, moves, action, power, smoothness, goal" \
        "$report"
fi

# --- 3. determinism --------------------------------------------------------------------------------
json2=$scratch/solved2.json
run solve2 "$scene" --planner kpiece --seed 1 --time-limit 60 --json "$json2"
if report=$(python3 - "$json1" "$json2" 2>&1 <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for key in ["action", "power", "smoothness", "moves", "steps", "reaches_goal"]:
    assert key in a and key in b, f"key '{key}' missing"
    assert a[key] == b[key], f"{key}: {a[key]!r} then {b[key]!r}"
PY
) && [ $status -eq 0 ]; then
    ok "same seed twice gives identical action, power and smoothness"
else
    not_ok "same seed twice gives identical action, power and smoothness" "second run exit $status" "$report"
fi

# --- 4. not solved -----------------------------------------------------------------------------------
unsolved_json=$scratch/unsolved.json
run unsolved "$scenes/scene2.xml" --time-limit 0.01 --json "$unsolved_json"
if [ $status -eq 1 ] && python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d["solved"] is False else 1)' "$unsolved_json" 2>/dev/null; then
    ok "scene2.xml with --time-limit 0.01: exit 1 and JSON solved false"
else
    not_ok "scene2.xml with --time-limit 0.01: exit 1 and JSON solved false" \
        "command: $plan $scenes/scene2.xml --time-limit 0.01 --json $unsolved_json" \
        "expected exit 1, got $status" "json: $(head -c 300 "$unsolved_json" 2>/dev/null)" "$(outputs)"
fi

# EST needs about 6 s for seed 1 of scene 2: Ctrl-C after 1 s finds it unsolved
check_interrupt "$scenes/scene2.xml" --planner est --seed 1
check_output_failure "$scenes/scene2.xml" --time-limit 0.01
check_no_temporary_files

# --- 5. bad input ------------------------------------------------------------------------------------
expect_bad "missing scene file" "$scratch/scenes/no_such_scene.xml" - "not found"
expect_bad "a device as the scene file" /dev/zero - "/dev/zero: is not a regular file, not a scene file"
expect_bad_option "--param goal_bias=1.5" "bad value '1.5' for parameter 'goal_bias' of planner RRT (range 0.:.05:1.): out of range" \
    "$scenes/scene2.xml" --planner rrt --param goal_bias=1.5

# the unclosed element's line
expect_bad_edit "malformed XML" malformed_xml '<goal xy="0.92 -1.0" radius="0.05"/>' '<goal xy="0.92 -1.0" radius="0.05">' \
    '<goal xy=' "XML"

expect_bad_edit "unknown element" unknown_element '  <floor size="2.98 2.98"/>' '  <carpet colour="red"/>\n  <floor size="2.98 2.98"/>' \
    '<carpet' "carpet"

expect_bad_edit "out-of-range parameter" out_of_range 'erp="0.5"' 'erp="2"' \
    'erp="2"' "erp"

expect_bad_edit "start inside a fixed wall" start_in_wall 'start="-0.84 0.97"' 'start="0 0.5"' \
    'name="wall4"' "starts touching 'wall4'"

expect_bad_option "--planner foo" "foo" "$scene" --planner foo
expect_listed "--list-params shows the scene's goal bias on RRT" "  goal_bias = 0.05 (range 0.:.05:1.)" \
    "$scene" --planner rrt --list-params
expect_listed "--list-params shows a --param value" "  goal_bias = 0.25 (range 0.:.05:1.)" \
    "$scene" --planner rrt --list-params --param goal_bias=0.25

expect_bad_option "--param with an unknown name" "command line option --param: unknown parameter 'no_such' of planner RRT" \
    "$scene" --planner rrt --param no_such=1
expect_bad_option "--param with a bad value" "bad value 'abc' for parameter 'goal_bias'" "$scene" --planner rrt \
    --param goal_bias=abc
expect_bad_option "--seed 0" "--seed" "$scene" --seed 0
expect_bad_option "--time-limit -1" "--time-limit" "$scene" --time-limit -1
expect_bad_option "unwritable --json path" "/nonexistent/dir/x.json" "$scene" --time-limit 1 --json /nonexistent/dir/x.json

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
