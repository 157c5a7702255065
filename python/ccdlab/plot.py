"""Charts of a run's results as matplotlib Figures (docs/python.md): `ccdlab.plot.missed(results)`
and the others below take a `ccdlab.Results` (or any ccdlab-results/2 dict) and return a
Figure; nothing is written (`fig.savefig(...)` is the caller's). `scripts/plot.py` draws its
files with these functions. This module needs matplotlib and numpy only (not the compiled
module), so the script loads it from the source tree.

Cost is wall-clock seconds per simulated second (`cost="wall"`), or the CPU time of the
thread that ran the method (`cost="cpu"`). Timestep axes also show the frequency 1/dt (Hz)
on top."""
import re

import matplotlib
import numpy as np
from matplotlib.figure import Figure

CHARTS = ("missed", "false_positives", "cost", "speed_accuracy", "penetration")
# The record field the cost charts read and its axis label.
COST = {"wall": ("seconds_per_simulated_second", "seconds of computation per simulated second"),
        "cpu": ("cpu_seconds_per_simulated_second", "CPU seconds per simulated second")}
MARKERS = "osD^v<>pP*Xh"


def by_method(records):
    """Records grouped by method (in first-seen order), each group sorted by dt."""
    out = {}
    for r in records:
        out.setdefault(r["method"], []).append(r)
    for rs in out.values():
        rs.sort(key=lambda r: r["dt"])
    return out


def label(name):
    """A method name as a label: a `$` not already escaped is escaped (not matplotlib's mathtext)."""
    return re.sub(r"(?<!\\)\$", r"\\$", name)


def cost_field(cost):
    """The record field and axis label of `cost` ("wall" or "cpu")."""
    if cost not in COST:
        raise ValueError(f"cost: must be one of {', '.join(sorted(COST))}, got {cost!r}")
    return COST[cost]


def style(i):
    """The colour and marker of the i-th method."""
    cmap = matplotlib.colormaps["tab20" if i >= 10 else "tab10"]
    return dict(color=cmap(i % cmap.N), marker=MARKERS[i % len(MARKERS)])


def title(res):
    s = res["scene"]
    t = res["truth"]
    name = res["experiment"].get("name", "experiment")
    return (f"{name}: {s['bodies']} bodies, {s['motion'].replace('_', ' ')} motion, "
            f"horizon {s['horizon']:g} s, {t['events']} contact events")


def finish(fig, ax, res, legend=True):
    ax.set_title(title(res), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    if legend:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False,
                  ncol=1 if len(ax.get_legend_handles_labels()[0]) <= 18 else 2)
    fig.tight_layout()
    return fig


def _records(res):
    records = res.get("records") if isinstance(res, dict) else None
    if not isinstance(records, list) or not records:
        raise ValueError("results: records: no records to plot (a ccdlab-results/2 dict, as ccdlab.run returns)")
    return records


def line_chart(res, key, ylabel, methods=None, yscale="symlog"):
    """One line per method (those in `methods` when given) of key(record) against dt."""
    records = _records(res)
    fig = Figure(figsize=(10, 5.5))
    ax = fig.subplots()
    for i, (name, rs) in enumerate(by_method(records).items()):
        if methods is not None and name not in methods:
            continue
        ax.plot([r["dt"] for r in rs], [key(r) for r in rs], label=label(name), linewidth=1.4,
                markersize=4, **style(i))
    log_axis(ax, "x", [r["dt"] for r in records])
    y_axis(ax, [key(r) for r in records if methods is None or r["method"] in methods], yscale)
    ax.set_xlabel("timestep dt (s)")
    ax.set_ylabel(ylabel)
    hz_axis(ax)
    return finish(fig, ax, res)


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


def missed(results):
    """The missed fraction of contact events against dt, one line per method."""
    return line_chart(results, lambda r: r["missed_fraction"], "missed fraction of contact events")


def false_positives(results):
    """False positives per step against dt, one line per method."""
    return line_chart(results, lambda r: r["false_positives_per_step"], "false positives per step")


