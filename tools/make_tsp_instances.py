#!/usr/bin/python3
"""Writes the segment-TSP benchmark instances of bench/tsp_instances/ (see docs/tsp.md).

Mission-like: the 230 x 30 grid is cut into horizontal strips of s rows (s = 5 for even instance
numbers, 7 for odd ones: the paper's s1 and s2); segments lie on strip centre rows
y_j = min(j*s + (s-1)//2, 29), span 1-60 cells, and never touch another segment of their strip (as
maximal runs of targeted columns never do). The UAV is on a uniformly random cell. Segments are
listed strip by strip, left to right, each from its left end.

Deterministic: instance i of size g uses random.Random(1000 * g + i).
Usage: /usr/bin/python3 tools/make_tsp_instances.py [OUT_DIR]   (default bench/tsp_instances)
"""
import json
import pathlib
import random
import sys

WIDTH, HEIGHT = 230, 30
SIZES = (5, 10, 20, 40, 80)
INSTANCES = 20
MAX_CELLS = 60


def instance(g, index):
    rng = random.Random(1000 * g + index)
    s = 5 if index % 2 == 0 else 7
    rows = sorted({min(j * s + (s - 1) // 2, HEIGHT - 1) for j in range((HEIGHT + s - 1) // s)})
    taken = {y: [] for y in rows}  # y -> [(x1, x2)]
    segments = []
    longest = MAX_CELLS
    failures = 0
    while len(segments) < g:
        y = rows[rng.randrange(len(rows))]
        cells = rng.randint(1, longest)
        x1 = rng.randrange(0, WIDTH - cells + 1)
        x2 = x1 + cells - 1
        if any(x1 <= b + 1 and a - 1 <= x2 for a, b in taken[y]):
            failures += 1
            if failures % 1000 == 0 and longest > 1:
                longest -= 1  # a crowded grid: allow shorter segments only
            continue
        taken[y].append((x1, x2))
        segments.append(((x1, y), (x2, y)))
    segments.sort(key=lambda s: (s[0][1], s[0][0]))
    start = (rng.randrange(WIDTH), rng.randrange(HEIGHT))
    return {"start": list(start), "segments": [[list(a), list(b)] for a, b in segments]}


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "bench/tsp_instances")
    out.mkdir(parents=True, exist_ok=True)
    for g in SIZES:
        for i in range(INSTANCES):
            text = json.dumps(instance(g, i), separators=(",", ":"))
            (out / f"g{g:03d}_{i:02d}.json").write_text(text + "\n")


if __name__ == "__main__":
    main()
