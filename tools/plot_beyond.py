#!/usr/bin/python3
"""Figures of Sweep-Inspect's targets from a `beyond` run's runs.csv (docs/sweep-inspect.md, "Measured results").

Usage: /usr/bin/python3 tools/plot_beyond.py RUNS_CSV --out DIR [--format png,pdf] [--dpi 110]

Writes, one column per scenario of the paper and one point per cell (s2, n):
  beyond_targets   top: T_c over the best paper planner's mean T_c — Sweep-Inspect (with its 95 %
                   bootstrap interval; red where it misses the 0.8 target), the oracle (sees the
                   truth) and the analytic lower bound; bottom: T_m over the lawnmower's, with
                   Sweep-Inspect's interval and the T_m bound
  beyond_failures  T_c with one UAV failing at a random step below 200 over the failure-free T_c,
                   with intervals, for every planner that completed all its missions with a
                   failure (the others are named in the title with their completed share)
The values and intervals are tools/beyond_targets.py's (the same seeded resampling).
Uses only Debian's python3-matplotlib, python3-numpy and python3-pandas.
"""

import argparse
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import beyond_targets  # noqa: E402
import plot_report  # noqa: E402

plt.rcParams.update({
    "font.size": 9,
    "axes.titlesize": 10,
    "legend.fontsize": 8,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "pdf.fonttype": 42,
})

T_C_TARGET = 0.8
FAILURE_TARGET = 1.3
# The report's colours (tools/plot_report.py's PLANNER_COLOURS, colour-blind safe), so that every
# planner looks the same in every figure; a missed target is grey, the targets black.
COLOUR = plot_report.PLANNER_COLOURS
MISSED = "#999999"
MET = COLOUR["sweep-inspect"]
FAILURE_PLANNERS = ["lawnmower", "part-tsp", "part-tsp0", "coop-frontier", "part-tsp-share",
                    beyond_targets.OURS]


def cell_label(row):
    return f"{row['s2']}/{row['n']}"


def errorbar(ax, x, value, interval, colour, **style):
    low, high = interval
    ax.errorbar([x], [value], yerr=[[value - low], [high - value]], color=colour, capsize=2,
                linestyle="none", **style)


def targets_figure(cells):
    """Two rows (T_c ratio, T_m ratio) by the scenarios found in `cells` (beyond_targets.cells)."""
    scenarios = [s for s in beyond_targets.SCENARIOS if any(c["scenario"] == s for c in cells)]
    fig, axes = plt.subplots(2, len(scenarios), figsize=(3.2 * len(scenarios), 5.6), sharey="row",
                             squeeze=False)
    for column, scenario in enumerate(scenarios):
        rows = [c for c in cells if c["scenario"] == scenario]
        top, bottom = axes[0][column], axes[1][column]
        for x, r in enumerate(rows):
            met = r["ratio"] <= T_C_TARGET
            errorbar(top, x, r["ratio"], r["ratio_ci"], MET if met else MISSED, marker="o",
                     markersize=5, label="sweep-inspect" if x == 0 else None)
            top.plot([x], [r["oracle_T_c"] / r["best_T_c"]], marker="^",
                     color=COLOUR["oracle-part-tsp"],
                     linestyle="none", label="oracle-part-tsp (sees the truth)" if x == 0 else None)
            top.plot([x], [r["bound_T_c"] / r["best_T_c"]], marker="_", markersize=12,
                     color="black", linestyle="none", label="lower bound" if x == 0 else None)
            met_m = r["T_m_ratio"] <= 1.0
            errorbar(bottom, x, r["T_m_ratio"], r["T_m_ratio_ci"], MET if met_m else MISSED,
                     marker="o", markersize=5)
            bottom.plot([x], [r["bound_T_m"] / r["lawnmower_T_m"]], marker="_", markersize=12,
                        color="black", linestyle="none")
        top.axhline(1.0, color="grey", linewidth=1)
        top.axhline(T_C_TARGET, color="black", linewidth=1, linestyle="--",
                    label=f"target {T_C_TARGET}" if column == 0 else None)
        bottom.axhline(1.0, color="black", linewidth=1, linestyle="--")
        top.set_title(scenario)
        for ax in (top, bottom):
            ax.set_xticks(range(len(rows)))
            ax.set_xticklabels([cell_label(r) for r in rows])
        bottom.set_xlabel("$s_2$ / n")
    # Shared rows: every interval shown whole, 0 and the reference line 1 included.
    top_high = max([1.0] + [c["ratio_ci"][1] for c in cells] + [c["ratio"] for c in cells])
    bottom_high = max([1.0] + [c["T_m_ratio_ci"][1] for c in cells])
    axes[0][0].set_ylim(0, 1.05 * top_high)
    axes[1][0].set_ylim(0, 1.05 * bottom_high)
    axes[0][0].set_ylabel("$T_c$ / best paper planner's $T_c$")
    axes[1][0].set_ylabel("$T_m$ / lawnmower's $T_m$")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), frameon=False,
               bbox_to_anchor=(0.5, -0.02))
    fig.suptitle("Sweep-Inspect against the best paper planner and the lawnmower "
                 "(means, 95 % bootstrap intervals; red: target missed)")
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    return fig


