#!/usr/bin/python3
"""Runs Part-TSP and Part-TSP0 with one TSP solver over the paper's evaluation grid through the CLI
and reports, per cell, incomplete missions, the mean planner time per mission and the longest single
TSP solve (wall time) with its mission.

Usage (from the repository root, after building the release preset):
  /usr/bin/python3 bench/part_tsp_solver_sweep.py --cli build/release/hullinspect --solver exact \
      --uavs 4 5 6 7 8 --s2 7 9 11 --seeds 20 [--jobs 2]
"""

import argparse
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

SCENARIOS = ["perfect", "imperfect", "inhomogeneous", "combined"]


def run_one(cli, algorithm, solver, scenario, s2, uavs, seed):
    cmd = [cli, "run", "--json", "--algorithm", algorithm, "--tsp-solver", solver, "--scenario",
           scenario, "--s2", str(s2), "--uavs", str(uavs), "--seed", str(seed)]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode not in (0, 3):
        sys.exit(f"{' '.join(cmd)} failed: {out.stderr.strip()}")
    return json.loads(out.stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default="build/release/hullinspect")
    ap.add_argument("--solver", default="exact")
    ap.add_argument("--uavs", type=int, nargs="+", default=[4, 5, 6, 7, 8])
    ap.add_argument("--s2", type=int, nargs="+", default=[7, 9, 11])
    ap.add_argument("--seeds", type=int, default=20, help="seeds 1..N")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    incomplete = 0
    missions = 0
    worst = (0.0, "")
    print("| scenario | s2 | n | algorithm | incomplete | mean planner ms | longest solve ms |")
    print("|---|---|---|---|---|---|---|")
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for scenario in SCENARIOS:
            for s2 in args.s2:
                for n in args.uavs:
                    for alg in ["part-tsp0", "part-tsp"]:
                        futures = [pool.submit(run_one, args.cli, alg, args.solver, scenario, s2, n, seed)
                                   for seed in range(1, args.seeds + 1)]
                        rs = [f.result() for f in futures]
                        bad = sum(1 for r in rs if not r["complete"])
                        longest = max(rs, key=lambda r: r["tsp_max_seconds"])
                        mean_ms = 1e3 * sum(r["planner_seconds"] for r in rs) / len(rs)
                        print(f"| {scenario} | {s2} | {n} | {alg} | {bad} | {mean_ms:.1f} | "
                              f"{1e3 * longest['tsp_max_seconds']:.1f} |", flush=True)
                        incomplete += bad
                        missions += len(rs)
                        if longest["tsp_max_seconds"] > worst[0]:
                            worst = (longest["tsp_max_seconds"],
                                     f"{scenario} s2={s2} n={n} {alg} seed={longest['seed']}")
    print(f"\n{missions} missions, {incomplete} incomplete; longest single solve "
          f"{1e3 * worst[0]:.0f} ms ({worst[1]})")


if __name__ == "__main__":
    main()
