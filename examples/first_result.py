#!/usr/bin/python3
"""From a numpy simulation to "what does 60 Hz miss?" and a chart, in Python only.

Runnable as a script and cell by cell (the `# %%` cells of Jupyter, VS Code and Spyder):

    PYTHONPATH=build/python /usr/bin/python3 examples/first_result.py [-o DIR]

(or with the package installed: pip install --no-build-isolation ., docs/python.md).
It simulates balls bouncing in a pen with numpy, hands the recorded frames to ccdlab,
computes the exact contacts of the recorded motion, asks which of them a discrete AABB
check at 60 Hz and a continuous capsule bound miss, lists the missed ones, and draws the
missed fraction against the timestep into DIR/missed.png (default results/first-result).
It exits with status 1 when a check of its own fails (the conservative capsule bound must
miss nothing).
"""
# %% The simulation: 40 fast balls (up to 8 m/s per axis) under gravity in a 6 m pen, semi-implicit Euler at 240 Hz,
# restitution 0.9 on the floor and walls; the balls pass through each other (ccdlab
# measures contacts, it does not resolve them). Every 2nd state is a frame (120 Hz).
import argparse
import os
import sys

import numpy as np

import ccdlab

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("-o", "--output", default="results/first-result", help="output folder")
args, _ = ap.parse_known_args()  # cells run in a notebook see the notebook's own argv

rng = np.random.default_rng(2026)
n, hz, seconds, pen = 40, 240, 2.0, 6.0
radius = rng.uniform(0.05, 0.2, n)
x = rng.uniform(radius[:, None], pen - radius[:, None], (n, 3))
v = rng.uniform(-8.0, 8.0, (n, 3))
g = np.array([0.0, -9.81, 0.0])
frames, times = [x.copy()], [0.0]
for step in range(1, int(seconds * hz) + 1):
    v = v + g / hz
    x = x + v / hz
    low, high = x < radius[:, None], x > pen - radius[:, None]
    x = np.where(low, radius[:, None], np.where(high, pen - radius[:, None], x))
    v = np.where(low | high, -0.9 * v, v)
    if step % 2 == 0:
        frames.append(x.copy())
        times.append(step / hz)
frames, times = np.array(frames), np.array(times)
print(f"simulated {n} balls for {seconds} s: {len(times)} frames")

# %% The recorded motion as a scene (linear between frames, as `ccdlab import` reads it),
# and its exact contacts.
scene = ccdlab.import_frames(frames, times, radii=radius)
truth = ccdlab.truth(scene)
print(scene)
print(truth)

# %% Which contacts does each method miss? A discrete AABB test and a continuous capsule
# bound (conservative: it must miss nothing), both over a uniform grid, at 30 to 480 Hz.
# The scene goes to the run as it is, in memory.
results = ccdlab.run({"format": "ccdlab-experiment/1", "scene": scene, "hz": [30, 60, 120, 240, 480],
                      "methods": ["aabb/grid", "capsule/grid"]}, missed_events=True)
print(results)
at_60 = results.missed("aabb/grid", 1 / 60)
record = results.record("aabb/grid", 1 / 60)
print(f"aabb/grid at 60 Hz misses {record['missed']} of {record['events']} contacts:")
for m in at_60[:10]:
    print(f"  bodies {m['a']} and {m['b']}: in contact from {m['enter']:.4f} s to {m['exit']:.4f} s "
          f"({1000 * (m['exit'] - m['enter']):.2f} ms)")
if len(at_60) > 10:
    print(f"  ... and {len(at_60) - 10} more")

# %% A chart: the missed fraction against the timestep, per method (the chart of
# scripts/plot.py, as a matplotlib Figure).
import ccdlab.plot  # noqa: E402  (needs matplotlib)

fig = ccdlab.plot.missed(results)
os.makedirs(args.output, exist_ok=True)
chart = os.path.join(args.output, "missed.png")
fig.savefig(chart, dpi=100, bbox_inches="tight")
print(f"chart: {chart}")

# %% Checks: the conservative bound misses nothing at any rate; the discrete one misses
# something at 30 Hz on this fast scene; the list matches the count.
capsule_missed = [r["missed"] for r in results.records if r["method"] == "capsule/grid"]
ok = all(m == 0 for m in capsule_missed) and results.record("aabb/grid", 1 / 30)["missed"] > 0
ok = ok and len(at_60) == record["missed"] + record.get("static_missed", 0)
if __name__ == "__main__" and not ok:
    print("first_result: a check failed", file=sys.stderr)
    sys.exit(1)
