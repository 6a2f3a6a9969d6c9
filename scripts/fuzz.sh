#!/usr/bin/env bash
# libFuzzer on the project's input readers (test/fuzz: one target per reader), built in build-fuzz/
# with clang-14, AddressSanitizer and UndefinedBehaviorSanitizer.
#   scripts/fuzz.sh smoke                 every target for 20 s from its corpus (CI runs this)
#   scripts/fuzz.sh run TARGET SECONDS    a campaign: new inputs in out/fuzz/TARGET/corpus, failing
#                                         inputs in out/fuzz/TARGET/ (the campaign goes on after
#                                         one), libFuzzer's log in out/fuzz/TARGET.log
# Targets: mm_scene phys_scene urdf urdf_mesh srdf benchmark_cfg. A failing input is replayed with
# build-fuzz/test/fuzz/fuzz_TARGET FILE; add it to test/fuzz/corpus/TARGET once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
usage() { sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage

scripts/install-deps.sh clang-14 libfuzzer-14-dev libclang-rt-14-dev
cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DOMPL_MM_FUZZ=ON -DOMPL_MM_UNITY_BUILD=ON > /dev/null
cmake --build build-fuzz -j "$(nproc 2>/dev/null || echo 2)"
export LSAN_OPTIONS="suppressions=$PWD/test/fuzz/lsan.supp"

case "$1" in
  smoke)
    (cd build-fuzz && ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)")
    ;;
  run)
    [ $# -eq 3 ] || usage
    target=$2 seconds=$3
    binary=build-fuzz/test/fuzz/fuzz_$target
    [ -x "$binary" ] || { echo "fuzz.sh: no target '$target' (see test/fuzz/CMakeLists.txt)" >&2; exit 2; }
    work=out/fuzz/$target
    mkdir -p "$work/corpus"
    # fork mode: a failing input is kept and the campaign goes on
    "$binary" -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
      -dict="test/fuzz/dict/$target.dict" -artifact_prefix="$work/" \
      "$work/corpus" "test/fuzz/corpus/$target" > "out/fuzz/$target.log" 2>&1 || status=$?
    grep -E '^#[0-9]+' "out/fuzz/$target.log" | tail -1
    grep -E '^stat::' "out/fuzz/$target.log" || true
    exit "${status:-0}"
    ;;
  *) usage ;;
esac
