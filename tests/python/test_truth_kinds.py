# ccdlab.truth() is the truth `ccdlab truth` writes, for every kind of scene: rigid shapes
# (certified brackets with error fields), scenery (static events), a box that wraps around
# and free (torque-free) spin. Each is compared with the JSON the command writes, field for
# field and bit for bit (events, errors, grazing flags, static events, digest).
import json

import pytest

import ccdlab


def command_truth(tmp_path, cli, scene_file):
    out = tmp_path / "truth.json"
    cli("truth", scene_file, "-o", out, "--quiet", "--threads", "2")
    return json.loads(out.read_text())


def scene_file(tmp_path, scene):
    path = tmp_path / "scene.json"
    scene.save(str(path))
    return path


def test_rigid_example(tmp_path, cli, source_dir):
    path = source_dir / "data" / "scenes" / "rigid-example.json"
    expected = command_truth(tmp_path, cli, path)
    truth = ccdlab.truth(ccdlab.load_scene(str(path)), threads=2)
    assert truth.to_json() == expected
    assert len(truth) == len(expected["events"]) > 5
    # Certified events carry their errors; the crate and the stick (0, 2) touch from 0.447 s.
    assert truth.enter_error is not None and truth.enter_error.tolist() == [
        e.get("enter_error", 0.0) for e in expected["events"]]
    first = [e for e in expected["events"] if (e["a"], e["b"]) == (0, 2)][0]
    assert first["enter"] == pytest.approx(0.447, abs=1e-3)


@pytest.mark.parametrize("name, params", [
    ("tumble", {"bodies": 12, "seed": 1, "horizon": 1.0}),       # rigid bodies and scenery
    ("pinball", {"bodies": 40, "obstacles": 20, "seed": 1}),     # spheres and scenery
])
def test_scenery(tmp_path, cli, name, params):
    scene = ccdlab.generate(name, **params)
    expected = command_truth(tmp_path, cli, scene_file(tmp_path, scene))
    truth = ccdlab.truth(scene, threads=2)
    assert truth.to_json() == expected
    statics = expected["static_events"]
    assert len(statics) > 0  # the scene touches its scenery: the comparison sees static events
    assert truth.static_body.tolist() == [e["body"] for e in statics]
    assert truth.static_polygon.tolist() == [e["polygon"] for e in statics]
    assert truth.static_enter.tolist() == [e["enter"] for e in statics]
    assert truth.static_exit.tolist() == [e["exit"] for e in statics]
    if any("enter_error" in e or "grazing" in e for e in statics):
        assert truth.static_exit_error.tolist() == [e.get("exit_error", 0.0) for e in statics]
        assert truth.static_grazing.tolist() == [e.get("grazing", False) for e in statics]


@pytest.mark.parametrize("name, params", [
    ("gas", {"bodies": 200, "seed": 3, "wrap": 1, "horizon": 1.0}),                 # spheres through the seams
    ("sticks", {"bodies": 60, "seed": 2, "wrap": 1, "fraction": 0.05}),               # shapes through the seams
    ("sticks", {"bodies": 60, "seed": 4, "free": 1, "fraction": 0.15, "speed_max": 4}),  # free spin
])
def test_wrapped_and_free_spin(tmp_path, cli, name, params):
    scene = ccdlab.generate(name, **params)
    expected = command_truth(tmp_path, cli, scene_file(tmp_path, scene))
    truth = ccdlab.truth(scene, threads=2)
    assert len(expected["events"]) > 0
    assert truth.to_json() == expected
    assert truth.static_body is None  # no scenery


def test_sphere_scene_without_scenery_has_no_static_fields(source_dir):
    truth = ccdlab.truth(ccdlab.load_scene(str(source_dir / "data" / "scenes" / "example.json")))
    assert truth.static_body is None and truth.enter_error is None
