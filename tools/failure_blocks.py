#!/usr/bin/python3
"""Sweep-Inspect's failure ratio over all seeds and over consecutive blocks of seeds.

Per cell (scenario x s2 x n) that has a `*-fail1` twin in runs.csv: Sweep-Inspect's mean T_c
with one failure over its failure-free mean, on all the seeds and on each block of BLOCK seeds
in seed order (default 50, the `paper` preset's count), and how many blocks exceed the target's
1.3x. It shows whether a cell that misses the target on the preset's 50 seeds misses it in the
population or by the draw (docs/sweep-inspect.md, "Limits"; bench/configs/failure_population.yaml).

    /usr/bin/python3 tools/failure_blocks.py RUNS.csv [BLOCK]
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from beyond_targets import FAILURE_TARGET, OURS, read_runs  # noqa: E402

SUFFIX = "-fail1"


def ratio(runs):
    failing = runs["scenario"].str.endswith(SUFFIX)
    return runs[failing]["T_c"].mean() / runs[~failing]["T_c"].mean()


def cells(runs, block=50):
    """One dict per cell: scenario, s2, uavs, seeds, ratio, blocks (ratios), above (count)."""
    runs = runs[runs["algorithm"] == OURS].copy()
    runs["base"] = runs["scenario"].str.removesuffix(SUFFIX)
    out = []
    for (base, s2, uavs), cell in runs.groupby(["base", "s2", "uavs"], sort=True):
        if not cell["scenario"].str.endswith(SUFFIX).any() or (cell["scenario"] == base).sum() == 0:
            continue
        seeds = sorted(cell["seed"].unique())
        blocks = [ratio(cell[cell["seed"].isin(seeds[i:i + block])])
                  for i in range(0, len(seeds) - block + 1, block)]
        out.append({"scenario": base, "s2": int(s2), "uavs": int(uavs), "seeds": len(seeds),
                    "ratio": ratio(cell), "blocks": blocks,
                    "above": sum(r > FAILURE_TARGET for r in blocks)})
    return out


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit("usage: failure_blocks.py RUNS.csv [BLOCK]")
    block = int(argv[2]) if len(argv) == 3 else 50
    print(f"| scenario | s2 | n | seeds | T_c one failure / none | blocks of {block} seeds | "
          f"blocks > {FAILURE_TARGET} |")
    print("|---|---:|---:|---:|---:|---|---:|")
    for c in cells(read_runs(argv[1]), block):
        blocks = ", ".join(f"{r:.3f}" for r in c["blocks"])
        print(f"| {c['scenario']} | {c['s2']} | {c['uavs']} | {c['seeds']} | {c['ratio']:.3f} | "
              f"{blocks} | {c['above']} of {len(c['blocks'])} |")


if __name__ == "__main__":
    main(sys.argv)
