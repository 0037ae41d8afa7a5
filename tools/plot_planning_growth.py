#!/usr/bin/python3
"""Figure of bench/planning_growth_bench's growth table: planning time against hull area.

Usage: /usr/bin/python3 tools/plot_planning_growth.py GROWTH_CSV FIGURE.png

GROWTH_CSV is `planning_growth_bench --csv` output. Draws one panel per scenario and fleet size n:
planner CPU seconds against the hull area (×1 … ×8 the default hull's), log-log, one line per
planner with the slope of its least-squares line in the legend, and a dotted line of slope 1.
"""

import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    """{(scenario, n): {planner: [(area, seconds), ...]}} in file order."""
    panels = {}
    with open(path, encoding="utf-8", newline="") as f:
        for line, row in enumerate(csv.DictReader(f), start=2):
            try:
                key = (row["scenario"], int(row["n"]))
                point = (float(row["area"]), float(row["planner_seconds"]))
            except (KeyError, TypeError, ValueError) as e:
                raise ValueError(f"{path}:{line}: expected planner, scenario, n, area and "
                                 f"planner_seconds ({e})") from None
            if point[0] <= 0 or point[1] < 0 or not all(map(math.isfinite, point)):
                raise ValueError(f"{path}:{line}: expected a positive area and seconds >= 0")
            panels.setdefault(key, {}).setdefault(row["planner"], []).append(point)
    if not panels:
        raise ValueError(f"{path}: no rows")
    return panels


def slope(points):
    """The least-squares slope of log(seconds) against log(area)."""
    xs = [math.log(a) for a, _ in points]
    ys = [math.log(max(s, 1e-6)) for _, s in points]
    mx = sum(xs) / len(xs)
    my = sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        panels = load(argv[1])
    except (OSError, ValueError) as e:
        print(f"plot_planning_growth: {e}", file=sys.stderr)
        return 2
    keys = sorted(panels)
    fig, axes = plt.subplots(1, len(keys), figsize=(4.2 * len(keys), 4), squeeze=False)
    for ax, key in zip(axes[0], keys):
        for planner, points in panels[key].items():
            ax.plot([a for a, _ in points], [max(s, 1e-4) for _, s in points], marker="o",
                    label=f"{planner} ({slope(points):.2f})")
        ax.plot([1, 8], [0.01, 0.08], ":", color="grey", label="slope 1")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_title(f"{key[0]}, n = {key[1]}")
        ax.set_xlabel("hull area (× the default hull)")
        ax.set_ylabel("planner CPU seconds")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
