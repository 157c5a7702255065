#!/usr/bin/python3
"""Records a small simulation and measures its contacts with ccdlab (docs/import.md).

Balls of different sizes fall under gravity in a 4 m x 4 m pen and bounce on its floor and
walls (restitution 0.8), integrated with semi-implicit Euler at 256 Hz; the balls do not
react to each other (ccdlab measures contacts, it does not resolve them). Every 4th
integrator state (64 Hz) is written as CSV, the format `ccdlab import` reads:

    body,t,x,y,z,radius

The script then runs

    ccdlab import DIR/frames.csv -o DIR/scene.json      # linear motion between frames
    ccdlab truth DIR/scene.json -o DIR/truth.json       # exact contacts of that motion

and checks what it can check by itself: `ccdlab poses` of the imported scene at the frame
times gives back the recorded centres; every pair closer than its radii at a frame lies
inside a contact of the truth; the middle of every contact of the truth is in contact in
the recording's own linear interpolation. It exits with status 1 when a check fails.

usage: /usr/bin/python3 examples/record_bouncing_balls.py [-o DIR] [--balls N] [--seconds T]
                                                         [--seed S] [--ccdlab PATH]
  -o DIR        output folder (default results/bouncing-balls)
  --balls N     number of balls (default 24)
  --seconds T   simulated time (default 2)
  --ccdlab PATH the program (default build/ccdlab of this repository)
Only the Python standard library and numpy.
"""
import argparse
import csv
import json
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEP = 1.0 / 256.0      # integrator step (s); dyadic, so frame times are exact doubles
RECORD_EVERY = 4        # frames at 64 Hz
GRAVITY = np.array([0.0, -9.81, 0.0])
PEN = 4.0               # the pen is [0, PEN] on x and z, the floor is y = 0
RESTITUTION = 0.8


def simulate(balls, seconds, seed):
    """Semi-implicit Euler with floor and wall bounces; returns (times, positions[frame, ball, 3], radii)."""
    rng = np.random.default_rng(seed)
    radius = rng.uniform(0.1, 0.3, balls)
    pos = np.column_stack([rng.uniform(0.5, PEN - 0.5, balls), rng.uniform(0.5, 3.0, balls),
                           rng.uniform(0.5, PEN - 0.5, balls)])
    vel = rng.uniform(-2.0, 2.0, (balls, 3))
    steps = int(round(seconds / STEP))
    times, frames = [0.0], [pos.copy()]
    for k in range(1, steps + 1):
        vel += GRAVITY * STEP
        pos += vel * STEP
        low = pos[:, 1] < radius  # the floor
        pos[low, 1] = radius[low]
        vel[low, 1] = -RESTITUTION * vel[low, 1]
        for axis in (0, 2):  # the walls
            for side, limit in ((-1, radius), (1, PEN - radius)):
                out = side * (pos[:, axis] - limit) > 0
                pos[out, axis] = limit[out]
                vel[out, axis] = -RESTITUTION * vel[out, axis]
        if k % RECORD_EVERY == 0:
            times.append(k * STEP)
            frames.append(pos.copy())
    return np.array(times), np.array(frames), radius


def write_frames(path, times, frames, radius):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["body", "t", "x", "y", "z", "radius"])
        for k, t in enumerate(times):
            for i in range(len(radius)):
                x, y, z = frames[k, i]
                w.writerow([i, repr(float(t)), repr(float(x)), repr(float(y)), repr(float(z)), repr(float(radius[i]))])


def run(ccdlab, *args):
    subprocess.run([ccdlab, *args], check=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-o", dest="out", default=os.path.join(ROOT, "results", "bouncing-balls"))
    p.add_argument("--balls", type=int, default=24)
    p.add_argument("--seconds", type=float, default=2.0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--ccdlab", default=os.path.join(ROOT, "build", "ccdlab"))
    a = p.parse_args()
    if a.balls < 2 or not a.seconds > 0:
        p.error("need --balls >= 2 and --seconds > 0")
    os.makedirs(a.out, exist_ok=True)
    frames_csv = os.path.join(a.out, "frames.csv")
    scene_json = os.path.join(a.out, "scene.json")
    truth_json = os.path.join(a.out, "truth.json")
    poses_csv = os.path.join(a.out, "poses.csv")

    times, frames, radius = simulate(a.balls, a.seconds, a.seed)
    write_frames(frames_csv, times, frames, radius)
    run(a.ccdlab, "import", frames_csv, "-o", scene_json)
    run(a.ccdlab, "truth", scene_json, "-o", truth_json, "--quiet")
    with open(truth_json) as f:
        events = json.load(f)["events"]

    failures = []
    # 1. The imported scene's motion passes through every recorded centre.
    dt = times[1] - times[0]
    run(a.ccdlab, "poses", scene_json, "--times", f"0:{times[-1]!r}:{dt!r}", "-o", poses_csv)
    poses = np.loadtxt(poses_csv, delimiter=",", skiprows=1)
    n = len(radius)
    back = poses[:, 2:5].reshape(-1, n, 3)
    if back.shape != frames.shape:
        failures.append(f"poses gave {back.shape[0]} frames, the recording has {frames.shape[0]}")
    else:
        err = np.abs(back - frames).max()
        if err > 1e-9:
            failures.append(f"the imported motion misses a recorded centre by {err:.3g} m")
    # 2. A pair closer than its radii at a frame is inside a contact of the truth.
    by_pair = {}
    for e in events:
        by_pair.setdefault((e["a"], e["b"]), []).append((e["enter"], e["exit"]))
    touching_frames = 0
    for k, t in enumerate(times):
        d = np.linalg.norm(frames[k][:, None, :] - frames[k][None, :, :], axis=2)
        R = radius[:, None] + radius[None, :]
        for i, j in zip(*np.nonzero(np.triu(d < R * (1 - 1e-9), 1))):
            touching_frames += 1
            if not any(lo <= t <= hi for lo, hi in by_pair.get((int(i), int(j)), [])):
                failures.append(f"bodies {i} and {j} overlap at t = {t} but no contact of the truth holds it")
    # 3. The middle of every contact is a contact of the linear interpolation.
    for e in events:
        tm = 0.5 * (e["enter"] + e["exit"])
        k = min(int(np.searchsorted(times, tm, side="right")) - 1, len(times) - 2)
        u = (tm - times[k]) / (times[k + 1] - times[k])
        pa = frames[k, e["a"]] * (1 - u) + frames[k + 1, e["a"]] * u
        pb = frames[k, e["b"]] * (1 - u) + frames[k + 1, e["b"]] * u
        R = radius[e["a"]] + radius[e["b"]]
        if np.linalg.norm(pa - pb) > R * (1 + 1e-9):
            failures.append(f"contact {e} is not a contact of the recording at its middle t = {tm}")

    print(f"{n} balls, {len(times)} frames at {1 / dt:.0f} Hz ({a.seconds} s): {len(events)} contacts "
          f"({touching_frames} pair-frames in contact); files in {a.out}")
    for f in failures[:20]:
        print("FAILED:", f)
    return 1 if failures or not events else 0


if __name__ == "__main__":
    sys.exit(main())
