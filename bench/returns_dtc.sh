#!/bin/sh
# Planned battery returns and the ratio to the lower bound on the DTC hull (docs/results.md,
# "Planned returns"): 8 UAVs, imperfect scenario, one launch site on the quay below mid-ship at
# (373, 0), 900 s per battery, 1 m/s (at the paper's 0.5 m/s, 900 s is refused from that site:
# the farthest hull cell needs 978 s). Every planner, and Sweep-Inspect also without its planned
# returns (sweep-inspect-layer), over the seeds given (default 1 2 3). Prints one CSV row per
# mission: planner, seed, T_c, T_m, sorties, bound_T_c, bound_T_m, battery_crashes.
# Usage: bench/returns_dtc.sh [HULLINSPECT] [SEED ...]
set -eu
bin=${1:-build/release/hullinspect}
[ $# -gt 0 ] && shift
seeds=${*:-1 2 3}
echo "planner,seed,T_c,T_m,sorties,bound_T_c,bound_T_m,battery_crashes"
for seed in $seeds; do
  for a in lawnmower part-tsp part-tsp0 coop-frontier sweep-inspect sweep-inspect-layer \
    oracle-part-tsp; do
    case $a in
      sweep-inspect-layer) args="-a sweep-inspect -O planned-returns=false" ;;
      *) args="-a $a" ;;
    esac
    # shellcheck disable=SC2086
    "$bin" run --hull dtc -n 8 $args --scenario imperfect --seed "$seed" --launch 373,0 \
      --endurance 900 --speed 1 --json |
      /usr/bin/python3 -c 'import json, sys
j = json.load(sys.stdin)
print(",".join(str(j[k]) for k in ("T_c", "T_m", "sorties", "bound_T_c", "bound_T_m", "battery_crashes")))' |
      sed "s/^/$a,$seed,/"
  done
done
