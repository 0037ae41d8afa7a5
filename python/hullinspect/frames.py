"""Typed pandas readers of an experiment's result files (docs/experiments.md): runs.csv with
`complete` as bool, empty T_c/T_m as missing and each planner option as a column; samples.csv in
long format (one row per run and curve time)."""

import os

import numpy as np

# Columns that hold text even when every value looks like a number (ids are hex digits; zone lists
# are '/'-separated).
_TEXT_COLUMNS = {"run_id", "cell_id", "scenario", "sweep", "sweep_value", "algorithm", "planner",
                 "planner_options", "hull", "p_c", "l_c", "zone_bounds"}
# Counts that are empty when the event did not happen.
_OPTIONAL_COUNTS = {"T_c", "T_m"}


def _results_file(path, name):
    path = os.fspath(path)
    return os.path.join(path, name) if os.path.isdir(path) else path


def _numeric(series):
    """The column as integers or floats when every non-empty value is a number, else unchanged."""
    import pandas as pd

    filled = series.ne("")
    converted = pd.to_numeric(series.where(filled), errors="coerce")
    if converted.notna().sum() != filled.sum():
        return series
    if filled.all() and (converted == np.floor(converted)).all() and \
            not series.str.contains(r"[.eE]", regex=True).any():
        return converted.astype(np.int64)
    return converted


def _options(packed):
    """'r1=2;tsp-solver=exact' → {'r1': '2', 'tsp-solver': 'exact'}."""
    out = {}
    for item in filter(None, packed.split(";")):
        key, _, value = item.partition("=")
        out[key] = value
    return out


def typed_runs(frame):
    """runs.csv rows (all text) as typed columns, planner options spread into columns."""
    import pandas as pd

    frame = frame.copy()
    for column in frame.columns:
        if column == "complete":
            if not frame[column].isin(["0", "1"]).all():
                raise ValueError("runs.csv: complete: expected 0 or 1 in every row")
            frame[column] = frame[column] == "1"
        elif column in _OPTIONAL_COUNTS:
            frame[column] = pd.to_numeric(frame[column].where(frame[column] != ""),
                                          errors="raise").astype("Int64")
        elif column not in _TEXT_COLUMNS:
            frame[column] = _numeric(frame[column])
    if "planner_options" in frame:
        options = [_options(p) for p in frame["planner_options"]]
        keys = sorted({k for o in options for k in o})
        for key in keys:
            column = key if key not in frame.columns else "planner." + key
            values = pd.Series([o.get(key, "") for o in options], index=frame.index)
            converted = _numeric(values)
            # Missing where the run's planner has no such option: NaN, or None among text.
            frame[column] = values.where(values != "", None) if converted is values else converted
    return frame


def read_runs(path):
    """runs.csv (the file, or a results directory holding it) as a typed DataFrame."""
    import pandas as pd

    frame = pd.read_csv(_results_file(path, "runs.csv"), dtype=str, keep_default_na=False)
    return typed_runs(frame)


def read_samples(path):
    """samples.csv (the file, or a results directory) in long format: run_id, t, inspected, known
    (integers), sorted by run then time."""
    import pandas as pd

    wide = pd.read_csv(_results_file(path, "samples.csv"), dtype={"run_id": str})
    long = wide.melt(id_vars="run_id", var_name="column", value_name="value")
    parts = long["column"].str.rpartition("_")
    long["series"], long["t"] = parts[0], parts[2].astype(np.int64)
    out = long.pivot_table(index=["run_id", "t"], columns="series", values="value",
                           aggfunc="first").reset_index()
    out.columns.name = None
    order = {run: i for i, run in enumerate(wide["run_id"])}
    out = out.sort_values(["run_id", "t"], key=lambda c: c.map(order) if c.name == "run_id" else c)
    out = out.reset_index(drop=True)[["run_id", "t", "inspected", "known"]]
    for column in ("inspected", "known"):
        out[column] = out[column].astype(np.int64)
    return out
