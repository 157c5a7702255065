#!/usr/bin/python3
"""Charts of a ccdlab results file (ccdlab-results/2), as PNG and SVG.

usage: /usr/bin/python3 scripts/plot.py RESULTS.json [-o DIR] [--format png,svg] [--cost wall|cpu]

Draws, into DIR (default: RESULTS without .json, plus "-plots"):
  missed.{png,svg}        missed fraction against dt, one line per method
  false_positives.*       false positives per step against dt
  cost.*                  seconds per simulated second against dt
  speed_accuracy.*        left: cost against missed fraction, every (method, dt) a point,
                          the Pareto front drawn, zero-miss methods marked; right: each
                          method's cost at its cheapest zero-miss dt (bars, labelled
                          with that dt), so that zero-miss methods stay readable
  penetration.*           penetration depth at detection against dt (discrete methods)
Cost is wall-clock seconds per simulated second (seconds_per_simulated_second), or with
--cost cpu the CPU time of the thread that ran the method (cpu_seconds_per_simulated_second:
what small runs are compared by on a loaded machine). Timestep axes also show the frequency 1/dt (Hz) on top. Prints each path. Needs Debian's python3-matplotlib (run with /usr/bin/python3).
Reads results only; exits with status 2 on a file that is not a results file.
"""
import argparse
import os
import sys

import matplotlib
import numpy as np
from results_json import BadInput, by_method, read_results, shown

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CHARTS = ("missed", "false_positives", "cost", "speed_accuracy", "penetration")
# The record field the cost charts read and its axis label (--cost).
COST = {"wall": ("seconds_per_simulated_second", "seconds of computation per simulated second"),
        "cpu": ("cpu_seconds_per_simulated_second", "CPU seconds per simulated second")}
cost_field, cost_label = COST["wall"]


def cost_of(r):
    return r[cost_field]
MARKERS = "osD^v<>pP*Xh"


