#!/usr/bin/env bash
# Tests for the ompl_mm_plan command-line contract (docs/DESIGN "Apps and their contracts"): exit 0
# solved, 1 not solved, 2 bad input naming file:line; the JSON, SVG and path outputs; determinism.
# Usage: test_ompl_mm_plan.sh PATH/TO/ompl_mm_plan SCENES_DIR SCRATCH_DIR
# Prints "ok - name" / "not ok - name" per check and ends with "N passed, M failed".
set -u

if [ $# -ne 3 ]; then
    echo "usage: $0 OMPL_MM_PLAN SCENES_DIR SCRATCH_DIR" >&2
    exit 2
fi
plan=$1
scenes=$2
scratch=$3
base=mobile_blocked.xml

# the shared harness: run, ok/not_ok, make_scene, edit, expect_bad, ...
source "$(dirname "${BASH_SOURCE[0]}")/app_contract_lib.sh"

rm -rf "$scratch"
mkdir -p "$scratch/scenes" || exit 2
cp -r "$scenes/robots" "$scratch/scenes/" || exit 2
# run from elsewhere, so the URDF path must be resolved relative to the scene file
cd "$scratch" || exit 2
scene=$scenes/$base

# --- 1. a solved run and its outputs ------------------------------------------------------------
json=$scratch/solved.json
svg=$scratch/solved.svg
path1=$scratch/solved1.txt
run solve1 "$scene" --seed 1 --json "$json" --svg "$svg" --path "$path1"
if [ $status -eq 0 ]; then
    ok "solves $base with --seed 1: exit 0"
else
    not_ok "solves $base with --seed 1: exit 0" "command: $plan $scene --seed 1 --json $json --svg $svg --path $path1" \
        "expected exit 0, got $status" "$(outputs)"
fi

if report=$(python3 - "$json" 2>&1 <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
for key in ["scene", "planner", "seed", "solved", "time_s", "stats", "path_length_m", "path_vertices", "primitives"]:
    assert key in d, f"key '{key}' missing"
assert d["scene"] == "mobile_blocked", f"scene is {d['scene']!r}"
assert d["planner"] == "mopl", f"planner is {d['planner']!r}"
assert d["seed"] == 1, f"seed is {d['seed']!r}"
assert d["solved"] is True, f"solved is {d['solved']!r}"
assert isinstance(d["time_s"], (int, float)) and 0 <= d["time_s"] < math.inf, f"time_s is {d['time_s']!r}"
stats = d["stats"]
assert isinstance(stats, dict), "stats is not an object"
for key in ["time_nearest_s", "iterations", "collision_queries"]:
    assert isinstance(stats.get(key), (int, float)) and stats[key] >= 0, f"stats.{key} is {stats.get(key)!r}"
assert stats["iterations"] > 0 and stats["collision_queries"] > 0, "no iterations or collision queries counted"
assert isinstance(d["path_length_m"], (int, float)) and d["path_length_m"] > 0, f"path_length_m is {d['path_length_m']!r}"
assert d["path_valid"] is True, f"path_valid is {d['path_valid']!r}"
assert isinstance(d["path_vertices"], int) and d["path_vertices"] > 1, f"path_vertices is {d['path_vertices']!r}"
counts = d["primitives"]
for kind in ["transit", "push", "pickup", "transfer"]:
    assert isinstance(counts.get(kind), int) and counts[kind] >= 0, f"primitives.{kind} is {counts.get(kind)!r}"
assert counts["push"] > 0, "obj3 must be pushed, but primitives.push is 0"
PY
); then
    ok "JSON result is valid and complete"
else
    not_ok "JSON result is valid and complete" "$report" "json: $(head -c 800 "$json" 2>/dev/null)"
fi

check_svg "$svg"

if report=$(python3 - "$path1" "$json" 2>&1 <<'PY'
import json, math, sys
lines = [line for line in open(sys.argv[1]).read().splitlines() if line.strip()]
assert lines and lines[0].startswith("#"), "no header line starting with '#'"
columns = len(lines[0][1:].split())
rows = [line.split() for line in lines[1:] if not line.startswith("#")]
assert len(rows) >= 2, f"{len(rows)} data lines, expected at least 2"
assert rows[0][0] == "start", f"first data line starts with {rows[0][0]!r}, expected 'start'"
for number, row in enumerate(rows, 2):
    assert row[0] in ("start", "transit", "push"), f"data line {number} starts with {row[0]!r}"
    assert len(row) == columns, f"data line {number} has {len(row)} columns, the header names {columns}"
    assert all(math.isfinite(float(v)) for v in row[2:]), f"data line {number} has a non-finite value"
vertices = json.load(open(sys.argv[2])).get("path_vertices")
assert vertices is None or len(rows) == vertices, f"{len(rows)} data lines but JSON path_vertices {vertices}"
PY
); then
    ok "path file has a header and start/transit/push waypoints"
else
    not_ok "path file has a header and start/transit/push waypoints" "$report"
fi

# the JSON's values, recomputed from the path file and the picture
if report=$(python3 - "$path1" "$json" "$svg" 2>&1 <<'PY'
import json, math, sys
import xml.etree.ElementTree as ET
lines = [line for line in open(sys.argv[1]).read().splitlines() if line.strip()]
header = lines[0][1:].split()
rows = [line.split() for line in lines[1:]]
column = {name: k for k, name in enumerate(header)}
tools = [[float(row[column[f"tool.{c}"]]) for c in "xyz"] for row in rows]
d = json.load(open(sys.argv[2]))
assert d["path_vertices"] == len(rows), f"path_vertices {d['path_vertices']}, path file {len(rows)} waypoints"
# a mobile base moves its tool in straight lines between waypoints: the length is the sum of the chords
length = sum(math.dist(a, b) for a, b in zip(tools, tools[1:]))
assert abs(d["path_length_m"] - length) < 1e-6 * max(1.0, length), f"path_length_m {d['path_length_m']}, chords {length}"
# one application per run of equal labels (kind and object)
counts = {"transit": 0, "push": 0, "pickup": 0, "transfer": 0}
labels = [(row[0], row[1]) for row in rows[1:]]
for k, label in enumerate(labels):
    if k == 0 or label != labels[k - 1]:
        counts[label[0]] += 1
assert d["primitives"] == counts, f"primitives {d['primitives']}, from the labels {counts}"
# the picture's waypoints are the path's tool points under one scale and shift (y flipped)
dots = [(float(c.get("cx")), float(c.get("cy"))) for c in ET.parse(sys.argv[3]).getroot().iter("{http://www.w3.org/2000/svg}circle")
        if c.get("class") == "waypoint"]
assert len(dots) == len(tools), f"{len(dots)} waypoints drawn, {len(tools)} in the path file"
i, j = max(((a, b) for a in range(len(tools)) for b in range(len(tools))),
           key=lambda p: abs(tools[p[0]][0] - tools[p[1]][0]))
scale = (dots[j][0] - dots[i][0]) / (tools[j][0] - tools[i][0])
assert scale > 0, f"the picture's x axis runs backwards (scale {scale})"
for (x, y, _), (px, py) in zip(tools, dots):
    ex = dots[i][0] + scale * (x - tools[i][0])
    ey = dots[i][1] - scale * (y - tools[i][1])
    assert abs(px - ex) < 0.02 and abs(py - ey) < 0.02, f"waypoint ({x}, {y}) drawn at ({px}, {py}), expected ({ex:.2f}, {ey:.2f})"
PY
); then
    ok "JSON values recomputed from the path file and the SVG: length, vertices, primitive counts, drawn waypoints"
else
    not_ok "JSON values recomputed from the path file and the SVG: length, vertices, primitive counts, drawn waypoints" "$report"
fi

# --- 2. determinism --------------------------------------------------------------------------------
path2=$scratch/solved2.txt
run solve2 "$scene" --seed 1 --path "$path2"
if [ $status -eq 0 ] && [ -s "$path1" ] && cmp -s "$path1" "$path2"; then
    ok "same seed twice gives identical path files"
else
    not_ok "same seed twice gives identical path files" "second run exit $status" \
        "$(diff "$path1" "$path2" 2>&1 | head -n 6)"
fi

# --- 2b. the plan executed in physics (--simulate) --------------------------------------------------
sim_json=$scratch/simulated.json
sim_path=$scratch/simulated.txt
run simulate "$scene" --seed 1 --simulate --json "$sim_json" --path "$sim_path"
if [ $status -eq 0 ] && report=$(python3 - "$sim_json" "$sim_path" "$path1" 2>&1 <<'PY'
import json, math, sys
check = json.load(open(sys.argv[1]))["physics_check"]
for key in ("confirmed", "goal_holds", "max_position_error_m", "max_yaw_error_rad", "simulated_s", "action",
            "power", "smoothness", "objects"):
    assert key in check, f"physics_check has no {key}"
rows = [line.split() for line in open(sys.argv[2])]
names = rows[0][1:]
last = dict(zip(names, rows[-1]))
planned = [line.split() for line in open(sys.argv[3])]
assert [r[:len(planned[1])] for r in rows[1:]] == planned[1:], "the planned columns stay as they are"
for name, errors in check["objects"].items():
    error = math.dist([float(last[f"sim.{name}.{c}"]) for c in "xyz"], [float(last[f"{name}.{c}"]) for c in "xyz"])
    assert abs(error - errors["position_error_m"]) < 1e-6, f"{name}: {error} from the path file, reported {errors}"
assert check["max_position_error_m"] == max(o["position_error_m"] for o in check["objects"].values())
assert check["confirmed"] == (check["max_position_error_m"] <= 0.02 and check["goal_holds"] and not any(
    o["tipped"] or o["off_surface"] for o in check["objects"].values()))
PY
); then
    ok "--simulate: physics_check in the JSON, its errors recomputed from the path file's simulated columns"
else
    not_ok "--simulate: physics_check in the JSON, its errors recomputed from the path file's simulated columns" \
        "exit $status" "$report" "$(outputs)"
fi

# --- 2c. physics-aware pushes (--push-model physics) ------------------------------------------------
aware_json=$scratch/aware.json
run aware "$scene" --seed 1 --push-model physics --simulate --json "$aware_json"
if [ $status -eq 0 ] && report=$(python3 - "$aware_json" 2>&1 <<'PY'
import json, sys
record = json.load(open(sys.argv[1]))
assert record["primitives"]["push"] > 0, "the plan pushes"
assert record["physics_check"]["confirmed"], record["physics_check"]
PY
); then
    ok "--push-model physics: the plan's pushes hold in the physics check"
else
    not_ok "--push-model physics: the plan's pushes hold in the physics check" "exit $status" "$report" "$(outputs)"
fi

# --- 3. help and usage -----------------------------------------------------------------------------
check_help_and_usage --planner --seed --time-limit --param --json --svg --path --simulate --push-model mopl

# --- 4. not solved -----------------------------------------------------------------------------------
walled=$(make_scene walled_goal)
edit "$walled" '  <!-- the floor is not an obstacle' \
    '  <!-- four thin walls around the goal of obj3 -->\n  <obstacle name="goal_wall_n"><origin xyz="-0.9 -0.58 0.5"/><box size="0.74 0.1 1"/></obstacle>\n  <obstacle name="goal_wall_s"><origin xyz="-0.9 -1.22 0.5"/><box size="0.74 0.1 1"/></obstacle>\n  <obstacle name="goal_wall_e"><origin xyz="-0.58 -0.9 0.5"/><box size="0.1 0.74 1"/></obstacle>\n  <obstacle name="goal_wall_w"><origin xyz="-1.22 -0.9 0.5"/><box size="0.1 0.74 1"/></obstacle>\n\n  <!-- the floor is not an obstacle'
walled_json=$scratch/walled.json
run walled "$walled" --time-limit 1 --json "$walled_json"
if [ $status -eq 1 ] && python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d["solved"] is False else 1)' "$walled_json" 2>/dev/null; then
    ok "walled-in goal: exit 1 and JSON solved false"
