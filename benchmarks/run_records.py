"""The run record that ompl_mm_plan and ompl_phys_plan write with --json (ompl_core's RunResult:
scene, planner, seed, time_limit_s, solved, approximate, status, time_s, then the library's
details), read back by the benchmark scripts. Standard library only."""
import json
import os
import subprocess
import sys


def run_app(binary, scene, seed, workdir, extra=(), path_file=None):
    """Runs one planning app on scene with seed and returns its run record (a dict); with
    path_file, the app also writes its path there (--path). Exits the script when the app rejects
    the input (exit 2): every later run would fail too."""
    out = os.path.join(workdir, f"{os.path.basename(scene)}-{'-'.join(extra)}-{seed}.json".replace("/", "_"))
    args = [binary, scene, "--seed", str(seed), "--json", out, *extra]
    if path_file:
        args += ["--path", path_file]
    status = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if status.returncode == 2:
        sys.exit(f"{os.path.basename(binary)} rejected the input: {status.stderr.strip()}")
    with open(out) as f:
        return json.load(f)


def check_binary(binary):
    """Exits the script when binary is not an executable."""
    if not os.access(binary, os.X_OK):
        sys.exit(f"{binary}: not an executable (build first: scripts/build.sh)")


def read_path_file(path_file):
    """The waypoints of an ompl_mm_plan --path file: a list of dicts, column name -> value (the
    'segment' and 'object' columns as text, the rest as numbers)."""
    with open(path_file) as f:
        header = f.readline().lstrip("#").split()
        rows = []
        for line in f:
            values = line.split()
            rows.append({k: (v if k in ("segment", "object") else float(v)) for k, v in zip(header, values)})
    return rows


def round_trip_pushes(rows, tolerance=1e-6):
    """Push runs (consecutive push waypoints of one object) after which the object stands where it
    stood before the same or an earlier push run of it: pointless manipulation."""
    runs = {}  # object -> list of (row before the run, last row of the run)
    for i in range(1, len(rows)):
        if rows[i]["segment"] != "push":
            continue
        obj = rows[i]["object"]
        if i > 1 and rows[i - 1]["segment"] == "push" and rows[i - 1]["object"] == obj:
            runs[obj][-1] = (runs[obj][-1][0], i)
        else:
            runs.setdefault(obj, []).append((i - 1, i))
    def pose(row, obj):
        return [row[f"{obj}.{c}"] for c in ("x", "y", "z", "yaw")]
    count = 0
    for obj, spans in runs.items():
        for j, (_, end) in enumerate(spans):
            if any(max(abs(a - b) for a, b in zip(pose(rows[before], obj), pose(rows[end], obj))) < tolerance
                   for before, _ in spans[: j + 1]):
                count += 1
    return count
