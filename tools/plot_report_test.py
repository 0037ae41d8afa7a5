#!/usr/bin/python3
"""Tests of tools/plot_report.py's Fig. 8 (run by CTest as plot_report_tool).

The figure is drawn from a small made-up curves.csv and its matplotlib objects are inspected: every
panel of one figure shows the same time range, and an algorithm whose curve does not change over a
sweep (a prior-blind one under a p_TP sweep) is drawn in a style no prior-aware line has.
"""

import os
import re
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

    def test_no_title_inside_the_figure(self):
        self.assertIsNone(self.fig._suptitle)


def summary_rows():
    """summary.csv rows of one scenario, two s2 values, two fleet sizes, three algorithms, with
    bootstrap intervals that are not mean ± std (so the test sees which one is drawn)."""
    out = []
    for s2 in (7, 9):
        for n in (4, 8):
            for k, a in enumerate(["lawnmower", "part-tsp", "my-planner"]):
                mean = 100.0 + 10 * k + n
                out.append({"scenario": "perfect", "sweep": "", "sweep_value": "", "s2": str(s2),
                            "uavs": str(n), "algorithm": a, "runs": "5", "incomplete": "0",
                            "T_c_count": "5", "T_c_mean": str(mean), "T_c_std": "20",
                            "T_c_ci_low": str(mean - 3), "T_c_ci_high": str(mean + 5),
                            "T_m_count": "5", "T_m_mean": str(mean + 50), "T_m_std": "20",
                            "T_m_ci_low": str(mean + 47), "T_m_ci_high": str(mean + 55)})
    return out


class PaperFigures(unittest.TestCase):
    """Every figure: 3.5 or 7 in wide, every text at least 7 pt, no title, each planner in its
    fixed colour-blind-safe colour, error bars the report's bootstrap intervals."""

    def setUp(self):
        import tempfile
        self.tmp = tempfile.TemporaryDirectory()
        self.figures = {}
        self.saved = plot_report.save

        def keep(fig, out_dir, stem, written):
            self.figures[stem] = fig
            self.saved(fig, self.tmp.name, stem, written)
        plot_report.save = keep
        self.algorithms = ["lawnmower", "part-tsp", "my-planner"]
        colour = plot_report.colours(self.algorithms)
        curves = []
        for s2 in (7, 9):
            for a, reached in zip(self.algorithms, (300, 200, 250)):
                curves += rows("perfect", "", "", a, reached, s2=s2)
        curves = plot_report.Curves(curves)
        self.written = []
        plot_report.fig6(summary_rows(), "perfect", self.algorithms, colour, 5, "unused",
                         self.written)
        plot_report.fig7(curves, "perfect", 4, self.algorithms, colour, 5, GRID_END, "unused",
                         self.written)
        plot_report.fig8(made_up_curves(), 5, 4, ["p_tp"], [], ["lawnmower", "part-tsp"],
                         plot_report.colours(["lawnmower", "part-tsp"]), 3, GRID_END, "unused",
                         self.written)

    def tearDown(self):
        plot_report.save = self.saved
        self.tmp.cleanup()
        import matplotlib.pyplot as plt
        plt.close("all")

    def test_widths_are_one_or_two_columns(self):
        self.assertEqual(sorted(self.figures), ["fig6_perfect", "fig7_perfect_n4",
                                                "fig8_s2-5_n4"])
        for stem, fig in self.figures.items():
            self.assertIn(fig.get_figwidth(), (plot_report.ONE_COLUMN, plot_report.TWO_COLUMN),
                          stem)
            self.assertLessEqual(fig.get_figheight(), 9.0, stem)

    def test_files_are_pdf_and_png_of_that_size(self):
        import matplotlib.image
        self.assertEqual(sorted(os.path.basename(p) for p in self.written),
                         sorted(f"{stem}.{ext}" for stem in self.figures for ext in ("pdf", "png")))
        for stem, fig in self.figures.items():
            png = matplotlib.image.imread(os.path.join(self.tmp.name, f"{stem}.png"))
            self.assertEqual(png.shape[1], round(fig.get_figwidth() * plot_report.DPI), stem)
            with open(os.path.join(self.tmp.name, f"{stem}.pdf"), "rb") as f:
                pdf = f.read()
            box = re.search(rb"/MediaBox \[ *0 0 ([0-9.]+) ([0-9.]+) *\]", pdf)
            self.assertAlmostEqual(float(box.group(1)), fig.get_figwidth() * 72, places=0)

    def test_every_text_is_at_least_7_pt(self):
        from matplotlib.text import Text
        for stem, fig in self.figures.items():
            texts = [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
            self.assertGreater(len(texts), 5, stem)
            for t in texts:
                self.assertGreaterEqual(t.get_fontsize(), plot_report.MIN_FONT,
                                        (stem, t.get_text()))

    def test_no_figure_title(self):
        for stem, fig in self.figures.items():
            self.assertIsNone(fig._suptitle, stem)

    def test_each_planner_has_its_fixed_colour_in_every_figure(self):
        expected = {"lawnmower": to_rgba(plot_report.PLANNER_COLOURS["lawnmower"]),
                    "part-tsp": to_rgba(plot_report.PLANNER_COLOURS["part-tsp"]),
                    "my-planner": to_rgba(plot_report.colours(self.algorithms)["my-planner"])}
        self.assertEqual(len(set(expected.values())), 3)
        for stem, fig in self.figures.items():
            legend = fig.legends[0]
            handles = getattr(legend, "legend_handles", None) or legend.legendHandles
            for handle, text in zip(handles, legend.get_texts()):
                self.assertEqual(to_rgba(handle.get_color()), expected[text.get_text()], stem)
        # A planner's colour is its own in any order or company; another algorithm's never
        # repeats a colour of its figure.
        again = plot_report.colours(["my-planner", "part-tsp", "part-tsp0", "coop-frontier"])
        self.assertEqual(to_rgba(again["part-tsp"]), expected["part-tsp"])
        self.assertEqual(again["part-tsp0"], plot_report.PLANNER_COLOURS["part-tsp0"])
        self.assertEqual(len(set(again.values())), 4)

    def test_palette_is_okabe_ito(self):
        self.assertEqual(set(plot_report.PLANNER_COLOURS.values()) - {"#000000"},
                         {"#E69F00", "#56B4E9", "#009E73", "#F0E442", "#0072B2", "#D55E00",
                          "#CC79A7"})
        self.assertIn(plot_report.planner_colour("anything"), plot_report.OKABE_ITO.values())

    def test_bar_error_bars_are_the_bootstrap_intervals(self):
        fig = self.figures["fig6_perfect"]
        ax = fig.axes[0]  # T_c, s2 = 7
        segments = [seg for coll in ax.collections for seg in coll.get_segments()]
        spans = sorted((round(s[0][1], 6), round(s[1][1], 6)) for s in segments)
        # lawnmower, n = 4: mean 104, interval [101, 109]; never mean ± std (84, 124).
        self.assertIn((101.0, 109.0), spans)
        self.assertNotIn((84.0, 124.0), spans)


if __name__ == "__main__":
    unittest.main()