else
    not_ok "walled-in goal: exit 1 and JSON solved false" "command: $plan $walled --time-limit 1 --json $walled_json" \
        "expected exit 1, got $status" "json: $(head -c 300 "$walled_json" 2>/dev/null)" "$(outputs)"
fi

# --- 5. bad input ------------------------------------------------------------------------------------
expect_bad "missing scene file" "$scratch/scenes/no_such_scene.xml" - "not found"

expect_bad_edit "malformed XML" malformed_xml '<origin xyz="-1 0 0.5"/>' '<origin xyz="-1 0 0.5">' \
    '<origin xyz="-1 0 0.5">' "XML"

expect_bad_edit "unknown element" unknown_element '  <surface name="floor"' '  <colour value="red"/>\n  <surface name="floor"' \
    '<colour' "colour"

expect_bad_edit "unknown attribute" unknown_attribute 'max="2.5 2.5"/>' 'max="2.5 2.5" colour="red"/>' \
    'colour="red"' "colour"

expect_bad_edit "malformed number" malformed_number '<origin xyz="-1 0 0.5"/>' '<origin xyz="-1 0 0.5abc"/>' \
    '0.5abc' "0.5abc"

expect_bad_edit "missing URDF file" missing_urdf 'urdf="robots/mobile_disc.urdf"' 'urdf="robots/no_such_robot.urdf"' \
    'no_such_robot.urdf' "no_such_robot.urdf"

