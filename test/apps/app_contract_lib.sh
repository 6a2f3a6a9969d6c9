# The harness the app contract tests share (sourced): bounded runs, ok/not ok reporting, scene
# copies with edits, and checks for bad input. The sourcing script sets plan (the app), scenes
# (the scene folder), scratch (a scratch folder) and base (the scene file copied by make_scene).

# every run is bounded, so a hang fails the check instead of the whole test
run_limit=300

passed=0
failed=0
ok() {
    echo "ok - $1"
    passed=$((passed + 1))
}
not_ok() {
    echo "not ok - $1"
    shift
    local line
    for line in "$@"; do
        printf '%s\n' "$line" | sed 's/^/#   /'
    done
    failed=$((failed + 1))
}

# run NAME ARGS...: runs the app ($plan) with stdout/stderr in $scratch/NAME.{out,err}; sets $status
run() {
    local name=$1
    shift
    out=$scratch/$name.out
    err=$scratch/$name.err
    timeout "$run_limit" "$plan" "$@" >"$out" 2>"$err"
    status=$?
}

# show the last command's output in a failure report
outputs() {
    echo "stdout: $(head -c 600 "$out")"
    echo "stderr: $(head -c 600 "$err")"
}

# make_scene NAME: copies the base scene to $scratch/scenes/NAME.xml and prints the copy's path
make_scene() {
    cp "$scenes/$base" "$scratch/scenes/$1.xml" && echo "$scratch/scenes/$1.xml"
}

# edit FILE OLD NEW: replaces the one occurrence of OLD in FILE by NEW ("\n" in NEW is a newline)
edit() {
    python3 - "$@" <<'PY'
import sys
path, old, new = sys.argv[1], sys.argv[2], sys.argv[3].replace("\\n", "\n")
text = open(path).read()
if text.count(old) != 1:
    sys.exit(f"edit: '{old}' occurs {text.count(old)} times in {path}, expected once")
open(path, "w").write(text.replace(old, new))
PY
}

# line_of FILE TEXT: the number of the first line of FILE containing TEXT
line_of() {
    grep -n -F -- "$2" "$1" | head -n 1 | cut -d: -f1
}

# expect_bad NAME SCENE LINE TEXT ARGS...: the app exits 2 and stderr names "scene:LINE:"
# (LINE "-": just the scene's file name) and contains TEXT; ARGS are passed after SCENE
expect_bad() {
    local name=$1 scene=$2 line=$3 text=$4
    shift 4
    if [ -z "$line" ]; then
        not_ok "bad input: $name" "could not generate the scene $scene (edit failed)"
        return
    fi
    run bad "$scene" --time-limit 2 "$@"
    local where
    where=$(basename "$scene")
    [ "$line" != "-" ] && where="$where:$line:"
    if [ $status -ne 2 ]; then
        not_ok "bad input: $name" "command: $plan $scene --time-limit 2 $*" "expected exit 2, got $status" "$(outputs)"
    elif ! grep -q -F -- "$where" "$err"; then
        not_ok "bad input: $name" "command: $plan $scene --time-limit 2 $*" "stderr does not name '$where'" "$(outputs)"
    elif ! grep -q -i -F -- "$text" "$err"; then
        not_ok "bad input: $name" "command: $plan $scene --time-limit 2 $*" "stderr does not mention '$text'" "$(outputs)"
    else
        ok "bad input: $name"
    fi
}

# expect_bad_edit NAME COPY OLD NEW LOCATE TEXT ARGS...: the base scene, copied to COPY.xml with OLD
# replaced by NEW, makes the app exit 2 naming the line of the first text LOCATE and mentioning TEXT
expect_bad_edit() {
    local name=$1 copy=$2 old=$3 new=$4 locate=$5 text=$6 file
    shift 6
    file=$(make_scene "$copy")
    edit "$file" "$old" "$new"
    expect_bad "$name" "$file" "$(line_of "$file" "$locate")" "$text" "$@"
}

# expect_bad_option NAME TEXT ARGS...: a bad command line exits 2 with TEXT on stderr
expect_bad_option() {
    local name=$1 text=$2
    shift 2
    run bad "$@"
    if [ $status -ne 2 ]; then
        not_ok "bad input: $name" "command: $plan $*" "expected exit 2, got $status" "$(outputs)"
    elif ! grep -q -F -- "$text" "$err"; then
        not_ok "bad input: $name" "command: $plan $*" "stderr does not mention '$text'" "$(outputs)"
    else
        ok "bad input: $name"
    fi
}

