#!/usr/bin/env python3
"""Draws Planner Arena's figures from a benchmark database as PNG files: the SQLite database that
Debian's ompl_benchmark_statistics makes from OMPL benchmark logs (ompl_mm_benchmark's, for
instance). Runs are grouped by experiment name (shards of one benchmark merged with -a share it)
and by planner configuration name, labelled without its 'geometric_' or 'control_' prefix; each
planner keeps its colour in every figure. Each figure has one panel per experiment name.

Figures (file names in DIR):
  time.png                   planning time of all runs per planner, box plots on a log scale with
                             every run as a point (x: not solved), the experiment's time limit dashed
  success.png                solved runs per planner, percent, with k/n on each bar
  metric_action.png          action of the solved runs' re-simulated paths, N·s·m (physics)
  metric_power.png           power, W (physics)
  metric_smoothness.png      smoothness (integrated squared jerk), m²/s⁵ (physics)
  metric_path_length_m.png   Cartesian length of the tool point's path, m (MOPL)
  primitives.png             mean count of each primitive kind in a solved path (MOPL)
  time_shares.png            where a solved run's planning time goes: mean over the solved runs
                             of each measured part (time_sampling_s ...) divided by the run's
                             time, stacked per planner, the rest as 'other' (MOPL)
A figure whose columns are absent from the runs table, or have no value in a solved run, is
skipped with a note. 'Solved' is the runs table's solved flag (an exact solution), as in Planner
Arena: approximate solutions count as unsolved. Values that are not finite numbers are left out
and counted in a note.

Needs matplotlib (Debian: python3-matplotlib, for /usr/bin/python3); standard library otherwise.
Exit status: 0 on success, 2 on a bad argument or database, 1 when matplotlib is missing.

Example:
  ompl_benchmark_statistics run.log -d run.db && benchmarks/plot.py run.db --out plots
"""
import argparse
import math
import os
import sqlite3
import sys
import urllib.request

PREFIXES = ("geometric_", "control_")

# box-plot metrics: column, axis label with unit, figure title
BOX_METRICS = (
    ("action", "action (N·s·m)", "Action of the solved runs (lower is better)"),
    ("power", "power (W)", "Power of the solved runs"),
    ("smoothness", "smoothness (m²/s⁵)",
     "Smoothness (integrated squared jerk) of the solved runs (lower is smoother)"),
    ("path_length_m", "tool-path length (m)", "Cartesian tool-path length of the solved runs"),
)
PRIMITIVES = (("primitives_transit", "transit"), ("primitives_push", "push"),
              ("primitives_pickup", "pickup"), ("primitives_transfer", "transfer"))
TIME_PARTS = (("time_sampling_s", "sampling"), ("time_nearest_s", "nearest neighbour"),
              ("time_propagate_s", "propagate"), ("time_connect_s", "connect"),
              ("time_smoothing_s", "smoothing"))
# spent inside the parts above (primitives, grasp samples, smoothing): drawn beside them, not stacked
IK_PART = ("time_ik_s", "inverse kinematics (within the parts)")
REQUIRED_TABLES = ("runs", "experiments", "plannerConfigs")
REQUIRED_RUN_COLUMNS = ("experimentid", "plannerid", "time", "solved")


class BadInput(Exception):
    """A database this script cannot read; the message names the file."""


class Benchmark:
    """The runs of one database, grouped for plotting.

    experiments: experiment names, in the order they first appear (lowest id);
    planners: planner configuration names, likewise; labels/colours: per configuration name;
    time_limits: experiment name -> sorted distinct time limits, s; columns: the runs table's
    columns; runs: one dict per run, column -> value, plus 'experiment' and 'planner' (names)."""

    def __init__(self, path, experiments, planners, time_limits, columns, runs):
        self.path = path
        self.experiments = experiments
        self.planners = planners
        self.time_limits = time_limits
        self.columns = columns
        self.runs = runs
        self.labels = planner_labels(planners)
        self.colours = {}
        self.notes = []
        self.bad_values = {}  # column -> {run id: value that is not a finite number}

    def select(self, experiment, planner, solved_only=False):
        """The runs of one experiment name and planner configuration name."""
        return [r for r in self.runs if r["experiment"] == experiment and r["planner"] == planner
                and (not solved_only or r["solved"])]

    def values(self, runs, column):
        """The finite numbers in column of runs; any other non-empty value is noted once."""
        out = []
        for r in runs:
            v = number(r.get(column))
            if v is not None and math.isfinite(v):
                out.append(v)
            elif r.get(column) is not None:
                self.bad_values.setdefault(column, {})[r.get("id")] = r[column]
        return out

    def note_bad_values(self):
        """One note per column with values that were left out."""
        for column, bad in self.bad_values.items():
            shown = ", ".join(f"run {i}: {v!r}" for i, v in list(bad.items())[:3])
            more = f" and {len(bad) - 3} more" if len(bad) > 3 else ""
            self.note(f"{column}: left out {len(bad)} that are not finite numbers ({shown}{more})")

    def note(self, text):
        if text not in self.notes:
            self.notes.append(text)
            print(f"note: {text}")


