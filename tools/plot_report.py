#!/usr/bin/python3
"""Draws the figures of `hullinspect report` from an experiment's results.

Usage: /usr/bin/python3 plot_report.py --results RESULTS_DIR --summary SUMMARY_CSV --out FIG_DIR
           [--planners A,B,...] [--labels A=Label,...] [--format png,pdf] [--dpi 150]

Reads RESULTS_DIR/curves.csv and RESULTS_DIR/manifest.json and the report's summary.csv, and
writes, as PNG and PDF, sized for a paper (7 in wide for two columns, 3.5 in for one column; every
text at least 7 pt at that size; no titles: the report's captions say what each figure shows):
  fig6_<scenario>            T_c and T_m, mean with the report's 95 % bootstrap interval (or ± std
                             with --error-bars std), grouped bars (x: fleet size, bars: algorithms),
                             one column per s2 (the paper's Fig. 6)
  fig7_<scenario>_n<n>       mean c(t) and m(t) with a ±1 std band, one column per s2 (Fig. 7)
  fig8_s2-<s2>_n<n>          mean c(t) per sweep (line style: swept value) and per plain scenario
                             (Fig. 8); only when the experiment has sweeps
Every planner has one colour in every figure (PLANNER_COLOURS, the Okabe–Ito palette, which
readers with colour-vision deficiencies tell apart); another algorithm takes a palette colour by a
hash of its name, the next one along when a planner of the same figure has that one. Uses only
Debian's python3-matplotlib and python3-numpy.
"""

import argparse
import csv
import json
import math
import os
import re
import sys
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
import numpy as np  # noqa: E402

# Figure widths (inches) of a one- and a two-column paper layout, and the smallest font (points)
# any text may have at those sizes.
ONE_COLUMN = 3.5
TWO_COLUMN = 7.0
MIN_FONT = 7

plt.rcParams.update({
    "font.size": 8,
    "axes.titlesize": 8,
    "axes.labelsize": 8,
    "xtick.labelsize": 7,
    "ytick.labelsize": 7,
    "legend.fontsize": 7,
    "legend.title_fontsize": 7,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "lines.linewidth": 1.0,
    "pdf.fonttype": 42,
    "svg.fonttype": "none",  # text stays text in SVG figures (editable, searchable)
})

# Okabe & Ito's colour-blind-safe palette.
OKABE_ITO = {"orange": "#E69F00", "sky blue": "#56B4E9", "bluish green": "#009E73",
             "yellow": "#F0E442", "blue": "#0072B2", "vermillion": "#D55E00",
             "reddish purple": "#CC79A7", "black": "#000000"}
# One colour per planner (and per label of the presets' variants), the same in every figure.
PLANNER_COLOURS = {
    "lawnmower": OKABE_ITO["blue"],
    "part-tsp": OKABE_ITO["vermillion"],
    "part-tsp0": OKABE_ITO["orange"],
    "coop-frontier": OKABE_ITO["bluish green"],
    "sweep-inspect": OKABE_ITO["reddish purple"],
    "part-tsp-share": OKABE_ITO["sky blue"],
    "oracle-part-tsp": OKABE_ITO["black"],
    "nearest-first": OKABE_ITO["yellow"],
}


def planner_colour(name):
    """The fixed colour of a planner or algorithm label: its own, else one of the palette by a
    hash of the name (the same in every figure and every run)."""
    if name in PLANNER_COLOURS:
        return PLANNER_COLOURS[name]
    palette = list(OKABE_ITO.values())
    return palette[zlib.crc32(name.encode()) % len(palette)]


def figure_width(panel_columns):
    """One paper column for a single column of panels, two columns otherwise."""
    return ONE_COLUMN if panel_columns <= 1 else TWO_COLUMN


# How swept parameters are written on the figures (other sweep names are shown as they are).
SWEEP_LABELS = {
    "p_tp": "$p_{TP}$",
    "p_fp": "$p_{FP}$",
    "p_c": "$p_C$",
    "l_c": "$l_C$",
    "back_p_c": "back $p_C$",
    "front_p_c": "front $p_C$",
    "back_l_c": "back $l_C$",
    "front_l_c": "front $l_C$",
    "front_back_p_c": "front/back $p_C$",
}

LINE_STYLES = ["-", "--", ":", "-.", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 3)), (0, (8, 2))]


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def unique(values):
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return seen


def safe(name):
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", name).strip("-") or "scenario"


def number(text):
    return float(text) if text not in ("", None) else math.nan


