#!/usr/bin/env bash
# Installs what is missing, builds, and plans MOBILE BLOCKED: prints the summary and writes
# out/mobile_blocked.{svg,png,html,json,txt}.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
status=0
build/apps/ompl_mm_plan scenes/mobile_blocked.xml --seed 1 \
  --json out/mobile_blocked.json --svg out/mobile_blocked.svg --html out/mobile_blocked.html \
  --path out/mobile_blocked.txt || status=$?
if command -v rsvg-convert > /dev/null && [ -f out/mobile_blocked.svg ]; then
  rsvg-convert -o out/mobile_blocked.png out/mobile_blocked.svg
fi
echo "picture: out/mobile_blocked.svg (and .png); 3-D view: out/mobile_blocked.html; result: out/mobile_blocked.json"
exit $status
