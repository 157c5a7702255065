#!/usr/bin/python3
"""Charts and a summary table of one stability study (docs/studies.md), combining the
results files of its experiments (ccdlab-results/2).

usage: /usr/bin/python3 scripts/plot_study.py STUDY RESULTS.json... [-o DIR] [--format png,svg]
                                              [--ccdlab PATH]

STUDY is one of: tunnelling, sap-coherence, equal-endpoints, grazing, precision,
bound-violation, mixed-sizes, scaling, scheduling, spinning, fit, cloth. Draws STUDY-*.{png,...} into DIR (default
results/studies/STUDY/plots), prints a Markdown summary of the key numbers on standard
output, then each chart's path. Results files may come in any order: each study sorts
them by its own variable (N, offset, ratio...), read from the results themselves.
equal-endpoints also regenerates each lattice scene with `ccdlab scene` (--ccdlab, default
build/ccdlab) to count the box pairs that closed and strict comparisons report.
Reads results only (and writes scenes to a temporary folder); exits with status 2 on bad input.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot  # noqa: E402  (sets the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402

STUDIES = ("tunnelling", "sap-coherence", "equal-endpoints", "grazing", "precision",
           "bound-violation", "mixed-sizes", "scaling", "scheduling", "spinning", "fit", "cloth", "thin-obstacles")


def fail(msg):
    print(f"plot_study.py: {msg}", file=sys.stderr)
    sys.exit(2)


def source(res):
    """The generator parameters of the results' scene ({} for a scene file)."""
    s = res["scene"].get("source")
    return s if isinstance(s, dict) else {}


def per_step(r, key):
    return r[key] / r["steps"] if r["steps"] else 0.0


def swaps_per_step(r):
    """The broad phase's "swaps" counter per step (0 for methods without it)."""
    return r.get("counters", {}).get("swaps", 0) / r["steps"] if r["steps"] else 0.0


def save(fig, outdir, stem, formats):
    fig.tight_layout()
    paths = []
    for fmt in formats:
        p = os.path.join(outdir, f"{stem}.{fmt}")
        fig.savefig(p, dpi=100)
        paths.append(p)
    plt.close(fig)
    return paths


def log_y(ax):
    """A log value axis over the lines `ax` draws; linear with a note when none of their
    values is > 0 (plot.y_axis): an all-zero series has nothing to show on a log scale."""
    ys = [float(y) for line in ax.get_lines() for y in line.get_ydata() if y is not None and float(y) == float(y)]
    plot.y_axis(ax, ys, "log")


def legend(ax, **kw):
    ax.legend(fontsize=8, frameon=False, **kw)


def dts(res):
    return sorted({r["dt"] for r in res["records"]}, reverse=True)


def fmt_dt(dt):
    return f"{dt:.3g}"


def method_order(results):
    names = []
    for res in results:
        for r in res["records"]:
            if r["method"] not in names:
                names.append(r["method"])
    return names


def record(res, method, dt):
    for r in res["records"]:
        if r["method"] == method and r["dt"] == dt:
            return r
    return None


def self_check_line(results):
    bad = [(res["experiment"]["name"], r["method"], r["dt"]) for res in results for r in res["records"]
           if not r["self_check"]["ok"]]
    unexpected = sum(r["self_check"]["unexpected_contacts"] for res in results for r in res["records"])
    undetected = sum(r["self_check"]["undetected_sampled_events"] for res in results for r in res["records"])
    return (f"self-check: {len(bad)} record(s) not ok; unexpected contacts {unexpected}, "
            f"undetected sampled events {undetected}")


# ---------------------------------------------------------------------------- tunnelling

