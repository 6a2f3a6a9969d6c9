#!/usr/bin/env bash
# Tests for check_layers.py: the project's includes keep the layer table, and an include that
# points up a layer, planted in a scratch copy, is caught.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check="$root/test/layering/check_layers.py"

python3 "$check" "$root"

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for dir in ompl_core ompl_mm ompl_phys apps benchmarks docs test/common test/ompl_phys/common; do
  mkdir -p "$scratch/$(dirname "$dir")"
  cp -r "$root/$dir" "$scratch/$dir"
done
printf '#include "ompl_mm/setup/ManipulationSetup.h"\n' >> "$scratch/ompl_mm/scene/Scene.h"
printf '#include "ompl_mm/scene/Scene.h"\n' >> "$scratch/ompl_phys/world/BodyState.h"
if output=$(python3 "$check" "$scratch"); then
  echo "FAIL: planted upward includes were not caught"; exit 1
fi
for expected in "ompl_mm/scene must not include ompl_mm/setup/ManipulationSetup.h" \
                "ompl_phys/world must not include ompl_mm/scene/Scene.h"; do
  grep -qF "$expected" <<<"$output" || { echo "FAIL: missing '$expected' in: $output"; exit 1; }
done
echo "layering: the table holds and planted upward includes are caught"
