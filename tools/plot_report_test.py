#!/usr/bin/python3
"""Tests of tools/plot_report.py's Fig. 8 (run by CTest as plot_report_tool).

The figure is drawn from a small made-up curves.csv and its matplotlib objects are inspected: every
panel of one figure shows the same time range, and an algorithm whose curve does not change over a
sweep (a prior-blind one under a p_TP sweep) is drawn in a style no prior-aware line has.
"""

import sys
import unittest
from pathlib import Path

import numpy as np
from matplotlib.colors import to_rgba

sys.path.insert(0, str(Path(__file__).resolve().parent))
import plot_report  # noqa: E402

GRID_END = 1000


def ramp(reached_at, steps=GRID_END):
    """c(t) rising linearly to 100 % at t = reached_at, then flat (one sample every 10 s)."""
    t = np.arange(0, steps + 1, 10)
    return t, np.minimum(100.0, 100.0 * t / reached_at)


def rows(scenario, sweep, value, algorithm, reached_at, s2=5, n=4):
    t, c = ramp(reached_at)
    return [{"scenario": scenario, "sweep": sweep, "sweep_value": value, "s2": str(s2),
             "uavs": str(n), "algorithm": algorithm, "t": str(int(ti)), "c_mean": repr(ci),
             "c_std": "1.0", "m_mean": repr(ci), "m_std": "1.0"} for ti, ci in zip(t, c)]


def made_up_curves():
    """A p_tp sweep of 3 values (lawnmower the same for all, part-tsp faster with a better sensor),
    an l_c sweep of 2 values (every algorithm changes: the truth changes), a plain scenario whose
    curves end much later than the sweeps' (so one x range for all panels is visible)."""
    r = []
    for i, value in enumerate(["0.6", "0.8", "1"]):
        r += rows(f"p_tp={value}", "p_tp", value, "lawnmower", 200)
        r += rows(f"p_tp={value}", "p_tp", value, "part-tsp", 120 - 20 * i)
    for i, value in enumerate(["2", "4"]):
        r += rows(f"l_c={value}", "l_c", value, "lawnmower", 210 + 30 * i)
        r += rows(f"l_c={value}", "l_c", value, "part-tsp", 150 + 30 * i)
    r += rows("paper", "", "", "lawnmower", 600)
    r += rows("paper", "", "", "part-tsp", 400)
    return plot_report.Curves(r)


class Fig8(unittest.TestCase):
    def setUp(self):
        self.figures = []
        self.saved = plot_report.save
        plot_report.save = lambda fig, out_dir, stem, written: self.figures.append((stem, fig))
        self.algorithms = ["lawnmower", "part-tsp"]
        self.colour = plot_report.colours(self.algorithms)
        plot_report.fig8(made_up_curves(), 5, 4, ["p_tp", "l_c"], ["paper"], self.algorithms,
                         self.colour, 3, GRID_END, "unused", [])
        self.assertEqual(len(self.figures), 1)
        stem, self.fig = self.figures[0]
        self.assertEqual(stem, "fig8_s2-5_n4")
        self.panels = {ax.get_title(): ax for ax in self.fig.axes if ax.get_visible()}

    def tearDown(self):
        plot_report.save = self.saved
        import matplotlib.pyplot as plt
        plt.close("all")

    def lines_of(self, title, algorithm):
        ax = self.panels[title]
        return [ln for ln in ax.get_lines()
                if to_rgba(ln.get_color()) == to_rgba(self.colour[algorithm])]

    def test_one_panel_per_sweep_and_per_plain_scenario(self):
        self.assertEqual(sorted(self.panels), ["scenario paper", "sweep of $l_C$",
                                               "sweep of $p_{TP}$"])

    def test_all_panels_share_one_x_range_that_shows_every_curve_reaching_100(self):
        limits = {title: ax.get_xlim() for title, ax in self.panels.items()}
        self.assertEqual(len(set(limits.values())), 1, limits)
        low, high = next(iter(limits.values()))
        self.assertEqual(low, 0)
        # The slowest curve (plain scenario, lawnmower) reaches 100 % at t = 600.
        self.assertGreaterEqual(high, 600)
        self.assertLess(high, GRID_END)

    def test_a_prior_blind_curve_the_same_for_every_swept_value_is_drawn_once_in_its_own_style(self):
        blind = self.lines_of("sweep of $p_{TP}$", "lawnmower")
        aware = self.lines_of("sweep of $p_{TP}$", "part-tsp")
        self.assertEqual(len(blind), 1)
        self.assertEqual(len(aware), 3)
        style = lambda ln: (ln.get_linewidth(), ln.get_alpha(), ln.get_linestyle())  # noqa: E731
        for ln in aware:
            self.assertNotEqual(style(ln), style(blind[0]))
            self.assertGreater(blind[0].get_linewidth(), 2 * ln.get_linewidth())
        self.assertLess(blind[0].get_alpha(), 1)
        # The prior-aware lines differ from each other by the swept value's line style.
        self.assertEqual(len({ln.get_linestyle() for ln in aware}), 3)
        legend = [t.get_text() for t in self.panels["sweep of $p_{TP}$"].get_legend().get_texts()]
        self.assertEqual(legend, ["0.6", "0.8", "1", "lawnmower: same for all"])

    def test_a_prior_blind_curve_that_changes_with_the_sweep_is_drawn_per_value(self):
        blind = self.lines_of("sweep of $l_C$", "lawnmower")
        aware = self.lines_of("sweep of $l_C$", "part-tsp")
        self.assertEqual(len(blind), 2)
        self.assertEqual([ln.get_linestyle() for ln in blind],
                         [ln.get_linestyle() for ln in aware])
        legend = [t.get_text() for t in self.panels["sweep of $l_C$"].get_legend().get_texts()]
        self.assertEqual(legend, ["2", "4"])

    def test_the_title_counts_instances(self):
        self.assertIn("3 instances)", self.fig._suptitle.get_text())
        plot_report.fig8(made_up_curves(), 5, 4, ["p_tp"], [], self.algorithms, self.colour, 1,
                         GRID_END, "unused", [])
        self.assertIn("1 instance)", self.figures[-1][1]._suptitle.get_text())


if __name__ == "__main__":
    unittest.main()
