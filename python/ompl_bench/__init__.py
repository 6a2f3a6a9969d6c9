"""Benchmarks from Python: the runs ompl_mm_benchmark makes, and OMPL's database of them.

    import ompl_bench
    logs = ompl_bench.run("benchmarks/mopl_table1_quick.cfg", output="out")
    db = ompl_bench.to_database(logs, "out/table1.db")    # Planner Arena's database, for pandas

run() takes a cfg in OMPL.app's ompl_benchmark format (see docs/benchmarks.md) naming ompl_mm or
physics scenes, and gives the same logs as the command-line tool. Bad input raises
ompl_core.InputError, naming the file and line.
"""
import os
import shutil
import subprocess
import sys

from ompl_core import InputError
from ._ompl import OMPL_STATISTICS_SCRIPT
from ._ompl_bench import run_config

__all__ = ["InputError", "run", "statistics_scripts", "to_database"]


def run(config, shard=None, output=None, progress=False):
    """Runs the benchmark cfg `config` (or shard K of N of it: "K/N" or (K, N)), writing its logs
    (and the paths it asks for) into `output` instead of the cfg's output folder when given; prints
    a line per run on standard error when `progress`. The GIL is released; Ctrl-C stops the
    benchmark once the run in progress ends and raises KeyboardInterrupt. Returns the logs' paths."""
    if shard is None:
        shard = "1/1"
    elif not isinstance(shard, str):
        index, count = shard
        shard = f"{index}/{count}"
    written = run_config(os.fspath(config), shard, os.fspath(output) if output else "", bool(progress))
    return [file for file in written if file.endswith(".log")]


def statistics_scripts():
    """The OMPL benchmark statistics scripts to_database() tries, in order: that of the OMPL this
    module was built against, then those on PATH (Debian's ompl-demos installs one)."""
    found = [OMPL_STATISTICS_SCRIPT] if OMPL_STATISTICS_SCRIPT else []
    for name in ("ompl_benchmark_statistics", "ompl_benchmark_statistics.py"):
        script = shutil.which(name)
        if script and script not in found:
            found.append(script)
    return found


def to_database(logs, db, append=False, script=None):
    """Loads benchmark logs (a path or a list of them) into the SQLite database `db` with OMPL's
    ompl_benchmark_statistics, as Planner Arena reads it; a fresh database unless `append`. Uses
    `script` when given, else the first of statistics_scripts() that runs with this Python (OMPL
    2.0's needs OMPL's own Python bindings). Returns db."""
    logs = [os.fspath(logs)] if isinstance(logs, (str, os.PathLike)) else [os.fspath(log) for log in logs]
    if not logs:
        raise ValueError("to_database needs at least one benchmark log")
    for log in logs:
        if not os.path.isfile(log):
            raise FileNotFoundError(f"no benchmark log {log}")
    candidates = [os.fspath(script)] if script else statistics_scripts()
    if not candidates:
        raise FileNotFoundError("no ompl_benchmark_statistics script: install OMPL's (Debian: ompl-demos) "
                                "or pass script=")
    db = os.fspath(db)
    skipped = []
    for candidate in candidates:
        done = subprocess.run([sys.executable, candidate, *logs, "-d", db] + (["-a"] if append else []),
                              capture_output=True, text=True)
        if done.returncode == 0:
            return db
        if script is None and "No module named 'ompl'" in done.stderr:
            skipped.append(candidate)
            continue
        raise RuntimeError(f"{candidate} failed (exit status {done.returncode}): {done.stderr.strip()}")
    raise RuntimeError("no ompl_benchmark_statistics script runs with " + sys.executable + ": " +
                       ", ".join(skipped) + " need OMPL's Python bindings (import ompl); install "
                       "them or Debian's ompl-demos, or pass script=")
