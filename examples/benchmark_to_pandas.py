"""Runs a benchmark cfg with ompl_bench, reads its runs from OMPL's benchmark database into a pandas
DataFrame and draws each problem's and planner's planning time and path length: a starting point
for one's own analysis, with every column of the database's runs table in the frame.

    PYTHONPATH=build/python /usr/bin/python3 examples/benchmark_to_pandas.py --out benchmark.png
"""
import argparse
import os
import sqlite3
import sys

import pandas
from matplotlib.figure import Figure
from matplotlib.patches import Patch
from matplotlib.ticker import FormatStrFormatter, LogLocator

import ompl_bench

CONFIG = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benchmarks",
                      "mopl_table1_quick.cfg")
DATABASE_NAME = "benchmark.db"
# every run, with its problem (experiment) and planner names beside the runs table's columns
RUNS_QUERY = """
    SELECT experiments.name AS problem, plannerConfigs.name AS planner_config, runs.*
    FROM runs
    JOIN experiments ON runs.experimentid = experiments.id
    JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id
    ORDER BY runs.id"""
PLANNER_PREFIXES = ("geometric_", "control_")
# path length columns, the first present is drawn: MOPL's tool path, else OMPL's own length
PATH_LENGTHS = (("path_length_m", "tool path length (m)"),
                ("solution_length", "solution length (state-space units)"))


def read_runs(db):
    """The runs of the benchmark database `db` (OMPL's ompl_benchmark_statistics schema) as a DataFrame:
    a row per run, the columns of the runs table (time in seconds, solved, ...) and `problem` and
    `planner` (the planner configuration's name without OMPL's 'geometric_'/'control_' prefix)."""
    with sqlite3.connect(db) as connection:
        frame = pandas.read_sql_query(RUNS_QUERY, connection)
    prefix = f"^({'|'.join(PLANNER_PREFIXES)})"
    frame["planner"] = frame["planner_config"].str.replace(prefix, "", regex=True)
    return frame


def path_length_column(frame):
    """The first of PATH_LENGTHS's columns that the frame has, with its axis label."""
    for column, label in PATH_LENGTHS:
        if column in frame and frame[column].notna().any():
            return column, label
    raise ValueError("the runs have no path length column: " + ", ".join(c for c, _ in PATH_LENGTHS))


def draw_boxes(axes, frame, column, label):
    """Box plots of `column` per problem (along x, in the frame's order) and planner (side by side, a
    colour each), leaving out the runs without a value; each median line is labelled "median of
    PROBLEM · PLANNER"."""
    problems, planners = list(frame["problem"].unique()), list(frame["planner"].unique())
    width = 0.7 / len(planners)
    for index, planner in enumerate(planners):
        runs = frame[frame["planner"] == planner].dropna(subset=[column])
        groups = list(runs.groupby("problem", sort=False)[column])
        if not groups:
            continue
        # the planners' boxes side by side, centred on their problem's tick
        offset = (index - (len(planners) - 1) / 2) * width
        boxes = axes.boxplot([values for _, values in groups],
                             positions=[problems.index(problem) + offset for problem, _ in groups],
                             widths=0.9 * width, patch_artist=True, medianprops={"color": "black"},
                             boxprops={"facecolor": f"C{index}", "alpha": 0.6}, flierprops={"markersize": 4})
        for median, (problem, _) in zip(boxes["medians"], groups):
            median.set_label(f"median of {problem} · {planner}")
    axes.set_xticks(range(len(problems)), problems)
    axes.set_ylabel(label)
    axes.grid(True, axis="y", color="0.9")
    axes.legend(handles=[Patch(facecolor=f"C{i}", alpha=0.6, label=p) for i, p in enumerate(planners)],
                title="planner", loc="best")


def plot_runs(frame, title=""):
    """A figure of two panels: the planning time of all runs (log scale, ticks at 1, 2 and 5 times a
    power of ten) and the path length of the solved runs, box plots per problem and planner."""
    figure = Figure(figsize=(11, 4.6), layout="constrained")
    time_axes, length_axes = figure.subplots(1, 2)
    draw_boxes(time_axes, frame, "time", "planning time (s)")
    time_axes.set_yscale("log")
    time_axes.yaxis.set_major_locator(LogLocator(subs=(1, 2, 5)))
    time_axes.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    time_axes.set_title(f"Planning time, all {len(frame)} runs")
    column, label = path_length_column(frame)
    solved = frame["solved"] == 1
    draw_boxes(length_axes, frame.assign(**{column: frame[column].where(solved)}), column, label)
    length_axes.set_title(f"Path length, the {solved.sum()} solved runs")
    figure.suptitle(title)
    return figure


def main(argv=None):
    """Runs the benchmark into the output folder, makes its database (OUTPUT/benchmark.db), prints
    the count of runs, of solved runs and the median time per problem and planner, and writes the
    PNG. Returns 0, 1 when the database cannot be made, 2 on bad input."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--config", default=CONFIG, help="the benchmark cfg (default: the project's "
                        "benchmarks/mopl_table1_quick.cfg)")
    parser.add_argument("--output", default="benchmark_out", help="folder for the logs and the database "
                        "(default benchmark_out)")
    parser.add_argument("--out", default="benchmark_to_pandas.png", help="the PNG to write")
    parser.add_argument("--dpi", type=int, default=100, help="pixels per inch of the PNG (default 100)")
    args = parser.parse_args(argv)
    try:
        logs = ompl_bench.run(args.config, output=args.output, progress=True)
    except ompl_bench.InputError as error:
        print(f"benchmark_to_pandas: {error}", file=sys.stderr)
        return 2
    try:
        db = ompl_bench.to_database(logs, os.path.join(args.output, DATABASE_NAME))
    except (OSError, RuntimeError) as error:
        print(f"benchmark_to_pandas: {error}", file=sys.stderr)
        return 1
    frame = read_runs(db)
    print(frame.groupby(["problem", "planner"], sort=False).agg(
        runs=("solved", "size"), solved=("solved", "sum"), median_time_s=("time", "median")))
    title = f"{os.path.basename(args.config)}: box plots of the runs, medians as black lines"
    plot_runs(frame, title).savefig(args.out, dpi=args.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main())