def planner_labels(planners):
    """Configuration name -> label without its 'geometric_'/'control_' prefix, unless two
    configurations would then share a label."""
    def strip(name):
        for p in PREFIXES:
            if name.startswith(p) and len(name) > len(p):
                return name[len(p):]
        return name
    stripped = [strip(p) for p in planners]
    return {p: (s if stripped.count(s) == 1 else p) for p, s in zip(planners, stripped)}


def number(value):
    """value as a float, or None when it is empty or not a number."""
    if value is None or isinstance(value, bytes):
        return None
    try:
        return float(value)
    except ValueError:
        return None


def open_database(path):
    """A read-only connection to path; BadInput when it is missing or not an SQLite database."""
    if not os.path.exists(path):
        raise BadInput(f"{path}: no such file")
    if not os.path.isfile(path):
        raise BadInput(f"{path}: not a file")
    try:
        db = sqlite3.connect(f"file:{urllib.request.pathname2url(os.path.abspath(path))}?mode=ro", uri=True)
        tables = {row[0] for row in db.execute("SELECT name FROM sqlite_master WHERE type IN ('table', 'view')")}
    except sqlite3.Error as e:
        raise BadInput(f"{path}: not an SQLite database ({e})") from e
    missing = [t for t in REQUIRED_TABLES if t not in tables]
    if missing:
        raise BadInput(f"{path}: no {', '.join(missing)} table (not a database from ompl_benchmark_statistics?)")
    return db


def read_benchmark(path):
    """The Benchmark in the database at path; BadInput when it cannot be plotted."""
    db = open_database(path)
    try:
        columns = [row[1] for row in db.execute("PRAGMA table_info(runs)")]
        missing = [c for c in REQUIRED_RUN_COLUMNS if c not in columns]
        if missing:
            raise BadInput(f"{path}: the runs table has no {', '.join(missing)} column")
        experiment_rows = db.execute("SELECT id, name, timelimit FROM experiments ORDER BY id").fetchall()
        planner_rows = db.execute("SELECT id, name FROM plannerConfigs ORDER BY id").fetchall()
        cursor = db.execute("SELECT * FROM runs ORDER BY id")
        names = [d[0] for d in cursor.description]
        rows = cursor.fetchall()
    except sqlite3.Error as e:
        raise BadInput(f"{path}: cannot read the benchmark tables ({e})") from e
    finally:
        db.close()
    if not rows:
        raise BadInput(f"{path}: the runs table is empty")
    experiment_of = {i: (name if name else f"experiment {i}") for i, name, _ in experiment_rows}
    planner_of = {i: (name if name else f"planner {i}") for i, name in planner_rows}
    runs = []
    for row in rows:
        run = dict(zip(names, row))
        run["experiment"] = experiment_of.get(run["experimentid"], f"experiment {run['experimentid']}")
        run["planner"] = planner_of.get(run["plannerid"], f"planner {run['plannerid']}")
        run["solved"] = number(run["solved"]) == 1.0
        runs.append(run)
    # names in order of first id; only those with runs
    used_experiments = {r["experiment"] for r in runs}
    used_planners = {r["planner"] for r in runs}
    experiments = list(dict.fromkeys(n for n in experiment_of.values() if n in used_experiments))
    experiments += sorted(used_experiments - set(experiments))
    planners = list(dict.fromkeys(n for n in planner_of.values() if n in used_planners))
    planners += sorted(used_planners - set(planners))
    time_limits = {}
    for _, name, limit in experiment_rows:
        v = number(limit)
        if v is not None and math.isfinite(v) and v > 0:
            time_limits.setdefault(name, set()).add(v)
    time_limits = {n: sorted(v) for n, v in time_limits.items()}
    return Benchmark(path, experiments, planners, time_limits, names, runs)


