#!/usr/bin/python3
"""Side by side: the public Python DARP reference (alice-st/DARP) against hullinspect's partitioners
on the same grid and the same start cells (docs/partition.md, "Against the Python reference").

The reference is not part of this repository and is never copied into it: pass the path of a
checkout of it. The script skips cleanly (exit status 0, one line saying why) when the path is
missing or the reference cannot be imported (it needs numpy, numba and OpenCV: Debian
python3-numba and python3-opencv). Its `Visualization` module (pygame, scikit-learn) is only used
for drawing and is replaced by an empty module.

Usage (from the repository root, after the release build):
  /usr/bin/python3 tools/darp_reference_compare.py --reference /path/to/DARP \\
      --uavs 4 8 --repetitions 3 [--hull data/hulls/default.txt] [--max-iter 80000]

For each n: the reference's wall time (numba compiled beforehand on a small grid, so compilation is
not counted), iterations and success; hullinspect's `partition --json` seconds for darp and
transfer on the same starts (the model's default start cells for n UAVs, taken from hullinspect);
medians over the repetitions and the ratios reference / ours.
"""

import argparse
import contextlib
import io
import json
import os
import statistics
import subprocess
import sys
import time
import types

CLI = os.path.join("build", "release", "hullinspect")


def skip(reason: str) -> None:
    print(f"darp_reference_compare: skipped: {reason}")
    sys.exit(0)


def load_reference(path: str):
    if not os.path.isfile(os.path.join(path, "darp.py")):
        skip(f"no darp.py in {path!r} (pass a checkout of alice-st/DARP with --reference)")
    sys.modules.setdefault("Visualization", types.ModuleType("Visualization"))
    sys.modules["Visualization"].darp_area_visualization = None
    sys.path.insert(0, path)
    try:
        import darp  # noqa: E402  (the reference)
    except ImportError as e:
        skip(f"the reference cannot be imported: {e}")
    return darp


def read_mask(path: str) -> list[str]:
    """Rows of a hullinspect text mask, top row (largest y) first; 'X' is hull."""
    with open(path, encoding="utf-8") as f:
        return [line.rstrip("\n") for line in f if line.strip() and not line.startswith(";")]


def run_reference(darp, rows: list[str], starts, max_iter: int):
    """Runs the reference on the grid (row = y from the top, column = x); returns
    (seconds, iterations, success)."""
    height, width = len(rows), len(rows[0])
    obstacles = [r * width + c for r in range(height) for c in range(width) if rows[r][c] != "X"]
    positions = [(height - 1 - y) * width + x for x, y in starts]
    with contextlib.redirect_stdout(io.StringIO()):
        solver = darp.DARP(height, width, False, positions, [], obstacles, False, MaxIter=max_iter)
        t0 = time.perf_counter()
        success, iterations = solver.divideRegions()
        seconds = time.perf_counter() - t0
    return seconds, iterations, bool(success)


def run_ours(hull: str, n: int, partitioner: str):
    out = subprocess.run(
        [CLI, "partition", "--uavs", str(n), "--hull", hull, "--partitioner", partitioner, "--json"],
        capture_output=True, text=True, check=False)
    if out.returncode not in (0, 3):
        sys.exit(f"darp_reference_compare: hullinspect failed: {out.stderr.strip()}")
    report = json.loads(out.stdout)
    return report


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reference", required=True, help="path of an alice-st/DARP checkout")
    ap.add_argument("--hull", default="data/hulls/default.txt", help="hullinspect text mask")
    ap.add_argument("--uavs", type=int, nargs="+", default=[4, 8])
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--max-iter", type=int, default=80000, help="the reference's MaxIter")
    args = ap.parse_args()
    darp = load_reference(args.reference)
    if not os.access(CLI, os.X_OK):
        skip(f"{CLI} not built (run the release build first)")
    rows = read_mask(args.hull)
    # Compile the reference's numba functions on a small grid first.
    run_reference(darp, ["XXXXXX"] * 4, [(0, 0), (5, 3)], 100)

    print("| n | reference s (median) | iterations | success | darp s | transfer s "
          "| reference / darp | reference / transfer |")
    print("|---|---|---|---|---|---|---|---|")
    for n in args.uavs:
        ours = {p: [run_ours(args.hull, n, p) for _ in range(args.repetitions)]
                for p in ("darp", "transfer")}
        starts = [tuple(r["start"]) for r in ours["darp"][0]["regions"]]
        ref = [run_reference(darp, rows, starts, args.max_iter) for _ in range(args.repetitions)]
        ref_s = statistics.median(r[0] for r in ref)
        darp_s = statistics.median(r["seconds"] for r in ours["darp"])
        transfer_s = statistics.median(r["seconds"] for r in ours["transfer"])
        print(f"| {n} | {ref_s:.3f} | {statistics.median(r[1] for r in ref):g} "
              f"| {sum(r[2] for r in ref)}/{len(ref)} | {darp_s:.4f} | {transfer_s:.4f} "
              f"| {ref_s / darp_s:.0f}× | {ref_s / transfer_s:.0f}× |", flush=True)


if __name__ == "__main__":
    main()
