#!/usr/bin/python3
"""Tests of tools/beyond_targets.py (run by CTest as beyond_targets_tool).

A made-up runs.csv of one cell, five seeds: the best paper planner is picked by mean T_c, the
ratios are ratios of means, their bootstrap intervals hold the value, collapse to it when every
seed has the same ratio, and are the same on every call (a fixed stream); the counts line counts
a missed target.
"""

import contextlib
import io
import sys
import tempfile
import unittest
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))
import beyond_targets  # noqa: E402

SEEDS = [1, 2, 3, 4, 5]


def runs(ours, ours_failing, lawnmower=100.0):
    rows = []
    for i, seed in enumerate(SEEDS):
        for algorithm, t_c in [("lawnmower", lawnmower), ("part-tsp", 130.0),
                               ("part-tsp0", 140.0), ("coop-frontier", 120.0),
                               ("sweep-inspect", ours[i])]:
            rows.append({"scenario": "imperfect", "s2": 7, "uavs": 4, "seed": seed,
                         "algorithm": algorithm, "T_c": t_c, "T_m": t_c + 10, "complete": 1,
                         "bound_T_c": 20, "bound_T_m": 50})
        rows.append({"scenario": "imperfect-fail1", "s2": 7, "uavs": 4, "seed": seed,
                     "algorithm": "sweep-inspect", "T_c": ours_failing[i], "T_m": 0,
                     "complete": 1, "bound_T_c": 20, "bound_T_m": 50})
    return pd.DataFrame(rows)


class BeyondTargets(unittest.TestCase):
    def test_ratios_of_means_with_intervals_that_hold_them(self):
        ours = [70.0, 90.0, 60.0, 80.0, 75.0]
        failing = [100.0, 100.0, 70.0, 110.0, 90.0]
        (cell,) = beyond_targets.cells(runs(ours, failing))
        self.assertEqual(cell["best"], "lawnmower")
        self.assertAlmostEqual(cell["ratio"], 75.0 / 100.0)
        low, high = cell["ratio_ci"]
        self.assertLess(low, cell["ratio"])
        self.assertGreater(high, cell["ratio"])
        self.assertGreaterEqual(low, 0.6)  # no resample can leave the seeds' range
        self.assertLessEqual(high, 0.9)
        self.assertAlmostEqual(cell["fail_ratio"], 94.0 / 75.0)
        fail_low, fail_high = cell["fail_ratio_ci"]
        self.assertLess(fail_low, cell["fail_ratio"])
        self.assertGreater(fail_high, cell["fail_ratio"])
        self.assertEqual(cell["faster"], 5)
        self.assertAlmostEqual(cell["diff"], 25.0)
        (again,) = beyond_targets.cells(runs(ours, failing))
        self.assertEqual(again["ratio_ci"], cell["ratio_ci"])  # a fixed stream, not the clock
        self.assertEqual(again["fail_ratio_ci"], cell["fail_ratio_ci"])

    def test_equal_ratios_give_a_point_interval(self):
        (cell,) = beyond_targets.cells(runs([80.0] * 5, [96.0] * 5))
        self.assertEqual(cell["ratio_ci"], (0.8, 0.8))
        self.assertAlmostEqual(cell["fail_ratio_ci"][0], 1.2)
        self.assertAlmostEqual(cell["fail_ratio_ci"][1], 1.2)

    def test_the_table_is_the_same_on_every_call_and_counts_misses(self):
        frame = runs([70.0, 90.0, 60.0, 80.0, 95.0], [100.0, 130.0, 70.0, 110.0, 140.0])
        with tempfile.TemporaryDirectory() as scratch:
            path = Path(scratch) / "runs.csv"
            frame.to_csv(path, index=False)
            printed = []
            for _ in range(2):
                out = io.StringIO()
                with contextlib.redirect_stdout(out):
                    beyond_targets.main(path)
                printed.append(out.getvalue())
        self.assertEqual(printed[0], printed[1])
        # 79 / 100 meets 0.8; 110 / 79 = 1.39 misses 1.3; T_m 89 <= 110.
        self.assertIn("| imperfect | 7 | 4 | 100 (lawnmower) | 79 | 0.79 [", printed[0])
        self.assertIn("| 1.39 ✗ [", printed[0])
        self.assertIn("T_c <= 0.8x best paper planner: 1 of 1; T_m <= lawnmower: 1 of 1; "
                      "T_c one failure <= 1.3x: 0 of 1", printed[0])


if __name__ == "__main__":
    unittest.main()