expect_bad_edit "start in collision" start_in_collision '<robot joints="1.9 1.9"/>' '<robot joints="-1 0"/>' \
    '<robot joints="-1 0"/>' "block1"

expect_bad_edit "unknown primitive type" unknown_primitive '<push_mobile standoff="0.41"/>' '<push_flying standoff="0.41"/>' \
    'push_flying' "push_flying"

expect_bad_edit "unknown planner parameter" unknown_planner_parameter 'name="vertex_step"' 'name="vertex_stride"' \
    'vertex_stride' "vertex_stride"

expect_bad_edit "out-of-range planner parameter" planner_parameter_out_of_range 'name="connect_step" value="0.05"' 'name="connect_step" value="-1"' \
    'name="connect_step"' "connect_step"

expect_bad_edit "goal on no support surface" goal_off_surface '<object name="obj3" xyz="-0.9 -0.9 *"' '<object name="obj3" xyz="3 3 *"' \
    'xyz="3 3 *"' "obj3"

# impossible problems fail before planning, at the line that makes them impossible
expect_bad_edit "object goal inside an obstacle" goal_in_obstacle '<object name="obj3" xyz="-0.9 -0.9 *"' '<object name="obj3" xyz="-1 0 *"' \
    'xyz="-1 0 *"' "object 'obj3' and obstacle 'block1' collide at their goal poses"

