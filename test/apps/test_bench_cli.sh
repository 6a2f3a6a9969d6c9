#!/usr/bin/env bash
# Tests for the command lines of the benchmark programs bench_ik and bench_propagation: --help exits
# 0; unknown options, malformed or out-of-range numbers and missing files exit 2 with a message that
# names them; a tiny real run of each exits 0 and prints its table.
# Usage: test_bench_cli.sh BENCH_IK|none BENCH_PROPAGATION SCENES_DIR SCRATCH_DIR   (none: bench_ik was
# not built, for want of Orocos KDL; its checks are skipped)
# Prints "ok - name" / "not ok - name" per check and ends with "N passed, M failed".
set -u

if [ $# -ne 4 ]; then
    echo "usage: $0 BENCH_IK|none BENCH_PROPAGATION SCENES_DIR SCRATCH_DIR" >&2
    exit 2
fi
bench_ik=$1
bench_propagation=$2
scenes=$3
scratch=$4

# the shared harness: run (of $plan), ok/not_ok, expect_bad_option, check_help_and_usage, ...
source "$(dirname "${BASH_SOURCE[0]}")/app_contract_lib.sh"

rm -rf "$scratch"
mkdir -p "$scratch" || exit 2

# expect_help NAME WORDS...: $plan --help exits 0 and prints "Usage" and every word
expect_help() {
    local name=$1 missing="" word
    shift
    run help --help
    for word in Usage "$@"; do
        grep -q -F -- "$word" "$out" || missing="$missing $word"
    done
    if [ $status -eq 0 ] && [ -z "$missing" ]; then
        ok "$name --help exits 0 and lists the options"
    else
        not_ok "$name --help exits 0 and lists the options" "exit $status; not mentioned:$missing" "$(outputs)"
    fi
}

# expect_run NAME TEXT ARGS...: $plan ARGS exits 0 and prints TEXT
expect_run() {
    local name=$1 text=$2
    shift 2
    run tiny "$@"
    if [ $status -eq 0 ] && grep -q -F -- "$text" "$out"; then
        ok "$name"
    else
        not_ok "$name" "command: $plan $*" "expected exit 0 and '$text', got exit $status" "$(outputs)"
    fi
}

# --- bench_ik --------------------------------------------------------------------------------------
if [ "$bench_ik" = none ]; then
    ok "bench_ik # SKIP not built (no Orocos KDL)"
else
    plan=$bench_ik
    expect_help bench_ik --queries --tip --seed --iterations --damping --posture
    expect_bad_option "bench_ik unknown option" "unrecognised option '--no-such-option'" --no-such-option
    expect_bad_option "bench_ik malformed --queries" "the argument ('abc') for option '--queries' is invalid" \
        --queries abc
    expect_bad_option "bench_ik --queries 0" "--queries must be at least 1, got 0" --queries 0
    expect_bad_option "bench_ik --queries -5" "--queries must be at least 1, got -5" --queries=-5
    expect_bad_option "bench_ik --seed 0" "--seed must be in [1, 4294967295], got 0" --seed 0
    expect_bad_option "bench_ik --damping -1" "--damping must be a finite number of at least 0" --damping=-1
    expect_bad_option "bench_ik --posture nan" "--posture must be a finite number of at least 0" --posture nan
    expect_bad_option "bench_ik unknown --tip" "has no link 'no_such_link'" --tip no_such_link --queries 1
    expect_bad_option "bench_ik --tip without a moving joint" "no moving joint" --tip base_link --queries 1
    expect_bad_option "bench_ik missing URDF" "$scratch/no_such_robot.urdf: URDF file not found" \
        "$scratch/no_such_robot.urdf"
    expect_bad_option "bench_ik two URDFs" "too many positional options" \
        "$scenes/robots/kuka_lwr.urdf" "$scenes/robots/kuka_lwr.urdf"
    expect_run "bench_ik --queries 20: exit 0 and the IkSolver row" "| ompl_mm IkSolver" --queries 20
fi

# --- bench_propagation -----------------------------------------------------------------------------
plan=$bench_propagation
scene=$scenes/physics/scene1.xml
expect_help bench_propagation SCENE.xml --steps --repeats
run noscene
if [ $status -eq 2 ] && grep -q -F "no scene file given" "$err"; then
    ok "bench_propagation without a scene: exit 2"
else
    not_ok "bench_propagation without a scene: exit 2" "expected exit 2 and 'no scene file given', got $status" \
        "$(outputs)"
fi
expect_bad_option "bench_propagation unknown option" "unrecognised option '--no-such-option'" \
    "$scene" --no-such-option
expect_bad_option "bench_propagation malformed --steps" "the argument ('abc') for option '--steps' is invalid" \
    "$scene" --steps abc
expect_bad_option "bench_propagation --steps 0" "--steps must be at least 1, got 0" "$scene" --steps 0
expect_bad_option "bench_propagation --repeats 0" "--repeats must be at least 1, got 0" "$scene" --repeats 0
expect_bad_option "bench_propagation --repeats -1" "--repeats must be at least 1, got -1" "$scene" --repeats=-1
expect_bad_option "bench_propagation missing scene file" "$scratch/no_such_scene.xml: scene file not found" \
    "$scene" "$scratch/no_such_scene.xml"
expect_bad_option "bench_propagation manipulation scene" "the root element must be <physics_scene>" \
    "$scenes/mobile_blocked.xml"
expect_run "bench_propagation --steps 20 --repeats 1: exit 0 and the scene's row" "| scene1 |" \
    "$scene" --steps 20 --repeats 1

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
