#!/usr/bin/python3
"""Static picture of one mission for papers: the map at the end (or at --time T), each UAV's
trajectory (solid at z = 1, dashed at z = 2), its plane changes, for partitioned planners the
region outlines, and with no-fly zones the no-fly positions (hatched, outlined) and the hull cells
no allowed footprint reaches (cross-hatched; docs/model.md "No-fly zones"). Reads a trace written by `hullinspect run --trace FILE` (docs/trace-format.md).

Usage (Debian's Python, which sees python3-matplotlib):
    /usr/bin/python3 tools/plot_mission.py mission.json                 # mission.png + mission.pdf
    /usr/bin/python3 tools/plot_mission.py mission.json -o fig.pdf --time 120 --title "Part-TSP"

Exit status: 0 written, 2 unreadable or malformed trace / bad option.
"""

import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection, PatchCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

# Cell colours for print (the viewer's, with white instead of dark grey around the hull).
NON_HULL = (1.0, 1.0, 1.0)
UNKNOWN = (139 / 255, 147 / 255, 158 / 255)
CLEAN = (0.90, 0.91, 0.93)
CORROSION = (245 / 255, 140 / 255, 40 / 255)
INSPECTED = (46 / 255, 160 / 255, 67 / 255)
# The viewer's region colours, mixed with much white: regions must not hide the trajectories.
REGIONS = [
    (78, 121, 167), (150, 110, 190), (80, 160, 170), (200, 110, 150), (110, 120, 140), (100, 140, 225),
    (170, 90, 140), (60, 140, 130), (160, 150, 220), (70, 170, 200), (180, 130, 170), (90, 90, 170),
]
REGION_TINT = 0.78
# No-fly positions: red hatching with a red outline, as the viewer hatches them. Hull cells that no
# allowed footprint reaches: purple cross-hatching over the cell's colour (its state stays visible);
# dense for cells no footprint reaches, sparse for those only z = 2 sees.
NO_FLY = "#b2182b"
NO_FLY_HATCH = "////"
UNREACHABLE = "#5e3c99"
UNREACHABLE_HATCH = {"x": "xxxx", "d": "xx"}
PAPER_UAV_FIELDS = 5  # x, y, z, transit_left, active (then airborne, battery_left, away_left)
# Trajectory colours: no orange or green, which mark corrosion.
UAV_COLORS = ["#1f77b4", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#555555", "#bcbd22",
              "#393b79", "#843c39", "#000000", "#7b4173"]


class TraceError(Exception):
    pass


def read_trace(path):
    try:
        with open(path, encoding="utf-8") as f:
            trace = json.load(f)
    except OSError as e:
        raise TraceError(f"{path}: cannot open the file ({e.strerror})") from None
    except json.JSONDecodeError as e:
        raise TraceError(f"{path}:{e.lineno}: not a JSON trace: {e.msg}") from None
    if not isinstance(trace, dict) or trace.get("format") != "hullinspect-trace":
        raise TraceError(f'{path}: format: expected "hullinspect-trace" (not a hullinspect trace?)')
    if trace.get("version") not in (1, 2, 3, 4):
        raise TraceError(f"{path}: version: {trace.get('version')} is not supported (this script reads versions 1 to 4)")
    for key in ("grid", "initial_map", "frames", "footprint", "result"):
        if key not in trace:
            raise TraceError(f"{path}: {key}: missing")
    return trace


def rows_to_array(rows, symbols=False):
    """rows[y] strings, y = 0 bottom → int array [y, x]; '.' → -1; 'A'.. → 10.. when symbols."""
    def value(ch):
        if ch == ".":
            return -1
        if symbols and ch.isalpha():
            return ord(ch) - ord("A") + 10
        return int(ch)
    return np.array([[value(ch) for ch in row] for row in rows], dtype=np.int16)


def map_at(trace, t):
    m = rows_to_array(trace["initial_map"]).ravel()
    for frame in trace["frames"][: t + 1]:
        c = frame["c"]
        if c:
            m[np.asarray(c[0::2])] = np.asarray(c[1::2])
    return m.reshape(trace["grid"]["height"], trace["grid"]["width"])


