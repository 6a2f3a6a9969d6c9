#!/usr/bin/env bash
# The quick variants of the paper reproductions run end to end with one command each
# (benchmarks/run_config.sh): a log per problem, the Planner Arena database with a row per run, and
# the figures as PNG files.
# Usage: test_quick_configs.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR
set -u
source_dir=$1
build_dir=$2
scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
failed=0

# check NAME CONFIG RUNS FIGURES...: runs the config, then checks the database's run count and figures
check() {
  local name=$1 config=$2 runs=$3
  shift 3
  local out=$scratch/$name
  if ! "$source_dir/benchmarks/run_config.sh" "$source_dir/benchmarks/$config" --output "$out" \
      --build "$build_dir" > "$out.out" 2> "$out.err"; then
    echo "not ok - $config: run_config.sh failed"; sed 's/^/#   /' "$out.err" | tail -20; failed=1; return
  fi
  local count
  count=$(/usr/bin/python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('SELECT COUNT(*) FROM runs').fetchone()[0])" "$out/${config%.cfg}.db")
  if [ "$count" = "$runs" ]; then echo "ok - $config: $runs runs in the database"; else
    echo "not ok - $config: $runs runs in the database, got $count"; failed=1; fi
  local figure
  for figure in "$@"; do
    if head -c 8 "$out/plots/$figure" 2>/dev/null | grep -q PNG; then echo "ok - $config: plots/$figure"; else
      echo "not ok - $config: plots/$figure is missing or no PNG"; failed=1; fi
  done
}

check mopl mopl_table1_quick.cfg 30 time.png success.png metric_path_length_m.png primitives.png time_shares.png
check physics physics_quick.cfg 30 time.png success.png
exit $failed
