"""hullinspect: multi-UAV two-resolution hull inspection planner and simulator (docs/python.md).

Bindings of the C++ library; every result equals what the `hullinspect` CLI gives for the same
inputs, and bad input raises ValueError with the CLI's one-line message.
"""

import csv
import json
import os
import shutil
import tempfile

import numpy as np

from . import _core
from ._core import Hull, Instance

__all__ = ["Hull", "Instance", "MissionResult", "Planner", "make_instance", "run_mission",
           "run_experiment", "to_dataframe", "register_planner", "catalog"]

# Keyword parameters of run_mission that are mission parameters (MissionParams) or scenario
# options; anything else is a planner option. Python spells them with '_', the CLI with '-'.
_MISSION_KEYS = {"s1", "theta", "start-z", "time-limit"}
_SCENARIO_KEYS = {"p-c", "l-c", "front-p-c", "front-l-c", "p-tp", "p-fp"}


def _text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _split_params(params, options):
    mission, scenario, planner = {}, {}, {}
    for key, value in (options or {}).items():
        planner[str(key)] = _text(value)
    for key, value in params.items():
        name = key.replace("_", "-")
        if name in _MISSION_KEYS:
            mission[name] = _text(value)
        elif name in _SCENARIO_KEYS:
            scenario[name] = _text(value)
        else:
            planner[name] = _text(value)
    return mission, scenario, planner


class MissionResult:
    """One mission's outcome: .complete, .T_c, .T_m, .c and .m (percent per step), .counters."""

    def __init__(self, raw):
        summary = json.loads(raw["json"])
        self.summary = summary
        self.complete = summary["complete"]
        self.T_c = summary["T_c"]
        self.T_m = summary["T_m"]
        self.c = np.asarray(raw["c"], dtype=float)
        self.m = np.asarray(raw["m"], dtype=float)
        self.counters = {k: v for k, v in summary.items()
                         if k not in ("algorithm", "uavs", "s1", "s2", "seed", "complete", "T_c",
                                      "T_m")}

    def __repr__(self):
        return (f"MissionResult({self.summary['algorithm']}, complete={self.complete}, "
                f"T_c={self.T_c}, T_m={self.T_m})")


def run_mission(algorithm="part-tsp", uavs=4, s2=7, seed=1, scenario="perfect", hull=None,
                options=None, **params):
    """Simulates one mission, like `hullinspect run --json`.

    params: s1, theta, start_z, time_limit (mission); p_c, l_c, front_p_c, front_l_c, p_tp, p_fp
    (scenario overrides); anything else, or `options` (a dict with the CLI's kebab-case keys), is a
    planner option, e.g. r1=3 or options={"tsp.dp-max-segments": 12}.
    """
    if isinstance(hull, str):
        hull = Hull.load(hull)
    mission, scenario_options, planner = _split_params(params, options)
    raw = _core.run_mission(algorithm, int(uavs), int(s2), int(seed), scenario, hull, planner,
                            mission, scenario_options)
    return MissionResult(raw)


def make_instance(hull, seed, scenario="perfect", **params):
    """Draws C (.truth) and C' (.prior) for a hull, a seed and a scenario (with p_c=… overrides)."""
    if isinstance(hull, str):
        hull = Hull.load(hull)
    options = {k.replace("_", "-"): _text(v) for k, v in params.items()}
    return _core.make_instance(hull, int(seed), scenario, options)


def _read_runs(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_experiment(config, jobs=2, out=None):
    """Runs an experiment and returns runs.csv as a list of dicts (one per run, values as text).

    config: a YAML path, a preset name ("paper-quick") or a dict with the YAML's keys. out: the
    results directory to write (must not exist or be empty); None = a temporary one, removed after.
    Python planners may be used with any `jobs`: C++ planners run in parallel, Python planners'
    decide() calls take the GIL and so run one at a time; results do not depend on `jobs`.
    """
    if isinstance(config, dict):
        kind, value = "text", json.dumps(config)
    elif os.path.exists(str(config)) or str(config).endswith((".yaml", ".yml")):
        kind, value = "path", str(config)
    else:
        kind, value = "preset", str(config)
    if out is not None:
        _core.run_experiment(kind, value, int(jobs), str(out))
        return _read_runs(os.path.join(str(out), "runs.csv"))
    tmp = tempfile.mkdtemp(prefix="hullinspect-")
    try:
        results = os.path.join(tmp, "results")
        _core.run_experiment(kind, value, int(jobs), results)
        return _read_runs(os.path.join(results, "runs.csv"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def to_dataframe(rows):
    """runs.csv rows (run_experiment's result) as a pandas DataFrame with numeric columns typed."""
    import pandas as pd

    frame = pd.DataFrame(rows)
    for column in frame.columns:
        converted = pd.to_numeric(frame[column], errors="coerce")
        if converted.notna().sum() == frame[column].ne("").sum():
            frame[column] = converted
    return frame


class Planner:
    """Base class of Python planners: override start(context) and decide(view).

    context: hull (numpy bool [y][x]), prior (C', int8 [y][x]), starts [(x, y)], uavs, s1, s2,
    plane_change_steps, time_limit. view: t, map (M, int8 [y][x]: -1 not hull, 0 unknown, 1 clean,
    2 corrosion seen, 3 inspected), prior, uavs [(x, y, z, in_transit, failed)]. The truth is never
    shown. decide returns one action per UAV: "N", "S", "E", "W", "hover" or "change".
    """

    def start(self, context):
        pass

    def decide(self, view):
        raise NotImplementedError("a Planner must implement decide(view)")


def register_planner(name, cls, description=None):
    """Makes `cls` (a Planner subclass) available as algorithm `name` in run_mission and
    run_experiment; each mission gets a new instance. Names cannot be registered twice."""
    if not (isinstance(cls, type) and issubclass(cls, Planner)):
        raise ValueError(f"register_planner: {cls!r} is not a subclass of hullinspect.Planner")
    _core.register_planner(name, cls, description or (cls.__doc__ or "a Python planner").strip())


def catalog(kind=""):
    """What `hullinspect list KIND --json` prints: planners, partitioners, tsp-solvers, scenarios,
    presets with their declared options."""
    return json.loads(_core.catalog(kind))
