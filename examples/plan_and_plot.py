"""Plans MOBILE BLOCKED and KUKA TABLE with MOPL and draws, for each scene, the tool's path and every
object's track seen from above: what a plan moves and where, read from the numpy arrays that
ompl_mm.plan() returns.

    PYTHONPATH=build/python /usr/bin/python3 examples/plan_and_plot.py --seed 1 --out plans.png
"""
import argparse
import os
import sys

import numpy
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

import ompl_mm

SCENE_NAMES = ("mobile_blocked", "kuka_table")
SCENES_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes")
TOOL_COLOUR = "C0"
# the objects take the colour cycle's next colours, in the scene's order
OBJECT_COLOURS = tuple(f"C{i}" for i in range(1, 10))
PANEL_SIZE_IN = (5.5, 5.6)


def plan_scenes(scenes_dir, seed, names=SCENE_NAMES):
    """The MOPL plan of each scene file scenes_dir/NAME.xml with random seed `seed`, in the order of
    `names`. Raises ompl_mm.InputError naming the file when one is missing or malformed."""
    return [ompl_mm.plan(ompl_mm.load_scene(os.path.join(scenes_dir, name + ".xml")), seed=seed)
            for name in names]


def draw_track(axes, xy, colour, label, linewidth):
    """The polyline xy (n x 2) in `colour` with `label` for the legend, an open circle at its start
    and a filled square at its end."""
    axes.plot(xy[:, 0], xy[:, 1], color=colour, linewidth=linewidth, label=label, zorder=2)
    axes.plot(xy[0, 0], xy[0, 1], marker="o", markersize=8, color=colour, markerfacecolor="white",
              linestyle="none", zorder=3)
    axes.plot(xy[-1, 0], xy[-1, 1], marker="s", markersize=7, color=colour, linestyle="none", zorder=3)


def draw_plan(axes, result):
    """The top view of one solved plan: each object's track (labelled with its name, "not moved"
    when it stays in place), the tool's path over them, equal axes in metres and a legend below
    (the tool first)."""
    for (name, track), colour in zip(result.path.objects.items(), OBJECT_COLOURS):
        moved = numpy.ptp(track[:, :2], axis=0).max() > 0
        draw_track(axes, track[:, :2], colour, name if moved else f"{name} (not moved)", linewidth=3.5)
    draw_track(axes, result.path.tool[:, :2], TOOL_COLOUR, "tool", linewidth=1.3)
    axes.set_aspect("equal", adjustable="datalim")
    axes.grid(True, color="0.9")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.set_title(f"{result.record['scene']} · {result.record['planner']} · seed {result.record['seed']}")
    markers = [Line2D([], [], marker="o", color="0.3", markerfacecolor="white", linestyle="none",
                      label="start"),
               Line2D([], [], marker="s", color="0.3", linestyle="none", label="end")]
    *objects, tool = axes.get_legend_handles_labels()[0]
    axes.legend(handles=[tool, *objects, *markers], loc="upper center",
                bbox_to_anchor=(0.5, -0.13), ncol=4, frameon=False)


def plot_plans(results):
    """A figure with one top-view panel per solved plan result, side by side."""
    figure = Figure(figsize=(PANEL_SIZE_IN[0] * len(results), PANEL_SIZE_IN[1]), layout="constrained")
    for axes, result in zip(figure.subplots(1, len(results), squeeze=False)[0], results):
        draw_plan(axes, result)
    return figure


def main(argv=None):
    """Plans the scenes, draws them and writes the PNG. Returns 0, 1 when a scene is not solved,
    2 on bad input (a missing or malformed scene file, a seed out of range)."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1, help="the planner's random seed (default 1)")
    parser.add_argument("--scenes", default=SCENES_DIR, help="folder of the scene files "
                        "(default: the project's scenes/)")
    parser.add_argument("--scene", action="append", metavar="NAME",
                        help="plan the scene file NAME.xml of that folder; repeat for more "
                             f"(default: {' and '.join(SCENE_NAMES)})")
    parser.add_argument("--out", default="plan_and_plot.png", help="the PNG to write")
    parser.add_argument("--dpi", type=int, default=100, help="pixels per inch of the PNG (default 100)")
    args = parser.parse_args(argv)
    try:
        results = plan_scenes(args.scenes, args.seed, args.scene or SCENE_NAMES)
    except ValueError as error:  # ompl_mm.InputError is one
        print(f"plan_and_plot: {error}", file=sys.stderr)
        return 2
    unsolved = [result.record["scene"] for result in results if not result.solved]
    if unsolved:
        print(f"plan_and_plot: no plan found for {', '.join(unsolved)} with seed {args.seed}",
              file=sys.stderr)
        return 1
    plot_plans(results).savefig(args.out, dpi=args.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main())
