#!/usr/bin/env bash
# Tests for scripts/build-with-ompl2.sh's refusals, on a copy of the scripts in a scratch folder (no
# build happens): without an OMPL 2 to use or install, and with OMPL2_PREFIX at a folder that holds
# no OMPL 2, it names what it needs and exits 2; --help describes it and exits 0.
# Usage: test_build_with_ompl2.sh SOURCE_DIR SCRATCH_DIR
set -u
source_dir=$1
scratch=$2
failed=0
check() { # name, condition status
    if [ "$2" -eq 0 ]; then echo "ok - $1"; else echo "not ok - $1"; failed=$((failed + 1)); fi
}

rm -rf "$scratch" && mkdir -p "$scratch" && cp -r "$source_dir/scripts" "$scratch/" || exit 1
script=$scratch/scripts/build-with-ompl2.sh

output=$(OMPL2_SHARED="$scratch/no_such_folder" bash "$script" --no-test 2>&1)
status=$?
[ $status -eq 2 ] && grep -q "no OMPL 2 to build against" <<< "$output" &&
    grep -q "OMPL2_PREFIX" <<< "$output" && grep -q "$scratch/no_such_folder/ompl-2.0.2-src.tar.gz" <<< "$output"
check "no OMPL 2 to use or install: exit 2, naming OMPL2_PREFIX and the missing source" $?
[ ! -e "$scratch/build-ompl2" ]
check "nothing is unpacked or built then" $?

output=$(OMPL2_PREFIX="$scratch/scripts" bash "$script" --no-test 2>&1)
status=$?
[ $status -eq 2 ] && grep -q "is not an OMPL 2" <<< "$output"
check "OMPL2_PREFIX without an OMPL 2: exit 2, saying so" $?

output=$(bash "$script" --help 2>&1)
status=$?
[ $status -eq 0 ] && grep -q "^Usage: scripts/build-with-ompl2.sh" <<< "$output"
check "--help: exit 0 with the usage" $?

echo "$failed failed"
[ $failed -eq 0 ]