def error_bar(row, metric, mean):
    """(low, high) of a summary.csv row's error bar: the report's 95 % bootstrap interval of the
    mean, or mean ± std with --error-bars std (or when the summary has no interval columns)."""
    if ERROR_BARS == "ci" and f"{metric}_ci_low" in row and row[f"{metric}_ci_low"] != "":
        return number(row[f"{metric}_ci_low"]), number(row[f"{metric}_ci_high"])
    std = number(row[f"{metric}_std"])
    return mean - std, mean + std


FORMATS = ["png", "pdf"]  # set by main() from --format, --dpi and --error-bars
DPI = 300
ERROR_BARS = "ci"
LABELS = {}
# Algorithms that ignore the prior: under p_TP / p_FP sweeps their curves coincide.
PRIOR_BLIND = {"lawnmower", "part-tsp0"}


def legend_label(algorithm):
    return LABELS.get(algorithm, algorithm)


def save(fig, out_dir, stem, written):
    for ext in FORMATS:
        path = os.path.join(out_dir, f"{stem}.{ext}")
        # At the figure's own size (no tight bounding box): 3.5 or 7 in wide, as laid out.
        fig.savefig(path, dpi=DPI if ext == "png" else None)
        written.append(path)
    plt.close(fig)


def colours(algorithms):
    """The colour of each algorithm of a figure: a planner's own; another algorithm's by a hash of
    its name, moved on along the palette while a colour of the figure already has it."""
    out = {a: PLANNER_COLOURS[a] for a in algorithms if a in PLANNER_COLOURS}
    palette = list(OKABE_ITO.values())
    for a in algorithms:
        if a in out:
            continue
        start = palette.index(planner_colour(a))
        free = [palette[(start + i) % len(palette)] for i in range(len(palette))
                if palette[(start + i) % len(palette)] not in out.values()]
        out[a] = free[0] if free else palette[start]
    return {a: out[a] for a in algorithms}


def algorithm_legend(fig, algorithms, colour):
    handles = [Line2D([0], [0], color=colour[a], lw=4) for a in algorithms]
    per_row = 4 if fig.get_figwidth() >= TWO_COLUMN else 2
    fig.legend(handles, [legend_label(a) for a in algorithms], loc="lower center",
               ncol=min(len(algorithms), per_row),
               frameon=False, bbox_to_anchor=(0.5, -0.01))


def fig6(summary, scenario, algorithms, colour, instances, out_dir, written):
    rows = [r for r in summary if r["scenario"] == scenario]
    s2s = unique(int(r["s2"]) for r in rows)
    ns = unique(int(r["uavs"]) for r in rows)
    width_in = figure_width(len(s2s))
    fig, axes = plt.subplots(2, len(s2s), figsize=(width_in, 0.6 * width_in if len(s2s) > 1 else
                                                   1.2 * width_in), squeeze=False, sharey="row")
    width = 0.8 / max(1, len(algorithms))
    for row, (metric, label) in enumerate([("T_c", "$T_c$ (s)"), ("T_m", "$T_m$ (s)")]):
        for col, s2 in enumerate(s2s):
            ax = axes[row][col]
            for k, a in enumerate(algorithms):
                xs, means, lows, highs, notes = [], [], [], [], []
                for i, n in enumerate(ns):
                    match = [r for r in rows if int(r["s2"]) == s2 and int(r["uavs"]) == n
                             and r["algorithm"] == a]
                    if not match or int(match[0][f"{metric}_count"]) == 0:
                        continue
                    r = match[0]
                    xs.append(i + (k - (len(algorithms) - 1) / 2) * width)
                    mean = number(r[f"{metric}_mean"])
                    low, high = error_bar(r, metric, mean)
                    means.append(mean)
                    lows.append(mean - low)
                    highs.append(high - mean)
                    notes.append(int(r["incomplete"]))
                if not xs:
                    continue
                ax.bar(xs, means, width, yerr=[lows, highs], color=colour[a], capsize=1.5,
                       error_kw={"elinewidth": 0.6, "capthick": 0.6}, label=a)
                for x, m, h, inc in zip(xs, means, highs, notes):
                    if inc:
                        ax.annotate(f"{inc} inc.", (x, m + h), ha="center", va="bottom",
                                    fontsize=MIN_FONT, color="black", rotation=90)
            ax.set_xticks(range(len(ns)))
            ax.set_xticklabels([str(n) for n in ns])
            ax.set_xlabel("fleet size n")
            if col == 0:
                ax.set_ylabel(label)
            ax.set_title(f"$s_2$ = {s2}")
            ax.grid(axis="x", visible=False)
    algorithm_legend(fig, algorithms, colour)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    save(fig, out_dir, f"fig6_{safe(scenario)}", written)


