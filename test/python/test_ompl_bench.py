"""Tests for the Python module ompl_bench: run() writes the logs ompl_mm_benchmark writes for the
same cfg (same runs, seeds and results), shards split the runs, to_database() builds OMPL's
database from them, bad input raises ompl_core.InputError naming the file and line, and Ctrl-C
stops a benchmark. Run by ctest with the build tree's python folder on PYTHONPATH; the app's and
scenes' locations come from OMPL_MM_BENCHMARK and OMPL_MM_SCENES."""
import os
import sqlite3
import subprocess

import pytest

import ompl_bench
import ompl_core
from signal_support import interrupted

SCENES = os.environ["OMPL_MM_SCENES"]
APP = os.environ["OMPL_MM_BENCHMARK"]
# what a run gives apart from its times and memory (which differ from run to run)
RESULT_COLUMNS = "seed, solved, status, path_vertices, path_length_m, solution_length"
# two MOPLs, the second with coarser steps and a label of its own
PLANNERS = ("mopl =", "mopl =", "mopl.vertex_step = 0.5", "mopl.name = mopl_coarse")


def write_config(folder, runs=3, planners=PLANNERS):
    """A cfg of MOBILE BLOCKED (solved in a tenth of a second or so) with runs runs of each
    planner (cfg lines), 20 s each at most."""
    config = folder / "small.cfg"
    config.write_text(f"[problem]\nname = mobile_blocked\nscene = {SCENES}/mobile_blocked.xml\ntime_limit = 20\n\n"
                      f"[benchmark]\nrun_count = {runs}\nseed = 1\noutput = out\n\n[planner]\n" +
                      "".join(f"{line}\n" for line in planners))
    return config


def results(db):
    """The runs in db: planner name and the result columns, in run order."""
    with sqlite3.connect(db) as connection:
        return connection.execute(f"SELECT plannerConfigs.name, {RESULT_COLUMNS} FROM runs JOIN plannerConfigs "
                                  "ON runs.plannerid = plannerConfigs.id ORDER BY runs.id").fetchall()


def test_run_writes_the_apps_logs_and_to_database_loads_them(tmp_path):
    config = write_config(tmp_path)
    logs = ompl_bench.run(config, output=tmp_path / "python")
    assert logs == [str(tmp_path / "python" / "small.log")] and os.path.isfile(logs[0])
    subprocess.run([APP, str(config), "--output", str(tmp_path / "app"), "--quiet"], check=True,
                   capture_output=True)
    ours = ompl_bench.to_database(logs, tmp_path / "python.db")
    theirs = ompl_bench.to_database([tmp_path / "app" / "small.log"], tmp_path / "app.db")
    assert ours == str(tmp_path / "python.db")
    rows = results(ours)
    assert len(rows) == 6 and {row[0] for row in rows} == {"geometric_mopl", "geometric_mopl_coarse"}
    assert all(row[2] for row in rows), "MOBILE BLOCKED solved in every run"
    assert rows == results(theirs)


def test_the_cfgs_own_output_folder_is_the_default(tmp_path):
    config = write_config(tmp_path, runs=1, planners=("mopl =",))
    assert ompl_bench.run(str(config)) == [str(tmp_path / "out" / "small.log")]


def test_shards_split_the_runs(tmp_path):
    config = write_config(tmp_path)
    first = ompl_bench.run(config, shard=(1, 2), output=tmp_path)
    second = ompl_bench.run(config, shard="2/2", output=tmp_path)
    assert first == [str(tmp_path / "small.shard-1-of-2.log")]
    assert second == [str(tmp_path / "small.shard-2-of-2.log")]
    whole = ompl_bench.run(config, output=tmp_path / "whole")
    merged = sorted(results(ompl_bench.to_database(first + second, tmp_path / "shards.db")))
    assert merged == sorted(results(ompl_bench.to_database(whole, tmp_path / "whole.db")))


def test_to_database_makes_a_fresh_database_unless_asked_to_append(tmp_path):
    logs = ompl_bench.run(write_config(tmp_path, runs=2, planners=("mopl =",)), output=tmp_path)
    db = tmp_path / "runs.db"
    ompl_bench.to_database(logs, db)
    ompl_bench.to_database(logs, db)
    assert len(results(db)) == 2
    ompl_bench.to_database(logs[0], db, append=True)
    assert len(results(db)) == 4


def test_the_statistics_script_of_ompl_is_found():
    scripts = ompl_bench.statistics_scripts()
    assert scripts and all(os.path.isfile(script) for script in scripts)


def test_bad_configs_raise_input_error_naming_file_and_line(tmp_path):
    with pytest.raises(ompl_core.InputError) as error:
        ompl_bench.run(tmp_path / "missing.cfg")
    assert "missing.cfg" in str(error.value)
    config = write_config(tmp_path, planners=("mopl =", "no_such_planner ="))
    line = config.read_text().splitlines().index("no_such_planner =") + 1
    with pytest.raises(ompl_core.InputError) as error:
        ompl_bench.run(config, output=tmp_path)
    assert error.value.file == str(config) and error.value.line == line
    assert "no_such_planner" in str(error.value)
    for shard in ("3/2", "0/1", "x"):
        with pytest.raises(ompl_core.InputError):
            ompl_bench.run(write_config(tmp_path), shard=shard, output=tmp_path)


def test_to_database_refuses_missing_logs_and_reports_a_failing_script(tmp_path):
    with pytest.raises(FileNotFoundError) as error:
        ompl_bench.to_database([tmp_path / "missing.log"], tmp_path / "x.db")
    assert "missing.log" in str(error.value)
    with pytest.raises(ValueError):
        ompl_bench.to_database([], tmp_path / "x.db")
    bad = tmp_path / "bad.log"
    bad.write_text("not a benchmark log\n")
    with pytest.raises(RuntimeError) as error:
        ompl_bench.to_database([bad], tmp_path / "x.db")
    assert "ompl_benchmark_statistics" in str(error.value)


def test_ctrl_c_stops_the_benchmark_and_raises_keyboard_interrupt(tmp_path):
    """SIGINT during a benchmark of a thousand short runs ends it after the run in progress."""
    config = write_config(tmp_path, runs=1000, planners=("mopl =",))
    status, out = interrupted(
        f"import ompl_bench; ompl_bench.run({str(config)!r}, output={str(tmp_path)!r})", 2.0)
    assert status == 3 and out.endswith("interrupted\n"), out
    assert not (tmp_path / "small.log").exists(), "no log of an interrupted problem"
