#!/usr/bin/env python3
"""Tests for benchmarks/blockers.py: in a corridor closed by objects one behind the other it counts
each, and an object leaving room beside it none; in MOBILE BLOCKED obj4 and one of obj1 and obj2 stand
between the robot and obj3, both sets reported, in the same order whatever the hash seed; --max
below the count exits 1; a missing file, a point against a box and a scene of another kind exit 2
naming the file. Standard library only.

Usage: test_blockers.py --scenes DIR --scratch DIR"""
import argparse
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
BLOCKERS = os.path.join(HERE, "..", "..", "benchmarks", "blockers.py")

ARGS = None

# A corridor 0.6 m wide along y = 0 between two boxes, the robot (r 0.2) at its west end; the
# objects (r 0.1) stand in the corridor where OBJECTS puts them.
CORRIDOR = """<?xml version="1.0"?>
<scene name="corridor" time_limit="10">
  <robot urdf="robots/mobile_disc.urdf" tool_link="body"/>
  <obstacle name="north"><origin xyz="0 1.15 0.5"/><box size="4 1.7 1"/></obstacle>
  <obstacle name="south"><origin xyz="0 -1.15 0.5"/><box size="4 1.7 1"/></obstacle>
  <surface name="floor" height="0" min="-2 -2" max="2 2"/>
{objects}
  <start>
    <robot joints="-1.7 0"/>
{starts}
  </start>
  <goal><robot joints="1.7 0" tolerance="0.01"/></goal>
</scene>
"""


def run(*args, env=None):
    return subprocess.run([sys.executable, BLOCKERS, *args], capture_output=True, text=True, env=env)


class Blockers(unittest.TestCase):
    def corridor(self, positions):
        """A corridor scene with objects named o1, o2, ... at the given x positions on y = 0."""
        names = [f"o{k + 1}" for k in range(len(positions))]
        objects = "\n".join(f'  <object name="{n}"><cylinder radius="0.1" length="0.3"/></object>' for n in names)
        starts = "\n".join(f'    <object name="{n}" xyz="{x} {y} 0"/>' for n, (x, y) in zip(names, positions))
        path = os.path.join(ARGS.scratch, f"corridor_{len(positions)}.xml")
        with open(path, "w") as f:
            f.write(CORRIDOR.format(objects=objects, starts=starts))
        return path

    def test_objects_one_behind_the_other_each_count(self):
        path = self.corridor([(-0.5, 0.0), (0.5, 0.0)])
        result = run(path, "--to", "1.7", "0")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.splitlines(), ["2 objects in the way, 1 smallest set:", "  o1 o2"])
        beyond_first = run(path, "--to", "0", "0")
        self.assertEqual(beyond_first.stdout.splitlines()[1], "  o1")

    def test_an_object_is_in_the_way_only_of_a_robot_too_wide_to_pass_it(self):
        # an object against the corridor's north side closes it to a robot 0.4 m wide, not to one
        # 0.1 m wide
        path = self.corridor([(0.0, 0.2)])
        self.assertEqual(run(path, "--to", "1.7", "0").stdout.splitlines()[0], "1 object in the way, 1 smallest set:")
        self.assertEqual(run(path, "--to", "1.7", "0", "--robot-radius", "0.05").stdout.splitlines(),
                         ["0 objects in the way, 1 smallest set:", "  (none)"])

    def test_mobile_blocked_has_two_smallest_sets_in_a_fixed_order(self):
        scene = os.path.join(ARGS.scenes, "mobile_blocked.xml")
        outputs = set()
        for seed in ("1", "2", "3"):
            result = run(scene, "--to", "-1.85", "-1.85", env=dict(os.environ, PYTHONHASHSEED=seed))
            self.assertEqual(result.returncode, 0, result.stderr)
            outputs.add(result.stdout)
        self.assertEqual(len(outputs), 1)
        self.assertEqual(outputs.pop().splitlines(),
                         ["2 objects in the way, 2 smallest sets:", "  obj1 obj4", "  obj2 obj4"])
        self.assertEqual(run(scene, "--to", "-1.85", "-1.85", "--max", "1").returncode, 1)

    def test_bad_input_exits_2_naming_the_file(self):
        missing = os.path.join(ARGS.scratch, "missing.xml")
        result = run(missing, "--to", "0", "0")
        self.assertEqual(result.returncode, 2)
        self.assertIn(missing, result.stderr)
        scene = os.path.join(ARGS.scenes, "mobile_blocked.xml")
        result = run(scene, "--to", "-1", "0")  # inside block1
        self.assertEqual(result.returncode, 2)
        self.assertIn("--to -1 0", result.stderr)
        result = run(os.path.join(ARGS.scenes, "kuka_table.xml"), "--to", "0", "0")
        self.assertEqual(result.returncode, 2)
        self.assertIn("kuka_table.xml", result.stderr)
        self.assertEqual(run(scene, "--to", "0", "0", "--grid", "0").returncode, 2)


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("--scenes", required=True)
    parser.add_argument("--scratch", required=True)
    ARGS, rest = parser.parse_known_args()
    os.makedirs(ARGS.scratch, exist_ok=True)
    unittest.main(argv=[sys.argv[0], *rest])


if __name__ == "__main__":
    main()