class Curves:
    """curves.csv indexed by cell: (scenario, s2, n, algorithm) -> arrays over t."""

    def __init__(self, rows):
        self.rows = rows
        grouped = {}
        for r in rows:
            key = (r["scenario"], int(r["s2"]), int(r["uavs"]), r["algorithm"])
            grouped.setdefault(key, []).append(r)
        self.cells = {}
        for key, cell_rows in grouped.items():
            self.cells[key] = {
                "t": np.array([int(r["t"]) for r in cell_rows]),
                **{f"{m}_{s}": np.array([number(r[f"{m}_{s}"]) for r in cell_rows])
                   for m in ("c", "m") for s in ("mean", "std")},
            }

    def __iter__(self):
        return iter(self.rows)

    def series(self, scenario, s2, n, algorithm, metric):
        cell = self.cells.get((scenario, s2, n, algorithm))
        if cell is None:
            empty = np.array([])
            return empty, empty, empty
        return cell["t"], cell[f"{metric}_mean"], cell[f"{metric}_std"]


def curve_series(curves, scenario, s2, n, algorithm, metric):
    return curves.series(scenario, s2, n, algorithm, metric)


def time_limit_shown(series, grid_end):
    """The time by which every mean curve shown has reached 100 %, with a margin."""
    last = 0
    for t, mean in series:
        if len(t) == 0:
            continue
        reached = np.nonzero(mean >= 100.0 - 1e-9)[0]
        last = max(last, t[reached[0]] if len(reached) else grid_end)
    return min(grid_end, last * 1.05 + 5) if last else grid_end


def fig7(curves, scenario, n, algorithms, colour, instances, grid_end, out_dir, written):
    s2s = unique(int(r["s2"]) for r in curves if r["scenario"] == scenario)
    width_in = figure_width(len(s2s))
    fig, axes = plt.subplots(2, len(s2s), figsize=(width_in, 0.6 * width_in if len(s2s) > 1 else
                                                   1.2 * width_in), squeeze=False, sharey=True)
    for row, (metric, label) in enumerate([("c", "$c(t)$ (%)"), ("m", "$m(t)$ (%)")]):
        shown = []
        for col, s2 in enumerate(s2s):
            ax = axes[row][col]
            for a in algorithms:
                t, mean, std = curve_series(curves, scenario, s2, n, a, metric)
                if len(t) == 0:
                    continue
                shown.append((t, mean))
                ax.plot(t, mean, color=colour[a], lw=1.0, label=legend_label(a))
                band = ~np.isnan(std)
                ax.fill_between(t[band], np.clip(mean - std, 0, 100)[band],
                                np.clip(mean + std, 0, 100)[band], color=colour[a], alpha=0.18,
                                lw=0)
            ax.set_xlabel("time t (s)")
            if col == 0:
                ax.set_ylabel(label)
            ax.set_title(f"$s_2$ = {s2}, n = {n}")
            ax.set_ylim(0, 102)
        limit = time_limit_shown(shown, grid_end)
        for ax in axes[row]:
            ax.set_xlim(0, limit)
    algorithm_legend(fig, algorithms, colour)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    save(fig, out_dir, f"fig7_{safe(scenario)}_n{n}", written)


