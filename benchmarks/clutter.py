#!/usr/bin/env python3
"""MOPL in clutter: scene families with K extra movable objects that the goal does not care about,
and how planning time and memory grow with K. Each family adds K cylinders to a base scene (by
default MOBILE BLOCKED), placed at random on the free floor, several placements per K: half of the
extras are placed where they block the way (the gap to the nearest obstacle or object is narrower
than the robot, so it cannot pass between them), the other half anywhere free. Each scene is
planned over several seeds, one ompl_mm_plan process per run; the report gives per K the success,
the median, mean and max planning time, the peak memory of the process and where the time went.
A dense family: --radius for smaller extras and --region (repeatable) to pack them, in turn, into
rectangles of the floor, anywhere free there, instead of across the whole floor.
Standard library only.

Examples (the generated scenes go to out/clutter/; without clearing: --param clear_probability=0):
  benchmarks/clutter.py --counts 0 4 8 12 16 --placements 2 --seeds 5 --markdown out/clutter.md
  benchmarks/clutter.py --counts 16 32 --radius 0.08 --length 0.3 \
      --region -2.5 0.5 -0.5 2.5 --region 0.5 -2.5 2.5 -0.5     (MOBILE BLOCKED's two side regions)
"""
import argparse
import math
import os
import random
import statistics
import sys
import tempfile
import xml.etree.ElementTree as ET

from run_records import check_binary, run_app

# The extras by default: MOBILE BLOCKED's cylinders.
RADIUS = 0.2
LENGTH = 0.5
# Floor margin kept free around the robot's start and goal and the goal objects' targets, metres.
KEEP_CLEAR = 0.5
# Least gap between an extra and anything else, metres: no contact at the start.
MIN_GAP = 0.01
PLACEMENT_TRIES = 100000


class Floor:
    """The free floor of a base scene: its surface rectangle, the boxes standing on it, the objects
    and the places to keep clear."""

    def __init__(self, root, robot_radius):
        surface = root.find("surface")
        self.low = [float(v) for v in surface.get("min").split()]
        self.high = [float(v) for v in surface.get("max").split()]
        self.boxes = []  # (centre x, y, half size x, y)
        for obstacle in root.findall("obstacle"):
            box, origin = obstacle.find("box"), obstacle.find("origin")
            if box is None or origin is None or origin.get("rpy"):
                sys.exit(f"obstacle '{obstacle.get('name')}': only boxes without rpy are supported")
            x, y, _ = (float(v) for v in origin.get("xyz").split())
            sx, sy, _ = (float(v) for v in box.get("size").split())
            self.boxes.append((x, y, sx / 2, sy / 2))
        self.discs = []  # (x, y, radius) of the objects
        for obj in root.find("start").findall("object"):
            x, y, _ = (float(v) for v in obj.get("xyz").split())
            self.discs.append((x, y, float(root.find(f"object[@name='{obj.get('name')}']/cylinder").get("radius"))))
        start = [float(v) for v in root.find("start/robot").get("joints").split()]
        goal = [float(v) for v in root.find("goal/robot").get("joints").split()]
        self.clear = [start[:2], goal[:2]]
        for obj in root.find("goal").findall("object"):
            x, y = obj.get("xyz").split()[:2]
            if x != "*" and y != "*":
                self.clear.append([float(x), float(y)])
        self.robot_diameter = 2 * robot_radius

    def fixed_gap(self, x, y, r):
        """The free gap from a disc at (x, y) of radius r to the nearest box or the floor's edge."""
        gaps = [x - self.low[0] - r, self.high[0] - x - r, y - self.low[1] - r, self.high[1] - y - r]
        for bx, by, hx, hy in self.boxes:
            dx, dy = max(abs(x - bx) - hx, 0.0), max(abs(y - by) - hy, 0.0)
            gaps.append(math.hypot(dx, dy) - r)
        return min(gaps)

    def gap(self, x, y, r):
        """The free gap from a disc at (x, y) of radius r to the nearest box, wall or object."""
        return min([self.fixed_gap(x, y, r)] + [math.hypot(x - ox, y - oy) - r - orad for ox, oy, orad in self.discs])

    def place(self, rng, radius, blocking, region=None):
        """A free spot for one more disc of radius (touching nothing): within region (x min, y min,
        x max, y max) when given, anywhere free there; else one that leaves the robot no way between
        it and its nearest neighbour when blocking, else any."""
        low = [max(self.low[0], region[0]), max(self.low[1], region[1])] if region else self.low
        high = [min(self.high[0], region[2]), min(self.high[1], region[3])] if region else self.high
        for _ in range(PLACEMENT_TRIES):
            x = rng.uniform(low[0] + radius, high[0] - radius)
            y = rng.uniform(low[1] + radius, high[1] - radius)
            if any(math.hypot(x - cx, y - cy) < KEEP_CLEAR + radius for cx, cy in self.clear):
                continue
            gap = self.gap(x, y, radius)
            if gap >= MIN_GAP and (region or gap < self.robot_diameter or not blocking):
                self.discs.append((x, y, radius))
                return x, y
        where = f" in region {' '.join(f'{v:g}' for v in region)}" if region else ""
        sys.exit(f"no free spot{where} for {len(self.discs) + 1} objects after {PLACEMENT_TRIES} tries")


