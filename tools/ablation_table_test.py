#!/usr/bin/python3
"""Tests of tools/ablation_table.py (run by CTest as ablation_table_tool).

A made-up runs.csv of two variants on two scenarios: means over complete missions only, the
count of incomplete ones, rows and columns in the order of their first run.
"""

import sys
import unittest
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))
import ablation_table  # noqa: E402


def runs():
    rows = [
        ("base", "perfect", 1, 10, 20),
        ("base", "perfect", 1, 20, 40),
        ("off", "perfect", 1, 30, 50),
        ("off", "perfect", 0, None, None),
        ("base", "combined", 1, 7, 9),
        ("off", "combined", 0, None, None),
    ]
    return pd.DataFrame(rows, columns=["algorithm", "scenario", "complete", "T_c", "T_m"])


class AblationTable(unittest.TestCase):
    def test_means_of_complete_missions_and_incomplete_counts(self):
        lines = ablation_table.table(runs())
        self.assertEqual(lines[0], "| variant | perfect | combined |")
        self.assertEqual(lines[2], "| base | 15 / 30 | 7 / 9 |")
        self.assertEqual(lines[3], "| off | 30 / 50 (1 inc.) | – (1 inc.) |")

    def test_order_of_first_runs(self):
        reordered = runs().iloc[::-1].reset_index(drop=True)
        lines = ablation_table.table(reordered)
        self.assertEqual(lines[0], "| variant | combined | perfect |")
        self.assertTrue(lines[2].startswith("| off |"))


if __name__ == "__main__":
    unittest.main()
