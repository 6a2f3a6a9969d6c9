#!/usr/bin/env bash
# The Slurm commands of docs/benchmarks.md, run as written on a single-node Slurm cluster that this
# test brings up on the machine itself (munged and slurmctld/slurmd with a configuration written
# here, all in a scratch folder, stopped at the end): a job array of 8 shards of a benchmark, then
# the merge job that depends on it. The merged database must hold the same runs (planner, seed,
# solved, path length, iterations, pushes, tree size) as one unsharded run of the same config.
# Skips (exit 77) naming the reason when the Slurm or MUNGE programs are missing or the cluster
# cannot start here (not root, no free port).
#   test_slurm_shards.sh BUILD_DIR SOURCE_DIR SCRATCH
set -uo pipefail
build=$(cd "$1" && pwd) source_dir=$(cd "$2" && pwd) scratch=$3
skip() { echo "skipped: $*"; exit 77; }
fail() { echo "not ok - $*"; exit 1; }

for program in munged slurmctld slurmd sbatch squeue sinfo ompl_benchmark_statistics sqlite3; do
  command -v "$program" > /dev/null || skip "$program is not installed (Debian: slurm-wlm, munge, sqlite3, ompl-demos)"
done
[ "$(id -u)" -eq 0 ] || skip "the daemons of a test cluster run as root here; run as root (CI does)"

rm -rf "$scratch"
mkdir -p "$scratch"/{munge,state,spool,log,submit/benchmarks}
cluster=$scratch
daemons=()
stop_cluster() {
  for pid in "${daemons[@]}"; do kill "$pid" 2> /dev/null; done
  for pid in "${daemons[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
  done
}
trap stop_cluster EXIT

# MUNGE, Slurm's authentication: a key and a socket of our own
dd if=/dev/urandom of="$cluster/munge/munge.key" bs=1024 count=1 status=none
chmod 700 "$cluster/munge" && chmod 400 "$cluster/munge/munge.key"
munged --force --foreground --key-file="$cluster/munge/munge.key" --socket="$cluster/munge/socket" \
  --pid-file="$cluster/munge/pid" --log-file="$cluster/log/munged.log" --seed-file="$cluster/munge/seed" \
  > "$cluster/log/munged.out" 2>&1 &
daemons+=($!)
for _ in $(seq 50); do [ -S "$cluster/munge/socket" ] && break; sleep 0.1; done
[ -S "$cluster/munge/socket" ] || skip "munged did not start: $(tail -3 "$cluster/log/munged.log" 2> /dev/null)"

# Slurm: this machine as controller and only node, on free ports
node=$(hostname -s)
cpus=$(nproc)
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
cat > "$cluster/slurm.conf" << CONF
ClusterName=ompl_mm_test
SlurmctldHost=$node
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$cluster/munge/socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/log/slurmctld.log
SlurmdLogFile=$cluster/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$node CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$cluster/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" > "$cluster/log/slurmctld.out" 2>&1 &
daemons+=($!)
slurmd -D -f "$SLURM_CONF" > "$cluster/log/slurmd.out" 2>&1 &
daemons+=($!)
ready=
for _ in $(seq 100); do
  sinfo_state=$(sinfo -h -o %t 2> /dev/null)
  [ "$sinfo_state" = idle ] && { ready=1; break; }
  sleep 0.2
done
[ -n "$ready" ] || skip "the test cluster did not come up (node state '${sinfo_state:-none}'): \
$(tail -3 "$cluster/log/slurmctld.log" "$cluster/log/slurmd.log" 2> /dev/null | tr '\n' ' ')"
echo "ok - a single-node Slurm cluster is up ($node, $cpus CPUs)"

# the submission folder: the docs' script and a config of the docs' name whose runs are
# deterministic per seed (MOBILE BLOCKED, 8 runs over two problems: one per shard)
submit=$cluster/submit
ln -s "$source_dir/benchmarks/slurm_shard.sh" "$submit/benchmarks/slurm_shard.sh"
cat > "$submit/benchmarks/physics.cfg" << CFG
[problem]
name = first
scene = $source_dir/scenes/mobile_blocked.xml
[problem]
name = second
scene = $source_dir/scenes/mobile_blocked.xml
[benchmark]
time_limit = 30
run_count = 4
seed = 7
output = ../out/benchmarks/physics
[planner]
mopl =
CFG

# the docs' block, as written
commands=$(awk '/^On a Slurm cluster/ {found = 1} found && /^```sh/ {inside = 1; next} inside && /^```/ {exit} inside {print}' \
  "$source_dir/docs/benchmarks.md")
[ -n "$commands" ] || fail "docs/benchmarks.md has no Slurm commands after 'On a Slurm cluster'"
echo "# the docs' commands:"
printf '%s\n' "$commands" | sed 's/^/#   /'
(cd "$submit" && BUILD=$build bash -euo pipefail -c "$commands") || fail "the docs' Slurm commands failed"
for _ in $(seq 600); do
  [ -z "$(squeue -h 2> /dev/null)" ] && break
  sleep 0.5
done
[ -z "$(squeue -h)" ] || fail "jobs still queued after 5 minutes: $(squeue -h | head -3)"
merged=$submit/physics.db
[ -f "$merged" ] || fail "the merge job wrote no physics.db: $(cat "$submit"/slurm-*.out 2> /dev/null | tail -5)"
echo "ok - 8 array tasks and the merge job ran; physics.db written"

# one unsharded run of the same config
"$build/apps/ompl_mm_benchmark" "$submit/benchmarks/physics.cfg" --quiet --output "$cluster/whole" \
  || fail "the unsharded run failed"
ompl_benchmark_statistics "$cluster"/whole/physics.*.log -d "$cluster/whole.db" > /dev/null 2>&1 \
  || fail "ompl_benchmark_statistics failed on the unsharded logs"
rows() {
  sqlite3 "$1" "SELECT e.name, p.name, r.seed, r.status, r.solved, r.path_length_m, r.iterations, r.primitives_push,
                r.tree_vertices FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id
                JOIN experiments e ON r.experimentid = e.id ORDER BY e.name, p.name, r.seed"
}
sharded=$(rows "$merged") whole=$(rows "$cluster/whole.db")
[ "$(printf '%s\n' "$whole" | wc -l)" -eq 8 ] || fail "the unsharded database holds $(printf '%s\n' "$whole" | wc -l) runs, not 8"
[ "$sharded" = "$whole" ] || fail "the merged shards differ from one unsharded run:
sharded:
$sharded
unsharded:
$whole"
echo "ok - the merged shards hold the same 8 runs as one unsharded run"
