#!/usr/bin/python3
"""Pictures of what a method missed: `ccdlab animate`.

usage: /usr/bin/python3 scripts/animate.py SCENE.json --results RESULTS.json --method METHOD
           --dt DT [--from T0] [--to T1] [--fps N] [--frames-per-step K] [--force] -o OUT.gif|OUT.mp4

Draws the scene between T0 and T1, projected on the two widest axes of its box:
  left    every body at the frame's time (grey) over the static scenery (brown: floors,
          ramps, mesh triangles); the bodies of each contact the method missed, body-body or
          body-scenery, in red while the contact lasts, circled where it happened;
  right   a zoom on the missed contact nearest in time: the two bodies (or the body and its
          scenery polygon, outlined in red) now (filled), where the method saw them at its
          samples t_k = k dt (outlines), their paths, and the contact (red) at its exact enter
          time;
  bottom  a time line: the samples (ticks), the missed contacts (red bars), the frame's time.
The missed contacts are the runner's own (ccdlab.run with missed_events=True, the list of
`ccdlab run --list-missed`): an event is
missed by a discrete method when no sample falls inside it, by a continuous one when no step
containing its enter time confirmed it. The method must be one of RESULTS.json's and the
scene must be the results' scene (same digest); when a record has this dt (within 1 %) its dt
is used and its missed count must equal the recomputed one.

Writes a GIF (Pillow, with Debian's python3-matplotlib) or an MP4 (needs ffmpeg). Bad input
exits with status 2 and one line naming the file and the field. Needs the ccdlab module.

The work is estimated before any of it, as every ccdlab command does (check_work below,
docs/formats.md "Work estimates and `--force`"): the frames (at most 2000), the bodies drawn
over them (frames x bodies, at most 2e6 body-frames) and the run that finds the missed
contacts (bodies x horizon / dt, at most 1e11 body-steps); past a limit it exits with status 2
and one line stating the estimate, unless --force.
"""
import argparse
import json
import math
import os
import shutil
import sys
import tempfile

import numpy as np

import matplotlib
from results_json import BadInput, read_results

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import animation  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402


MAX_FRAMES = 2000
MAX_BODY_FRAMES = 2e6     # bodies drawn, summed over the frames: about 20 us each
MAX_BODY_STEPS = 1e11     # the run's body-steps, as `ccdlab run` (kMaxWorkWithoutForce)


def work_number(x):
    """Three significant digits, as the C++ work_number ("1.2e+13", "430")."""
    return f"{x:.3g}"


def check_work(amount, limit, unit, detail, force, file, field):
    """Refuses work above `limit` (or not a number) unless `force`, in the words of the C++
    check_work(): FILE: FIELD: needs AMOUNT UNIT (DETAIL), above the limit LIMIT without --force."""
    if force or amount <= limit:
        return
    raise BadInput(f"{file}: {field}: needs {work_number(amount)} {unit} ({detail}), "
                   f"above the limit {work_number(limit)} without --force")


def load_results(path):
    res = read_results(path)
    if not isinstance(res.get("records"), list):
        raise BadInput(f"{path}: records: must be an array")
    truth = res.get("truth")
    if not isinstance(truth, dict) or not isinstance(truth.get("scene_sha256"), str):
        raise BadInput(f"{path}: truth.scene_sha256: missing")
    return res


def pick_record(res, path, method, dt):
    records = [r for r in res["records"] if isinstance(r, dict) and r.get("method") == method]
    if not records:
        names = sorted({r.get("method") for r in res["records"] if isinstance(r, dict)}, key=str)
        raise BadInput(f"{path}: records: no method {method} (the file has {', '.join(map(str, names))})")
    near = [r for r in records if isinstance(r.get("dt"), (int, float)) and abs(r["dt"] - dt) <= 0.01 * dt]
    return min(near, key=lambda r: abs(r["dt"] - dt)) if near else None


def projection_axes(scene_json, positions):
    box = scene_json.get("box")
    if box:
        extent = np.array(box["max"]) - np.array(box["min"])
    else:
        extent = positions.reshape(-1, 3).max(axis=0) - positions.reshape(-1, 3).min(axis=0)
    order = np.argsort(-extent, kind="stable")
    return sorted(order[:2].tolist())


