#!/usr/bin/env python3
"""The fewest objects a disc robot must move out of its way to get from its start to a point of the
floor, in a scene of MOBILE BLOCKED's kind (boxes and cylinders on one floor): a breadth-first
search over sets of objects taken away, each set's free space flooded on a grid from the robot's
start. Taken away is optimistic (a push must still find room for the object), so the count is a
lower bound on the pushes a plan needs before the robot gets there. Tells a scene family's hard
placements from planner trouble (docs/benchmarks.md, "a dense family of small objects").
Standard library only.

Example (where the robot must stand to push obj3 onto its goal in MOBILE BLOCKED):
  benchmarks/blockers.py scenes/mobile_blocked.xml --to -1.85 -1.85
prints "2 objects in the way, 2 smallest sets:" and the sets, "obj1 obj4" and "obj2 obj4".
Exit status: 0 found, 1 not within --max objects, 2 bad input.
"""
import argparse
import collections
import os
import sys
import xml.etree.ElementTree as ET

from clutter import Floor

# Clearance kept between the robot and anything, metres: no grazing contact counts as a way.
MARGIN = 0.01


class Grid:
    """The floor in cells: for each, whether a box or wall leaves no room for the robot's centre
    there, and which objects do."""

    def __init__(self, floor, names, robot_radius, step):
        self.step = step
        self.low = floor.low
        self.size = [int(round((floor.high[k] - floor.low[k]) / step)) + 1 for k in range(2)]
        reach = robot_radius + MARGIN
        self.wall = set()
        self.blockers = {}
        for i in range(self.size[0]):
            for j in range(self.size[1]):
                x, y = self.point((i, j))
                if floor.fixed_gap(x, y, reach) < 0.0:
                    self.wall.add((i, j))
                    continue
                inside = [name for name, (ox, oy, r) in zip(names, floor.discs)
                          if (x - ox) ** 2 + (y - oy) ** 2 < (reach + r) ** 2]
                if inside:
                    self.blockers[(i, j)] = inside

    def point(self, cell):
        return self.low[0] + cell[0] * self.step, self.low[1] + cell[1] * self.step

    def cell(self, x, y):
        return round((x - self.low[0]) / self.step), round((y - self.low[1]) / self.step)

    def flood(self, start, removed):
        """Cells the robot's centre reaches from start with the objects of removed taken away, and
        the objects met at the border."""
        seen, queue, met = {start}, collections.deque([start]), set()
        while queue:
            i, j = queue.popleft()
            for cell in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
                if cell in seen or cell in self.wall or not (0 <= cell[0] < self.size[0] and 0 <= cell[1] < self.size[1]):
                    continue
                left = [name for name in self.blockers.get(cell, ()) if name not in removed]
                if left:
                    met.update(left)
                    continue
                seen.add(cell)
                queue.append(cell)
        return seen, met


def fewest_in_way(grid, start, goal, most):
    """Every smallest set of objects (at most `most`) whose removal lets the robot from start reach
    goal, each a sorted list, in sorted order; empty when there is none."""
    layer, tried = [frozenset()], {frozenset()}
    for _ in range(most + 1):
        following, found = [], []
        for removed in layer:
            reached, met = grid.flood(start, removed)
            if goal in reached:
                found.append(sorted(removed))
            for name in sorted(met):
                wider = removed | {name}
                if wider not in tried:
                    tried.add(wider)
                    following.append(wider)
        if found:
            return sorted(found)
        layer = following
    return []


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--to", nargs=2, type=float, required=True, metavar=("X", "Y"),
                        help="where the robot's centre must get, metres")
    parser.add_argument("--robot-radius", type=float, default=0.2, help="metres (default: 0.2)")
    parser.add_argument("--grid", type=float, default=0.03, help="cell size, metres (default: 0.03)")
    parser.add_argument("--max", type=int, default=6, help="most objects to take away (default: 6)")
    args = parser.parse_args()
    if not 0.001 <= args.grid <= 1.0 or args.robot_radius <= 0.0 or args.max < 0:
        parser.error("--grid must be in [0.001, 1], --robot-radius positive, --max not negative")
    try:
        root = ET.parse(args.scene).getroot()
    except (OSError, ET.ParseError) as error:
        print(f"{args.scene}: {error}", file=sys.stderr)
        return 2
    try:
        floor = Floor(root, args.robot_radius)
    except (AttributeError, TypeError, ValueError, SystemExit) as error:
        print(f"{args.scene}: not a scene of boxes and cylinders on one floor ({error})", file=sys.stderr)
        return 2
    names = [obj.get("name") for obj in root.find("start").findall("object")]
    grid = Grid(floor, names, args.robot_radius, args.grid)
    start = grid.cell(*floor.clear[0])
    goal = grid.cell(*args.to)
    for what, cell in (("the robot's start", start), (f"--to {args.to[0]:g} {args.to[1]:g}", goal)):
        if not (0 <= cell[0] < grid.size[0] and 0 <= cell[1] < grid.size[1]) or cell in grid.wall:
            print(f"{args.scene}: {what} leaves the robot no room (off the floor or against a box)", file=sys.stderr)
            return 2
    ways = fewest_in_way(grid, start, goal, args.max)
    if not ways:
        print(f"more than {args.max} in the way (or no way at all)")
        return 1
    plural = lambda count, word: f"{count} {word}{'' if count == 1 else 's'}"
    print(f"{plural(len(ways[0]), 'object')} in the way, {plural(len(ways), 'smallest set')}:")
    for removed in ways:
        print("  " + (" ".join(removed) if removed else "(none)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