expect_bad_edit "robot goal inside an obstacle" robot_goal_in_obstacle '<robot joints="0 0" tolerance="0.01"/>' '<robot joints="-1 0" tolerance="0.01"/>' \
    '<robot joints="-1 0" tolerance' "robot link 'body' and obstacle 'block1' collide at their goal poses"

expect_bad_edit "object goal overlapping the robot goal" goal_on_robot_goal '<object name="obj3" xyz="-0.9 -0.9 *"' '<object name="obj3" xyz="0.3 0 *"' \
    'xyz="0.3 0 *"' "robot link 'body' and object 'obj3' collide at their goal poses"

expect_bad_edit "object goals overlapping each other" goals_overlap '<object name="obj3" xyz="-0.9 -0.9 *" yaw="*" tolerance="0.01"/>' \
    '<object name="obj3" xyz="-0.9 -0.9 *" yaw="*" tolerance="0.01"/>\n    <object name="obj1" xyz="-1.2 -0.9 *"/>' \
    'xyz="-0.9 -0.9 *" yaw' "object 'obj1' and object 'obj3' collide at their goal poses"

expect_bad_edit "standoff smaller than robot and object" standoff_too_small '<push_mobile standoff="0.41"/>' '<push_mobile standoff="0.3"/>' \
    'standoff="0.3"' "push_mobile standoff 0.3 leaves the robot overlapping object 'obj1'"