def check_benchmark(bench, path):
    """Notes what looks wrong in a merged database: experiments of one name with different
    scenes or time limits, and a seed that one planner ran twice in one experiment name (a
    shard merged twice?)."""
    try:
        db = open_database(path)
        columns = [row[1] for row in db.execute("PRAGMA table_info(experiments)")]
        if "scene_hash" in columns:
            hashes = {}
            for name, h in db.execute("SELECT name, scene_hash FROM experiments"):
                hashes.setdefault(name, set()).add(h)
            for name, hs in hashes.items():
                if len(hs) > 1:
                    bench.note(f"experiment '{name}' merges {len(hs)} different scene_hash values: "
                               f"{sorted(map(str, hs))}")
        db.close()
    except sqlite3.Error:
        pass
    for name, limits in bench.time_limits.items():
        if len(limits) > 1:
            bench.note(f"experiment '{name}' has different time limits: {', '.join(f'{t:g}' for t in limits)} s")
    if "seed" not in bench.columns:
        return
    seen = {}
    for r in bench.runs:
        if r["seed"] is not None:
            key = (r["experiment"], r["planner"], r["seed"])
            seen[key] = seen.get(key, 0) + 1
    repeated = {}
    for (experiment, planner, seed), count in seen.items():
        if count > 1:
            repeated.setdefault((experiment, planner), []).append(f"{seed} ({count} runs)")
    for (experiment, planner), seeds in repeated.items():
        more = f" and {len(seeds) - 3} more" if len(seeds) > 3 else ""
        bench.note(f"experiment '{experiment}', planner '{planner}': repeated seeds {', '.join(seeds[:3])}{more} "
                   f"(a shard merged twice?)")


# --- drawing ---------------------------------------------------------------------------------

def load_pyplot():
    """matplotlib.pyplot on the non-interactive Agg backend; exits with status 1 without it."""
    try:
        import matplotlib
    except ImportError as e:
        sys.exit(f"plot.py: {e}: install Debian's python3-matplotlib and run this script with "
                 f"/usr/bin/python3 (this is {sys.executable})")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def assign_colours(bench, plt):
    """One colour per planner configuration, the same in every figure."""
    cmap = plt.get_cmap("tab10" if len(bench.planners) <= 10 else "tab20")
    bench.colours = {p: cmap(i % cmap.N) for i, p in enumerate(bench.planners)}


def figure_grid(plt, bench, title, panel_width=None):
    """A figure with one panel per experiment name (up to three per row): (figure, [(name, axes)])."""
    n = len(bench.experiments)
    ncols = min(n, 3)
    nrows = math.ceil(n / ncols)
    width = panel_width or max(5.0, 0.8 * len(bench.planners) + 2.4)
    fig, axes = plt.subplots(nrows, ncols, figsize=(width * ncols, 4.3 * nrows + 0.4),
                             squeeze=False, layout="constrained")
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    fig.suptitle(title, fontsize=12, fontweight="bold")
    return fig, list(zip(bench.experiments, axes.flat))


def planner_ticks(ax, bench, counts=None):
    """Planner labels under positions 1 … P, with 'n=…' under each when counts are given."""
    labels = [bench.labels[p] for p in bench.planners]
    if counts is not None:
        labels = [f"{l}\nn={c}" for l, c in zip(labels, counts)]
    ax.set_xticks(range(1, len(labels) + 1))
    long = max(len(bench.labels[p]) for p in bench.planners) * len(labels) > 36
    ax.set_xticklabels(labels, rotation=25 if long else 0, ha="right" if long else "center")
    ax.set_xlim(0.4, len(labels) + 0.6)
    for tick, p in zip(ax.get_xticklabels(), bench.planners):
        tick.set_color(darker(bench.colours[p]))


