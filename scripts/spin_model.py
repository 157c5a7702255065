#!/usr/bin/python3
"""The spin-model study (docs/studies.md): what the constant-spin shortcut costs.

The same tumbling sticks, plates and crates (ccdlab scene sticks|plates|crates, the same
seed and draws) run twice: with the true torque-free motion (free=1: the angular momentum
is constant, the angular velocity wanders) and with the engine shortcut that keeps the
initial angular velocity (free=0, a prescribed spin). `ccdlab truth` gives each one's
certified contacts; an event of the shortcut is *invented* when the true truth has no
event of that pair overlapping it in time, an event of the true truth is *lost* when the
shortcut has none. Counted per shape, elongation (largest over smallest half extent) and
horizon (events entering before it).

usage: /usr/bin/python3 scripts/spin_model.py [-o DIR] [--threads N] [--ccdlab PATH] [--quick]
  -o DIR      results and charts (default results/studies/spin-model)
  --threads N threads of `ccdlab truth` (default 2)
  --quick     a seconds-long run (one shape, two elongations, 40 bodies) for the test suite;
              fails (status 1) when the two motions give the same contacts
Prints a Markdown table and the charts' paths; exits with status 2 on bad usage.
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot  # noqa: E402,F401  (sets the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def truth_of(ccdlab, gen, params, free, out, threads):
    scene = os.path.join(out, f"{gen}-{params['elongation']}-{'free' if free else 'constant'}.json")
    truth = scene[:-5] + "-truth.json"
    args = [f"{k}={v}" for k, v in params.items()] + [f"free={1 if free else 0}"]
    subprocess.run([ccdlab, "scene", gen, *args, "-o", scene], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([ccdlab, "truth", scene, "-o", truth, "--threads", str(threads), "--quiet"], check=True)
    with open(truth) as f:
        return json.load(f)["events"]


def unmatched(events, others):
    """Events of `events` with no event of the same pair in `others` overlapping in time
    (brackets included)."""
    by_pair = {}
    for e in others:
        by_pair.setdefault((e["a"], e["b"]), []).append(e)
    out = []
    for e in events:
        lo = e["enter"] - e.get("enter_error", 0.0)
        hi = e["exit"] + e.get("exit_error", 0.0)
        hit = False
        for o in by_pair.get((e["a"], e["b"]), []):
            if o["enter"] - o.get("enter_error", 0.0) <= hi and lo <= o["exit"] + o.get("exit_error", 0.0):
                hit = True
                break
        if not hit:
            out.append(e)
    return out


def main():
    ap = argparse.ArgumentParser(description="the spin-model study", add_help=True)
    ap.add_argument("-o", default=os.path.join(ROOT, "results", "studies", "spin-model"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--ccdlab", default=os.path.join(ROOT, "build", "ccdlab"))
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    if a.threads < 1:
        print("spin_model.py: --threads must be >= 1", file=sys.stderr)
        sys.exit(2)
    os.makedirs(a.o, exist_ok=True)
    shapes = ["sticks"] if a.quick else ["sticks", "plates", "crates"]
    elongations = [2, 8] if a.quick else [2, 4, 8, 16, 32]
    horizon = 2.0 if a.quick else 4.0
    horizons = [horizon / 4, horizon / 2, horizon] if a.quick else [0.25, 0.5, 1.0, 2.0, 4.0]
    base = {"bodies": 40 if a.quick else 400, "horizon": horizon, "seed": 22, "spin_max": 12, "speed_max": 1,
            "fraction": 0.1, "overlap": 1}
    rows = []
    start = time.time()
    for gen in shapes:
        for el in elongations:
            params = dict(base, elongation=el)
            true_ev = truth_of(a.ccdlab, gen, params, True, a.o, a.threads)
            short_ev = truth_of(a.ccdlab, gen, params, False, a.o, a.threads)
            lost, invented = unmatched(true_ev, short_ev), unmatched(short_ev, true_ev)
            for h in horizons:
                before = lambda evs: sum(1 for e in evs if e["enter"] <= h)  # noqa: E731
                rows.append({"shape": gen, "elongation": el, "horizon": h, "true_events": before(true_ev),
                             "shortcut_events": before(short_ev), "lost": before(lost),
                             "invented": before(invented)})
    with open(os.path.join(a.o, "spin-model.json"), "w") as f:
        json.dump({"parameters": base, "rows": rows, "seconds": time.time() - start}, f, indent=1)
    print(f"spin-model: {len(shapes) * len(elongations) * 2} truths in {time.time() - start:.1f} s\n")
    print("| shape | elongation | horizon (s) | true events | shortcut events | lost | invented |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['shape']} | {r['elongation']} | {r['horizon']:g} | {r['true_events']} | {r['shortcut_events']} "
              f"| {r['lost']} | {r['invented']} |")
    plots = os.path.join(a.o, "plots")
    os.makedirs(plots, exist_ok=True)
    frac = lambda r, k: r[k] / r["true_events"] if r["true_events"] else 0.0  # noqa: E731

    def plot(select, x, xlabel, title, name):
        """Lost and invented fractions of each shape's rows chosen by `select`, against `x`."""
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for gen in shapes:
            rs = [r for r in rows if r["shape"] == gen and select(r)]
            ax.plot([r[x] for r in rs], [frac(r, "lost") for r in rs], "o-", label=f"{gen}: lost")
            ax.plot([r[x] for r in rs], [frac(r, "invented") for r in rs], "s--", label=f"{gen}: invented")
        ax.set_xscale("log", base=2)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("fraction of the true events")
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        path = os.path.join(plots, name)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        return path

    # 1: against the horizon, at the middle elongation; 2: against the elongation, at the full horizon.
    mid = elongations[len(elongations) // 2]
    p1 = plot(lambda r: r["elongation"] == mid, "horizon", "horizon (s)",
              f"constant spin against free tumbling, elongation {mid}", "spin-model-horizon.png")
    p2 = plot(lambda r: r["horizon"] == horizons[-1], "elongation", "elongation (largest / smallest half extent)",
              f"constant spin against free tumbling, horizon {horizons[-1]:g} s", "spin-model-elongation.png")
    print()
    print(p1)
    print(p2)
    if a.quick and not any(r["lost"] + r["invented"] for r in rows):
        print("spin_model.py: the shortcut matched the free motion exactly: the study measures nothing", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
