#!/usr/bin/python3
"""Sweeps Coop-Frontier's alpha and beta over a tuning set of seeds and reports mean T_c and T_m.

Drives `hullinspect run --json` (one process per mission, --jobs at a time). The tuning seeds must be
disjoint from the evaluation seeds (the paper's comparisons use seeds 1-50; the default tuning set is
1001-1030).

Example (the measurement in docs/coop-frontier.md):
  /usr/bin/python3 tools/tune_coop_frontier.py --cli build/release/hullinspect \
      --alpha 0,0.25,0.5,0.75,1 --beta 0,0.25,0.5,1,2,4 --seeds 1001-1030
"""

import argparse
import concurrent.futures
import itertools
import json
import statistics
import subprocess
import sys


def parse_list(text, kind):
    return [kind(v) for v in text.split(",") if v]


def parse_seeds(text):
    seeds = []
    for part in text.split(","):
        if "-" in part:
            lo, hi = part.split("-")
            seeds.extend(range(int(lo), int(hi) + 1))
        elif part:
            seeds.append(int(part))
    return seeds


def run_one(cli, scenario, s2, n, seed, alpha, beta, extra):
    cmd = [cli, "run", "--algorithm", "coop-frontier", "--scenario", scenario, "--s2", str(s2),
           "--uavs", str(n), "--seed", str(seed), "--alpha", str(alpha), "--beta", str(beta),
           "--json"] + extra
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({out.returncode}): {out.stderr.strip()}")
    r = json.loads(out.stdout)
    return r["T_c"], r["T_m"]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default="build/release/hullinspect")
    ap.add_argument("--alpha", default="0,0.25,0.5,0.75,1")
    ap.add_argument("--beta", default="0,0.25,0.5,1,2,4")
    ap.add_argument("--seeds", default="1001-1030")
    ap.add_argument("--scenarios", default="perfect,imperfect,inhomogeneous,combined")
    ap.add_argument("--s2", default="7,11")
    ap.add_argument("--uavs", default="4,8")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("-O", "--option", action="append", default=[],
                    help="extra planner option KEY=VALUE passed to every run")
    args = ap.parse_args()

    alphas = parse_list(args.alpha, float)
    betas = parse_list(args.beta, float)
    seeds = parse_seeds(args.seeds)
    scenarios = parse_list(args.scenarios, str)
    s2s = parse_list(args.s2, int)
    fleet = parse_list(args.uavs, int)
    extra = list(itertools.chain.from_iterable(["-O", o] for o in args.option))
    cells = list(itertools.product(scenarios, s2s, fleet, seeds))

    jobs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for alpha, beta in itertools.product(alphas, betas):
            for cell in cells:
                jobs[(alpha, beta) + cell] = pool.submit(run_one, args.cli, *cell, alpha, beta, extra)
        results = {k: f.result() for k, f in jobs.items()}

    print(f"tuning set: seeds {args.seeds} ({len(seeds)}), scenarios {args.scenarios}, "
          f"s2 {args.s2}, n {args.uavs}: {len(cells)} missions per (alpha, beta)")
    print("mean over the set; T_c/T_c0 and T_m/T_m0 = mean per-mission ratio to alpha = 0.5, "
          "beta = 1 when in the grid\n")
    base = (0.5, 1.0)
    has_base = base[0] in alphas and base[1] in betas
    rows = []
    for alpha, beta in itertools.product(alphas, betas):
        tc = [results[(alpha, beta) + c][0] for c in cells]
        tm = [results[(alpha, beta) + c][1] for c in cells]
        row = {"alpha": alpha, "beta": beta, "T_c": statistics.mean(tc), "T_m": statistics.mean(tm)}
        if has_base:
            row["rc"] = statistics.mean(results[(alpha, beta) + c][0] / results[base + c][0]
                                        for c in cells)
            row["rm"] = statistics.mean(results[(alpha, beta) + c][1] / results[base + c][1]
                                        for c in cells)
        rows.append(row)
    print("| alpha | beta | mean T_c | mean T_m |" + (" T_c/T_c0 | T_m/T_m0 |" if has_base else ""))
    print("|---|---|---|---|" + ("---|---|" if has_base else ""))
    for r in rows:
        line = f"| {r['alpha']:g} | {r['beta']:g} | {r['T_c']:.1f} | {r['T_m']:.1f} |"
        if has_base:
            line += f" {r['rc']:.3f} | {r['rm']:.3f} |"
        print(line)
    best = min(rows, key=lambda r: (r["T_c"], r["T_m"]))
    print(f"\nlowest mean T_c: alpha = {best['alpha']:g}, beta = {best['beta']:g} "
          f"(T_c {best['T_c']:.1f}, T_m {best['T_m']:.1f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
