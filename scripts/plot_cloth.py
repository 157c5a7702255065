#!/usr/bin/env python3
"""Pictures of a cloth run: reads the frames written by `ccdlab cloth` and draws the cloth
at a few times (first, middle, last by default) with its obstacles.

    /usr/bin/python3 scripts/plot_cloth.py FRAMES.json -o PICTURE.png [--frames 0,5,-1]
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("frames")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--frames", dest="pick", default=None, help="comma-separated frame indices")
    args = ap.parse_args()
    with open(args.frames) as f:
        run = json.load(f)
    frames = run["frames"]
    pick = [int(i) for i in args.pick.split(",")] if args.pick else [0, len(frames) // 2, -1]
    tri = np.array(run["triangles"])
    fig = plt.figure(figsize=(4 * len(pick), 4))
    all_x = np.concatenate([np.array(frames[i]["x"]).reshape(-1, 3) for i in pick])
    lo, hi = all_x.min(axis=0), all_x.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2 + 1e-9
    for k, i in enumerate(pick):
        ax = fig.add_subplot(1, len(pick), k + 1, projection="3d")
        x = np.array(frames[i]["x"]).reshape(-1, 3)
        # ccdlab's y is up: draw (x, z, y).
        ax.plot_trisurf(x[:, 0], x[:, 2], x[:, 1], triangles=tri, cmap="viridis", linewidth=0.1,
                        edgecolor="k", alpha=0.9)
        for s in run.get("spheres", []):
            u, v = np.mgrid[0:2 * np.pi:24j, 0:np.pi:12j]
            c, r = s["center"], s["radius"]
            ax.plot_surface(c[0] + r * np.cos(u) * np.sin(v), c[2] + r * np.sin(u) * np.sin(v),
                            c[1] + r * np.cos(v), color="tab:red", alpha=0.35, linewidth=0)
        ax.set_xlim(centre[0] - half, centre[0] + half)
        ax.set_ylim(centre[2] - half, centre[2] + half)
        ax.set_zlim(centre[1] - half, centre[1] + half)
        ax.set_title(f"{run['scene']}, t = {frames[i]['t']:.2f} s")
        ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(args.output, dpi=90)


if __name__ == "__main__":
    main()