def darker(colour):
    return tuple(0.7 * c for c in colour[:3])


def spread(position, n, width=0.36):
    """x positions of n points around position, evenly spread (no random jitter)."""
    if n == 1:
        return [position]
    return [position - width / 2 + width * k / (n - 1) for k in range(n)]


def draw_boxes(ax, bench, groups, empty_text):
    """Box plots at positions 1 … P of groups (per planner, a list of (value, solved) pairs),
    every value as a point on top (solved: dot, unsolved: x); empty_text where a planner has none."""
    positions = [i + 1 for i, g in enumerate(groups) if g]
    if positions:
        boxes = ax.boxplot([[v for v, _ in groups[i - 1]] for i in positions], positions=positions,
                           widths=0.6, patch_artist=True, showfliers=False,
                           medianprops={"color": "black", "linewidth": 1.5})
        for patch, pos in zip(boxes["boxes"], positions):
            patch.set_facecolor(bench.colours[bench.planners[pos - 1]])
            patch.set_alpha(0.55)
    for i, g in enumerate(groups):
        if not g:
            ax.text(i + 1, 0.5, empty_text, transform=ax.get_xaxis_transform(), rotation=90,
                    ha="center", va="center", color="0.45", fontsize=9)
            continue
        xs = spread(i + 1, len(g))
        solved = [(x, v) for x, (v, ok) in zip(xs, g) if ok]
        unsolved = [(x, v) for x, (v, ok) in zip(xs, g) if not ok]
        if solved:
            ax.plot(*zip(*solved), "o", color="black", markersize=3.5, zorder=3)
        if unsolved:
            ax.plot(*zip(*unsolved), "x", color="#c00000", markersize=5, zorder=3)
    ax.grid(axis="y", alpha=0.3)


def plot_time(plt, bench, out):
    fig, panels = figure_grid(plt, bench, "Planning time of all runs")
    from matplotlib.lines import Line2D
    for name, ax in panels:
        groups = [[(v, r["solved"]) for r in bench.select(name, p) for v in bench.values([r], "time")]
                  for p in bench.planners]
        draw_boxes(ax, bench, groups, "no run")
        # a log scale: run times span decades, and a limit far above them would flatten the boxes
        times = [v for g in groups for v, _ in g if v > 0]
        top = max(times + bench.time_limits.get(name, []) + [1e-3])
        bottom = min(times + [top]) / 2
        for i, g in enumerate(groups):
            if g:
                ax.text(i + 1, max(v for v, _ in g) * 1.2, f"median\n{median([v for v, _ in g]):.3g} s",
                        ha="center", va="bottom", fontsize=8)
        handles = [Line2D([], [], marker="o", color="black", ls="", markersize=3.5, label="solved run"),
                   Line2D([], [], marker="x", color="#c00000", ls="", markersize=5, label="not solved")]
        for t in bench.time_limits.get(name, []):
            ax.axhline(t, color="0.3", ls="--", lw=1.2)
        if name in bench.time_limits:
            limits = ", ".join(f"{t:g}" for t in bench.time_limits[name])
            handles.append(Line2D([], [], color="0.3", ls="--", label=f"time limit {limits} s"))
        ax.set_yscale("log")
        ax.set_ylim(bottom, top * 8)
        ax.legend(handles=handles, loc="upper center", ncol=len(handles), fontsize=8,
                  handletextpad=0.3, columnspacing=1.5, frameon=False)
        ax.set_ylabel("planning time (s)")
        ax.set_title(f"{name} ({sum(len(g) for g in groups)} runs)")
        planner_ticks(ax, bench, [len(g) for g in groups])
    return save(plt, fig, out, "time.png")


def plot_success(plt, bench, out):
    fig, panels = figure_grid(plt, bench, "Solved runs (exact solutions)")
    for name, ax in panels:
        for i, p in enumerate(bench.planners):
            runs = bench.select(name, p)
            k = sum(1 for r in runs if r["solved"])
            percent = 100.0 * k / len(runs) if runs else 0.0
            ax.bar(i + 1, percent, width=0.6, color=bench.colours[p], alpha=0.85)
            ax.text(i + 1, percent + 2, f"{k}/{len(runs)}" if runs else "no run", ha="center", va="bottom",
                    fontsize=10)
        ax.set_ylim(0, 112)
        ax.set_yticks(range(0, 101, 20))
        ax.set_ylabel("solved runs (%)")
        ax.set_title(name)
        ax.grid(axis="y", alpha=0.3)
        planner_ticks(ax, bench)
    return save(plt, fig, out, "success.png")


