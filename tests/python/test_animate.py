# `ccdlab animate`: a tunnelling contact built from dyadic numbers, missed by a discrete
# method at dt = 1/8 and drawn; the continuous method misses nothing; bad input exit 2.
import json
import shutil
import subprocess

import numpy as np
import pytest
from PIL import Image

from conftest import write_json

# Body 0 (r = 1/16) moves at 4 m/s in x from x = 1 through body 1 (r = 1/16) at rest at
# x = 2.25: in contact while |x0 - 2.25| <= 1/8, from t = 1.125/4 = 0.28125 to 0.34375 s.
# The samples k/8 nearest are 0.25 and 0.375: aabb misses it; capsule sees it.
SCENE = {"format": "ccdlab-scene/1", "horizon": 1.0,
         "box": {"min": [0, -1, -1], "max": [8, 1, 1]},
         "bodies": [{"radius": 0.0625, "position": [1, 0, 0], "velocity": [4, 0, 0]},
                    {"radius": 0.0625, "position": [2.25, 0, 0], "velocity": [0, 0, 0]},
                    {"radius": 0.0625, "position": [6, 0.5, 0], "velocity": [0, 0, 0]}]}


@pytest.fixture(scope="module")
def run_files(tmp_path_factory):
    from conftest import ccdlab_cli
    folder = tmp_path_factory.mktemp("animate")
    scene = write_json(folder / "tunnel.json", SCENE)
    experiment = write_json(folder / "exp.json", {"format": "ccdlab-experiment/1", "name": "tunnel",
                                                 "scene": "tunnel.json", "dt": [0.125],
                                                 "methods": ["aabb/brute", "capsule/brute"]})
    ccdlab_cli("run", experiment, "-o", folder / "results.json", "--quiet")
    return folder, scene, folder / "results.json"


def red_pixels(frame):
    rgb = np.asarray(frame.convert("RGB")).astype(int)
    return int(np.sum((rgb[..., 0] > 200) & (rgb[..., 1] < 60) & (rgb[..., 2] < 60)))


def test_missed_tunnelling_contact_is_drawn(run_files, cli):
    folder, scene, results = run_files
    records = {r["method"]: r for r in json.loads(results.read_text())["records"]}
    assert records["aabb/brute"]["missed"] == 1 and records["capsule/brute"]["missed"] == 0
    out = folder / "missed.gif"
    run = cli("animate", scene, "--results", results, "--method", "aabb/brute", "--dt", "0.125",
              "--from", "0.25", "--to", "0.375", "-o", out)
    assert "misses 1 of 1 contacts, 1 between 0.25 and 0.375" in run.stderr
    gif = Image.open(out)
    assert gif.format == "GIF" and gif.n_frames == 7  # 6 frames per step + the last
    gif.seek(0)
    before = red_pixels(gif)   # t = 0.25: not yet in contact
    gif.seek(3)
    during = red_pixels(gif)   # t = 0.3125: in contact, bodies drawn red and circled
    assert during > before + 50


def test_a_method_that_misses_nothing(run_files, cli):
    folder, scene, results = run_files
    run = cli("animate", scene, "--results", results, "--method", "capsule/brute", "--dt", "0.125",
              "--from", "0.25", "--to", "0.5", "--frames-per-step", "2", "-o", folder / "none.gif")
    assert "misses 0 of 1 contacts" in run.stderr
    assert Image.open(folder / "none.gif").n_frames == 5


@pytest.mark.parametrize("args, message", [
    (["--method", "sphere/grid"], "records: no method sphere/grid"),
    (["--method", "aabb/brute", "--from", "0.5", "--to", "0.25"], "--from, --to:"),
    (["--method", "aabb/brute", "-o", "x.png"], "-o: must end in .gif or .mp4"),
])
def test_bad_input_exits_2(run_files, cli, args, message):
    folder, scene, results = run_files
    full = [scene, "--results", results, "--dt", "0.125", "-o", folder / "bad.gif"] + args
    run = cli("animate", *full, check=False)
    assert run.returncode == 2 and message in run.stderr
    assert len(run.stderr.strip().splitlines()) == 1


def test_results_of_another_scene_exit_2(run_files, cli, tmp_path):
    folder, scene, results = run_files
    other = json.loads(json.dumps(SCENE))
    other["bodies"][2]["position"] = [5, 0.5, 0]
    other_file = write_json(tmp_path / "other.json", other)
    run = cli("animate", other_file, "--results", results, "--method", "aabb/brute", "--dt", "0.125",
              "-o", tmp_path / "x.gif", check=False)
    assert run.returncode == 2 and "truth.scene_sha256" in run.stderr


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed")
def test_mp4_with_ffmpeg(run_files, cli):
    folder, scene, results = run_files
    out = folder / "missed.mp4"
    cli("animate", scene, "--results", results, "--method", "aabb/brute", "--dt", "0.125",
        "--from", "0.25", "--to", "0.375", "-o", out)
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                            "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", str(out)],
                           capture_output=True, text=True, check=True)
    assert int(probe.stdout.strip()) == 7


def many_bodies(n):
    """n bodies at rest, apart: the scene of no results file (its digest is checked after the estimate)."""
    return {"format": "ccdlab-scene/1", "horizon": 1.0,
            "bodies": [{"radius": 0.1, "position": [i, 0, 0], "velocity": [0, 0, 0]} for i in range(n)]}


@pytest.mark.parametrize("scene_of, args, message", [
    (lambda: SCENE, ["--dt", "0.001"],
     "--from, --to: needs 6e+03 frames (1 s at dt = 0.001, 6 frames per step), above the limit 2e+03 without --force"),
    (lambda: many_bodies(3000), ["--dt", "0.125", "--frames-per-step", "100"],
     "bodies: needs 2.4e+06 body-frames (3000 bodies x 801 frames), above the limit 2e+06 without --force"),
    (lambda: SCENE, ["--dt", "1e-11", "--from", "0", "--to", "1e-9"],
     "--dt: needs 3e+11 body-steps (3 bodies, 100000000000 steps at dt = 1e-11), above the limit 1e+11 "
     "without --force"),
])
def test_work_estimate_refuses_up_front(run_files, cli, tmp_path, scene_of, args, message):
    folder, _, results = run_files
    scene = write_json(tmp_path / "scene.json", scene_of())
    out = tmp_path / "big.gif"
    run = cli("animate", scene, "--results", results, "--method", "aabb/brute", "-o", out, *args, check=False)
    assert run.returncode == 2
    assert run.stderr == f"ccdlab animate: {scene}: {message}\n"
    assert not out.exists() and list(tmp_path.iterdir()) == [scene]


def test_force_lifts_the_estimate(run_files, cli, tmp_path):
    # Forced, the 3,000 bodies pass the estimate and reach the next check (the results are of
    # another scene): the estimate, not the drawing, refused them before.
    folder, _, results = run_files
    scene = write_json(tmp_path / "scene.json", many_bodies(3000))
    run = cli("animate", scene, "--results", results, "--method", "aabb/brute", "--dt", "0.125",
              "--frames-per-step", "100", "--force", "-o", tmp_path / "big.gif", check=False)
    assert run.returncode == 2 and "truth.scene_sha256" in run.stderr and "body-frames" not in run.stderr
