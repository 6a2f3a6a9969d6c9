#!/usr/bin/env python3
"""Tests for benchmarks/ab_seeds.py: two run records count as the same result when they agree on
every value both write but the times and the peak memory, which differ between any two runs; the
new binary plans --new-scene when given; and push reversals counted from a path file's rows as the
library counts them. Standard library only."""
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "benchmarks"))
import ab_seeds  # noqa: E402
from run_records import push_reversals  # noqa: E402


def record(**changes):
    run = {"seed": 3, "solved": True, "time_s": 0.5, "peak_memory_mb": 30.0, "path_length_m": 15.2,
           "stats": {"iterations": 1200, "time_nearest_s": 0.1}}
    run.update(changes)
    return run


class SameValues(unittest.TestCase):
    def test_times_and_memory_do_not_count(self):
        other = record(time_s=0.9, peak_memory_mb=45.0, stats={"iterations": 1200, "time_nearest_s": 0.3})
        self.assertTrue(ab_seeds.same_values(record(), other))

    def test_results_count(self):
        self.assertFalse(ab_seeds.same_values(record(), record(path_length_m=15.3)))
        self.assertFalse(ab_seeds.same_values(record(), record(stats={"iterations": 1201, "time_nearest_s": 0.1})))

    def test_a_key_only_one_build_writes_does_not_count(self):
        self.assertTrue(ab_seeds.same_values(record(), record(clearings=0)))


class NewScene(unittest.TestCase):
    """A stand-in app writes the scene it was given into its record, so the records agree exactly
    when both sides planned the same scene."""

    def compare(self, *options):
        with tempfile.TemporaryDirectory() as directory:
            app = os.path.join(directory, "app")
            with open(app, "w") as f:
                f.write(textwrap.dedent(f"""\
                    #!{sys.executable}
                    import json, sys
                    args = sys.argv[1:]
                    record = {{"scene": args[0], "seed": int(args[args.index("--seed") + 1]),
                              "solved": True, "time_s": 0.1}}
                    json.dump(record, open(args[args.index("--json") + 1], "w"))
                    """))
            os.chmod(app, 0o755)
            script = os.path.join(HERE, "..", "..", "benchmarks", "ab_seeds.py")
            result = subprocess.run([sys.executable, script, app, app, "a.xml", "--seeds", "2", *options],
                                    capture_output=True, text=True, check=True)
        return result.stdout

    def test_without_it_both_plan_the_scene(self):
        self.assertIn("identical results (all values both write, but times): 2/2 seeds", self.compare())

    def test_with_it_the_new_binary_plans_it(self):
        self.assertIn("identical results (all values both write, but times): 0/2 seeds",
                      self.compare("--new-scene", "b.xml"))


def rows(*moves):
    """Path-file rows of two objects, a and b, from the origin: each move is (segment, object, dx, dy)."""
    at = {"a": [0.0, 0.0], "b": [5.0, 0.0]}
    def row(segment, obj):
        values = {"segment": segment, "object": obj}
        for name, (x, y) in at.items():
            values.update({f"{name}.x": x, f"{name}.y": y, f"{name}.z": 0.0, f"{name}.yaw": 0.0})
        return values
    result = [row("start", "-")]
    for segment, obj, dx, dy in moves:
        if obj in at:
            at[obj] = [at[obj][0] + dx, at[obj][1] + dy]
        result.append(row(segment, obj))
    return result


class PushReversals(unittest.TestCase):
    def test_a_push_back_against_the_one_before_is_one(self):
        self.assertEqual(push_reversals(rows(("push", "a", 1.0, 0.0), ("transit", "-", 0, 0),
                                             ("push", "a", -0.3, 0.2))), 1)

    def test_a_push_on_or_across_is_none(self):
        self.assertEqual(push_reversals(rows(("push", "a", 1.0, 0.0), ("push", "a", 0.5, 0.0),
                                             ("push", "a", 0.0, 1.0), ("push", "a", -0.0009, 1.0))), 0)

    def test_other_objects_pushes_between_do_not_hide_it(self):
        self.assertEqual(push_reversals(rows(("push", "a", 1.0, 0.0), ("push", "b", 1.0, 0.0),
                                             ("push", "a", -0.5, 0.0), ("push", "b", -2.0, 0.0))), 2)

    def test_a_carry_between_ends_the_comparison(self):
        self.assertEqual(push_reversals(rows(("push", "a", 1.0, 0.0), ("transfer", "a", 0.0, 1.0),
                                             ("push", "a", -0.5, 0.0))), 0)


if __name__ == "__main__":
    unittest.main()