def main(argv):
    ap = argparse.ArgumentParser(prog="ccdlab animate", description="Animate what a method missed")
    ap.add_argument("scene", metavar="SCENE.json")
    ap.add_argument("--results", required=True, metavar="RESULTS.json")
    ap.add_argument("--method", required=True)
    ap.add_argument("--dt", required=True, type=float)
    ap.add_argument("--from", dest="t0", type=float, default=None)
    ap.add_argument("--to", dest="t1", type=float, default=None)
    ap.add_argument("--fps", type=int, default=12)
    ap.add_argument("--frames-per-step", type=int, default=6)
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--force", action="store_true", help="animate past the work estimate's limits")
    args = ap.parse_args(argv)
    try:
        return animate(args)
    except BadInput as e:
        print(f"ccdlab animate: {e}", file=sys.stderr)
        return 2
    except MemoryError:  # the same one line as the other commands' out-of-memory handler
        print(f"ccdlab animate: out of memory while animating {args.scene}", file=sys.stderr)
        return 1
    except OSError as e:  # a full disk or an unwritable output while writing the animation
        print(f"ccdlab animate: {args.output}: {e.strerror or e}", file=sys.stderr)
        return 1


def animate(args):
    try:
        import ccdlab
    except ImportError as e:
        print(f"ccdlab animate: the ccdlab Python module is not importable ({e}); build with "
              "-DCCDLAB_PYTHON=ON or set PYTHONPATH to the build's python folder", file=sys.stderr)
        return 1
    ext = os.path.splitext(args.output)[1].lower()
    if ext not in (".gif", ".mp4"):
        raise BadInput(f"{args.output}: -o: must end in .gif or .mp4")
    if ext == ".mp4" and not shutil.which("ffmpeg"):
        raise BadInput(f"{args.output}: -o: an .mp4 needs ffmpeg (apt-get install ffmpeg); .gif needs nothing")
    if not (args.dt > 0 and math.isfinite(args.dt)):
        raise BadInput("--dt: must be a number > 0")
    if not 1 <= args.fps <= 100 or not 1 <= args.frames_per_step <= 100:
        raise BadInput("--fps, --frames-per-step: must be in [1, 100]")
    res = load_results(args.results)
    record = pick_record(res, args.results, args.method, args.dt)
    dt = record["dt"] if record else args.dt

    try:
        scene = ccdlab.load_scene(args.scene)
    except ValueError as e:
        raise BadInput(str(e))
    t0 = 0.0 if args.t0 is None else args.t0
    t1 = scene.horizon if args.t1 is None else args.t1
    if not (0.0 <= t0 < t1 <= scene.horizon):
        raise BadInput(f"--from, --to: must satisfy 0 <= from < to <= horizon = {scene.horizon}")
    per_window = (t1 - t0) / dt * args.frames_per_step
    if not math.isfinite(per_window) or not math.isfinite(scene.horizon / dt):
        raise BadInput(f"--dt: {dt:g} is too small for the horizon {scene.horizon:g} s")
    frames = int(math.ceil(per_window)) + 1
    bodies = len(scene)
    check_work(frames, MAX_FRAMES, "frames",
               f"{t1 - t0:g} s at dt = {dt:g}, {args.frames_per_step} frames per step", args.force,
               args.scene, "--from, --to")
    check_work(frames * bodies, MAX_BODY_FRAMES, "body-frames", f"{bodies} bodies x {frames} frames",
               args.force, args.scene, "bodies")
    steps = math.ceil(scene.horizon / dt)
    check_work(bodies * steps, MAX_BODY_STEPS, "body-steps",
               f"{bodies} bodies, {steps} steps at dt = {dt:g}", args.force, args.scene, "--dt")

    truth = ccdlab.truth(scene)
    if truth.scene_sha256 != res["truth"]["scene_sha256"]:
        raise BadInput(f"{args.results}: truth.scene_sha256: the results are of another scene than {args.scene}")
    experiment = {"format": "ccdlab-experiment/1", "name": "animate", "scene": os.path.abspath(args.scene),
                  "dt": [dt], "methods": [args.method]}
    recorded = res.get("experiment")
    used = recorded.get("acceleration_bound_used") if isinstance(recorded, dict) else None
    if isinstance(used, (int, float)) and not isinstance(used, bool) and 0 <= used < float("inf"):
        experiment["acceleration_bound"] = used
    with tempfile.TemporaryDirectory() as tmp:
        truth.save(os.path.join(tmp, "truth.json"))
        try:
            run = ccdlab.run(experiment, truth=os.path.join(tmp, "truth.json"), missed_events=True,
                             force=args.force)
        except ValueError as e:
            raise BadInput(str(e))
    run_record = run["records"][0]
    for key in ("missed", "static_missed"):
        if record is not None and record.get(key, 0) != run_record.get(key, 0):
            raise BadInput(f"{args.results}: records[{res['records'].index(record)}].{key}: is "
                           f"{record.get(key)}, the method misses {run_record.get(key, 0)} here")
    if record is None:
        print(f"ccdlab animate: note: {args.results} has no record of {args.method} at dt = {args.dt:g}; "
              "computed", file=sys.stderr)
    # Body-body misses (a, b) and body-scenery misses (body, polygon: b = -1), by entry.
    missed = [{"a": m["a"], "b": m["b"], "polygon": -1, "enter": m["enter"], "exit": m["exit"]}
              for m in run_record["missed_events"]]
    missed += [{"a": m["body"], "b": -1, "polygon": m["polygon"], "enter": m["enter"], "exit": m["exit"]}
               for m in run_record.get("static_missed_events", [])]
    missed = sorted((m for m in missed if m["exit"] >= t0 and m["enter"] <= t1), key=lambda m: m["enter"])
    r = run_record
    body_total = r["events"] - r["initial_contacts"] - r.get("undecided", 0)
    scenery_total = r.get("static_events", 0) - r.get("static_initial_contacts", 0) - r.get("static_undecided", 0)
    kinds = (f" ({r['missed']} of {body_total} body-body, {r.get('static_missed', 0)} of {scenery_total} "
             "body-scenery)" if r.get("static_events", 0) else "")
    print(f"ccdlab animate: {args.method} at dt = {dt:.6g} s misses {r['missed'] + r.get('static_missed', 0)} of "
          f"{body_total + scenery_total} contacts{kinds}, {len(missed)} between {t0:g} and {t1:g} s",
          file=sys.stderr)

    times = np.linspace(t0, t1, frames)
    samples = np.arange(math.ceil(t0 / dt - 1e-9), math.floor(t1 / dt + 1e-9) + 1) * dt
    samples = samples[(samples >= t0) & (samples <= t1)]
    pos = scene.positions(times.tolist())
    pos_samples = scene.positions(samples.tolist()) if samples.size else np.zeros((0, len(scene), 3))
    radius = scene.radius
    scene_json = scene.to_json()
    ax_u, ax_v = projection_axes(scene_json, pos)
    names = "xyz"
    # The scenery as Scene::scenery orders it: the polygons, then the mesh's triangles.
    mesh = scene_json.get("scenery_mesh") or {}
    scenery = [np.array(p["polygon"], dtype=np.float64) for p in scene_json.get("scenery", [])]
    scenery += [np.array([mesh["vertices"][i] for i in tri], dtype=np.float64) for tri in mesh.get("triangles", [])]

    ev_a = np.array([m["a"] for m in missed], dtype=np.int64)
    ev_b = np.array([m["b"] for m in missed], dtype=np.int64)
    ev_enter = np.array([m["enter"] for m in missed], dtype=np.float64)
    ev_exit = np.array([m["exit"] for m in missed], dtype=np.float64)
    ev_polygon = np.array([m["polygon"] for m in missed], dtype=np.int64)
    # Where: between the two centres at entry; a body-scenery contact, the body's centre.
    at_enter = scene.positions(ev_enter.tolist()) if len(ev_a) else np.zeros((0, len(scene), 3))
    ev_where = np.array([0.5 * (at_enter[k, ev_a[k]] + at_enter[k, ev_b[k]]) if ev_b[k] >= 0 else at_enter[k, ev_a[k]]
                         for k in range(len(ev_a))]).reshape(-1, 3)

    fig = plt.figure(figsize=(11, 6.4))
    grid = fig.add_gridspec(2, 2, height_ratios=[5, 1], hspace=0.3, wspace=0.15)
    ax_all = fig.add_subplot(grid[0, 0])
    ax_zoom = fig.add_subplot(grid[0, 1])
    ax_time = fig.add_subplot(grid[1, :])
    lo = pos[..., [ax_u, ax_v]].min(axis=(0, 1)) - radius.max()
    hi = pos[..., [ax_u, ax_v]].max(axis=(0, 1)) + radius.max()
    ax_all.set_xlim(lo[0], hi[0])
    ax_all.set_ylim(lo[1], hi[1])
    for a in (ax_all, ax_zoom):
        a.set_aspect("equal")
        a.set_xlabel(f"{names[ax_u]} (m)")
        a.set_ylabel(f"{names[ax_v]} (m)")
    def draw_scenery(ax, highlight=-1):
        for j, poly in enumerate(scenery):
            ax.add_patch(plt.Polygon(poly[:, [ax_u, ax_v]], closed=True, facecolor="#9c8f6a", alpha=0.35,
                                     edgecolor="red" if j == highlight else "#5a5035",
                                     lw=2.0 if j == highlight else 0.6))

    draw_scenery(ax_all)
    bodies = EllipseCollection(2 * radius, 2 * radius, np.zeros(len(radius)), units="xy",
                               offsets=pos[0][:, [ax_u, ax_v]], transOffset=ax_all.transData,
                               facecolors="0.6", edgecolors="none", alpha=0.5)
    ax_all.add_collection(bodies)
    marks = ax_all.scatter([], [], s=160, facecolors="none", edgecolors="red", linewidths=1.5)
    title = fig.suptitle("")

    ax_time.set_xlim(t0, t1)
    ax_time.set_ylim(0, 1)
    ax_time.set_yticks([])
    ax_time.set_xlabel("t (s)")
    for s in samples:
        ax_time.axvline(s, color="0.5", lw=0.8)
    for e0, e1 in zip(ev_enter, ev_exit):
        ax_time.add_patch(plt.Rectangle((e0, 0.25), max(e1 - e0, (t1 - t0) * 0.003), 0.5, color="red"))
    cursor = ax_time.axvline(t0, color="black", lw=1.5)
    ax_time.set_title("samples (grey) and missed contacts (red)", fontsize=9)

    def draw_zoom(k, t):
        ax_zoom.clear()
        ax_zoom.set_aspect("equal")
        ax_zoom.set_xlabel(f"{names[ax_u]} (m)")
        ax_zoom.set_ylabel(f"{names[ax_v]} (m)")
        if not len(ev_a):
            ax_zoom.set_title("no missed contact in this window", fontsize=9)
            return
        e = int(np.argmin(np.minimum(abs(ev_enter - t), abs(ev_exit - t))))
        pair = (ev_a[e], ev_b[e]) if ev_b[e] >= 0 else (ev_a[e],)
        draw_scenery(ax_zoom, ev_polygon[e])
        centre = ev_where[e][[ax_u, ax_v]]
        half = 4 * max(radius[p] for p in pair)
        speed = max(np.linalg.norm(pos[-1, p] - pos[0, p]) for p in pair) / max(t1 - t0, 1e-300)
        half = max(half, 1.2 * speed * dt)
        ax_zoom.set_xlim(centre[0] - half, centre[0] + half)
        ax_zoom.set_ylim(centre[1] - half, centre[1] + half)
        for p, colour in zip(pair, ("tab:blue", "tab:orange")):
            ax_zoom.plot(pos[:, p, ax_u], pos[:, p, ax_v], color=colour, lw=0.8, alpha=0.6)
            for s_index in range(len(samples)):
                xy = pos_samples[s_index, p, [ax_u, ax_v]]
                ax_zoom.add_patch(Circle(xy, radius[p], fill=False, ec=colour, lw=0.8, ls="--"))
            if len(samples):  # the sample centres, visible however small the body
                ax_zoom.plot(pos_samples[:, p, ax_u], pos_samples[:, p, ax_v], "o", mfc="none", mec=colour,
                             markersize=5)
            touching = ev_enter[e] <= t <= ev_exit[e]
            ax_zoom.add_patch(Circle(pos[k, p, [ax_u, ax_v]], radius[p], color="red" if touching else colour,
                                     alpha=0.7))
        ax_zoom.plot(*centre, marker="*", color="red", markersize=14)
        who = (f"bodies {pair[0]} and {pair[1]}" if len(pair) == 2 else
               f"body {pair[0]} and scenery polygon {ev_polygon[e]}")
        ax_zoom.set_title(f"{who}: in contact {ev_enter[e]:.4f}-{ev_exit[e]:.4f} s;\n"
                          f"dashed: where the method saw them (every {dt:.4g} s)", fontsize=9)

    def frame(k):
        t = times[k]
        bodies.set_offsets(pos[k][:, [ax_u, ax_v]])
        colours = np.full(len(radius), "0.6", dtype=object)
        active = (ev_enter <= t) & (ev_exit >= t)
        for a, b in zip(ev_a[active], ev_b[active]):
            colours[a] = "red"
            if b >= 0:
                colours[b] = "red"
        bodies.set_facecolors(list(colours))
        seen = ev_enter <= t
        marks.set_offsets(ev_where[seen][:, [ax_u, ax_v]] if seen.any() else np.zeros((0, 2)))
        cursor.set_xdata([t, t])
        sampled = samples.size and np.min(np.abs(samples - t)) < 0.5 * (times[1] - times[0] if frames > 1 else dt)
        title.set_text(f"{args.method}, dt = {dt:.4g} s: t = {t:.4f} s{'  (sample)' if sampled else ''}; "
                       f"missed contacts circled ({int(seen.sum())} of {len(ev_a)} so far)")
        draw_zoom(k, t)
        return []

    anim = animation.FuncAnimation(fig, frame, frames=frames, blit=False)
    writer = animation.PillowWriter(fps=args.fps) if ext == ".gif" else animation.FFMpegWriter(fps=args.fps)
    out_dir = os.path.dirname(os.path.abspath(args.output))
    if not os.path.isdir(out_dir):
        raise BadInput(f"{args.output}: -o: folder {out_dir} does not exist")
    tmp = os.path.join(out_dir, f".{os.path.basename(args.output)}.tmp.{os.getpid()}{ext}")
    try:
        anim.save(tmp, writer=writer, dpi=80)
        os.replace(tmp, args.output)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    print(args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
