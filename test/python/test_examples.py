"""Tests for the examples (examples/): plan_and_plot's panels draw the tool path and the object
tracks of a fresh plan with the same seed; benchmark_to_pandas's DataFrame and box plots agree with
its benchmark database read directly with sqlite3; both main()s write a PNG of the requested size
that shows the plotted colours; bad input exits with status 2 naming the file. Run by ctest with the
build tree's python folder on PYTHONPATH; the project's and scenes' folders come from OMPL_MM_SOURCE
and OMPL_MM_SCENES. The benchmark (about 20 s) runs once, for all the tests that read it."""
import importlib.util
import os
import sqlite3
import subprocess
import sys

import numpy
import pandas
import pytest
from matplotlib import colors, image

import ompl_core
import ompl_mm

SOURCE = os.environ["OMPL_MM_SOURCE"]
SCENES = os.environ["OMPL_MM_SCENES"]
EXAMPLES = os.path.join(SOURCE, "examples")
SEED = 2
DPI = 60
NOT_MOVED_SUFFIX = " (not moved)"


def load_example(name):
    """The example examples/NAME.py imported as a module."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(EXAMPLES, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


plan_and_plot = load_example("plan_and_plot")
benchmark_to_pandas = load_example("benchmark_to_pandas")


def scene_file(name):
    return os.path.join(SCENES, name + ".xml")


def read_png(path):
    """The PNG's pixels as rows x columns x RGB, 0 to 1."""
    return image.imread(path)[:, :, :3]


def pixels_in_colour(pixels, rgb):
    """How many pixels have the colour rgb, to within the PNG's rounding."""
    return int(numpy.all(numpy.abs(pixels - numpy.asarray(rgb)) <= 2 / 255, axis=2).sum())


def assert_png_of_figure(path, figure):
    """The PNG has the figure's size at DPI and is not blank: more than 3 % of it is not white."""
    pixels = read_png(path)
    width, height = figure.get_size_inches() * DPI
    assert pixels.shape[:2] == (round(height), round(width))
    assert (pixels < 0.95).any(axis=2).mean() > 0.03
    return pixels


def labelled_lines(axes):
    """The axes' lines that have a label of their own, by label."""
    return {line.get_label(): line for line in axes.get_lines() if not line.get_label().startswith("_")}


# plan_and_plot

@pytest.fixture(scope="module")
def plans():
    return plan_and_plot.plan_scenes(SCENES, SEED)


def test_each_panel_draws_the_tool_path_of_a_fresh_plan_with_the_same_seed(plans):
    figure = plan_and_plot.plot_plans(plans)
    assert len(figure.axes) == len(plan_and_plot.SCENE_NAMES)
    for axes, name in zip(figure.axes, plan_and_plot.SCENE_NAMES):
        assert axes.get_title() == f"{name} · mopl · seed {SEED}"
        assert axes.get_aspect() == 1.0 and axes.get_xlabel() == "x (m)" and axes.get_ylabel() == "y (m)"
        fresh = ompl_mm.plan(scene_file(name), seed=SEED)
        tool = labelled_lines(axes)["tool"]
        numpy.testing.assert_array_equal(tool.get_xydata(), fresh.path.tool[:, :2])
        markers = {(line.get_marker(), tuple(line.get_xydata()[0])) for line in axes.get_lines()
                   if line.get_color() == tool.get_color() and line is not tool}
        assert markers == {("o", tuple(fresh.path.tool[0, :2])), ("s", tuple(fresh.path.tool[-1, :2]))}


def test_each_object_has_its_track_and_its_name_in_the_legend(plans):
    figure = plan_and_plot.plot_plans(plans)
    for axes, result in zip(figure.axes, plans):
        lines = labelled_lines(axes)
        legend = [text.get_text() for text in axes.get_legend().get_texts()]
        objects = ompl_mm.load_scene(scene_file(result.record["scene"])).objects
        assert sorted(legend) == sorted(list(lines) + ["start", "end"])
        assert len(lines) == len(objects) + 1
        assert len({line.get_color() for line in lines.values()}) == len(lines), "a colour per track"
        for name in objects:
            track = result.path.objects[name][:, :2]
            moved = not (track == track[0]).all()
            line = lines[name if moved else name + NOT_MOVED_SUFFIX]
            numpy.testing.assert_array_equal(line.get_xydata(), track)
    kuka_table_tracks = labelled_lines(figure.axes[1])
    assert all(name in kuka_table_tracks for name in ("cyl1", "cyl2", "cyl3")), "every cylinder is moved"


def test_plan_and_plot_main_writes_a_png_showing_every_track(tmp_path, plans):
    out = tmp_path / "plans.png"
    status = plan_and_plot.main(["--seed", str(SEED), "--scenes", SCENES, "--out", str(out),
                                 "--dpi", str(DPI)])
    assert status == 0
    figure = plan_and_plot.plot_plans(plans)
    pixels = assert_png_of_figure(out, figure)
    for axes in figure.axes:
        for label, line in labelled_lines(axes).items():
            assert pixels_in_colour(pixels, colors.to_rgb(line.get_color())) >= 10, label


