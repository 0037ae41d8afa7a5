#!/usr/bin/python3
"""Draws the figures of `hullinspect report` from an experiment's results.

Usage: /usr/bin/python3 plot_report.py --results RESULTS_DIR --summary SUMMARY_CSV --out FIG_DIR
           [--planners A,B,...] [--labels A=Label,...] [--format png,pdf] [--dpi 150]

Reads RESULTS_DIR/curves.csv and RESULTS_DIR/manifest.json and the report's summary.csv, and
writes, as PNG and PDF:
  fig6_<scenario>            T_c and T_m, mean ± std, grouped bars (x: fleet size, bars: algorithms),
                             one column per s2 (the paper's Fig. 6)
  fig7_<scenario>_n<n>       mean c(t) and m(t) with a ±1 std band, one column per s2 (Fig. 7)
  fig8_s2-<s2>_n<n>          mean c(t) per sweep (line style: swept value) and per plain scenario
                             (Fig. 8); only when the experiment has sweeps
Uses only Debian's python3-matplotlib and python3-numpy.
"""

import argparse
import csv
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
import numpy as np  # noqa: E402

plt.rcParams.update({
    "font.size": 10,
    "axes.titlesize": 11,
    "axes.labelsize": 10,
    "legend.fontsize": 9,
    "figure.titlesize": 12,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "pdf.fonttype": 42,
    "svg.fonttype": "none",  # text stays text in SVG figures (editable, searchable)
})

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


FORMATS = ["png", "pdf"]  # set by main() from --format and --dpi
DPI = 150
LABELS = {}
# Algorithms that ignore the prior: under p_TP / p_FP sweeps their curves coincide.
PRIOR_BLIND = {"lawnmower", "part-tsp0"}


def counted(count, noun):
    """'1 instance', '5 instances'."""
    return f"{count} {noun}{'' if count == 1 else 's'}"


def legend_label(algorithm):
    return LABELS.get(algorithm, algorithm)


def save(fig, out_dir, stem, written):
    for ext in FORMATS:
        path = os.path.join(out_dir, f"{stem}.{ext}")
        fig.savefig(path, dpi=DPI if ext == "png" else None, bbox_inches="tight")
        written.append(path)
    plt.close(fig)


def colours(algorithms):
    cmap = plt.get_cmap("tab10")
    return {a: cmap(i % 10) for i, a in enumerate(algorithms)}


def algorithm_legend(fig, algorithms, colour):
    handles = [Line2D([0], [0], color=colour[a], lw=6) for a in algorithms]
    fig.legend(handles, [legend_label(a) for a in algorithms], loc="lower center",
               ncol=min(len(algorithms), 6),
               frameon=False, bbox_to_anchor=(0.5, -0.01))


