"""Tutorial 03: a planner written in Python, benchmarked against Part-TSP.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/03_python_planner.py

NearestOpen descends to the close-up plane and moves each UAV towards the nearest cell that is
still unknown or uninspected (M = 0 or 2). It sees only what the UAVs know (view.map, view.prior,
view.uavs). Registered by name, it runs in run_mission and run_experiment like a built-in planner.
"""
import numpy as np

import hullinspect


class NearestOpen(hullinspect.Planner):
    """close-up sweep to the nearest open cell (tutorial 03)"""

    def decide(self, view):
        open_y, open_x = np.nonzero((view.map == 0) | (view.map == 2))
        actions = []
        for (x, y, z, in_transit, failed) in view.uavs:
            if in_transit or failed or len(open_x) == 0:
                actions.append("hover")
            elif z == 2:
                actions.append("change")
            else:
                i = int(np.argmin(np.abs(open_x - x) + np.abs(open_y - y)))
                tx, ty = int(open_x[i]), int(open_y[i])
                actions.append("E" if tx > x else "W" if tx < x else
                               "N" if ty > y else "S" if ty < y else "hover")
        return actions


hullinspect.register_planner("nearest-open", NearestOpen)

config = {
    "name": "tutorial-03",
    "hull": "rectangle",
    "grid": {"width": 60, "height": 16},
    "scenarios": ["perfect", "imperfect"],
    "uavs": [3],
    "algorithms": ["nearest-open", "part-tsp"],
    "instances": 3,
}
frame = hullinspect.to_dataframe(hullinspect.run_experiment(config, jobs=2))
assert (frame["complete"] == 1).all()
print(frame.groupby(["scenario", "algorithm"])[["T_c", "T_m", "moves"]].mean().to_string())
