#!/usr/bin/python3
"""Figure and table of bench/mission_scale_bench's "Growth" missions (docs/results.md, "Missions at scale").

Usage: /usr/bin/python3 tools/plot_mission_scale.py BENCH_JSON FIGURE.png

BENCH_JSON is `mission_scale_bench --benchmark_format=json` output. Draws one panel per planner:
CPU seconds per mission against the hull area (×1 … ×8 the default hull's), one line per fleet
size n; prints the same numbers as a Markdown table (CPU s, and T_m in steps) on stdout.
"""

import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ALGORITHMS = ["lawnmower", "part-tsp", "part-tsp0", "coop-frontier"]
AREA_LABELS = ["×1", "×2", "×4", "×8"]


def load(path):
    """{(hull index, n, algorithm): (cpu seconds, T_m, complete, area)} of the Growth runs."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        parts = b["name"].split("/")
        if parts[0] != "Growth" or b.get("run_type") == "aggregate":
            continue
        hull, n, a = int(parts[1]), int(parts[2]), int(parts[3])
        scale = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[b["time_unit"]]
        rows[(hull, n, ALGORITHMS[a])] = (b["cpu_time"] * scale, int(b["T_m"]),
                                          int(b["complete"]), b["area"])
    return rows


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    rows = load(argv[1])
    hulls = sorted({h for h, _, _ in rows})
    fleets = sorted({n for _, n, _ in rows})
    fig, axes = plt.subplots(1, len(ALGORITHMS), figsize=(14, 3.6), sharey=True)
    for ax, algorithm in zip(axes, ALGORITHMS):
        for n in fleets:
            xs = [rows[(h, n, algorithm)][3] for h in hulls if (h, n, algorithm) in rows]
            ys = [rows[(h, n, algorithm)][0] for h in hulls if (h, n, algorithm) in rows]
            ax.plot(xs, ys, marker="o", label=f"n = {n}")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xticks([1, 2, 4, 8])
        ax.set_xticklabels(AREA_LABELS)
        ax.set_title(algorithm)
        ax.set_xlabel("hull area (default hull = ×1)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("CPU s per mission")
    axes[-1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)

    print("| planner | n | " + " | ".join(f"{a} CPU s (T_m)" for a in AREA_LABELS) + " |")
    print("|---|---|" + "---|" * len(AREA_LABELS))
    for algorithm in ALGORITHMS:
        for n in fleets:
            cells = []
            for h in hulls:
                cpu, t_m, complete, _ = rows.get((h, n, algorithm), (float("nan"), 0, 0, 0))
                cells.append(f"{cpu:.3g} ({t_m if complete else 'incomplete'})")
            print(f"| {algorithm} | {n} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
