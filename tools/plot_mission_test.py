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


if __name__ == "__main__":
    unittest.main()
