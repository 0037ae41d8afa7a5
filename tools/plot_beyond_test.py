#!/usr/bin/python3
"""Tests of tools/plot_beyond.py (run by CTest as plot_beyond_tool).

Made-up runs of two cells (imperfect, s2 = 7, n = 4 and 8; five seeds) are drawn, and the
matplotlib objects are inspected: Sweep-Inspect's points sit at the ratios of means (red where the
target is missed), the oracle and the lower bound at theirs, the target lines where the targets put
them; the failure figure leaves out a planner that did not complete its missions with a failure
and names it; the command writes both files.
"""

import sys
import tempfile
import unittest
from pathlib import Path

import matplotlib
import pandas as pd
from matplotlib.colors import to_rgba

sys.path.insert(0, str(Path(__file__).resolve().parent))
import beyond_targets  # noqa: E402
import plot_beyond  # noqa: E402

SEEDS = [1, 2, 3, 4, 5]
# Per fleet size: the paper planners' T_c, Sweep-Inspect's (ratio 0.7 with n = 4, 0.9 with n = 8 to
# the best, the lawnmower's 100 and 50), and with one failure.
T_C = {4: {"lawnmower": 100.0, "part-tsp": 120.0, "part-tsp0": 130.0, "coop-frontier": 110.0,
           "sweep-inspect": 70.0, "oracle-part-tsp": 40.0},
       8: {"lawnmower": 50.0, "part-tsp": 60.0, "part-tsp0": 65.0, "coop-frontier": 55.0,
           "sweep-inspect": 45.0, "oracle-part-tsp": 30.0}}
FAILING = {"sweep-inspect": 1.2, "coop-frontier": 1.1, "part-tsp": None}  # None: incomplete


def made_up_runs():
    rows = []
    for n, times in T_C.items():
        for seed in SEEDS:
            wobble = seed - 3  # the means stay those of T_C
            for algorithm, t_c in times.items():
                common = {"s2": 7, "uavs": n, "seed": seed, "algorithm": algorithm,
                          "bound_T_c": 10.0, "bound_T_m": 20.0}
                rows.append({**common, "scenario": "imperfect", "T_c": t_c + wobble,
                             "T_m": 2 * t_c + wobble, "complete": 1})
                if algorithm in FAILING:
                    factor = FAILING[algorithm]
                    rows.append({**common, "scenario": "imperfect-fail1",
                                 "T_c": (t_c + wobble) * factor if factor else float("nan"),
                                 "T_m": float("nan"), "complete": 1 if factor else 0})
    return pd.DataFrame(rows)


def points(ax):
    """(x, y, colour) of each errorbar's marker in `ax`."""
    out = []
    for container in ax.containers:
        line = container.lines[0]
        out.append((float(line.get_xdata()[0]), float(line.get_ydata()[0]),
                    to_rgba(line.get_color())))
    return sorted(out)


class PlotBeyond(unittest.TestCase):
    def setUp(self):
        self.runs = made_up_runs()

    def tearDown(self):
        matplotlib.pyplot.close("all")

    def test_targets_figure_places_ratios_bounds_and_targets(self):
        fig = plot_beyond.targets_figure(beyond_targets.cells(self.runs))
        top, bottom = fig.axes[0], fig.axes[1]
        self.assertEqual(top.get_title(), "imperfect")
        (x4, r4, c4), (x8, r8, c8) = points(top)
        self.assertAlmostEqual(r4, 0.7)
        self.assertAlmostEqual(r8, 0.9)
        self.assertEqual(c4, to_rgba(plot_beyond.MET))
        self.assertEqual(c8, to_rgba(plot_beyond.MISSED))
        marks = {(round(ln.get_xdata()[0]), round(float(ln.get_ydata()[0]), 6), ln.get_marker())
                 for ln in top.get_lines() if len(ln.get_xdata()) == 1}
        self.assertIn((0, 0.4, "^"), marks)   # the oracle: 40 / 100
        self.assertIn((1, 0.6, "^"), marks)   # 30 / 50
        self.assertIn((0, 0.1, "_"), marks)   # the bound: 10 / 100
        self.assertIn((1, 0.2, "_"), marks)
        levels = {round(float(ln.get_ydata()[0]), 6) for ln in top.get_lines()
                  if ln.get_linestyle() == "--"}
        self.assertEqual(levels, {0.8})
        (_, m4, _), (_, m8, _) = points(bottom)
        self.assertAlmostEqual(m4, 140.0 / 200.0)
        self.assertAlmostEqual(m8, 90.0 / 100.0)
        self.assertEqual([t.get_text() for t in top.get_xticklabels()], ["7/4", "7/8"])

    def test_failure_figure_leaves_out_incomplete_planners_and_names_them(self):
        fig = plot_beyond.failures_figure(self.runs)
        (ax,) = [a for a in fig.axes if a.get_title() == "imperfect"]
        ratios = sorted(round(y, 6) for _, y, _ in points(ax))
        self.assertEqual(ratios, [1.1, 1.1, 1.2, 1.2])  # coop-frontier and ours, n = 4 and 8
        colours = {c for _, _, c in points(ax)}
        self.assertNotIn(to_rgba(plot_beyond.COLOUR["part-tsp"]), colours)
        self.assertIn("part-tsp 0/10", fig._suptitle.get_text())
        levels = {round(float(ln.get_ydata()[0]), 6) for ln in ax.get_lines()
                  if ln.get_linestyle() == "--"}
        self.assertEqual(levels, {1.3})

    def test_failure_intervals_are_the_tables(self):
        wobbly = self.runs.copy()
        failing = (wobbly.scenario == "imperfect-fail1") & (wobbly.algorithm == "sweep-inspect")
        wobbly.loc[failing, "T_c"] += wobbly.loc[failing, "seed"] ** 2  # intervals of some width
        table = beyond_targets.cells(wobbly)
        drawn = plot_beyond.failure_cells(wobbly, "sweep-inspect")
        self.assertEqual([c["fail_ratio_ci"] for c in table], [c[4] for c in drawn])
        self.assertLess(table[0]["fail_ratio_ci"][0], table[0]["fail_ratio_ci"][1])

    def test_the_command_writes_both_figures(self):
        with tempfile.TemporaryDirectory() as scratch:
            path = Path(scratch) / "runs.csv"
            self.runs.to_csv(path, index=False)
            plot_beyond.main([str(path), "--out", scratch, "--format", "png"])
            for stem in ["beyond_targets", "beyond_failures"]:
                self.assertGreater((Path(scratch) / f"{stem}.png").stat().st_size, 10_000)


if __name__ == "__main__":
    unittest.main()
