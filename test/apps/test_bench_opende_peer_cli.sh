#!/usr/bin/env bash
# Tests for the command line of bench_opende_peer: --help exits 0; unknown options, malformed or
# out-of-range numbers, unknown planners and missing files exit 2 with a message that names them; a
# tiny real run exits 0 and prints both tables.
# Usage: test_bench_opende_peer_cli.sh BENCH_OPENDE_PEER SCENES_DIR SCRATCH_DIR
# Prints "ok - name" / "not ok - name" per check and ends with "N passed, M failed".
set -u

if [ $# -ne 3 ]; then
    echo "usage: $0 BENCH_OPENDE_PEER SCENES_DIR SCRATCH_DIR" >&2
    exit 2
fi
plan=$1
scenes=$2
scratch=$3

# the shared harness: run (of $plan), ok/not_ok, expect_bad_option, ...
source "$(dirname "${BASH_SOURCE[0]}")/app_contract_lib.sh"

rm -rf "$scratch"
mkdir -p "$scratch" || exit 2
scene=$scenes/physics/scene1.xml

run help --help
if [ $status -eq 0 ] && grep -q -F -- "--planners" "$out" && grep -q -F -- "--seeds" "$out" &&
    grep -q -F -- "--time-limit" "$out"; then
    ok "--help exits 0 and lists the options"
else
    not_ok "--help exits 0 and lists the options" "exit $status" "$(outputs)"
fi
expect_bad_option "no scene" "no scene file given"
expect_bad_option "unknown option" "unrecognised option '--no-such-option'" "$scene" --no-such-option
expect_bad_option "malformed --seeds" "the argument ('abc') for option '--seeds' is invalid" "$scene" --seeds abc
expect_bad_option "--seeds 0" "--seeds must be at least 1, got 0" "$scene" --seeds 0
expect_bad_option "--time-limit -1" "--time-limit must be a positive number of seconds, got -1" \
    "$scene" --time-limit=-1
expect_bad_option "--time-limit nan" "--time-limit must be a positive number of seconds" "$scene" --time-limit nan
expect_bad_option "unknown planner" "--planners: unknown planner 'est' (known: rrt, kpiece, sycloprrt)" \
    "$scene" --planners rrt,est
expect_bad_option "no planner" "--planners names no planner" "$scene" --planners ""
expect_bad_option "missing scene file" "$scratch/no_such_scene.xml: scene file not found" \
    "$scene" "$scratch/no_such_scene.xml"
expect_bad_option "manipulation scene" "the root element must be <physics_scene>" "$scenes/mobile_blocked.xml"

run tiny "$scene" --seeds 1 --time-limit 5 --planners rrt
if [ $status -eq 0 ] && grep -q -F "| scene1 | ours |" "$out" && grep -q -F "| scene1 | peer |" "$out" &&
    grep -q -F "| scene1 | rrt | 1/1 |" "$out"; then
    ok "a tiny run: exit 0, both sides' step costs and ours solved"
else
    not_ok "a tiny run: exit 0, both sides' step costs and ours solved" "exit $status" "$(outputs)"
fi

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
