#!/usr/bin/python3
"""Issue 15's targets for Sweep-Inspect from a `beyond` run's runs.csv (docs/beyond.md, "Measured").

Per cell (scenario x s2 x n of the paper's four scenarios): the best of the four paper planners by
mean T_c, Sweep-Inspect's mean T_c and the ratio, the paired difference best - Sweep-Inspect
(mean and normal 95 % interval over the seeds) and on how many seeds Sweep-Inspect was faster,
the lawnmower's and Sweep-Inspect's mean T_m, completed missions without and with one failure,
and Sweep-Inspect's mean T_c with one failure over its failure-free mean. Prints a Markdown table
(x marks a missed target) and the counts.

    /usr/bin/python3 tools/beyond_targets.py results/beyond/runs.csv
"""
import math
import sys

import pandas as pd

PAPER = ["lawnmower", "part-tsp", "part-tsp0", "coop-frontier"]
OURS = "sweep-inspect"


def main(path):
    runs = pd.read_csv(path)
    runs = runs[runs["algorithm"].isin(PAPER + [OURS])]
    print("| scenario | s2 | n | best paper T_c | sweep-inspect T_c | ratio | best − ours [95 % CI] "
          "| ours faster | lawnmower T_m | sweep-inspect T_m | complete (no failure, one failure) "
          "| T_c one failure / none |")
    print("|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|")
    met = {"T_c": 0, "T_m": 0, "fail": 0}
    cells = 0
    for scenario in ["perfect", "imperfect", "inhomogeneous", "combined"]:
        for s2 in sorted(runs["s2"].unique()):
            for n in sorted(runs["uavs"].unique()):
                cell = runs[(runs.scenario == scenario) & (runs.s2 == s2) & (runs.uavs == n)]
                fail = runs[(runs.scenario == scenario + "-fail1") & (runs.s2 == s2) &
                            (runs.uavs == n) & (runs.algorithm == OURS)]
                if cell.empty:
                    continue
                cells += 1
                means = cell.groupby("algorithm")[["T_c", "T_m"]].mean()
                best = means.loc[PAPER, "T_c"].idxmin()
                ours = cell[cell.algorithm == OURS].set_index("seed")
                theirs = cell[cell.algorithm == best].set_index("seed")
                diff = (theirs["T_c"] - ours["T_c"]).dropna()
                half = 1.96 * diff.std(ddof=1) / math.sqrt(len(diff)) if len(diff) > 1 else 0.0
                ratio = means.loc[OURS, "T_c"] / means.loc[best, "T_c"]
                t_m_ok = means.loc[OURS, "T_m"] <= means.loc["lawnmower", "T_m"]
                fail_ratio = fail["T_c"].mean() / means.loc[OURS, "T_c"]
                met["T_c"] += ratio <= 0.8
                met["T_m"] += t_m_ok
                met["fail"] += fail_ratio <= 1.3
                complete = f"{int(ours['complete'].sum())}/{len(ours)}, " \
                           f"{int(fail['complete'].sum())}/{len(fail)}"
                print(f"| {scenario} | {s2} | {n} | {means.loc[best, 'T_c']:.0f} ({best}) "
                      f"| {means.loc[OURS, 'T_c']:.0f} | {ratio:.2f}{'' if ratio <= 0.8 else ' ✗'} "
                      f"| {diff.mean():.1f} [{diff.mean() - half:.1f}, {diff.mean() + half:.1f}] "
                      f"| {int((diff > 0).sum())}/{len(diff)} "
                      f"| {means.loc['lawnmower', 'T_m']:.0f} "
                      f"| {means.loc[OURS, 'T_m']:.0f}{'' if t_m_ok else ' ✗'} | {complete} "
                      f"| {fail_ratio:.2f}{'' if fail_ratio <= 1.3 else ' ✗'} |")
    print()
    print(f"T_c <= 0.8x best paper planner: {met['T_c']} of {cells}; T_m <= lawnmower: "
          f"{met['T_m']} of {cells}; T_c one failure <= 1.3x: {met['fail']} of {cells}")


if __name__ == "__main__":
    main(sys.argv[1])