expect_bad_edit "goal that no primitive can reach" no_primitive_moves_it '<push_mobile standoff="0.41"/>' '' \
    'xyz="-0.9 -0.9 *"' "object 'obj3' must move to its goal but no primitive of the scene can move it there"

expect_bad_edit "allow_collision naming an unknown link" allow_unknown_link '<robot urdf="robots/mobile_disc.urdf" tool_link="body"/>' \
    '<robot urdf="robots/mobile_disc.urdf" tool_link="body">\n    <allow_collision link1="body" link2="wheel"/>\n  </robot>' \
    '<allow_collision' "allow_collision names link 'wheel', which robot 'mobile_disc' does not have"

expect_bad_edit "probabilities that contradict each other" probabilities_sum '<param name="move_to_object_factor" value="1.0"/>' \
    '<param name="move_to_object_factor" value="1.0"/>\n    <param name="undefined_probability" value="0.8"/>' \
    'name="undefined_probability"' "undefined_probability + start_value_probability exceeds 1"
expect_bad_option "--param probabilities that contradict each other" \
    "command line option --param: MOPL: undefined_probability + start_value_probability exceeds 1" \
    "$scene" --param undefined_probability=0.8

expect_bad_option "--push-model unknown" "push model must be kinematic or physics" "$scene" --push-model exact
expect_bad_option "--seed 0" "--seed" "$scene" --seed 0
expect_bad_option "--seed -1" "--seed" "$scene" --seed -1
expect_bad_option "--seed 2^32" "--seed" "$scene" --seed 4294967296
expect_bad_option "--time-limit -1" "--time-limit" "$scene" --time-limit -1
expect_bad_option "--planner foo" "foo" "$scene" --planner foo
expect_bad_option "--threads 0" "--threads must be 1 to 64, got 0" "$scene" --threads 0
expect_bad_option "--threads for OMPL's planner" "threads above 1 race MOPL searches; planner 'rrt'" \
    "$scene" --threads 2 --planner rrt
race1=$scratch/race1.txt
race2=$scratch/race2.txt
race_json=$scratch/race.json
run race1 "$scene" --seed 87 --threads 2 --path "$race1" --json "$race_json"
run race2 "$scene" --seed 87 --threads 2 --path "$race2"
if [ $status -eq 0 ] && [ -s "$race1" ] && cmp -s "$race1" "$race2" &&
    python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["solved"] and d["path_valid"] else 1)' \
        "$race_json" 2>/dev/null; then
    ok "--threads 2: a race of two searches gives the same valid path twice"
else
    not_ok "--threads 2: a race of two searches gives the same valid path twice" "$(outputs)"
fi

restarts_json=$scratch/restarts.json
run param_restarts "$scene" --seed 1 --time-limit 20 --param restart_iterations=50 --json "$restarts_json"
if python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["stats"]["restarts"] >= 1 else 1)' \
    "$restarts_json" 2>/dev/null; then
    ok "--param restart_iterations=50 reaches MOPL: the run restarts"
else
    not_ok "--param restart_iterations=50 reaches MOPL: the run restarts" "json: $(head -c 600 "$restarts_json")" "$(outputs)"
fi

