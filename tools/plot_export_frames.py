#!/usr/bin/python3
"""The frames of a waypoint export (docs/export.md): reads the csv files written by
`hullinspect export TRACE --format csv --origin ... --heading ... --out DIR` and draws
(left) the side view X–Z of the ship frame with each UAV's legs and waypoints, (middle) the top view
X–Y with the hull's side plane, the two stand-off planes and the camera's yaw, and (right) the same
waypoints in local ENU metres, rotated by the ship's heading.

Usage: /usr/bin/python3 tools/plot_export_frames.py DIR -o docs/img/export-frames.png
Exit status: 0 written, 2 unreadable input.
"""

import argparse
import csv
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", help="directory of uav<k>.csv files (geo-referenced export)")
    ap.add_argument("-o", "--out", required=True, help="PNG or PDF to write")
    a = ap.parse_args()
    files = sorted(glob.glob(os.path.join(a.dir, "uav*.csv")), key=lambda p: int(os.path.basename(p)[3:-4]))
    if not files:
        print(f"plot_export_frames: {a.dir}: no uav*.csv files", file=sys.stderr)
        return 2
    uavs = [read(p) for p in files]
    if "east_m" not in uavs[0][0]:
        print(f"plot_export_frames: {files[0]}: not geo-referenced (export with --origin and --heading)",
              file=sys.stderr)
        return 2
    fig = plt.figure(figsize=(13, 7.5))
    grid = fig.add_gridspec(2, 2, height_ratios=[1, 1.3], width_ratios=[2.4, 1])
    side = fig.add_subplot(grid[0, :])
    top = fig.add_subplot(grid[1, 0])
    enu = fig.add_subplot(grid[1, 1])
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, rows in enumerate(uavs):
        c = colours[k % len(colours)]
        x = [float(r["x_m"]) for r in rows]
        y = [float(r["y_m"]) for r in rows]
        z = [float(r["z_m"]) for r in rows]
        side.plot(x, z, "-", color=c, lw=1, label=f"UAV {k}")
        side.plot(x, z, "o", color=c, ms=2.5)
        side.plot(x[0], z[0], "s", color=c, ms=6, mec="k")
        top.plot(x, y, "-", color=c, lw=1)
        top.plot(x, y, "o", color=c, ms=2.5)
        # Yaw arrows at a few waypoints: the camera looks at the hull.
        for r in rows[:: max(1, len(rows) // 6)]:
            yaw = math.radians(float(r["yaw_deg"]))
            top.annotate("", xy=(float(r["x_m"]) + 0.9 * math.cos(yaw), float(r["y_m"]) + 0.9 * math.sin(yaw)),
                         xytext=(float(r["x_m"]), float(r["y_m"])),
                         arrowprops={"arrowstyle": "->", "color": c, "lw": 1})
        e = [float(r["east_m"]) for r in rows]
        n = [float(r["north_m"]) for r in rows]
        enu.plot(e, n, "-", color=c, lw=1)
    side.set_title("side view: ship frame X–Z (m), waypoints ●, start ■")
    side.set_xlabel("X (m, stern → bow)")
    side.set_ylabel("Z (m, up)")
    side.set_aspect("equal")
    side.legend(loc="upper center", bbox_to_anchor=(0.5, -0.33), fontsize=8, ncol=len(uavs))
    # The planes: the hull's side plane at y = 0 (Ys) and the two stand-offs in front of it.
    planes = sorted({(int(r["plane"]), round(float(r["y_m"]), 4)) for rows in uavs for r in rows})
    xmax = max(float(r["x_m"]) for rows in uavs for r in rows) + 1
    top.axhline(0, color="k", lw=2)
    top.text(0.5, 0, " hull side plane Ys (depth 0)", fontsize=8, va="bottom")
    for plane, y in planes:
        top.axhline(y, color="grey", lw=0.6, ls=":")
        top.text(xmax, y, f" z = {plane}: ζ{plane} = {abs(y):.2f} m", fontsize=8, va="center")
    top.set_title("top view: ship frame X–Y (m), yaw →")
    top.set_xlabel("X (m, stern → bow)")
    top.set_ylabel("Y (m, to port)")
    reach = max(abs(y) for _, y in planes) + 1
    top.set_ylim(*sorted((-math.copysign(1, planes[0][1]), math.copysign(reach, planes[0][1]))))
    enu.set_title("local ENU (m) after the heading")
    enu.set_xlabel("east (m)")
    enu.set_ylabel("north (m)")
    enu.set_aspect("equal")
    enu.plot(0, 0, "k+", ms=10)
    enu.text(0, 0, " origin", fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print(f"wrote {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
