"""The run record that ompl_mm_plan and ompl_phys_plan write with --json (ompl_core's RunResult:
scene, planner, seed, time_limit_s, solved, approximate, status, time_s, then the library's
details), read back by the benchmark scripts. Standard library only."""
import json
import math
import os
import sys
import tempfile


def run_app(binary, scene, seed, workdir, extra=(), path_file=None):
    """Runs one planning app on scene with seed and returns its run record (a dict) with the peak
    memory of the process added ("peak_memory_mb", its largest resident set); with path_file, the
    app also writes its path there (--path). Exits the script when the app rejects the input
    (exit 2): every later run would fail too."""
    out = os.path.join(workdir, f"{os.path.basename(scene)}-{'-'.join(extra)}-{seed}.json".replace("/", "_"))
    args = [binary, scene, "--seed", str(seed), "--json", out, *extra]
    if path_file:
        args += ["--path", path_file]
    with tempfile.TemporaryFile(mode="w+") as stderr:
        # spawned and reaped here, so that wait4 gives this process's own resource use
        pid = os.posix_spawn(args[0], args, os.environ,
                             file_actions=[(os.POSIX_SPAWN_OPEN, 1, os.devnull, os.O_WRONLY, 0),
                                           (os.POSIX_SPAWN_DUP2, stderr.fileno(), 2)])
        _, status, usage = os.wait4(pid, 0)
        if os.waitstatus_to_exitcode(status) == 2:
            stderr.seek(0)
            sys.exit(f"{os.path.basename(binary)} rejected the input: {stderr.read().strip()}")
    with open(out) as f:
        record = json.load(f)
    record["peak_memory_mb"] = usage.ru_maxrss / 1024.0  # Linux reports kilobytes
    return record


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


def push_reversals(rows, tolerance=1e-3):
    """Pushes that move an object back against the push of it just before (the object not moved
    between them) by more than tolerance metres, as ManipulationPath::pushReversals() counts them:
    the push before carried the object past a point this one brings it back towards."""
    objects = sorted({k[:-2] for k in rows[0] if k.endswith(".x") and k[:-2] + ".yaw" in rows[0]}) if rows else []
    count = 0
    for obj in objects:
        previous = None  # the object's last push, while nothing else has moved it since
        for before, row in zip(rows, rows[1:]):
            moved = [row[f"{obj}.{c}"] - before[f"{obj}.{c}"] for c in ("x", "y", "z")]
            if row["segment"] != "push" or row["object"] != obj:
                if any(moved):
                    previous = None
                continue
            if not any(moved):
                continue
            if previous and sum(a * b for a, b in zip(moved, previous)) / math.hypot(*previous) < -tolerance:
                count += 1
            previous = moved
    return count


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