def cost(results, *, cost="wall"):
    """Seconds of computation per simulated second against dt, one line per method (log axis)."""
    field, _ = cost_field(cost)
    return line_chart(results, lambda r: r[field],
                      "cost (" + ("CPU " if cost == "cpu" else "") + "s per simulated s)", yscale="log")


_cost = cost  # the chart, where a `cost` argument hides it


def penetration(results):
    """The largest penetration depth at detection against dt, one line per discrete method
    (a ValueError when every method is continuous)."""
    discrete = {r["method"] for r in _records(results) if not r["continuous"]}
    if not discrete:
        raise ValueError("results: penetration: every method is continuous (no penetration to draw)")
    return line_chart(results, lambda r: r["max_penetration"], "largest penetration depth at detection",
                      methods=discrete)


def speed_accuracy(results, *, cost="wall"):
    """Left: cost against missed fraction, every (method, dt) a point, the Pareto front drawn,
    zero-miss methods marked; right: each method's cost at its cheapest zero-miss dt (bars,
    labelled with that dt)."""
    field, cost_label = cost_field(cost)
    fig = Figure(figsize=(15, 6))
    ax, bars = fig.subplots(1, 2, gridspec_kw={"width_ratios": [3, 2]})
    groups = by_method(_records(results))
    zero_miss_panel(bars, groups, field)
    pts = []
    for i, (name, rs) in enumerate(groups.items()):
        zero = all(r["missed"] == 0 for r in rs)
        st = style(i)
        xs = [r[field] for r in rs]
        ys = [r["missed_fraction"] for r in rs]
        pts += list(zip(xs, ys))
        ax.scatter(xs, ys, s=55 if zero else 22, color=st["color"], marker="*" if zero else st["marker"],
                   edgecolors="black" if zero else "none", linewidths=0.6,
                   label=label(name) + (" (zero misses)" if zero else ""), zorder=3)
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
    return finish(fig, ax, results, legend=False)


def zero_miss_panel(ax, groups, field):
    """Per method, the cost at its cheapest zero-miss point, cheapest first; methods that
    miss at every dt are listed at the bottom without a bar."""
    rows = []
    for i, (name, rs) in enumerate(groups.items()):
        zero = [r for r in rs if r["missed"] == 0]
        best = min(zero, key=lambda r: r[field]) if zero else None
        rows.append((best[field] if best else float("inf"), name, i, best))
    rows.sort(key=lambda row: (row[0], row[1]))
    finite = [row[0] for row in rows if row[0] != float("inf") and row[0] > 0]
    for y, (c, name, i, best) in enumerate(rows):
        if best is None:
            ax.text(0.01, y, "misses at every dt", transform=ax.get_yaxis_transform(), va="center",
                    fontsize=8, color="gray")
            continue
        ax.barh(y, c, color=style(i)["color"], height=0.7)
        ax.text(c, y, "  " + dt_text(best), va="center", fontsize=8)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([label(row[1]) for row in rows], fontsize=8)
    ax.invert_yaxis()
    if finite and len(finite) == sum(row[0] != float("inf") for row in rows):  # a log axis: every cost > 0
        ax.set_xscale("log")
        ax.set_xlim(min(finite) / 3, max(finite) * 30)
    ax.set_xlabel("cost at the cheapest zero-miss dt (" + ("CPU " if field.startswith("cpu") else "")
                  + "s per simulated s)")
    ax.set_title("cost of missing nothing", fontsize=10)
    ax.grid(True, axis="x", which="both", alpha=0.3)


def charts(results, *, cost="wall"):
    """Every chart of the results, {name: Figure} in the order of CHARTS; penetration only
    when some method is discrete."""
    out = {"missed": missed(results), "false_positives": false_positives(results),
           "cost": _cost(results, cost=cost), "speed_accuracy": speed_accuracy(results, cost=cost)}
    if any(not r["continuous"] for r in _records(results)):
        out["penetration"] = penetration(results)
    return out
