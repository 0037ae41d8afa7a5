#!/usr/bin/python3
"""Tests of tools/plot_mission.py's drawing (run by CTest as plot_mission_tool)."""

import sys
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import plot_mission  # noqa: E402


def track(states):
    """states: (x, y, z, transit_left) per step → the [t, 5] array plot_mission reads."""
    return np.array([[x, y, z, tr, 1] for x, y, z, tr in states], dtype=np.int32)


class FlightRuns(unittest.TestCase):
    def test_a_z2_flight_is_one_polyline_not_one_segment_per_cell(self):
        t = track([(x, 3, 2, 0) for x in range(10)])
        runs = list(plot_mission.flight_runs(t))
        self.assertEqual(len(runs), 1)
        points, close = runs[0]
        self.assertFalse(close)
        self.assertEqual(len(points), 10)

    def test_runs_split_where_the_plane_changes(self):
        # 3 moves at z = 2, a one-step descent (u_z = 1), 2 moves at z = 1, then hovering.
        states = [(0, 0, 2, 0), (1, 0, 2, 0), (2, 0, 2, 0), (3, 0, 2, 0), (3, 0, 1, 0),
                  (4, 0, 1, 0), (5, 0, 1, 0), (5, 0, 1, 0)]
        runs = [(p[:, 0].tolist(), close) for p, close in plot_mission.flight_runs(track(states))]
        self.assertEqual(runs, [([0, 1, 2, 3, 3], False), ([3, 4, 5, 5], True)])
        self.assertEqual(list(plot_mission.plane_changes(track(states))), [(3, True)])

    def test_a_transit_of_several_steps_is_one_plane_change(self):
        states = [(0, 0, 1, 0), (0, 0, 1, 2), (0, 0, 1, 1), (0, 0, 2, 0), (1, 0, 2, 0)]
        self.assertEqual(list(plot_mission.plane_changes(track(states))), [(0, False)])

    def test_a_uav_that_never_moves_draws_no_line(self):
        self.assertEqual(list(plot_mission.flight_runs(track([(2, 2, 2, 0)] * 5))), [])


def small_trace(no_fly=None, unreachable=None):
    """A 12 × 6 mission of one UAV hovering at (1, 1) for 3 steps, with optional zone rows."""
    w, h = 12, 6
    trace = {
        "format": "hullinspect-trace", "version": 2, "parameters": {"algorithm": "lawnmower"},
        "grid": {"width": w, "height": h, "cell_size_m": 0.5}, "footprint": [1, 3],
        "initial_map": ["0" * w] * h, "partition": None,
        "frames": [{"t": t, "u": [1, 1, 2, 0, 1], "c": []} for t in range(3)],
        "result": {"T_c": None, "T_m": None},
    }
    if no_fly is not None:
        trace["no_fly"] = no_fly
    if unreachable is not None:
        trace["unreachable"] = unreachable
    return trace


# A wall of no-fly positions (columns 5-6, rows 2-5) and, behind it, hull cells no footprint
# reaches ('x', columns 5-6 rows 4-5) and cells only z = 2 sees ('d', row 3).
NO_FLY = ["............", "............", ".....##.....", ".....##.....", ".....##.....",
          ".....##....."]
UNREACHABLE = ["............", "............", "............", ".....dd.....", ".....xx.....",
               ".....xx....."]


def cells_of(collection):
    """The cells the rectangles of a PatchCollection cover."""
    cells = set()
    for path in collection.get_paths():
        (x0, y0), (x1, y1) = path.get_extents().get_points()
        for x in range(round(x0 + 0.5), round(x1 + 0.5)):
            for y in range(round(y0 + 0.5), round(y1 + 0.5)):
                cells.add((x, y))
    return cells


def pixels_at(fig, ax, x, y):
    """The RGB pixels inside cell (x, y) of the rendered figure (a margin left out)."""
    fig.canvas.draw()
    image = np.asarray(fig.canvas.buffer_rgba())[:, :, :3]
    (px0, py0), (px1, py1) = ax.transData.transform([(x - 0.4, y - 0.4), (x + 0.4, y + 0.4)])
    rows = image.shape[0]
    return image[int(rows - py1):int(rows - py0), int(px0):int(px1)].reshape(-1, 3)


def has_colour(pixels, hex_colour, tolerance=40):
    rgb = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)])
    return bool(np.any(np.abs(pixels.astype(int) - rgb).sum(axis=1) < tolerance))


class NoFlyZones(unittest.TestCase):
    def test_runs_merge_the_cells_of_a_row(self):
        self.assertEqual(plot_mission.cell_runs([(5, 2), (6, 2), (5, 3), (8, 3), (7, 3)]),
                         [(5, 2, 2), (5, 3, 1), (7, 3, 2)])

    def test_no_fly_positions_and_unreachable_cells_are_drawn_hatched(self):
        fig = plot_mission.plot(small_trace(NO_FLY, UNREACHABLE), 2, None, True)
        ax = fig.axes[0]
        by_gid = {c.get_gid(): c for c in ax.collections if c.get_gid()}
        wall = {(x, y) for y in range(2, 6) for x in (5, 6)}
        self.assertEqual(cells_of(by_gid["no-fly"]), wall)
        self.assertEqual(by_gid["no-fly"].get_hatch(), plot_mission.NO_FLY_HATCH)
        self.assertEqual(cells_of(by_gid["unreachable-x"]), {(5, 4), (6, 4), (5, 5), (6, 5)})
        self.assertEqual(cells_of(by_gid["unreachable-d"]), {(5, 3), (6, 3)})
        self.assertEqual(len(by_gid["no-fly-outline"].get_segments()), 12)  # the wall's outline
        # Rendered: the hatch colour inside a no-fly cell, not in a free cell.
        self.assertTrue(has_colour(pixels_at(fig, ax, 5, 2), plot_mission.NO_FLY))
        self.assertFalse(has_colour(pixels_at(fig, ax, 9, 2), plot_mission.NO_FLY))
        self.assertFalse(has_colour(pixels_at(fig, ax, 9, 2), plot_mission.UNREACHABLE))
        labels = [t.get_text() for t in fig.axes[1].get_legend().get_texts()]
        self.assertIn("no-fly position (8)", labels)
        self.assertIn("unreachable: no footprint (4)", labels)
        self.assertIn("unreachable at z = 1: seen from z = 2 only (2)", labels)

    def test_a_mission_without_no_fly_zones_draws_none(self):
        fig = plot_mission.plot(small_trace(), 2, None, True)
        gids = {c.get_gid() for c in fig.axes[0].collections}
        self.assertFalse(gids & {"no-fly", "no-fly-outline", "unreachable-x", "unreachable-d"})
        labels = [t.get_text() for t in fig.axes[1].get_legend().get_texts()]
        self.assertFalse([label for label in labels if "no-fly" in label or "unreachable" in label])


if __name__ == "__main__":
    unittest.main()
