"""hullinspect: multi-UAV two-resolution hull inspection planner and simulator (docs/python.md).

Bindings of the C++ library; every result equals what the `hullinspect` CLI gives for the same
inputs, and bad input raises ValueError with the CLI's one-line message, naming the Python keyword
where the CLI names its option. Defaults are the CLI's, read from the same declarations.
"""

import csv
import json
import os
import shutil
import tempfile
import types

import numpy as np

from . import _core
from ._core import Hull, Instance
from .frames import read_runs, read_samples, typed_runs
from .trace import Trace, read_trace, trace_from_text

__all__ = ["Hull", "Instance", "MissionResult", "Planner", "Session", "Trace", "make_instance",
           "run_mission", "run_experiment", "to_dataframe", "read_runs", "read_samples",
           "read_trace", "register_planner", "catalog"]
__version__ = _core.__version__

# The defaults of `hullinspect run` and `hullinspect experiment`, from the CLI's declarations.
_DEFAULTS = _core.mission_defaults()

# run --json keys that describe the mission rather than count something.
_SUMMARY_KEYS = {"algorithm", "uavs", "s1", "s2", "seed", "complete", "T_c", "T_m"}


def _text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _hull_arguments(hull):
    """(Hull object or None, path for --hull or "")."""
    if hull is None or isinstance(hull, Hull):
        return hull, ""
    return None, os.fspath(hull)


def _mission(algorithm, uavs, s2, seed, scenario, hull_path, options, params):
    """The mission of these arguments, read through the declarations of `hullinspect run`'s
    options (same checks, same messages)."""
    return _core.mission_input(algorithm, uavs, s2, seed, scenario, hull_path,
                               dict(options or {}), params)


class MissionResult:
    """One mission's outcome: .complete, .T_c, .T_m, .c and .m (percent per step), .counters, and
    .trace (a Trace) when the mission was run with trace=… or keep_trace=True, else None."""

    def __init__(self, raw):
        summary = json.loads(raw["json"])
        text = raw.get("trace")
        self.trace = None if text is None else trace_from_text(text)
        self.summary = summary
        self.complete = summary["complete"]
        self.T_c = summary["T_c"]
        self.T_m = summary["T_m"]
        self.c = np.asarray(raw["c"], dtype=float)
        self.m = np.asarray(raw["m"], dtype=float)
        self.counters = {k: v for k, v in summary.items() if k not in _SUMMARY_KEYS}

    def __repr__(self):
        return (f"MissionResult({self.summary['algorithm']}, complete={self.complete}, "
                f"T_c={self.T_c}, T_m={self.T_m})")


def run_mission(algorithm=_DEFAULTS["algorithm"], uavs=_DEFAULTS["uavs"], s2=_DEFAULTS["s2"],
                seed=_DEFAULTS["seed"], scenario=_DEFAULTS["scenario"], hull=None, options=None,
                trace=None, keep_trace=False, **params):
    """Simulates one mission, like `hullinspect run --json`.

    hull: None (the default hull), a Hull, or anything --hull takes (a path, "dtc").
    trace: a path to write the mission's trace to (as `run --trace`); keep_trace=True keeps it in
    memory without a file. Either way result.trace is a Trace (per-step DataFrames).
    params: every other option of `hullinspect run` with '_' for '-' (s1=5, theta=90, p_c=0.01,
    time_limit=900, r1=3, partitioner="stripes", starts=[(0, 15), (100, 15)], fail=["1@40"],
    prior="prior.txt", …); a keyword that is not one of them, and every entry of `options` (a dict
    with the CLI's KEY=VALUE keys, e.g. {"tsp.max-segments": 12}), is a planner option (-O).
    """
    hull_object, hull_path = _hull_arguments(hull)
    mission = _mission(algorithm, uavs, s2, seed, scenario, hull_path, options, params)
    trace_path = "" if trace is None else os.fspath(trace)
    if trace is not None and not trace_path:
        raise ValueError("trace: expected a file path (got an empty one)")
    return MissionResult(_core.run_mission(mission, hull_object, trace_path,
                                           bool(keep_trace) or bool(trace_path)))


def make_instance(hull, seed, scenario=_DEFAULTS["scenario"], **params):
    """Draws C (.truth) and C' (.prior) for a hull, a seed and a scenario (with p_c=… overrides)."""
    if hull is None:
        hull = Hull.default()
    elif not isinstance(hull, Hull):
        hull = Hull.load(os.fspath(hull))
    options = {k.replace("_", "-"): _text(v) for k, v in params.items()}
    return _core.make_instance(hull, seed, scenario, options)