def plot_metric(plt, bench, out, column, axis_label, title):
    file_name = f"metric_{column}.png"
    if column not in bench.columns:
        return skip(file_name, f"no '{column}' column in the runs table")
    solved = [r for r in bench.runs if r["solved"]]
    if not bench.values(solved, column):
        return skip(file_name, f"no '{column}' value in a solved run")
    fig, panels = figure_grid(plt, bench, title)
    for name, ax in panels:
        groups = [[(v, True) for v in bench.values(bench.select(name, p, True), column)] for p in bench.planners]
        draw_boxes(ax, bench, groups, "no solved run")
        ax.set_ylabel(axis_label)
        ax.set_title(name)
        planner_ticks(ax, bench, [len(g) for g in groups])
    return save(plt, fig, out, file_name)


def columns_with_values(bench, candidates):
    """The (column, label) pairs of candidates that have a value in a solved run; None when no
    candidate is a column at all (an empty list when they are, without values)."""
    if not any(c in bench.columns for c, _ in candidates):
        return None
    solved = [r for r in bench.runs if r["solved"]]
    return [(c, label) for c, label in candidates if c in bench.columns and bench.values(solved, c)]


def plot_primitives(plt, bench, out):
    file_name = "primitives.png"
    kinds = columns_with_values(bench, PRIMITIVES)
    if not kinds:
        return skip(file_name, f"no primitives_* {'value in a solved run' if kinds == [] else 'column in the runs table'}")
    width_each = 0.8 / len(bench.planners)
    fig, panels = figure_grid(plt, bench, "Primitives in a solved path (mean count)",
                              panel_width=max(5.0, 0.25 * len(kinds) * len(bench.planners) + 3.0))
    for name, ax in panels:
        for j, p in enumerate(bench.planners):
            runs = bench.select(name, p, True)
            xs = [k + 1 - 0.4 + width_each * (j + 0.5) for k in range(len(kinds))]
            means = [mean(bench.values(runs, c)) for c, _ in kinds]
            heights = [m if m is not None else 0.0 for m in means]
            ax.bar(xs, heights, width=width_each * 0.9, color=bench.colours[p], alpha=0.85,
                   label=f"{bench.labels[p]} (n={len(runs)})")
            if len(bench.planners) <= 4:
                for x, m in zip(xs, means):
                    ax.text(x, (m or 0.0), "–" if m is None else f"{m:.1f}", ha="center", va="bottom", fontsize=8)
        ax.set_xticks(range(1, len(kinds) + 1))
        ax.set_xticklabels([label for _, label in kinds])
        ax.set_xlabel("primitive kind")
        ax.set_ylabel("mean count per solved path")
        ax.set_ylim(0, ax.get_ylim()[1] * 1.25)
        ax.grid(axis="y", alpha=0.3)
        ax.legend(loc="upper right", fontsize=8, title="planner (solved runs)", title_fontsize=8)
        ax.set_title(name)
    return save(plt, fig, out, file_name)


def time_shares(bench, runs, parts):
    """Mean over runs of each part's share of the run's time, percent (None without a run)."""
    shares = [[] for _ in parts]
    for r in runs:
        total = number(r["time"])
        if total is None or not math.isfinite(total) or total <= 0:
            continue
        values = [bench.values([r], c) for c, _ in parts]
        if any(not v for v in values):
            continue
        for s, v in zip(shares, values):
            s.append(100.0 * v[0] / total)
    return [mean(s) for s in shares], len(shares[0])


