#!/usr/bin/env bash
# One command from a benchmark config to its Planner Arena database and plots:
#   benchmarks/run_config.sh CONFIG.cfg [--output DIR] [--build BUILD]
# runs ompl_mm_benchmark (progress on stderr), loads its logs with Debian's ompl_benchmark_statistics
# into DIR/<cfg name>.db and draws the figures of benchmarks/plot.py into DIR/plots/. DIR defaults to
# the cfg's output folder. Exit status: that of the first step that fails.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$here/../build
config=""
output=""
while [ $# -gt 0 ]; do
  case $1 in
    --output) output=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    -h|--help) sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) config=$1; shift ;;
  esac
done
if [ -z "$config" ]; then
  echo "usage: $0 CONFIG.cfg [--output DIR] [--build BUILD]" >&2
  exit 2
fi
name=$(basename "$config" .cfg)
args=("$config")
[ -n "$output" ] && args+=(--output "$output")
written=$("$build/apps/ompl_mm_benchmark" "${args[@]}")
mapfile -t logs < <(grep '\.log$' <<< "$written")
dir=$(dirname "${logs[0]}")
db=$dir/$name.db
rm -f "$db"
ompl_benchmark_statistics "${logs[@]}" -d "$db" > /dev/null
# Debian's interpreter, which has python3-matplotlib (a python3 earlier on PATH may not)
"${PYTHON:-/usr/bin/python3}" "$here/plot.py" "$db" --out "$dir/plots"
echo "database: $db"
