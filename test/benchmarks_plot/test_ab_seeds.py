#!/usr/bin/env python3
"""Tests for benchmarks/ab_seeds.py: two run records count as the same result when they agree on
every value both write but the times and the peak memory, which differ between any two runs.
Standard library only."""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "benchmarks"))
import ab_seeds  # noqa: E402


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


if __name__ == "__main__":
    unittest.main()
