#!/usr/bin/python3
"""Draws a hull JSON (hullinspect hull import --out NAME) as a PNG: the hull mask and the depth of
the surface from the side plane, in the ship frame (metres).

Example: tools/plot_hull.py wigley.json wigley.png
The DTC (GPL-3+ data) is drawn the same way from the installed file, never into the repository:
  hullinspect hull import dtc --out /tmp/dtc && tools/plot_hull.py /tmp/dtc.json /tmp/dtc.png
"""
import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("hull", help="hull JSON written by `hullinspect hull import`")
    parser.add_argument("out", help="PNG to write")
    parser.add_argument("--title", help="figure title (default: the mesh's name)")
    a = parser.parse_args()
    try:
        with open(a.hull) as f:
            h = json.load(f)
        mask = np.array(h["mask"], dtype=float)
        depth = np.array(h["depth"], dtype=float)
        cell, (x0, z0) = h["cell_size"], h["origin"]
    except (OSError, ValueError, KeyError) as e:
        sys.exit("plot_hull.py: %s: not a hull JSON (%s)" % (a.hull, e))
    extent = [x0, x0 + mask.shape[1] * cell, z0, z0 + mask.shape[0] * cell]
    depth = np.where(mask > 0, depth, np.nan)
    aspect = max(1.0, (extent[1] - extent[0]) / max(extent[3] - extent[2], 1e-9))
    width = 10
    panel = min(4.0, width / aspect * 0.9 + 1.1)  # inches: the plot plus its title and labels
    fig, axes = plt.subplots(2, 1, figsize=(width, 2 * panel), constrained_layout=True)
    axes[0].imshow(mask, origin="lower", extent=extent, cmap="Greys", vmin=0, vmax=1.6,
                   interpolation="nearest")
    axes[0].set_title("%s: %d × %d cells of %g m, %d hull cells, %s side"
                      % (a.title or h.get("mesh", a.hull), mask.shape[1], mask.shape[0], cell,
                         int(mask.sum()), h["side"]))
    im = axes[1].imshow(depth, origin="lower", extent=extent, cmap="viridis",
                        interpolation="nearest")
    axes[1].set_title("depth from the side plane Y = %.2f m (m)" % (round(h["side_plane_y"], 2) + 0.0))
    fig.colorbar(im, ax=axes[1], shrink=0.8)
    for ax in axes:
        ax.set_xlabel("X (m, stern → bow)")
        ax.set_ylabel("Z (m, up)")
    fig.savefig(a.out, dpi=110)
    print("wrote %s" % a.out)


if __name__ == "__main__":
    main()