def cell_image(m, owner):
    img = np.zeros(m.shape + (3,))
    img[m < 0] = NON_HULL
    img[m == 0] = UNKNOWN
    img[m == 1] = CLEAN
    if owner is not None:
        for o in np.unique(owner[owner >= 0]):
            base = np.array(REGIONS[o % len(REGIONS)]) / 255
            tint = base * (1 - REGION_TINT) + REGION_TINT
            img[(owner == o) & (m == 1)] = tint
            img[(owner == o) & (m == 0)] = base * 0.6 + 0.4
    img[m == 2] = CORROSION
    img[m == 3] = INSPECTED
    return img


def boundary_segments(labels, different):
    """Cell edges between horizontally or vertically adjacent cells for which different(a, b)."""
    h, w = labels.shape
    segments = []
    for y in range(h):
        for x in range(w):
            a = labels[y, x]
            if x + 1 < w and different(a, labels[y, x + 1]):
                segments.append([(x + 0.5, y - 0.5), (x + 0.5, y + 0.5)])
            if y + 1 < h and different(a, labels[y + 1, x]):
                segments.append([(x - 0.5, y + 0.5), (x + 0.5, y + 0.5)])
    return segments


def row_cells(rows, symbol):
    """Cells (x, y) of rows[y] (y = 0 the bottom) whose character is `symbol`."""
    return [(x, y) for y, row in enumerate(rows) for x, ch in enumerate(row) if ch == symbol]


def cell_runs(cells):
    """The cells as maximal horizontal runs (x0, y, length), so a zone is a few rectangles."""
    runs = []
    for x, y in sorted(cells, key=lambda c: (c[1], c[0])):
        if runs and runs[-1][1] == y and runs[-1][0] + runs[-1][2] == x:
            runs[-1] = (runs[-1][0], y, runs[-1][2] + 1)
        else:
            runs.append((x, y, 1))
    return runs


def hatched_cells(ax, cells, color, hatch, gid, zorder):
    """Adds the cells as one collection of hatched rectangles (no fill) named `gid`."""
    patches = [Rectangle((x - 0.5, y - 0.5), n, 1) for x, y, n in cell_runs(cells)]
    collection = PatchCollection(patches, facecolor="none", edgecolor=color, hatch=hatch,
                                 linewidths=0, zorder=zorder)
    collection.set_gid(gid)
    ax.add_collection(collection)
    return collection


def uav_tracks(trace, until):
    """Per UAV: array [t, (x, y, z, transit_left, active)] for t = 0..until."""
    frames = trace["frames"][: until + 1]
    u = np.array([f["u"] for f in frames], dtype=np.int32)
    fields = len(trace.get("uav_fields", range(PAPER_UAV_FIELDS)))
    n = u.shape[1] // fields
    return [u[:, k * fields:k * fields + PAPER_UAV_FIELDS] for k in range(n)]


def flight_runs(track):
    """The UAV's flight split into maximal runs on one style: yields (points [k, 2], close) where
    close means flown at z = 1 (on z = 1 at both ends of every step of the run, not in transit)."""
    xy = track[:, 0:2].astype(float)
    z, transit = track[:, 2], track[:, 3]
    if len(xy) < 2:
        return
    close = (z[:-1] == 1) & (transit[:-1] == 0) & (z[1:] == 1)
    start = 0
    for i in range(1, len(close) + 1):
        if i == len(close) or close[i] != close[start]:
            points = xy[start:i + 1]
            if np.any(points != points[0]):  # a run that never moves draws nothing
                yield points, bool(close[start])
            start = i


def plane_changes(track):
    """Yields (t, descending) for every plane change starting between t and t + 1: the UAV was on a
    plane at t and at t + 1 is in transit (z is then the plane it leaves) or already on the other
    plane (u_z = 1)."""
    z, transit = track[:, 2], track[:, 3]
    on_plane = transit[:-1] == 0
    starting = on_plane & ((transit[1:] > 0) | (z[1:] != z[:-1]))
    for i in np.flatnonzero(starting):
        yield int(i), bool(z[i] == 2)