def make_scene(base, count, placement, robot_radius, directory, radius=RADIUS, length=LENGTH, regions=()):
    """Writes the base scene with count extras (cylinders of radius and length) of placement number
    `placement`, packed into the regions in turn when there are some; returns its path and the
    dimension of its state space (the robot's joints, and x, y, z, yaw per object)."""
    tree = ET.parse(base)
    root = tree.getroot()
    robot = root.find("robot")
    robot.set("urdf", os.path.join(os.path.dirname(os.path.abspath(base)), robot.get("urdf")))
    floor = Floor(root, robot_radius)
    rng = random.Random(placement)
    objects = root.findall("object")
    after = list(root).index(objects[-1]) + 1
    start = root.find("start")
    for i in range(count):
        region = regions[i % len(regions)] if regions else None
        x, y = floor.place(rng, radius, blocking=(i % 2 == 0), region=region)
        name = f"extra{i + 1}"
        element = ET.Element("object", name=name)
        ET.SubElement(element, "cylinder", radius=str(radius), length=str(length))
        root.insert(after + i, element)
        ET.SubElement(start, "object", name=name, xyz=f"{x:.4f} {y:.4f} 0")
    if radius != RADIUS:
        # a standoff for every object suits one radius only: each object then gets its own
        for push in root.iter("push_mobile"):
            push.attrib.pop("standoff", None)
    family = "" if radius == RADIUS and not regions else f"_r{radius:g}"
    root.set("name", f"{root.get('name')}{family}_k{count}_p{placement}")
    path = os.path.join(directory, f"{root.get('name')}.xml")
    ET.indent(tree)
    tree.write(path, xml_declaration=True, encoding="unicode")
    joints = len(start.find("robot").get("joints").split())
    return path, joints + 4 * len(root.findall("object"))


def report(count, dims, results, time_limit):
    solved = [r for r in results if r["solved"]]
    times = sorted(r["time_s"] if r["solved"] else math.inf for r in results)
    memory = [r["peak_memory_mb"] for r in results]
    total = max(sum(r["time_s"] for r in solved), 1e-12)
    share = lambda key: f"{100.0 * sum(r['stats'][key] for r in solved) / total:.0f}"
    mean = f"{statistics.mean(r['time_s'] for r in solved):.2f} s" if solved else "-"
    longest = f"{times[-1]:.2f} s" if times[-1] < math.inf else f"unsolved in {time_limit:g} s"
    median = f"{statistics.median(times):.2f} s" if statistics.median(times) < math.inf else "-"
    return (f"| {count} | {dims} | {len(solved)}/{len(results)} | {median} | {mean} | {longest} | "
            f"{statistics.median(memory):.0f} / {max(memory):.0f} MB | "
            f"{share('time_nearest_s')} / {share('time_sampling_s')} / {share('time_propagate_s')} / "
            f"{share('time_connect_s')} / {share('time_smoothing_s')} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scene", default="scenes/mobile_blocked.xml", help="base scene (default: %(default)s)")
    parser.add_argument("--counts", type=int, nargs="+", default=[0, 4, 8, 12, 16], help="numbers of extras K")
    parser.add_argument("--placements", type=int, default=2, help="placements per K (default: %(default)s)")
    parser.add_argument("--seeds", type=int, default=5, help="seeds per placement (default: %(default)s)")
    parser.add_argument("--time-limit", type=float, default=60.0, help="seconds per run (default: %(default)s)")
    parser.add_argument("--robot-radius", type=float, default=0.2, help="metres (default: %(default)s)")
    parser.add_argument("--radius", type=float, default=RADIUS, help="extras' radius, metres (default: %(default)s)")
    parser.add_argument("--length", type=float, default=LENGTH, help="extras' length, metres (default: %(default)s)")
    parser.add_argument("--region", type=float, nargs=4, action="append", default=[],
                        metavar=("XMIN", "YMIN", "XMAX", "YMAX"),
                        help="pack the extras into this floor rectangle (repeatable: in turn)")
    parser.add_argument("--binary", default="build/apps/ompl_mm_plan")
    parser.add_argument("--out", default="out/clutter", help="directory of the scenes (default: %(default)s)")
    parser.add_argument("--markdown", help="also write the table to this file")
    parser.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                        help="set a planner parameter in every run (repeatable), e.g. clear_probability=1")
    args = parser.parse_args()
    check_binary(args.binary)
    if min(args.counts) < 0 or args.placements < 1 or args.seeds < 1 or not args.time_limit > 0:
        sys.exit("counts must be at least 0, placements and seeds at least 1, the time limit positive")
    if not (args.radius > 0 and args.length > 0):
        sys.exit("the extras' radius and length must be positive")
    for region in args.region:
        if not (region[0] < region[2] and region[1] < region[3]):
            sys.exit(f"region {' '.join(f'{v:g}' for v in region)}: its minimum must lie below its maximum")
    os.makedirs(args.out, exist_ok=True)

    extras = f"r {args.radius:g} m" + "".join(f", in {' '.join(f'{v:g}' for v in r)}" for r in args.region)
    lines = [f"{os.path.basename(args.scene)} with K extra objects ({extras}), {args.placements} placements x "
             f"{args.seeds} seeds per K, {args.time_limit:g} s limit"
             + "".join(f", {setting}" for setting in args.param), "",
             "| K | state dims | solved | median | mean (solved) | max | peak memory median / max | "
             "time % nearest / sampling / propagate / connect / smoothing |",
             "|---|---|---|---|---|---|---|---|"]
    print("\n".join(lines), flush=True)
    options = ("--time-limit", str(args.time_limit), *(o for setting in args.param for o in ("--param", setting)))
    with tempfile.TemporaryDirectory() as workdir:
        for count in args.counts:
            results = []
            for placement in range(1, args.placements + 1):
                scene, dims = make_scene(args.scene, count, placement, args.robot_radius, args.out,
                                         args.radius, args.length, args.region)
                for seed in range(1, args.seeds + 1):
                    results.append(run_app(args.binary, scene, seed, workdir, options))
            lines.append(report(count, dims, results, args.time_limit))
            print(lines[-1], flush=True)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
