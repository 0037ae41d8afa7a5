"""Tutorial 05: a live session — the planner steering a fleet whose cameras you read.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/05_live_session.py

hullinspect.Session is the integration point for a real fleet (a ROS node would wrap it): instead
of simulating the cameras from a ground truth, you tell it what they saw, and it answers with the
next action of every UAV. Here the "cameras" are a function reading a hidden corrosion map, so the
tutorial runs anywhere; on a fleet, `camera_readings` would come from the image pipeline.

One step of the protocol (docs/python.md, "Live session"):
  1. fly the actions the previous step returned (none before the first step);
  2. collect (x, y, plane, corroded) for every hull cell in every sensing UAV's footprint —
     Session.expected_readings() lists exactly those cells;
  3. actions = session.step(readings, failed=[UAVs that stopped working]); [] means finished.
"""
import numpy as np

import hullinspect

hull = hullinspect.Hull.default()
# What we expect before take-off (C'), and the corrosion really there (hidden from the planner).
instance = hullinspect.make_instance(hull, seed=7, scenario="imperfect")
hidden_truth = instance.truth

# Coop-Frontier plans on the shared map every step, so when a UAV fails the others take over its
# frontiers (Part-TSP would leave the failed UAV's partition unfinished; docs/failures.md).
session = hullinspect.Session("coop-frontier", hull=hull, prior=instance.prior, uavs=4)


def camera_readings(cells):
    """Stand-in for the cameras: the hidden map at every cell the UAVs are looking at."""
    return [(x, y, plane, bool(hidden_truth[y][x] == 1)) for (x, y, plane) in cells]


failed = []
actions = session.step(camera_readings(session.expected_readings()))  # t = 0: take-off readings
while actions:
    # ... send `actions` to the UAVs and wait for them to arrive ...
    state = session.state
    if state.t == 200:
        failed = [3]  # UAV 3 reports a fault: it did not fly its last action and sees nothing more
    actions = session.step(camera_readings(session.expected_readings(failed)), failed=failed)
    failed = []
    if session.state.t % 100 == 0:
        m = session.state.map
        known = np.isin(m, (1, 3)).sum() / hull.cells * 100
        print(f"t = {session.state.t:4d} s   mapped {known:5.1f} %   UAVs {session.state.uavs}")

state = session.state
result = session.result()
print(f"finished at t = {state.t} s: complete = {state.complete}, "
      f"corroded cells inspected {int((state.map == 3).sum())} of {int((hidden_truth == 1).sum())}, "
      f"moves {result.counters['moves']}, UAVs failed {result.counters['failed_uavs']}")
assert state.complete and np.array_equal(state.map == 3, hidden_truth == 1)
