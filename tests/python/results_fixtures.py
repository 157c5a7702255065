# Small real results files for the tests of the scripts that read them (report.py, plot.py,
# plot_study.py), made with the ccdlab command alone: two spheres that cross once (nothing
# is missed, nothing is a false positive), two that never meet (every count is 0), and one
# record only. Each is a ccdlab-results/2 file as `ccdlab run` writes it.
import copy
import json

from conftest import ccdlab_cli


def crossing_scene(gap):
    """Two spheres of radius 0.5 flying along x through each other (gap 0) or passing `gap`
    metres apart in y (no contact), over 4 s, no gravity."""
    return {"format": "ccdlab-scene/1", "horizon": 4.0, "gravity": [0, 0, 0],
            "bodies": [{"radius": 0.5, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                       {"radius": 0.5, "position": [4, 1 + gap if gap else 0, 0], "velocity": [-1, 0, 0]}]}


def run_results(folder, name, scene, methods, dts):
    """`ccdlab run` of `methods` x `dts` on `scene`; the parsed results."""
    folder.mkdir(parents=True, exist_ok=True)
    scene_path = folder / f"{name}-scene.json"
    scene_path.write_text(json.dumps(scene))
    experiment = folder / f"{name}-experiment.json"
    experiment.write_text(json.dumps({"format": "ccdlab-experiment/1", "name": name, "scene": str(scene_path),
                                      "dt": dts, "methods": methods}))
    out = folder / f"{name}.json"
    ccdlab_cli("run", experiment, "-o", out, "--quiet")
    return json.loads(out.read_text())


def crossing_results(folder):
    """The reproduction of issue 36 part 2: aabb/sap and capsule/grid at dt 0.1 and 0.01 on
    two spheres crossing once; nothing missed, no false positive."""
    return run_results(folder, "crossing", crossing_scene(0), ["aabb/sap", "capsule/grid"], [0.1, 0.01])


def never_meeting_results(folder):
    """Two spheres that never touch: no event, so every count and fraction is 0; the costs
    are set to 0 too, so that every number a chart draws against dt is 0."""
    res = run_results(folder, "apart", crossing_scene(2.0), ["aabb/sap", "capsule/grid"], [0.1, 0.01])
    assert res["truth"]["events"] == 0
    zero = copy.deepcopy(res)
    for r in zero["records"]:
        for k, v in r.items():
            if isinstance(v, (int, float)) and not isinstance(v, bool) and k not in ("dt", "hz", "job", "steps"):
                r[k] = 0 if isinstance(v, int) else 0.0
    return zero


def single_record_results(folder):
    """One method at one dt: one record."""
    return run_results(folder, "single", crossing_scene(0), ["aabb/sap"], [0.1])