def fig8(curves, s2, n, sweeps, plain, algorithms, colour, instances, grid_end, out_dir, written):
    panels = [("sweep", s) for s in sweeps] + [("scenario", p) for p in plain]
    cols = min(len(panels), 3)
    rows = math.ceil(len(panels) / cols)
    width_in = figure_width(cols)
    fig, axes = plt.subplots(rows, cols, figsize=(width_in, (width_in / cols) * 0.95 * rows + 0.5),
                             squeeze=False, sharey=True)
    shown = []  # every curve drawn: one x range shared by all panels, so they compare
    for index, (kind, name) in enumerate(panels):
        ax = axes[index // cols][index % cols]
        if kind == "sweep":
            scenarios = unique(r["scenario"] for r in curves if r["sweep"] == name)
            values = [next(r["sweep_value"] for r in curves if r["scenario"] == s)
                      for s in scenarios]
        else:
            scenarios, values = [name], [None]
        same_notes = []
        for a in algorithms:
            series = [curve_series(curves, sc, s2, n, a, "c") for sc in scenarios]
            series = [(i, t, mean) for i, (t, mean, _) in enumerate(series) if len(t) > 0]
            if not series:
                continue
            # A prior-blind algorithm whose curve is the same for every swept value (the sweep
            # changes only the prior) is drawn once, wide and translucent, instead of as several
            # lines on top of each other that would show only the last style.
            identical = len(series) > 1 and all(
                len(t) == len(series[0][1]) and np.allclose(mean, series[0][2], equal_nan=True)
                for _, t, mean in series[1:])
            if identical:
                _, t, mean = series[0]
                shown.append((t, mean))
                ax.plot(t, mean, color=colour[a], lw=3.0, alpha=0.35, solid_capstyle="butt")
                same_notes.append(legend_label(a))
                continue
            for i, t, mean in series:
                shown.append((t, mean))
                ax.plot(t, mean, color=colour[a], ls=LINE_STYLES[i % len(LINE_STYLES)], lw=1.0)
        ax.set_ylim(0, 102)
        ax.set_xlabel("time t (s)")
        if index % cols == 0:
            ax.set_ylabel("$c(t)$ (%)")
        if kind == "sweep":
            name_label = SWEEP_LABELS.get(name, name)
            ax.set_title(f"sweep of {name_label}")
            handles = [Line2D([0], [0], color="black", ls=LINE_STYLES[i % len(LINE_STYLES)])
                       for i in range(len(values))]
            texts = list(values)
            if same_notes:
                handles.append(Line2D([0], [0], color="0.5", lw=3.0, alpha=0.35))
                texts.append(f"{', '.join(same_notes)}: same for all")
            ax.legend(handles, texts, title=name_label, loc="lower right")
        else:
            ax.set_title(f"scenario {name}")
    limit = time_limit_shown(shown, grid_end)
    for index in range(len(panels)):
        axes[index // cols][index % cols].set_xlim(0, limit)
    for index in range(len(panels), rows * cols):
        axes[index // cols][index % cols].set_visible(False)
    algorithm_legend(fig, algorithms, colour)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    save(fig, out_dir, f"fig8_s2-{s2}_n{n}", written)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True, help="experiment results directory")
    parser.add_argument("--summary", required=True, help="summary.csv written by the report")
    parser.add_argument("--out", required=True, help="directory for the figures")
    parser.add_argument("--planners", default="",
                        help="comma-separated algorithms to draw, in this order (default: all)")
    parser.add_argument("--labels", default="",
                        help="comma-separated ALGORITHM=LABEL pairs for legends")
    parser.add_argument("--format", default="png,pdf",
                        help="comma-separated file types: png, pdf, svg (default %(default)s)")
    parser.add_argument("--dpi", type=int, default=300,
                        help="resolution of PNG files (default %(default)s)")
    parser.add_argument("--error-bars", choices=["ci", "std"], default="ci",
                        help="Fig. 6 error bars: the 95 %% bootstrap interval of the mean (ci, "
                             "default) or ± one standard deviation (std)")
    args = parser.parse_args()
    global DPI, FORMATS, ERROR_BARS
    DPI = args.dpi
    ERROR_BARS = args.error_bars
    FORMATS = [f for f in args.format.split(",") if f]
    for f in FORMATS:
        if f not in ("png", "pdf", "svg"):
            sys.exit(f"plot_report.py: --format: '{f}' is not png, pdf or svg")
    for pair in filter(None, args.labels.split(",")):
        key, sep, value = pair.partition("=")
        if not sep or not key or not value:
            sys.exit(f"plot_report.py: --labels: '{pair}' is not ALGORITHM=LABEL")
        LABELS[key] = value

    with open(os.path.join(args.results, "manifest.json"), encoding="utf-8") as f:
        manifest = json.load(f)
    config = manifest["config"]
    instances = len(config["seeds"])
    grid_end = config["curve"]["end"]
    summary = read_csv(args.summary)
    curves = Curves(read_csv(os.path.join(args.results, "curves.csv")))
    os.makedirs(args.out, exist_ok=True)

    algorithms = unique(r["algorithm"] for r in summary)
    if args.planners:
        wanted = [a for a in args.planners.split(",") if a]
        missing = [a for a in wanted if a not in algorithms]
        if missing:
            sys.exit(f"plot_report.py: --planners: no results for {', '.join(missing)} "
                     f"(the results hold {', '.join(algorithms)})")
        algorithms = wanted
    colour = colours(algorithms)
    plain = unique(r["scenario"] for r in summary if r["sweep"] == "")
    sweeps = unique(r["sweep"] for r in summary if r["sweep"] != "")
    written = []
    for scenario in plain:
        fig6(summary, scenario, algorithms, colour, instances, args.out, written)
        for n in unique(int(r["uavs"]) for r in curves if r["scenario"] == scenario):
            fig7(curves, scenario, n, algorithms, colour, instances, grid_end, args.out, written)
    if sweeps:
        pairs = unique((int(r["s2"]), int(r["uavs"])) for r in curves)
        for s2, n in pairs:
            fig8(curves, s2, n, sweeps, plain, algorithms, colour, instances, grid_end, args.out,
                 written)
    print(f"plot_report.py: wrote {len(written)} figure files to {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