def test_a_missing_scenes_folder_exits_with_status_2_naming_the_missing_file(tmp_path):
    missing = tmp_path / "no_scenes"
    with pytest.raises(ompl_core.InputError, match="mobile_blocked.xml"):
        plan_and_plot.plan_scenes(str(missing), SEED)
    out = tmp_path / "plans.png"
    command = [sys.executable, os.path.join(EXAMPLES, "plan_and_plot.py"), "--scenes", str(missing),
               "--out", str(out)]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    assert done.returncode == 2
    assert str(missing / "mobile_blocked.xml") in done.stderr and "not found" in done.stderr
    assert not out.exists()


# benchmark_to_pandas

@pytest.fixture(scope="module")
def benchmark(tmp_path_factory):
    """main()'s exit status, database and PNG for the quick Table I benchmark."""
    folder = tmp_path_factory.mktemp("benchmark")
    out = folder / "benchmark.png"
    status = benchmark_to_pandas.main(["--output", str(folder / "logs"), "--out", str(out),
                                       "--dpi", str(DPI)])
    return status, str(folder / "logs" / benchmark_to_pandas.DATABASE_NAME), out


def database_values(db, column, solved_only=False):
    """Problem name -> the runs' values of `column`, read with sqlite3 alone."""
    query = (f"SELECT experiments.name, runs.{column} FROM runs JOIN experiments ON runs.experimentid = "
             f"experiments.id {'WHERE runs.solved = 1' if solved_only else ''} ORDER BY runs.id")
    values = {}
    with sqlite3.connect(db) as connection:
        for problem, value in connection.execute(query):
            values.setdefault(problem, []).append(value)
    return values


def test_the_frame_has_every_run_of_the_quick_benchmark(benchmark):
    status, db, _ = benchmark
    assert status == 0
    frame = benchmark_to_pandas.read_runs(db)
    assert frame.groupby("problem", sort=False).size().to_dict() == {
        "mobile_blocked": 10, "kuka_table": 10, "kuka_cabinet": 10}
    assert (frame["planner"] == "mopl").all() and (frame["planner_config"] == "geometric_mopl").all()
    assert (frame["time"] > 0).all() and frame["solved"].isin([0, 1]).all()
    for column in ("time", "solved"):  # whether a run solved within its limit depends on the machine
        assert frame.groupby("problem")[column].apply(list).to_dict() == database_values(db, column)


@pytest.mark.parametrize("panel,column,unit", [(0, "time", "(s)"), (1, "path_length_m", "(m)")])
def test_the_box_plots_show_the_databases_medians_and_quartiles(benchmark, panel, column, unit):
    _, db, _ = benchmark
    axes = benchmark_to_pandas.plot_runs(benchmark_to_pandas.read_runs(db)).axes[panel]
    assert axes.get_ylabel().endswith(unit)
    values = database_values(db, column, solved_only=(panel == 1))
    problems = [label.get_text() for label in axes.get_xticklabels()]
    assert problems == list(values)
    lines = labelled_lines(axes)
    boxes = sorted(axes.patches, key=lambda box: box.get_path().vertices[:, 0].mean())
    assert len(boxes) == len(problems)
    for problem, box in zip(problems, boxes):
        median = lines[f"median of {problem} · mopl"].get_ydata()
        assert median[0] == median[1] == pytest.approx(numpy.median(values[problem]), rel=1e-12)
        box_y = box.get_path().vertices[:, 1]
        assert (box_y.min(), box_y.max()) == pytest.approx(tuple(numpy.percentile(values[problem], [25, 75])))


def test_benchmark_main_writes_a_png_showing_the_boxes(benchmark):
    _, db, out = benchmark
    figure = benchmark_to_pandas.plot_runs(benchmark_to_pandas.read_runs(db))
    pixels = assert_png_of_figure(out, figure)
    red, green, blue, alpha = figure.axes[0].patches[0].get_facecolor()
    over_white = alpha * numpy.array([red, green, blue]) + (1 - alpha)
    assert figure.axes[0].get_yscale() == "log"
    assert pixels_in_colour(pixels, over_white) > 200, "the boxes' fill"


def test_the_path_length_falls_back_to_ompl_solution_length():
    frame = pandas.DataFrame({"solution_length": [1.0, 2.0]})
    assert benchmark_to_pandas.path_length_column(frame)[0] == "solution_length"
    with pytest.raises(ValueError, match="path_length_m"):
        benchmark_to_pandas.path_length_column(pandas.DataFrame({"time": [1.0]}))


def test_a_missing_config_exits_with_status_2_naming_it(tmp_path, capsys):
    missing = tmp_path / "no.cfg"
    out = tmp_path / "benchmark.png"
    status = benchmark_to_pandas.main(["--config", str(missing), "--output", str(tmp_path),
                                       "--out", str(out)])
    assert status == 2
    assert str(missing) in capsys.readouterr().err
    assert not out.exists()
