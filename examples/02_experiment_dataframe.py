"""Tutorial 02: an experiment into a pandas DataFrame and a figure.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/02_experiment_dataframe.py [OUT.png]

Runs two planners on a few seeds (a dict config; a YAML path or a preset name works the same),
prints mean T_c and T_m per planner and fleet size, and plots T_m against the fleet size.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import hullinspect

config = {
    "name": "tutorial-02",
    "scenarios": ["perfect"],
    "uavs": [2, 4],
    "algorithms": ["lawnmower", "part-tsp"],
    "instances": 3,
}
rows = hullinspect.run_experiment(config, jobs=2)
frame = hullinspect.to_dataframe(rows)
table = frame.groupby(["algorithm", "uavs"])[["T_c", "T_m"]].mean()
print(table.to_string())

out = sys.argv[1] if len(sys.argv) > 1 else "tutorial-02.png"
fig, ax = plt.subplots(figsize=(5, 3.5))
for algorithm, group in frame.groupby("algorithm"):
    means = group.groupby("uavs")["T_m"].mean()
    ax.plot(means.index, means.values, marker="o", label=algorithm)
ax.set_xlabel("UAVs n")
ax.set_ylabel("mean T_m (s)")
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"wrote {out}")
