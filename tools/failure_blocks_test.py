#!/usr/bin/python3
"""Tests of tools/failure_blocks.py (run by CTest as failure_blocks_tool).

A made-up runs.csv of one cell, four seeds, blocks of two: the ratios are ratios of means over
all seeds and over each block in seed order, other planners and cells without a failing twin
are left out, and a block above 1.3 is counted.
"""

import sys
import unittest
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))
import failure_blocks  # noqa: E402


def runs(plain, failing):
    rows = []
    for seed, (t, f) in enumerate(zip(plain, failing), start=10):
        rows.append({"scenario": "combined", "s2": 7, "uavs": 4, "seed": seed,
                     "algorithm": "sweep-inspect", "T_c": t})
        rows.append({"scenario": "combined-fail1", "s2": 7, "uavs": 4, "seed": seed,
                     "algorithm": "sweep-inspect", "T_c": f})
        rows.append({"scenario": "combined-fail1", "s2": 7, "uavs": 4, "seed": seed,
                     "algorithm": "lawnmower", "T_c": 10 * f})
        rows.append({"scenario": "perfect", "s2": 7, "uavs": 4, "seed": seed,
                     "algorithm": "sweep-inspect", "T_c": t})
    # Rows in reverse seed order, so that blocks in file order would not be blocks in seed order.
    return pd.DataFrame(rows[::-1])


class FailureBlocks(unittest.TestCase):
    def test_ratios_of_means_per_block_in_seed_order(self):
        # Seeds 10, 11 fail at 1.2x and 1.25x; seeds 12, 13 at 1.4x and 1.35x.
        (cell,) = failure_blocks.cells(runs([100, 200, 100, 200], [120, 250, 140, 270]), 2)
        self.assertEqual((cell["scenario"], cell["s2"], cell["uavs"]), ("combined", 7, 4))
        self.assertEqual(cell["seeds"], 4)
        self.assertAlmostEqual(cell["ratio"], 780 / 600)
        self.assertEqual(len(cell["blocks"]), 2)
        self.assertAlmostEqual(cell["blocks"][0], 370 / 300)
        self.assertAlmostEqual(cell["blocks"][1], 410 / 300)
        self.assertEqual(cell["above"], 1)

    def test_a_short_last_block_is_left_out(self):
        (cell,) = failure_blocks.cells(runs([100, 100, 100], [110, 110, 200]), 2)
        self.assertEqual(len(cell["blocks"]), 1)
        self.assertAlmostEqual(cell["blocks"][0], 1.1)
        self.assertEqual(cell["above"], 0)


if __name__ == "__main__":
    unittest.main()
