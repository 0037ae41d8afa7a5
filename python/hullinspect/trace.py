"""Mission traces (docs/trace-format.md) as tidy pandas DataFrames: one row per UAV per step, one
row per map change, one row per planner annotation."""

import json
import os

import numpy as np

from . import _core


def _rows_array(rows):
    """A trace matrix (strings, rows[0] the bottom row) as int8 [y][x] with -1 for '.'."""
    out = np.full((len(rows), len(rows[0]) if rows else 0), -1, dtype=np.int8)
    for y, row in enumerate(rows):
        for x, ch in enumerate(row):
            if ch != ".":
                out[y, x] = int(ch, 36)
    return out


class Trace:
    """One mission's trace: every UAV's state at every step and what the map and planner did.

    DataFrames (built on first use):
      uavs         t, k, then the trace's uav_fields (x, y, z, transit_left, active, and with
                   launch sites airborne, battery_left, away_left), in_transit (bool: changing
                   plane or away), active and airborne as bool, mode (the planner's last
                   annotation, None before one)
      map_changes  t, cell, x, y, value (M's new value: 1 clean, 2 corrosion seen, 3 inspected)
      annotations  t, k, mode, target_x, target_y (None when no target), plan ([(x, y), …])
      series       t, inspected, known (the counts behind c(t) and m(t))
    Arrays (int8 [y][x], -1 off the hull): truth, prior, initial_map. map_at(t) is M at time t.
    parameters, grid, result: the trace's objects as dicts.
    """

    def __init__(self, data):
        self.data = data
        self.parameters = data["parameters"]
        self.grid = data["grid"]
        self.result = data["result"]
        self.uav_fields = list(data["uav_fields"])
        self.width = int(self.grid["width"])
        self.height = int(self.grid["height"])
        self._frames = {}

    def __repr__(self):
        return (f"Trace({self.parameters.get('algorithm')}, {len(self.data['frames'])} frames, "
                f"{self.uav_count} UAVs)")

    @property
    def uav_count(self):
        frames = self.data["frames"]
        return len(frames[0]["u"]) // len(self.uav_fields) if frames else 0

    @property
    def truth(self):
        return _rows_array(self.data["truth"])

    @property
    def prior(self):
        return _rows_array(self.data["prior"])

    @property
    def initial_map(self):
        return _rows_array(self.data["initial_map"])

    def map_at(self, t):
        """M at time t: the initial map with the changes of frames 0 … t applied."""
        frames = self.data["frames"]
        if not 0 <= t < len(frames):
            raise ValueError(f"t: must be in [0, {len(frames) - 1}] (got {t})")
        flat = self.initial_map.reshape(-1)
        for frame in frames[: t + 1]:
            changes = frame["c"]
            flat[np.asarray(changes[0::2], dtype=np.int64)] = np.asarray(changes[1::2])
        return flat.reshape(self.height, self.width)

    def _frame(self, name, build):
        if name not in self._frames:
            self._frames[name] = build()
        return self._frames[name]

    @property
    def annotations(self):
        return self._frame("annotations", self._annotations)

    @property
    def uavs(self):
        return self._frame("uavs", self._uavs)

    @property
    def map_changes(self):
        return self._frame("map_changes", self._map_changes)

    @property
    def series(self):
        import pandas as pd

        return self._frame("series", lambda: pd.DataFrame({
            "t": np.arange(len(self.data["series"]["inspected"]), dtype=np.int64),
            "inspected": np.asarray(self.data["series"]["inspected"], dtype=np.int64),
            "known": np.asarray(self.data["series"]["known"], dtype=np.int64)}))

    def _annotations(self):
        import pandas as pd

        rows = []
        for frame in self.data["frames"]:
            for key, note in sorted(frame.get("p", {}).items(), key=lambda kv: int(kv[0])):
                target = note.get("target")
                rows.append((frame["t"], int(key), note.get("mode"),
                             None if target is None else target[0],
                             None if target is None else target[1],
                             [tuple(p) for p in note.get("plan", [])]))
        frame = pd.DataFrame(rows, columns=["t", "k", "mode", "target_x", "target_y", "plan"])
        for column in ("t", "k"):
            frame[column] = frame[column].astype(np.int64)
        for column in ("target_x", "target_y"):
            frame[column] = frame[column].astype("Int64")
        return frame

    def _uavs(self):
        import pandas as pd

        frames = self.data["frames"]
        n, fields = self.uav_count, len(self.uav_fields)
        values = np.asarray([f["u"] for f in frames], dtype=np.int64)
        values = values.reshape(len(frames), n, fields)
        t = np.repeat(np.asarray([f["t"] for f in frames], dtype=np.int64), n)
        out = pd.DataFrame({"t": t, "k": np.tile(np.arange(n, dtype=np.int64), len(frames))})
        for i, name in enumerate(self.uav_fields):
            out[name] = values[:, :, i].reshape(-1)
        if "active" in out:
            out["active"] = out["active"].astype(bool)
        if "transit_left" in out:
            out["in_transit"] = out["transit_left"] > 0
        if "away_left" in out:
            out["in_transit"] |= out["away_left"] > 0
        if "airborne" in out:
            out["airborne"] = out["airborne"].astype(bool)
        # The mode a UAV is in at t: its last annotation at or before t.
        modes = np.full((len(frames), n), None, dtype=object)
        current = [None] * n
        for i, frame in enumerate(frames):
            for key, note in frame.get("p", {}).items():
                current[int(key)] = note.get("mode")
            modes[i, :] = current
        out["mode"] = modes.reshape(-1)
        return out

    def _map_changes(self):
        import pandas as pd

        t, cell, value = [], [], []
        for frame in self.data["frames"]:
            changes = frame["c"]
            t.extend([frame["t"]] * (len(changes) // 2))
            cell.extend(changes[0::2])
            value.extend(changes[1::2])
        cell = np.asarray(cell, dtype=np.int64)
        return pd.DataFrame({"t": np.asarray(t, dtype=np.int64), "cell": cell,
                             "x": cell % self.width, "y": cell // self.width,
                             "value": np.asarray(value, dtype=np.int64)})


def read_trace(path):
    """Reads a trace file written by `hullinspect run --trace` or run_mission(trace=…), checked as
    `hullinspect view` checks it (ValueError naming the file and field otherwise)."""
    return Trace(json.loads(_core.read_trace(os.fspath(path))))


def trace_from_text(text):
    """A Trace from the JSON text the library recorded in memory."""
    return Trace(json.loads(text))