def plot_time_shares(plt, bench, out):
    file_name = "time_shares.png"
    parts = columns_with_values(bench, TIME_PARTS)
    if not parts:
        return skip(file_name, f"no time_*_s {'value in a solved run' if parts == [] else 'column in the runs table'}")
    fig, panels = figure_grid(plt, bench, "Where the planning time of a solved run goes (mean share)",
                              panel_width=max(6.5, 0.8 * len(bench.planners) + 4.5))
    cmap = plt.get_cmap("Set2")
    part_colours = [cmap(k % cmap.N) for k in range(len(parts))]
    for name, ax in panels:
        counts, highest = [], 100.0
        for i, p in enumerate(bench.planners):
            means, n = time_shares(bench, bench.select(name, p, True), parts)
            counts.append(n)
            if n == 0:
                ax.text(i + 1, 50, "no solved run", rotation=90, ha="center", va="center", color="0.45", fontsize=9)
                continue
            bottom = 0.0
            for k, m in enumerate(means):
                draw_share(ax, i + 1, bottom, m, part_colours[k], parts[k][1] if i == 0 else None)
                bottom += m
            if bottom > 100.5:
                bench.note(f"experiment '{name}', planner '{p}': the measured parts add up to "
                           f"{bottom:.0f} % of the time")
                highest = max(highest, bottom)
            draw_share(ax, i + 1, bottom, max(0.0, 100.0 - bottom), "0.88", "other (not measured)" if i == 0 else None,
                       hatch="//")
            draw_ik_share(ax, bench, name, p, i + 1, first=i == 0)
            ax.bar(i + 1, 100.0, width=0.6, fill=False, edgecolor=bench.colours[p], linewidth=2.5)
        if highest > 100.0:  # parts that overlap: show all of them, and where 100 % is
            ax.axhline(100.0, color="black", lw=1.0, ls=":")
        ax.set_ylim(0, highest)
        ax.set_ylabel("share of planning time (%)")
        ax.set_title(name)
        planner_ticks(ax, bench, counts)
        handles, labels = ax.get_legend_handles_labels()
        ax.legend(handles[::-1], labels[::-1], loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9,
                  title="part", title_fontsize=9, frameon=False)
    return save(plt, fig, out, file_name)


def draw_ik_share(ax, bench, name, planner, x, first):
    """The share of inverse kinematics as a narrow bar right of the stacked one, when it is measured."""
    if not columns_with_values(bench, (IK_PART,)):
        return
    means, n = time_shares(bench, bench.select(name, planner, True), (IK_PART,))
    if n == 0 or not means[0]:
        return
    ax.bar(x + 0.38, means[0], width=0.12, color="tab:purple", label=IK_PART[1] if first else None)
    ax.text(x + 0.38, means[0], f"{means[0]:.0f} %", ha="center", va="bottom", fontsize=7)


def draw_share(ax, x, bottom, height, colour, label, hatch=None):
    """One segment of a stacked bar, its percentage written in it when there is room."""
    ax.bar(x, height, bottom=bottom, width=0.6, color=colour, edgecolor="white", linewidth=0.5,
           hatch=hatch, label=label)
    if height >= 6:
        ax.text(x, bottom + height / 2, f"{height:.0f} %", ha="center", va="center", fontsize=8)


def mean(values):
    return sum(values) / len(values) if values else None


def median(values):
    v = sorted(values)
    return (v[(len(v) - 1) // 2] + v[len(v) // 2]) / 2


def save(plt, fig, out, file_name):
    path = os.path.join(out, file_name)
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print(path)
    return path


def skip(file_name, reason):
    print(f"skipped {file_name}: {reason}")
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("db", metavar="DB", help="SQLite database made by ompl_benchmark_statistics")
    parser.add_argument("--out", metavar="DIR", required=True, help="directory for the PNG files (made if missing)")
    args = parser.parse_args()
    try:
        bench = read_benchmark(args.db)
    except BadInput as e:
        print(f"plot.py: {e}", file=sys.stderr)
        return 2
    plt = load_pyplot()
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        print(f"plot.py: {args.out}: cannot make the output directory ({e.strerror})", file=sys.stderr)
        return 2
    assign_colours(bench, plt)
    check_benchmark(bench, args.db)
    plot_time(plt, bench, args.out)
    plot_success(plt, bench, args.out)
    for column, axis_label, title in BOX_METRICS:
        plot_metric(plt, bench, args.out, column, axis_label, title)
    plot_primitives(plt, bench, args.out)
    plot_time_shares(plt, bench, args.out)
    bench.note_bad_values()
    return 0


if __name__ == "__main__":
    sys.exit(main())
