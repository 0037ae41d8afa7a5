#!/usr/bin/python3
"""Checks the paper's Coop-Frontier claims (Section V-B.2 and Fig. 8 c2) with the CLI.

On paired instances (the same seeds for every algorithm and scenario; perfect and imperfect share
the ground truth, as do inhomogeneous and combined) it runs every available algorithm of
lawnmower, part-tsp, part-tsp0, coop-frontier and reports per scenario and s2:
  - T_c and T_m as mean ± sample standard deviation,
  - c̄ = the mean of c(t) over t = 0 … H (H = the largest T_c of any run with that s2, over every
    scenario and algorithm; c(t) = 100 after a mission ends), i.e. the normalised area under the
    c(t) curve: higher is better, it summarises the whole curve rather than its last point, and it
    is comparable across scenarios,
  - t50 / t90 = the first t at which the mean c(t) curve reaches 50 % / 90 %.
Then the degradation from perfect to imperfect information (paired per seed) and the ranking in the
combined scenario.

c(t) is read from each mission's trace (--trace to a temporary file).

Example (the measurement in docs/coop-frontier.md):
  /usr/bin/python3 tools/coop_frontier_paper_check.py --cli build/release/hullinspect \
      --uavs 4 --s2 7 11 --seeds 50
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

ALGORITHMS = ["lawnmower", "part-tsp", "part-tsp0", "coop-frontier"]


def available(cli, algorithm):
    out = subprocess.run([cli, "run", "--algorithm", algorithm, "--uavs", "1", "--time-limit", "1",
                          "--json"], capture_output=True, text=True)
    return out.returncode in (0, 3)


def run_one(cli, algorithm, scenario, uavs, s2, seed, options, tmpdir):
    trace = os.path.join(tmpdir, f"{algorithm}-{scenario}-{s2}-{seed}.json")
    cmd = [cli, "run", "--json", "--algorithm", algorithm, "--scenario", scenario, "--uavs",
           str(uavs), "--s2", str(s2), "--seed", str(seed), "--trace", trace]
    for o in options.get(algorithm, []):
        cmd += ["-O", o]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({out.returncode}): {out.stderr.strip()}")
    r = json.loads(out.stdout)
    with open(trace) as f:
        t = json.load(f)
    os.remove(trace)
    corroded = r["corroded_cells"]
    inspected = t["series"]["inspected"]
    r["c"] = [100.0 if corroded == 0 else 100.0 * v / corroded for v in inspected]
    return r


def c_at(series, t):
    return series[t] if t < len(series) else 100.0


def mean_std(values):
    return statistics.mean(values), (statistics.stdev(values) if len(values) > 1 else 0.0)


def first_reaching(curve, level):
    for t, v in enumerate(curve):
        if v >= level:
            return t
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default="build/release/hullinspect")
    ap.add_argument("--uavs", type=int, default=4)
    ap.add_argument("--s2", type=int, nargs="+", default=[7, 11])
    ap.add_argument("--seeds", type=int, default=50, help="seeds 1..N")
    ap.add_argument("--scenarios", nargs="+",
                    default=["perfect", "imperfect", "inhomogeneous", "combined"])
    ap.add_argument("--algorithms", nargs="+", default=ALGORITHMS)
    ap.add_argument("--coop-option", action="append", default=[],
                    help="extra coop-frontier option KEY=VALUE (repeatable)")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    algorithms = [a for a in args.algorithms if available(args.cli, a)]
    missing = [a for a in args.algorithms if a not in algorithms]
    options = {"coop-frontier": args.coop_option}
    seeds = list(range(1, args.seeds + 1))
    print(f"n = {args.uavs}, seeds 1–{args.seeds}, algorithms {', '.join(algorithms)}"
          + (f" (not in this build: {', '.join(missing)})" if missing else "")
          + (f", coop-frontier options {args.coop_option}" if args.coop_option else ""))

    results = {}
    with tempfile.TemporaryDirectory() as tmpdir, ThreadPoolExecutor(args.jobs) as pool:
        futures = {(a, sc, s2, seed): pool.submit(run_one, args.cli, a, sc, args.uavs, s2, seed,
                                                  options, tmpdir)
                   for sc in args.scenarios for s2 in args.s2 for a in algorithms for seed in seeds}
        for key, f in futures.items():
            results[key] = f.result()

    cbar = {}
    print("\n| scenario | s2 | algorithm | T_c mean ± std | T_m mean ± std | c̄ | t50 | t90 |")
    print("|---|---|---|---|---|---|---|---|")
    horizons = {s2: max(results[(a, sc, s2, s)]["T_c"] for a in algorithms for sc in args.scenarios
                        for s in seeds) for s2 in args.s2}
    for sc in args.scenarios:
        for s2 in args.s2:
            horizon = horizons[s2]
            for a in algorithms:
                rs = [results[(a, sc, s2, s)] for s in seeds]
                tc = mean_std([r["T_c"] for r in rs])
                tm = mean_std([r["T_m"] for r in rs])
                per_seed = [statistics.mean(c_at(r["c"], t) for t in range(horizon + 1)) for r in rs]
                for s, v in zip(seeds, per_seed):
                    cbar[(a, sc, s2, s)] = v
                curve = [statistics.mean(c_at(r["c"], t) for r in rs) for t in range(horizon + 1)]
                print(f"| {sc} | {s2} | {a} | {tc[0]:.1f} ± {tc[1]:.1f} | {tm[0]:.1f} ± {tm[1]:.1f} | "
                      f"{statistics.mean(per_seed):.1f} | {first_reaching(curve, 50)} | "
                      f"{first_reaching(curve, 90)} |")

    if "perfect" in args.scenarios and "imperfect" in args.scenarios:
        print("\nDegradation from perfect to imperfect information (paired per seed; mean):")
        print("| s2 | algorithm | T_c imperfect / perfect | T_c imperfect − perfect | "
              "c̄ perfect − imperfect |")
        print("|---|---|---|---|---|")
        for s2 in args.s2:
            for a in algorithms:
                tc = {sc: [results[(a, sc, s2, s)]["T_c"] for s in seeds]
                      for sc in ("perfect", "imperfect")}
                ratio = statistics.mean(i / p for i, p in zip(tc["imperfect"], tc["perfect"]))
                diff = statistics.mean(i - p for i, p in zip(tc["imperfect"], tc["perfect"]))
                loss = statistics.mean(cbar[(a, "perfect", s2, s)] - cbar[(a, "imperfect", s2, s)]
                                       for s in seeds)
                print(f"| {s2} | {a} | {ratio:.2f} | {diff:.1f} | {loss:.1f} |")
    if "combined" in args.scenarios:
        print("\nCombined scenario: ranking by mean c̄ (higher is better), wins = seeds on which the "
              "algorithm has the highest c̄:")
        for s2 in args.s2:
            ranking = sorted(algorithms, key=lambda a: -statistics.mean(
                cbar[(a, "combined", s2, s)] for s in seeds))
            wins = {a: 0 for a in algorithms}
            for s in seeds:
                best = max(algorithms, key=lambda a: cbar[(a, "combined", s2, s)])
                wins[best] += 1
            print(f"  s2 = {s2}: " + " > ".join(
                f"{a} ({statistics.mean(cbar[(a, 'combined', s2, s)] for s in seeds):.1f}, "
                f"{wins[a]} wins)" for a in ranking))
    return 0


if __name__ == "__main__":
    sys.exit(main())