def fig6(summary, scenario, algorithms, colour, instances, out_dir, written):
    rows = [r for r in summary if r["scenario"] == scenario]
    s2s = unique(int(r["s2"]) for r in rows)
    ns = unique(int(r["uavs"]) for r in rows)
    fig, axes = plt.subplots(2, len(s2s), figsize=(3.6 * len(s2s) + 1.2, 6.6), squeeze=False,
                             sharey="row")
    width = 0.8 / max(1, len(algorithms))
    for row, (metric, label) in enumerate([("T_c", "$T_c$ (s)"), ("T_m", "$T_m$ (s)")]):
        for col, s2 in enumerate(s2s):
            ax = axes[row][col]
            for k, a in enumerate(algorithms):
                xs, means, stds, notes = [], [], [], []
                for i, n in enumerate(ns):
                    match = [r for r in rows if int(r["s2"]) == s2 and int(r["uavs"]) == n
                             and r["algorithm"] == a]
                    if not match or int(match[0][f"{metric}_count"]) == 0:
                        continue
                    r = match[0]
                    xs.append(i + (k - (len(algorithms) - 1) / 2) * width)
                    means.append(number(r[f"{metric}_mean"]))
                    stds.append(number(r[f"{metric}_std"]))
                    notes.append(int(r["incomplete"]))
                if not xs:
                    continue
                ax.bar(xs, means, width, yerr=stds, color=colour[a], capsize=2,
                       error_kw={"elinewidth": 0.8}, label=a)
                for x, m, s, inc in zip(xs, means, stds, notes):
                    if inc:
                        ax.annotate(f"{inc} inc.", (x, m + s), ha="center", va="bottom",
                                    fontsize=7, color="crimson", rotation=90)
            ax.set_xticks(range(len(ns)))
            ax.set_xticklabels([str(n) for n in ns])
            ax.set_xlabel("fleet size n")
            if col == 0:
                ax.set_ylabel(label)
            ax.set_title(f"$s_2$ = {s2}")
            ax.grid(axis="x", visible=False)
    fig.suptitle(f"{scenario}: inspection time $T_c$ and mission time $T_m$ "
                 f"(mean ± std over {counted(instances, 'instance')})")
    algorithm_legend(fig, algorithms, colour)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
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
    fig, axes = plt.subplots(2, len(s2s), figsize=(3.6 * len(s2s) + 1.2, 6.6), squeeze=False,
                             sharey=True)
    for row, (metric, label) in enumerate([("c", "$c(t)$, corrosion inspected (%)"),
                                           ("m", "$m(t)$, mission progress (%)")]):
        shown = []
        for col, s2 in enumerate(s2s):
            ax = axes[row][col]
            for a in algorithms:
                t, mean, std = curve_series(curves, scenario, s2, n, a, metric)
                if len(t) == 0:
                    continue
                shown.append((t, mean))
                ax.plot(t, mean, color=colour[a], lw=1.4, label=legend_label(a))
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
    fig.suptitle(f"{scenario}: mean $c(t)$ and $m(t)$ with ±1 std band "
                 f"({counted(instances, 'instance')}, n = {n})")
    algorithm_legend(fig, algorithms, colour)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    save(fig, out_dir, f"fig7_{safe(scenario)}_n{n}", written)


def fig8(curves, s2, n, sweeps, plain, algorithms, colour, instances, grid_end, out_dir, written):
    panels = [("sweep", s) for s in sweeps] + [("scenario", p) for p in plain]
    cols = min(len(panels), 4)
    rows = math.ceil(len(panels) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.0 * cols + 0.6, 3.6 * rows + 0.8),
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
                ax.plot(t, mean, color=colour[a], lw=4.0, alpha=0.35, solid_capstyle="butt")
                same_notes.append(legend_label(a))
                continue
            for i, t, mean in series:
                shown.append((t, mean))
                ax.plot(t, mean, color=colour[a], ls=LINE_STYLES[i % len(LINE_STYLES)], lw=1.3)
        ax.set_ylim(0, 102)
        ax.set_xlabel("time t (s)")
        if index % cols == 0:
            ax.set_ylabel("$c(t)$, corrosion inspected (%)")
        if kind == "sweep":
            name_label = SWEEP_LABELS.get(name, name)
            ax.set_title(f"sweep of {name_label}")
            handles = [Line2D([0], [0], color="black", ls=LINE_STYLES[i % len(LINE_STYLES)])
                       for i in range(len(values))]
            texts = list(values)
            if same_notes:
                handles.append(Line2D([0], [0], color="0.5", lw=4.0, alpha=0.35))
                texts.append(f"{', '.join(same_notes)}: same for all")
            ax.legend(handles, texts, title=name_label, loc="lower right", fontsize=8)
        else:
            ax.set_title(f"scenario {name}")
    limit = time_limit_shown(shown, grid_end)
    for index in range(len(panels)):
        axes[index // cols][index % cols].set_xlim(0, limit)
    for index in range(len(panels), rows * cols):
        axes[index // cols][index % cols].set_visible(False)
    fig.suptitle(f"Mean $c(t)$ under single-parameter sweeps ($s_2$ = {s2}, n = {n}, "
                 f"{counted(instances, 'instance')})")
    algorithm_legend(fig, algorithms, colour)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
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
    parser.add_argument("--dpi", type=int, default=150,
                        help="resolution of PNG files (default %(default)s)")
    args = parser.parse_args()
    global DPI, FORMATS
    DPI = args.dpi
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