def fail(msg):
    print(f"plot.py: {msg}", file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        res = read_results(path)
    except BadInput as e:
        fail(str(e))
    records = res.get("records")
    if not isinstance(records, list) or not records:
        fail(f"{shown(path)}: records: no records to plot")
    for key in ("experiment", "scene", "truth"):
        if not isinstance(res.get(key), dict):
            fail(f"{shown(path)}: {key}: must be an object")
    for i, r in enumerate(records):
        if not isinstance(r, dict):
            fail(f"{shown(path)}: records[{i}]: must be an object")
        for k in ("method", "dt", "missed_fraction", "false_positives_per_step",
                  "seconds_per_simulated_second", "continuous", "max_penetration"):
            if k not in r:
                fail(f"{shown(path)}: records[{i}].{k}: missing field")
        if not isinstance(r["method"], str):
            fail(f"{shown(path)}: records[{i}].method: must be a string")
        r["method"] = r["method"].replace("$", r"\$")  # a label, not matplotlib's mathtext
        for k in ("dt", "missed_fraction", "false_positives_per_step", "seconds_per_simulated_second",
                  "max_penetration"):  # drawn on log axes: limits and ticks must fit a double
            v = r[k]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (v == 0 or 1e-300 <= abs(v) <= 1e300):
                fail(f"{shown(path)}: records[{i}].{k}: must be 0 or a number of magnitude in [1e-300, 1e300]")
        if r["dt"] <= 0:
            fail(f"{shown(path)}: records[{i}].dt: must be > 0")
    return res


def style(i):
    cmap = plt.get_cmap("tab20" if i >= 10 else "tab10")
    return dict(color=cmap(i % cmap.N), marker=MARKERS[i % len(MARKERS)])


def title(res):
    s = res["scene"]
    t = res["truth"]
    name = res["experiment"].get("name", "experiment")
    return (f"{name}: {s['bodies']} bodies, {s['motion'].replace('_', ' ')} motion, "
            f"horizon {s['horizon']:g} s, {t['events']} contact events")


def finish(fig, ax, res, outdir, stem, formats, legend=True):
    ax.set_title(title(res), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    if legend:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False,
                  ncol=1 if len(ax.get_legend_handles_labels()[0]) <= 18 else 2)
    fig.tight_layout()
    paths = []
    for fmt in formats:
        p = os.path.join(outdir, f"{stem}.{fmt}")
        fig.savefig(p, dpi=130)
        paths.append(p)
    plt.close(fig)
    return paths


def line_chart(res, outdir, formats, stem, key, ylabel, methods=None, yscale="symlog"):
    fig, ax = plt.subplots(figsize=(10, 5.5))
    groups = by_method(res["records"])
    names = list(groups)
    for i, name in enumerate(names):
        if methods is not None and name not in methods:
            continue
        rs = groups[name]
        ax.plot([r["dt"] for r in rs], [key(r) for r in rs], label=name, linewidth=1.4,
                markersize=4, **style(i))
    log_axis(ax, "x", [r["dt"] for r in res["records"]])
    y_axis(ax, [key(r) for r in res["records"] if methods is None or r["method"] in methods], yscale)
    ax.set_xlabel("timestep dt (s)")
    ax.set_ylabel(ylabel)
    hz_axis(ax)
    return finish(fig, ax, res, outdir, stem, formats)


def log_limits(values):
    """Limits of a log axis around the values > 0 (a factor 2 beyond each end, so that a
    single value sits mid-axis); None when no value is > 0."""
    positive = [v for v in values if v > 0]
    return (min(positive) / 2, max(positive) * 2) if positive else None


def log_axis(ax, which, values):
    """A log axis around `values` (every one > 0), its limits set here: matplotlib's own
    margins collapse on a single value."""
    limits = log_limits(values)
    (ax.set_xscale if which == "x" else ax.set_yscale)("log")
    if limits:
        (ax.set_xlim if which == "x" else ax.set_ylim)(*limits)


def y_axis(ax, ys, yscale):
    """The value axis: "symlog" (0 at the bottom, a log scale above the smallest value > 0)
    or "log" (values <= 0 not drawn); linear from 0 with a note when no value is > 0, as
    when nothing was missed, nothing was a false positive or every cost is 0."""
    limits = log_limits(ys)
    if limits is None:
        ax.set_ylim(-0.05, 1.0)
        ax.text(0.5, 0.5, "every value is 0", transform=ax.transAxes, ha="center", va="center", fontsize=12,
                color="gray")
    elif yscale == "symlog":
        ax.set_yscale("symlog", linthresh=limits[0] * 2)
        ax.set_ylim(0, limits[1])
    else:
        ax.set_yscale(yscale)
        ax.set_ylim(*limits)


def hz_axis(ax):
    """A top axis labelling the timesteps as frequencies (1 / dt, Hz)."""
    inverse = (lambda x: 1.0 / np.maximum(x, 1e-300), lambda x: 1.0 / np.maximum(x, 1e-300))
    top = ax.secondary_xaxis("top", functions=inverse)
    top.set_xlabel("frequency 1/dt (Hz)", fontsize=9)


def dt_text(r):
    """A record's timestep as people say it: "60 Hz" when given as a frequency, else seconds."""
    hz = r.get("hz", 0)
    if hz and float(hz).is_integer() and abs(1.0 / hz - r["dt"]) <= 1e-12 * r["dt"] and hz >= 1:
        return f"{hz:g} Hz"
    return f"dt {r['dt']:.3g} s"


def pareto(points):
    """Points (cost, missed) not dominated by another (lower or equal on both, lower on one)."""
    front = []
    for p in sorted(points):
        if not front or p[1] < front[-1][1]:
            front.append(p)
    return front


def speed_accuracy(res, outdir, formats):
    fig, (ax, bars) = plt.subplots(1, 2, figsize=(15, 6), gridspec_kw={"width_ratios": [3, 2]})
    groups = by_method(res["records"])
    zero_miss_panel(bars, groups)
    pts = []
    for i, (name, rs) in enumerate(groups.items()):
        zero = all(r["missed"] == 0 for r in rs)
        st = style(i)
        xs = [cost_of(r) for r in rs]
        ys = [r["missed_fraction"] for r in rs]
        pts += list(zip(xs, ys))
        ax.scatter(xs, ys, s=55 if zero else 22, color=st["color"], marker="*" if zero else st["marker"],
                   edgecolors="black" if zero else "none", linewidths=0.6,
                   label=name + (" (zero misses)" if zero else ""), zorder=3)
    front = pareto(pts)
    ax.plot([p[0] for p in front], [p[1] for p in front], color="black", linewidth=1.0,
            linestyle="--", label="Pareto front", zorder=2)
    if log_limits([p[0] for p in pts]):
        log_axis(ax, "x", [p[0] for p in pts])
    y_axis(ax, [p[1] for p in pts], "symlog")
    ax.set_xlabel(f"cost ({cost_label})")
    ax.set_ylabel("missed fraction of contact events")
    ax.legend(fontsize=7, loc="upper right", frameon=True, framealpha=0.85,
              ncol=1 if len(groups) <= 12 else 2)
    return finish(fig, ax, res, outdir, "speed_accuracy", formats, legend=False)


def zero_miss_panel(ax, groups):
    """Per method, the cost at its cheapest zero-miss point, cheapest first; methods that
    miss at every dt are listed at the bottom without a bar."""
    rows = []
    for i, (name, rs) in enumerate(groups.items()):
        zero = [r for r in rs if r["missed"] == 0]
        best = min(zero, key=cost_of) if zero else None
        rows.append((cost_of(best) if best else float("inf"), name, i, best))
    rows.sort(key=lambda row: (row[0], row[1]))
    finite = [row[0] for row in rows if row[0] != float("inf") and row[0] > 0]
    for y, (cost, name, i, best) in enumerate(rows):
        if best is None:
            ax.text(0.01, y, "misses at every dt", transform=ax.get_yaxis_transform(), va="center",
                    fontsize=8, color="gray")
            continue
        ax.barh(y, cost, color=style(i)["color"], height=0.7)
        ax.text(cost, y, "  " + dt_text(best), va="center", fontsize=8)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([row[1] for row in rows], fontsize=8)
    ax.invert_yaxis()
    if finite and len(finite) == sum(row[0] != float("inf") for row in rows):  # a log axis: every cost > 0
        ax.set_xscale("log")
        ax.set_xlim(min(finite) / 3, max(finite) * 30)
    ax.set_xlabel("cost at the cheapest zero-miss dt (" + ("CPU " if cost_field.startswith("cpu") else "")
                  + "s per simulated s)")
    ax.set_title("cost of missing nothing", fontsize=10)
    ax.grid(True, axis="x", which="both", alpha=0.3)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Charts of a ccdlab results file (PNG and SVG).")
    ap.add_argument("results", help="a ccdlab-results/2 file written by `ccdlab run`")
    ap.add_argument("-o", "--output", help="output folder (default: RESULTS-plots next to the file)")
    ap.add_argument("--format", default="png,svg", help="comma-separated formats (default png,svg)")
    ap.add_argument("--cost", default="wall", choices=sorted(COST),
                    help="cost axis: wall-clock (default) or the method thread's CPU time")
    args = ap.parse_args(argv)
    global cost_field, cost_label
    cost_field, cost_label = COST[args.cost]
    res = load(args.results)
    for i, r in enumerate(res["records"]):
        if cost_field not in r:
            fail(f"{args.results}: records[{i}].{cost_field}: missing field (--cost {args.cost})")
    outdir = args.output or os.path.splitext(args.results)[0] + "-plots"
    formats = [f for f in args.format.split(",") if f]
    for f in formats:
        if f not in ("png", "svg", "pdf"):
            fail(f"--format: unknown format '{f}' (png, svg, pdf)")
    os.makedirs(outdir, exist_ok=True)
    paths = []
    paths += line_chart(res, outdir, formats, "missed", lambda r: r["missed_fraction"],
                        "missed fraction of contact events")
    paths += line_chart(res, outdir, formats, "false_positives", lambda r: r["false_positives_per_step"],
                        "false positives per step")
    paths += line_chart(res, outdir, formats, "cost", cost_of,
                        "cost (" + ("CPU " if args.cost == "cpu" else "") + "s per simulated s)", yscale="log")
    paths += speed_accuracy(res, outdir, formats)
    discrete = {r["method"] for r in res["records"] if not r["continuous"]}
    if discrete:
        paths += line_chart(res, outdir, formats, "penetration", lambda r: r["max_penetration"],
                            "largest penetration depth at detection", methods=discrete)
    for p in paths:
        print(p)


if __name__ == "__main__":
    main()