def _read_runs(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_experiment(config, jobs=_DEFAULTS["jobs"], out=None, resume=False):
    """Runs an experiment and returns runs.csv as a list of dicts (one per run, values as text).

    config: a YAML path, a preset name ("paper-quick") or a dict with the YAML's keys. out: the
    results directory to write (must not exist or be empty, unless resume); None = a temporary one,
    removed after. resume=True keeps the finished runs in `out` and runs the missing ones (as
    `--resume`), so a script can be run again. jobs: worker threads, 0 = every core (the CLI's
    default). Python planners may be used with any `jobs`: C++ planners run in parallel, Python
    planners' calls run one at a time on the calling thread, where Ctrl-C stops the experiment
    (KeyboardInterrupt; the finished runs stay in `out`); results do not depend on `jobs`.
    """
    if isinstance(config, dict):
        kind, value = "text", json.dumps(config)
    elif os.path.exists(str(config)) or str(config).endswith((".yaml", ".yml")):
        kind, value = "path", str(config)
    else:
        kind, value = "preset", str(config)
    if out is not None:
        out = os.fspath(out)
        # The runner's own refusal names the CLI's --resume and --out.
        if not resume and os.path.isdir(out) and os.listdir(out):
            raise ValueError(f"out: {out}: is not empty: pass resume=True to continue the "
                             "experiment in it, or choose another out")
        _core.run_experiment(kind, value, jobs, out, bool(resume))
        return _read_runs(os.path.join(os.fspath(out), "runs.csv"))
    tmp = tempfile.mkdtemp(prefix="hullinspect-")
    try:
        results = os.path.join(tmp, "results")
        _core.run_experiment(kind, value, jobs, results, False)
        return _read_runs(os.path.join(results, "runs.csv"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def to_dataframe(rows):
    """runs.csv rows (run_experiment's result) as a typed pandas DataFrame, as read_runs gives."""
    import pandas as pd

    return typed_runs(pd.DataFrame(rows, dtype=str))


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
    if description is None:
        description = (cls.__doc__ or "a Python planner").strip().splitlines()[0]
    _core.register_planner(str(name), cls, description)


def catalog(kind=""):
    """What `hullinspect list KIND --json` prints: planners, partitioners, tsp-solvers, scenarios,
    presets with their declared options."""
    return json.loads(_core.catalog(kind))


class Session:
    """A live mission: the planner steered by what the cameras saw (docs/python.md, "Live session").

    Session(algorithm, hull=None, prior=None, uavs=…, s2=…, options=None, **params) takes the
    mission options of run_mission except the instance (scenario, seed, truth, failures): the
    truth is what step() is told. prior: C' as None (no expected corrosion), a map file (any
    hull-mask format) or an array [y][x] with 1 on expected corrosion.

    step(readings, failed=()) applies the actions returned by the previous step (none before the
    first), takes `readings` — (x, y, plane, corroded) for every hull cell in the footprint of
    every UAV on a plane, exactly the cells expected_readings(failed) lists — and returns the next
    action per UAV ("N", "S", "E", "W", "hover", "change"), or [] once the mission has finished.
    `failed` lists UAVs that failed before carrying out the previous actions (they sense nothing
    from then on). Bad readings raise ValueError and change nothing. With keep_trace=True,
    trace() gives the mission so far as a Trace, as run_mission records one.
    """

    def __init__(self, algorithm, hull=None, prior=None, uavs=_DEFAULTS["uavs"], s2=_DEFAULTS["s2"],
                 options=None, keep_trace=False, **params):
        for key in ("scenario", "seed"):
            if key in params:
                raise ValueError(f"Session: {key} does not apply to a live session (the readings "
                                 "are the truth)")
        hull_object, hull_path = _hull_arguments(hull)
        mission = _mission(algorithm, uavs, s2, _DEFAULTS["seed"], _DEFAULTS["scenario"],
                           hull_path, options, params)
        self._session = _core.Session(mission, hull_object, prior, bool(keep_trace))

    def step(self, readings, failed=()):
        return self._session.step(readings, [int(k) for k in failed])

    def expected_readings(self, failed=()):
        """The (x, y, plane) cells the next step's readings must cover, in (y, x, plane) order."""
        return self._session.expected_readings([int(k) for k in failed])

    @property
    def state(self):
        """t, map (M, int8 [y][x]), uavs [(x, y, z, in_transit, failed)], finished, complete."""
        s = self._session
        return types.SimpleNamespace(t=s.t, map=s.map, uavs=s.uavs, finished=s.finished,
                                     complete=s.complete)

    @property
    def finished(self):
        return self._session.finished

    def result(self):
        """The mission so far as a MissionResult (T_c and c count the corrosion reported)."""
        return MissionResult(self._session.result())

    def trace(self):
        """The mission so far as a Trace (needs keep_trace=True; its truth is the readings)."""
        return trace_from_text(self._session.trace())
