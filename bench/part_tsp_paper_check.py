#!/usr/bin/python3
"""Reproduces the paper's Part-TSP claims (Section V-B.1, Fig. 6 a1/a2) with the CLI.

Runs lawnmower, part-tsp0 and part-tsp on the same instances (paired seeds) of the perfect-information
scenario and prints T_c and T_m as mean ± sample standard deviation, the paired differences, and the
share of instances where Part-TSP's T_c is under half the lawnmower's.

Usage (from the repository root, after building the release preset):
  /usr/bin/python3 bench/part_tsp_paper_check.py --cli build/release/hullinspect \
      --uavs 4 --s2 7 11 --seeds 50 [--option skip-resolved=true ...] [--jobs 2]
"""

import argparse
import json
import statistics
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor


def run_one(cli, algorithm, uavs, s2, seed, scenario, options):
    cmd = [cli, "run", "--json", "--algorithm", algorithm, "--uavs", str(uavs), "--s2", str(s2),
           "--seed", str(seed), "--scenario", scenario]
    if algorithm != "lawnmower":
        for o in options:
            cmd += ["-O", o]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode not in (0, 3):
        sys.exit(f"{' '.join(cmd)} failed: {out.stderr.strip()}")
    r = json.loads(out.stdout)
    if not r["complete"]:
        sys.exit(f"incomplete mission: {' '.join(cmd)}")
    return r


def mean_std(values):
    return statistics.mean(values), statistics.stdev(values) if len(values) > 1 else 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default="build/release/hullinspect")
    ap.add_argument("--uavs", type=int, default=4)
    ap.add_argument("--s2", type=int, nargs="+", default=[7, 11])
    ap.add_argument("--seeds", type=int, default=50, help="seeds 1..N")
    ap.add_argument("--scenario", default="perfect")
    ap.add_argument("--option", action="append", default=[],
                    help="extra planner option KEY=VALUE for part-tsp and part-tsp0 (repeatable)")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    algorithms = ["lawnmower", "part-tsp0", "part-tsp"]
    seeds = range(1, args.seeds + 1)
    print(f"scenario {args.scenario}, n = {args.uavs}, seeds 1–{args.seeds}, options {args.option or 'none'}")
    print("| s2 | algorithm | T_c mean ± std | T_m mean ± std | plane changes | TSP solves |")
    print("|---|---|---|---|---|---|")
    summary = []
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for s2 in args.s2:
            results = {}
            for alg in algorithms:
                futures = [pool.submit(run_one, args.cli, alg, args.uavs, s2, seed, args.scenario,
                                       args.option) for seed in seeds]
                results[alg] = [f.result() for f in futures]
            for alg in algorithms:
                rs = results[alg]
                tc = mean_std([r["T_c"] for r in rs])
                tm = mean_std([r["T_m"] for r in rs])
                pc = statistics.mean(r["plane_changes"] for r in rs)
                ts = statistics.mean(r["tsp_solves"] for r in rs)
                print(f"| {s2} | {alg} | {tc[0]:.1f} ± {tc[1]:.1f} | {tm[0]:.1f} ± {tm[1]:.1f} | "
                      f"{pc:.1f} | {ts:.1f} |")
            lm, p0, pt = (results[a] for a in algorithms)
            tc_ratio = [p["T_c"] / l["T_c"] for p, l in zip(pt, lm)]
            tm_diff = [p["T_m"] - q["T_m"] for p, q in zip(pt, p0)]
            tm_rel = [(p["T_m"] - q["T_m"]) / q["T_m"] for p, q in zip(pt, p0)]
            half = sum(1 for r in tc_ratio if r < 0.5)
            summary.append(
                f"s2 = {s2}: T_c(part-tsp) / T_c(lawnmower) = {statistics.mean(tc_ratio):.2f} mean "
                f"(under 0.5 on {half} of {len(tc_ratio)}); T_m(part-tsp) − T_m(part-tsp0) = "
                f"{statistics.mean(tm_diff):+.1f} ± {statistics.stdev(tm_diff):.1f} steps "
                f"({100 * statistics.mean(tm_rel):+.1f} %), higher on "
                f"{sum(1 for d in tm_diff if d > 0)} of {len(tm_diff)}")
    print()
    for line in summary:
        print(line)


if __name__ == "__main__":
    main()
