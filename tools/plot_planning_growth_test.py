#!/usr/bin/python3
"""Tests of tools/plot_planning_growth.py (run by CTest as plot_planning_growth_tool).

The slopes of made-up times (linear and quadratic in the area) are 1 and 2; a bad row is refused
naming its line; the command draws one panel per scenario and fleet size and writes the figure.
"""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import plot_planning_growth  # noqa: E402

HEADER = "planner,scenario,n,area,hull_cells,planner_seconds,complete\n"


def rows(planner, scenario, n, power):
    return "".join(f"{planner},{scenario},{n},{a},{a * 6361},{0.01 * a ** power},1\n"
                   for a in (1, 2, 4, 8))


class PlotPlanningGrowthTest(unittest.TestCase):
    def write(self, directory, text):
        path = Path(directory) / "growth.csv"
        path.write_text(text, encoding="utf-8")
        return path

    def test_slopes_of_linear_and_quadratic_growth(self):
        with tempfile.TemporaryDirectory() as d:
            path = self.write(d, HEADER + rows("a", "perfect", 4, 1) + rows("b", "perfect", 4, 2))
            panels = plot_planning_growth.load(str(path))
        self.assertEqual(list(panels), [("perfect", 4)])
        self.assertAlmostEqual(plot_planning_growth.slope(panels[("perfect", 4)]["a"]), 1.0)
        self.assertAlmostEqual(plot_planning_growth.slope(panels[("perfect", 4)]["b"]), 2.0)

    def test_a_bad_row_is_refused_naming_its_line(self):
        with tempfile.TemporaryDirectory() as d:
            path = self.write(d, HEADER + rows("a", "perfect", 4, 1) + "a,perfect,4,x,1,1,1\n")
            with self.assertRaisesRegex(ValueError, r"growth\.csv:6: expected"):
                plot_planning_growth.load(str(path))

    def test_the_command_writes_one_panel_per_scenario_and_fleet_size(self):
        with tempfile.TemporaryDirectory() as d:
            path = self.write(d, HEADER + rows("a", "perfect", 4, 1) + rows("a", "perfect", 16, 1)
                              + rows("a", "imperfect", 4, 1))
            figure = Path(d) / "growth.png"
            self.assertEqual(plot_planning_growth.main(["x", str(path), str(figure)]), 0)
            self.assertGreater(figure.stat().st_size, 0)
            self.assertEqual(len(plot_planning_growth.load(str(path))), 3)
            self.assertEqual(plot_planning_growth.main(["x", str(Path(d) / "none.csv"),
                                                        str(figure)]), 2)


if __name__ == "__main__":
    unittest.main()