expect_listed "--list-params shows a --param value and the scene's" "  vertex_step = 0.3 (range 0.01:0.01:10)" \
    "$scene" --list-params --param vertex_step=0.3
expect_listed "--list-params shows the scene's parameters" "  moving_object_penalty = 0.6 (range 0.:0.1:100.)" \
    "$scene" --list-params

expect_bad_option "--param with an unknown name" "command line option --param: unknown parameter 'no_such' of planner MOPL" \
    "$scene" --param no_such=1
expect_bad_option "--param with a bad value" "bad value 'abc' for parameter 'connect_step'" "$scene" --param connect_step=abc
expect_bad_option "--param without NAME=" "expected NAME=VALUE" "$scene" --param connect_step
expect_bad_option "unwritable --json path" "/nonexistent/dir/x.json" "$scene" --time-limit 1 --json /nonexistent/dir/x.json

# parameter values are checked against their type and declared range (OMPL's own conversion wraps
# -1 to 4294967295, truncates 1.5 and accepts 0x10; a tiny connect_step hung the run)
expect_bad_option "--param restart_iterations=-1" "bad value '-1' for parameter 'restart_iterations' of planner MOPL (range 0:1000:1000000): out of the range of its type" \
    "$scene" --param restart_iterations=-1
expect_bad_option "--param restart_iterations=1.5" "(range 0:1000:1000000): must be a whole number" "$scene" --param restart_iterations=1.5
expect_bad_option "--param restart_iterations=1e20" "bad value '1e20' for parameter 'restart_iterations'" "$scene" --param restart_iterations=1e20
expect_bad_option "--param restart_iterations=0x10" "(range 0:1000:1000000): not a finite decimal number" "$scene" --param restart_iterations=0x10
expect_bad_option "--param smoothing_attempts=-1" "bad value '-1' for parameter 'smoothing_attempts'" "$scene" --param smoothing_attempts=-1
expect_bad_option "--param connect_step=1e-9" "bad value '1e-9' for parameter 'connect_step' of planner MOPL (range 0.001:0.001:1): out of range" \
    "$scene" --param connect_step=1e-9
expect_bad_option "--param joint_weight=-1" "bad value '-1' for parameter 'joint_weight' of planner MOPL (range 0.:0.1:100.): out of range" \
    "$scene" --param joint_weight=-1
expect_bad_option "--param moving_object_penalty=-1" "bad value '-1' for parameter 'moving_object_penalty'" "$scene" --param moving_object_penalty=-1
expect_bad_option "--param vertex_step=inf" "bad value 'inf' for parameter 'vertex_step'" "$scene" --param vertex_step=inf
expect_bad "a device as the scene file" /dev/zero - "/dev/zero: is not a regular file, not a scene file"

# a huge time limit means none (it used to overflow OMPL's clock and end the run at once)
run huge_limit "$scene" --seed 1 --time-limit 1e10
if [ $status -eq 0 ]; then
    ok "--time-limit 1e10 plans without a practical limit and solves"
else
    not_ok "--time-limit 1e10 plans without a practical limit and solves" "expected exit 0, got $status" "$(outputs)"
fi
check_interrupt "$walled"
check_output_failure "$scene" --seed 1
check_no_temporary_files

# an output named through a symbolic link is written where the link points; the link stays
target_json=$scratch/linked_target.json
rm -f "$target_json" "$scratch/link.json"
echo stale >"$target_json"
ln -s "$target_json" "$scratch/link.json"
run through_link "$scene" --seed 1 --json "$scratch/link.json"
if [ $status -eq 0 ] && [ -L "$scratch/link.json" ] && python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$target_json" 2>/dev/null; then
    ok "--json through a symbolic link writes its target and keeps the link"
else
    not_ok "--json through a symbolic link writes its target and keeps the link" "exit $status" \
        "link: $(ls -l "$scratch/link.json" 2>&1)" "target: $(head -c 200 "$target_json")"
fi

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
