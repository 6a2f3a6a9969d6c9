"""The run record that ompl_mm_plan and ompl_phys_plan write with --json (ompl_core's RunResult:
scene, planner, seed, time_limit_s, solved, approximate, status, time_s, then the library's
details), read back by the benchmark scripts. Standard library only."""
import json
import os
import subprocess
import sys


def run_app(binary, scene, seed, workdir, extra=()):
    """Runs one planning app on scene with seed and returns its run record (a dict).
    Exits the script when the app rejects the input (exit 2): every later run would fail too."""
    out = os.path.join(workdir, f"{os.path.basename(scene)}-{'-'.join(extra)}-{seed}.json".replace("/", "_"))
    args = [binary, scene, "--seed", str(seed), "--json", out, *extra]
    status = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if status.returncode == 2:
        sys.exit(f"{os.path.basename(binary)} rejected the input: {status.stderr.strip()}")
    with open(out) as f:
        return json.load(f)


def check_binary(binary):
    """Exits the script when binary is not an executable."""
    if not os.access(binary, os.X_OK):
        sys.exit(f"{binary}: not an executable (build first: scripts/build.sh)")