def tunnelling(results, outdir, formats, study="tunnelling"):
    res = results[0]
    out = [f"### {study}: {plot.title(res)}", "",
           "missed events per method (columns: dt, s)", ""]
    ds = dts(res)
    out.append("| method | conservative | " + " | ".join(fmt_dt(d) for d in ds) + " |")
    out.append("|---|---|" + "---|" * len(ds))
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for i, (name, rs) in enumerate(plot.by_method(res["records"]).items()):
        cont = rs[0]["continuous"]
        ax.plot([r["dt"] for r in rs], [r["missed"] for r in rs], label=name, linewidth=1.3, markersize=4,
                linestyle="-" if cont else "--", **plot.style(i))
        row = {r["dt"]: r["missed"] for r in rs}
        out.append(f"| {name} | {'yes' if rs[0]['conservative'] and cont else 'no'} | "
                   + " | ".join(str(row.get(d, "")) for d in ds) + " |")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("timestep dt (s)")
    ax.set_ylabel("missed contact events")
    ax.set_title(f"{study}: {res['truth']['events']} events; dashed: discrete", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    legend(ax, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    out += ["", self_check_line(results)]
    return out, save(fig, outdir, f"{study}-missed-events", formats)


# ---------------------------------------------------------------------------- sap-coherence

def swap_budget(broad_phase, n):
    """Swaps per step above which the broad phase rebuilds (ccd/broad_phase/sap.hpp,
    sort_sweep.hpp): sap 2 * 6n * bit_width(2n) + 64 (endpoints, three axes), sweep
    32 n + 64 (starts, one axis)."""
    if broad_phase == "sap":
        return 2 * 6 * n * (2 * n).bit_length() + 64
    return 32 * n + 64


COHERENT = ("sap", "sweep")  # broad phases that keep a sorted order between steps


def sap_coherence(results, outdir, formats):
    results = sorted(results, key=lambda r: r["scene"]["bodies"])
    present = [b for b in COHERENT if any(r["broad_phase"] == b for res in results for r in res["records"])]
    head = "| N | dt (s) | steps | "
    rule = "|---|---|---|"
    for b in present:
        head += f"{b} swaps / step | {b} rebuilds | {b} ms / step | {b} first step ms | "
        rule += "---|---|---|---|"
    head += "grid ms / step | grid first step ms |"
    rule += "---|---|"
    out = ["### sap-coherence: rain, swaps and broad-phase time against dt and N", "",
           "swap budgets per step (rebuild above): "
           + "; ".join(f"{b} " + ", ".join(f"{swap_budget(b, res['scene']['bodies'])} (N = {res['scene']['bodies']})"
                                             for res in results) for b in present), "", head, rule]
    fig, axes = plt.subplots(1, len(present) + 1, figsize=(5.2 * (len(present) + 1), 4.6), squeeze=False)
    axes = axes[0]
    tax = axes[-1]
    for i, res in enumerate(results):
        n = res["scene"]["bodies"]
        st = plot.style(i)
        by = {b: sorted([r for r in res["records"] if r["broad_phase"] == b], key=lambda r: r["dt"]) for b in present}
        grid = {r["dt"]: r for r in res["records"] if r["method"] == "aabb/grid"}
        for ax, b in zip(axes, present):
            rs = by[b]
            xs = [r["dt"] for r in rs]
            ax.plot(xs, [swaps_per_step(r) for r in rs], label=f"N = {n}", **st)
            ax.axhline(swap_budget(b, n), color=st["color"], linestyle=":", linewidth=1)
            lost = [r for r in rs if r["rebuilds"] > 1]
            if lost:
                ax.scatter([r["dt"] for r in lost], [swaps_per_step(r) for r in lost], s=90,
                           facecolors="none", edgecolors="red", zorder=4)
        for b, ls in zip(present, ("-", "--")):
            rs = by[b]
            tax.plot([r["dt"] for r in rs], [per_step(r, "broad_seconds") * 1e3 for r in rs], linestyle=ls,
                     label=f"{b}, N = {n}", color=st["color"], marker=st.get("marker", "o"), markersize=4)
        xs = sorted({r["dt"] for b in present for r in by[b]})
        g = [grid[d] for d in xs if d in grid]
        if g:
            tax.plot([r["dt"] for r in g], [per_step(r, "broad_seconds") * 1e3 for r in g], linestyle=":",
                     label=f"grid, N = {n}", color=st["color"], marker="x")
        for d in reversed(xs):
            row = [by_dt for by_dt in (next((r for r in by[b] if r["dt"] == d), None) for b in present)]
            steps = next(r["steps"] for r in row if r is not None)
            cells = []
            for r in row:
                if r is None:
                    cells += ["", "", "", ""]
                else:
                    cells += [f"{swaps_per_step(r):.0f}", str(r["rebuilds"]),
                              f"{per_step(r, 'broad_seconds') * 1e3:.3g}", f"{r['first_broad_seconds'] * 1e3:.3g}"]
            gr = grid.get(d)
            cells += ([f"{per_step(gr, 'broad_seconds') * 1e3:.3g}", f"{gr['first_broad_seconds'] * 1e3:.3g}"]
                      if gr else ["", ""])
            out.append(f"| {n} | {fmt_dt(d)} | {steps} | " + " | ".join(cells) + " |")
    for ax in axes:
        ax.set_xscale("log")
        log_y(ax)
        ax.set_xlabel("timestep dt (s)")
        ax.grid(True, which="both", alpha=0.3)
    what = {"sap": "endpoint swaps, 3 axes", "sweep": "start swaps, 1 axis"}
    for ax, b in zip(axes, present):
        ax.set_ylabel("insertion-sort swaps per step")
        ax.set_title(f"{b}: {what[b]} per step\n(dotted: rebuild budget; red rings: coherence lost)", fontsize=9)
        legend(ax)
    tax.set_ylabel("broad-phase ms per step")
    tax.set_title("broad phase per step: " + ", ".join(f"{b} {ls}" for b, ls in zip(present, ("solid", "dashed")))
                  + ", grid dotted", fontsize=9)
    legend(tax, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    out += ["", self_check_line(results)]
    return out, save(fig, outdir, "sap-coherence", formats)


# ---------------------------------------------------------------------------- equal-endpoints

def lattice_pair_counts(res, ccdlab):
    """Box pairs at t = 0 (box = centre -+ r) with closed (<=) and strict (<) overlap on all
    three axes, and sphere pairs with |d| <= R and |d| < R, on the experiment's scene."""
    src = source(res)
    if src.get("generator") != "lattice":
        return None
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "scene.json")
        args = [ccdlab, "scene", "lattice"]
        for k, v in src.items():
            if k == "generator":
                continue
            v = ",".join(repr(float(x)) for x in v) if isinstance(v, list) else repr(v)
            args.append(f"{k}={v}")
        try:
            subprocess.run(args + ["-o", path], check=True, stdout=subprocess.DEVNULL)
        except (OSError, subprocess.CalledProcessError) as e:
            fail(f"could not regenerate the lattice scene with {ccdlab}: {e}")
        with open(path) as f:
            scene = json.load(f)
    bodies = scene["bodies"]
    import numpy as np
    p = np.array([b["position"] for b in bodies], dtype=float)
    r = np.array([b["radius"] for b in bodies], dtype=float)
    lo, hi = p - r[:, None], p + r[:, None]
    iu = np.triu_indices(len(bodies), 1)
    closed = np.ones(len(iu[0]), dtype=bool)
    strict = np.ones(len(iu[0]), dtype=bool)
    for a in range(3):
        la, ha = lo[iu[0], a], hi[iu[0], a]
        lb, hb = lo[iu[1], a], hi[iu[1], a]
        closed &= (lb <= ha) & (la <= hb)
        strict &= (lb < ha) & (la < hb)
    d2 = ((p[iu[0]] - p[iu[1]]) ** 2).sum(axis=1)
    rr = (r[iu[0]] + r[iu[1]]) ** 2
    return {"boxes_closed": int(closed.sum()), "boxes_strict": int(strict.sum()),
            "spheres_closed": int((d2 <= rr).sum()), "spheres_strict": int((d2 < rr).sum())}


def equal_endpoints(results, outdir, formats, ccdlab):
    results = sorted(results, key=lambda r: r["experiment"]["name"], reverse=True)  # rest first
    out = ["### equal-endpoints: lattice of exactly touching spheres", ""]
    fig, axes = plt.subplots(1, len(results), figsize=(5.5 * len(results), 4.8), squeeze=False)
    for ax, res in zip(axes[0], results):
        name = res["experiment"]["name"]
        ev = res["truth"]["events"]
        counts = lattice_pair_counts(res, ccdlab)
        out.append(f"**{name}**: {res['scene']['bodies']} bodies, {ev} truth events "
                   f"({res['truth']['tangent_events']} tangent), {res['truth']['pairs']} pairs")
        if counts:
            out.append(f"at t = 0: box pairs closed (<=) {counts['boxes_closed']}, strict (<) "
                       f"{counts['boxes_strict']}; sphere pairs |d| <= R {counts['spheres_closed']}, "
                       f"|d| < R {counts['spheres_strict']}")
        ds = dts(res)
        out += ["", "cells: pairs confirmed per sample or step (mean) / events missed; the events in "
                "progress at t = 0 are initial contacts, not detections", "",
                "| method | " + " | ".join(f"dt {fmt_dt(d)}" for d in ds) + " |",
                "|---|" + "---|" * len(ds)]
        methods = method_order([res])
        smallest = ds[-1]
        vals = []
        for m in methods:
            row = [record(res, m, d) for d in ds]
            out.append(f"| {m} | " + " | ".join(f"{r['confirmed'] / max(1, r['steps']):.0f} / {r['missed']}"
                                                 for r in row) + " |")
            last = record(res, m, smallest)
            vals.append(last["confirmed"] / max(1, last["steps"]))
        out.append("")
        xs = range(len(methods))
        touching = counts["spheres_closed"] if counts else ev
        ax.bar(xs, vals, color=["tab:blue" if v >= touching else "tab:red" for v in vals])
        ax.axhline(touching, color="black", linewidth=1, label=f"touching at t = 0: {touching} pairs")
        if counts:
            ax.axhline(counts["spheres_strict"], color="tab:red", linestyle="--", linewidth=1.2,
                       label=f"strict |d| < R at t = 0: {counts['spheres_strict']} pairs")
            ax.axhline(counts["boxes_strict"], color="tab:orange", linestyle=":", linewidth=1.4,
                       label=f"strict box overlap at t = 0: {counts['boxes_strict']} pairs")
        ax.set_xticks(list(xs))
        ax.set_xticklabels(methods, rotation=60, ha="right", fontsize=8)
        ax.set_ylabel(f"pairs confirmed per step at dt = {fmt_dt(smallest)}")
        ax.set_title(f"{name}: {res['scene']['bodies']} bodies", fontsize=10)
        ax.grid(True, axis="y", alpha=0.3)
        legend(ax, loc="lower left")
    out.append(self_check_line(results))
    return out, save(fig, outdir, "equal-endpoints", formats)


# ---------------------------------------------------------------------------- grazing

def grazing(results, outdir, formats):
    results = sorted(results, key=lambda r: r["experiment"]["name"], reverse=True)  # dyadic first
    out = ["### grazing: tangent, one-ulp, shallow and near-miss passes", ""]
    fig, axes = plt.subplots(1, len(results), figsize=(6 * len(results), 4.5), squeeze=False)
    for ax, res in zip(axes[0], results):
        t = res["truth"]
        name = res["experiment"]["name"]
        out.append(f"**{name}**: {res['scene']['bodies']} bodies, truth: {t['events']} events, "
                   f"{t['tangent_events']} tangent (enter == exit)")
        ds = dts(res)
        out += ["", "| method | " + " | ".join(fmt_dt(d) for d in ds) + " |", "|---|" + "---|" * len(ds)]
        for i, (m, rs) in enumerate(plot.by_method(res["records"]).items()):
            ax.plot([r["dt"] for r in rs], [r["detected"] for r in rs], label=m, linewidth=1.3, markersize=4,
                    linestyle="-" if rs[0]["continuous"] else "--", **plot.style(i))
            row = {r["dt"]: r["detected"] for r in rs}
            out.append(f"| {m} | " + " | ".join(str(row[d]) for d in ds) + " |")
        out.append("")
        ax.axhline(t["events"], color="black", linewidth=1)
        ax.axhline(t["tangent_events"], color="gray", linestyle=":", linewidth=1)
        ax.set_xscale("log", base=2 if "dyadic" in name else 10)
        ax.set_ylim(bottom=0, top=max(1, t["events"]) * 1.08)  # 1 when the truth has no event
        ax.set_xlabel("timestep dt (s)")
        ax.set_ylabel("events detected")
        ax.set_title(f"{name}: {t['events']} events (black), {t['tangent_events']} tangent (dotted)",
                     fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    legend(axes[0][-1], loc="upper left", bbox_to_anchor=(1.01, 1.0))
    out.append(self_check_line(results))
    return out, save(fig, outdir, "grazing-detected", formats)


# ---------------------------------------------------------------------------- precision

def offset_of(res):
    o = source(res).get("offset", 0)
    return float(o[0] if isinstance(o, list) else o)


def precision(results, outdir, formats):
    results = sorted(results, key=offset_of)
    offsets = [offset_of(r) for r in results]
    labels = [f"{o:g}" for o in offsets]
    methods = method_order(results)
    out = ["### precision: the default gas moved by an offset", "",
           "| offset | truth events | " + " | ".join(methods) + " |", "|---|---|" + "---|" * len(methods)]
    for res, lab in zip(results, labels):
        cells = []
        for m in methods:
            rs = [r for r in res["records"] if r["method"] == m]
            missed = sum(r["missed"] for r in rs)
            unexpected = sum(r["self_check"]["unexpected_contacts"] for r in rs)
            cells.append(f"{missed}" + (f" (+{unexpected} unexp.)" if unexpected else ""))
        out.append(f"| {lab} | {res['truth']['events']} | " + " | ".join(cells) + " |")
    out += ["", "cells: missed events summed over dt = "
            + ", ".join(fmt_dt(d) for d in dts(results[0])) + " s; unexp. = confirmed contacts the truth lacks",
            "", "false positives per step at the smallest dt:", "",
            "| offset | " + " | ".join(methods) + " |", "|---|" + "---|" * len(methods)]
    small = dts(results[0])[-1]
    for res, lab in zip(results, labels):
        out.append(f"| {lab} | " + " | ".join(f"{record(res, m, small)['false_positives_per_step']:.2f}"
                                             for m in methods) + " |")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    xs = list(range(len(results)))
    for i, m in enumerate(methods):
        st = plot.style(i)
        cont = record(results[0], m, small)["continuous"]
        ls = "-" if cont else "--"
        ax1.plot(xs, [sum(r["missed"] for r in res["records"] if r["method"] == m) for res in results],
                 label=m, linestyle=ls, **st)
        ax2.plot(xs, [record(res, m, small)["false_positives_per_step"] for res in results], label=m,
                 linestyle=ls, **st)
    for ax in (ax1, ax2):
        ax.set_xticks(xs)
        ax.set_xticklabels(labels)
        ax.set_xlabel("offset added to every coordinate")
        ax.grid(True, which="both", alpha=0.3)
    ax1.set_yscale("symlog", linthresh=1)
    ax1.set_ylim(bottom=0)
    ax1.set_ylabel("missed events (sum over dt)")
    ax2.set_yscale("symlog", linthresh=0.1)
    ax2.set_ylim(bottom=0)
    ax2.set_ylabel(f"false positives per step at dt = {fmt_dt(small)}")
    legend(ax2, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    out += ["", self_check_line(results)]
    return out, save(fig, outdir, "precision", formats)


# ---------------------------------------------------------------------------- bound-violation

def ratio_of(res):
    true_max = source(res).get("max_acceleration", res["scene"]["max_acceleration"])
    return res["experiment"]["acceleration_bound_used"] / true_max


def bound_violation(results, outdir, formats):
    results = sorted(results, key=ratio_of)
    ratios = [ratio_of(r) for r in results]
    methods = method_order(results)
    ds = dts(results[0])
    out = ["### bound-violation: swarm, acceleration_bound = ratio x the true bound", "",
           f"cells: missed events at dt = {' / '.join(fmt_dt(d) for d in ds)} s "
           f"(truth: {results[0]['truth']['events']} events)", "",
           "| ratio | A used | " + " | ".join(methods) + " |", "|---|---|" + "---|" * len(methods)]
    for res, q in zip(results, ratios):
        cells = [" / ".join(str(record(res, m, d)["missed"]) for d in ds) for m in methods]
        out.append(f"| {q:g} | {res['experiment']['acceleration_bound_used']:g} | " + " | ".join(cells) + " |")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for i, m in enumerate(methods):
        ax.plot(ratios, [sum(r["missed"] for r in res["records"] if r["method"] == m) for res in results],
                label=m, **plot.style(i))
    ax.axvline(1.0, color="black", linewidth=0.8, linestyle=":")
    ax.set_yscale("symlog", linthresh=1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("acceleration_bound / true maximum |a|")
    ax.set_ylabel(f"missed events (sum over {len(ds)} dt)")
    ax.set_title("bounded bounds given a wrong acceleration bound", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    legend(ax)
    out += ["", self_check_line(results)]
    return out, save(fig, outdir, "bound-violation", formats)


# ---------------------------------------------------------------------------- scheduling

SCHEDULING_ORDER = ("sparse-gas", "dense-gas", "bullets", "swarm", "violation")


def scheduling_key(res):
    name = res["experiment"]["name"].replace("scheduling-", "")
    return SCHEDULING_ORDER.index(name) if name in SCHEDULING_ORDER else len(SCHEDULING_ORDER)


def pair_checks(r):
    """Bound pair tests: counted by a scheduled method; every candidate for a fixed step."""
    return r.get("pair_checks", r["candidates"])


def narrow_calls(r):
    """Narrow-phase calls: counted by a scheduled method; every passed pair for a fixed step."""
    return r.get("narrow_calls", r["bound_candidates"])


def cpu_cost(r):
    """CPU seconds per simulated second (the method thread's CPU time); wall-clock for
    results written before records carried it."""
    return r.get("cpu_seconds_per_simulated_second", r["seconds_per_simulated_second"])


def cheapest(records):
    """The cheapest record at zero misses by CPU time (None when every one misses)."""
    ok = [r for r in records if r["missed"] == 0 and r["continuous"]]
    return min(ok, key=cpu_cost) if ok else None


def scheduling(results, outdir, formats):
    results = sorted(results, key=scheduling_key)
    out = ["### scheduling: fixed steps against the earliest-contact scheduler", "",
           "cheapest zero-miss record of each family (over methods and dt, by CPU time): CPU and wall "
           "seconds per simulated second, pair checks (bound pair tests), narrow calls, bound refreshes", "",
           "| scene | events | family | method | dt (s) | CPU s / simulated s | wall s / simulated s | pair checks | "
           "narrow calls | refreshes | scheduler / fixed (CPU) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    main = [res for res in results if scheduling_key(res) < 4]
    fig, axes = plt.subplots(1, max(1, len(main)), figsize=(4.6 * max(1, len(main)), 4.4), squeeze=False)
    for ax, res in zip(axes[0], main):
        name = res["experiment"]["name"].replace("scheduling-", "")
        recs = [r for r in res["records"] if r["continuous"]]
        fixed = cheapest([r for r in recs if "pair_checks" not in r])
        sched = cheapest([r for r in recs if "pair_checks" in r])
        for fam, r in (("fixed", fixed), ("@earliest", sched)):
            if r is None:
                out.append(f"| {name} | {res['truth']['events']} | {fam} | (every record misses) | | | | | | | |")
                continue
            ratio = ""
            if fam == "@earliest" and fixed is not None:
                ratio = f"{cpu_cost(r) / cpu_cost(fixed):.2f}"
            refreshes = r.get("refreshes", res["scene"]["bodies"] * r["steps"])
            out.append(f"| {name} | {res['truth']['events']} | {fam} | {r['method']} | {fmt_dt(r['dt'])} | "
                       f"{cpu_cost(r):.4g} | {r['seconds_per_simulated_second']:.4g} | {pair_checks(r)} | "
                       f"{narrow_calls(r)} | {refreshes} | {ratio} |")
        for i, (m, rs) in enumerate(plot.by_method(recs).items()):
            sched_m = "@earliest" in m
            ax.plot([r["dt"] for r in rs], [cpu_cost(r) for r in rs], label=m,
                    linestyle="-" if sched_m else "--", linewidth=1.3, markersize=4, **plot.style(i % 4))
        ax.set_xscale("log")
        log_y(ax)
        ax.set_xlabel("dt: step (fixed) or longest window (@earliest), s")
        ax.set_ylabel("CPU seconds per simulated second")
        ax.set_title(f"{name}: {res['truth']['events']} events", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    legend(axes[0][-1], loc="upper left", bbox_to_anchor=(1.01, 1.0))
    paths = save(fig, outdir, "scheduling", formats)
    for res in results:
        if scheduling_key(res) != 4:
            continue
        ds = dts(res)
        out += ["", f"#### {res['experiment']['name']}: acceleration_bound {res['experiment']['acceleration_bound_used']:g}"
                f" (true maximum {source(res).get('max_acceleration', res['scene']['max_acceleration']):g}), "
                f"missed events at dt = {' / '.join(fmt_dt(d) for d in ds)} s", "",
                "| method | missed |", "|---|---|"]
        for m in method_order([res]):
            out.append(f"| {m} | " + " / ".join(str(record(res, m, d)["missed"]) for d in ds) + " |")
    out += ["", self_check_line(results)]
    return out, paths


# ---------------------------------------------------------------------------- mixed-sizes / scaling

def time_against(results, outdir, formats, stem, xkey, xlabel, title):
    results = sorted(results, key=xkey)
    xs = [xkey(r) for r in results]
    methods = method_order(results)
    all_dt = sorted({r["dt"] for res in results for r in res["records"]}, reverse=True)
    out = [f"### {stem}: {title}", "",
           "cells: broad-phase ms per step (candidate pairs per step), per dt", "",
           f"| {xlabel} | dt (s) | " + " | ".join(methods) + " |", "|---|---|" + "---|" * len(methods)]
    for res, x in zip(results, xs):
        for d in dts(res):
            cells = []
            for m in methods:
                r = record(res, m, d)
                cells.append("" if r is None else
                             f"{per_step(r, 'broad_seconds') * 1e3:.3g} ({per_step(r, 'candidates'):.0f})")
            out.append(f"| {x:g} | {fmt_dt(d)} | " + " | ".join(cells) + " |")
    out += ["", "| " + xlabel + " | truth s | run: total s of all jobs |", "|---|---|---|"]
    for res, x in zip(results, xs):
        out.append(f"| {x:g} | {res['truth']['seconds']:.2f} | "
                   f"{sum(r['total_seconds'] * res['experiment'].get('repeats', 1) for r in res['records']):.1f} |")
    fig, axes = plt.subplots(1, len(all_dt), figsize=(5.5 * len(all_dt) + 1.5, 4.5), squeeze=False)
    for ax, d in zip(axes[0], all_dt):
        for i, m in enumerate(methods):
            pts = [(x, record(res, m, d)) for res, x in zip(results, xs)]
            pts = [(x, r) for x, r in pts if r is not None]
            if pts:
                ax.plot([x for x, _ in pts], [per_step(r, "broad_seconds") * 1e3 for _, r in pts], label=m,
                        **plot.style(i))
        ax.set_xscale("log")
        log_y(ax)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("broad-phase ms per step")
        ax.set_title(f"dt = {fmt_dt(d)} s", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    legend(axes[0][-1], loc="upper left", bbox_to_anchor=(1.01, 1.0))
    out += ["", self_check_line(results)]
    return out, save(fig, outdir, stem, formats)

# ---------------------------------------------------------------------------- fit

def fit(results, outdir, formats):
    """False positives per step against elongation, one panel per generator; the misses
    of every discrete method (equal: each bound holds the shape at the sample) and of every
    continuous one (zero) in the table."""
    gens = []
    for res in results:
        g = source(res).get("generator", "?")
        if g not in gens:
            gens.append(g)
    out = ["### fit: false positives per step against elongation", "",
           "| scene | elongation | " + " | ".join(method_order(results)) + " | missed (discrete) | missed (continuous) |",
           "|---|---|" + "---|" * (len(method_order(results)) + 2)]
    fig, axes = plt.subplots(1, len(gens), figsize=(6 * len(gens), 4.5), squeeze=False)
    for ax, g in zip(axes[0], gens):
        rs_g = sorted([res for res in results if source(res).get("generator") == g],
                      key=lambda res: source(res).get("elongation", 0))
        names = method_order(rs_g)
        for i, name in enumerate(names):
            xs, ys = [], []
            for res in rs_g:
                r = next((r for r in res["records"] if r["method"] == name), None)
                if r is not None:
                    xs.append(source(res)["elongation"])
                    ys.append(per_step(r, "false_positives"))
            ax.plot(xs, ys, label=name, linewidth=1.3, markersize=4,
                    linestyle="-" if any(r["continuous"] for r in rs_g[0]["records"] if r["method"] == name) else "--",
                    **plot.style(i))
        for res in rs_g:
            recs = {r["method"]: r for r in res["records"]}
            disc = sorted({r["missed"] for r in res["records"] if not r["continuous"]})
            cont = sorted({r["missed"] for r in res["records"] if r["continuous"]})
            out.append(f"| {g} | {source(res)['elongation']:g} | "
                       + " | ".join(f"{per_step(recs[n], 'false_positives'):.1f}" if n in recs else ""
                                    for n in method_order(results))
                       + f" | {', '.join(map(str, disc))} | {', '.join(map(str, cont))} |")
        ax.set_xscale("log", base=2)
        log_y(ax)
        ax.set_xlabel("elongation (largest / smallest half extent)")
        ax.set_ylabel("false positives per step")
        ax.set_title(f"{g}: {rs_g[0]['scene']['bodies']} bodies; dashed: discrete", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    legend(axes[0][-1], loc="upper left", bbox_to_anchor=(1.01, 1.0))
    out += ["", "false positives per step (columns: methods); misses: the distinct counts over the discrete and "
            "the continuous methods", "", self_check_line(results)]
    return out, save(fig, outdir, "fit-false-positives", formats)


# ---------------------------------------------------------------------------- cloth

CLOTH_ORDER = ("drape", "twist", "pile")


def load_cloth(path):
    """A ccdlab-cloth-results/1 file (exit 2 naming the file and field otherwise)."""
    try:
        with open(path) as f:
            res = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        fail(f"{path}: {e}")
    if not isinstance(res, dict) or res.get("format") != "ccdlab-cloth-results/1":
        fail(f"{path}: format: not a ccdlab-cloth-results/1 file")
    if not res.get("records"):
        fail(f"{path}: records: no records to plot")
    for i, r in enumerate(res["records"]):
        for k in ("method", "mode", "culler", "k", "dt", "missed", "events", "candidates", "false_positives",
                  "checks", "seconds_per_simulated_second", "conservative"):
            if k not in r:
                fail(f"{path}: records[{i}].{k}: missing field")
    return res


def cloth_key(res):
    name = res["scene"]["source"]
    return CLOTH_ORDER.index(name) if name in CLOTH_ORDER else len(CLOTH_ORDER)


def cloth(results, outdir, formats):
    results = sorted(results, key=cloth_key)
    out = ["### cloth: self-collision checks every k integrator steps, against the exact mesh truth", ""]
    rows = (("missed", "missed contact events", "symlog"),
            ("seconds_per_simulated_second", "seconds per simulated second", "log"),
            ("fp_per_check", "false positives per check", "symlog"))
    fig, axes = plt.subplots(len(rows), len(results), figsize=(4.6 * len(results), 3.4 * len(rows)), squeeze=False)
    for col, res in enumerate(results):
        sc = res["scene"]
        name = sc["source"]
        ks = sorted({r["k"] for r in res["records"]})
        out += [f"#### {name}: {sc['triangles']} triangles, {sc['steps']} steps of {sc['step']:g} s, thickness "
                f"{sc['thickness']:g}; {res['truth']['events']} contact events", "",
                "missed events / false positives / seconds per simulated second, per check interval k", "",
                "| method | conservative | " + " | ".join(f"k = {k}" for k in ks) + " |",
                "|---|---|" + "---|" * len(ks)]
        groups = plot.by_method(res["records"])
        for i, (m, rs) in enumerate(groups.items()):
            rs = sorted(rs, key=lambda r: r["k"])
            by_k = {r["k"]: r for r in rs}
            out.append(f"| {m} | {'yes' if rs[0]['conservative'] else 'no'} | " + " | ".join(
                f"{by_k[k]['missed']} / {by_k[k]['false_positives']} / {by_k[k]['seconds_per_simulated_second']:.3g}"
                if k in by_k else "" for k in ks) + " |")
            for row, (key, label, scale) in enumerate(rows):
                ax = axes[row][col]
                ys = [(r["false_positives"] / r["checks"] if r["checks"] else 0.0) if key == "fp_per_check" else r[key]
                      for r in rs]
                ax.plot([r["k"] for r in rs], ys, label=m, linewidth=1.3, markersize=4,
                        linestyle="-" if rs[0]["mode"] == "continuous" else "--", **plot.style(i))
        for row, (key, label, scale) in enumerate(rows):
            ax = axes[row][col]
            ax.set_xscale("log", base=2)
            if scale == "symlog":
                ax.set_yscale("symlog", linthresh=1)
                ax.set_ylim(bottom=0)
            else:
                log_y(ax)
            ax.set_xlabel("check interval k (integrator steps)")
            ax.set_ylabel(label)
            ax.grid(True, which="both", alpha=0.3)
        axes[0][col].set_title(f"{name}: {res['truth']['events']} events; dashed: discrete", fontsize=10)
        out.append("")
    legend(axes[0][-1], loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return out, save(fig, outdir, "cloth", formats)


# ---------------------------------------------------------------------------- thin-obstacles

def static_work(r):
    """'static pair tests / static narrow calls / CPU s per simulated s' of one record (the
    CPU time is the whole method's, body-body pairs included)."""
    if "static_pair_checks" in r:  # @earliest
        tests, calls = r["static_pair_checks"], r["static_narrow_calls"]
    else:
        tests, calls = r["static_candidates"], r["static_bound_candidates"]
    return f"{tests} / {calls} / {r['cpu_seconds_per_simulated_second']:.3g}"


def thin_obstacles(results, outdir, formats):
    """Static misses (balls through thin scenery polygons) against dt, the polygon tests
    the kinematic principle saved (`@fixed:kinematic=1` methods), and the static work and
    CPU time of the conservative fixed-step methods against the scheduled ones (`@earliest`)."""
    res = results[0]
    ds = dts(res)
    out = [f"### thin-obstacles: {plot.title(res)}", "",
           "missed body-static events per method (columns: dt, s)", "",
           "| method | conservative | " + " | ".join(fmt_dt(d) for d in ds) + " |",
           "|---|---|" + "---|" * len(ds)]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    saved_rows = []
    work_rows = []
    for i, (name, rs) in enumerate(plot.by_method(res["records"]).items()):
        if rs[0]["continuous"] and "kinematic=1" not in name:
            cells = {r["dt"]: static_work(r) for r in rs}
            work_rows.append(f"| {name} | " + " | ".join(cells.get(d, "") for d in ds) + " |")
        cont = rs[0]["continuous"]
        ax.plot([r["dt"] for r in rs], [r["static_missed"] for r in rs], label=name, linewidth=1.3, markersize=4,
                linestyle="-" if cont else "--", **plot.style(i))
        row = {r["dt"]: r["static_missed"] for r in rs}
        out.append(f"| {name} | {'yes' if rs[0]['conservative'] and cont else 'no'} | "
                   + " | ".join(str(row.get(d, "")) for d in ds) + " |")
        if any(r["static_tests_saved"] for r in rs) or "kinematic=1" in name:
            saved = {r["dt"]: (r["static_tests_saved"], r["static_bound_candidates"]) for r in rs}
            saved_rows.append(f"| {name} | " + " | ".join(
                f"{saved[d][0]} / {saved[d][1]}" if d in saved else "" for d in ds) + " |")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("timestep dt (s)")
    ax.set_ylabel("missed body-static events")
    ax.set_title(f"thin-obstacles: {res['records'][0]['static_events']} body-static events; dashed: discrete",
                 fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    legend(ax, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    if saved_rows:
        out += ["", "kinematic principle: static tests saved / static pairs passed by the bound (columns: dt, s)", "",
                "| method | " + " | ".join(fmt_dt(d) for d in ds) + " |", "|---|" + "---|" * len(ds)] + saved_rows
    if work_rows:
        out += ["", "static pair tests / static narrow calls / CPU s per simulated s (fixed steps: static_candidates / "
                "static_bound_candidates; @earliest: static_pair_checks / static_narrow_calls; columns: dt, s)", "",
                "| method | " + " | ".join(fmt_dt(d) for d in ds) + " |", "|---|" + "---|" * len(ds)] + work_rows
    out += ["", self_check_line(results)]
    return out, save(fig, outdir, "thin-obstacles-missed", formats)


def check_study_inputs(study, paths, results):
    """What a study reads beyond the records, checked per file (exit 2 naming it)."""
    for p, res in zip(paths, results):
        src = source(res)
        if study == "fit" and (isinstance(src.get("elongation"), bool)
                               or not isinstance(src.get("elongation"), (int, float))):
            fail(f"{plot.shown(p)}: scene.source.elongation: missing (the fit study draws generated scenes "
                 "against their elongation)")
        if study == "bound-violation":
            true_max = src.get("max_acceleration", res["scene"].get("max_acceleration"))
            if isinstance(true_max, bool) or not isinstance(true_max, (int, float)) or not true_max > 0:
                fail(f"{plot.shown(p)}: scene.max_acceleration: must be > 0 (the bound-violation study divides "
                     "the bound used by it)")
            used = res["experiment"].get("acceleration_bound_used")
            if isinstance(used, bool) or not isinstance(used, (int, float)):
                fail(f"{plot.shown(p)}: experiment.acceleration_bound_used: missing")


def main(argv=None):
    ap = argparse.ArgumentParser(description="Charts of one stability study (docs/studies.md).")
    ap.add_argument("study", choices=STUDIES)
    ap.add_argument("results", nargs="+", help="the study's ccdlab-results/2 files")
    ap.add_argument("-o", "--output", help="output folder (default results/studies/STUDY/plots)")
    ap.add_argument("--format", default="png", help="comma-separated formats (default png)")
    ap.add_argument("--ccdlab", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build",
                                                     "ccdlab"), help="the ccdlab binary (equal-endpoints)")
    args = ap.parse_args(argv)
    formats = [f for f in args.format.split(",") if f]
    for f in formats:
        if f not in ("png", "svg", "pdf"):
            fail(f"--format: unknown format '{f}' (png, svg, pdf)")
    outdir = args.output or os.path.join("results", "studies", args.study, "plots")
    if args.study == "cloth":
        results = [load_cloth(p) for p in args.results]
        os.makedirs(outdir, exist_ok=True)
        lines, paths = cloth(results, outdir, formats)
        print("\n".join(lines))
        print()
        for p in paths:
            print(p)
        return
    results = [plot.load(p) for p in args.results]
    for p, res in zip(args.results, results):
        for i, r in enumerate(res["records"]):
            for k in ("steps", "missed", "detected", "broad_seconds", "candidates", "self_check"):
                if k not in r:
                    fail(f"{p}: records[{i}].{k}: missing field")
    check_study_inputs(args.study, args.results, results)
    os.makedirs(outdir, exist_ok=True)
    s = args.study
    if s == "tunnelling":
        lines, paths = tunnelling(results, outdir, formats)
    elif s == "sap-coherence":
        lines, paths = sap_coherence(results, outdir, formats)
    elif s == "equal-endpoints":
        lines, paths = equal_endpoints(results, outdir, formats, args.ccdlab)
    elif s == "grazing":
        lines, paths = grazing(results, outdir, formats)
    elif s == "precision":
        lines, paths = precision(results, outdir, formats)
    elif s == "bound-violation":
        lines, paths = bound_violation(results, outdir, formats)
    elif s == "mixed-sizes":
        lines, paths = time_against(results, outdir, formats, "mixed-sizes",
                                    lambda r: r["scene"]["radius_max"] / r["scene"]["radius_min"],
                                    "r_max / r_min", "broad-phase time against the radius spread")
    elif s == "scheduling":
        lines, paths = scheduling(results, outdir, formats)
    elif s == "spinning":
        lines, paths = tunnelling(results, outdir, formats, "spinning")
    elif s == "fit":
        lines, paths = fit(results, outdir, formats)
    elif s == "thin-obstacles":
        lines, paths = thin_obstacles(results, outdir, formats)
    else:
        lines, paths = time_against(results, outdir, formats, "scaling", lambda r: r["scene"]["bodies"],
                                    "bodies N", "broad-phase time against N")
    print("\n".join(lines))
    print()
    for p in paths:
        print(p)


if __name__ == "__main__":
    main()