def failure_cells(runs, algorithm):
    """Per cell of the paper's scenarios: (scenario, s2, n, ratio, interval, completed, missions)
    of `algorithm`'s T_c with one failure over its failure-free T_c, seeds paired."""
    out = []
    for scenario in beyond_targets.SCENARIOS:
        for s2 in sorted(runs["s2"].unique()):
            for n in sorted(runs["uavs"].unique()):
                mine = runs[(runs.algorithm == algorithm) & (runs.s2 == s2) & (runs.uavs == n)]
                none = mine[mine.scenario == scenario].set_index("seed")
                fail = mine[mine.scenario == scenario + "-fail1"].set_index("seed")
                if none.empty or fail.empty:
                    continue
                completed = int(fail["complete"].sum())
                ratio, interval = float("nan"), (float("nan"), float("nan"))
                if completed == len(fail):  # else no ratio: some missions never ended
                    ratio, interval = beyond_targets.paired_ratio(
                        fail["T_c"], none["T_c"], beyond_targets.stream(scenario, s2, n, 1))
                out.append((scenario, s2, n, ratio, interval, completed, len(fail)))
    return out


def failures_figure(runs):
    algorithms = [a for a in FAILURE_PLANNERS if a in set(runs["algorithm"])]
    per = {a: failure_cells(runs, a) for a in algorithms}
    drawn = [a for a in algorithms if per[a] and all(c[5] == c[6] for c in per[a])]
    left_out = [f"{a} {sum(c[5] for c in per[a])}/{sum(c[6] for c in per[a])}"
                for a in algorithms if a not in drawn and per[a]]
    scenarios = [s for s in beyond_targets.SCENARIOS
                 if any(c[0] == s for a in drawn for c in per[a])]
    fig, axes = plt.subplots(1, max(1, len(scenarios)), figsize=(3.2 * max(1, len(scenarios)), 3.4),
                             sharey=True, squeeze=False)
    width = 0.8 / max(1, len(drawn))
    for column, scenario in enumerate(scenarios):
        ax = axes[0][column]
        labels = []
        for j, algorithm in enumerate(drawn):
            rows = [c for c in per[algorithm] if c[0] == scenario]
            labels = [f"{c[1]}/{c[2]}" for c in rows]
            for x, c in enumerate(rows):
                offset = x - 0.4 + width * (j + 0.5)
                errorbar(ax, offset, c[3], c[4], COLOUR[algorithm], marker="o", markersize=4,
                         label=algorithm if x == 0 and column == 0 else None)
        ax.axhline(1.0, color="grey", linewidth=1)
        ax.axhline(FAILURE_TARGET, color="black", linewidth=1, linestyle="--",
                   label=f"target {FAILURE_TARGET}" if column == 0 else None)
        ax.set_xticks(range(len(labels)))
        ax.set_xticklabels(labels)
        ax.set_title(scenario)
        ax.set_xlabel("$s_2$ / n")
    axes[0][0].set_ylabel("$T_c$ one failure / none")
    handles, names = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, names, loc="lower center", ncol=len(names), frameon=False,
               bbox_to_anchor=(0.5, -0.04))
    title = "One UAV failing at a random step below 200 (means, 95 % bootstrap intervals)"
    if left_out:
        title += "\nnot drawn, missions completed with a failure: " + ", ".join(left_out)
    fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    return fig


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs")
    parser.add_argument("--out", required=True)
    parser.add_argument("--format", default="png,pdf")
    parser.add_argument("--dpi", type=int, default=110)
    args = parser.parse_args(argv)
    runs = beyond_targets.read_runs(args.runs)
    os.makedirs(args.out, exist_ok=True)
    figures = {"beyond_targets": targets_figure(beyond_targets.cells(runs)),
               "beyond_failures": failures_figure(runs)}
    for stem, fig in figures.items():
        for ext in args.format.split(","):
            path = os.path.join(args.out, f"{stem}.{ext}")
            fig.savefig(path, dpi=args.dpi if ext == "png" else None, bbox_inches="tight")
            print(path)
        plt.close(fig)


if __name__ == "__main__":
    main()
