#!/usr/bin/python3
"""Scans for missions the deconfliction layer keeps from completing (docs/model.md §13).

Runs the paper-quick preset's scenarios, s2 and fleets with every registered planner (default
options) and a few instances at each separation D, through `hullinspect experiment`, and lists
every mission that is incomplete or counts a separation conflict. Exits 1 if there is one.

Usage (from the repository root, after building the release preset):
  /usr/bin/python3 bench/separation_scan.py --cli build/release/hullinspect --out DIR \
      [--separations 1 2 3] [--instances 3] [--jobs 2]
"""

import argparse
import csv
import pathlib
import subprocess
import sys


def planners(cli):
    out = subprocess.run([cli, "list", "planners"], capture_output=True, text=True, check=True)
    # "  name: description" at two spaces; options are indented further.
    return [line.strip().split(":")[0].split()[0] for line in out.stdout.splitlines()
            if line.startswith("  ") and not line.startswith("   ")]


def config(d, algorithms, instances):
    names = "\n".join(f"  - {a}" for a in algorithms)
    return (f"name: separation-scan-d{d}\nhull: default\ngrid:\n  cell_size: 0.5\n"
            "scenarios: [perfect, imperfect, inhomogeneous, combined]\n"
            f"s1: 5\ns2: [7, 9, 11]\ntheta: 90\nuavs: [4, 8]\nalgorithms:\n{names}\n"
            f"instances: {instances}\ntime_limit: 20000\nseparation: {d}\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--cli", default="build/release/hullinspect")
    p.add_argument("--out", required=True, help="a new directory for the configs and results")
    p.add_argument("--separations", type=int, nargs="+", default=[1, 2, 3])
    p.add_argument("--instances", type=int, default=3)
    p.add_argument("--jobs", type=int, default=2)
    a = p.parse_args()
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=False)
    algorithms = planners(a.cli)
    bad = 0
    total = 0
    for d in a.separations:
        cfg = out / f"d{d}.yaml"
        cfg.write_text(config(d, algorithms, a.instances))
        subprocess.run([a.cli, "experiment", "--config", str(cfg), "--out", str(out / f"d{d}"),
                        "--jobs", str(a.jobs)], check=True, stdout=subprocess.DEVNULL)
        with open(out / f"d{d}" / "runs.csv", newline="") as f:
            for row in csv.DictReader(f):
                total += 1
                if row["complete"] == "1" and row["separation_conflicts"] in ("", "0"):
                    continue
                bad += 1
                print(f"D={d} {row['algorithm']} {row['scenario']} s2={row['s2']} "
                      f"n={row['uavs']} seed={row['seed']}: complete={row['complete']} "
                      f"conflicts={row['separation_conflicts']} steps={row['steps']}")
    print(f"{total} missions, {bad} incomplete or in conflict")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