# check_help_and_usage WORDS...: --help exits 0 and names every word; no scene argument exits 2
check_help_and_usage() {
    run help --help
    local missing="" word
    for word in "$@"; do
        grep -q -w -F -- "$word" "$out" || missing="$missing $word"
    done
    if [ $status -eq 0 ] && [ -z "$missing" ]; then
        ok "--help exits 0 and lists the options and planners"
    else
        not_ok "--help exits 0 and lists the options and planners" "exit $status; not mentioned:$missing" "$(outputs)"
    fi
    run noscene
    if [ $status -eq 2 ]; then
        ok "no scene argument: exit 2"
    else
        not_ok "no scene argument: exit 2" "expected exit 2, got $status" "$(outputs)"
    fi
}

# expect_listed NAME TEXT ARGS...: the app exits 0 and prints the line TEXT (e.g. --list-params)
expect_listed() {
    local name=$1 text=$2
    shift 2
    run listed "$@"
    if [ $status -eq 0 ] && grep -q -x -F -- "$text" "$out"; then
        ok "$name"
    else
        not_ok "$name" "command: $plan $*" "expected exit 0 and the line '$text', got exit $status" "$(outputs)"
    fi
}

# check_svg FILE: FILE is well-formed XML with an <svg> root
check_svg() {
    local report
    if report=$(python3 - "$1" 2>&1 <<'PY'
import sys
import xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag in ("svg", "{http://www.w3.org/2000/svg}svg"), f"root element is <{root.tag}>"
PY
    ); then
        ok "SVG is well-formed XML with an <svg> root"
    else
        not_ok "SVG is well-formed XML with an <svg> root" "$report"
    fi
}

# check_output_failure ARGS...: the app with ARGS and --json /dev/full (a device whose every write
# fails, as on a full disk) plans, then exits 1 naming the file
check_output_failure() {
    run full_disk "$@" --json /dev/full
    if [ $status -eq 1 ] && grep -q -F -- "/dev/full: writing the file failed" "$err"; then
        ok "--json /dev/full: exit 1 naming the file"
    else
        not_ok "--json /dev/full: exit 1 naming the file" "command: $plan $* --json /dev/full" \
            "expected exit 1, got $status" "$(outputs)"
    fi
}

# check_interrupt SCENE ARGS...: a run without a time limit (--time-limit inf) that cannot end by
# itself within a second ends within two seconds of Ctrl-C (SIGINT), exits 1 and still writes its
# JSON, with the time limit written as null
check_interrupt() {
    local json=$scratch/interrupted.json
    rm -f "$json"
    "$plan" "$@" --time-limit inf --json "$json" >"$scratch/interrupt.out" 2>"$scratch/interrupt.err" &
    local pid=$! started
    sleep 1
    started=$(date +%s.%N)
    kill -INT $pid
    local waited=0
    while kill -0 $pid 2>/dev/null && [ $waited -lt 40 ]; do
        sleep 0.05
        waited=$((waited + 1))
    done
    if kill -0 $pid 2>/dev/null; then
        kill -KILL $pid
        wait $pid 2>/dev/null
        not_ok "Ctrl-C ends a run without a time limit" "command: $plan $* --time-limit inf; still running 2 s after SIGINT"
        return
    fi
    wait $pid
    local code=$?
    local elapsed
    elapsed=$(python3 -c "import sys, time; print(f'{time.time() - float(sys.argv[1]):.2f}')" "$started")
    if [ $code -eq 1 ] && python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["solved"] is False and d["time_limit_s"] is None else 1)' "$json" 2>/dev/null; then
        ok "Ctrl-C ends a run without a time limit (after ${elapsed} s), exit 1, JSON written"
    else
        not_ok "Ctrl-C ends a run without a time limit, exit 1, JSON written" "command: $plan $* --time-limit inf" \
            "exit $code" "json: $(head -c 300 "$json" 2>/dev/null)" "stderr: $(head -c 300 "$scratch/interrupt.err")"
    fi
}

# check_no_temporary_files: every output was put in place; no temporary file is left in $scratch
check_no_temporary_files() {
    local left
    left=$(find "$scratch" -name '*.tmp[0-9]*' | head -n 3)
    if [ -z "$left" ]; then
        ok "no temporary output file is left behind"
    else
        not_ok "no temporary output file is left behind" "found: $left"
    fi
}
