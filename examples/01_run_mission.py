"""Tutorial 01 (Python): run one mission and print c(t) and m(t) every 50 s.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/01_run_mission.py [algorithm]

The same mission as examples/01_run_mission.cpp and `hullinspect run --scenario imperfect --seed 7`.
"""
import sys

import hullinspect

algorithm = sys.argv[1] if len(sys.argv) > 1 else "lawnmower"
result = hullinspect.run_mission(algorithm=algorithm, scenario="imperfect", seed=7)
print(f"{algorithm}: T_c = {result.T_c} s, T_m = {result.T_m} s, moves {result.counters['moves']}")
for t in range(0, len(result.c), 50):
    print(f"t = {t:4d} s   c = {result.c[t]:5.1f} %   m = {result.m[t]:5.1f} %")
sys.exit(0 if result.complete else 1)
