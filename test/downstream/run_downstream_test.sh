#!/usr/bin/env bash
# Installs the project into a scratch prefix (not /usr), builds the downstream project in
# test/downstream against it with find_package(ompl_mm), find_package(ompl_phys) and
# find_package(ompl_bench), plans the installed mobile_blocked.xml and physics/scene1.xml scenes with
# it, found through the packages' ompl_mm_SCENES_DIR and ompl_phys_SCENES_DIR, and benchmarks a
# planner the downstream program registers. With PYTHON (the interpreter the Python modules are
# built for) in the environment, the installed modules must import and plan with only the prefix's
# Python folder on PYTHONPATH. With OTHER_OMPL_DIR (the CMake folder of an OMPL of
# another version than the build's), configuring against that OMPL must fail, naming both versions.
# Usage: run_downstream_test.sh BUILD_DIR SOURCE_DIR SCRATCH_DIR [OTHER_OMPL_DIR]
set -u

if [ $# -lt 3 ] || [ $# -gt 4 ]; then
    echo "usage: $0 BUILD_DIR SOURCE_DIR SCRATCH_DIR [OTHER_OMPL_DIR]" >&2
    exit 2
fi
build_dir=$1
source_dir=$2
scratch=$3
other_ompl=${4:-}
prefix=$scratch/prefix
downstream_build=$scratch/build

fail() {
    echo "downstream test FAILED: $*" >&2
    exit 1
}

# start from a clean scratch dir so nothing from an earlier run is reused
rm -rf "$scratch" || fail "cannot clean $scratch"
mkdir -p "$scratch" || fail "cannot create $scratch"

echo "== install $build_dir into $prefix"
cmake --install "$build_dir" --prefix "$prefix" || fail "cmake --install $build_dir --prefix $prefix"

# the physics package stands on ompl_core alone, never on the MOPL library
phys_targets=$prefix/lib/cmake/ompl_phys/ompl_physTargets.cmake
[ -f "$phys_targets" ] || phys_targets=$(find "$prefix" -name ompl_physTargets.cmake | head -n 1)
grep -q "ompl_core::ompl_core" "$phys_targets" || fail "$phys_targets does not link ompl_core"
if grep -q -e "ompl_mm::" -e "find_dependency(ompl_mm" "$phys_targets" "$(dirname "$phys_targets")/ompl_physConfig.cmake"; then
    fail "the installed ompl_phys package refers to ompl_mm"
fi

scene=$prefix/share/ompl_mm/scenes/mobile_blocked.xml
[ -f "$scene" ] || fail "installed scene missing: $scene"

echo "== configure $source_dir/test/downstream"
cmake -S "$source_dir/test/downstream" -B "$downstream_build" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release || fail "configuring the downstream project against $prefix"

echo "== build"
cmake --build "$downstream_build" -j 2 || fail "building the downstream project"

echo "== run on the package's scene (ompl_mm_SCENES_DIR)"
"$downstream_build/downstream_plan"
status=$?
[ $status -eq 0 ] || fail "downstream_plan exited with $status (expected 0)"

phys_scene=$prefix/share/ompl_mm/scenes/physics/scene1.xml
[ -f "$phys_scene" ] || fail "installed scene missing: $phys_scene"
echo "== run on the package's physics scene (ompl_phys_SCENES_DIR)"
"$downstream_build/downstream_phys"
status=$?
[ $status -eq 0 ] || fail "downstream_phys exited with $status (expected 0)"

echo "== a benchmark with the program's own planner (find_package(ompl_bench))"
cat > "$scratch/own.cfg" <<CFG || fail "cannot write $scratch/own.cfg"
[problem]
name = scene1
scene = $phys_scene
[benchmark]
time_limit = 0.5
run_count = 1
[planner]
greedy_rrt =
CFG
"$downstream_build/downstream_benchmark" "$scratch/own.cfg" --quiet
status=$?
[ $status -eq 0 ] || fail "downstream_benchmark exited with $status (expected 0)"
grep -q "^control_greedy_rrt$" "$scratch/own.log" || fail "$scratch/own.log has no control_greedy_rrt"

echo "== the installed planner app"
env -i PATH=/usr/bin:/bin "$prefix/bin/ompl_mm_plan" "$scene" --seed 1 > /dev/null ||
    fail "the installed ompl_mm_plan does not plan $scene"

python_dir=$prefix/lib/python3/dist-packages
if [ -n "${PYTHON:-}" ]; then
    echo "== the installed Python modules, with only $python_dir on PYTHONPATH"
    [ -d "$python_dir/ompl_mm" ] || fail "no Python module ompl_mm in $python_dir"
    sed 's/^greedy_rrt =$/rrt =/' "$scratch/own.cfg" > "$scratch/python.cfg" || fail "cannot write $scratch/python.cfg"
    env -i PATH=/usr/bin:/bin PYTHONPATH="$python_dir" "$PYTHON" -c "
import ompl_mm, ompl_phys, ompl_bench
assert ompl_mm.plan('$scene', seed=3).solved
assert ompl_phys.plan('$phys_scene', planner='rrt', seed=3, time_limit=5).record['planner']
assert ompl_bench.run('$scratch/python.cfg', output='$scratch/python')
" || fail "the installed Python modules do not import or plan"
fi

if [ -n "$other_ompl" ]; then
    echo "== configure against another OMPL ($other_ompl): must fail at configure time"
    output=$(cmake -S "$source_dir/test/downstream" -B "$scratch/build-other" -DCMAKE_PREFIX_PATH="$prefix" \
        -Dompl_DIR="$other_ompl" -DCMAKE_BUILD_TYPE=Release 2>&1)
    status=$?
    echo "$output" | tail -n 12
    [ $status -ne 0 ] || fail "configuring against $other_ompl succeeded"
    echo "$output" | tr -s ' \n' ' ' | grep -q "was built against OMPL" ||
        fail "configuring against $other_ompl failed without naming the OMPL the package was built with"
fi

echo "downstream test passed"
