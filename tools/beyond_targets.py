#!/usr/bin/python3
"""The targets for Sweep-Inspect from a `beyond` run's runs.csv (docs/sweep-inspect.md, "Measured results").

Per cell (scenario x s2 x n of the paper's four scenarios): the best of the four paper planners by
mean T_c, Sweep-Inspect's mean T_c and the ratio with a 95 % bootstrap interval, the paired
difference best - Sweep-Inspect (mean and normal 95 % interval over the seeds) and on how many
seeds Sweep-Inspect was faster, the lawnmower's and Sweep-Inspect's mean T_m, completed missions
without and with one failure, and Sweep-Inspect's mean T_c with one failure over its failure-free
mean, with a 95 % bootstrap interval. Prints a Markdown table (x marks a missed target: the ratio
itself, not its interval) and the counts.

The intervals resample the seeds (each seed keeps its missions together, so the pairing of the
planners, and of a seed's mission with and without a failure, is kept) 4 000 times from a fixed
stream: the same runs.csv always prints the same table. With the `beyond` preset's 10 seeds a
cell they are wide; bench/configs/beyond_tuning_seeds.yaml gives the targets' own cells (the
`paper` preset's, n = 4..8) on 100 tuning seeds, and with `--instances 50` on the preset's seeds.

    /usr/bin/python3 tools/beyond_targets.py results/beyond/runs.csv
"""
import math
import sys

import numpy as np
import pandas as pd

PAPER = ["lawnmower", "part-tsp", "part-tsp0", "coop-frontier"]
OURS = "sweep-inspect"
ORACLE = "oracle-part-tsp"  # a bound, not a planner: never the best paper planner
SCENARIOS = ["perfect", "imperfect", "inhomogeneous", "combined"]
RESAMPLES = 4000
FAILURE_TARGET = 1.3  # T_c with one of n UAVs failing <= 1.3x its failure-free T_c


def read_runs(path):
    """An experiment's runs.csv, read whole: its zone columns (`p_c`, `l_c`) mix numbers and
    `/`-separated lists, which pandas' chunked type guess warns about on large files."""
    return pd.read_csv(path, low_memory=False)


def ratio_interval(numerator, denominator, stream):
    """95 % percentile bootstrap interval of mean(numerator) / mean(denominator), seeds paired;
    `stream` (a list of ints) seeds the resampling, so that each interval has a stream of its
    own and adding one leaves the others as they were."""
    rng = np.random.default_rng([15] + stream)
    count = len(numerator)
    if count < 2:
        value = numerator.mean() / denominator.mean()
        return value, value
    picks = rng.integers(0, count, size=(RESAMPLES, count))
    ratios = numerator[picks].mean(axis=1) / denominator[picks].mean(axis=1)
    low, high = np.percentile(ratios, [2.5, 97.5])
    return low, high


def paired_ratio(numerator, denominator, stream_key):
    """mean(numerator) / mean(denominator) of two per-seed Series (indexed by seed), and its
    bootstrap interval over the seeds both have (ratio_interval, seeded by `stream_key`)."""
    paired = pd.concat([numerator, denominator], axis=1, keys=["a", "b"]).dropna()
    interval = ratio_interval(paired["a"].to_numpy(), paired["b"].to_numpy(), stream_key)
    return numerator.mean() / denominator.mean(), interval


def stream(scenario, s2, n, quantity):
    """The resampling stream of one interval: its cell and which ratio (0: T_c over the best
    paper planner's, 1: with one failure over none, 2: T_m over the lawnmower's), so that an
    interval is the same whichever cells a runs.csv holds and whichever tool prints it."""
    return [SCENARIOS.index(scenario), int(s2), int(n), quantity]


