#!/usr/bin/env python3
"""Tests for benchmarks/plot.py: figures drawn from small Planner Arena databases made here (the
schema of ompl_benchmark_statistics, with the columns the figures read), figures skipped when
their columns are missing or empty, and bad input rejected with exit status 2. Standard library
only; plot.py itself needs matplotlib, so the tests run it with an interpreter that has it
(this one, else Debian's /usr/bin/python3) and are skipped when none has."""
import os
import sqlite3
import struct
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
PLOT = os.path.join(HERE, "..", "..", "benchmarks", "plot.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def python_with_matplotlib():
    """An interpreter that imports matplotlib, or None."""
    for python in dict.fromkeys([sys.executable, "/usr/bin/python3"]):
        if python and os.path.exists(python) and subprocess.run(
                [python, "-c", "import matplotlib"], capture_output=True, timeout=30).returncode == 0:
            return python
    return None


PYTHON = python_with_matplotlib()


def make_db(path, experiments, planners, run_columns, runs):
    """A database in ompl_benchmark_statistics' schema. experiments: (id, name, timelimit, seed);
    planners: (id, name); run_columns: extra 'name TYPE' columns of runs; runs: dicts."""
    db = sqlite3.connect(path)
    db.execute("CREATE TABLE experiments (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512), "
               "totaltime REAL, timelimit REAL, memorylimit REAL, runcount INTEGER, version VARCHAR(128), "
               "hostname VARCHAR(1024), cpuinfo TEXT, date DATETIME, seed VARCHAR(24), setup TEXT)")
    db.execute("CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512) NOT NULL, "
               "settings TEXT)")
    columns = ["experimentid INTEGER", "plannerid INTEGER", "seed INTEGER", "solved BOOLEAN", "status ENUM",
               "time REAL"] + list(run_columns)
    db.execute(f"CREATE TABLE runs (id INTEGER PRIMARY KEY AUTOINCREMENT, {', '.join(columns)})")
    db.execute("CREATE TABLE progress (runid INTEGER, time REAL, PRIMARY KEY (runid, time))")
    db.executemany("INSERT INTO experiments (id, name, timelimit, seed) VALUES (?, ?, ?, ?)", experiments)
    db.executemany("INSERT INTO plannerConfigs (id, name, settings) VALUES (?, ?, '')", planners)
    for run in runs:
        names = list(run)
        db.execute(f"INSERT INTO runs ({', '.join(names)}) VALUES ({', '.join('?' * len(names))})",
                   [run[n] for n in names])
    db.commit()
    db.close()


def mopl_runs():
    """Two planners on one scene split in two shards (same name) and on a second scene; every
    run solved, with MOPL's path and time statistics. Parts of the time take half of it."""
    runs = []
    for experiment in (1, 2, 3):
        for planner in (1, 2):
            for k in range(3):
                time = 0.1 * (k + 1) * planner
                runs.append({"experimentid": experiment, "plannerid": planner, "seed": 100 * experiment + k,
                             "solved": 1, "status": 6, "time": time, "path_length_m": 10.0 + k + planner,
                             "primitives_transit": 3 + k, "primitives_push": 2, "primitives_pickup": 0,
                             "primitives_transfer": 0, "time_sampling_s": 0.1 * time,
                             "time_nearest_s": 0.2 * time, "time_propagate_s": 0.1 * time,
                             "time_connect_s": 0.05 * time, "time_smoothing_s": 0.05 * time, "time_ik_s": 0.0})
    return runs


def physics_runs():
    """RRT solves both scenes, PDST neither (approximate solutions, after the time limit);
    power is a column without a value."""
    runs = []
    for experiment in (1, 2):
        for k in range(4):
            runs.append({"experimentid": experiment, "plannerid": 1, "seed": k, "solved": 1, "status": 6,
                         "time": 0.5 + 0.1 * k, "action": 2.0 + k, "smoothness": 5e4 * (k + 1), "power": None})
            runs.append({"experimentid": experiment, "plannerid": 2, "seed": k, "solved": 0, "status": 5,
                         "time": 3.02 + 0.01 * k, "action": None, "smoothness": None, "power": None})
    return runs


MOPL_COLUMNS = ["path_length_m REAL", "primitives_transit INTEGER", "primitives_push INTEGER",
                "primitives_pickup INTEGER", "primitives_transfer INTEGER", "time_sampling_s REAL",
                "time_nearest_s REAL", "time_propagate_s REAL", "time_connect_s REAL", "time_smoothing_s REAL",
                "time_ik_s REAL"]


@unittest.skipIf(PYTHON is None, "no Python interpreter with matplotlib (Debian: python3-matplotlib)")
class PlotTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def plot(self, db, out="plots"):
        out = os.path.join(self.dir, out)
        result = subprocess.run([PYTHON, PLOT, db, "--out", out], capture_output=True, text=True, timeout=60)
        return result, out

    def assert_png(self, path):
        with open(path, "rb") as f:
            data = f.read()
        self.assertEqual(data[:8], PNG_SIGNATURE, path)
        self.assertGreater(len(data), 5000, f"{path}: suspiciously small")
        width, height = struct.unpack(">II", data[16:24])  # IHDR follows the signature
        self.assertGreaterEqual(min(width, height), 400, f"{path}: {width}x{height} pixels")

    def assert_figures(self, result, out, written, skipped):
        """written exist as PNG files and are printed; skipped are absent and noted."""
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(sorted(os.listdir(out)), sorted(written))
        for name in written:
            self.assert_png(os.path.join(out, name))
            self.assertIn(os.path.join(out, name), result.stdout.splitlines())
        for name in skipped:
            self.assertIn(f"skipped {name}", result.stdout)

    def test_mopl_database_gives_mopl_figures_and_skips_physics_metrics(self):
        db = os.path.join(self.dir, "mopl.db")
        make_db(db, [(1, "scene_a", 2.0, "1"), (2, "scene_a", 2.0, "1"), (3, "scene_b", 2.0, "1")],
                [(1, "geometric_mopl"), (2, "geometric_mopl_fine")], MOPL_COLUMNS, mopl_runs())
        result, out = self.plot(db)
        self.assert_figures(result, out,
                            ["time.png", "success.png", "metric_path_length_m.png", "primitives.png",
                             "time_shares.png"],
                            ["metric_action.png", "metric_power.png", "metric_smoothness.png"])
        self.assertIn("no 'action' column", result.stdout)

    def test_physics_database_skips_missing_and_empty_metric_columns(self):
        db = os.path.join(self.dir, "phys.db")
        make_db(db, [(1, "scene1", 3.0, "1"), (2, "scene3", 3.0, "1")], [(1, "control_rrt"), (2, "control_pdst")],
                ["action REAL", "power REAL", "smoothness REAL"], physics_runs())
        result, out = self.plot(db)
        self.assert_figures(result, out, ["time.png", "success.png", "metric_action.png", "metric_smoothness.png"],
                            ["metric_power.png", "metric_path_length_m.png", "primitives.png", "time_shares.png"])
        self.assertIn("no 'path_length_m' column", result.stdout)
        self.assertIn("no 'power' value", result.stdout)

    def test_seed_run_twice_in_merged_shards_is_noted(self):
        db = os.path.join(self.dir, "twice.db")
        runs = [{"experimentid": e, "plannerid": 1, "seed": 7, "solved": 1, "status": 6, "time": 0.2}
                for e in (1, 2)]
        make_db(db, [(1, "scene_a", 1.0, "7"), (2, "scene_a", 1.0, "7")], [(1, "geometric_mopl")], [], runs)
        result, out = self.plot(db)
        self.assert_figures(result, out, ["time.png", "success.png"], [])
        self.assertIn("repeated seeds 7 (2 runs)", result.stdout)

    def assert_rejected(self, db, *words):
        result, out = self.plot(db)
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        for word in (db,) + words:
            self.assertIn(word, result.stderr)
        self.assertFalse(os.path.exists(out), "no output directory for bad input")

    def test_missing_database_exits_2_naming_it(self):
        self.assert_rejected(os.path.join(self.dir, "absent.db"), "no such file")

    def test_file_that_is_not_a_database_exits_2(self):
        db = os.path.join(self.dir, "text.db")
        with open(db, "w") as f:
            f.write("Experiment scene_a\nnot a database at all, but long enough to be read as one\n" * 20)
        self.assert_rejected(db, "not an SQLite database")

    def test_database_without_runs_table_exits_2(self):
        db = os.path.join(self.dir, "empty.db")
        connection = sqlite3.connect(db)
        connection.execute("CREATE TABLE experiments (id INTEGER, name TEXT, timelimit REAL)")
        connection.close()
        self.assert_rejected(db, "runs")

    def test_usage_error_exits_2(self):
        result = subprocess.run([PYTHON, PLOT], capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 2)
        self.assertIn("usage", result.stderr)


if __name__ == "__main__":
    unittest.main()
