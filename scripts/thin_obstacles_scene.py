#!/usr/bin/env python3
"""Writes data/scenes/thin-obstacles.json: the scene of the thin-obstacles study
(docs/studies.md). 120 small fast balls (radius 1/16 to 1/8, speed 16 to 64) in the box
[0, 16]^3 without gravity, among 48 thin square plates (side 1 to 2, each parallel to a
coordinate plane, dyadic coordinates) and 16 tilted triangles: a ball crosses a plate in
a few milliseconds, so a discrete method tunnels through at any common frame rate.
Deterministic (fixed seed).  usage: scripts/thin_obstacles_scene.py [-o FILE]"""
import argparse
import json
import math
import random


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", "--output", default="data/scenes/thin-obstacles.json")
    args = ap.parse_args()
    rng = random.Random(14)
    d = lambda x: round(x * 64) / 64  # dyadic coordinates
    scenery = []
    for _ in range(48):
        axis = rng.randrange(3)
        side = d(rng.uniform(1, 2))
        c = [d(rng.uniform(2, 14)) for _ in range(3)]
        u, v = [(axis + 1) % 3, (axis + 2) % 3]
        corners = []
        for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
            p = list(c)
            p[u] += a * side
            p[v] += b * side
            corners.append(p)
        scenery.append({"polygon": corners})
    for _ in range(16):
        c = [rng.uniform(2, 14) for _ in range(3)]
        tri = [[d(c[k] + rng.uniform(-1, 1)) for k in range(3)] for _ in range(3)]
        scenery.append({"polygon": tri})
    bodies = []
    for _ in range(120):
        r = d(rng.uniform(1 / 16, 1 / 8))
        p = [d(rng.uniform(1, 15)) for _ in range(3)]
        speed = rng.uniform(16, 64)
        z = rng.uniform(-1, 1)
        phi = rng.uniform(0, 2 * math.pi)
        s = math.sqrt(1 - z * z)
        v = [d(speed * s * math.cos(phi)), d(speed * s * math.sin(phi)), d(speed * z)]
        bodies.append({"radius": r, "position": p, "velocity": v})
    scene = {"format": "ccdlab-scene/2", "horizon": 1.0,
             "box": {"min": [0, 0, 0], "max": [16, 16, 16]},
             "bodies": bodies, "scenery": scenery}
    with open(args.output, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