def plot(trace, until, title, show_partition):
    grid = trace["grid"]
    w, h = grid["width"], grid["height"]
    m = map_at(trace, until)
    owner = None
    if show_partition and trace.get("partition"):
        owner = rows_to_array(trace["partition"], symbols=True)
    tracks = uav_tracks(trace, until)
    n = len(tracks)
    colors = [UAV_COLORS[k % len(UAV_COLORS)] for k in range(n)]

    fig_w = 12.0
    map_h = fig_w * h / w
    fig, (ax, legend_ax) = plt.subplots(
        2, 1, figsize=(fig_w, map_h + 1.6), constrained_layout=True,
        gridspec_kw={"height_ratios": [map_h + 0.9, 0.7]})
    legend_ax.axis("off")
    ax.imshow(cell_image(m, owner), origin="lower", interpolation="nearest",
              extent=(-0.5, w - 0.5, -0.5, h - 0.5))
    hull = m >= 0
    ax.add_collection(LineCollection(boundary_segments(hull, lambda a, b: a != b),
                                     colors="0.35", linewidths=0.6))
    if owner is not None:
        ax.add_collection(LineCollection(
            boundary_segments(owner, lambda a, b: a >= 0 and b >= 0 and a != b),
            colors="black", linewidths=1.1))

    # No-fly zones (trace `no_fly`, `unreachable`): present only when the mission had some.
    no_fly = row_cells(trace.get("no_fly") or [], "#")
    unreachable = {k: row_cells(trace.get("unreachable") or [], k) for k in ("x", "d")}
    # Unreachable cells lie behind no-fly positions, so they are drawn over them.
    for k, cells in unreachable.items():
        if cells:
            hatched_cells(ax, cells, UNREACHABLE, UNREACHABLE_HATCH[k], f"unreachable-{k}", 2.6)
    if no_fly:
        hatched_cells(ax, no_fly, NO_FLY, NO_FLY_HATCH, "no-fly", 2.4)
        mask = np.zeros((h, w), dtype=bool)
        for x, y in no_fly:
            mask[y, x] = True
        # Padded by one cell so a zone on the grid's edge is closed too, then shifted back.
        segments = [[(x - 1, y - 1) for x, y in segment]
                    for segment in boundary_segments(np.pad(mask, 1), lambda a, b: a != b)]
        outline = LineCollection(segments, colors=NO_FLY, linewidths=1.0, zorder=2.4)
        outline.set_gid("no-fly-outline")
        ax.add_collection(outline)

    ups, downs = {}, {}
    for k, track in enumerate(tracks):
        xy = track[:, 0:2].astype(float)
        for run_xy, close in flight_runs(track):
            # One polyline per run, so the dash pattern of z = 2 flows along it (one line per
            # one-cell segment would restart the pattern at every cell and look solid).
            ax.plot(run_xy[:, 0], run_xy[:, 1], color=colors[k],
                    ls="solid" if close else (0, (3, 2)), lw=1.8 if close else 1.0,
                    solid_capstyle="round", dash_capstyle="round", zorder=3)
        for i, descending in plane_changes(track):
            key = (xy[i, 0], xy[i, 1], colors[k])
            target = downs if descending else ups
            target[key] = target.get(key, 0) + 1
    # Plane changes: one marker per UAV and cell (repeats at one cell are counted, not stacked),
    # ▼ just below the cell centre and ▲ just above, smaller when there are many (Coop-Frontier
    # changes plane hundreds of times).
    total = sum(downs.values()) + sum(ups.values())
    size = 42 if total <= 40 else max(12, 42 * (40 / total) ** 0.5)
    for points, marker, dy in ((downs, "v", -0.3), (ups, "^", 0.3)):
        if points:
            px, py, pc = zip(*points)
            ax.scatter(px, np.asarray(py) + dy, marker=marker, s=size, c=list(pc),
                       edgecolors="black", linewidths=0.5, zorder=6)
    for k, track in enumerate(tracks):
        ax.plot(track[0, 0], track[0, 1], "o", ms=9, mfc="white", mec=colors[k], mew=1.8, zorder=5)
        ax.plot(track[-1, 0], track[-1, 1], "s", ms=5.5, mfc=colors[k], mec="black", mew=0.6,
                zorder=5)

    ax.set_xlim(-0.5, w - 0.5)
    ax.set_ylim(-0.5, h - 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (cells, stern → bow)")
    ax.set_ylabel("y (cells)")

    r = trace["result"]
    p = trace.get("parameters", {})
    if title is None:
        fp = trace["footprint"]
        uavs = f"{n} UAV" if n == 1 else f"{n} UAVs"
        title = f"{p.get('algorithm', 'mission')}, {uavs}, s1 = {fp[0]}, s2 = {fp[1]}"
        if "seed" in p:
            title += f", seed {p['seed']}"
        tc = "—" if r.get("T_c") is None else f"{r['T_c']} s"
        tm = "—" if r.get("T_m") is None else f"{r['T_m']} s"
        title += f": T_c = {tc}, T_m = {tm}"
        if until < len(trace["frames"]) - 1:
            title += f" (shown at t = {until} s)"
    ax.set_title(title, fontsize=11)

    handles = [Line2D([], [], color=colors[k], lw=2, label=f"UAV {k}") for k in range(n)]
    handles += [
        Line2D([], [], color="0.2", lw=1.8, label="flown at z = 1"),
        Line2D([], [], color="0.2", lw=1.0, ls=(0, (3, 2)), label="flown at z = 2"),
        Line2D([], [], ls="", marker="v", mfc="0.6", mec="black",
               label=f"descend 2 → 1 ({sum(downs.values())})"),
        Line2D([], [], ls="", marker="^", mfc="0.6", mec="black",
               label=f"ascend 1 → 2 ({sum(ups.values())})"),
        Line2D([], [], ls="", marker="o", mfc="white", mec="0.2", label="start"),
        Line2D([], [], ls="", marker="s", mfc="0.4", mec="black", label="position at the end"),
        Patch(fc=INSPECTED, label="corrosion inspected"),
        Patch(fc=CORROSION, label="corrosion expected / detected"),
        Patch(fc=CLEAN, ec="0.6",
              label="explored, clean" if owner is None else "explored, clean (tint of its region)"),
        Patch(fc=UNKNOWN, label="unknown" if owner is None else "unknown (region colour)"),
    ]
    if owner is not None:
        handles.append(Line2D([], [], color="black", lw=1.1, label="region boundary"))
    if no_fly:
        handles.append(Patch(fc="none", ec=NO_FLY, hatch=NO_FLY_HATCH,
                             label=f"no-fly position ({len(no_fly)})"))
    if unreachable["x"]:
        handles.append(Patch(fc="none", ec=UNREACHABLE, hatch=UNREACHABLE_HATCH["x"],
                             label=f"unreachable: no footprint ({len(unreachable['x'])})"))
    if unreachable["d"]:
        handles.append(Patch(fc="none", ec=UNREACHABLE, hatch=UNREACHABLE_HATCH["d"],
                             label=f"unreachable at z = 1: seen from z = 2 only ({len(unreachable['d'])})"))
    legend_ax.legend(handles=handles, loc="center", ncol=min(8, max(4, (len(handles) + 2) // 3)),
                     fontsize=8, frameon=False)
    return fig


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("trace", help="trace written by `hullinspect run --trace FILE`")
    parser.add_argument("-o", "--out", action="append",
                        help="output file, .png or .pdf (repeatable; default: TRACE's name with .png and .pdf)")
    parser.add_argument("--time", type=int, help="draw the mission up to this step (default: the end)")
    parser.add_argument("--title", help="figure title (default: algorithm, fleet, footprints, T_c, T_m)")
    parser.add_argument("--no-partition", action="store_true", help="do not colour or outline regions")
    parser.add_argument("--dpi", type=int, default=200, help="resolution of PNG output (default 200)")
    args = parser.parse_args(argv)

    try:
        trace = read_trace(args.trace)
    except TraceError as e:
        print(f"plot_mission.py: {e}", file=sys.stderr)
        return 2
    last = len(trace["frames"]) - 1
    until = last if args.time is None else args.time
    if not 0 <= until <= last:
        print(f"plot_mission.py: --time: {until} is outside [0, {last}]", file=sys.stderr)
        return 2
    outs = args.out or [os.path.splitext(args.trace)[0] + ext for ext in (".png", ".pdf")]
    for out in outs:
        if os.path.splitext(out)[1].lower() not in (".png", ".pdf", ".svg"):
            print(f"plot_mission.py: {out}: expected a .png, .pdf or .svg file name", file=sys.stderr)
            return 2

    fig = plot(trace, until, args.title, not args.no_partition)
    for out in outs:
        tmp = f"{out}.tmp-{os.getpid()}{os.path.splitext(out)[1]}"
        try:
            fig.savefig(tmp, dpi=args.dpi)
            os.replace(tmp, out)
        except OSError as e:
            if os.path.exists(tmp):
                os.remove(tmp)
            print(f"plot_mission.py: {out}: cannot write ({e.strerror})", file=sys.stderr)
            return 2
        print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