def cells(runs):
    """One dict per cell of the paper's scenarios found in runs, in the table's order: the table's
    values, and for tools/plot_beyond.py Sweep-Inspect's T_m over the lawnmower's (with its
    interval), the oracle's mean T_c (NaN without it) and the mean lower bounds."""
    runs = runs[runs["algorithm"].isin(PAPER + [OURS, ORACLE])]
    out = []
    for scenario in SCENARIOS:
        for s2 in sorted(runs["s2"].unique()):
            for n in sorted(runs["uavs"].unique()):
                cell = runs[(runs.scenario == scenario) & (runs.s2 == s2) & (runs.uavs == n)]
                fail = runs[(runs.scenario == scenario + "-fail1") & (runs.s2 == s2) &
                            (runs.uavs == n) & (runs.algorithm == OURS)]
                if cell.empty:
                    continue
                means = cell.groupby("algorithm")[["T_c", "T_m"]].mean()
                best = means.loc[PAPER, "T_c"].idxmin()
                ours = cell[cell.algorithm == OURS].set_index("seed")
                theirs = cell[cell.algorithm == best].set_index("seed")
                diff = (theirs["T_c"] - ours["T_c"]).dropna()
                half = 1.96 * diff.std(ddof=1) / math.sqrt(len(diff)) if len(diff) > 1 else 0.0
                ratio, ratio_ci = paired_ratio(ours["T_c"], theirs["T_c"],
                                               stream(scenario, s2, n, 0))
                t_m_ratio, t_m_ratio_ci = paired_ratio(
                    ours["T_m"], cell[cell.algorithm == "lawnmower"].set_index("seed")["T_m"],
                    stream(scenario, s2, n, 2))
                row = {
                    "scenario": scenario, "s2": s2, "n": n, "best": best,
                    "best_T_c": means.loc[best, "T_c"], "T_c": means.loc[OURS, "T_c"],
                    "ratio": ratio, "ratio_ci": ratio_ci,
                    "diff": diff.mean(), "diff_half": half,
                    "faster": int((diff > 0).sum()), "seeds": len(diff),
                    "lawnmower_T_m": means.loc["lawnmower", "T_m"], "T_m": means.loc[OURS, "T_m"],
                    "T_m_ratio": t_m_ratio, "T_m_ratio_ci": t_m_ratio_ci,
                    "complete": int(ours["complete"].sum()), "runs": len(ours),
                    "fail_complete": int(fail["complete"].sum()), "fail_runs": len(fail),
                    "fail_ratio": float("nan"), "fail_ratio_ci": (float("nan"), float("nan")),
                    "bound_T_c": cell["bound_T_c"].mean(), "bound_T_m": cell["bound_T_m"].mean(),
                    "oracle_T_c": (means.loc[ORACLE, "T_c"] if ORACLE in means.index
                                   else float("nan")),
                }
                if not fail.empty:
                    row["fail_ratio"], row["fail_ratio_ci"] = paired_ratio(
                        fail.set_index("seed")["T_c"], ours["T_c"], stream(scenario, s2, n, 1))
                out.append(row)
    return out


def main(path):
    rows = cells(read_runs(path))
    print("| scenario | s2 | n | best paper T_c | sweep-inspect T_c | ratio [95 % CI] "
          "| best − ours [95 % CI] | ours faster | lawnmower T_m | sweep-inspect T_m "
          "| complete (no failure, one failure) | T_c one failure / none [95 % CI] |")
    print("|---|---:|---:|---:|---:|---|---|---:|---:|---:|---:|---|")
    met = {"T_c": 0, "T_m": 0, "fail": 0}
    for r in rows:
        t_c_ok = r["ratio"] <= 0.8
        t_m_ok = r["T_m"] <= r["lawnmower_T_m"]
        fail_ok = r["fail_ratio"] <= FAILURE_TARGET
        met["T_c"] += t_c_ok
        met["T_m"] += t_m_ok
        met["fail"] += fail_ok
        low, high = r["ratio_ci"]
        fail_low, fail_high = r["fail_ratio_ci"]
        print(f"| {r['scenario']} | {r['s2']} | {r['n']} | {r['best_T_c']:.0f} ({r['best']}) "
              f"| {r['T_c']:.0f} | {r['ratio']:.2f}{'' if t_c_ok else ' ✗'} "
              f"[{low:.2f}, {high:.2f}] "
              f"| {r['diff']:.1f} [{r['diff'] - r['diff_half']:.1f}, "
              f"{r['diff'] + r['diff_half']:.1f}] "
              f"| {r['faster']}/{r['seeds']} | {r['lawnmower_T_m']:.0f} "
              f"| {r['T_m']:.0f}{'' if t_m_ok else ' ✗'} "
              f"| {r['complete']}/{r['runs']}, {r['fail_complete']}/{r['fail_runs']} "
              f"| {r['fail_ratio']:.2f}{'' if fail_ok else ' ✗'} "
              f"[{fail_low:.2f}, {fail_high:.2f}] |")
    print()
    print(f"T_c <= 0.8x best paper planner: {met['T_c']} of {len(rows)}; T_m <= lawnmower: "
          f"{met['T_m']} of {len(rows)}; T_c one failure <= 1.3x: {met['fail']} of {len(rows)}")


if __name__ == "__main__":
    main(sys.argv[1])
