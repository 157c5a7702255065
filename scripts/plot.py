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
The charts are the Python package's (python/ccdlab/plot.py, `ccdlab.plot`), loaded from the
source tree beside this script: it needs matplotlib, not the compiled module.
"""
import argparse
import importlib.util
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (scripts importing this one draw with pyplot)
from results_json import BadInput, read_results, shown  # noqa: E402


def _charts_module():
    """python/ccdlab/plot.py of this source tree, loaded by path (importing the package
    would need its compiled module)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "python", "ccdlab", "plot.py")
    spec = importlib.util.spec_from_file_location("ccdlab_plot_charts", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


charts = _charts_module()
# The helpers scripts/plot_study.py and scripts/spin_model.py draw with.
by_method, style, title, y_axis, log_axis, hz_axis = (charts.by_method, charts.style, charts.title,
                                                      charts.y_axis, charts.log_axis, charts.hz_axis)
CHARTS = charts.CHARTS
COST = charts.COST


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


def main(argv=None):
    ap = argparse.ArgumentParser(description="Charts of a ccdlab results file (PNG and SVG).")
    ap.add_argument("results", help="a ccdlab-results/2 file written by `ccdlab run`")
    ap.add_argument("-o", "--output", help="output folder (default: RESULTS-plots next to the file)")
    ap.add_argument("--format", default="png,svg", help="comma-separated formats (default png,svg)")
    ap.add_argument("--cost", default="wall", choices=sorted(COST),
                    help="cost axis: wall-clock (default) or the method thread's CPU time")
    args = ap.parse_args(argv)
    cost_field = COST[args.cost][0]
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
    for stem, fig in charts.charts(res, cost=args.cost).items():
        for fmt in formats:
            p = os.path.join(outdir, f"{stem}.{fmt}")
            fig.savefig(p, dpi=130)
            print(p)


if __name__ == "__main__":
    main()
