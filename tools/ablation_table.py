#!/usr/bin/python3
"""A planner's ablation as one Markdown table: a row per variant, a column per scenario.

Each cell is the mean T_c / T_m over the variant's complete missions of that scenario (all its
s2, n and seeds together), with the count of incomplete ones when there are any. Rows and
columns come in the order of their first run in runs.csv (the config's order), as
docs/sweep-inspect.md shows bench/configs/sweep_inspect_ablation.yaml.

    /usr/bin/python3 tools/ablation_table.py RUNS.csv
"""
import sys

import pandas as pd


def table(runs):
    """The Markdown lines of the table of `runs` (a DataFrame of runs.csv's columns)."""
    variants = list(dict.fromkeys(runs["algorithm"]))
    scenarios = list(dict.fromkeys(runs["scenario"]))
    lines = ["| variant | " + " | ".join(scenarios) + " |",
             "|---|" + "---:|" * len(scenarios)]
    for variant in variants:
        cells = []
        for scenario in scenarios:
            these = runs[(runs["algorithm"] == variant) & (runs["scenario"] == scenario)]
            complete = these[these["complete"] == 1]
            text = (f"{complete['T_c'].mean():.0f} / {complete['T_m'].mean():.0f}"
                    if len(complete) else "–")
            incomplete = len(these) - len(complete)
            if incomplete:
                text += f" ({incomplete} inc.)"
            cells.append(text)
        lines.append(f"| {variant} | " + " | ".join(cells) + " |")
    return lines


def main(argv):
    if len(argv) != 2:
        print("usage: ablation_table.py RUNS.csv", file=sys.stderr)
        return 2
    try:
        runs = pd.read_csv(argv[1], usecols=["algorithm", "scenario", "complete", "T_c", "T_m"])
    except (OSError, ValueError) as e:
        print(f"ablation_table.py: {argv[1]}: {e}", file=sys.stderr)
        return 2
    print("\n".join(table(runs)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
