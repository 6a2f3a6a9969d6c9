#!/usr/bin/env python3
"""Tests for benchmarks/clutter.py: the generated scenes keep MOBILE BLOCKED's objects, goal and
start, add K cylinders that touch nothing and stay clear of the robot's start and goal and of the
goal object's target, half of them blocking (a gap narrower than the robot to their nearest
neighbour); a dense family packs smaller cylinders into given rectangles, touching nothing; the same
placement number gives the same scene; ompl_mm_plan accepts every scene; the report has a row per K
with the peak memory. Standard library only.

Usage: test_clutter.py --mm-plan BINARY --scenes DIR --scratch DIR"""
import argparse
import math
import os
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
BENCHMARKS = os.path.join(HERE, "..", "..", "benchmarks")
sys.path.insert(0, BENCHMARKS)
import clutter  # noqa: E402

ARGS = None


def text(path):
    with open(path) as f:
        return f.read()


def starts(path):
    """name -> (x, y) of the objects' start positions in a scene file."""
    root = ET.parse(path).getroot()
    return {o.get("name"): tuple(float(v) for v in o.get("xyz").split()[:2])
            for o in root.find("start").findall("object")}


class ClutterScenes(unittest.TestCase):
    def setUp(self):
        self.base = os.path.join(ARGS.scenes, "mobile_blocked.xml")
        os.makedirs(ARGS.scratch, exist_ok=True)

    def test_extras_are_placed_by_the_rules(self):
        path, dims = clutter.make_scene(self.base, 8, 3, 0.2, ARGS.scratch)
        self.assertEqual(dims, 2 + 4 * 12)
        positions = starts(path)
        self.assertEqual(len(positions), 12)
        base = starts(self.base)
        for name, xy in base.items():
            self.assertEqual(positions[name], xy)
        goal = lambda scene: [(e.tag, e.attrib) for e in ET.parse(scene).getroot().find("goal")]
        self.assertEqual(goal(path), goal(self.base))
        floor = clutter.Floor(ET.parse(self.base).getroot(), 0.2)
        blocking = 0
        for i in range(1, 9):
            x, y = positions[f"extra{i}"]
            others = {n: p for n, p in positions.items() if n != f"extra{i}"}
            floor.discs = [(ox, oy, clutter.RADIUS) for ox, oy in others.values()]
            gap = floor.gap(x, y, clutter.RADIUS)
            self.assertGreaterEqual(gap, clutter.MIN_GAP - 1e-3, f"extra{i} touches something")
            for cx, cy in floor.clear:
                self.assertGreaterEqual(math.hypot(x - cx, y - cy), clutter.KEEP_CLEAR + clutter.RADIUS - 1e-3)
            # placed blocking or not when it was placed; later extras can only narrow its gaps
            if i % 2 == 1:
                self.assertLess(gap, 0.4, f"extra{i} should block")
                blocking += 1
        self.assertEqual(blocking, 4)

    def test_dense_family_packs_small_extras_into_the_regions(self):
        regions = [(-2.5, 0.5, -0.5, 2.5), (0.5, -2.5, 2.5, -0.5)]
        path, dims = clutter.make_scene(self.base, 32, 1, 0.2, ARGS.scratch, 0.08, 0.3, regions)
        self.assertEqual(dims, 2 + 4 * 36)
        root = ET.parse(path).getroot()
        self.assertIn("_r0.08_k32_p1", root.get("name"))
        # pushed from their own standoffs, not from the base scene's (made for its larger objects)
        self.assertIsNone(root.find("primitives/push_mobile").get("standoff"))
        positions = starts(path)
        floor = clutter.Floor(ET.parse(self.base).getroot(), 0.2)
        for i in range(1, 33):
            name = f"extra{i}"
            cylinder = root.find(f"object[@name='{name}']/cylinder")
            self.assertEqual((cylinder.get("radius"), cylinder.get("length")), ("0.08", "0.3"))
            x, y = positions[name]
            xmin, ymin, xmax, ymax = regions[(i - 1) % 2]
            self.assertTrue(xmin + 0.08 - 1e-3 <= x <= xmax - 0.08 + 1e-3 and
                            ymin + 0.08 - 1e-3 <= y <= ymax - 0.08 + 1e-3, f"{name} at {x}, {y}")
            floor.discs = [(ox, oy, 0.08 if n.startswith("extra") else 0.2)
                           for n, (ox, oy) in positions.items() if n != name]
            self.assertGreaterEqual(floor.gap(x, y, 0.08), clutter.MIN_GAP - 1e-3, f"{name} touches something")

    def test_a_region_too_small_is_reported(self):
        run = subprocess.run([sys.executable, os.path.join(BENCHMARKS, "clutter.py"), "--scene", self.base,
                              "--counts", "40", "--placements", "1", "--seeds", "1", "--binary", ARGS.mm_plan,
                              "--out", ARGS.scratch, "--radius", "0.1", "--region", "-2.5", "2", "-2", "2.5"],
                             capture_output=True, text=True, timeout=600)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("no free spot in region -2.5 2 -2 2.5", run.stderr)

    def test_same_placement_same_scene(self):
        a, _ = clutter.make_scene(self.base, 6, 2, 0.2, ARGS.scratch)
        first = text(a)
        b, _ = clutter.make_scene(self.base, 6, 2, 0.2, ARGS.scratch)
        self.assertEqual(text(b), first)
        c, _ = clutter.make_scene(self.base, 6, 5, 0.2, ARGS.scratch)
        self.assertNotEqual(starts(c), starts(a))

    def test_the_planner_accepts_the_scenes(self):
        for count in (0, 16):
            path, _ = clutter.make_scene(self.base, count, 1, 0.2, ARGS.scratch)
            run = subprocess.run([ARGS.mm_plan, path, "--time-limit", "0.2"], capture_output=True, text=True,
                                 timeout=120)
            self.assertIn(run.returncode, (0, 1), run.stderr)

    def test_report_has_a_row_per_count_with_memory(self):
        out = os.path.join(ARGS.scratch, "clutter.md")
        run = subprocess.run([sys.executable, os.path.join(BENCHMARKS, "clutter.py"), "--scene", self.base,
                              "--counts", "0", "2", "--placements", "1", "--seeds", "1", "--time-limit", "0.5",
                              "--binary", ARGS.mm_plan, "--out", ARGS.scratch, "--markdown", out,
                              "--param", "clear_probability=1"],
                             capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("clear_probability=1", text(out).splitlines()[0])
        rows = [line for line in text(out).splitlines() if line.startswith(("| 0 |", "| 2 |"))]
        self.assertEqual(len(rows), 2)
        self.assertRegex(rows[1], r"\| 2 \| 26 \| [01]/1 \|.* MB \|")

    def test_unknown_planner_parameter_is_rejected(self):
        run = subprocess.run([sys.executable, os.path.join(BENCHMARKS, "clutter.py"), "--scene", self.base,
                              "--counts", "0", "--placements", "1", "--seeds", "1", "--binary", ARGS.mm_plan,
                              "--out", ARGS.scratch, "--param", "no_such_parameter=1"],
                             capture_output=True, text=True, timeout=60)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("no_such_parameter", run.stderr)

    def test_bad_arguments_are_rejected(self):
        run = subprocess.run([sys.executable, os.path.join(BENCHMARKS, "clutter.py"), "--counts", "-1",
                              "--binary", ARGS.mm_plan], capture_output=True, text=True, timeout=60)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("counts must be at least 0", run.stderr)
        run = subprocess.run([sys.executable, os.path.join(BENCHMARKS, "clutter.py"), "--region", "1", "0", "0", "1",
                              "--binary", ARGS.mm_plan], capture_output=True, text=True, timeout=60)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("its minimum must lie below its maximum", run.stderr)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--mm-plan", required=True)
    parser.add_argument("--scenes", required=True)
    parser.add_argument("--scratch", required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0], *rest])
