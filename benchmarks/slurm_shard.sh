#!/usr/bin/env bash
# One shard of a benchmark as a task of a Slurm job array: the shard index and count come from
# Slurm's SLURM_ARRAY_TASK_ID (1-based) and SLURM_ARRAY_TASK_COUNT. Submit all shards, then merge:
#   jobid=$(sbatch --parsable --array=1-8 benchmarks/slurm_shard.sh benchmarks/physics.cfg)
#   sbatch --dependency=afterok:$jobid --wrap \
#     "ompl_benchmark_statistics out/benchmarks/physics/physics.*.shard-*-of-8.log -d physics.db"
# Options after the config go to ompl_mm_benchmark (--output DIR, say). BUILD sets the build folder.
#SBATCH --job-name=ompl_mm_benchmark
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
if [ -z "${SLURM_ARRAY_TASK_ID:-}" ] || [ -z "${SLURM_ARRAY_TASK_COUNT:-}" ]; then
  echo "slurm_shard.sh: run as a Slurm array task (sbatch --array=1-N), or set SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT" >&2
  exit 2
fi
# under sbatch the script runs from a spool copy: the submission folder is the repository
here=${SLURM_SUBMIT_DIR:-$(cd "$(dirname "$0")/.." && pwd)}
build=${BUILD:-$here/build}
exec "$build/apps/ompl_mm_benchmark" "$@" --quiet --shard "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT"
