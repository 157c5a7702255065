#!/usr/bin/env python3
"""Chart of peers_bench results: median ms/frame against N (log-log), one line per method.

Usage: /usr/bin/python3 scripts/plot_peers.py results/peers/peers.json [OUT_PREFIX]
Writes OUT_PREFIX.png and OUT_PREFIX.svg (default: next to the JSON file, named peers).
Solid lines: ccdlab; dashed: peers (FCL, Bullet, Boost). Thread CPU time (the figure on a
shared machine); the grey dotted guides are c * N log N and c * N through the fastest
method's largest size, for judging growth. Only reads the JSON; writes only the charts.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(path) or ".", "peers")
    with open(path) as f:
        doc = json.load(f)
    series = {}
    library = {}
    for r in doc["results"]:
        if r.get("status") != "ok":
            continue
        series.setdefault(r["method"], []).append((r["n"], r["median_cpu_ms"]))
        library[r["method"]] = r["library"]
    fig, ax = plt.subplots(figsize=(9, 6))
    cmap = plt.get_cmap("tab20")
    for k, (name, pts) in enumerate(sorted(series.items(), key=lambda kv: -min(p[1] for p in kv[1]))):
        pts.sort()
        xs, ys = zip(*pts)
        own = library[name] == "ccdlab"
        ax.plot(xs, ys, marker="o", linestyle="-" if own else "--", linewidth=2.2 if own else 1.2,
                color=cmap(k % 20), label=f"{name} ({library[name]})")
    # Growth guides through the fastest method at the largest size.
    best = min(((p[-1][0], p[-1][1], name) for name, p in series.items()), key=lambda t: (-t[0], t[1]), default=None)
    if best:
        n1, t1, _ = best
        ns = sorted({r["n"] for r in doc["results"]})
        ax.plot(ns, [t1 * (n / n1) * math.log(n) / math.log(n1) for n in ns], ":", color="grey", label="∝ N log N")
        ax.plot(ns, [t1 * n / n1 for n in ns], ":", color="black", alpha=0.5, label="∝ N")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("bodies N (shared moving-spheres scene, ~0.137 pairs per body)")
    ax.set_ylabel("median thread-CPU ms per frame (update + query)")
    ax.set_title("Broad phases: ccdlab (solid) vs FCL 0.7, Bullet 3.24, Boost 1.74 (dashed)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(f"{out}.{ext}", dpi=120)
        print(f"wrote {out}.{ext}")


if __name__ == "__main__":
    main()
